// SPDX-License-Identifier: BSD-3-Clause
/* Test support: run the mhplan program as a user would and capture what it prints. */
#ifndef MHPLAN_TESTS_CLI_SUPPORT_H
#define MHPLAN_TESTS_CLI_SUPPORT_H

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace mhplan::test
{
    /** \brief Exit code and output (stdout and stderr together) of one mhplan invocation. */
    struct CliResult
    {
        int code;
        std::string out;
    };

    /** \brief Run `mhplan ARGS` (the binary under test, MHPLAN_BINARY) through the shell. */
    inline CliResult runCli(const std::string &args)
    {
        const std::string cmd = std::string(MHPLAN_BINARY) + " " + args + " 2>&1";
        FILE *pipe = popen(cmd.c_str(), "r");
        if (pipe == nullptr)
            return {-1, ""};
        std::string out;
        std::array<char, 4096> buf{};
        while (fgets(buf.data(), buf.size(), pipe) != nullptr)
            out += buf.data();
        const int status = pclose(pipe);
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
    }

    inline bool contains(const std::string &hay, const std::string &needle)
    {
        return hay.find(needle) != std::string::npos;
    }
} // namespace mhplan::test

#endif

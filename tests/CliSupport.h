// SPDX-License-Identifier: BSD-3-Clause
/* Test support: run the mhplan program as a user would and capture what it prints. */
#ifndef MHPLAN_TESTS_CLI_SUPPORT_H
#define MHPLAN_TESTS_CLI_SUPPORT_H

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

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

    /** \brief Run `mhplan ARGS` and keep only its stdout (stderr is discarded): a --json document. */
    inline CliResult runCliStdout(const std::string &args)
    {
        return runCli(args + " 2>/dev/null");
    }

    /** \brief Parse \e json with Python's json module (an independent parser) and print the Python
        expression \e expr of the document `d`; "PARSE ERROR ..." when it is not valid JSON. */
    inline std::string pyJson(const std::string &json, const std::string &expr,
                              const std::string &tag = "doc")
    {
        // One file per process and call: ctest runs the tests of a binary in parallel processes.
        static int calls = 0;
        const std::string file = std::string(P_tmpdir) + "/mhplan_json_" + tag + "_" +
                                 std::to_string(getpid()) + "_" + std::to_string(++calls) + ".json";
        FILE *f = std::fopen(file.c_str(), "w");
        if (f == nullptr)
            return "cannot write " + file;
        std::fputs(json.c_str(), f);
        std::fclose(f);
        const std::string script =
            "import json,math,sys\ntry:\n d = json.load(open('" + file +
            "'))\nexcept Exception as e:\n print('PARSE ERROR', e); sys.exit(0)\nprint(" + expr + ")\n";
        const std::string py = file + ".py";
        f = std::fopen(py.c_str(), "w");
        if (f == nullptr)
            return "cannot write " + py;
        std::fputs(script.c_str(), f);
        std::fclose(f);
        FILE *pipe = popen(("/usr/bin/python3 " + py + " 2>&1").c_str(), "r");
        if (pipe == nullptr)
            return "cannot run python3";
        std::string out;
        std::array<char, 4096> buf{};
        while (fgets(buf.data(), buf.size(), pipe) != nullptr)
            out += buf.data();
        pclose(pipe);
        std::remove(file.c_str());
        std::remove(py.c_str());
        while (!out.empty() && (out.back() == '\n' || out.back() == '\r'))
            out.pop_back();
        return out;
    }

    inline bool contains(const std::string &hay, const std::string &needle)
    {
        return hay.find(needle) != std::string::npos;
    }
} // namespace mhplan::test

#endif

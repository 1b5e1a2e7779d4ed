// SPDX-License-Identifier: BSD-3-Clause
/* mhplan arena: what it refuses before anything starts (no R needed). Serving Planner Arena itself is tested
   in a browser by tests/arena/arena_test.sh. */
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using mhplan::test::contains;
using mhplan::test::runCli;

namespace
{
    fs::path scratch(const std::string &name)
    {
        const fs::path dir =
            fs::temp_directory_path() / ("mhplan_test_cli_arena_" + std::to_string(getpid()));
        fs::create_directories(dir);
        return dir / name;
    }

    /** An SQLite file with \e tables (empty), made by Debian's sqlite3 program. */
    std::string sqliteFile(const std::string &name, const std::string &tables)
    {
        const std::string path = scratch(name).string();
        fs::remove(path);
        const std::string cmd = "sqlite3 '" + path + "' \"" + tables + "\"";
        EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
        return path;
    }
} // namespace

TEST(CliArena, RefusesWhatIsNotABenchmarkDatabase)
{
    auto r = runCli("arena " + scratch("missing.db").string());
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "missing.db: no such file")) << r.out;

    r = runCli("arena " + scratch("").string());
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "not a regular file")) << r.out;

    const fs::path text = scratch("text.db");
    std::ofstream(text) << "experiments plannerConfigs runs\n";
    r = runCli("arena " + text.string());
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "text.db: not an SQLite database")) << r.out;

    r = runCli("arena " + sqliteFile("other.db", "CREATE TABLE experiments(id); CREATE TABLE runs(id);"));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "not an OMPL benchmark database (no table plannerConfigs, progress, enums"))
        << r.out;
    fs::remove_all(scratch("").parent_path());
}

TEST(CliArena, RefusesBadOptionsAndABusyPort)
{
    const std::string db =
        sqliteFile("bench.db", "CREATE TABLE experiments(id); CREATE TABLE plannerConfigs(id);"
                               "CREATE TABLE runs(id); CREATE TABLE progress(runid);"
                               "CREATE TABLE enums(name);");
    auto r = runCli("arena");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "expected one argument")) << r.out;
    r = runCli("arena " + db + " --port 70000");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "--port must be in 1..65535 (got 70000)")) << r.out;
    r = runCli("arena " + db + " --colour red");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "--colour")) << r.out;
    r = runCli("arena " + db + " --host no.such.host.invalid");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "--host 'no.such.host.invalid': cannot resolve it")) << r.out;

    // A port something listens on is refused before R starts.
    const int s = ::socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_GE(s, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr *>(&a), sizeof a), 0);
    ASSERT_EQ(::listen(s, 1), 0);
    socklen_t len = sizeof a;
    ASSERT_EQ(::getsockname(s, reinterpret_cast<sockaddr *>(&a), &len), 0);
    const int port = ntohs(a.sin_port);
    r = runCli("arena " + db + " --port " + std::to_string(port));
    ::close(s);
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "127.0.0.1:" + std::to_string(port) + " is in use")) << r.out;
    EXPECT_FALSE(contains(r.out, "starting")) << r.out;
    fs::remove_all(scratch("").parent_path());
}

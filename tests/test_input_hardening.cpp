// SPDX-License-Identifier: BSD-3-Clause
/* Issue 19: inputs that were accepted or escaped as the wrong error, each refused with file, line and field.
 */
#include "CliSupport.h"

#include "benchmarks/Campaign.h"
#include "benchmarks/Database.h"
#include "src/io/GridIO.h"
#include "src/io/WorldIO.h"
#include "src/registry/Registry.h"
#include "src/sim/ScenarioIO.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

namespace
{
    /** \brief The InputError message of \e f, or "" (and a failure) when it does not throw one. */
    template <typename F> std::string inputError(F &&f)
    {
        try
        {
            f();
        }
        catch (const mhplan::InputError &e)
        {
            return e.what();
        }
        catch (const std::exception &e)
        {
            ADD_FAILURE() << "not an InputError: " << e.what();
            return "";
        }
        ADD_FAILURE() << "accepted";
        return "";
    }

    bool contains(const std::string &s, const std::string &part)
    {
        return s.find(part) != std::string::npos;
    }

    std::string campaignError(const std::string &planners)
    {
        return inputError(
            [&] {
                mhplan::bench::parseCampaign("campaign: c\nworlds: [bfo_case1]\nplanners:\n" + planners,
                                             "c.yaml");
            });
    }
} // namespace

TEST(CampaignChecks, PlannersParametersAndProgressAreCheckedAtParse)
{
    std::string e = campaignError("  - RRTstar\n  - NoSuchPlanner\n");
    EXPECT_TRUE(contains(e, "c.yaml:5: field 'planners[1]': unknown planner 'NoSuchPlanner'")) << e;
    EXPECT_TRUE(contains(e, "RRTstar")) << e;
    e = campaignError("  - {planner: SMA, params: {nonsense: 1}}\n");
    EXPECT_TRUE(contains(e, "c.yaml:4: field 'planners[0].params'")) << e;
    EXPECT_TRUE(contains(e, "no parameter 'nonsense'")) << e;
    e = campaignError("  - {planner: SMA, params: {population_size: 2.5}}\n");
    EXPECT_TRUE(contains(e, "population_size") && contains(e, "an integer")) << e;
    e = campaignError("  - {planner: RRTstar, params: {range: nan}}\n");
    EXPECT_TRUE(contains(e, "range") && contains(e, "out of range")) << e;
    e = campaignError("  - {planner: SMA, progress: [iterations INTEGER, nonsense]}\n");
    EXPECT_TRUE(contains(e, "c.yaml:4: field 'planners[0].progress[1]'")) << e;
    EXPECT_TRUE(contains(e, "no progress property 'nonsense'") && contains(e, "'best cost REAL'")) << e;
    e = campaignError("  - {planner: SMA, params: {population_size: 10, population_size: 12}}\n");
    EXPECT_TRUE(contains(e, "duplicate key 'population_size'")) << e;
    e = campaignError("  - {planner: SMA, params: {[a]: 1}}\n");
    EXPECT_TRUE(contains(e, "c.yaml:4") && contains(e, "a key must be a plain name")) << e;
    // A valid entry still parses.
    const mhplan::bench::Campaign c = mhplan::bench::parseCampaign(
        "campaign: c\nworlds: [bfo_case1]\nplanners:\n  - {planner: SMA, params: {population_size: 12}, "
        "progress: [iterations INTEGER]}\n",
        "c.yaml");
    ASSERT_EQ(c.planners.size(), 1u);
    EXPECT_EQ(c.planners[0].params.at("population_size"), "12");
}

TEST(WorldChecks, KeysBoundsAndGridsAreChecked)
{
    const auto world = [](const std::string &text)
    { return inputError([&] { mhplan::parseWorldYaml(text, "w.yaml"); }); };
    std::string e = world("bounds: [0, 10, 0, 10]\nqueries: [{[a]: 1, start: [1,1], goal: [2,2]}]\n");
    EXPECT_TRUE(contains(e, "w.yaml:2") && contains(e, "a key must be a plain name")) << e;
    e = world("bounds: [0, 10, 0, 10]\n{a: 1}: 2\n");
    EXPECT_TRUE(contains(e, "w.yaml:2") && contains(e, "a key must be a plain name")) << e;
    e = world("bounds: [0, 10, 0, 10]\nobstacles:\n  - circle:\n      center: [5, 5]\n      radius: 1\n"
              "      radius: 2\n");
    EXPECT_TRUE(
        contains(e, "w.yaml:6: field 'obstacles[0].circle.radius': duplicate key 'radius' (first given on "
                    "line 5)"))
        << e;
    e = world("bounds: [0, 1e-300, 0, 1e-300]\n");
    EXPECT_TRUE(contains(e, "w.yaml:1: field 'bounds'") && contains(e, "degenerate")) << e;
    e = world("bounds: [-1e308, 1e308, 0, 10]\n");
    EXPECT_TRUE(contains(e, "field 'bounds'") && contains(e, "within")) << e;
    e = world("bounds: [0, 10, 0, 10]\nobstacles: [{circle: {center: [5, 5], radius: 1e307}}]\n");
    EXPECT_TRUE(contains(e, "radius")) << e;
    e = world("grid:\n  rows: ['..', '..']\n  threshold: 0.4\n");
    EXPECT_TRUE(contains(e, "w.yaml:3: field 'grid.threshold'") && contains(e, ".pgm")) << e;
    e = world("grid:\n  rows: ['..', '..']\n  cell_size: 1e300\n");
    EXPECT_TRUE(contains(e, "field 'grid'") && contains(e, "extent")) << e;
    e = world("grid: {file: x.txt}\n");
    EXPECT_EQ(e.find("field 'grid.file'"), e.rfind("field 'grid.file'")) << "field named twice: " << e;
}

TEST(GridChecks, HeadersCannotMakeTheReaderAllocate)
{
    // A header declaring 25525 x 40081 (about 1 GB of cells) with three pixel bytes: refused by the stated
    // limit, before any grid exists.
    std::istringstream pgm("P5 25525 40081 255\n\x01\x02\x03");
    std::string e = inputError([&] { mhplan::parsePgm(pgm, "big.pgm"); });
    EXPECT_TRUE(contains(e, "big.pgm:1") && contains(e, "grid too large")) << e;
    // Within the limit, a short raster is refused as truncated (the grid is built only after the pixels).
    std::istringstream shortPgm("P5 4000 4000 255\n\x01\x02\x03");
    e = inputError([&] { mhplan::parsePgm(shortPgm, "short.pgm"); });
    EXPECT_TRUE(contains(e, "truncated P5 raster") && contains(e, "found 3")) << e;
    std::istringstream map("type octile\nheight 4000\nwidth 4000\nmap\n....\n");
    e = inputError([&] { mhplan::parseMovingAIMap(map, "big.map"); });
    EXPECT_TRUE(contains(e, "big.map:5") && contains(e, "row 1 has 4 characters")) << e;
    // The line of a missing row is the last line of the file, not one past it.
    std::istringstream rows("type octile\nheight 3\nwidth 2\nmap\n..\n");
    e = inputError([&] { mhplan::parseMovingAIMap(rows, "m.map"); });
    EXPECT_TRUE(contains(e, "m.map:5: missing map rows")) << e;
    // Binary bytes are shown escaped, not echoed.
    std::istringstream binary(std::string("type octile\nheight 1\nwidth 2\nmap\n.\x01\n"));
    e = inputError([&] { mhplan::parseMovingAIMap(binary, "b.map"); });
    EXPECT_TRUE(contains(e, "byte 0x1")) << e;
    std::istringstream header(std::string("type oct\x02ile\n"));
    e = inputError([&] { mhplan::parseMovingAIMap(header, "h.map"); });
    EXPECT_TRUE(contains(e, "\\x02")) << e;
    EXPECT_FALSE(contains(e, "\x02")) << e;
}

namespace
{
    /** \brief Collects OMPL's console messages of level ERROR. */
    class ErrorLog : public ompl::msg::OutputHandler
    {
      public:
        void log(const std::string &text, ompl::msg::LogLevel level, const char *, int) override
        {
            if (level == ompl::msg::LOG_ERROR)
                errors.push_back(text);
        }
        std::vector<std::string> errors;
    };
} // namespace

// Issue 19: on a space they cannot plan in, the lattice and potential-field planners refuse at setup() with
// an ompl::Exception and log the reason through OMPL_ERROR (as README.md says of every mhplan planner).
TEST(PlannerSetup, UnsupportedSpaceThrowsAndLogs)
{
    for (const std::string name : {"AStar", "ThetaStar", "APF", "BFO", "ATBFO"})
    {
        auto space = std::make_shared<ompl::base::RealVectorStateSpace>(3);
        space->setBounds(0.0, 1.0);
        auto ss = std::make_shared<ompl::geometric::SimpleSetup>(space);
        ss->setStateValidityChecker([](const ompl::base::State *) { return true; });
        ompl::base::ScopedState<> start(space), goal(space);
        start = std::vector<double>{0.1, 0.1, 0.1};
        goal = std::vector<double>{0.9, 0.9, 0.9};
        ss->setStartAndGoalStates(start, goal);
        ss->setPlanner(mhplan::builtinPlanners().create(name, ss->getSpaceInformation()));
        ErrorLog log;
        ompl::msg::OutputHandler *previous = ompl::msg::getOutputHandler();
        const ompl::msg::LogLevel level = ompl::msg::getLogLevel();
        ompl::msg::useOutputHandler(&log);
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        std::string thrown;
        try
        {
            ss->setup();
        }
        catch (const ompl::Exception &e)
        {
            thrown = e.what();
        }
        ompl::msg::useOutputHandler(previous);
        ompl::msg::setLogLevel(level);
        EXPECT_NE(thrown.find(name), std::string::npos) << name << ": " << thrown;
        EXPECT_NE(thrown.find("2D RealVectorStateSpace"), std::string::npos) << name << ": " << thrown;
        ASSERT_FALSE(log.errors.empty()) << name << " logged no error";
        EXPECT_NE(log.errors.back().find(name), std::string::npos) << log.errors.back();
    }
}

// Issue 19: BIT* is registered as "BITstar" and its messages name it so (OMPL 1.5.2 renames the k-nearest
// BIT* it constructs "kBITstar"). Only messages that OMPL prints inside setup() itself, such as its notice
// that no objective was given, still carry OMPL's name.
TEST(PlannerSetup, BitStarMessagesNameBitStar)
{
    auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
    space->setBounds(0.0, 1.0);
    auto ss = std::make_shared<ompl::geometric::SimpleSetup>(space);
    ss->setStateValidityChecker([](const ompl::base::State *) { return true; });
    ompl::base::ScopedState<> start(space), goal(space);
    start = std::vector<double>{0.1, 0.1};
    goal = std::vector<double>{0.9, 0.9};
    ss->setStartAndGoalStates(start, goal);
    ss->setOptimizationObjective(
        std::make_shared<ompl::base::PathLengthOptimizationObjective>(ss->getSpaceInformation()));
    ss->setPlanner(mhplan::builtinPlanners().create("BITstar", ss->getSpaceInformation()));
    EXPECT_EQ(ss->getPlanner()->getName(), "BITstar");
    struct AllMessages : ompl::msg::OutputHandler
    {
        void log(const std::string &text, ompl::msg::LogLevel, const char *, int) override
        {
            messages.push_back(text);
        }
        std::vector<std::string> messages;
    } log;
    ompl::msg::OutputHandler *previous = ompl::msg::getOutputHandler();
    const ompl::msg::LogLevel level = ompl::msg::getLogLevel();
    ompl::msg::useOutputHandler(&log);
    ompl::msg::setLogLevel(ompl::msg::LOG_DEBUG);
    ss->solve(ompl::base::IterationTerminationCondition(50));
    ompl::msg::useOutputHandler(previous);
    ompl::msg::setLogLevel(level);
    ASSERT_FALSE(log.messages.empty());
    bool named = false;
    for (const std::string &m : log.messages)
    {
        EXPECT_EQ(m.find("kBITstar"), std::string::npos) << m;
        named = named || m.find("BITstar:") != std::string::npos;
    }
    EXPECT_TRUE(named) << "no message names BITstar";
}

// Issue 19: resource limits are stated and enforced with a message, not run into.
TEST(Limits, TimeStepPolygonAndFileSize)
{
    const std::string scenario = "bounds: [0, 10, 0, 10]\nrobots: [{name: r, start: [1, 1], goal: [9, 9]}]\n";
    std::string e =
        inputError([&] { mhplan::parseScenarioYaml(scenario + "simulation: {dt: 1e-9}\n", "s.yaml"); });
    EXPECT_TRUE(contains(e, "s.yaml:3: field 'simulation.dt'") && contains(e, "at least")) << e;
    e = inputError(
        [&]
        { mhplan::parseScenarioYaml(scenario + "simulation: {dt: 0.0001, time_limit: 1e7}\n", "s.yaml"); });
    EXPECT_TRUE(contains(e, "simulation.dt") && contains(e, "steps")) << e;

    // A polygon of kMaxPolygonVertices + 1 vertices (a convex one, so only the limit refuses it).
    std::ostringstream poly;
    poly << "bounds: [-10, 10, -10, 10]\nobstacles:\n  - polygon: {points: [";
    const std::size_t n = mhplan::kMaxPolygonVertices + 1;
    for (std::size_t i = 0; i < n; ++i)
        poly << (i ? ", " : "") << "[" << 5.0 * std::cos(2.0 * M_PI * i / n) << ", "
             << 5.0 * std::sin(2.0 * M_PI * i / n) << "]";
    poly << "]}\n";
    e = inputError([&] { mhplan::parseWorldYaml(poly.str(), "p.yaml"); });
    EXPECT_TRUE(contains(e, "p.yaml:3") && contains(e, "at most 2000")) << e;

    const std::string big = "bounds: [0, 10, 0, 10]\n" + std::string(mhplan::kMaxYamlBytes, '#');
    e = inputError([&] { mhplan::parseWorldYaml(big, "big.yaml"); });
    EXPECT_TRUE(contains(e, "big.yaml") && contains(e, "limited to")) << e;
}

// Issue 26: special files, second documents, hostile names, one --time range, write errors, signals, no
// shell. Each check runs in a child process with a deadline and a memory cap where the old behaviour was to
// block forever or to read without end, so that a regression fails here instead of hanging the suite.
namespace
{
    namespace fs = std::filesystem;

    fs::path scratchDir(const std::string &tag)
    {
        const fs::path dir =
            fs::temp_directory_path() / ("mhplan_test_hardening_" + std::to_string(::getpid())) / tag;
        fs::remove_all(dir);
        fs::create_directories(dir);
        return dir;
    }

    /** Run \e body in a child process (address space capped at 1 GiB) for at most \e seconds; its exit
        code, or -1 when it had to be killed (it blocked or did not end). */
    int isolated(const std::function<int()> &body, double seconds = 20.0)
    {
        std::cout.flush();
        std::cerr.flush();
        const pid_t pid = ::fork();
        if (pid == 0)
        {
            struct rlimit cap
            {
                std::size_t{1} << 30, std::size_t{1} << 30
            };
            ::setrlimit(RLIMIT_AS, &cap);
            int code = 99;
            try
            {
                code = body();
            }
            catch (...)
            {
                code = 98;
            }
            ::_exit(code);
        }
        const auto t0 = std::chrono::steady_clock::now();
        int status = 0;
        while (::waitpid(pid, &status, WNOHANG) == 0)
        {
            if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > seconds)
            {
                ::kill(pid, SIGKILL);
                ::waitpid(pid, &status, 0);
                return -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

    /** 0 when loading \e path as a world throws an InputError containing \e part, 1 otherwise. */
    int worldRefused(const std::string &path, const std::string &part)
    {
        try
        {
            mhplan::loadWorld(path);
        }
        catch (const mhplan::InputError &e)
        {
            return contains(e.what(), part) ? 0 : 2;
        }
        return 1;
    }
} // namespace

TEST(SpecialFiles, FifoDeviceAndLoopAreRefusedWithoutReading)
{
    const fs::path dir = scratchDir("special");
    const std::string fifo = (dir / "fifo.yaml").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(isolated([&] { return worldRefused(fifo, "FIFO"); }), 0) << "a FIFO blocks or is read";
    for (const char *name : {"zero.yaml", "zero.map", "zero.pgm"})
    {
        fs::create_symlink("/dev/zero", dir / name);
        EXPECT_EQ(isolated([&] { return worldRefused((dir / name).string(), "is a device"); }), 0) << name;
    }
    fs::create_symlink(dir / "loop_b.yaml", dir / "loop_a.yaml");
    fs::create_symlink(dir / "loop_a.yaml", dir / "loop_b.yaml");
    EXPECT_EQ(isolated([&] { return worldRefused((dir / "loop_a.yaml").string(), "symbolic-link loop"); }),
              0);
    // Scenario and campaign files go through the same reader.
    EXPECT_EQ(isolated(
                  [&]
                  {
                      try
                      {
                          mhplan::loadScenario(fifo);
                      }
                      catch (const mhplan::InputError &e)
                      {
                          return contains(e.what(), "FIFO") ? 0 : 2;
                      }
                      return 1;
                  }),
              0);
    const auto r = mhplan::test::runCli("bench " + fifo + " --list");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "FIFO")) << r.out;
    const auto d = mhplan::test::runCli("bench " + dir.string() + " --list");
    EXPECT_EQ(d.code, 1);
    EXPECT_TRUE(contains(d.out, "is a directory")) << d.out;
}

TEST(YamlDocuments, ASecondDocumentIsRefused)
{
    const std::string world = "bounds: [0, 10, 0, 10]\nqueries: [{start: [1, 1], goal: [9, 9]}]\n";
    std::string e =
        inputError([&] { mhplan::parseWorldYaml(world + "---\nbounds: [0, 1, 0, 1]\n", "w.yaml"); });
    EXPECT_TRUE(contains(e, "w.yaml:") && contains(e, "second one")) << e;
    e = inputError(
        [&] { mhplan::bench::parseCampaign("worlds: [bfo_case1]\nplanners: [RRTstar]\n---\n", "c.yaml"); });
    EXPECT_TRUE(contains(e, "c.yaml") && contains(e, "second one")) << e;
    // Nesting and explicit tags.
    std::string deep =
        "bounds: [0, 10, 0, 10]\ndescription: " + std::string(1000, '[') + std::string(1000, ']') + "\n";
    e = inputError([&] { mhplan::parseWorldYaml(deep, "deep.yaml"); });
    EXPECT_TRUE(contains(e, "deep.yaml")) << e;
    e = inputError(
        [&]
        {
            mhplan::bench::parseCampaign("time_limit: !!int 0.7\nworlds: [bfo_case1]\nplanners: [RRTstar]\n",
                                         "t.yaml");
        });
    EXPECT_TRUE(contains(e, "t.yaml:1") && contains(e, "time_limit") && contains(e, "!!int")) << e;
}

TEST(Names, ControlCharactersAreRefusedWhenReadAndBlanksByCampaigns)
{
    std::string e =
        inputError([&] { mhplan::parseWorldYaml("name: \"a\\nb\"\nbounds: [0, 10, 0, 10]\n", "n.yaml"); });
    EXPECT_TRUE(contains(e, "n.yaml:1: field 'name'") && contains(e, "control characters (found 0x0a)")) << e;
    e = inputError(
        [&]
        {
            mhplan::parseWorldYaml(
                "bounds: [0, 10, 0, 10]\nqueries: [{name: \"q\\tx\", start: [1, 1], goal: [9, 9]}]\n",
                "q.yaml");
        });
    EXPECT_TRUE(contains(e, "q.yaml:2: field 'queries[0].name'") && contains(e, "0x09")) << e;

    // Two worlds whose names differ only before a blank would both become "one-default" in OMPL's logs.
    const fs::path dir = scratchDir("names");
    std::ofstream(dir / "lab.yaml")
        << "name: lab one\nbounds: [0, 10, 0, 10]\nqueries: [{start: [1, 1], goal: [9, 9]}]\n";
    std::ofstream(dir / "c.yaml") << "worlds: [lab.yaml]\nplanners: [RRTstar]\n";
    const mhplan::bench::Campaign c = mhplan::bench::loadCampaign((dir / "c.yaml").string());
    e = inputError([&] { mhplan::bench::enumerateExperiments(c, [](const std::string &s) { return s; }); });
    EXPECT_TRUE(contains(e, "world name 'lab one'") && contains(e, "no blanks")) << e;
}

TEST(CliLimits, TimeHasOneRangeAndWriteErrorsAreReported)
{
    for (const std::string cmd : {"plan bfo_case1 --planner RRTConnect --time 1e10",
                                  "compare bfo_case1 --planners RRTConnect --runs 1 --time 1e10",
                                  "plan bfo_case1 --planner RRTConnect --time 0.0001"})
    {
        const auto r = mhplan::test::runCli(cmd);
        EXPECT_EQ(r.code, 1) << cmd << "\n" << r.out;
        EXPECT_TRUE(contains(r.out, "--time must be in [0.001, 1000000]")) << r.out;
    }
    const auto full =
        mhplan::test::runCli("plan bfo_case1 --planner RRTConnect --time 0.05 --json >/dev/full");
    EXPECT_EQ(full.code, 1) << full.out; // (its message goes to stderr, which the shell sends there too)
}

TEST(CliSignals, ReportPassesSigtermToItsChild)
{
    const fs::path dir = scratchDir("report_signal");
    const fs::path fake = dir / "python";
    const fs::path marker = dir / "got_term";
    // A stand-in for the Python interpreter that notes SIGTERM and waits for it.
    std::ofstream(fake) << "#!/bin/bash\ntrap 'echo term > \"" << marker.string()
                        << "\"; exit 143' TERM\necho started > \"" << (dir / "started").string()
                        << "\"\nfor i in $(seq 200); do sleep 0.05; done\n";
    fs::permissions(fake, fs::perms::owner_all);
    std::ofstream(dir / "db.sqlite") << "SQLite format 3";
    ::setenv("MHPLAN_PYTHON", fake.c_str(), 1);
    const pid_t pid = ::fork();
    if (pid == 0)
    {
        ::execl(MHPLAN_BINARY, MHPLAN_BINARY, "report", (dir / "db.sqlite").c_str(), "-o",
                (dir / "out").c_str(), static_cast<char *>(nullptr));
        ::_exit(127);
    }
    ::unsetenv("MHPLAN_PYTHON");
    for (int i = 0; i < 400 && !fs::exists(dir / "started"); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(fs::exists(dir / "started"));
    ::kill(pid, SIGTERM);
    int status = 0;
    ::waitpid(pid, &status, 0);
    for (int i = 0; i < 200 && !fs::exists(marker); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_TRUE(fs::exists(marker)) << "report.py was not told to stop";
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 143) << status;
}

TEST(CliShell, ArenaScriptPathsNeverReachAShell)
{
    const fs::path dir = scratchDir("arena_shell");
    const fs::path witness = dir / "X";
    const fs::path scripts = dir / ("a'$(touch " + witness.string() + ")'");
    fs::create_directories(scripts);
    std::ofstream(scripts / "install.sh") << "echo /nonexistent\nexit 1\n";
    const std::string db = (dir / "b.db").string();
    {
        mhplan::bench::detail::Database d(db);
        for (const char *t : {"experiments", "plannerConfigs", "runs", "progress", "enums"})
            d.exec(std::string("CREATE TABLE ") + t + " (id INTEGER)");
    }
    ::setenv("MHPLAN_ARENA_SCRIPTS", scripts.c_str(), 1);
    const auto r = mhplan::test::runCli("arena " + db + " --no-install --port 18767");
    ::unsetenv("MHPLAN_ARENA_SCRIPTS");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "Planner Arena is not available")) << r.out;
    EXPECT_FALSE(fs::exists(witness)) << "the script's path was run by a shell";
}

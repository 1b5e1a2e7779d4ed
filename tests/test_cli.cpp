// SPDX-License-Identifier: BSD-3-Clause
/* The mhplan program end to end: exit codes and messages as a user sees them. */
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using mhplan::test::contains;
using Result = mhplan::test::CliResult;

namespace
{
    Result run(const std::string &args)
    {
        return mhplan::test::runCli(args);
    }

    std::string tempPath(const std::string &name)
    {
        return testing::TempDir() + "/mhplan_cli_" + name;
    }

    /** \brief The value printed after \e key (e.g. "seed:"), up to the end of its line. */
    std::string valueAfter(const std::string &out, const std::string &key)
    {
        const auto at = out.find(key);
        if (at == std::string::npos)
            return "";
        const auto begin = out.find_first_not_of(' ', at + key.size());
        return out.substr(begin, out.find('\n', begin) - begin);
    }

    /** \brief Everything from "length:" on (the timing line comes before it). */
    std::string pathPart(const std::string &out)
    {
        const auto at = out.find("length:");
        return at == std::string::npos ? std::string() : out.substr(at);
    }

    /** \brief The states printed after "path:" (one "x y" per line), in order. */
    std::vector<std::pair<double, double>> pathStates(const std::string &out)
    {
        std::vector<std::pair<double, double>> states;
        const auto at = out.find("\npath:");
        if (at == std::string::npos)
            return states;
        std::istringstream lines(out.substr(out.find('\n', at + 1) + 1));
        std::string line;
        while (std::getline(lines, line))
        {
            std::istringstream in(line);
            double x = 0.0, y = 0.0;
            std::string rest;
            if (!(in >> x >> y) || (in >> rest))
                break;
            states.emplace_back(x, y);
        }
        return states;
    }

    /** \brief Planner settings whose run ends by itself, not by the clock, so that runs compared bit for bit
        do not depend on the machine's speed: OMPL's RRT returns at its first exact solution (so an exact
        status shows the clock did not stop it), SMA after max_iterations iterations (milliseconds). --time
        is only a safety net. */
    const std::vector<std::string> &selfEndingPlanners()
    {
        static const std::vector<std::string> planners{"--planner RRT --set range=0.5 --time 60",
                                                       "--planner SMA --set max_iterations=30 --time 60"};
        return planners;
    }
} // namespace

TEST(Cli, PlanFindsAValidPathAndWritesSvg)
{
    const std::string svg = tempPath("plan.svg");
    const Result r = run("plan bfo_case2 --planner RRTConnect --time 1 --seed 5 --svg " + svg);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "seed:      5")) << r.out;
    EXPECT_TRUE(contains(r.out, "valid:     yes")) << r.out;
    std::ifstream in(svg);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(contains(text, "<svg")) << "no svg written";
    EXPECT_TRUE(contains(text, "<polyline")) << "no path drawn";
}

TEST(Cli, SameSeedSamePath)
{
    for (const std::string &planner : selfEndingPlanners())
    {
        const Result a = run("plan bfo_case1 " + planner + " --seed 11");
        const Result b = run("plan bfo_case1 " + planner + " --seed 11");
        ASSERT_EQ(a.code, 0) << a.out;
        ASSERT_EQ(b.code, 0) << b.out;
        EXPECT_EQ(valueAfter(a.out, "status:"), "Exact solution") << planner;
        EXPECT_FALSE(pathStates(a.out).empty()) << a.out;
        EXPECT_EQ(pathPart(a.out), pathPart(b.out)) << planner; // length, gap, validity and every state
    }
}

TEST(Cli, AnotherSeedAnotherPath)
{
    // The seed matters: the same settings with seeds 11 and 12 give different paths (both valid).
    for (const std::string &planner : selfEndingPlanners())
    {
        const Result a = run("plan bfo_case1 " + planner + " --seed 11");
        const Result b = run("plan bfo_case1 " + planner + " --seed 12");
        ASSERT_EQ(a.code, 0) << a.out;
        ASSERT_EQ(b.code, 0) << b.out;
        EXPECT_EQ(valueAfter(a.out, "seed:"), "11");
        EXPECT_EQ(valueAfter(b.out, "seed:"), "12");
        const auto pa = pathStates(a.out), pb = pathStates(b.out);
        ASSERT_GE(pa.size(), 2u) << a.out;
        ASSERT_GE(pb.size(), 2u) << b.out;
        EXPECT_NE(pa, pb) << planner;
        EXPECT_NE(valueAfter(a.out, "length:"), valueAfter(b.out, "length:")) << planner;
    }
}

TEST(Cli, RefusesBadInputWithAClearMessage)
{
    struct Case
    {
        std::string args;
        std::vector<std::string> expect;
    };
    const std::vector<Case> cases = {
        {"plan bfo_case1 --planner NoSuchPlanner", {"unknown planner 'NoSuchPlanner'", "RRTstar", "PRMstar"}},
        {"plan bfo_case1 --planner RRTstar --set nonsense=1", {"no parameter 'nonsense'", "goal_bias"}},
        {"plan bfo_case1 --planner RRTstar --set goal_bias=-0.5", {"goal_bias", "out of range", ">= 0"}},
        {"plan bfo_case1 --planner RRTstar --set goal_bias", {"expected key=value"}},
        {"plan no_such_world", {"no_such_world", "no such file"}},
        {"plan bfo_case1 --colour red", {"unknown option '--colour'", "--planner"}},
        {"plan bfo_case1 --time -1", {"--time must be in [0.001, 1000000]"}},
        {"plan bfo_case1 --seed abc", {"--seed expects an integer"}},
        {"plan bfo_case1 --start 2,2 --goal 9,9", {"query 'command-line'", "start", "in collision"}},
        {"plan bfo_case1 --start 0,0", {"give both --start"}},
        {"plan bfo_case1 --query nope", {"no query named 'nope'", "default"}},
        {"plan bfo_case1 --backend magic", {"unknown collision back end 'magic'", "analytic"}},
        {"generate blobs", {"unknown kind 'blobs'", "circles"}},
        {"generate grid --density 2", {"--density must be in [0, 1)"}},
        {"generate circles --output x.map", {".map output needs a grid world"}},
        {"frobnicate", {"unknown command 'frobnicate'", "usage"}},
        {"planners NoSuchPlanner", {"unknown planner"}},
        {"optimum bfo_case1 --octile", {"--octile needs a grid world"}},
        {"optimum", {"expected exactly one WORLD"}},
    };
    for (const auto &c : cases)
    {
        const Result r = run(c.args);
        EXPECT_EQ(r.code, 1) << c.args << "\n" << r.out;
        for (const auto &e : c.expect)
            EXPECT_TRUE(contains(r.out, e)) << c.args << ": output lacks '" << e << "':\n" << r.out;
    }
}

TEST(Cli, BadWorldFileNamesFileAndLine)
{
    const std::string path = tempPath("bad.yaml");
    std::ofstream(path) << "name: bad\nbounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}\nobstacles:\n"
                           "  - circle: {center: [1, 1], radius: -3}\n";
    const Result r = run("plan " + path);
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, path + ":4")) << r.out;
    EXPECT_TRUE(contains(r.out, "obstacles[0].circle.radius")) << r.out;
}

TEST(Cli, GenerateWritesALoadableWorld)
{
    const std::string path = tempPath("gen.yaml");
    Result r = run("generate circles --count 30 --seed 3 --output " + path);
    ASSERT_EQ(r.code, 0) << r.out;
    r = run("worlds " + path);
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "circles_30_seed3")) << r.out;
    r = run("plan " + path + " --planner RRTConnect --time 1 --seed 2");
    EXPECT_EQ(r.code, 0) << r.out;
    const Result a = run("generate rectangles --count 10 --seed 9");
    const Result b = run("generate rectangles --count 10 --seed 9");
    EXPECT_EQ(a.out, b.out);
}

TEST(Cli, ListsWorldsAndPlannersWithParameters)
{
    Result r = run("worlds");
    ASSERT_EQ(r.code, 0) << r.out;
    for (const char *w : {"bfo_case1", "bfo_case2", "lrsma_scenario3"})
        EXPECT_TRUE(contains(r.out, w)) << r.out;
    r = run("planners");
    ASSERT_EQ(r.code, 0) << r.out;
    for (const char *p :
         {"RRT ", "RRTConnect", "RRTstar", "InformedRRTstar", "PRM ", "PRMstar", "BITstar", "FMTstar"})
        EXPECT_TRUE(contains(r.out, p)) << p;
    EXPECT_TRUE(contains(r.out, "range 0.:.05:1.")) << "ranges are listed";
    r = run("version");
    EXPECT_TRUE(contains(r.out, "OMPL 1.5.2")) << r.out;
}

TEST(Cli, OptimumAndGapAreReported)
{
    Result r = run("optimum bfo_case1");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "length:  14.2734")) << r.out; // docs/algorithms.md section 9
    EXPECT_TRUE(contains(r.out, "tangent-graph")) << r.out;
    r = run("optimum gms_grid10 --octile");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "grid-octile")) << r.out;
    r = run("plan bfo_case2 --planner RRTConnect --seed 4 --time 1");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "optimum:   14.4197868")) << r.out;
    EXPECT_TRUE(contains(r.out, "gap:")) << r.out;
}

// Issue 19: the defects found by trying malformed input, each refused with a clear message and rc 1.
TEST(Cli, RefusesWhatTheHardeningPassFound)
{
    const std::string dup = tempPath("dup.yaml");
    std::ofstream(dup)
        << "bounds: [0, 10, 0, 10]\nobstacles:\n  - circle: {center: [5, 5], radius: 1, radius: 2}\n";
    const std::string dupBounds = tempPath("dup_bounds.yaml");
    std::ofstream(dupBounds) << "bounds: [0, 10, 0, 10]\nname: x\nbounds: [0, 20, 0, 20]\n";
    const std::string rowsThreshold = tempPath("rows_threshold.yaml");
    std::ofstream(rowsThreshold) << "grid:\n  rows: ['....', '....']\n  threshold: 0.3\n";
    const std::string huge = tempPath("huge.yaml");
    std::ofstream(huge) << "bounds: [-1e308, 1e308, -1e308, 1e308]\nobstacles:\n"
                           "  - circle: {center: [0, 0], radius: 1e307}\n";
    const std::string tiny = tempPath("tiny.yaml");
    std::ofstream(tiny) << "bounds: [0, 1e-300, 0, 1e-300]\n";
    struct Case
    {
        std::string args;
        std::vector<std::string> expect;
    };
    const std::vector<Case> cases = {
        {"plan bfo_case1 --planner RRTstar --set range=nan", {"parameter 'range'", "out of range", "finite"}},
        {"plan bfo_case1 --planner SMA --set z=nan", {"parameter 'z'", "out of range"}},
        {"plan bfo_case1 --planner APF --set step_size=nan", {"parameter 'step_size'", "out of range"}},
        {"plan bfo_case1 --planner SMA --set population_size=2.5",
         {"population_size", "an integer in [2, 10000]"}},
        {"plan bfo_case1 --planner RRTstar --set range=1e999", {"parameter 'range'", "out of range"}},
        {"plan bfo_case1 --time inf", {"--time", "finite number", "'inf'"}},
        {"plan bfo_case1 --time nan", {"--time", "finite number"}},
        {"plan bfo_case1 --start nan,1 --goal 9,9", {"--start", "not a finite number"}},
        {"compare bfo_case1 --planners \"\"", {"--planners names no planner"}},
        {"compare bfo_case1 --planners ,", {"--planners names no planner"}},
        {"generate circles --radius 100 --bounds 0,10,0,10", {"--radius", "does not fit inside the bounds"}},
        {"generate circles --bounds 0,1e-300,0,1", {"degenerate"}},
        {"generate circles --bounds -1e308,1e308,0,10", {"within +-1e+09"}},
        {"generate grid --width 100000 --height 100000", {"grid too large", "67108864"}},
        {"generate maze --width 5000 --height 5000", {"grid cells allowed"}},
        {"plan " + dup, {dup + ":3", "duplicate key 'radius'", "first given on line 3"}},
        {"plan " + dupBounds, {dupBounds + ":3", "duplicate key 'bounds'", "first given on line 1"}},
        {"plan " + rowsThreshold, {rowsThreshold + ":3", "grid.threshold", "only to a .pgm"}},
        {"plan " + huge, {huge + ":1", "bounds", "within +-1e+09"}},
        {"optimum " + huge, {huge + ":1", "bounds"}},
        {"plan " + tiny, {tiny + ":1", "degenerate"}},
        {"plan " + testing::TempDir(), {"is a directory, not a world file"}},
    };
    for (const auto &c : cases)
    {
        const Result r = run(c.args);
        EXPECT_EQ(r.code, 1) << c.args << "\n" << r.out;
        for (const auto &e : c.expect)
            EXPECT_TRUE(contains(r.out, e)) << c.args << ": output lacks '" << e << "':\n" << r.out;
        EXPECT_FALSE(contains(r.out, "internal error")) << c.args << "\n" << r.out;
    }
    // One prefix per message.
    const Result unknown = run("worlds --nonsense");
    EXPECT_EQ(unknown.code, 1);
    EXPECT_TRUE(contains(unknown.out, "mhplan worlds: error: unknown option '--nonsense'")) << unknown.out;
    const Result gen = run("generate circles --radius 100");
    EXPECT_FALSE(contains(gen.out, "error: generate:")) << gen.out;
}

// Issue 19: the seed printed by a run without --seed is a 32-bit seed that --seed accepts and that gives the
// same run (iteration-bounded planner: no wall-clock dependence).
TEST(Cli, ThePrintedSeedReproducesTheRun)
{
    const std::string args = "plan bfo_case1 --planner SMA --time 100 --set max_iterations=30";
    const Result first = run(args);
    ASSERT_EQ(first.code, 0) << first.out;
    const std::string seed = valueAfter(first.out, "seed:");
    ASSERT_FALSE(seed.empty()) << first.out;
    const unsigned long long value = std::stoull(seed);
    EXPECT_GE(value, 1u);
    EXPECT_LE(value, 4294967295ULL);
    const Result again = run(args + " --seed " + seed);
    ASSERT_EQ(again.code, 0) << again.out;
    EXPECT_EQ(pathPart(first.out), pathPart(again.out));
    EXPECT_FALSE(pathPart(first.out).empty());

    // sim prints one seed, and it reproduces the run.
    const std::string sim = "sim mapf_2robots --controller bfo --time-limit 20";
    const Result s1 = run(sim);
    ASSERT_NE(s1.code, 1) << s1.out;
    const auto seeds = [](const std::string &out)
    {
        std::size_t n = 0;
        for (auto at = out.find("seed:"); at != std::string::npos; at = out.find("seed:", at + 1))
            ++n;
        return n;
    };
    EXPECT_EQ(seeds(s1.out), 1u) << s1.out;
    const std::string simSeed = valueAfter(s1.out, "seed:");
    const Result s2 = run(sim + " --seed " + simSeed);
    const auto table = [](const std::string &out) { return out.substr(0, out.find("wall time:")); };
    EXPECT_EQ(table(s1.out).substr(table(s1.out).find("robot ")),
              table(s2.out).substr(table(s2.out).find("robot ")));

    // compare: a printed seed that --seed accepts.
    const Result c = run("compare bfo_case1 --planners SMA --runs 1 --time 0.2");
    ASSERT_EQ(c.code, 0) << c.out;
    const std::string cs = c.out.substr(5, c.out.find(',') - 5);
    EXPECT_EQ(run("compare bfo_case1 --planners SMA --runs 1 --time 0.2 --seed " + cs).code, 0);
}

// Issue 19: a gap is printed only for an exact, collision-free path.
TEST(Cli, GapOnlyForExactValidPaths)
{
    const Result r = run("plan bfo_case1 --planner ThetaStar --set resolution=10000 --time 1");
    EXPECT_EQ(r.code, 3) << r.out;
    EXPECT_TRUE(contains(r.out, "gap:       - (no exact path)")) << r.out;
    EXPECT_FALSE(contains(r.out, " %")) << r.out;
}

TEST(Cli, ControllersListsEveryControllerWithItsParametersAndRefusesAnUnknownOne)
{
    const Result all = run("controllers");
    ASSERT_EQ(all.code, 0) << all.out;
    for (const char *name : {"dapf", "aapf", "bfo", "atbfo", "plan:"})
        EXPECT_TRUE(contains(all.out, name)) << name << " missing from:\n" << all.out;
    EXPECT_TRUE(contains(all.out, "C_a")) << all.out;
    EXPECT_TRUE(contains(all.out, "brake_margin")) << all.out;
    const Result one = run("controllers aapf");
    ASSERT_EQ(one.code, 0) << one.out;
    EXPECT_FALSE(contains(one.out, "atbfo")) << one.out;
    const Result bad = run("controllers nosuch");
    EXPECT_EQ(bad.code, 1) << bad.out;
    EXPECT_TRUE(contains(bad.out, "unknown controller 'nosuch'")) << bad.out;
}

// SPDX-License-Identifier: BSD-3-Clause
/* The mhplan program end to end: exit codes and messages as a user sees them. */
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <fstream>

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
    const Result a = run("plan bfo_case1 --planner RRT --time 0.5 --seed 11 --set range=0.5");
    const Result b = run("plan bfo_case1 --planner RRT --time 0.5 --seed 11 --set range=0.5");
    ASSERT_EQ(a.code, 0) << a.out;
    auto pathPart = [](const std::string &s) { return s.substr(s.find("length:")); };
    EXPECT_EQ(pathPart(a.out), pathPart(b.out));
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
        {"plan bfo_case1 --planner RRTstar --set goal_bias=7", {"goal_bias", "out of range", "[0., 1.]"}},
        {"plan bfo_case1 --planner RRTstar --set goal_bias", {"expected key=value"}},
        {"plan no_such_world", {"no_such_world", "no such file"}},
        {"plan bfo_case1 --colour red", {"unknown option '--colour'", "--planner"}},
        {"plan bfo_case1 --time -1", {"--time must be > 0"}},
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

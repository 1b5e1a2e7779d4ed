// SPDX-License-Identifier: BSD-3-Clause
/* The program off the plane (issue "The suite off the plane"): what a planner cannot run on is an answer
   known before anything runs (compare's n/a, plan's one refusal naming a planner that runs there), SMA's and
   LRSMA's default decoding on SE(2), the planners' spaces in `mhplan planners`, and the small things a new
   user met (generate's file name, sim's counters, --set's "not a number", version --help, --seed's help,
   compare --query, the line of a missing '}', a polygon robot's radius in `mhplan worlds`). */
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using mhplan::test::contains;
using mhplan::test::runCli;

namespace
{
    std::size_t count(const std::string &hay, const std::string &needle)
    {
        std::size_t n = 0;
        for (auto at = hay.find(needle); at != std::string::npos; at = hay.find(needle, at + needle.size()))
            ++n;
        return n;
    }

    std::string tempDir(const std::string &name)
    {
        const fs::path dir = fs::path(testing::TempDir()) / ("mhplan_offplane_" + name);
        fs::remove_all(dir);
        fs::create_directories(dir);
        return dir.string();
    }

    void write(const std::string &path, const std::string &text)
    {
        std::ofstream(path) << text;
    }
} // namespace

TEST(CliOffPlane, CompareSaysNotApplicableInsteadOfStopping)
{
    // An R^2-only planner on car and SE(2) worlds: n/a rows, the reason once per planner, the whole table.
    const auto r = runCli("compare bfo_case1 dubins_circles se2_narrow_passage --planners APF,GA,RRT "
                          "--time 0.01 --seed 1");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(count(r.out, " n/a "), 4u) << r.out; // APF and GA on the two non-planar worlds
    EXPECT_TRUE(contains(r.out, "APF plans on R^2 only")) << r.out;
    EXPECT_TRUE(contains(r.out, "GA plans on R^2 only")) << r.out;
    for (const char *world : {"bfo_case1", "dubins_circles", "se2_narrow_passage"})
    {
        EXPECT_EQ(count(r.out, std::string("\n") + world + " "), 3u) << world << "\n" << r.out;
        EXPECT_FALSE(contains(r.out, std::string(world) + "APF")) << r.out; // names never run together
    }
    EXPECT_FALSE(contains(r.out, "error")) << r.out;
}

TEST(CliOffPlane, CompareJsonMarksTheInapplicablePairsAndTakesAQuery)
{
    const auto r =
        mhplan::test::runCliStdout("compare dubins_circles --planners GA,RRT --time 0.01 --seed 1 --json");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(mhplan::test::pyJson(r.out, "[(x['planner'], x['applicable']) for x in d['results']]"),
              "[('GA', False), ('RRT', True)]");
    EXPECT_TRUE(contains(mhplan::test::pyJson(r.out, "d['results'][0]['reason']"),
                         "GA cannot run on the Dubins world 'dubins_circles': it plans on R^2 only; "))
        << r.out;

    // --query picks a world's query by name; an unknown name is refused, naming it.
    const std::string dir = tempDir("query");
    write(dir + "/two.yaml", "name: two\nbounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}\nrobot: {radius: 0}\n"
                             "obstacles: []\nqueries:\n  - {name: first, start: [1, 1], goal: [9, 9]}\n"
                             "  - {name: second, start: [1, 9], goal: [9, 1]}\n");
    const auto q = mhplan::test::runCliStdout("compare " + dir +
                                              "/two.yaml --planners RRT --time 0.01 "
                                              "--seed 1 --query second --json");
    ASSERT_EQ(q.code, 0) << q.out;
    EXPECT_EQ(mhplan::test::pyJson(q.out, "d['results'][0]['query']['name']"), "second");
    const auto bad = runCli("compare " + dir + "/two.yaml --planners RRT --time 0.01 --query third");
    EXPECT_EQ(bad.code, 1);
    EXPECT_TRUE(contains(bad.out, "third")) << bad.out;
}

TEST(CliOffPlane, PlanRefusesAnInapplicablePlannerOnceNamingOneThatRuns)
{
    const auto r = runCli("plan se2_narrow_passage --planner GA --seed 1");
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(count(r.out, "GA cannot run"), 1u) << r.out;
    EXPECT_TRUE(contains(r.out, "GA cannot run on the SE(2) world 'se2_narrow_passage': it plans on R^2 "
                                "only; "))
        << r.out;
    // ... and the planner it names runs there with its defaults (decoding auto: the space's interpolation).
    const auto l = runCli("plan se2_narrow_passage --planner LRSMA --seed 1 --set max_iterations=3 --quiet");
    EXPECT_NE(l.code, 1) << l.out;
    EXPECT_TRUE(contains(l.out, "status:")) << l.out;
    const auto s = runCli("plan dubins_circles --planner SMA --seed 1 --set max_iterations=3 --quiet");
    EXPECT_NE(s.code, 1) << s.out;
    // A refusal by the planner itself (an explicit spline on SE(2)) is printed once, without OMPL's copy.
    const auto spline =
        runCli("plan se2_narrow_passage --planner SMA --seed 1 --set decoding=spline --set max_iterations=3");
    EXPECT_EQ(spline.code, 1) << spline.out;
    EXPECT_EQ(count(spline.out, "decoding=polyline or auto"), 1u) << spline.out;
}

TEST(CliOffPlane, TheSmallThings)
{
    // --set with a word for a number.
    auto r = runCli("plan bfo_case1 --planner RRTstar --set range=abc");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "'abc' is not a number")) << r.out;
    // version --help is help.
    r = runCli("version --help");
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(contains(r.out, "usage: mhplan version")) << r.out;
    // --seed's help says what the seed reproduces.
    r = runCli("plan --help");
    EXPECT_TRUE(contains(r.out, "reproduces a run bounded")) << r.out;
    EXPECT_TRUE(contains(r.out, "a run bounded by time ends wherever the clock")) << r.out;
    // A polygon robot's radius is its reach, marked.
    r = runCli("worlds se2_narrow_passage");
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(contains(r.out, "* a polygon robot")) << r.out;
    EXPECT_FALSE(contains(r.out, " 0       ")) << r.out;
    // sim prints the controller's counters once.
    r = runCli("sim bfo_case3_lines --controller plan:RRTConnect --seed 1 --set plan_time=0.05");
    EXPECT_EQ(count(r.out, "counters:"), 1u) << r.out;
}

TEST(CliOffPlane, GenerateWritesAFileTheOtherCommandsRead)
{
    const std::string dir = tempDir("generate");
    auto r = runCli("generate circles --count 5 --seed 2 --output " + dir + "/c5");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(fs::exists(dir + "/c5.yaml"));
    EXPECT_TRUE(contains(r.out, "wrote " + dir + "/c5.yaml")) << r.out;
    r = runCli("worlds " + dir + "/c5.yaml");
    EXPECT_EQ(r.code, 0) << r.out;
    r = runCli("generate circles --output " + dir + "/c5.txt");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "'.txt' is not a world file")) << r.out;
    EXPECT_FALSE(fs::exists(dir + "/c5.txt"));
}

TEST(CliOffPlane, AMissingBraceIsReportedOnItsLine)
{
    const std::string dir = tempDir("brace");
    write(dir + "/w.yaml", "name: w\n"
                           "bounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}\n"
                           "robot: {radius: 0}\n"
                           "obstacles:\n"
                           "  - circle: {center: [5, 5], radius: 1}\n"
                           "  - circle: {center: [2, 2], radius: 1\n"
                           "queries:\n"
                           "  - {name: q, start: [1, 1], goal: [9, 9]}\n");
    const auto r = runCli("worlds " + dir + "/w.yaml");
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(contains(r.out, "w.yaml:6: malformed YAML: '{' opened on this line is not closed")) << r.out;
}

TEST(CliOffPlane, PlannersShowTheirSpacesAndOnlyTheFootersThatApply)
{
    // GA is planar (GA-MEM runs in state mode on every space since issue 31).
    EXPECT_TRUE(contains(runCli("planners GA").out, "runs on: R^2 only; anytime"));
    auto r = runCli("planners GA-MEM RRTstar");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "runs on: R^2, R^k, SE(2), Dubins, Reeds-Shepp, SE(3) (and tries other "
                                "spaces); anytime"))
        << r.out;
    EXPECT_FALSE(contains(r.out, "iterations versus max_iterations")) << r.out;
    r = runCli("planners SMA");
    EXPECT_TRUE(contains(r.out, "iterations versus max_iterations")) << r.out;
    const auto j = mhplan::test::runCliStdout("planners AStar --json");
    EXPECT_EQ(mhplan::test::pyJson(j.out, "(d['planners'][0]['spaces'], d['planners'][0]['deterministic'], "
                                          "d['planners'][0]['anytime'])"),
              "(['R^2'], True, False)");
}

TEST(CliOffPlane, PlanSvgDrawsThePolygonRobotAtStartGoalAndAlongThePath)
{
    // The bar is 2 m long and the gap 1 m wide: it starts upright and must lie down to pass. The run is
    // bounded by iterations (SMA, 100 iterations, seed 3; about 1.5 s), not by the clock, so the same path
    // and the same drawing come out on a loaded machine: footprints are drawn every 1.5 reach or 30 degrees
    // along the path, and a path planned under a time limit need not put one in the gap.
    const std::string dir = tempDir("footprints");
    const std::string svg = dir + "/p.svg";
    const auto r =
        runCli("plan se2_narrow_passage --planner SMA --set max_iterations=100 --time 120 --seed 3 "
               "--quiet --svg " +
               svg);
    ASSERT_TRUE(fs::exists(svg)) << r.out;
    std::ifstream in(svg);
    std::stringstream all;
    all << in.rdbuf();
    const std::string text = all.str();
    EXPECT_GE(count(text, "class=\"footprint\""), 5u) << text.substr(0, 2000);
    // The start's footprint: the bar upright at (2, 3), its first vertex (-1, -0.2) at (2.2, 2): 80 px/m,
    // 20 px margin, y up.
    const auto start = text.find("<title>start</title>");
    ASSERT_NE(start, std::string::npos);
    const auto startPolygon = text.rfind("<polygon class=\"footprint\"", start);
    EXPECT_TRUE(contains(text.substr(startPolygon, start - startPolygon), "points=\"196.00,340.00 "))
        << text.substr(startPolygon, start - startPolygon);
    EXPECT_TRUE(contains(text, "<title>goal</title>"));
    // Along the path: some footprint lies down (its long edge, the first, horizontal), others stand.
    int lying = 0, standing = 0;
    for (auto at = text.find("<title>pose "); at != std::string::npos; at = text.find("<title>pose ", at + 1))
    {
        const auto p = text.rfind("points=\"", at) + 8;
        double x0, y0, x1, y1;
        char comma;
        std::istringstream pts(text.substr(p, at - p));
        pts >> x0 >> comma >> y0 >> x1 >> comma >> y1;
        if (std::abs(x1 - x0) > 3.0 * std::abs(y1 - y0))
            ++lying;
        if (std::abs(y1 - y0) > 3.0 * std::abs(x1 - x0))
            ++standing;
    }
    EXPECT_GE(lying, 1) << "no footprint shows the bar turned to pass the gap";
    EXPECT_GE(standing, 1);
    fs::remove_all(dir);
}

TEST(CliOffPlane, ACampaignRefusesAnInapplicablePairOrSkipsItWhenToldAndTheReportSaysSo)
{
    // GA plans on R^2 only: paired with an SE(2) world, the campaign is refused when it is read, naming the
    // line, the pair and a planner that runs there; nothing is written. With skip_inapplicable the pair is
    // not run (no run recorded, GA still runs on the planar world) and the report lists it as skipped.
    const std::string dir = tempDir("skip");
    const std::string campaign = dir + "/c.yaml";
    const std::string body =
        "campaign: skiptest\ndatabase: " + dir + "/out/skip.db\nlogs: " + dir +
        "/out/logs\ntime_limit: 0.05\nruns: 1\nseed: 3\nworlds:\n  - se2_narrow_passage\n"
        "  - bfo_case1\nplanners:\n  - GA\n  - RRTstar\n";
    write(campaign, body);
    const auto refused = runCli("bench " + campaign);
    EXPECT_EQ(refused.code, 1) << refused.out;
    EXPECT_TRUE(contains(refused.out, "c.yaml:11: planners[0] (GA) on worlds[0] 'se2_narrow_passage'"))
        << refused.out;
    EXPECT_TRUE(contains(refused.out, "skip_inapplicable: true")) << refused.out;
    EXPECT_FALSE(fs::exists(dir + "/out/skip.db"));

    write(campaign, "skip_inapplicable: true\n" + body);
    const auto ran = runCli("bench " + campaign);
    ASSERT_EQ(ran.code, 0) << ran.out;
    EXPECT_TRUE(contains(ran.out, "skip_inapplicable")) << ran.out;
    const std::string db = dir + "/out/skip.db";
    const auto runs = [&](const std::string &world, const std::string &planner)
    {
        const std::string cmd =
            "sqlite3 " + db +
            " \"select count(*) from runs r join plannerConfigs p on r.plannerid = p.id join "
            "experiments e on r.experimentid = e.id where e.name = '" +
            world + "-default' and p.name = 'geometric_" + planner + "'\"";
        FILE *pipe = popen(cmd.c_str(), "r");
        char buf[64] = {0};
        const bool got = pipe != nullptr && std::fgets(buf, sizeof buf, pipe) != nullptr;
        if (pipe != nullptr)
            pclose(pipe);
        return got ? std::atoi(buf) : -1;
    };
    EXPECT_EQ(runs("se2_narrow_passage", "GA"), 0);
    EXPECT_EQ(runs("se2_narrow_passage", "RRTstar"), 1);
    EXPECT_EQ(runs("bfo_case1", "GA"), 1);
    EXPECT_EQ(runs("bfo_case1", "RRTstar"), 1);

    const auto report = runCli("report " + db + " -o " + dir + "/report");
    ASSERT_EQ(report.code, 0) << report.out;
    std::ifstream in(dir + "/report/index.html");
    std::stringstream html;
    html << in.rdbuf();
    EXPECT_TRUE(contains(html.str(), "skipped by the campaign's skip_inapplicable, not a failure): GA."));
}

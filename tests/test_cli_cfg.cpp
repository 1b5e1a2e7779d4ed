// SPDX-License-Identifier: BSD-3-Clause
/* mhplan plan PROBLEM.cfg and mhplan bench PROBLEM.cfg (docs/omplapp.md): a path checked densely against the
   meshes, the file's benchmark into an OMPL log and database with every run's path checked, saved paths,
   and refusals that name the file, line and key. */
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using mhplan::test::contains;
using mhplan::test::runCli;
namespace fs = std::filesystem;

namespace
{
    const std::string kDir = std::string(MHPLAN_ENVIRONMENTS_DIR) + "/omplapp/";
}

TEST(CliCfg, PlanSE2AndSE3WithDenseCheck)
{
    auto r = runCli("plan " + kDir + "bugtrap.cfg --planner KPIECE --time 5 --seed 3 --quiet");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "problem:   bugtrap (SE(2)")) << r.out;
    EXPECT_TRUE(contains(r.out, "planner:   KPIECE1")) << r.out;
    EXPECT_TRUE(contains(r.out, "status:    Exact solution")) << r.out;
    EXPECT_TRUE(contains(r.out, "valid:     yes (independent dense check")) << r.out;
    // The file's first planner (rrtconnect) by default; the path written as states.
    const std::string path = (fs::temp_directory_path() / "mhplan_cli_cfg.path").string();
    r = runCli("plan " + kDir + "passage.cfg --seed 4 --quiet --validator discrete --path " + path);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "(SE(3)")) << r.out;
    EXPECT_TRUE(contains(r.out, "planner:   RRTConnect")) << r.out;
    EXPECT_TRUE(contains(r.out, "OMPL's discrete validator")) << r.out;
    std::ifstream in(path);
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    std::istringstream first(line);
    double x = 0;
    first >> x;
    EXPECT_NEAR(x, -3.0, 1e-9) << line; // the start's x; then y z and the quaternion
}

TEST(CliCfg, BenchWritesLogDatabaseAndShortestPaths)
{
    const fs::path dir = fs::temp_directory_path() / "mhplan_cli_cfg_bench";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // The shipped problem with its own [benchmark] (save_paths = shortest), 2 runs of 0.5 s.
    const auto r = runCli("bench " + kDir + "passage.cfg --runs 2 --time 0.5 --seed 5 --no-progress --logs " +
                          dir.string());
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "RRTConnect")) << r.out;
    EXPECT_TRUE(contains(r.out, "BKPIECE1")) << r.out;
    EXPECT_TRUE(contains(r.out, "0 invalid")) << r.out;
    EXPECT_TRUE(fs::exists(dir / "passage.log"));
    EXPECT_TRUE(fs::exists(dir / "passage.db"));
    std::size_t paths = 0;
    for (const auto &e : fs::directory_iterator(dir))
        paths += e.path().extension() == ".path" ? 1 : 0;
    EXPECT_EQ(paths, 2u) << "one shortest path per planner";
    std::ifstream log(dir / "passage.log");
    const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(contains(text, "dense check valid BOOLEAN")) << "every run's check is recorded";
}

TEST(CliCfg, RefusalsNameTheFileLineAndKey)
{
    const fs::path dir = fs::temp_directory_path() / "mhplan_cli_cfg_bad";
    fs::create_directories(dir);
    const std::string head =
        "[problem]\nworld = " + kDir + "bugtrap_env.obj\nrobot = " + kDir +
        "bar_robot.dae\nstart.x=0\nstart.y=0\nstart.theta=0\ngoal.x=0\ngoal.y=6\ngoal.theta=0\n";
    const auto write = [&](const std::string &name, const std::string &text)
    {
        std::ofstream((dir / name).string()) << text;
        return (dir / name).string();
    };
    std::string f = write("p1.cfg", head + "[planner]\nkpiece =\nkpiece.rnage = 3\n");
    auto r = runCli("plan " + f);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_TRUE(contains(r.out, f + ":12: key 'planner.kpiece.rnage'")) << r.out;
    EXPECT_TRUE(contains(r.out, "no parameter 'rnage'")) << r.out;
    f = write("p2.cfg", head + "[planner]\nnosuchplanner =\n");
    r = runCli("bench " + f + " --runs 1 --time 0.1");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_TRUE(contains(r.out, f + ":11: key 'planner.nosuchplanner': unknown planner")) << r.out;
    f = write("p3.cfg", head + "control = dynamic_car\n");
    r = runCli("plan " + f);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_TRUE(contains(r.out, f + ":10: key 'problem.control'")) << r.out;
    f = write("p4.cfg", head + "[planner]\nrrt =\n");
    r = runCli("bench " + f);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_TRUE(contains(r.out, "key 'benchmark.time_limit' is missing")) << r.out;
    f = write("p5.cfg", head + "[planner]\nrrtstar =\nrrtstar.range = 20000\nrrtstar.rewire_factor = 2.5\n");
    r = runCli("plan " + f + " --time 0.2 --quiet");
    EXPECT_NE(r.code, 1) << "OMPL's suggestions are hints: " << r.out;
}

TEST(CliCfg, SvgFromAboveAndMeshExport)
{
    // plan --svg: the problem from above (environment, start, goal), the path and the robot's footprint.
    const std::string svg = (fs::temp_directory_path() / "mhplan_cli_cfg.svg").string();
    fs::remove(svg);
    auto r = runCli("plan " + kDir + "bugtrap.cfg --planner BITstar --time 2 --seed 3 --quiet --svg " + svg);
    EXPECT_EQ(r.code, 0) << r.out;
    std::ifstream in(svg);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char *cls : {"class=\"environment\"", "class=\"path\"", "class=\"start\"", "class=\"goal\""})
        EXPECT_TRUE(contains(text, cls)) << cls;
    std::size_t footprints = 0;
    for (std::size_t at = text.find("class=\"footprint\""); at != std::string::npos;
         at = text.find("class=\"footprint\"", at + 1))
        ++footprints;
    EXPECT_GE(footprints, 3u) << "at the first and last pose and along the 6 m";
    // worlds PROBLEM.cfg --json: the meshes as planned on (60 + 12 triangles), the robot centred.
    r = runCli("worlds " + kDir + "bugtrap.cfg --json");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "\"space\": \"se2\"")) << r.out.substr(0, 400);
    EXPECT_TRUE(contains(r.out, "\"environment\"")) << r.out.substr(0, 400);
    r = runCli("worlds " + kDir + "passage.cfg");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "passage\tse3\t48 environment triangles\t12 robot triangles")) << r.out;
}

// SPDX-License-Identifier: BSD-3-Clause
/* Simulation experiments in campaigns: parsed and refused with file:line, their rows carry exactly what an
   independent run of the simulator with the same seed and start perturbation returns; a hanging simulation
   run is killed and recorded as Crash; plan:<P> controllers draw from the campaign's registry. */
#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"
#include "CliSupport.h"
#include "BenchSupport.h"
#include "src/sim/Controllers.h"
#include "ompl_planners/lattice/ThetaStar.h"
#include "src/registry/Registry.h"
#include "src/sim/ScenarioIO.h"
#include "src/sim/Simulation.h"
#include "src/base/World.h"
#include "benchmarks/Improvements.h"

#include <ompl/base/Planner.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

using namespace mhplan;
using namespace mhplan::bench;
namespace ob = ompl::base;
namespace fs = std::filesystem;

using namespace mhplan::test;

// --- simulation experiments ------------------------------------------------------------------------------

namespace
{
    std::string campaignError(const std::string &text)
    {
        try
        {
            parseCampaign(text, "bad.yaml");
        }
        catch (const InputError &e)
        {
            return std::string(e.what());
        }
        return std::string();
    }

    /** The error of running \e c (enumeration and checks happen before anything runs). */
    std::string runError(const Campaign &c)
    {
        try
        {
            runCampaign(c, options());
        }
        catch (const InputError &e)
        {
            return std::string(e.what());
        }
        return std::string();
    }

    /** A campaign of one planning experiment (bfo_case1, RRT*, one run) and one simulation experiment
        (mapf_2robots, dapf and aapf, two runs with perturbed starts). */
    Campaign simCampaign(const std::string &tag)
    {
        Campaign c = parseCampaign("campaign: simtiny\n"
                                   "time_limit: 0.02\n"
                                   "runs: 1\n"
                                   "seed: 5\n"
                                   "worlds: [bfo_case1]\n"
                                   "planners: [RRTstar]\n"
                                   "simulations:\n"
                                   "  - scenario: scenarios/mapf_2robots\n"
                                   "    runs: 2\n"
                                   "    start_jitter: 0.05\n"
                                   "    heading_jitter: 0.2\n"
                                   "    controllers:\n"
                                   "      - dapf\n"
                                   "      - {controller: aapf, name: aapf}\n",
                                   "simtiny.yaml");
        const fs::path dir =
            fs::temp_directory_path() / ("mhplan_test_bench_sim_" + std::to_string(::getpid())) / tag;
        fs::remove_all(dir);
        fs::create_directories(dir);
        c.database = (dir / "sim.db").string();
        c.logDir = (dir / "logs").string();
        return c;
    }
} // namespace

TEST(Campaign, ParsesSimulationsAndRefusesBadEntriesWithFileAndLine)
{
    const Campaign c = parseCampaign("simulations:\n"
                                     "  - scenario: scenarios/mapf_2robots\n"
                                     "    runs: 4\n"
                                     "    seed: 9\n"
                                     "    start_jitter: 0.1\n"
                                     "    controllers:\n"
                                     "      - dapf\n"
                                     "      - {controller: aapf, name: aapf_b, params: {}}\n",
                                     "sim.yaml");
    EXPECT_TRUE(c.worlds.empty());
    EXPECT_TRUE(c.planners.empty());
    ASSERT_EQ(c.simulations.size(), 1u);
    const SimulationSpec &s = c.simulations[0];
    EXPECT_EQ(s.scenario, "scenarios/mapf_2robots");
    EXPECT_EQ(s.runs, 4u);
    EXPECT_EQ(s.seed, 9u);
    EXPECT_DOUBLE_EQ(s.startJitter, 0.1);
    EXPECT_EQ(s.line, 2);
    ASSERT_EQ(s.controllers.size(), 2u);
    EXPECT_EQ(s.controllers[0].displayName, "dapf");
    EXPECT_EQ(s.controllers[1].controller, "aapf");
    EXPECT_EQ(s.controllers[1].displayName, "aapf_b");
    EXPECT_EQ(s.controllers[1].line, 8);
    const auto all = enumerateExperiments(c, resolveShipped);
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0].name, "mapf_2robots-sim");
    EXPECT_EQ(all[0].runs, 4u);
    EXPECT_EQ(all[0].scenarioName, "mapf_2robots");
    EXPECT_NE(all[0].simulation, Experiment::kNoSimulation);

    const std::string head = "simulations:\n  - scenario: scenarios/mapf_2robots\n";
    auto e = campaignError(head + "    controllers: [dapf, nosuch]\n");
    EXPECT_NE(e.find("bad.yaml:3:"), std::string::npos) << e;
    EXPECT_NE(e.find("unknown controller 'nosuch'"), std::string::npos) << e;
    EXPECT_NE(e.find("aapf"), std::string::npos) << e; // the known names are listed
    e = campaignError(head + "    controllers: [dapf]\n    runz: 3\n");
    EXPECT_NE(e.find("bad.yaml:4:"), std::string::npos) << e;
    EXPECT_NE(e.find("unknown key 'runz'"), std::string::npos) << e;
    e = campaignError(head + "    controllers: [dapf]\n    runs: 0\n");
    EXPECT_NE(e.find("bad.yaml:4:"), std::string::npos) << e;
    EXPECT_NE(e.find("simulations[0].runs"), std::string::npos) << e;
    e = campaignError(head + "    runs: 2\n");
    EXPECT_NE(e.find("bad.yaml:2:"), std::string::npos) << e;
    EXPECT_NE(e.find("simulations[0].controllers"), std::string::npos) << e;
    e = campaignError(head + "    controllers: [dapf, dapf]\n");
    EXPECT_NE(e.find("duplicate controller name 'dapf'"), std::string::npos) << e;
    e = campaignError(head + "    controllers: [dapf]\n    start_jitter: -1\n");
    EXPECT_NE(e.find("simulations[0].start_jitter"), std::string::npos) << e;
    e = campaignError("simulations:\n  - controllers: [dapf]\n");
    EXPECT_NE(e.find("simulations[0].scenario"), std::string::npos) << e;
    e = campaignError("simulations: {scenario: x}\n");
    EXPECT_NE(e.find("bad.yaml:1:"), std::string::npos) << e;
    // Planning experiments need both worlds and planners, also beside simulations.
    e = campaignError("worlds: [bfo_case1]\nsimulations:\n  - {scenario: x, controllers: [dapf]}\n");
    EXPECT_NE(e.find("field 'planners': missing"), std::string::npos) << e;

    // A missing scenario and a bad controller parameter: refused before anything runs, with file:line.
    Campaign bad =
        parseCampaign("simulations:\n  - {scenario: no_such_scenario, controllers: [dapf]}\n", "bad.yaml");
    bad.database =
        (fs::temp_directory_path() / ("mhplan_test_bench_bad_" + std::to_string(::getpid())) / "bad.db")
            .string();
    bad.logDir = bad.database + ".logs";
    e = runError(bad);
    EXPECT_NE(e.find("bad.yaml:2: simulations[0]"), std::string::npos) << e;
    EXPECT_NE(e.find("no_such_scenario"), std::string::npos) << e;
    bad.simulations[0].scenario = "scenarios/mapf_2robots";
    bad.simulations[0].controllers[0].params["no_such_parameter"] = "1";
    e = runError(bad);
    EXPECT_NE(e.find("bad.yaml:2: simulations[0].controllers[0] (dapf)"), std::string::npos) << e;
    EXPECT_NE(e.find("no_such_parameter"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(bad.database));
}

TEST(SimulationCampaign, RowsCarryTheValuesTheSimulationReturns)
{
    const Campaign c = simCampaign("values");
    const CampaignSummary summary = runCampaign(c, options(2));
    ASSERT_EQ(summary.failed, 0u) << (summary.errors.empty() ? "" : summary.errors[0]);
    EXPECT_EQ(summary.experiments, 2u);
    EXPECT_EQ(summary.runs, 1u + 2u * 2u);
    EXPECT_EQ(summary.crashes, 0u);
    EXPECT_EQ(summary.mergedLogs, 2u);

    // Planning and simulation experiments in their own databases (sim.db and sim-sim.db), so that Planner
    // Arena shows each kind's columns only: one experiment per scenario in the simulation database.
    ASSERT_EQ(simulationDatabaseFile(c), (fs::path(c.database).parent_path() / "sim-sim.db").string());
    const Sql planning(c.database);
    EXPECT_EQ(planning.count("SELECT count(*) FROM experiments"), 1);
    EXPECT_EQ(
        planning.count("SELECT count(*) FROM experiments WHERE kind = 'planning' AND world = 'bfo_case1'"),
        1);
    const Sql sql(simulationDatabaseFile(c));
    EXPECT_EQ(sql.count("SELECT count(*) FROM experiments"), 1);
    const auto exp = sql.rows("SELECT name, scenario, robot_count, moving_obstacle_count, "
                              "reference_traversal_time_reduction_percent, kind, version, start_jitter "
                              "FROM experiments WHERE kind = 'simulation'");
    ASSERT_EQ(exp.size(), 1u);
    EXPECT_EQ(exp[0][0], "mapf_2robots-sim");
    EXPECT_EQ(exp[0][1], "mapf_2robots");
    EXPECT_EQ(exp[0][2], "2");
    EXPECT_EQ(exp[0][3], "0");
    EXPECT_DOUBLE_EQ(std::atof(exp[0][4].c_str()), 35.0);
    EXPECT_EQ(exp[0][6].rfind("OMPL 1.", 0), 0u) << exp[0][6];
    // Neither database carries the other kind's experiment columns (Planner Arena's "Problem parameters").
    const std::set<std::string> planningColumns = planning.columns("experiments");
    for (const char *col : {"scenario", "robot_count", "start_jitter"})
        EXPECT_EQ(planningColumns.count(col), 0u) << "planning experiments have the column " << col;
    EXPECT_EQ(sql.columns("experiments").count("world_file"), 0u);
    EXPECT_EQ(planningColumns.count("world_file"), 1u);
    // Planner Arena joins runs with experiments: no run property may repeat an experiment column.
    const std::set<std::string> expColumns = sql.columns("experiments");
    for (const std::string &col : sql.columns("runs"))
    {
        if (col != "id")
        {
            EXPECT_EQ(expColumns.count(col), 0u) << "runs." << col << " repeats an experiments column";
        }
    }
    // Status descriptions are OMPL's.
    const std::string exact =
        sql.rows("SELECT value FROM enums WHERE name = 'status' AND description = 'Exact solution'")
            .at(0)
            .at(0);

    // Every row against an independent run of the simulator with the same seed and perturbation.
    const auto experiments = enumerateExperiments(c, resolveShipped);
    ASSERT_EQ(experiments.size(), 2u);
    const Experiment &e = experiments[1];
    const Scenario scenario = loadScenario(e.scenarioFile);
    std::size_t checked = 0;
    std::set<std::string> makespans;
    for (const std::string controller : {"dapf", "aapf"})
        for (std::size_t k = 0; k < 2; ++k)
        {
            const auto rows = sql.rows(
                "SELECT runs.run_seed, runs.start_seed, runs.status, runs.solved, runs.makespan, "
                "runs.flowtime, "
                "runs.mean_traversal_time, runs.collisions, runs.static_collisions, runs.moving_collisions, "
                "runs.robot_collisions, runs.robots_stuck, runs.robots_done, runs.min_robot_distance, "
                "runs.min_obstacle_clearance, runs.total_path_length, runs.robot_steps, runs.steps, "
                "runs.robot_steps_per_second, runs.time FROM runs JOIN plannerConfigs ON runs.plannerid = "
                "plannerConfigs.id JOIN experiments ON runs.experimentid = experiments.id WHERE "
                "experiments.kind = 'simulation' AND plannerConfigs.name = 'sim:" +
                controller + "' AND runs.run_index = " + std::to_string(k));
            ASSERT_EQ(rows.size(), 1u) << controller << " run " << k;
            const auto &r = rows[0];
            const std::uint32_t seed = simulationRunSeed(e, controller, k);
            const std::uint32_t startSeed = simulationStartSeed(e, k);
            EXPECT_EQ(r[0], std::to_string(seed));
            EXPECT_EQ(r[1], std::to_string(startSeed));
            Scenario s = scenario;
            applyStartJitter(s, 0.05, 0.2, startSeed);
            EXPECT_NE(distance(s.robots[0].start, scenario.robots[0].start), 0.0);
            EXPECT_LE(distance(s.robots[0].start, scenario.robots[0].start), 0.05);
            Simulation sim(s, makeController(controller), seed);
            const SimulationResult res = sim.run();
            const auto near = [](const std::string &stored, double expected)
            {
                if (!std::isfinite(expected))
                    return stored == "NULL";
                return std::abs(std::atof(stored.c_str()) - expected) <=
                       1e-12 * std::max(1.0, std::abs(expected));
            };
            double traversal = 0.0, length = 0.0;
            for (const auto &rr : res.robots)
            {
                traversal += rr.traversalTime;
                length += rr.pathLength;
            }
            EXPECT_EQ(r[2] == exact, res.allDone) << controller << " run " << k;
            EXPECT_EQ(r[3], res.allDone ? "1" : "0");
            EXPECT_TRUE(near(r[4], res.makespan)) << r[4] << " vs " << res.makespan;
            EXPECT_TRUE(near(r[5], res.flowtime)) << r[5] << " vs " << res.flowtime;
            EXPECT_TRUE(near(r[6], traversal / static_cast<double>(res.robots.size()))) << r[6];
            EXPECT_EQ(r[7], std::to_string(res.collisions()));
            EXPECT_EQ(r[8], std::to_string(res.staticCollisions));
            EXPECT_EQ(r[9], std::to_string(res.movingCollisions));
            EXPECT_EQ(r[10], std::to_string(res.robotCollisions));
            EXPECT_EQ(r[11], std::to_string(res.stuck));
            EXPECT_EQ(r[12], std::to_string(res.done));
            EXPECT_TRUE(near(r[13], res.minRobotDistance)) << r[13];
            EXPECT_TRUE(near(r[14], res.minObstacleClearance)) << r[14];
            EXPECT_TRUE(near(r[15], length)) << r[15];
            EXPECT_EQ(r[16], std::to_string(res.robotSteps));
            EXPECT_EQ(r[17], std::to_string(res.steps));
            EXPECT_GT(std::atof(r[18].c_str()), 0.0);
            EXPECT_GT(std::atof(r[19].c_str()), 0.0);
            makespans.insert(r[4]);
            ++checked;
        }
    EXPECT_EQ(checked, 4u);
    EXPECT_GE(makespans.size(), 2u); // the perturbed starts make the runs differ
    // The controllers' settings are their planner configurations.
    EXPECT_EQ(sql.count("SELECT count(*) FROM plannerConfigs WHERE name = 'sim:aapf' AND settings LIKE "
                        "'%controller = aapf%'"),
              1);

    // Resume: a second call finds every experiment complete.
    const CampaignSummary again = runCampaign(c, options());
    EXPECT_EQ(again.skipped, 2u);
    EXPECT_EQ(again.runs, 0u);
    EXPECT_EQ(again.mergedLogs, 0u);
    fs::remove_all(fs::temp_directory_path() / ("mhplan_test_bench_sim_" + std::to_string(::getpid())));
}

TEST(SimulationCampaign, PlanControllersDrawFromTheCampaignsRegistry)
{
    const std::string text = "campaign: ownplanner\n"
                             "simulations:\n"
                             "  - scenario: scenarios/mapf_2robots\n"
                             "    runs: 1\n"
                             "    controllers: [plan:ThetaStarHere]\n";
    // The built-in registry does not know the planner: the campaign file is refused, naming the controller.
    try
    {
        parseCampaign(text, "own.yaml");
        ADD_FAILURE() << "no InputError";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("plan:ThetaStarHere"), std::string::npos) << e.what();
    }
    Campaign c = parseCampaign(text, "own.yaml", testRegistry());
    ASSERT_EQ(c.simulations.size(), 1u);
    const fs::path dir = fs::temp_directory_path() / ("mhplan_test_bench_own_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    c.database = (dir / "own.db").string();
    c.logDir = (dir / "logs").string();
    const CampaignSummary summary = runCampaign(c, options());
    ASSERT_EQ(summary.failed, 0u) << (summary.errors.empty() ? "" : summary.errors[0]);
    EXPECT_EQ(summary.runs, 1u);
    EXPECT_EQ(summary.crashes, 0u);
    const Sql sql(c.database);
    const auto rows = sql.rows("SELECT runs.solved FROM runs JOIN plannerConfigs ON "
                               "runs.plannerid = plannerConfigs.id WHERE plannerConfigs.name LIKE "
                               "'%ThetaStarHere%'");
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0][0], "1");
    fs::remove_all(dir);
}

TEST(SimulationCampaign, StartJitterIsDeterministicAndValid)
{
    const Scenario base = loadScenario(resolveShipped("scenarios/mapf_15robots"));
    Scenario a = base, b = base, z = base;
    applyStartJitter(a, 0.3, 0.5, 11);
    applyStartJitter(b, 0.3, 0.5, 11);
    applyStartJitter(z, 0.0, 0.0, 11);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < base.robots.size(); ++i)
    {
        EXPECT_EQ(a.robots[i].start.x, b.robots[i].start.x);
        EXPECT_EQ(a.robots[i].heading, b.robots[i].heading);
        EXPECT_EQ(z.robots[i].start.x, base.robots[i].start.x);
        EXPECT_LE(distance(a.robots[i].start, base.robots[i].start), 0.3 + 1e-12);
        EXPECT_LE(std::abs(a.robots[i].heading - base.robots[i].heading), 0.5 + 1e-12);
        moved += distance(a.robots[i].start, base.robots[i].start) > 0.0 ? 1 : 0;
        for (std::size_t j = 0; j < i; ++j)
            EXPECT_GE(distance(a.robots[i].start, a.robots[j].start),
                      a.robots[i].radius + a.robots[j].radius);
    }
    EXPECT_GT(moved, base.robots.size() / 2);
    // The perturbed scenario is still a valid scenario: a simulation accepts it.
    Simulation sim(a, makeController("aapf"), 1);
    EXPECT_TRUE(sim.step());
}

TEST(SimulationCampaign, AHangingRunIsKilledAndRecordedAsCrash)
{
    // Plan-then-follow with RRT* planning 5 s per robot: 15 robots take over a minute, and no run of it can
    // end before the first plan's 5 s; the wall limit (4 s, the watchdog looks every 0.2 s) kills it and the
    // campaign goes on with the next controller. The limit covers dapf's run too: measured 0.18 s of wall
    // time in a release build on a loaded machine (3-5 times more with the sanitizers), so 4 s leaves it
    // a margin that a limit below the watchdog's first look (the former 0.05 s) did not.
    Campaign c = parseCampaign("campaign: hang\n"
                               "runs: 1\n"
                               "simulations:\n"
                               "  - scenario: scenarios/mapf_15robots\n"
                               "    wall_limit: 4\n"
                               "    controllers:\n"
                               "      - {controller: plan:RRTstar, name: slow, params: {plan_time: 5}}\n"
                               "      - dapf\n",
                               "hang.yaml");
    const fs::path dir = fs::temp_directory_path() / ("mhplan_test_bench_hang_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    c.database = (dir / "hang.db").string();
    c.logDir = (dir / "logs").string();
    const CampaignSummary s = runCampaign(c, options());
    EXPECT_EQ(s.completed, 1u);
    EXPECT_EQ(s.runs, 2u);
    EXPECT_EQ(s.crashes, 1u);
    const Sql sql(c.database);
    const std::string crash =
        sql.rows("SELECT value FROM enums WHERE name = 'status' AND description = 'Crash'").at(0).at(0);
    const auto rows =
        sql.rows("SELECT plannerConfigs.name, runs.status, runs.solved, runs.makespan FROM runs JOIN "
                 "plannerConfigs ON runs.plannerid = plannerConfigs.id ORDER BY plannerConfigs.name");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0][0], "sim:dapf");
    EXPECT_NE(rows[0][1], crash);
    EXPECT_NE(rows[0][3], "NULL");
    EXPECT_EQ(rows[1][0], "sim:slow");
    EXPECT_EQ(rows[1][1], crash);
    EXPECT_EQ(rows[1][2], "0");
    EXPECT_EQ(rows[1][3], "NULL");
    fs::remove_all(dir);
}

TEST(Campaign, SimulationsGoToTheirOwnDatabaseByDefault)
{
    const std::string sims = "simulations:\n  - {scenario: scenarios/mapf_2robots, controllers: [dapf]}\n";
    const std::string planning = "worlds: [bfo_case1]\nplanners: [RRTstar]\n";
    // Planning and simulation experiments: "-sim" before the extension, in the database's directory.
    Campaign c = parseCampaign("campaign: both\ndatabase: results/both.db\n" + planning + sims, "both.yaml");
    EXPECT_EQ(simulationDatabaseFile(c), "results/both-sim.db");
    c.database = "plain.sqlite";
    EXPECT_EQ(simulationDatabaseFile(c), "plain-sim.sqlite");
    // Simulations only: one database, the campaign's.
    c = parseCampaign("campaign: only\n" + sims, "only.yaml");
    EXPECT_EQ(simulationDatabaseFile(c), "only.db");
    // Named in the campaign file: used as it is.
    c = parseCampaign("campaign: named\nsimulation_database: moving.db\n" + planning + sims, "named.yaml");
    EXPECT_EQ(simulationDatabaseFile(c), "moving.db");
    EXPECT_THROW(parseCampaign("simulation_database: ''\n" + planning + sims, "empty.yaml"), InputError);
}

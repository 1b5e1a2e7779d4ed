// SPDX-License-Identifier: BSD-3-Clause
/* OMPL.app's .cfg problem files (docs/omplapp.md): the keys read as OMPL.app's benchmark program reads them,
   every refusal naming the file, line and key, and the problems of environments/omplapp solved by OMPL's
   planners with paths that pass the independent dense check. */
#include "src/base/World.h"
#include "src/io/CfgIO.h"
#include "src/registry/Registry.h"

#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace mhplan;
namespace ob = ompl::base;

namespace
{
    const std::string kDir = std::string(MHPLAN_ENVIRONMENTS_DIR) + "/omplapp/";

    std::string errorOf(const std::string &text)
    {
        try
        {
            parseCfg(text, "/x/p.cfg");
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "";
    }

    const std::string kSE2 = "[problem]\nworld = env.dae\nrobot = robot.dae\nstart.x = 1\nstart.y = 2\n"
                             "start.theta = 0.5\ngoal.x = 3\ngoal.y = 4\ngoal.theta = 0\n";
} // namespace

TEST(Cfg, SE2ProblemBenchmarkAndPlanners)
{
    const CfgProblem p =
        parseCfg(kSE2 + "threshold = 0.01\n[benchmark]\ntime_limit = 5\nmem_limit=100\n"
                        "run_count = 3\nsave_paths = shortest\nsimplify = 0\n"
                        "[planner]\nrrtconnect.range = 50\nrrtconnect =\nrrtconnect.range = 100\nkpiece =\n"
                        "problem.longest_valid_segment_fraction = 0.2\n"
                        "kpiece.name = My KPIECE\nKPIECE.problem.sampler = gaussian\n",
                 "/x/p.cfg");
    EXPECT_FALSE(p.se3);
    EXPECT_EQ(p.name, "p");
    EXPECT_EQ(p.world, "/x/env.dae");
    EXPECT_EQ(p.robot, "/x/robot.dae");
    EXPECT_TRUE(p.start.position.isApprox(Eigen::Vector3d(1, 2, 0)));
    EXPECT_NEAR(Eigen::AngleAxisd(p.start.orientation).angle(), 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(p.threshold, 0.01);
    EXPECT_FALSE(p.volume.has_value());
    EXPECT_EQ(*p.timeLimit, 5.0);
    EXPECT_EQ(*p.runCount, 3u);
    EXPECT_EQ(p.savePaths, "shortest");
    EXPECT_FALSE(p.simplify);
    // OMPL.app's instance rules: NAME.PARAM creates an instance when there is none, NAME= always creates
    // one, later NAME.PARAM lines set the last instance; problem.KEY before a planner is that planner's.
    ASSERT_EQ(p.planners.size(), 3u);
    EXPECT_EQ(p.planners[0].name, "rrtconnect");
    EXPECT_EQ(p.planners[0].params.at("range").value, "50");
    EXPECT_EQ(p.planners[1].params.at("range").value, "100");
    EXPECT_EQ(p.planners[1].params.at("range").line, 20);
    EXPECT_EQ(p.planners[2].name, "kpiece");
    EXPECT_EQ(p.planners[2].context.at("longest_valid_segment_fraction").value, "0.2");
    EXPECT_EQ(p.planners[2].context.at("sampler").value, "gaussian");
    EXPECT_EQ(p.planners[2].displayName, "My KPIECE");
}

TEST(Cfg, SE3WhenZOrAxisKeysAreGiven)
{
    const CfgProblem p = parseCfg(
        "[problem]\nworld=/abs/env.stl\nrobot=r.ply\nstart.x=0\nstart.y=0\nstart.z=1\nstart.theta=1\n"
        "start.axis.x=0\nstart.axis.y=2\nstart.axis.z=0\ngoal.x=1\ngoal.y=1\ngoal.z=1\ngoal.theta=0\n"
        "goal.axis.x=0\ngoal.axis.y=0\ngoal.axis.z=1\nvolume.min.x=-1\nvolume.min.y=-2\nvolume.min.z=-3\n"
        "volume.max.x=1\nvolume.max.y=2\nvolume.max.z=3\nobjective = max_min_clearance\n"
        "objective.threshold = 0.5\nmotion_validator = discrete\n",
        "rel/p.cfg");
    EXPECT_TRUE(p.se3);
    EXPECT_EQ(p.world, "/abs/env.stl");
    EXPECT_EQ(p.robot, "rel/r.ply");
    const Eigen::AngleAxisd aa(p.start.orientation);
    EXPECT_NEAR(aa.angle(), 1.0, 1e-12);
    EXPECT_TRUE(aa.axis().isApprox(Eigen::Vector3d::UnitY()));
    ASSERT_TRUE(p.volume.has_value());
    EXPECT_TRUE(p.volume->min().isApprox(Eigen::Vector3d(-1, -2, -3)));
    EXPECT_EQ(p.objective, "max_min_clearance");
    EXPECT_DOUBLE_EQ(p.objectiveThreshold, 0.5);
    EXPECT_EQ(p.motionValidator, "discrete");
}

TEST(Cfg, CarStateSpacesOfPlanarProblems)
{
    // OMPL.app's statespace and turningradius keys: a Dubins or Reeds-Shepp car in the plane.
    CfgProblem p = parseCfg(kSE2 + "statespace = Dubins\nturningradius = 0.75\n", "/x/p.cfg");
    EXPECT_EQ(p.car, "dubins");
    EXPECT_DOUBLE_EQ(p.turningRadius, 0.75);
    p = parseCfg(kSE2 + "statespace = reeds_shepp\n", "/x/p.cfg");
    EXPECT_EQ(p.car, "reeds_shepp");
    EXPECT_DOUBLE_EQ(p.turningRadius, 1.0);
    ASSERT_FALSE(p.notes.empty()) << "the default turning radius is said";
    EXPECT_NE(p.notes.back().find("turning radius 1"), std::string::npos) << p.notes.back();
    EXPECT_TRUE(parseCfg(kSE2 + "statespace = se2\n", "/x/p.cfg").car.empty());
}

TEST(Cfg, RefusalsNameFileLineAndKey)
{
    struct Case
    {
        std::string text;
        std::string expect;
    };
    const std::vector<Case> cases = {
        {kSE2 + "control = kinematic_car\n", "/x/p.cfg:10: key 'problem.control': control-based problems"},
        {kSE2 + "objective = mechanical_work\n", "/x/p.cfg:10: key 'problem.objective': objective "
                                                 "'mechanical_work' is not supported; accepted: length, "
                                                 "max_min_clearance"},
        {kSE2 + "start.x = 2\n", "/x/p.cfg:10: key 'problem.start.x': given twice (first on line 4)"},
        {kSE2 + "start.q = 2\n", "/x/p.cfg:10: key 'problem.start.q': unknown pose key"},
        {kSE2 + "threshold = abc\n",
         "/x/p.cfg:10: key 'problem.threshold': expected a finite number, got 'abc'"},
        {kSE2 + "volume.min.x = 0\n",
         "/x/p.cfg: key 'problem.volume.min.y' is missing: give the whole volume or none"},
        {kSE2 + "volume.min.w = 0\n", "/x/p.cfg:10: key 'problem.volume.min.w': unknown volume key"},
        {kSE2 + "start.z = 0\n", "/x/p.cfg: key 'problem.start.axis.x' is missing: an SE(3) problem"},
        {kSE2 + "turningradius = 1\n", "/x/p.cfg:10: key 'problem.turningradius': only a car has a turning"},
        {kSE2 + "statespace = dubins\nturningradius = 0\n",
         "/x/p.cfg:11: key 'problem.turningradius': must be > 0"},
        {kSE2 + "statespace = kinematic_car\n",
         "/x/p.cfg:10: key 'problem.statespace': state space "
         "'kinematic_car' is not supported for this problem; accepted: "
         "se2, dubins, reedsshepp"},
        {kSE2 + "motion_validator = exact\n",
         "/x/p.cfg:10: key 'problem.motion_validator': expected certified or discrete"},
        {kSE2 + "[benchmark]\nrun_count = 2.5\n",
         "/x/p.cfg:11: key 'benchmark.run_count': expected an integer"},
        {kSE2 + "[benchmark]\ntime_limit = -1\n", "/x/p.cfg:11: key 'benchmark.time_limit': must be > 0"},
        {kSE2 + "[benchmark]\nspeed = 3\n",
         "/x/p.cfg:11: key 'benchmark.speed': unknown key; accepted: mem_limit"},
        {kSE2 + "[benchmark]\nsave_paths = some\n", "/x/p.cfg:11: key 'benchmark.save_paths': expected all"},
        {kSE2 + "[extras]\n", "/x/p.cfg:10: unknown section [extras]"},
        {"world = x\n", "/x/p.cfg:1: a key before any section"},
        {kSE2 + "just words\n", "/x/p.cfg:10: expected KEY = VALUE"},
        {"[problem]\nrobot = r.dae\n", "/x/p.cfg: key 'problem.world' is missing"},
        {"[problem]\nworld=e\nrobot=r\nstart.x=0\nstart.y=0\nstart.z=0\nstart.theta=0\nstart.axis.x=0\n"
         "start.axis.y=0\nstart.axis.z=0\ngoal.x=0\ngoal.y=0\ngoal.z=0\ngoal.theta=0\ngoal.axis.x=0\n"
         "goal.axis.y=0\ngoal.axis.z=1\n",
         "/x/p.cfg:8: key 'problem.start.axis': the rotation axis is zero"},
    };
    for (const auto &c : cases)
    {
        const std::string e = errorOf(c.text);
        EXPECT_NE(e.find(c.expect), std::string::npos) << "expected: " << c.expect << "\ngot: " << e;
    }
}

TEST(Cfg, MeshErrorsNameTheCfgKey)
{
    const std::string path = (std::filesystem::temp_directory_path() / "mhplan_cfg_missing.cfg").string();
    std::ofstream(path)
        << "[problem]\nworld = nothing_here.obj\nrobot = " << kDir
        << "bar_robot.dae\nstart.x=0\nstart.y=0\nstart.theta=0\ngoal.x=1\ngoal.y=0\ngoal.theta=0\n";
    try
    {
        loadCfgProblem(path);
        ADD_FAILURE() << "a missing mesh accepted";
    }
    catch (const InputError &e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(path + ":2: key 'problem.world'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("nothing_here.obj: no such mesh file"), std::string::npos) << msg;
    }
}

TEST(Cfg, VolumeInferredFromTheEnvironment)
{
    const std::string path = (std::filesystem::temp_directory_path() / "mhplan_cfg_infer.cfg").string();
    std::ofstream(path) << "[problem]\nworld = " << kDir << "passage_env.stl\nrobot = " << kDir
                        << "rod_robot.ply\nstart.x=-6\nstart.y=0\nstart.z=0\nstart.theta=0\nstart.axis.x=0\n"
                           "start.axis.y=0\nstart.axis.z=1\ngoal.x=3\ngoal.y=0\ngoal.z=0\ngoal.theta=0\n"
                           "goal.axis.x=0\ngoal.axis.y=0\ngoal.axis.z=1\n";
    const LoadedCfgProblem p = loadCfgProblem(path);
    // The wall's box [-0.25, 0.25] x [-4, 4] x [-4, 4] grown to hold the start (x = -6) and goal (x = 3).
    EXPECT_TRUE(p.spec.volume.min().isApprox(Eigen::Vector3d(-6, -4, -4))) << p.spec.volume.min().transpose();
    EXPECT_TRUE(p.spec.volume.max().isApprox(Eigen::Vector3d(3, 4, 4))) << p.spec.volume.max().transpose();
}

namespace
{
    void solveAndCheck(const std::string &cfg, const std::string &planner, const std::string &validator)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        ompl::RNG::setSeed(5);
        LoadedCfgProblem p = loadCfgProblem(kDir + cfg);
        p.spec.motionValidator = validator;
        auto ss = makeMeshSetup(p.spec);
        ss->setPlanner(builtinPlanners().create(planner, ss->getSpaceInformation()));
        const ob::PlannerStatus status = ss->solve(ob::plannerOrTerminationCondition(
            ob::IterationTerminationCondition(100000), ob::timedPlannerTerminationCondition(60.0)));
        ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << cfg << " " << planner;
        long contact = -1;
        const std::size_t poses = denseMeshPathCheck(*p.spec.model, *ss->getSpaceInformation(),
                                                     ss->getSolutionPath(), 1e-3, contact);
        EXPECT_GT(poses, 100u);
        if (validator == "certified")
        {
            EXPECT_EQ(contact, -1) << cfg << " " << planner << ": motion " << contact
                                   << " touches an obstacle";
        }
    }
} // namespace

TEST(CfgProblems, BugTrapSolvedWithCertifiedMotions)
{
    solveAndCheck("bugtrap.cfg", "rrtconnect", "certified");
    solveAndCheck("bugtrap.cfg", "kpiece", "certified");
}

TEST(CfgProblems, NarrowPassageSolvedWithCertifiedMotions)
{
    solveAndCheck("passage.cfg", "rrtconnect", "certified");
    solveAndCheck("passage.cfg", "bkpiece", "discrete");
}

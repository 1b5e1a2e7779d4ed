// SPDX-License-Identifier: BSD-3-Clause
/* 3D YAML worlds (docs/worlds3d.md): the format read and written back, every refusal naming the file, line
   and field, solid boxes and spheres (a point inside a box collides), and the shipped examples solved in R^3
   and SE(3) with paths that pass the independent dense check. */
#include "CliSupport.h"

#include "src/base/World.h"
#include "src/io/World3dIO.h"
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
    const std::string kDir = std::string(MHPLAN_ENVIRONMENTS_DIR) + "/3d/";

    const std::string kHead = "space: r3\n"                                      // 1
                              "bounds: {min: [0, 0, 0], max: [10, 6, 6]}\n"      // 2
                              "robot: {point: {}}\n"                             // 3
                              "obstacles:\n"                                     // 4
                              "  - box: {center: [5, 3, 3], size: [1, 1, 1]}\n"; // 5

    const std::string kQueries = "queries:\n"                                          // 6
                                 "  - {name: q, start: [1, 1, 1], goal: [9, 5, 5]}\n"; // 7

    /** The message of loading \e text as /x/w.yaml (parsing, then building the problem of its first query).
     */
    std::string errorOf(const std::string &text)
    {
        try
        {
            const auto w = std::make_shared<const World3d>(parseWorld3d(text, "/x/w.yaml"));
            loadCfgProblem(world3dProblem(w, ""));
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "(accepted)";
    }

    void expectRefused(const std::string &text, const std::string &where, const std::string &what)
    {
        const std::string e = errorOf(text);
        EXPECT_NE(e.find("/x/w.yaml:" + where + "'"), std::string::npos) << e;
        EXPECT_NE(e.find(what), std::string::npos) << e;
    }
} // namespace

TEST(World3d, ReadsTheExampleAndWritesItBack)
{
    const std::string file = kDir + "narrow_passage.yaml";
    const World3d w = loadCfg(file).world3d ? *loadCfg(file).world3d : World3d{};
    EXPECT_EQ(w.name, "narrow_passage_3d");
    EXPECT_EQ(w.space, RigidSpace::R3);
    EXPECT_EQ(w.robot, "sphere");
    EXPECT_DOUBLE_EQ(w.robotRadius, 0.3);
    ASSERT_EQ(w.obstacles.size(), 6u);
    EXPECT_EQ(w.obstacles[4].kind, World3dObstacle::Kind::Sphere);
    EXPECT_EQ(w.obstacles[1].line, 11);
    // The slab turned by 0.5 rad about +z: its x axis.
    EXPECT_TRUE(
        w.obstacles[5].pose.linear().col(0).isApprox(Eigen::Vector3d(std::cos(0.5), std::sin(0.5), 0)));
    ASSERT_EQ(w.queries.size(), 2u);
    EXPECT_EQ(w.queries[1].name, "low");
    EXPECT_TRUE(w.queries[1].goal.position.isApprox(Eigen::Vector3d(9, 5, 5.5)));

    const World3d back = parseWorld3d(world3dYaml(w), "/y/again.yaml");
    EXPECT_EQ(back.name, w.name);
    EXPECT_EQ(back.space, w.space);
    EXPECT_TRUE(back.bounds.isApprox(w.bounds));
    ASSERT_EQ(back.obstacles.size(), w.obstacles.size());
    for (std::size_t i = 0; i < w.obstacles.size(); ++i)
    {
        EXPECT_EQ(back.obstacles[i].kind, w.obstacles[i].kind) << i;
        EXPECT_TRUE(back.obstacles[i].pose.isApprox(w.obstacles[i].pose, 1e-12)) << i;
        EXPECT_TRUE(back.obstacles[i].size.isApprox(w.obstacles[i].size)) << i;
        EXPECT_DOUBLE_EQ(back.obstacles[i].radius, w.obstacles[i].radius) << i;
    }
    ASSERT_EQ(back.queries.size(), 2u);
    EXPECT_TRUE(back.queries[1].start.position.isApprox(w.queries[1].start.position));

    // SE(3): a mesh robot (its path absolute when written) and orientations as axis and angle.
    const World3d s = *loadCfg(kDir + "narrow_passage_se3.yaml").world3d;
    EXPECT_EQ(s.space, RigidSpace::SE3);
    EXPECT_EQ(s.robot, "mesh");
    const World3d s2 = parseWorld3d(world3dYaml(s), "/y/again.yaml");
    EXPECT_EQ(std::filesystem::weakly_canonical(s2.robotFile),
              std::filesystem::weakly_canonical(s.robotFile));
    EXPECT_TRUE(s2.queries[0].start.orientation.isApprox(s.queries[0].start.orientation, 1e-12));
    EXPECT_TRUE(s.queries[0].start.orientation.isApprox(
        Eigen::Quaterniond(Eigen::AngleAxisd(1.5707963, Eigen::Vector3d::UnitZ()))));
}

TEST(World3d, RefusalsNameFileLineAndField)
{
    EXPECT_EQ(errorOf(kHead + kQueries), "(accepted)");
    expectRefused(kHead + kQueries + "colour: red\n", "8: field '(top level).colour", "colour");
    expectRefused("space: r2\n" + kHead.substr(10) + kQueries, "1: field 'space", "r3 or se3");
    expectRefused(kHead + "  - box: {center: [1, 1, 1], size: 2}\n" + kQueries,
                  "6: field 'obstacles[1].box.size", "three numbers");
    expectRefused(kHead + "  - box: {center: [1, 1, 1], size: [1, 0, 1]}\n" + kQueries,
                  "6: field 'obstacles[1].box.size", "> 0");
    expectRefused(kHead + "  - box: {centre: [1, 1, 1], size: [1, 1, 1]}\n" + kQueries,
                  "6: field 'obstacles[1].box.centre", "center, rotation, size");
    expectRefused(kHead + "  - sphere: {center: [1, 1, 1], radius: -1}\n" + kQueries,
                  "6: field 'obstacles[1].sphere.radius", "> 0");
    expectRefused(kHead + "  - cone: {}\n" + kQueries, "6: field 'obstacles[1].cone", "box, mesh, sphere");
    expectRefused(
        kHead + "  - box: {center: [8, 1, 1], size: [1, 1, 1], rotation: {axis: [0, 0, 0], angle: 1}}\n" +
            kQueries,
        "6: field 'obstacles[1].box.rotation.axis", "zero");
    expectRefused("space: r3\nbounds: {min: [0, 0, 0], max: [10, 0, 6]}\n" + kHead.substr(52) + kQueries,
                  "2: field 'bounds.max", "exceed");
    expectRefused("space: r3\nbounds: {min: [0, 0, 0], max: [10, 6, 6]}\nrobot: {sphere: 0}\n" +
                      kHead.substr(kHead.find("obstacles")) + kQueries,
                  "3: field 'robot.sphere", "> 0");
    expectRefused(kHead + "queries:\n  - {name: q, start: [1, 1], goal: [9, 5, 5]}\n",
                  "7: field 'queries[0].start", "three numbers");
    expectRefused(kHead + "queries:\n  - {name: q, start: {position: [1, 1, 1], axis: [0, 0, 1], angle: 1}, "
                          "goal: [9, 5, 5]}\n",
                  "7: field 'queries[0].start", "no orientation");
    expectRefused(kHead + kQueries + "  - {name: q, start: [1, 1, 1], goal: [9, 5, 5]}\n",
                  "8: field 'queries[1].name", "twice");
    // After the scene is built: out of bounds, in collision (a point inside the solid box), a missing mesh.
    expectRefused(kHead + "queries:\n  - {name: q, start: [1, 1, 7], goal: [9, 5, 5]}\n",
                  "7: field 'queries[0].start", "outside the bounds");
    expectRefused(kHead + "queries:\n  - {name: q, start: [1, 1, 1], goal: [5.2, 3.1, 2.9]}\n",
                  "7: field 'queries[0].goal", "in collision");
    expectRefused(kHead + "  - mesh: nothere.stl\n" + kQueries, "6: field 'obstacles[1].mesh", "nothere.stl");
    // A query by name; an unknown one is refused, naming those there are.
    const std::string path = (std::filesystem::temp_directory_path() / "mhplan_world3d_q.yaml").string();
    std::ofstream(path) << kHead << kQueries;
    EXPECT_NO_THROW(loadCfg(path, "q"));
    try
    {
        loadCfg(path, "nosuch");
        ADD_FAILURE() << "an unknown query was accepted";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("no query 'nosuch'; the world has q"), std::string::npos)
            << e.what();
    }
}

TEST(World3d, SolidPrimitivesAndAPointRobot)
{
    std::vector<SceneObstacle> scene;
    Eigen::Isometry3d at = Eigen::Isometry3d::Identity();
    at.translation() = Eigen::Vector3d(5, 3, 3);
    scene.push_back(
        {MeshShape::box(Eigen::Vector3d(2, 2, 2)), at, boxTriangles(Eigen::Vector3d(2, 2, 2), at)});
    at.translation() = Eigen::Vector3d(1, 1, 1);
    scene.push_back({MeshShape::sphere(0.5), at, sphereTriangles(0.5, at.translation())});
    const MeshRigidModel point(scene, 0.0, RigidSpace::R3);
    const auto placed = [](double x, double y, double z)
    {
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(x, y, z);
        return t;
    };
    EXPECT_TRUE(point.collides(placed(5, 3, 3))); // deep inside the box: solid
    EXPECT_TRUE(point.collides(placed(5.9, 3.9, 2.1)));
    EXPECT_TRUE(point.collides(placed(1, 1, 1))); // inside the ball
    EXPECT_FALSE(point.collides(placed(7, 3, 3)));
    EXPECT_NEAR(point.clearance(placed(7, 3, 3)), 1.0, 1e-5);   // to the box's face x = 6
    EXPECT_NEAR(point.clearance(placed(1, 1, 2.5)), 1.0, 1e-5); // to the ball
    EXPECT_LE(point.clearance(placed(5, 3, 3)), 0.0);
    EXPECT_EQ(point.reach(), 0.0);
    // A ball robot of radius 0.5 touches the box from 0.5 away.
    const MeshRigidModel ball(scene, 0.5, RigidSpace::SE3);
    EXPECT_TRUE(ball.collides(placed(6.4, 3, 3)));
    EXPECT_FALSE(ball.collides(placed(6.6, 3, 3)));
    EXPECT_NEAR(ball.clearance(placed(7, 3, 3)), 0.5, 1e-5);
    EXPECT_EQ(ball.environmentMesh().triangles.size(), 12u + sphereTriangles(0.5, {}).triangles.size());
}

TEST(World3d, MeshObstaclesAreSurfaces)
{
    // The wall of environments/omplapp/passage_env.stl (closed boxes, x in [-0.25, 0.25]) as a mesh obstacle,
    // beside a solid box of the same size: a point inside the box collides, one inside the mesh does not.
    const std::string text = "space: r3\nbounds: {min: [-5, -5, -5], max: [5, 5, 5]}\nrobot: {point: {}}\n"
                             "obstacles:\n  - mesh: " +
                             std::string(MHPLAN_ENVIRONMENTS_DIR) +
                             "/omplapp/passage_env.stl\n"
                             "  - box: {center: [3, 2, 0], size: [0.5, 3.5, 8]}\n"
                             "queries:\n  - {name: q, start: [-3, 0, 0], goal: [4, 0, 0]}\n";
    const auto w = std::make_shared<const World3d>(parseWorld3d(text, "/x/w.yaml"));
    const LoadedCfgProblem p = loadCfgProblem(world3dProblem(w, ""));
    const MeshRigidModel &m = *p.spec.model;
    EXPECT_GT(m.environmentTriangles(), 0u);
    const auto at = [](double x, double y, double z)
    {
        Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
        t.translation() = Eigen::Vector3d(x, y, z);
        return t;
    };
    EXPECT_TRUE(m.collides(at(3, 2, 0)));  // inside the solid box
    EXPECT_FALSE(m.collides(at(0, 2, 0))); // inside the closed mesh: a surface, not detected (as OMPL.app)
    EXPECT_NEAR(m.clearance(at(0, 2, 0)), 0.25, 1e-5); // to the mesh's nearest face
}

namespace
{
    void solveAndCheck(const std::string &file, const std::string &planner)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        static const bool seeded = (ompl::RNG::setSeed(3), true); // once, before any sampler exists
        (void)seeded;
        const LoadedCfgProblem p = loadCfgProblem(kDir + file);
        const auto ss = makeMeshSetup(p.spec);
        ss->setPlanner(builtinPlanners().create(planner, ss->getSpaceInformation()));
        const ob::PlannerStatus status = ss->solve(ob::plannerOrTerminationCondition(
            ob::IterationTerminationCondition(50000), ob::timedPlannerTerminationCondition(30.0)));
        ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << file << " " << planner;
        long contact = -1;
        const std::size_t poses = denseMeshPathCheck(*p.spec.model, *ss->getSpaceInformation(),
                                                     ss->getSolutionPath(), 1e-2, contact);
        EXPECT_GT(poses, 100u);
        EXPECT_EQ(contact, -1) << file << " " << planner << ": motion " << contact << " touches an obstacle";
        // The path crosses the wall (x = 5) through its hole.
        bool crossed = false;
        const auto &path = ss->getSolutionPath();
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
            crossed = crossed || p.spec.model->placement(path.getState(i)).translation().x() > 5.25;
        EXPECT_TRUE(crossed);
    }
} // namespace

TEST(World3d, ExamplesSolvedInR3AndSE3WithDenseCheck)
{
    solveAndCheck("narrow_passage.yaml", "RRTConnect");
    solveAndCheck("narrow_passage_se3.yaml", "RRTConnect");
}

TEST(World3d, PlanCommandReadsA3dWorld)
{
    const std::string svg = (std::filesystem::temp_directory_path() / "mhplan_world3d_plan.svg").string();
    const auto r =
        mhplan::test::runCli("plan " + kDir + "narrow_passage.yaml --planner RRTstar --time 0.3 --seed 2 " +
                             "--quiet --svg " + svg);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(
        mhplan::test::contains(r.out, "problem:   narrow_passage_3d (R^3, 6 obstacles (0 mesh triangles)"))
        << r.out;
    EXPECT_TRUE(mhplan::test::contains(r.out, "valid:     yes (independent dense check")) << r.out;
    // The top projection: the obstacles' triangles, the path, the ball at the start and the goal.
    std::ifstream in(svg);
    const std::string picture((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(mhplan::test::contains(picture, "narrow_passage_3d (R^3, seen from above)"))
        << picture.substr(0, 300);
    for (const char *cls : {"class=\"environment\"", "class=\"path\"", "class=\"start\"", "class=\"goal\""})
        EXPECT_TRUE(mhplan::test::contains(picture, cls)) << cls;
    const auto bad = mhplan::test::runCli("plan " + kDir + "narrow_passage.yaml --query nosuch");
    EXPECT_EQ(bad.code, 1) << bad.out;
    EXPECT_TRUE(mhplan::test::contains(bad.out, "no query 'nosuch'")) << bad.out;
}

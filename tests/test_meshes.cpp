// SPDX-License-Identifier: BSD-3-Clause
/* Meshes (docs/meshes.md): reading COLLADA (nested transforms, instances, up axis), OBJ, STL and PLY;
   refusing unreadable, empty, degenerate and oversized meshes; collision and clearance by FCL against
   analytic answers; the certified motion validator against dense pose checks. */
#include "src/base/PlannerRegistry.h"
#include "src/base/World.h"
#include "src/collision/MeshRigidBody.h"
#include "src/io/CfgIO.h"
#include "src/io/MeshIO.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

using namespace mhplan;
namespace ob = ompl::base;

namespace
{
    const std::string kDir = std::string(MHPLAN_ENVIRONMENTS_DIR) + "/omplapp/";

    std::string tempFile(const std::string &name, const std::string &text)
    {
        const std::string path = (std::filesystem::temp_directory_path() / ("mhplan_mesh_" + name)).string();
        std::ofstream(path) << text;
        return path;
    }

    std::string errorOf(const std::function<void()> &f)
    {
        try
        {
            f();
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "";
    }

    bool hasVertex(const TriangleMesh &m, const Eigen::Vector3d &p)
    {
        for (const auto &v : m.vertices)
            if ((v - p).norm() < 1e-5)
                return true;
        return false;
    }

    /** A unit cube [0, 1]^3 as an OBJ text moved by (dx, dy, dz). */
    std::string cubeObj(double dx, double dy, double dz)
    {
        std::ostringstream o;
        for (int i = 0; i < 8; ++i)
            o << "v " << dx + (i & 1) << " " << dy + ((i >> 1) & 1) << " " << dz + ((i >> 2) & 1) << "\n";
        o << "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
        return o.str();
    }
} // namespace

TEST(MeshIO, ColladaNestedTransformsInstancesAndUpAxis)
{
    // nested_xup.dae (environments/omplapp/make_meshes.py): a unit cube placed twice under a translated
    // node, once rotated 90 degrees about the file's z and scaled 2; the file is X_UP, turned as assimp and
    // OMPL.app turn it (its x becomes +y): the file's point (x, y, z) lands at (-y, x, z).
    const TriangleMesh m = readMesh(kDir + "nested_xup.dae");
    EXPECT_EQ(m.triangles.size(), 24u);
    const Eigen::AlignedBox3d box = m.box();
    EXPECT_TRUE(box.min().isApprox(Eigen::Vector3d(-6, 8, 0), 1e-5)) << box.min().transpose();
    EXPECT_TRUE(box.max().isApprox(Eigen::Vector3d(0, 11, 2), 1e-5)) << box.max().transpose();
    // The file's point (10, 2, 0) (corner (1, 0, 0) of the scaled, turned instance) and (11, 6, 1) (the
    // far corner of the other instance).
    EXPECT_TRUE(hasVertex(m, {-2, 10, 0}));
    EXPECT_TRUE(hasVertex(m, {-6, 11, 1}));
}

TEST(MeshIO, ColladaUpAxisTurnedAsOmplAppReadsItAndUnitsIgnored)
{
    // An asymmetric triangle under a node matrix. As OMPL.app reads COLLADA (assimp's scene, the file's up
    // axis turned to +y): Y_UP keeps its coordinates, Z_UP (SketchUp) turns (x, y, z) to (x, z, -y). A
    // <unit> is not applied: OMPL.app's problem files mix a robot in inches with an environment without a
    // unit, both in the same numbers.
    const auto dae = [](const std::string &up, const std::string &unit)
    {
        return std::string(R"(<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1"><asset>)") +
               unit + "<up_axis>" + up + R"(</up_axis></asset>
<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="a" count="9">0 0 0 1 0 0 0 2 3</float_array>
<technique_common><accessor source="#a" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/>
<param name="Z" type="float"/></accessor></technique_common></source><vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node><matrix>1 0 0 5 0 1 0 0 0 0 1 0 0 0 0 1</matrix><instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene></COLLADA>
)";
    };
    const TriangleMesh y = readMesh(tempFile("yup.dae", dae("Y_UP", "")));
    EXPECT_TRUE(hasVertex(y, {5, 0, 0}) && hasVertex(y, {6, 0, 0}) && hasVertex(y, {5, 2, 3}));
    const TriangleMesh z = readMesh(tempFile("zup.dae", dae("Z_UP", "")));
    EXPECT_TRUE(hasVertex(z, {5, 0, 0}) && hasVertex(z, {6, 0, 0}) && hasVertex(z, {5, 3, -2}));
    const TriangleMesh inches =
        readMesh(tempFile("inch.dae", dae("Z_UP", R"(<unit meter="0.0254" name="inch"/>)")));
    EXPECT_TRUE(hasVertex(inches, {5, 0, 0}) && hasVertex(inches, {6, 0, 0}) && hasVertex(inches, {5, 3, -2}))
        << "the unit was applied";
}

TEST(MeshIO, ObjStlPlyRead)
{
    const TriangleMesh obj = readMesh(kDir + "bugtrap_env.obj");
    EXPECT_EQ(obj.triangles.size(), 60u);
    EXPECT_TRUE(obj.box().min().isApprox(Eigen::Vector3d(-4, -4, -1)));
    const TriangleMesh stl = readMesh(kDir + "passage_env.stl");
    EXPECT_EQ(stl.triangles.size(), 48u);
    EXPECT_TRUE(stl.box().max().isApprox(Eigen::Vector3d(0.25, 4, 4)));
    const TriangleMesh ply = readMesh(kDir + "rod_robot.ply");
    EXPECT_EQ(ply.triangles.size(), 12u);
    EXPECT_NEAR(ply.reachFrom(Eigen::Vector3d::Zero()), std::sqrt(0.64 + 0.0625 + 0.0625), 1e-6);
    // Quads are triangulated.
    EXPECT_EQ(readMesh(tempFile("cube.obj", cubeObj(0, 0, 0))).triangles.size(), 12u);
}

TEST(MeshIO, BadMeshesAreRefusedClearly)
{
    std::string e = errorOf([] { readMesh(kDir + "no_such_mesh.obj"); });
    EXPECT_NE(e.find("no_such_mesh.obj: no such mesh file"), std::string::npos) << e;
    e = errorOf([] { readMesh(tempFile("garbage.dae", "<COLLADA><broken")); });
    EXPECT_NE(e.find("garbage.dae"), std::string::npos) << e;
    EXPECT_NE(e.find("cannot read"), std::string::npos) << e;
    e = errorOf([] { readMesh(tempFile("empty.obj", "# nothing\n")); });
    EXPECT_NE(e.find("empty.obj"), std::string::npos) << e;
    // Only lines: no triangles.
    e = errorOf([] { readMesh(tempFile("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n")); });
    EXPECT_NE(e.find("lines.obj"), std::string::npos) << e;
    // Every triangle degenerate (collinear corners).
    e = errorOf([] { readMesh(tempFile("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")); });
    EXPECT_NE(e.find("flat.obj"), std::string::npos) << e;
    EXPECT_NE(e.find("degenerate"), std::string::npos) << e;
    // Size limits: the file's bytes and the triangles.
    MeshLimits small;
    small.maxFileBytes = 100;
    e = errorOf([&] { readMesh(kDir + "passage_env.stl", small); });
    EXPECT_NE(e.find("bytes, more than the 100 accepted"), std::string::npos) << e;
    small = MeshLimits{};
    small.maxTriangles = 20;
    e = errorOf([&] { readMesh(kDir + "bugtrap_env.obj", small); });
    EXPECT_NE(e.find("more than 20 triangles"), std::string::npos) << e;
    // A mesh with some degenerate triangles keeps the others.
    TriangleMesh m;
    m.source = "test";
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    m.triangles = {{0, 1, 2}, {0, 1, 3}};
    EXPECT_EQ(checkAndCleanMesh(m), 1u);
    EXPECT_EQ(m.triangles.size(), 1u);
    m.vertices[0].x() = std::nan("");
    EXPECT_THROW(checkAndCleanMesh(m), InputError);
}

TEST(MeshCollision, CollisionAndClearanceMatchTheGeometry)
{
    // A unit cube at the origin against a unit cube robot: along x the gap is known exactly.
    TriangleMesh env = readMesh(tempFile("env_cube.obj", cubeObj(0, 0, 0)));
    TriangleMesh robot = readMesh(tempFile("robot_cube.obj", cubeObj(-0.5, -0.5, -0.5)));
    const MeshRigidModel model(env, robot, false);
    EXPECT_TRUE(model.robotShift().isZero(1e-12)); // centred already
    EXPECT_NEAR(model.reach(), std::sqrt(0.75), 1e-9);
    for (const double gap : {0.01, 0.3, 2.0})
    {
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.translation() = Eigen::Vector3d(1.5 + gap, 0.5, 0.5);
        EXPECT_FALSE(model.collides(pose)) << gap;
        EXPECT_NEAR(model.clearance(pose), gap, 1e-5) << gap;
        EXPECT_LE(model.clearance(pose), gap) << "clearance is a lower bound";
    }
    Eigen::Isometry3d overlap = Eigen::Isometry3d::Identity();
    overlap.translation() = Eigen::Vector3d(1.2, 0.5, 0.5);
    EXPECT_TRUE(model.collides(overlap));
    EXPECT_LE(model.clearance(overlap), 0.0);
    // Turned 45 degrees about z, the robot reaches sqrt(2)/2 towards the cube.
    Eigen::Isometry3d turned = Eigen::Isometry3d::Identity();
    turned.translation() = Eigen::Vector3d(2.0, 0.5, 0.5);
    turned.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    EXPECT_NEAR(model.clearance(turned), 1.0 - std::sqrt(0.5), 1e-5);
}

namespace
{
    /** Random motions between valid states of \e ss: every motion the certified validator accepts passes
        the dense check at a step far below the clearances, and some are accepted and some refused. */
    void certifiedAgainstDense(const ompl::geometric::SimpleSetupPtr &ss, const MeshRigidModel &model,
                               double localRadius, int motions = 400, double step = 1e-3)
    {
        const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
        const auto validator =
            std::dynamic_pointer_cast<MeshCertifiedMotionValidator>(si->getMotionValidator());
        ASSERT_TRUE(validator);
        ompl::RNG rng(11); // its own generator: the same motions whatever ran before
        const bool planar = model.planar();
        const auto &bounds = planar ? si->getStateSpace()->as<ob::SE2StateSpace>()->getBounds()
                             : model.space() == RigidSpace::R3
                                 ? si->getStateSpace()->as<ob::RealVectorStateSpace>()->getBounds()
                                 : si->getStateSpace()->as<ob::SE3StateSpace>()->getBounds();
        // A random pose, within localRadius of \e near (per coordinate) when given, inside the bounds.
        const auto sample = [&](ob::State *s, const ob::State *near)
        {
            do
            {
                RigidPose pose;
                for (std::size_t k = 0; k < (planar ? 2u : 3u); ++k)
                {
                    const double c = near == nullptr ? 0.5 * (bounds.low[k] + bounds.high[k])
                                                     : model.placement(near).translation()[k];
                    const double h = near == nullptr ? 0.5 * (bounds.high[k] - bounds.low[k]) : localRadius;
                    pose.position[k] =
                        rng.uniformReal(std::max(bounds.low[k], c - h), std::min(bounds.high[k], c + h));
                }
                if (planar)
                    pose.orientation =
                        Eigen::AngleAxisd(rng.uniformReal(-M_PI, M_PI), Eigen::Vector3d::UnitZ());
                else
                {
                    double q[4];
                    rng.quaternion(q);
                    pose.orientation = Eigen::Quaterniond(q[3], q[0], q[1], q[2]);
                }
                setRigidState(s, pose, model.space());
            } while (!si->isValid(s));
        };
        ob::State *a = si->allocState(), *b = si->allocState();
        int accepted = 0, refused = 0, denseContacts = 0;
        for (int i = 0; i < motions; ++i)
        {
            sample(a, nullptr);
            sample(b, a);
            ompl::geometric::PathGeometric path(si, a, b);
            long contact = -1;
            denseMeshPathCheck(model, *si, path, step, contact);
            denseContacts += contact >= 0 ? 1 : 0;
            if (validator->checkMotion(a, b))
            {
                ++accepted;
                EXPECT_EQ(contact, -1) << "an accepted motion touches an obstacle (motion " << i << ")";
            }
            else
                ++refused;
            std::pair<ob::State *, double> last(si->allocState(), 0.0);
            if (!validator->checkMotion(a, b, last))
            {
                // The certified prefix is free.
                ompl::geometric::PathGeometric prefix(si, a, last.first);
                long c = -1;
                denseMeshPathCheck(model, *si, prefix, step, c);
                EXPECT_EQ(c, -1) << "motion " << i;
            }
            si->freeState(last.first);
        }
        std::cout << accepted << " motions accepted, " << refused << " refused, " << denseContacts
                  << " in contact by the dense check, " << validator->evaluations()
                  << " clearance evaluations\n";
        si->freeState(a);
        si->freeState(b);
        EXPECT_GT(accepted, motions / 10);
        EXPECT_GT(denseContacts, motions / 10);
        EXPECT_GE(refused, denseContacts);
    }

    /** \brief The bar robot in the 2D bug trap (environments/omplapp), volume [-7, 7]^2, start and goal
     * unset. */
    MeshProblemSpec bugTrapSpec()
    {
        MeshProblemSpec spec;
        spec.model = std::make_shared<MeshRigidModel>(readMesh(kDir + "bugtrap_env.obj"),
                                                      readMesh(kDir + "bar_robot.dae"), true);
        spec.volume = Eigen::AlignedBox3d(Eigen::Vector3d(-7, -7, 0), Eigen::Vector3d(7, 7, 0));
        return spec;
    }
} // namespace

TEST(MeshDenseCheck, AMotionEndingAtAHeadingOfMinusPiStaysInTheVolume)
{
    // OMPL's SO(2) holds [-pi, pi); its interpolation toward a heading of -pi (OMPL.app's reversed goals)
    // can end at +pi, the same heading. The dense check tests positions against the volume: a free motion
    // to such a goal is free (before, every path ending there failed it at its own goal).
    MeshProblemSpec spec = bugTrapSpec();
    spec.goal.position = {0, 6, 0};
    const auto ss = makeMeshSetup(spec);
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    ob::ScopedState<ob::SE2StateSpace> a(si), b(si), end(si);
    a->setXY(-5.0, 6.0);
    a->setYaw(1.6505869973918708);
    b->setXY(-3.0, 6.0);
    b->setYaw(-M_PI);
    ASSERT_TRUE(si->isValid(a.get()) && si->isValid(b.get()));
    si->getStateSpace()->interpolate(a.get(), b.get(), 1.0, end.get());
    ASSERT_FALSE(si->satisfiesBounds(end.get())) << "OMPL's interpolation ends at " << end->getYaw();
    ompl::geometric::PathGeometric path(si, a.get(), b.get());
    long contact = 0;
    EXPECT_GT(denseMeshPathCheck(*spec.model, *si, path, 0.01, contact), 100u);
    EXPECT_EQ(contact, -1);
    // A position outside the volume is still refused.
    b->setXY(-3.0, 7.5);
    ompl::geometric::PathGeometric out(si, a.get(), b.get());
    denseMeshPathCheck(*spec.model, *si, out, 0.01, contact);
    EXPECT_EQ(contact, 0);
}

TEST(MeshCertifiedValidator, SE2BugTrapAgainstDenseChecks)
{
    MeshProblemSpec spec = bugTrapSpec();
    spec.goal.position = {0, 6, 0};
    certifiedAgainstDense(makeMeshSetup(spec), *spec.model, 4.0);
}

TEST(MeshCertifiedValidator, DubinsAndReedsSheppCarsAgainstDenseChecks)
{
    // The cars' curves (docs/meshes.md): the bound follows the curve's length and turning, and a curve that
    // would leave the volume between its ends is refused (the dense check counts it as a contact).
    for (const char *car : {"dubins", "reeds_shepp"})
    {
        MeshProblemSpec spec;
        spec.model = std::make_shared<MeshRigidModel>(readMesh(kDir + "bugtrap_env.obj"),
                                                      readMesh(kDir + "bar_robot.dae"), true);
        spec.volume = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 0));
        spec.goal.position = {0, 4.5, 0};
        spec.car = car;
        spec.turningRadius = 0.6;
        const auto ss = makeMeshSetup(spec);
        EXPECT_EQ(spaceFlag(*ss->getStateSpace()),
                  std::string(car) == "dubins" ? cap::Dubins : cap::ReedsShepp);
        SCOPED_TRACE(car);
        certifiedAgainstDense(ss, *spec.model, 1.5, 80, 4e-3); // the curves are long: a coarser dense step
    }
}

TEST(MeshCertifiedValidator, SE3PassageAgainstDenseChecks)
{
    MeshProblemSpec spec;
    spec.model = std::make_shared<MeshRigidModel>(readMesh(kDir + "passage_env.stl"),
                                                  readMesh(kDir + "rod_robot.ply"), false);
    // A volume close about the wall, so that many motions cross it.
    spec.volume = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, -2), Eigen::Vector3d(2, 2, 2));
    spec.start.position = {-1.5, 0, 0};
    spec.goal.position = {1.5, 0, 0};
    certifiedAgainstDense(makeMeshSetup(spec), *spec.model, 3.0);
}

TEST(MeshCertifiedValidator, ThreeDWorldsAgainstDenseChecks)
{
    // docs/worlds3d.md: solid boxes and spheres with a ball robot in R^3, boxes with the rod in SE(3).
    for (const char *file : {"narrow_passage.yaml", "narrow_passage_se3.yaml"})
    {
        SCOPED_TRACE(file);
        const LoadedCfgProblem p = loadCfgProblem(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/3d/" + file);
        certifiedAgainstDense(makeMeshSetup(p.spec), *p.spec.model, 6.0, 150, 2e-3);
    }
}

TEST(MeshSetup, RefusesInvalidStartAndUnknownSettings)
{
    MeshProblemSpec spec = bugTrapSpec();
    spec.start.position = {-3.5, 0, 0}; // inside the left wall
    spec.goal.position = {0, 6, 0};
    std::string e = errorOf([&] { makeMeshSetup(spec); });
    EXPECT_NE(e.find("start pose is in collision"), std::string::npos) << e;
    spec.start.position = {0, 0, 0};
    spec.goal.position = {0, 9, 0};
    e = errorOf([&] { makeMeshSetup(spec); });
    EXPECT_NE(e.find("goal pose lies outside the volume"), std::string::npos) << e;
    spec.goal.position = {0, 6, 0};
    spec.context = {{"no_such_setting", "1"}};
    e = errorOf([&] { makeMeshSetup(spec); });
    EXPECT_NE(e.find("unknown problem setting 'no_such_setting'"), std::string::npos) << e;
    EXPECT_NE(e.find("longest_valid_segment_fraction"), std::string::npos) << e;
    spec.context = {{"longest_valid_segment_fraction", "0.02"}, {"sampler", "obstacle_based"}};
    spec.motionValidator = "discrete";
    const auto ss = makeMeshSetup(spec);
    EXPECT_NEAR(ss->getSpaceInformation()->getStateValidityCheckingResolution(), 0.02, 1e-12);
    EXPECT_FALSE(std::dynamic_pointer_cast<MeshCertifiedMotionValidator>(
        ss->getSpaceInformation()->getMotionValidator()));
}

TEST(MeshSetup, AHeadingOfPiIsTheHeadingOfMinusPi)
{
    // OMPL.app's problem files write a reversed heading as theta = 3.141592653589793; OMPL's SO(2) holds
    // [-pi, pi), so the pose is stored at -pi (the same heading) instead of being refused as outside the
    // volume.
    MeshProblemSpec spec = bugTrapSpec();
    spec.start.position = {0, 0, 0};
    spec.goal.position = {0, 6, 0};
    spec.goal.orientation =
        Eigen::Quaterniond(Eigen::AngleAxisd(3.141592653589793, Eigen::Vector3d::UnitZ()));
    ompl::geometric::SimpleSetupPtr ss;
    ASSERT_NO_THROW(ss = makeMeshSetup(spec));
    const auto *goal = ss->getProblemDefinition()->getGoal()->as<ob::GoalState>()->getState();
    const double yaw = goal->as<ob::SE2StateSpace::StateType>()->getYaw();
    EXPECT_NEAR(std::abs(yaw), M_PI, 1e-12);
    EXPECT_LT(yaw, M_PI);
    EXPECT_TRUE(ss->getSpaceInformation()->satisfiesBounds(goal));
}

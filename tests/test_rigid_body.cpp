// SPDX-License-Identifier: BSD-3-Clause
/* The rigid-body collision model and the certified motion validator of the SE(2)-based spaces
   (docs/spaces.md, "Rigid-body and car worlds"): FCL's answers against the independent geometry of
   src/base/Geometry.h, the displacement bound against OMPL's interpolation, and thousands of random motions
   on the shipped worlds (and a disc robot, and a grid world) of which no accepted one collides under a dense
   independent check at 1e-3 steps, while most motions the dense check finds free are accepted. */
#include "src/collision/CarSpaces.h"
#include "src/collision/Problem.h"
#include "src/collision/RigidBody.h"
#include "src/collision/RigidValidity.h"
#include "src/io/WorldIO.h"

#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    World shipped(const std::string &name)
    {
        return loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml");
    }

    /** bfo_case2's twelve circles with a disc robot of radius 0.3 in SE(2). */
    World discWorld()
    {
        World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case2.yaml");
        w.space = SpaceType::SE2;
        w.robotRadius = 0.3;
        return w;
    }

    /** gms_grid10 (an occupancy grid) with a triangle robot in SE(2). */
    World gridWorld()
    {
        World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/gms_grid10.yaml");
        w.space = SpaceType::SE2;
        w.robotPolygon = {{-0.2, -0.15}, {0.35, 0.0}, {-0.2, 0.15}};
        return w;
    }

    Pose2 randomPose(ompl::RNG &rng, const Box &b)
    {
        return {rng.uniformReal(b.xmin, b.xmax), rng.uniformReal(b.ymin, b.ymax), rng.uniformReal(-kPi, kPi)};
    }

    struct MotionCounts
    {
        std::size_t motions{0};
        std::size_t accepted{0};
        std::size_t denseFree{0};
        std::size_t acceptedAndDenseFree{0};
        std::size_t acceptedButColliding{0};
    };

    /** \e n random motions between valid poses at most a fifth of the world's size apart (headings at
        random), each checked by the world's motion validator and densely (1001 poses, t step 1e-3) by the
        independent geometry. */
    MotionCounts randomMotions(const World &world, std::size_t n, std::uint_fast32_t seed)
    {
        // The problem's pieces without its query (the worlds made here have no valid query).
        auto rigid = std::make_shared<const RigidBodyModel>(world);
        const auto si = std::make_shared<ob::SpaceInformation>(makeStateSpace(world));
        si->setStateValidityChecker(std::make_shared<RigidValidityChecker>(si, rigid));
        const auto mv = std::make_shared<CertifiedMotionValidator>(
            si, rigid, world.space, world.turningRadius, motionResolution(world));
        const RigidBodyModel &model = *rigid;
        ompl::RNG rng(seed);
        const double reach = 0.2 * std::max(world.bounds.width(), world.bounds.height());
        ob::State *s1 = si->allocState();
        ob::State *s2 = si->allocState();
        ob::State *s = si->allocState();
        MotionCounts c;
        auto validPose = [&](const Pose2 &p)
        { return model.freeDistance(p) > 0.0 && independentPoseFree(world, p); };
        while (c.motions < n)
        {
            const Pose2 a = randomPose(rng, world.bounds);
            if (!validPose(a))
                continue;
            const Pose2 b{a.x + rng.uniformReal(-reach, reach), a.y + rng.uniformReal(-reach, reach),
                          rng.uniformReal(-kPi, kPi)};
            if (!validPose(b))
                continue;
            ++c.motions;
            setStatePose(s1, a);
            setStatePose(s2, b);
            const bool accepted = mv->checkMotion(s1, s2);
            const SpaceMotion motion(si->getStateSpace().get(), world.space, model.rotationReach(),
                                     world.turningRadius, s1, s2);
            bool free = true;
            for (int k = 0; k <= 1000 && free; ++k)
            {
                motion.at(k / 1000.0, s);
                free = independentPoseFree(world, statePose(s));
            }
            c.accepted += accepted ? 1 : 0;
            c.denseFree += free ? 1 : 0;
            c.acceptedAndDenseFree += accepted && free ? 1 : 0;
            c.acceptedButColliding += accepted && !free ? 1 : 0;
        }
        si->freeState(s1);
        si->freeState(s2);
        si->freeState(s);
        return c;
    }

    void expectCertified(const std::string &label, const World &world, std::size_t n, std::uint_fast32_t seed)
    {
        const MotionCounts c = randomMotions(world, n, seed);
        EXPECT_EQ(c.acceptedButColliding, 0u) << label;
        ASSERT_GT(c.denseFree, n / 20) << label << ": too few free motions to measure anything";
        const double ratio = static_cast<double>(c.acceptedAndDenseFree) / static_cast<double>(c.denseFree);
        std::cout << label << ": " << c.motions << " motions, " << c.denseFree
                  << " free under the dense check, " << c.accepted
                  << " accepted, accepted / dense-free = " << ratio << "\n";
        // Not trivially conservative: it accepts most of what the dense check finds free.
        EXPECT_GT(ratio, 0.9) << label;
    }
} // namespace

TEST(RigidBody, FclAgreesWithTheIndependentGeometry)
{
    for (const World &world : {shipped("se2_narrow_passage"), shipped("reeds_shepp_parking"),
                               shipped("dubins_circles"), discWorld(), gridWorld()})
    {
        const RigidBodyModel model(world);
        ompl::RNG rng(11);
        std::size_t free = 0;
        for (int i = 0; i < 2000; ++i)
        {
            const Pose2 p = randomPose(rng, world.bounds);
            const double fcl = model.clearance(p);
            const double exact = independentPoseDistance(world, p);
            const bool indep = independentPoseFree(world, p);
            if (fcl > 0.0)
            {
                // A lower bound of the true distance, tight to the margin (plus GJK's tolerance).
                EXPECT_LE(fcl, exact + 1e-9) << world.name << " at " << p.x << "," << p.y << "," << p.yaw;
                EXPECT_GE(fcl, exact - 2.0 * model.margin() - 1e-6) << world.name;
                if (model.inBounds(p))
                {
                    EXPECT_TRUE(indep) << world.name;
                }
            }
            if (exact > 1e-6 && model.inBounds(p))
            {
                EXPECT_TRUE(model.isValid(p)) << world.name;
            }
            if (exact == 0.0)
            {
                EXPECT_FALSE(model.isValid(p) && fcl > 0.0) << world.name;
            }
            free += indep ? 1 : 0;
        }
        EXPECT_GT(free, 100u) << world.name;
    }
}

TEST(RigidBody, DisplacementBoundHoldsAlongOmplInterpolation)
{
    // Every robot vertex moves at most bound / 1000 between poses 1e-3 apart in the path parameter.
    for (const std::string name : {"se2_narrow_passage", "reeds_shepp_parking", "dubins_circles"})
    {
        const World world = shipped(name);
        const ob::StateSpacePtr space = makeStateSpace(world);
        const RigidBodyModel model(world);
        ompl::RNG rng(3);
        ob::State *a = space->allocState();
        ob::State *b = space->allocState();
        ob::State *s = space->allocState();
        double worst = 0.0;
        for (int i = 0; i < 200; ++i)
        {
            setStatePose(a, randomPose(rng, world.bounds));
            setStatePose(b, randomPose(rng, world.bounds));
            const SpaceMotion m(space.get(), world.space, model.rotationReach(), world.turningRadius, a, b);
            EXPECT_NEAR(m.length(), space->distance(a, b), 1e-9 * (1.0 + m.length()));
            std::vector<Vec2> last;
            for (int k = 0; k <= 1000; ++k)
            {
                m.at(k / 1000.0, s);
                const std::vector<Vec2> now = placedRobot(world, statePose(s));
                for (std::size_t v = 0; v < last.size(); ++v)
                    worst = std::max(worst, distance(now[v], last[v]) / (m.bound() / 1000.0 + 1e-12));
                last = now;
            }
        }
        EXPECT_LE(worst, 1.0 + 1e-6) << name;
        EXPECT_GT(worst, 0.5) << name << ": the bound should not be loose everywhere";
        space->freeState(a);
        space->freeState(b);
        space->freeState(s);
    }
}

TEST(RigidBody, ValidatorCertifiesTheNarrowPassage)
{
    const World world = shipped("se2_narrow_passage");
    const og::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], makeCollisionModel(world));
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    ob::ScopedState<> a(si), b(si), last(si);
    // Lying flat, the 0.4 m thick bar crosses the 1 m gap.
    setStatePose(a.get(), {3.0, 3.0, 0.0});
    setStatePose(b.get(), {7.0, 3.0, 0.0});
    EXPECT_TRUE(si->checkMotion(a.get(), b.get()));
    // Upright it does not: the certified prefix ends before the wall and is collision-free.
    setStatePose(a.get(), {3.0, 3.0, kPi / 2});
    setStatePose(b.get(), {7.0, 3.0, kPi / 2});
    std::pair<ob::State *, double> lastValid{last.get(), -1.0};
    EXPECT_FALSE(si->getMotionValidator()->checkMotion(a.get(), b.get(), lastValid));
    EXPECT_GT(lastValid.second, 0.2);
    EXPECT_LT(lastValid.second, 0.5);
    EXPECT_TRUE(independentPoseFree(world, statePose(last.get())));
    // Turning in place in the open is fine.
    setStatePose(b.get(), {3.0, 3.0, 0.0});
    EXPECT_TRUE(si->checkMotion(a.get(), b.get()));
    // The goal's pose differs from the start's: the objective is the space's (|dxy| + 0.5 |dyaw|).
    setStatePose(b.get(), {4.0, 3.0, 0.0});
    EXPECT_NEAR(ss->getOptimizationObjective()->motionCost(a.get(), b.get()).value(), 1.0 + 0.5 * kPi / 2,
                1e-12);
}

TEST(RigidBody, NoAcceptedMotionCollidesOnTheNarrowPassage)
{
    expectCertified("se2_narrow_passage", shipped("se2_narrow_passage"), 2000, 1);
}

TEST(RigidBody, NoAcceptedMotionCollidesOnTheParking)
{
    expectCertified("reeds_shepp_parking", shipped("reeds_shepp_parking"), 1500, 2);
}

TEST(RigidBody, NoAcceptedMotionCollidesAmongTheDubinsCircles)
{
    expectCertified("dubins_circles", shipped("dubins_circles"), 1500, 3);
}

TEST(RigidBody, NoAcceptedMotionCollidesForADiscRobot)
{
    expectCertified("se2 disc robot in bfo_case2", discWorld(), 1500, 4);
}

TEST(RigidBody, NoAcceptedMotionCollidesInAGrid)
{
    expectCertified("se2 triangle in gms_grid10", gridWorld(), 1500, 5);
}

TEST(RigidBody, SafeDubinsAgreesWithOmplAndSurvivesItsAssertion)
{
    const double rho = 1.3;
    auto safe = std::make_shared<SafeDubinsStateSpace>(rho);
    auto ompl = std::make_shared<ob::DubinsStateSpace>(rho);
    ob::State *a = safe->allocState();
    ob::State *b = safe->allocState();
    ob::State *s = safe->allocState();
    ompl::RNG rng(9);
    for (int i = 0; i < 3000; ++i)
    {
        setStatePose(a, {rng.uniformReal(-5, 5), rng.uniformReal(-5, 5), rng.uniformReal(-kPi, kPi)});
        setStatePose(b, {rng.uniformReal(-5, 5), rng.uniformReal(-5, 5), rng.uniformReal(-kPi, kPi)});
        ASSERT_NEAR(safe->distance(a, b), ompl->distance(a, b), 1e-9) << i;
        safe->interpolate(a, b, 0.999999999, s);
        const Pose2 end = statePose(s);
        const Pose2 goal = statePose(b);
        EXPECT_NEAR(std::hypot(end.x - goal.x, end.y - goal.y), 0.0, 1e-6) << i;
    }
    // A goal on the start's right turning circle: OMPL 1.5.2's dubins() aborts on an assertion near here.
    for (double phi : {0.5, 1.0, 2.0, 3.0})
    {
        setStatePose(a, {0.0, 0.0, 0.0});
        setStatePose(b, {rho * std::sin(phi), -rho * (1.0 - std::cos(phi)), -phi});
        EXPECT_NEAR(safe->distance(a, b), rho * phi, 1e-9) << phi;
        setStatePose(b, {rho * std::sin(phi) + 1e-5, -rho * (1.0 - std::cos(phi)), -phi + 1e-5});
        EXPECT_NEAR(safe->distance(a, b), rho * phi, 1e-3) << phi;
    }
    safe->freeState(a);
    safe->freeState(b);
    safe->freeState(s);
}

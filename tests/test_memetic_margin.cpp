// SPDX-License-Identifier: BSD-3-Clause
/* The memetic planners' reported paths in an OMPL program's set-up (a plain point checker, OMPL's
   DiscreteMotionValidator): no corner and no acute tip that the validator's samples miss is cut
   (docs/variants.md, "No corner the validator cannot see" and "The fine check"). Each world puts one obstacle
   on the straight way from the start to the goal, poking between the validator's samples and the margin's
   sideways copies; every returned path must pass the independent dense check of the benchmarks (points at
   most 1/2000 of the bounds' diagonal apart on every segment, the exact geometry; src/metrics/Metrics.h,
   defaultMetricStep). Budgets are generations, never wall-clock. */
#include "ompl_planners/memetic/MemeticPlanner.h"
#include "ompl_planners/memetic/MemeticToolkit.h"
#include "src/registry/Registry.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>

#include "RegistrySupport.h"
#include "SpaceProblems.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <vector>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    using Outline = std::vector<std::array<double, 2>>;

    bool inside(const Outline &poly, double x, double y)
    {
        bool in = false;
        for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        {
            const auto &p = poly[i], &q = poly[j];
            if ((p[1] > y) != (q[1] > y) && x < (q[0] - p[0]) * (y - p[1]) / (q[1] - p[1]) + p[0])
                in = !in;
        }
        return in;
    }

    /** \brief The 20 m square with one polygonal obstacle: a point checker, OMPL's DiscreteMotionValidator at
        resolution 0.002 (an OMPL app's; of the extent 28.3: a sample every s = 5.66 cm), start (1, 10), goal
        (19, 10). */
    og::SimpleSetupPtr problem(const Outline &obstacle, const std::string &planner,
                               const std::map<std::string, std::string> &params)
    {
        auto ss = test::planarAppProblem([obstacle](double x, double y) { return !inside(obstacle, x, y); },
                                         0.002, {1.0, 10.0}, {19.0, 10.0});
        ss->setPlanner(builtinPlanners().create(planner, ss->getSpaceInformation(), params));
        ss->setup();
        return ss;
    }

    /** \brief The length of the path's pieces inside the obstacle, each segment sampled at \e step (the
        benchmarks' dense check at the bounds' diagonal / 2000 = 1.41 cm; 0: it passes). */
    double lengthInside(const og::PathGeometric &path, const Outline &obstacle, double step)
    {
        double cut = 0.0;
        for (std::size_t i = 1; i < path.getStateCount(); ++i)
        {
            const double *a = path.getState(i - 1)->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *b = path.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
            const double l = std::hypot(b[0] - a[0], b[1] - a[1]);
            const auto n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(l / step)));
            for (std::size_t k = 0; k <= n; ++k)
            {
                const double u = double(k) / double(n);
                if (inside(obstacle, a[0] + (b[0] - a[0]) * u, a[1] + (b[1] - a[1]) * u))
                    cut += l / double(n);
            }
        }
        return cut;
    }

    const double kDenseStep = std::hypot(20.0, 20.0) / 2000.0;

    /** \brief Every memetic planner on \e obstacle with \e params; the returned paths' lengths inside it. */
    std::map<std::string, double> cuts(const Outline &obstacle,
                                       const std::map<std::string, std::string> &params,
                                       std::map<std::string, double> *lengths = nullptr)
    {
        std::map<std::string, double> out;
        for (const std::string &name : test::ofFamily("memetic"))
        {
            og::SimpleSetupPtr ss = problem(obstacle, name, params);
            const ob::PlannerPtr p = ss->getPlanner();
            EXPECT_EQ(p->solve(ob::PlannerTerminationCondition([] { return false; })),
                      ob::PlannerStatus::EXACT_SOLUTION)
                << name;
            if (!ss->haveExactSolutionPath())
                continue;
            out[name] = lengthInside(ss->getSolutionPath(), obstacle, kDenseStep);
            if (lengths != nullptr)
                (*lengths)[name] = ss->getSolutionPath().length();
        }
        return out;
    }

    /** \brief A star's tip: a triangle of apex angle 30 degrees pointing up, its apex 5 cm above the straight
        way at x = 10.113. There the tip is 2.7 cm wide, between two of the validator's samples (x = 10.085
       and 10.141 on the straight segment), and the margin's copies 2.8 cm to either side cross it over 1.2
       and 4.2 cm, between their samples (at the same x) too. */
    Outline tip()
    {
        const double apexX = 10.113, apexY = 10.05, depth = 6.0, half = depth * std::tan(M_PI / 12.0);
        return {{apexX - half, apexY - depth}, {apexX + half, apexY - depth}, {apexX, apexY}};
    }
    /** \brief The planners' margin on \e tk (validator_margin 0.5, validator_clearance 0.03,
        validator_min_clearance 0.001, validator_fine_step 0.25, all of the validator's spacing s) in the 20 m
        square; returns s. */
    double setPlannersMargin(MemeticToolkit &tk, const ob::SpaceInformationPtr &si)
    {
        const double s = si->getStateValidityCheckingResolution() * si->getMaximumExtent();
        tk.setBounds({0.0, 20.0, 0.0, 20.0});
        tk.setMargin(0.5 * s, 0.03 * s, 0.001 * s);
        tk.setFineCheck(s, 0.25 * s);
        return s;
    }
} // namespace

TEST(MemeticFineCheck, AnAcuteTipBetweenTheSamplesIsNotCut)
{
    // Without the fine check (validator_fine_step 0) the straight way through the tip passes the validator
    // and the margin, and is returned (so it was before the fine check); with it (the default, every s / 4 =
    // 1.41 cm, the dense check's step) every memetic planner's path goes round the tip's apex.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const Outline obstacle = tip();
    std::map<std::string, double> lengths;
    const auto without =
        cuts(obstacle, {{"seed", "5"}, {"max_iterations", "8"}, {"validator_fine_step", "0"}});
    const auto with = cuts(obstacle, {{"seed", "5"}, {"max_iterations", "8"}}, &lengths);
    std::size_t cutWithout = 0;
    for (const auto &[name, cut] : without)
        cutWithout += cut > 0.0 ? 1 : 0;
    EXPECT_GE(cutWithout, 1u) << "the test world no longer pokes between the samples";
    ASSERT_EQ(with.size(), test::ofFamily("memetic").size());
    for (const auto &[name, cut] : with)
    {
        EXPECT_EQ(cut, 0.0) << name << ": the returned path runs " << cut << " m inside the tip";
        EXPECT_LT(lengths[name], 18.001) << name;
        std::cout << "[fine check] " << name << ": length " << lengths[name]
                  << " (straight 18; inside without " << without.at(name) << " m)\n";
    }
}

TEST(MemeticFineCheck, ACornerBesideTheFirstSegmentIsSeenByTheCopies)
{
    // A square's 90-degree corner pokes 1 cm across the straight way 3 m from the start, between two of the
    // validator's samples (x = 3.934 and 3.991). The margin's copies used to fan out from the start and the
    // goal over the whole segment (on the segment from the start to the goal they never left it) and missed
    // it; now they reach their full offset s from the start and the goal, so the copy beside the corner
    // crosses it over 7.7 cm, more than their spacing (5.7 cm), and sees it, with or without the fine check.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const double cx = 3.962, cy = 9.99, d = 1.0;
    const Outline corner{{cx, cy}, {cx + d, cy + d}, {cx, cy + 2.0 * d}, {cx - d, cy + d}};
    for (const char *step : {"0", "0.25"})
        for (const auto &[name, cut] :
             cuts(corner, {{"seed", "5"}, {"max_iterations", "8"}, {"validator_fine_step", step}}))
            EXPECT_EQ(cut, 0.0) << name << " (validator_fine_step " << step << "): the returned path runs "
                                << cut << " m inside the corner";
}

TEST(MemeticMargin, ALoosePathAcrossATipIsMendedBesideIt)
{
    // A loose path (the search's, before the margin) runs across a tip whose width on it, 4.3 cm, lies
    // between two of the validator's samples; the margin's copies see the tip on both sides of the segment
    // down to the smallest clearance (both are inside it), so no sideways shift helps. makeStrict() looks at
    // the segment's own points there, finds one inside the tip and puts a waypoint beside it
    // (docs/variants.md, "The margin"): the strict path goes round the tip's apex, 8 cm above, and passes the
    // dense check.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const double depth = 6.0, half = depth * std::tan(M_PI / 12.0);
    // The second segment, (10, 10) to (19, 10): 160 samples 5.625 cm apart; the tip's crossing is centred
    // between the third and the fourth.
    const double apexX = 10.0 + 2.5 * 9.0 / 160.0, apexY = 10.08;
    const Outline obstacle{{apexX - half, apexY - depth}, {apexX + half, apexY - depth}, {apexX, apexY}};
    og::SimpleSetupPtr ss = test::planarAppProblem(
        [&](double x, double y) { return !inside(obstacle, x, y); }, 0.002, {1.0, 10.0}, {19.0, 10.0});
    ss->setup();
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    og::PathGeometric loose(si);
    for (const double x : {1.0, 10.0, 19.0})
    {
        ob::ScopedState<> s(si->getStateSpace());
        s[0] = x;
        s[1] = 10.0;
        loose.append(s.get());
    }
    ASSERT_TRUE(loose.check()) << "the validator now sees the tip on the loose path";
    ASSERT_GT(lengthInside(loose, obstacle, kDenseStep), 0.0) << "the loose path no longer crosses the tip";

    ompl::RNG rng(3);
    MemeticToolkit tk(si, rng);
    setPlannersMargin(tk, si);
    tk.setFixedPoints({1.0, 10.0}, {19.0, 10.0});
    MemeticPath path{{1.0, 10.0}, {10.0, 10.0}, {19.0, 10.0}};
    ASSERT_TRUE(tk.makeStrict(path, [] { return false; }));
    EXPECT_TRUE(tk.pathValid(path));
    og::PathGeometric strict(si);
    for (const Vec2 &p : path)
    {
        ob::ScopedState<> st(si->getStateSpace());
        st[0] = p.x;
        st[1] = p.y;
        strict.append(st.get());
    }
    EXPECT_EQ(lengthInside(strict, obstacle, kDenseStep), 0.0);
    EXPECT_TRUE(strict.check());
    // Round the apex, beside it: the mend adds one waypoint next to the tip (about 4 cm longer, a local
    // detour the polish then shortens), not the metres of pushing the segment's ends outward.
    EXPECT_LT(MemeticToolkit::length(path), 18.1);
    std::cout << "[margin] strict length " << MemeticToolkit::length(path) << " with " << path.size()
              << " points\n";
}

TEST(MemeticMargin, AContactInsideASegmentWhoseBendCannotMoveGetsAWaypoint)
{
    // A loose path's bend v = (10, 10) between two discs that graze its segments 1e-5 m away: the upper one
    // touches (1, 10) -> v 0.2 m before v, the lower one v -> (19, 10) halfway. The margin refuses v -> goal
    // for the lower disc, on one side; shifting v away from it (up) runs the first segment into the upper
    // disc, and the goal cannot move, so shifting the segment's ends cannot clear the contact (before: the
    // margin's rounds ran out and makeStrict() refused the path, which then counted as invalid). A waypoint
    // where the margin met the disc, shifted away from it, clears it (docs/variants.md, "No corner the
    // validator cannot see").
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const double r = 3.0, gap = 1e-5;
    const std::array<double, 2> upper{9.8, 10.0 + r + gap}, lower{14.5, 10.0 - r - gap};
    const auto clearance = [&](double x, double y)
    { return std::min(std::hypot(x - upper[0], y - upper[1]), std::hypot(x - lower[0], y - lower[1])) - r; };
    og::SimpleSetupPtr ss = test::planarAppProblem([&](double x, double y) { return clearance(x, y) >= 0.0; },
                                                   0.002, {1.0, 10.0}, {19.0, 10.0});
    ss->setup();
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    ompl::RNG rng(3);
    MemeticToolkit tk(si, rng);
    const double s = setPlannersMargin(tk, si);
    tk.setFixedPoints({1.0, 10.0}, {19.0, 10.0});
    MemeticPath path{{1.0, 10.0}, {10.0, 10.0}, {19.0, 10.0}};
    ASSERT_TRUE(tk.pathValid(path)) << "the validator refuses the loose path";
    ASSERT_TRUE(tk.makeStrict(path, [] { return false; }));
    EXPECT_TRUE(tk.pathValid(path));
    // Every point of the strict path (every 0.1 mm) keeps a clearance: not touching either disc.
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const double l = distance(path[i - 1], path[i]);
        const auto n = static_cast<std::size_t>(std::ceil(l / 1e-4));
        for (std::size_t k = 0; k <= n; ++k)
        {
            const Vec2 p = path[i - 1] + (path[i] - path[i - 1]) * (double(k) / double(n));
            least = std::min(least, clearance(p.x, p.y));
        }
    }
    EXPECT_GT(least, 0.0);
    // A local change: the clearance's detours, not a way round a disc.
    EXPECT_LT(MemeticToolkit::length(path), 18.01);
    std::cout << "[margin] strict length " << MemeticToolkit::length(path) << " with " << path.size()
              << " points, least clearance " << least << " m (c = " << 0.03 * s << " m)\n";
}

TEST(MemeticMargin, TheSearchsVerdictSeesAWallNextToASegmentsEnd)
{
    // With the margin on (an OMPL app's DiscreteMotionValidator), the search's own motion verdict also runs
    // the fine check within s of both ends: a wall 2 cm thick across the segment 1.8-3.8 cm from its start
    // lies between the validator's first two states (5.6 cm apart), so the validator alone accepts the
    // motion; the fine check's samples (every 1.4 cm) see it. Without the margin the verdict is the
    // validator's.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const double x0 = 1.0, near = x0 + 0.0182, far = x0 + 0.0382;
    og::SimpleSetupPtr ss = test::planarAppProblem([&](double x, double y)
                                                   { return !(x > near && x < far && y > 9.0 && y < 11.0); },
                                                   0.002, {1.0, 10.0}, {19.0, 10.0});
    ss->setup();
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    const Vec2 a{x0, 10.0}, b{19.0, 10.0};
    {
        ompl::RNG rng(3);
        MemeticToolkit plain(si, rng);
        plain.setBounds({0.0, 20.0, 0.0, 20.0});
        ASSERT_TRUE(plain.motionValid(a, b))
            << "the validator sees the wall: the test no longer probes anything";
    }
    ompl::RNG rng(3);
    MemeticToolkit tk(si, rng);
    setPlannersMargin(tk, si);
    EXPECT_FALSE(tk.motionValid(a, b));
    EXPECT_FALSE(tk.motionValid(b, a)); // the wall is next to the other end of the reversed motion
    // A motion clear of the wall's ends is still the validator's business alone beyond s from its ends.
    EXPECT_TRUE(tk.motionValid(Vec2{x0, 12.0}, Vec2{19.0, 12.0}));
}

TEST(MemeticMargin, APathThroughAPinchIsRefusedAndItsRefusedSegmentsAreCounted)
{
    // Two squares touching at one corner, (10, 10): a loose path along the other diagonal passes through the
    // touching point, between the validator's samples. No push of the margin undoes that (the way round
    // either square is a metre away), so makeStrict() refuses the path and counts the segments the margin
    // still refuses: the planners skip the halved retry when there are many (a loose path through a maze's
    // pinches; docs/variants.md, "Checks"). A path round both squares passes with none counted.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    og::SimpleSetupPtr ss = test::planarAppProblem(
        [&](double x, double y)
        {
            const bool closed = (x >= 9.0 && x <= 10.0 && y >= 9.0 && y <= 10.0) ||
                                (x >= 10.0 && x <= 11.0 && y >= 10.0 && y <= 11.0);
            return !closed;
        },
        0.002, {5.0, 15.0}, {15.0, 5.0});
    ss->setup();
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    ompl::RNG rng(3);
    MemeticToolkit tk(si, rng);
    setPlannersMargin(tk, si);
    tk.setFixedPoints({5.0, 15.0}, {15.0, 5.0});
    MemeticPath through{{5.0, 15.0}, {7.5, 12.5}, {12.5, 7.5}, {15.0, 5.0}};
    ASSERT_TRUE(tk.pathValid(through)) << "the validator sees the pinch: the test no longer probes anything";
    std::size_t refused = 99;
    EXPECT_FALSE(tk.makeStrict(
        through, [] { return false; }, &refused));
    EXPECT_GE(refused, 1u);
    EXPECT_LT(refused, through.size());

    MemeticPath round{{5.0, 15.0}, {12.0, 12.0}, {15.0, 5.0}};
    refused = 99;
    EXPECT_TRUE(tk.makeStrict(
        round, [] { return false; }, &refused));
    EXPECT_EQ(refused, 0u);
}

TEST(MemeticMargin, TheLocalSearchShowsEachPassesPath)
{
    // tighten()'s afterPass sees the path after every pass but the last (the raw path's strict retry reports
    // them as they come; docs/variants.md, "Checks"): each a valid path from the start to the goal, none
    // longer than the one before, the final path no longer than the last one seen.
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    const Outline wall{{9.0, 4.0}, {11.0, 4.0}, {11.0, 16.0}, {9.0, 16.0}};
    og::SimpleSetupPtr ss = test::planarAppProblem([&](double x, double y) { return !inside(wall, x, y); },
                                                   0.002, {1.0, 10.0}, {19.0, 10.0});
    ss->setup();
    const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
    ompl::RNG rng(3);
    MemeticToolkit tk(si, rng);
    setPlannersMargin(tk, si);
    tk.setFixedPoints({1.0, 10.0}, {19.0, 10.0});
    // A long way round the wall's upper end, zig-zagging.
    MemeticPath path{{1.0, 10.0}};
    for (int k = 1; k < 20; ++k)
        path.push_back({1.0 + 0.9 * k, 17.0 + (k % 2 == 0 ? 1.5 : 0.0)});
    path.push_back({19.0, 10.0});
    ASSERT_TRUE(tk.pathValid(path));
    std::vector<double> seen;
    const MemeticToolkit::StrictScope strict(tk);
    tk.tighten(
        path, 0.3, 1e-6, 30, [] { return false; }, 4000, false,
        [&](const MemeticPath &pass)
        {
            EXPECT_TRUE(tk.pathValid(pass));
            EXPECT_EQ(pass.front(), Vec2(1.0, 10.0));
            EXPECT_EQ(pass.back(), Vec2(19.0, 10.0));
            seen.push_back(MemeticToolkit::length(pass));
        });
    ASSERT_GE(seen.size(), 2u);
    for (std::size_t k = 1; k < seen.size(); ++k)
        EXPECT_LE(seen[k], seen[k - 1] + 1e-9);
    EXPECT_LE(MemeticToolkit::length(path), seen.back() + 1e-9);
    // Round the wall's end (10, 16): at least the two straight lines from start and goal to that corner.
    EXPECT_GE(MemeticToolkit::length(path), 2.0 * std::hypot(9.0, 6.0) - 1e-9);
    EXPECT_LT(seen.front(), 2.0 * std::hypot(9.0, 8.5));
}

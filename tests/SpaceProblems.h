// SPDX-License-Identifier: BSD-3-Clause
/* Test support: self-contained problems on SE(2), Dubins and Reeds-Shepp state spaces (no world files), with
   the test's own geometry as the validity checker and as the independent dense check of returned paths
   (docs/spaces.md). */
#ifndef MHPLAN_TESTS_SPACE_PROBLEMS_H
#define MHPLAN_TESTS_SPACE_PROBLEMS_H

#include "src/collision/CarSpaces.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace mhplan::test
{
    /** \brief An axis-aligned rectangle. */
    struct Rect
    {
        double xmin, xmax, ymin, ymax;
        Rect grown(double m) const { return {xmin - m, xmax + m, ymin - m, ymax + m}; }
    };

    /** \brief True when the segment (ax, ay)-(bx, by) meets the closed rectangle \e r (slab clipping). */
    inline bool segmentHitsRect(double ax, double ay, double bx, double by, const Rect &r)
    {
        double t0 = 0.0, t1 = 1.0;
        const double d[2] = {bx - ax, by - ay}, p[2] = {ax, ay};
        const double lo[2] = {r.xmin, r.ymin}, hi[2] = {r.xmax, r.ymax};
        for (int k = 0; k < 2; ++k)
        {
            if (std::abs(d[k]) < 1e-300)
            {
                if (p[k] < lo[k] || p[k] > hi[k])
                    return false;
                continue;
            }
            double ta = (lo[k] - p[k]) / d[k], tb = (hi[k] - p[k]) / d[k];
            if (ta > tb)
                std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
            if (t0 > t1)
                return false;
        }
        return true;
    }

    /** \brief A stick robot (a segment of half-length \e half centred at the state's position, along its
        heading) among wall rectangles in the box [0, 10]^2; \e margin grows the walls and shrinks the box
        (the checker is conservative by it, the dense check uses 0). */
    inline bool stickValid(const ompl::base::State *s, const std::vector<Rect> &walls, double half,
                           double margin)
    {
        const auto *se2 = s->as<ompl::base::SE2StateSpace::StateType>();
        const double c = std::cos(se2->getYaw()), n = std::sin(se2->getYaw());
        const double ax = se2->getX() - half * c, ay = se2->getY() - half * n;
        const double bx = se2->getX() + half * c, by = se2->getY() + half * n;
        for (const double v : {ax, ay, bx, by})
            if (v < margin || v > 10.0 - margin)
                return false;
        for (const Rect &r : walls)
            if (segmentHitsRect(ax, ay, bx, by, r.grown(margin)))
                return false;
        return true;
    }

    /** \brief A point robot among discs (x, y, radius) in the box [0, 10]^2 (margin as above). */
    inline bool pointAmongCircles(const ompl::base::State *s,
                                  const std::vector<std::array<double, 3>> &circles, double margin)
    {
        const auto *se2 = s->as<ompl::base::SE2StateSpace::StateType>();
        const double x = se2->getX(), y = se2->getY();
        if (x < margin || x > 10.0 - margin || y < margin || y > 10.0 - margin)
            return false;
        for (const auto &c : circles)
            if (std::hypot(x - c[0], y - c[1]) < c[2] + margin)
                return false;
        return true;
    }

    /** \brief A problem on \e space (an SE2StateSpace or a subclass) in the box [0, 10]^2: the validity
        \e valid (with the margin), OMPL's DiscreteMotionValidator at \e resolution of the extent, path
        length objective, start and goal (x, y, yaw). */
    inline ompl::geometric::SimpleSetupPtr
    se2Problem(const std::shared_ptr<ompl::base::SE2StateSpace> &space,
               const std::function<bool(const ompl::base::State *)> &valid,
               const std::array<double, 3> &start, const std::array<double, 3> &goal,
               double resolution = 0.001)
    {
        ompl::base::RealVectorBounds bounds(2);
        bounds.setLow(0.0);
        bounds.setHigh(10.0);
        space->setBounds(bounds);
        auto ss = std::make_shared<ompl::geometric::SimpleSetup>(space);
        ss->setStateValidityChecker(valid);
        ss->getSpaceInformation()->setStateValidityCheckingResolution(resolution);
        ss->getSpaceInformation()->setup();
        ompl::base::ScopedState<ompl::base::SE2StateSpace> s(space), g(space);
        s->setXY(start[0], start[1]);
        s->setYaw(start[2]);
        g->setXY(goal[0], goal[1]);
        g->setYaw(goal[2]);
        ss->setStartAndGoalStates(s, g, 1e-9);
        ss->setOptimizationObjective(
            std::make_shared<ompl::base::PathLengthOptimizationObjective>(ss->getSpaceInformation()));
        return ss;
    }

    /** \brief An OMPL program's planar problem in the 20 m square: the point checker \e valid (x, y), OMPL's
        DiscreteMotionValidator at \e resolution of the extent (28.3 m), path length objective, \e start and
        \e goal (x, y); no planner yet. */
    inline ompl::geometric::SimpleSetupPtr planarAppProblem(const std::function<bool(double, double)> &valid,
                                                            double resolution,
                                                            const std::array<double, 2> &start,
                                                            const std::array<double, 2> &goal)
    {
        namespace ob = ompl::base;
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(0.0, 20.0);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker(
            [valid](const ob::State *s)
            {
                const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
                return valid(v[0], v[1]);
            });
        si->setMotionValidator(std::make_shared<ob::DiscreteMotionValidator>(si));
        si->setStateValidityCheckingResolution(resolution);
        si->setup();
        auto ss = std::make_shared<ompl::geometric::SimpleSetup>(si);
        ob::ScopedState<> a(space), b(space);
        a[0] = start[0];
        a[1] = start[1];
        b[0] = goal[0];
        b[1] = goal[1];
        ss->setStartAndGoalStates(a, b);
        ss->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
        return ss;
    }

    /** \brief The walls of the slot problem: a wall across x in [4.8, 5.2] with a slot y in (4.6, 5.4). */
    inline std::vector<Rect> slotWalls()
    {
        return {{4.8, 5.2, -1.0, 4.6}, {4.8, 5.2, 5.4, 11.0}};
    }
    constexpr double kStickHalf = 0.8;
    constexpr double kCheckerMargin = 0.02;

    /** \brief SE(2) narrow passage needing rotation: a stick of length 1.6, upright at start (2, 2) and
        goal (8, 8), must turn to lie along x to pass the slot of height 0.8 in the wall. */
    inline ompl::geometric::SimpleSetupPtr slotProblem()
    {
        const std::vector<Rect> walls = slotWalls();
        return se2Problem(std::make_shared<ompl::base::SE2StateSpace>(),
                          [walls](const ompl::base::State *s)
                          { return stickValid(s, walls, kStickHalf, kCheckerMargin); },
                          {2.0, 2.0, M_PI / 2}, {8.0, 8.0, M_PI / 2});
    }

    /** \brief An easy SE(2) problem (for the contract): the stick from (1, 5) to (9, 5) heading along x
        past a block x in [4, 6], y in [3, 7]. */
    inline ompl::geometric::SimpleSetupPtr blockProblem()
    {
        const std::vector<Rect> walls{{4.0, 6.0, 3.0, 7.0}};
        return se2Problem(std::make_shared<ompl::base::SE2StateSpace>(),
                          [walls](const ompl::base::State *s)
                          { return stickValid(s, walls, 0.5, kCheckerMargin); },
                          {1.0, 5.0, 0.0}, {9.0, 5.0, 0.0});
    }

    /** \brief The discs of the car problems. */
    inline std::vector<std::array<double, 3>> carCircles()
    {
        return {{5.0, 5.0, 1.5}, {2.5, 7.0, 1.0}, {7.5, 3.0, 1.0}};
    }

    /** \brief A point car of turning radius 1 (Dubins, forward only; or Reeds-Shepp when \e reverse) from
        (1, 1) heading +x to (9, 9) heading +x among carCircles(); OMPL's Dubins / Reeds-Shepp motion
        validator (one curve per motion) at 0.005 of the extent (a step of 0.07 cuts a disc of radius 1 by
        at most 0.07^2 / 8 < 0.001, well inside the checker's margin of 0.02). */
    inline ompl::geometric::SimpleSetupPtr carProblem(bool reverse)
    {
        const auto circles = carCircles();
        std::shared_ptr<ompl::base::SE2StateSpace> space;
        if (reverse)
            space = std::make_shared<ompl::base::ReedsSheppStateSpace>(1.0);
        else
            space = std::make_shared<SafeDubinsStateSpace>(1.0); // OMPL's dubins() may assert
        auto ss = se2Problem(
            space,
            [circles](const ompl::base::State *s) { return pointAmongCircles(s, circles, kCheckerMargin); },
            {1.0, 1.0, 0.0}, {9.0, 9.0, 0.0}, 0.005);
        const ompl::base::SpaceInformationPtr &si = ss->getSpaceInformation();
        if (reverse)
            si->setMotionValidator(std::make_shared<ompl::base::ReedsSheppMotionValidator>(si));
        else
            si->setMotionValidator(std::make_shared<ompl::base::DubinsMotionValidator>(si));
        si->setup();
        return ss;
    }

    /** \brief Independent dense check of \e path with \e valid (the exact geometry): every segment
        interpolated by the space at steps of \e step times the space's maximum extent. */
    inline bool denseValid(const ompl::geometric::PathGeometric &path,
                           const std::function<bool(const ompl::base::State *)> &valid, double step = 2e-4)
    {
        const auto &si = path.getSpaceInformation();
        const double h = step * si->getMaximumExtent();
        ompl::base::State *s = si->allocState();
        bool ok = true;
        for (std::size_t i = 0; ok && i + 1 < path.getStateCount(); ++i)
        {
            const double d = si->distance(path.getState(i), path.getState(i + 1));
            const auto n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(d / h)));
            for (std::size_t k = 0; ok && k <= n; ++k)
            {
                si->getStateSpace()->interpolate(path.getState(i), path.getState(i + 1), double(k) / n, s);
                ok = valid(s);
            }
        }
        si->freeState(s);
        return ok;
    }
} // namespace mhplan::test

#endif

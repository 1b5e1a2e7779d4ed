// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: keeping mhplan's planners clear of OMPL 1.5.2's Dubins assertions (docs/spaces.md, "OMPL's Dubins
   assertions"). */
#ifndef MHPLAN_DUBINS_GUARD_H
#define MHPLAN_DUBINS_GUARD_H

#include "src/collision/CarSpaces.h"

#include <ompl/base/SpaceInformation.h>

#include <memory>

namespace mhplan
{
    /** \brief On OMPL's own DubinsStateSpace, some pairs of finite states abort the process inside OMPL's
        dubins() (an assertion that Debian's build keeps); every distance, interpolation and motion check of
        the pair calls it. A planner that builds states near its paths' curves meets such pairs (a state
        heading almost along the line to the other), so mhplan's planners ask this guard first: a pair it
        calls unsafe is never a motion (refused, so no returned path holds one), and its distance and
        interpolation come from SafeDubinsStateSpace (mhplan's own computation of the same shortest paths,
        equal to OMPL's wherever OMPL's do not abort). Inactive (every pair safe, no cost) on any other space
        and on SafeDubinsStateSpace itself. */
    class DubinsGuard
    {
      public:
        explicit DubinsGuard(const ompl::base::StateSpace *space);

        bool active() const { return safeSpace_ != nullptr; }

        /** \brief Whether OMPL can evaluate the pair: its distance, interpolation and motion check from \e a
            to \e b compute dubins(a, b), and dubins(b, a) too on the symmetric variant. */
        bool safe(const ompl::base::State *a, const ompl::base::State *b) const
        {
            return !active() ||
                   (!omplDubinsMayFail(a, b, radius_) && !(symmetric_ && omplDubinsMayFail(b, a, radius_)));
        }

        /** \brief The space's distance from \e a to \e b: OMPL's where it is safe, else the same metric by
            SafeDubinsStateSpace. \e isSafe: safe(a, b) where the caller has it already. */
        double distance(const ompl::base::SpaceInformation &si, const ompl::base::State *a,
                        const ompl::base::State *b) const
        {
            return distance(si, a, b, safe(a, b));
        }
        double distance(const ompl::base::SpaceInformation &si, const ompl::base::State *a,
                        const ompl::base::State *b, bool isSafe) const;

        /** \brief The space's interpolation, likewise. */
        void interpolate(const ompl::base::SpaceInformation &si, const ompl::base::State *a,
                         const ompl::base::State *b, double t, ompl::base::State *out) const
        {
            interpolate(si, a, b, t, out, safe(a, b));
        }
        void interpolate(const ompl::base::SpaceInformation &si, const ompl::base::State *a,
                         const ompl::base::State *b, double t, ompl::base::State *out, bool isSafe) const;

        /** \brief si.checkMotion(a, b), false for an unsafe pair. */
        bool checkMotion(const ompl::base::SpaceInformation &si, const ompl::base::State *a,
                         const ompl::base::State *b) const
        {
            return safe(a, b) && si.checkMotion(a, b);
        }

      private:
        double radius_{0.0};
        bool symmetric_{false};
        std::shared_ptr<SafeDubinsStateSpace> safeSpace_;
    };
} // namespace mhplan

#endif

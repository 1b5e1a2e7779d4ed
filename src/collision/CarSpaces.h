// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the Dubins state space mhplan builds (docs/spaces.md, "Rigid-body and car worlds"). */
#ifndef MHPLAN_CAR_SPACES_H
#define MHPLAN_CAR_SPACES_H

#include <ompl/base/spaces/DubinsStateSpace.h>

namespace mhplan
{
    /** \brief OMPL's DubinsStateSpace (forward only, asymmetric distance) with mhplan's own shortest-path
        word selection. OMPL 1.5.2's dubins() asserts (and Debian's build keeps assertions, so the process
        aborts) when the goal lies almost on one of the start's turning circles: it takes p = 0 for a
        slightly negative p^2 and then checks the end point to 2e-6. Here every one of the six words (LSL,
        RSR, LSR, RSL, RLR, LRL, and the single left or right arc) is computed by the closed forms of Shkel
       and Lumelsky, its end pose is followed from the start and compared with the goal, and the shortest word
       that arrives (within 1e-6 of the turning radius) is taken; OMPL's own interpolation then follows it.
       Distances equal OMPL's wherever OMPL's do not abort (tests/test_rigid_body.cpp checks it). */
    class SafeDubinsStateSpace : public ompl::base::DubinsStateSpace
    {
      public:
        explicit SafeDubinsStateSpace(double turningRadius)
            : ompl::base::DubinsStateSpace(turningRadius, false)
        {
        }

        double distance(const ompl::base::State *state1, const ompl::base::State *state2) const override;
        void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                         ompl::base::State *state) const override;
        void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                         bool &firstTime, DubinsPath &path, ompl::base::State *state) const override;

        /** \brief The shortest Dubins path (lengths in turning radii), as OMPL's dubins() but never aborting.
         */
        DubinsPath shortestPath(const ompl::base::State *state1, const ompl::base::State *state2) const;

        double turningRadius() const { return rho_; }
    };
} // namespace mhplan

#endif

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the Dubins state space mhplan builds (docs/spaces.md, "Rigid-body and car worlds"). */
#ifndef MHPLAN_CAR_SPACES_H
#define MHPLAN_CAR_SPACES_H

#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

namespace mhplan
{
    namespace detail
    {
        /** \brief The turning radius of OMPL's car spaces (a protected member, read through a derived
            class). */
        struct DubinsRadius : ompl::base::DubinsStateSpace
        {
            static double of(const ompl::base::DubinsStateSpace &s) { return s.*(&DubinsRadius::rho_); }
        };
        struct ReedsSheppRadius : ompl::base::ReedsSheppStateSpace
        {
            static double of(const ompl::base::ReedsSheppStateSpace &s)
            {
                return s.*(&ReedsSheppRadius::rho_);
            }
        };
    } // namespace detail

    /** \brief OMPL's DubinsStateSpace (forward only, asymmetric distance) with mhplan's own shortest-path
        word selection. OMPL 1.5.2's dubins() asserts (and Debian's build keeps assertions, so the process
        aborts) on some finite pairs: it rounds a first turn within 5e-7 of a whole turn to 0 and then checks
        the word's end to 2e-6 (omplDubinsMayFail() below; docs/spaces.md, "OMPL's Dubins assertions"). Here
        every one of the six words (LSL, RSR, LSR, RSL, RLR, LRL, and the single left or right arc) is
        computed by the closed forms of Shkel and Lumelsky, its end pose is followed from the start and
        compared with the goal, and the shortest word that arrives (within 1e-6 of the turning radius) is
        taken; OMPL's own interpolation then follows it. Distances equal OMPL's wherever OMPL's do not abort
        (tests/test_rigid_body.cpp checks it). */
    class SafeDubinsStateSpace : public ompl::base::DubinsStateSpace
    {
      public:
        /** \brief \e isSymmetric as OMPL's: the distance is the shorter of the two directions' paths, and
            interpolation follows that path. */
        explicit SafeDubinsStateSpace(double turningRadius, bool isSymmetric = false)
            : ompl::base::DubinsStateSpace(turningRadius, isSymmetric)
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

    /** \brief Whether OMPL 1.5.2's DubinsStateSpace::dubins(\e state1, \e state2) (turning radius \e rho)
        may fail one of its assertions, which Debian's build keeps, so that the process aborts
        (docs/spaces.md, "OMPL's Dubins assertions"). OMPL wraps each word's turn angles into [0, 2 pi) but
        takes a turn within 5e-7 of a whole turn short as 0; the word then misses the goal by about the
        dropped angle times its lever (the straight part's length and more), and the assertions compare the
        end with the goal to 2e-6 turning radii. This finds every word whose first turn, or whose two turns
        together, would be so rounded within twice OMPL's window (1e-6) and whose error could then exceed half
        of OMPL's tolerance: conservative. Distance and interpolation of OMPL's space evaluate both
        directions only when symmetric; DubinsGuard (ompl_planners/common) asks both. */
    bool omplDubinsMayFail(const ompl::base::State *state1, const ompl::base::State *state2, double rho);
} // namespace mhplan

#endif

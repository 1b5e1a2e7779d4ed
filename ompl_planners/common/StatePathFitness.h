// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the waypoint encoding and the [LRSMA] fitness on any state space with a parametrisation
   (docs/spaces.md, "Planners on state spaces"; docs/algorithms.md 1.1-1.2 are its R^k form). */
#ifndef MHPLAN_STATE_PATH_FITNESS_H
#define MHPLAN_STATE_PATH_FITNESS_H

#include "ompl_planners/common/DubinsGuard.h"
#include "ompl_planners/common/Fitness.h"
#include "ompl_planners/common/StateParametrisation.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <vector>

namespace mhplan
{
    /** \brief Decodes a candidate x (m waypoints of StateParametrisation::dimension() coordinates) into
        the path start, waypoint states, goal and evaluates the [LRSMA] fitness S = eta1 length + eta2 f2 on
        it, with the space's own metric and interpolation (docs/spaces.md):
        - each waypoint is StateParametrisation::fromVector() of its coordinates; consecutive states are
          joined by the space's interpolate() (straight lines and shortest rotations on SE(2)/SE(3), Dubins
          and Reeds-Shepp curves on those spaces);
        - length = sum of si->distance() over the m + 1 segments (the Dubins / Reeds-Shepp length there);
        - f2 = mean over n states interpolated along the path (at the evenly spaced parameters of the R^k
          polyline's samples, docs/algorithms.md 1.1) of the checker's penetration min(max(-clearance, 0) /
          1 m, 1) when the checker computes clearance, else 1 per invalid state (PenaltyMode::Clearance /
          ValidityOnly); a sample outside the space's bounds (si->satisfiesBounds(); a Dubins curve between
          states inside the box can leave it) adds 1;
        - feasible when f2 = 0 and every segment passes si->checkMotion(); a path with f2 = 0 that fails
          the motion validator gets f2 = 1e-3 (as in R^k).
        On DubinsStateSpace and ReedsSheppStateSpace the curve of a segment is computed once for all the
        samples on it (the spaces' caching interpolate()), not once per sample.
        Every state is allocated by configure(); evaluate() allocates nothing itself (OMPL's Dubins and
        Reeds-Shepp interpolation allocate a temporary state per call). Not thread-safe. */
    class StatePathFitness
    {
      public:
        StatePathFitness(ompl::base::SpaceInformationPtr si, const StateParametrisation &param);
        ~StatePathFitness();
        StatePathFitness(const StatePathFitness &) = delete;
        StatePathFitness &operator=(const StatePathFitness &) = delete;

        /** \brief Set the query, m = \e waypoints, n = \e samples interpolated states and the weights;
            allocates the states. */
        void configure(const ompl::base::State *start, const ompl::base::State *goal, unsigned int waypoints,
                       unsigned int samples, const FitnessWeights &weights);
        /** \brief Decode and evaluate \e x; path() then holds the decoded states. */
        FitnessResult evaluate(const double *x);
        /** \brief Decode \e x into path() without evaluating it. */
        void decode(const double *x);
        /** \brief The last decoded path: start, m waypoints, goal. */
        const std::vector<ompl::base::State *> &path() const { return path_; }
        PenaltyMode penaltyMode() const { return mode_; }

      private:
        void freeStates();

        ompl::base::SpaceInformationPtr si_;
        const StateParametrisation &param_;
        std::vector<ompl::base::State *> path_;
        ompl::base::State *sample_{nullptr};
        unsigned int samples_{100};
        FitnessWeights weights_;
        PenaltyMode mode_{PenaltyMode::ValidityOnly};
        /** \brief Set on those spaces: the curve of the current segment, reused by its samples. */
        const ompl::base::DubinsStateSpace *dubins_{nullptr};
        const ompl::base::ReedsSheppStateSpace *reedsShepp_{nullptr};
        ompl::base::DubinsStateSpace::DubinsPath dubinsPath_;
        ompl::base::ReedsSheppStateSpace::ReedsSheppPath reedsSheppPath_;
        /** \brief Pairs OMPL 1.5.2's Dubins code would abort on (docs/spaces.md, "OMPL's Dubins assertions"):
            such a segment is infeasible, measured and sampled by SafeDubinsStateSpace. */
        DubinsGuard guard_;
        std::vector<char> safe_;
    };
} // namespace mhplan

#endif

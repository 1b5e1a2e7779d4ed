// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the path fitness functions of docs/algorithms.md 1.2 ([LRSMA]) and 1.3 ([GMS]), shared by every
   population planner. */
#ifndef MHPLAN_FITNESS_H
#define MHPLAN_FITNESS_H

#include "src/collision/Collision.h"
#include "ompl_planners/common/PathEncoding.h"

#include <ompl/base/SpaceInformation.h>

#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Which fitness a planner uses. */
    enum class FitnessKind
    {
        LengthPenalty,     ///< [LRSMA] S = eta1 * length + eta2 * collision violation (1.2), minimised
        FeasibleInfeasible ///< [GMS] f1 (feasible) / f2 (infeasible), maximised reciprocals (1.3)
    };

    /** \brief The maximised [GMS] value (f1 or f2, docs/algorithms.md 1.3) of a [GMS] fitness key (what
        FitnessResult::fitness holds for FitnessKind::FeasibleInfeasible: -f1 < 0 for a feasible path,
        1 / f2 > 0 for an infeasible one, so that minimising the key ranks feasibility first, then f). */
    inline double gmsValueOfKey(double key)
    {
        return key < 0.0 ? -key : 1.0 / key;
    }

    /** \brief Parse "lrsma" or "gms" (throws std::invalid_argument naming the parameter 'fitness'). */
    FitnessKind parseFitnessKind(const std::string &name);
    std::string toString(FitnessKind kind);

    /** \brief Weights of both fitness functions (defaults from docs/algorithms.md 1.2 and 1.3). */
    struct FitnessWeights
    {
        /** \brief eta1 of [LRSMA] (length). */
        double lengthWeight{1.0};
        /** \brief eta2 of [LRSMA] (collision violation). */
        double penaltyWeight{1000.0};
        /** \brief w_d, w_s, w_sm of [GMS] f1 (length, danger, turning). */
        double distanceWeight{1.0};
        double safetyWeight{1.0};
        double smoothnessWeight{0.1};
        /** \brief d_safe of the [GMS] danger term alpha(l) = max(0, 1 - clearance(l) / d_safe). */
        double safeDistance{0.5};
        /** \brief w_l, w_c of [GMS] f2 (share of length inside obstacles, obstacles crossed per metre). */
        double infeasibleLengthWeight{1.0};
        double crossingWeight{1.0};
        /** \brief D of [GMS] f2 (unreadable in the paper; docs/algorithms.md 1.3): true (the recommendation)
            D = f1's denominator of the same path; false: a constant, 20 x the sum of the bounds' sides, so
            infeasible paths rank by w_l lin + w_c cro alone (the form before issue 17). */
        bool infeasibleBaseIsPath{true};
    };

    /** \brief One evaluation. */
    struct FitnessResult
    {
        /** \brief What planners minimise: [LRSMA] S; for [GMS] the key -f1 (feasible) or 1 / f2 =
            D + w_l lin + w_c cro (infeasible), see gmsValueOfKey(). */
        double fitness{0.0};
        /** \brief [GMS] only: the maximised value f1 or f2 (0 for [LRSMA]). */
        double gmsValue{0.0};
        double length{0.0};
        /** \brief Every segment passed the space information's motion validator. */
        bool feasible{false};
        /** \brief The collision violation (f2 of [LRSMA], lin + cro of [GMS]); 0 for feasible paths. */
        double violation{0.0};
    };

    /** \brief How the [LRSMA] collision term f2 measures a sample point (docs/algorithms.md 1.2). */
    enum class PenaltyMode
    {
        ExactCircles, ///< the spec's circle formula (planar WorldValidityChecker over circles only)
        Clearance,    ///< penetration depth from the validity checker's clearance()
        ValidityOnly  ///< 1 per invalid sample (the checker computes no clearance)
    };

    /** \brief Evaluates paths with the problem's own validity checker and motion validator, so it works on
        any ompl::base::RealVectorStateSpace problem of any dimension k (points are k coordinates; the
        planar Vec2 overloads are for k = 2).

        [LRSMA] collision term f2 (docs/algorithms.md 1.2), choices made here (penaltyMode()):
        - ExactCircles: when k = 2 and the validity checker is a WorldValidityChecker over an
          AnalyticCollisionModel whose world has only circles, the exact formula of the spec: f2 = sum over
          circles of the mean over the samples of max(1 - |q - c| / (R + r), 0), r the robot radius.
        - Clearance: otherwise, when the checker computes clearance (mhplan's WorldValidityChecker, or a
          foreign checker whose StateValidityCheckerSpecs::clearanceComputationType is not NONE):
          f2 = mean over the samples of min(max(-clearance(q), 0) / 1 m, 1).
        - ValidityOnly: a foreign checker with clearanceComputationType == NONE (the default of OMPL's
          StateValidityChecker, and of the std::function checkers of SpaceInformation), whose clearance() is
          not meaningful: f2 = the fraction of invalid samples (each invalid sample counts 1).
        - In every mode a sample outside the space's bounds (splines can overshoot) adds
          min(distance outside / 1 m, 1) to the mean: the outside of the box is treated as an obstacle.
        - A path with f2 = 0 that still fails the motion validator (a thin obstacle between samples) gets
          f2 = 1e-3 (so S rises by eta2 / 1000): it must not tie with a valid path of the same length.
        Feasibility (reported exact solutions) is decided by the motion validator, and for foreign checkers
        also by the space's bounds: OMPL's checkers and its DiscreteMotionValidator do not look at the bounds,
        and spline samples can overshoot them, so pointValid() and segmentValid() refuse points outside the
        bounds (mhplan's WorldValidityChecker models check their own box).

        [GMS] f1/f2 (1.3): segment clearance is exact for planar WorldValidityChecker models, otherwise
        sampled at the space's validity-checking resolution; with a checker that computes no clearance the
        danger term saf(p) is 0 (there is nothing to measure it with). The turning angle between segments
        is the angle between their direction vectors in R^k. lin(p) and cro(p) sample every segment at the
        validity-checking resolution (an obstacle crossing = one maximal run of invalid samples). The paper's
        reciprocals are maximised: f1 = 1 / (w_d dis + w_s saf + w_sm smo); f2 = 1 / (D + w_l lin + w_c cro)
        with D (unreadable in the paper) = f1's denominator of the same path, so an infeasible path scores
        below the same path without its collisions; every feasible path ranks above every infeasible one
        (open choices of docs/algorithms.md 1.3). FitnessResult::fitness is a key to minimise with that order
        (see gmsValueOfKey()); FitnessResult::gmsValue is f1 or f2 itself. alpha(l) is clamped to [0, 1].

        Holds two preallocated states: evaluate() does not allocate (the Vec2 overloads copy into buffers
        that are reused). Not thread-safe. */
    class PathFitness
    {
      public:
        explicit PathFitness(ompl::base::SpaceInformationPtr si);
        ~PathFitness();
        PathFitness(const PathFitness &) = delete;
        PathFitness &operator=(const PathFitness &) = delete;

        /** \brief Choose the fitness and weights; inspects the validity checker (call after its setup). */
        void configure(FitnessKind kind, const FitnessWeights &weights);

        /** \brief Evaluate \e path (start to goal); \e samples are the [LRSMA] interpolation points (may be
            the path itself; unused by [GMS]). Points of spaceDimension() coordinates. */
        FitnessResult evaluate(const PointsView &path, const PointsView &samples);
        /** \brief evaluate() for planar problems (k = 2). */
        FitnessResult evaluate(const std::vector<Vec2> &path, const std::vector<Vec2> &samples);

        /** \brief The motion validator's verdict on one straight segment (k coordinates each). */
        bool segmentValid(const double *a, const double *b) const;
        /** \brief The validity checker's verdict on one point (outside the space's bounds: invalid). */
        bool pointValid(const double *p) const;
        /** \brief Signed clearance from the validity checker (meaningful unless penaltyMode() is
            ValidityOnly). */
        double clearance(const double *p) const;
        /** \brief Minimum clearance along a segment (exact for mhplan's planar models, else sampled). */
        double segmentClearance(const double *a, const double *b) const;
        /** \brief Every segment of \e path valid. */
        bool pathValid(const PointsView &path) const;
        /** \brief The denominator w_d dis + w_s saf + w_sm smo of the [GMS] f1 = 1 / denominator of a path
            (no feasibility check): what node improvement lowers. */
        double gmsFeasibleFitness(const PointsView &path) const;

        /** \brief The motion validator's verdict on one straight segment. */
        bool segmentValid(const Vec2 &a, const Vec2 &b) const;
        /** \brief The validity checker's verdict on one point. */
        bool pointValid(const Vec2 &p) const;
        /** \brief Signed clearance from the validity checker. */
        double clearance(const Vec2 &p) const;
        /** \brief Minimum clearance along a segment (exact for mhplan's models, else sampled). */
        double segmentClearance(const Vec2 &a, const Vec2 &b) const;
        /** \brief Every segment of \e path valid. */
        bool pathValid(const std::vector<Vec2> &path) const;
        /** \brief The denominator of the [GMS] f1 of a planar path (no feasibility check). */
        double gmsFeasibleFitness(const std::vector<Vec2> &path) const;

        FitnessKind kind() const { return kind_; }
        const FitnessWeights &weights() const { return weights_; }
        /** \brief True when the exact circle formula of 1.2 is in use. */
        bool exactCircles() const { return mode_ == PenaltyMode::ExactCircles; }
        /** \brief How f2 measures a sample (set by configure()). */
        PenaltyMode penaltyMode() const { return mode_; }
        /** \brief Coordinates per point k (the state space's dimension). */
        unsigned int spaceDimension() const { return dim_; }
        const ompl::base::SpaceInformationPtr &spaceInformation() const { return si_; }

      private:
        double collisionViolation(const PointsView &samples) const;
        double outOfBounds(const double *p) const;
        /** \brief Inside the space's bounds (per coordinate, inclusive). */
        bool inBounds(const double *p) const;
        /** \brief The validity checker alone (no bounds). */
        bool checkerValid(const double *p) const;
        FitnessResult evaluateLengthPenalty(const PointsView &path, const PointsView &samples);
        FitnessResult evaluateGms(const PointsView &path);
        void toState(ompl::base::State *s, const double *p) const;
        void requirePlanar(const char *what) const;
        /** \brief Copy planar points into \e buffer and view them. */
        static PointsView planar(const std::vector<Vec2> &points, std::vector<double> &buffer);

        ompl::base::SpaceInformationPtr si_;
        ompl::base::State *s1_{nullptr};
        ompl::base::State *s2_{nullptr};
        FitnessKind kind_{FitnessKind::LengthPenalty};
        FitnessWeights weights_;
        unsigned int dim_{2};
        /** \brief Set when the checker is a WorldValidityChecker on a planar space: exact clearance queries.
         */
        CollisionModelPtr model_;
        PenaltyMode mode_{PenaltyMode::Clearance};
        std::vector<Circle> circles_;
        /** \brief The box outside which samples are penalised (per coordinate). */
        std::vector<double> low_, high_;
        double resolution_{0.01};
        /** \brief The constant D of FitnessWeights::infeasibleBaseIsPath = false. */
        double infeasibleConstant_{0.0};
        /** \brief Reused buffers of the planar overloads. */
        mutable std::vector<double> planarA_, planarB_, point_;
    };
} // namespace mhplan

#endif

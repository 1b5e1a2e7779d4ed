// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: SMA-MEM, MGO-MEM and LRSMA-MEM, memetic improved variants (not in the papers) whose update rules
   act on normal offsets at stations along the best path found so far. */
#ifndef MHPLAN_MEMETIC_OFFSET_PLANNERS_H
#define MHPLAN_MEMETIC_OFFSET_PLANNERS_H

#include "ompl_planners/memetic/MemeticPlanner.h"

#include <string>
#include <vector>

namespace mhplan
{
    /** \brief Base of the memetic variants of the continuous algorithms (SMA, MGO, LRSMA): a position is a
        vector x of K normal offsets at K stations along a feasible reference path, the best individual
        found so far (MemeticPlanner supplies walks, local search, elite polish, restarts).

        Choices (stated as docs/conventions.md asks):
        - Reference and stations: the reference is the best (coarse) individual ever found; its K stations
          sit at equal arc length (K = 8 + ceil(total turn of the reference / 0.25 rad), at most
          \c max_stations: the encoding grows with the number of obstacles the path wraps), each with the
          unit normal of its reference segment. The reference's own position is x = 0; the algorithms'
          "best position" is therefore 0. When a better individual appears it becomes the reference and
          every position is re-encoded against it.
        - Decoding x (always feasible): q_k = r_k + x_k n_k, shrunk toward r_k (halved twice, then r_k
          itself) until q_k is valid and sees r_k; the path runs start, q_1, ..., q_K, goal, joining
          consecutive points by a straight segment when the motion validator accepts it, else by returning
          along the normal to the reference, following it, and leaving it along the next normal. Then the
          coarse local search and the evaluation (MemeticPlanner::improveAndEvaluate()).
        - Lamarckian re-encoding: the improved path's offset at station k is its crossing with the normal
          line of station k closest to r_k (0 when it does not cross within the offset range).
        - Offsets are bounded by +-D, D = \c offset_range x the bounds' larger side (the "bounds" of the
          position; random positions are uniform in them).
        - State mode (any space but R^2, docs/spaces.md): the stations are K = min(\c max_stations, 8 + the
          reference's interior waypoints) states at equal arc length along the reference, a position holds a
          displacement of every coordinate of the parametrisation at every station (coordinate c scaled by
          its range over the largest range, so D applies to all alike); the decoding and the fallback to the
          reference are as above with the space's interpolation; the re-encoding is the displacement of the
          improved path's state at the station's arc share.
        - Schedules t/T: T = \c iterations generations per epoch; an epoch ends by a restart with elitism
          (MemeticPlanner) and the next one runs twice as long, so no time budget is needed. */
    class OffsetMemeticPlanner : public MemeticPlanner
    {
      public:
        OffsetMemeticPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name,
                             unsigned int populationSize);

        /** \brief Schedule length T of the first epoch (1..1000000). */
        void setIterations(unsigned int t);
        unsigned int getIterations() const { return iterations_; }
        /** \brief Largest number of stations K (8..1024). */
        void setMaxStations(unsigned int k);
        unsigned int getMaxStations() const { return maxStations_; }
        /** \brief Offset bound D as a share of the bounds' larger side (0.001..1). */
        void setOffsetRange(double r);
        double getOffsetRange() const { return offsetRange_; }

      protected:
        void startAlgorithm() override;
        void restartAlgorithm() override;
        void clearAlgorithm() override;
        void populationChanged() override;

        /** \brief Decode \e x into \e out, improve and evaluate it and re-encode the result into \e x; false
            when interrupted. */
        bool decodeEvaluate(std::vector<double> &x, Individual &out);
        /** \brief Offsets of \e ind's path against the current reference. */
        void encode(const Individual &ind, std::vector<double> &x);
        /** \brief Uniform random position in [-D, D]^K. */
        void randomPosition(std::vector<double> &x);
        void clampPosition(std::vector<double> &x) const;
        /** \brief Take a better individual of pop_ as the reference (re-encoding every position). */
        void updateReference();
        /** \brief The schedule index t in 1..T of generation \e t of the epoch, and T. */
        double scheduleFraction(unsigned long t) const;

        /** \brief The length of a position: K (planar) or K times the parametrisation's dimension (state
            mode). */
        unsigned int stations() const
        {
            return static_cast<unsigned int>(stateMode() ? rs_.size() * stateDim_ : r_.size());
        }
        double offsetBound() const { return offsetRange_ * scale(); }

        /** \brief Positions, one per individual of pop_. */
        std::vector<std::vector<double>> x_;

      private:
        void buildStations();
        // State mode (MemeticOffsetStates.cpp, docs/spaces.md "The memetic planners off the plane").
        void buildStateStations();
        void encodeStates(const StatePath &path, std::vector<double> &x);
        bool decodeEvaluateStates(std::vector<double> &x, Individual &out);

        unsigned int iterations_{30};
        unsigned int maxStations_{64};
        double offsetRange_{0.1};
        unsigned long epochLength_{30};
        Individual reference_;
        bool haveReference_{false};
        MemeticPath r_;
        std::vector<Vec2> n_;
        std::vector<std::size_t> seg_;
        StatePath rs_;
        unsigned int stateDim_{0};
        /** \brief State mode: coordinate c of an offset is x * coordScale_[c] (its range / the largest). */
        std::vector<double> coordScale_;
    };

    /** \brief SMA-MEM: the slime mould algorithm's update (Li et al. 2020) on station offsets. Each
       generation: rank by cost; weights W = 1 +- r log10((bF - S_i) / (bF - wF - eps) + 1) (better half
       plus); a = arctanh(1 - t/T), b = 1 - t/T; each slime mould is redrawn uniformly with probability \c z,
       else per offset X_j = X_best_j + vb_j (W_ij X_A_j - X_B_j) when r < tanh|S_i - DF|, else vc_j X_j
       (X_best = 0, the reference; DF its cost); every new position is decoded, improved, evaluated and
       replaces the old one (as in SMA; the best is archived as the reference). */
    class MemeticSlimeMould : public OffsetMemeticPlanner
    {
      public:
        explicit MemeticSlimeMould(const ompl::base::SpaceInformationPtr &si,
                                   const std::string &name = "SMA-MEM");
        void setZ(double z);
        double getZ() const { return z_; }

      protected:
        bool generation(unsigned long t) override;
        /** \brief One SMA step over the population (shared with LRSMA-MEM). */
        bool slimeMouldStep(unsigned long t);

      private:
        double z_{0.1};
    };

    /** \brief LRSMA-MEM: SMA-MEM plus LRSMA's (Zheng et al. 2023) Levy flight around the elite (three
        trials alpha (X_best + \c levy_step D levy()), alpha = 1 + index U(0, 0.5), Mantegna beta = 1.5,
        replacing the worst individual when better), and its rotation perturbation when the best cost has
        not changed by more than 1e-9 (relative) for 5 generations: the best \c rotation_fraction of the
        population is rotated, x + omega r x / |x| (omega U(0.1, 1), r U(-1, 1) per offset), greedily. */
    class MemeticLRSMA : public MemeticSlimeMould
    {
      public:
        explicit MemeticLRSMA(const ompl::base::SpaceInformationPtr &si);
        void setLevyStep(double s);
        double getLevyStep() const { return levyStep_; }
        void setRotationFraction(double f);
        double getRotationFraction() const { return rotationFraction_; }

      protected:
        bool generation(unsigned long t) override;
        void startAlgorithm() override;

      private:
        double levy();
        double levyStep_{0.05};
        double rotationFraction_{0.3};
        double sigmaU_{0.0};
        double previousBest_{0.0};
        unsigned int flat_{0};
    };

    /** \brief MGO-MEM: the mountain gazelle optimizer's (Abdollahzadeh et al. 2022) four moves on station
        offsets: territorial solitary males TSM = male - |(ri1 BH - ri2 X) F| Cof, maternity herds MH = (BH +
        Cof) + (ri3 male - ri4 X_rand) Cof, bachelor male herds BMH = (X - D) + (ri5 male - ri6 BH) Cof and
        migration MSF = a random position, with male = the reference (0), BH from a random gazelle of the
        worse two thirds and the mean of ceil(N/3) random ones, a = -1 - t/T, F = N(0,1) exp(2 - 2t/T); the
        4N children (decoded, improved, evaluated) and the N gazelles are merged and the best N kept. */
    class MemeticGazelle : public OffsetMemeticPlanner
    {
      public:
        explicit MemeticGazelle(const ompl::base::SpaceInformationPtr &si);

      protected:
        bool generation(unsigned long t) override;
    };
} // namespace mhplan

#endif

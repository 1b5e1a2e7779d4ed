// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the bacterial colony of BFO / ATBFO (docs/algorithms.md 6.1, 6.2), shared by the BFO planner
   (BacterialForaging) and the simulator's bfo / atbfo controllers. */
#ifndef MHPLAN_BACTERIAL_COLONY_H
#define MHPLAN_BACTERIAL_COLONY_H

#include <ompl/util/RandomNumbers.h>

#include <cstdint>
#include <vector>

namespace mhplan
{
    /** \brief Passino's loop counts and step of a BFO colony and ATBFO's adaptive tumble
        (docs/algorithms.md 6.1, 6.2). The owner keeps it; the colony reads it live (a change between two
        steps applies from the next step). */
    struct ColonySettings
    {
        /** \brief Nc, chemotactic steps per reproduction. */
        unsigned int chemotacticSteps{8};
        /** \brief Ns, the maximal swim length. */
        unsigned int swimLength{6};
        /** \brief Nre, reproductions per elimination-dispersal event. */
        unsigned int reproductionSteps{2};
        /** \brief Ned, elimination-dispersal events per run. */
        unsigned int eliminationEvents{1};
        /** \brief Ped, the probability of dispersal per bacterium and event. */
        double eliminationProbability{0.15};
        /** \brief C, the chemotactic step. */
        double stepSize{0.1};
        /** \brief ATBFO: a bacterium whose swim improved J more than \c improvementThreshold times in a
            chemotactic step (the tumble move not counted) keeps its direction for the next one. */
        bool adaptiveTumble{false};
        unsigned int improvementThreshold{3};
        /** \brief Passino's cell-to-cell term J_cc (d_att, w_att, h_rep, w_rep). */
        bool cellToCell{false};
        double attractDepth{0.1}, attractWidth{0.2}, repelHeight{0.1}, repelWidth{10.0};
    };

    /** \brief What a colony searches: the cost J, where a new bacterium lands, how a move is kept in the
        search region, when to stop, and the tumble direction. */
    class ColonyProblem
    {
      public:
        virtual ~ColonyProblem() = default;
        /** \brief J at \e x (without the cell-to-cell term). */
        virtual double cost(const double *x) = 0;
        /** \brief Draw a new bacterium into \e x (at the start of a run and at dispersal). */
        virtual void randomPosition(double *x) = 0;
        /** \brief Bring a moved bacterium \e x back into the search region. */
        virtual void constrain(double *x) = 0;
        /** \brief True when the search must stop now (tested before every evaluation). */
        virtual bool halt() { return false; }
        /** \brief A uniformly random unit direction \e phi of \e dim coordinates: Delta ~ U(-1, 1)^dim,
            redrawn while |Delta|^2 < 1e-24, then phi = Delta / |Delta| (computed as Delta times 1/|Delta|).
         */
        virtual void randomDirection(double *phi, unsigned int dim, ompl::RNG &rng);
    };

    /** \brief S bacteria in R^dim and Passino's loops (docs/algorithms.md 6.1): for l < Ned, k < Nre,
        j < Nc, every bacterium tumbles (a random unit direction phi, one unconditional move C phi) and
        swims (again C phi) while J improves, at most Ns times; health = sum of J after each chemotactic
        step; after Nc steps the healthier half splits (two copies each, ties by index; for odd S the
        median survives without splitting), the rest dies; after Nre reproductions each bacterium is moved
        to a new random position with probability Ped. ATBFO (6.2): a bacterium counts its improvements
        imp_count, the swim (run) moves that improved J (J < J_last; the tumble move is not counted,
        [BFO] Pseudo code 1), in a chemotactic step, so at most Ns; more than F_improv and it keeps its
        direction for the next step; offspring inherit direction and flag; a dispersed bacterium draws a
        fresh one. With cell-to-cell on, J_cc (Passino) is added to J for the swim decisions and the health.

        A position's J is cached between chemotactic steps; a new bacterium is evaluated when it first
        moves (or by evaluateAll()). step() runs one chemotactic step and resumes at the bacterium it was
        interrupted at. Sized once by start(); a run of the same size allocates nothing. */
    class BacterialColony
    {
      public:
        /** \brief What step() did. */
        enum class Step
        {
            Interrupted, ///< ColonyProblem::halt() stopped it; the next step() resumes there
            StepDone,    ///< one chemotactic step (with reproduction / dispersal when due)
            RunComplete  ///< the last step of the Ned-th elimination-dispersal event
        };

        explicit BacterialColony(const ColonySettings &settings) : settings_(&settings) {}

        /** \brief \e size bacteria in R^\e dim, each drawn by \e problem (not evaluated yet); the loop
            counters restart. */
        void start(unsigned int dim, unsigned int size, ColonyProblem &problem);
        /** \brief Make room for \e size bacteria in R^\e dim, so that start() with them allocates nothing
            (draws nothing). */
        void reserve(unsigned int dim, unsigned int size);
        /** \brief Evaluate every bacterium whose J is not known, in order; false when halted. */
        bool evaluateAll(ColonyProblem &problem);
        /** \brief One chemotactic step of the remaining bacteria, then reproduction / dispersal when due. */
        Step step(ColonyProblem &problem, ompl::RNG &rng);
        /** \brief Forget the colony (the next run calls start()). */
        void reset();

        bool started() const { return started_; }
        unsigned int size() const { return size_; }
        unsigned int dimension() const { return dim_; }
        /** \brief Bacterium \e i's position. */
        const double *position(unsigned int i) const { return row(x_, i); }
        /** \brief ATBFO: bacterium \e i keeps its tumble direction for its next chemotactic step. */
        bool keepsDirection(unsigned int i) const { return keep_[i] != 0; }

      private:
        bool moveBacterium(unsigned int i, ColonyProblem &problem, ompl::RNG &rng);
        void reproduce();
        void disperse(ColonyProblem &problem, ompl::RNG &rng);
        double cellToCell(const double *x, unsigned int self) const;

        double *row(std::vector<double> &v, unsigned int i) { return v.data() + std::size_t(i) * dim_; }
        const double *row(const std::vector<double> &v, unsigned int i) const
        {
            return v.data() + std::size_t(i) * dim_;
        }

        const ColonySettings *settings_;
        unsigned int dim_{0}, size_{0};
        // Positions, cached J (valid when known_), health, ATBFO directions and keep flags, scratch.
        std::vector<double> x_, dir_, trial_, scratchX_, scratchDir_;
        std::vector<double> cost_, health_, scratchCost_;
        std::vector<std::uint8_t> known_, keep_, scratchKnown_, scratchKeep_;
        std::vector<unsigned int> order_;
        unsigned int cursor_{0}, chemo_{0}, repro_{0}, elim_{0};
        bool started_{false};
    };
} // namespace mhplan

#endif

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the parameters of a BFO / ATBFO colony (docs/algorithms.md 6.1, 6.2), declared once for the two
   planners that run one: the online walk (BacterialWalk) and the global waypoint search (BacterialForaging).
 */
#ifndef MHPLAN_COLONY_PARAMETERS_H
#define MHPLAN_COLONY_PARAMETERS_H

#include "ompl_planners/field/BacterialColony.h"

#include <ompl/base/GenericParam.h>

namespace mhplan
{
    /** \brief Passino's loops, ATBFO's adaptive tumble and the cell-to-cell term as OMPL parameters; a
        planner derives from it, calls declareColonyParams() on its ParamSet and hands colonySettings() to
        its BacterialColony. Each setter checks its value against the one range the parameter is declared
        with and throws std::invalid_argument naming the parameter otherwise. */
    class ColonyParameters
    {
      public:
        /** \brief Nc, chemotactic steps per reproduction (1..100000). */
        void setChemotacticSteps(unsigned int n);
        unsigned int getChemotacticSteps() const { return colonySettings_.chemotacticSteps; }
        /** \brief Ns, maximal swim length (0..100000). */
        void setSwimLength(unsigned int n);
        unsigned int getSwimLength() const { return colonySettings_.swimLength; }
        /** \brief Nre, reproduction steps per elimination-dispersal event (1..100000). */
        void setReproductionSteps(unsigned int n);
        unsigned int getReproductionSteps() const { return colonySettings_.reproductionSteps; }
        /** \brief Ned, elimination-dispersal events per run (1..100000). */
        void setEliminationEvents(unsigned int n);
        unsigned int getEliminationEvents() const { return colonySettings_.eliminationEvents; }
        /** \brief Ped, probability of dispersal per bacterium and event (0..1). */
        void setEliminationProbability(double p);
        double getEliminationProbability() const { return colonySettings_.eliminationProbability; }
        /** \brief C, the chemotactic step size (1e-6..1000). */
        void setStepSize(double c);
        double getStepSize() const { return colonySettings_.stepSize; }
        /** \brief ATBFO's adaptive tumble on or off. */
        void setAdaptiveTumble(bool on) { colonySettings_.adaptiveTumble = on; }
        bool getAdaptiveTumble() const { return colonySettings_.adaptiveTumble; }
        /** \brief F_improv: a direction is kept when a step makes more improvements (0..100000). */
        void setImprovementThreshold(unsigned int f);
        unsigned int getImprovementThreshold() const { return colonySettings_.improvementThreshold; }
        /** \brief Passino's cell-to-cell attraction/repulsion term on or off. */
        void setCellToCell(bool on) { colonySettings_.cellToCell = on; }
        bool getCellToCell() const { return colonySettings_.cellToCell; }
        /** \brief d_att (0..1e6). */
        void setAttractDepth(double v);
        double getAttractDepth() const { return colonySettings_.attractDepth; }
        /** \brief w_att (0..1e6). */
        void setAttractWidth(double v);
        double getAttractWidth() const { return colonySettings_.attractWidth; }
        /** \brief h_rep (0..1e6). */
        void setRepelHeight(double v);
        double getRepelHeight() const { return colonySettings_.repelHeight; }
        /** \brief w_rep (0..1e6). */
        void setRepelWidth(double v);
        double getRepelWidth() const { return colonySettings_.repelWidth; }

      protected:
        explicit ColonyParameters(bool adaptiveTumble) { colonySettings_.adaptiveTumble = adaptiveTumble; }
        ~ColonyParameters() = default;
        /** \brief Declare the thirteen colony parameters (names as in docs/algorithms.md 6.1, 6.2). */
        void declareColonyParams(ompl::base::ParamSet &params);

        /** \brief Read live by the owner's colony. */
        ColonySettings colonySettings_;
    };
} // namespace mhplan

#endif

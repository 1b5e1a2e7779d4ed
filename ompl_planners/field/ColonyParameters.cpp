// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/field/ColonyParameters.h"
#include "src/base/Parameters.h"

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kChemotacticSteps{"chemotactic_steps", 1, 1, 100000,
                                               "Nc, chemotactic steps per reproduction"};
        constexpr ParamRange kSwimLength{"swim_length", 0, 1, 100000, "Ns, longest swim"};
        constexpr ParamRange kReproductionSteps{"reproduction_steps", 1, 1, 100000,
                                                "Nre, reproductions per elimination-dispersal event"};
        constexpr ParamRange kEliminationEvents{"elimination_events", 1, 1, 100000,
                                                "Ned, elimination-dispersal events per run"};
        constexpr ParamRange kEliminationProbability{"elimination_probability", 0, 0.01, 1,
                                                     "Ped, dispersal probability per bacterium and event"};
        constexpr ParamRange kStepSize{"step_size", 0.000001, 0.01, 1000, "C, the chemotactic step size"};
        constexpr ParamRange kImprovementThreshold{"improvement_threshold", 0, 1, 100000,
                                                   "F_improv: improvements that keep a direction (ATBFO)"};
        constexpr ParamRange kAttractDepth{"attract_depth", 0, 0.01, 1000000,
                                           "d_att of the cell-to-cell term"};
        constexpr ParamRange kAttractWidth{"attract_width", 0, 0.01, 1000000,
                                           "w_att of the cell-to-cell term"};
        constexpr ParamRange kRepelHeight{"repel_height", 0, 0.01, 1000000, "h_rep of the cell-to-cell term"};
        constexpr ParamRange kRepelWidth{"repel_width", 0, 0.01, 1000000, "w_rep of the cell-to-cell term"};
    } // namespace

    void ColonyParameters::declareColonyParams(ompl::base::ParamSet &params)
    {
        using C = ColonyParameters;
        declareRanged<unsigned int>(params, this, kChemotacticSteps, &C::setChemotacticSteps,
                                    &C::getChemotacticSteps);
        declareRanged<unsigned int>(params, this, kSwimLength, &C::setSwimLength, &C::getSwimLength);
        declareRanged<unsigned int>(params, this, kReproductionSteps, &C::setReproductionSteps,
                                    &C::getReproductionSteps);
        declareRanged<unsigned int>(params, this, kEliminationEvents, &C::setEliminationEvents,
                                    &C::getEliminationEvents);
        declareRanged<double>(params, this, kEliminationProbability, &C::setEliminationProbability,
                              &C::getEliminationProbability);
        declareRanged<double>(params, this, kStepSize, &C::setStepSize, &C::getStepSize);
        declareSwitch(params, this, "adaptive_tumble", &C::setAdaptiveTumble, &C::getAdaptiveTumble,
                      "ATBFO's adaptive tumble");
        declareRanged<unsigned int>(params, this, kImprovementThreshold, &C::setImprovementThreshold,
                                    &C::getImprovementThreshold);
        declareSwitch(params, this, "cell_to_cell", &C::setCellToCell, &C::getCellToCell,
                      "Passino's cell-to-cell attraction and repulsion");
        declareRanged<double>(params, this, kAttractDepth, &C::setAttractDepth, &C::getAttractDepth);
        declareRanged<double>(params, this, kAttractWidth, &C::setAttractWidth, &C::getAttractWidth);
        declareRanged<double>(params, this, kRepelHeight, &C::setRepelHeight, &C::getRepelHeight);
        declareRanged<double>(params, this, kRepelWidth, &C::setRepelWidth, &C::getRepelWidth);
    }

    void ColonyParameters::setChemotacticSteps(unsigned int n)
    {
        storeChecked(kChemotacticSteps, colonySettings_.chemotacticSteps, n);
    }

    void ColonyParameters::setSwimLength(unsigned int n)
    {
        storeChecked(kSwimLength, colonySettings_.swimLength, n);
    }

    void ColonyParameters::setReproductionSteps(unsigned int n)
    {
        storeChecked(kReproductionSteps, colonySettings_.reproductionSteps, n);
    }

    void ColonyParameters::setEliminationEvents(unsigned int n)
    {
        storeChecked(kEliminationEvents, colonySettings_.eliminationEvents, n);
    }

    void ColonyParameters::setEliminationProbability(double p)
    {
        storeChecked(kEliminationProbability, colonySettings_.eliminationProbability, p);
    }

    void ColonyParameters::setStepSize(double c)
    {
        storeChecked(kStepSize, colonySettings_.stepSize, c);
    }

    void ColonyParameters::setImprovementThreshold(unsigned int f)
    {
        storeChecked(kImprovementThreshold, colonySettings_.improvementThreshold, f);
    }

    void ColonyParameters::setAttractDepth(double v)
    {
        storeChecked(kAttractDepth, colonySettings_.attractDepth, v);
    }

    void ColonyParameters::setAttractWidth(double v)
    {
        storeChecked(kAttractWidth, colonySettings_.attractWidth, v);
    }

    void ColonyParameters::setRepelHeight(double v)
    {
        storeChecked(kRepelHeight, colonySettings_.repelHeight, v);
    }

    void ColonyParameters::setRepelWidth(double v)
    {
        storeChecked(kRepelWidth, colonySettings_.repelWidth, v);
    }
} // namespace mhplan

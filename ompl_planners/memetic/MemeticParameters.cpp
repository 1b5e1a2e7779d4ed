// SPDX-License-Identifier: BSD-3-Clause
// MemeticPlanner's parameters: their ranges, declarations and setters (docs/variants.md lists them).
#include "ompl_planners/memetic/MemeticPlanner.h"

#include "src/base/Parameters.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kWalkNoise{"walk_noise", 0, 0.1, 10,
                                        "largest priority noise of the randomised lattice walks"};
        constexpr ParamRange kWalkWeight{"walk_weight", 1, 0.1, 10,
                                         "heuristic weight of the walks after the first"};
        constexpr ParamRange kWalkExpansions{"walk_expansions", 1000, 1000, 100000000,
                                             "node budget of one walk"};
        constexpr ParamRange kLatticeLevels{"lattice_levels", 1, 1, 16,
                                            "number of lattice resolutions of the walks"};
        constexpr ParamRange kCoarseTurn{"coarse_turn", 0.01, 0.01, 3,
                                         "largest turn per waypoint after the coarse local search (rad)"};
        constexpr ParamRange kFineTurn{"fine_turn", 0.001, 0.001, 1,
                                       "largest turn per waypoint of the polished best path (rad)"};
        constexpr ParamRange kPolishPasses{"polish_passes", 1, 1, 100000,
                                           "local-search passes of the elite polish per generation"};
        constexpr ParamRange kEliteRewalks{"elite_rewalks", 0, 1, 1000,
                                           "re-walk trials on the best individual per generation"};
        constexpr ParamRange kTubeReroutes{
            "tube_reroutes", 0, 1, 1000,
            "tube reroutes of the best individual per generation (in the plane): "
            "the shortest route of a roadmap drawn near its path"};
        constexpr ParamRange kStagnation{
            "stagnation", 0, 1, 1000000,
            "generations without improvement before a restart (the elite kept); 0 = auto: 3 planar, 40 "
            "other spaces"};
        constexpr ParamRange kBisections{"bisections", 4, 1, 40, "bisection steps of each pull move"};
        constexpr ParamRange kValidatorMargin{"validator_margin", 0, 0.05, 4,
                                              "with OMPL's DiscreteMotionValidator: distance at which "
                                              "obstacles beside a segment are looked for, "
                                              "in its sample spacings (0 = no margin)"};
        constexpr ParamRange kValidatorClearance{"validator_clearance", 0, 0.005, 0.5,
                                                 "clearance kept from the obstacles the margin finds, in "
                                                 "sample spacings (0 = refuse the segment)"};
        constexpr ParamRange kValidatorMinClearance{
            "validator_min_clearance", 0, 0.0005, 0.5,
            "smallest clearance the margin keeps in a passage with obstacles on both sides, in sample "
            "spacings (validator_clearance halved down to it; 0 = never halved)"};
        constexpr ParamRange kValidatorFineStep{
            "validator_fine_step", 0, 0.01, 1,
            "step of the validity checker along every segment of a path before it is reported, in sample "
            "spacings (0 = no fine check)"};
        constexpr ParamRange kValidatorStateStep{
            "validator_state_step", 0, 0.001, 0.5,
            "off the plane: step of the validity checker along every motion of a path before it is "
            "reported, in sample spacings of the space's metric (0 = no fine check)"};
    } // namespace

    MemeticPlanner::MemeticPlanner(const ob::SpaceInformationPtr &si, const std::string &name,
                                   unsigned int populationSize)
        : PlannerBase(si, name, true)
    {
        specs_.approximateSolutions = true;
        specs_.optimizingPaths = true;
        specs_.canReportIntermediateSolutions = true;
        specs_.multithreaded = false;
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;
        stop_ = [this] { return stopRequested(); };

        declarePopulationSize(populationSize, "N, paths in the population");
        declareMaxIterations("generations per solve() call; 0 = until the time limit");
        declareRanged<double>(params(), this, kWalkNoise, &MemeticPlanner::setWalkNoise,
                              &MemeticPlanner::getWalkNoise);
        declareRanged<double>(params(), this, kWalkWeight, &MemeticPlanner::setWalkWeight,
                              &MemeticPlanner::getWalkWeight);
        declareRanged<unsigned int>(params(), this, kWalkExpansions, &MemeticPlanner::setWalkExpansions,
                                    &MemeticPlanner::getWalkExpansions);
        declareRanged<unsigned int>(params(), this, kLatticeLevels, &MemeticPlanner::setLatticeLevels,
                                    &MemeticPlanner::getLatticeLevels);
        declareRanged<double>(params(), this, kCoarseTurn, &MemeticPlanner::setCoarseTurn,
                              &MemeticPlanner::getCoarseTurn);
        declareRanged<double>(params(), this, kFineTurn, &MemeticPlanner::setFineTurn,
                              &MemeticPlanner::getFineTurn);
        declareRanged<unsigned int>(params(), this, kPolishPasses, &MemeticPlanner::setPolishPasses,
                                    &MemeticPlanner::getPolishPasses);
        declareRanged<unsigned int>(params(), this, kEliteRewalks, &MemeticPlanner::setEliteRewalks,
                                    &MemeticPlanner::getEliteRewalks);
        declareRanged<unsigned int>(params(), this, kTubeReroutes, &MemeticPlanner::setTubeReroutes,
                                    &MemeticPlanner::getTubeReroutes);
        declareRanged<unsigned int>(params(), this, kStagnation, &MemeticPlanner::setStagnation,
                                    &MemeticPlanner::getStagnation);
        declareRanged<unsigned int>(params(), this, kBisections, &MemeticPlanner::setBisections,
                                    &MemeticPlanner::getBisections);
        declareRanged<double>(params(), this, kValidatorMargin, &MemeticPlanner::setValidatorMargin,
                              &MemeticPlanner::getValidatorMargin);
        declareRanged<double>(params(), this, kValidatorClearance, &MemeticPlanner::setValidatorClearance,
                              &MemeticPlanner::getValidatorClearance);
        declareRanged<double>(params(), this, kValidatorMinClearance,
                              &MemeticPlanner::setValidatorMinClearance,
                              &MemeticPlanner::getValidatorMinClearance);
        declareRanged<double>(params(), this, kValidatorFineStep, &MemeticPlanner::setValidatorFineStep,
                              &MemeticPlanner::getValidatorFineStep);
        declareRanged<double>(params(), this, kValidatorStateStep, &MemeticPlanner::setValidatorStateStep,
                              &MemeticPlanner::getValidatorStateStep);

        declareProgress(true);
        addPlannerProgressProperty("motion checks INTEGER",
                                   [this] { return std::to_string(motionCheckCount()); });
        addPlannerProgressProperty("state checks INTEGER",
                                   [this] { return std::to_string(stateCheckCount()); });
        addPlannerProgressProperty("cached motion checks INTEGER",
                                   [this] { return std::to_string(cacheHitCount()); });
        addPlannerProgressProperty("improvements INTEGER",
                                   [this] { return std::to_string(improvementCount()); });
    }

    MemeticPlanner::~MemeticPlanner() = default;

    void MemeticPlanner::setSeed(unsigned long seed)
    {
        PlannerBase::setSeed(seed); // checks the range
        if (problemReady_)
            clear();
    }

    void MemeticPlanner::setWalkNoise(double noise)
    {
        storeChecked(kWalkNoise, walkNoise_, noise);
    }

    void MemeticPlanner::setWalkWeight(double w)
    {
        storeChecked(kWalkWeight, walkWeight_, w);
    }

    void MemeticPlanner::setWalkExpansions(unsigned int n)
    {
        storeChecked(kWalkExpansions, walkExpansions_, n);
    }

    void MemeticPlanner::setLatticeLevels(unsigned int n)
    {
        storeChecked(kLatticeLevels, latticeLevels_, n);
    }

    void MemeticPlanner::setCoarseTurn(double x)
    {
        storeChecked(kCoarseTurn, coarseTurn_, x);
    }

    void MemeticPlanner::setFineTurn(double x)
    {
        storeChecked(kFineTurn, fineTurn_, x);
    }

    void MemeticPlanner::setPolishPasses(unsigned int n)
    {
        storeChecked(kPolishPasses, polishPasses_, n);
    }

    void MemeticPlanner::setEliteRewalks(unsigned int n)
    {
        storeChecked(kEliteRewalks, eliteRewalks_, n);
    }

    void MemeticPlanner::setTubeReroutes(unsigned int n)
    {
        storeChecked(kTubeReroutes, tubeReroutes_, n);
    }

    void MemeticPlanner::setStagnation(unsigned int n)
    {
        storeChecked(kStagnation, stagnation_, n);
    }

    void MemeticPlanner::setBisections(unsigned int n)
    {
        storeChecked(kBisections, bisections_, n);
    }

    void MemeticPlanner::setValidatorMargin(double m)
    {
        storeChecked(kValidatorMargin, validatorMargin_, m);
    }

    void MemeticPlanner::setValidatorClearance(double c)
    {
        storeChecked(kValidatorClearance, validatorClearance_, c);
    }

    void MemeticPlanner::setValidatorMinClearance(double c)
    {
        checkParameter(kValidatorMinClearance, c);
        validatorMinClearance_ = c;
    }

    void MemeticPlanner::setValidatorFineStep(double f)
    {
        storeChecked(kValidatorFineStep, validatorFineStep_, f);
    }

    void MemeticPlanner::setValidatorStateStep(double f)
    {
        storeChecked(kValidatorStateStep, validatorStateStep_, f);
    }

    double MemeticPlanner::marginDistance() const
    {
        // Only OMPL's sampling validator leaves gaps between its samples; mhplan's exact and certified
        // validators decide every point of a motion (docs/variants.md).
        if (dynamic_cast<const ob::DiscreteMotionValidator *>(si_->getMotionValidator().get()) == nullptr)
            return 0.0;
        return validatorMargin_ * si_->getStateValidityCheckingResolution() * si_->getMaximumExtent();
    }
} // namespace mhplan

// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/PlannerBase.h"

#include "ompl_planners/common/PlannerSupport.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <limits>

namespace ob = ompl::base;

namespace mhplan
{
    const ParamRange SharedParameterRanges::seed{
        "seed", 0, 1, 4294967295, "seed of this planner's RNG; 0 = drawn from OMPL's global seed"};
    const ParamRange SharedParameterRanges::maxIterations{"max_iterations", 0, 1, 1000000000, ""};
    const ParamRange SharedParameterRanges::populationSize{"population_size", 2, 1, 10000, ""};

    PlannerBase::PlannerBase(const ob::SpaceInformationPtr &si, const std::string &name, bool seeded)
        : ob::Planner(si, name)
          // ompl::RNG() draws its seed from OMPL's global generator; a planner without randomness must not
          // consume one (the seeds of the planners constructed after it would change).
          ,
          rng_(seeded ? ompl::RNG() : ompl::RNG(1u)), bestCostValue_(std::numeric_limits<double>::infinity())
    {
        if (seeded)
            declareSeed();
    }

    PlannerBase::~PlannerBase()
    {
        for (ob::State *&s : scratch_)
            if (s != nullptr)
                si_->freeState(s);
        freeStates(*si_, plannerDataStates_);
    }

    void PlannerBase::clear()
    {
        ob::Planner::clear();
        freeStates(*si_, plannerDataStates_);
        bestCostValue_ = std::numeric_limits<double>::infinity();
        iterationCount_ = 0;
        evaluationCount_ = 0;
    }

    void PlannerBase::setSeed(unsigned long seed)
    {
        storeChecked(SharedParameterRanges::seed, seed_, seed);
    }

    void PlannerBase::setMaxIterations(unsigned int n)
    {
        storeChecked(SharedParameterRanges::maxIterations, maxIterations_, n);
    }

    void PlannerBase::setPopulationSize(unsigned int n)
    {
        storeChecked(SharedParameterRanges::populationSize, populationSize_, n);
    }

    void PlannerBase::declareSeed()
    {
        declareRanged<unsigned long>(params(), this, SharedParameterRanges::seed, &PlannerBase::setSeed,
                                     &PlannerBase::getSeed);
    }

    void PlannerBase::declareMaxIterations(const char *description)
    {
        ParamRange range = SharedParameterRanges::maxIterations;
        range.description = description;
        declareRanged<unsigned int>(params(), this, range, &PlannerBase::setMaxIterations,
                                    &PlannerBase::getMaxIterations);
    }

    void PlannerBase::declarePopulationSize(unsigned int n, const char *description)
    {
        populationSize_ = n;
        ParamRange range = SharedParameterRanges::populationSize;
        range.description = description;
        declareRanged<unsigned int>(params(), this, range, &PlannerBase::setPopulationSize,
                                    &PlannerBase::getPopulationSize);
    }

    void PlannerBase::declareProgress(bool evaluations)
    {
        // The names are read by the database and the report (benchmarks/README.md): keep them.
        addPlannerProgressProperty("best cost REAL", [this] { return formatCost(bestCost()); });
        addPlannerProgressProperty("iterations INTEGER", [this] { return std::to_string(iterationCount()); });
        if (evaluations)
            addPlannerProgressProperty("fitness evaluations INTEGER",
                                       [this] { return std::to_string(evaluationCount()); });
    }

    void PlannerBase::seedRng()
    {
        if (seed_ != 0)
            rng_.setLocalSeed(static_cast<std::uint_fast32_t>(seed_));
    }

    void PlannerBase::refuseSetup(const std::string &message)
    {
        setup_ = false;
        const std::string text = getName() + ": " + message;
        OMPL_ERROR("%s", text.c_str());
        throw ompl::Exception(text);
    }

    bool PlannerBase::startAndGoal(const ob::State *&start, const ob::State *&goal)
    {
        start = pis_.nextStart();
        if (start == nullptr)
        {
            OMPL_ERROR("%s: no valid start state", getName().c_str());
            inputFailure_ = ob::PlannerStatus::INVALID_START;
            return false;
        }
        goal = pis_.nextGoal();
        if (goal == nullptr)
        {
            OMPL_ERROR("%s: no goal state could be sampled", getName().c_str());
            inputFailure_ = ob::PlannerStatus::INVALID_GOAL;
            return false;
        }
        return true;
    }

    void PlannerBase::reportImprovementOf(std::size_t count, const PathFill &fill, const ob::Cost &cost)
    {
        reportImprovement(this, pdef_, *si_, count, fill, cost);
    }

    void PlannerBase::addSolutionPath(std::size_t count, const PathFill &fill, bool exact,
                                      const ob::Cost &cost, double approximateDistance)
    {
        addSolution(*this, pdef_, si_, count, fill, exact, cost, approximateDistance);
    }

    void PlannerBase::pathToPlannerData(ob::PlannerData &data, std::size_t count, const PathFill &fill,
                                        bool lastIsGoal) const
    {
        ob::Planner::getPlannerData(data);
        addPathToPlannerData(*si_, count, fill, lastIsGoal, data, plannerDataStates_);
    }

    ob::State *PlannerBase::scratchState(unsigned int i)
    {
        if (scratch_[i] == nullptr)
            scratch_[i] = si_->allocState();
        return scratch_[i];
    }
} // namespace mhplan

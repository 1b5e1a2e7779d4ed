// SPDX-License-Identifier: BSD-3-Clause
/* mhplan_space_table: every population planner that runs on any state space, and RRT*, on one problem per
   space: R^2 (bfo_case2), R^4 (a hypersphere in [0,1]^4, as tests/test_nd.cpp), SE(2)
   (se2_narrow_passage), Dubins (dubins_circles) and Reeds-Shepp (reeds_shepp_parking), with a fixed time
   budget and fixed seeds; prints a Markdown table of the success rate (exact paths that pass the independent
   check) and the median cost (the problem's objective) per planner and space (docs/spaces.md).

   mhplan_space_table [--time S] [--seeds N] [--environments DIR] */
#include "mhplan/collision/Metrics.h"
#include "mhplan/collision/Problem.h"
#include "mhplan/collision/RigidValidity.h"
#include "mhplan/io/WorldIO.h"
#include "mhplan/registry/Registry.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace mhplan;

namespace
{
    constexpr unsigned int kDimension = 4;
    constexpr double kSphereRadius = 0.25;

    double sphereClearance(const double *v)
    {
        double s = 0.0;
        for (unsigned int j = 0; j < kDimension; ++j)
            s += (v[j] - 0.5) * (v[j] - 0.5);
        return std::sqrt(s) - kSphereRadius;
    }

    class SphereChecker : public ob::StateValidityChecker
    {
      public:
        explicit SphereChecker(const ob::SpaceInformationPtr &si) : ob::StateValidityChecker(si)
        {
            specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;
        }
        bool isValid(const ob::State *s) const override { return clearance(s) >= 0.0; }
        double clearance(const ob::State *s) const override
        {
            return sphereClearance(s->as<ob::RealVectorStateSpace::StateType>()->values);
        }
    };

    og::SimpleSetupPtr sphereProblem()
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(kDimension);
        space->setBounds(0.0, 1.0);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker(std::make_shared<SphereChecker>(si));
        si->setMotionValidator(std::make_shared<ob::DiscreteMotionValidator>(si));
        si->setStateValidityCheckingResolution(0.0005);
        si->setup();
        auto ss = std::make_shared<og::SimpleSetup>(si);
        ob::ScopedState<> start(space), goal(space);
        for (unsigned int j = 0; j < kDimension; ++j)
        {
            start[j] = 0.05;
            goal[j] = 0.95;
        }
        ss->setStartAndGoalStates(start, goal, 1e-9);
        ss->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
        return ss;
    }

    /** Independent check of an R^4 path: inside [0,1]^4 and outside the sphere at 1e-4 spacing. */
    bool sphereFree(const og::PathGeometric &path)
    {
        std::vector<double> q(kDimension);
        for (std::size_t i = 1; i < path.getStateCount(); ++i)
        {
            const double *a = path.getState(i - 1)->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *b = path.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
            double len = 0.0;
            for (unsigned int j = 0; j < kDimension; ++j)
                len += (b[j] - a[j]) * (b[j] - a[j]);
            const auto steps =
                std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(std::sqrt(len) / 1e-4)));
            for (std::size_t s = 0; s <= steps; ++s)
            {
                for (unsigned int j = 0; j < kDimension; ++j)
                {
                    q[j] = a[j] + (b[j] - a[j]) * (double(s) / steps);
                    if (q[j] < 0.0 || q[j] > 1.0)
                        return false;
                }
                if (sphereClearance(q.data()) < 0.0)
                    return false;
            }
        }
        return true;
    }

    struct Problem
    {
        std::string label;
        std::function<og::SimpleSetupPtr()> make;
        std::function<bool(const og::SimpleSetup &)> independentlyFree;
    };

    Problem worldProblem(const std::string &label, const std::string &file)
    {
        auto world = std::make_shared<World>(loadWorld(file));
        Problem p;
        p.label = label;
        p.make = [world]()
        { return makeSimpleSetup(*world, world->queries.at(0), makeCollisionModel(*world)); };
        p.independentlyFree = [world](const og::SimpleSetup &ss)
        {
            const og::PathGeometric &path = ss.getSolutionPath();
            if (world->isRigid())
                return rigidPathMetrics(*world, *ss.getSpaceInformation(), path, RigidBodyModel(*world),
                                        defaultMetricStep(*world))
                    .collisionFree;
            return denseCollisionFree(pathPoints(path), *makeCollisionModel(*world),
                                      defaultMetricStep(*world));
        };
        return p;
    }

    std::string cell(std::size_t success, std::size_t runs, std::vector<double> costs,
                     const std::string &note)
    {
        if (!note.empty())
            return note;
        std::ostringstream out;
        out << std::fixed << std::setprecision(0) << 100.0 * success / std::max<std::size_t>(runs, 1) << " %";
        if (!costs.empty())
        {
            std::sort(costs.begin(), costs.end());
            const std::size_t n = costs.size();
            const double median = n % 2 ? costs[n / 2] : 0.5 * (costs[n / 2 - 1] + costs[n / 2]);
            out << " / " << std::setprecision(3) << median;
        }
        else
            out << " / -";
        return out.str();
    }
} // namespace

int main(int argc, char **argv)
{
    double timeLimit = 1.0;
    unsigned int seeds = 3;
    std::string environments = MHPLAN_ENVIRONMENTS_DIR;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string key = argv[i];
        if (key == "--time")
            timeLimit = std::atof(argv[i + 1]);
        else if (key == "--seeds")
            seeds = static_cast<unsigned int>(std::atoi(argv[i + 1]));
        else if (key == "--environments")
            environments = argv[i + 1];
        else
        {
            std::cerr << "mhplan_space_table: unknown option '" << key
                      << "'; accepted: --time S, --seeds N, --environments DIR\n";
            return 1;
        }
    }
    if (!(timeLimit > 0.0) || seeds == 0 || seeds > 1000)
    {
        std::cerr << "mhplan_space_table: --time must be > 0 and --seeds in [1, 1000]\n";
        return 1;
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(1);

    const std::vector<Problem> problems = {
        worldProblem("R^2 (bfo_case2)", environments + "/bfo_case2.yaml"),
        {"R^4 (hypersphere)", sphereProblem,
         [](const og::SimpleSetup &ss) { return sphereFree(ss.getSolutionPath()); }},
        worldProblem("SE(2) (se2_narrow_passage)", environments + "/se2_narrow_passage.yaml"),
        worldProblem("Dubins (dubins_circles)", environments + "/dubins_circles.yaml"),
        worldProblem("Reeds-Shepp (reeds_shepp_parking)", environments + "/reeds_shepp_parking.yaml"),
    };
    const PlannerRegistry &registry = builtinPlanners();
    std::vector<std::string> planners;
    for (const std::string &name : registry.names())
    {
        const PlannerEntry &e = registry.get(name);
        if (e.origin == "mhplan" && e.runsOn(cap::SE2)) // the population planners that run off the plane
            planners.push_back(name);
    }
    planners.push_back("RRTstar");

    std::cout << "| planner | ";
    for (const Problem &p : problems)
        std::cout << p.label << " | ";
    std::cout << "\n|---|";
    for (std::size_t i = 0; i < problems.size(); ++i)
        std::cout << "---|";
    std::cout << "\n";
    for (const std::string &name : planners)
    {
        std::cout << "| " << name << " | ";
        for (const Problem &problem : problems)
        {
            std::size_t success = 0;
            std::vector<double> costs;
            std::string note;
            for (unsigned int seed = 1; seed <= seeds && note.empty(); ++seed)
            {
                const og::SimpleSetupPtr ss = problem.make();
                std::map<std::string, std::string> params;
                if (name != "RRTstar")
                    params = {{"seed", std::to_string(seed)}, {"decoding", "polyline"}};
                try
                {
                    ss->setPlanner(registry.create(name, ss->getSpaceInformation(), params));
                    ss->setup();
                    const ob::PlannerStatus status = ss->solve(timeLimit);
                    if (status == ob::PlannerStatus::EXACT_SOLUTION && ss->haveExactSolutionPath() &&
                        problem.independentlyFree(*ss))
                    {
                        ++success;
                        costs.push_back(ss->getSolutionPath().cost(ss->getOptimizationObjective()).value());
                    }
                }
                catch (const std::exception &)
                {
                    note = "refused";
                }
            }
            std::cout << cell(success, seeds, costs, note) << " | " << std::flush;
        }
        std::cout << "\n";
    }
    std::cout
        << "\nCells: success rate (exact paths that pass the independent check) / median cost in the space's "
           "metric over the successful runs; "
        << seeds << " seeds, " << timeLimit << " s per run.\n";
    return 0;
}

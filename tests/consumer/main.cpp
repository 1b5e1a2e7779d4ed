// SPDX-License-Identifier: BSD-3-Clause
// Your own OMPL program, with mhplan's Slime Mould planner added in a few lines.
#include <src/registry/Registry.h>
#include <ompl_planners/population/SlimeMould.h>

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <cmath>
#include <iostream>

namespace ob = ompl::base;
namespace og = ompl::geometric;

int main()
{
    // A 10 m square with a disc of radius 2 in the middle: your space, your validity checker.
    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    space->setBounds(0.0, 10.0);
    og::SimpleSetup ss(space);
    ss.setStateValidityChecker(
        [](const ob::State *s)
        {
            const auto *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
            return std::hypot(v[0] - 5.0, v[1] - 5.0) > 2.0;
        });
    ss.getSpaceInformation()->setStateValidityCheckingResolution(0.001);
    ob::ScopedState<> start(space), goal(space);
    start[0] = 1.0;
    start[1] = 1.0;
    goal[0] = 9.0;
    goal[1] = 9.0;
    ss.setStartAndGoalStates(start, goal);
    ss.setOptimizationObjective(
        std::make_shared<ob::PathLengthOptimizationObjective>(ss.getSpaceInformation()));

    // mhplan: construct the planner directly and set its parameters by name.
    auto planner = std::make_shared<mhplan::SlimeMould>(ss.getSpaceInformation());
    planner->params().setParam("max_iterations", "100");
    planner->params().setParam("seed", "42");
    ss.setPlanner(planner);
    const ob::PlannerStatus status = ss.solve(10.0);
    if (status != ob::PlannerStatus::EXACT_SOLUTION)
    {
        std::cerr << "no exact solution: " << status.asString() << "\n";
        return 1;
    }
    std::cout << "SMA path length " << ss.getSolutionPath().length() << "\n";

    // Or add every mhplan planner to an existing OMPL benchmark in one line.
    ompl::tools::Benchmark benchmark(ss, "consumer");
    mhplan::addPlannersToBenchmark(benchmark);
    std::cout << "benchmark planners added\n";
    return 0;
}

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan_space_table: every population planner that runs on any state space, and RRT*, on one problem per
   space: R^2 (bfo_case2), R^4 and R^6 (a hypersphere in [0,1]^k, as tests/test_nd.cpp), SE(2)
   (se2_narrow_passage), Dubins (dubins_circles), Reeds-Shepp (reeds_shepp_parking) and SE(3) (a stick among
   balls, below; se3w: the rod through the hole of environments/3d/narrow_passage_se3.yaml, docs/worlds3d.md,
   with its certified validator and the independent dense mesh check), with a fixed time budget and fixed
   seeds; prints a Markdown table of the success rate (exact paths that pass the independent check) and the
   median cost (the problem's objective) per planner and space (docs/spaces.md).

   mhplan_space_table [--time S] [--seeds N] [--environments DIR] [--planners A,B,...]
                      [--problems r2,r4,r6,se2,dubins,reeds_shepp,se3,se3w] */
#include "src/metrics/Metrics.h"
#include "src/base/Parameters.h"
#include "src/collision/Problem.h"
#include "src/collision/RigidValidity.h"
#include "src/collision/MeshRigidBody.h"
#include "src/io/CfgIO.h"
#include "src/io/InputFile.h"
#include "src/io/World3dIO.h"
#include "src/io/YamlReader.h"
#include "src/io/WorldIO.h"
#include "src/registry/Registry.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
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
#include <stdexcept>
#include <string>
#include <vector>

namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace mhplan;

namespace
{
    constexpr double kSphereRadius = 0.25;

    double sphereClearance(const double *v, unsigned int k)
    {
        double s = 0.0;
        for (unsigned int j = 0; j < k; ++j)
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
            return sphereClearance(s->as<ob::RealVectorStateSpace::StateType>()->values,
                                   si_->getStateDimension());
        }
    };

    og::SimpleSetupPtr sphereProblem(unsigned int kDimension)
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

    /** Independent check of an R^k path: inside [0,1]^k and outside the sphere at 1e-4 spacing. */
    bool sphereFree(const og::PathGeometric &path, unsigned int kDimension)
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
                if (sphereClearance(q.data(), kDimension) < 0.0)
                    return false;
            }
        }
        return true;
    }

    /** The SE(3) problem: a stick (half length 0.8 along the body's x axis) in [0, 10]^3 among four balls;
        valid when the stick's segment keeps out of every ball and inside the box (exact segment-ball
        distance). Start (1, 1, 1) identity, goal (9, 9, 9) turned a half turn about z; OMPL's
        DiscreteMotionValidator at 0.002 of the extent. */
    constexpr double kStickHalf = 0.8;
    const double kBalls[4][4] = {{5, 5, 5, 2.2}, {3, 6.5, 3, 1.5}, {7, 3.5, 7, 1.5}, {6.5, 6.5, 2.5, 1.2}};

    bool stickValid(const ob::State *state)
    {
        const auto *s = state->as<ob::SE3StateSpace::StateType>();
        const ob::SO3StateSpace::StateType &q = s->rotation();
        // The body's x axis rotated by q.
        const double ax = 1 - 2 * (q.y * q.y + q.z * q.z), ay = 2 * (q.x * q.y + q.w * q.z),
                     az = 2 * (q.x * q.z - q.w * q.y);
        const double p[3] = {s->getX(), s->getY(), s->getZ()}, d[3] = {ax, ay, az};
        for (int e = -1; e <= 1; e += 2)
            for (int j = 0; j < 3; ++j)
            {
                const double v = p[j] + e * kStickHalf * d[j];
                if (v < 0.0 || v > 10.0)
                    return false;
            }
        for (const auto &b : kBalls)
        {
            double t = 0.0;
            for (int j = 0; j < 3; ++j)
                t += (b[j] - p[j]) * d[j];
            t = std::max(-kStickHalf, std::min(kStickHalf, t));
            double r2 = 0.0;
            for (int j = 0; j < 3; ++j)
                r2 += (p[j] + t * d[j] - b[j]) * (p[j] + t * d[j] - b[j]);
            if (r2 < b[3] * b[3])
                return false;
        }
        return true;
    }

    og::SimpleSetupPtr se3Problem()
    {
        auto space = std::make_shared<ob::SE3StateSpace>();
        ob::RealVectorBounds b(3);
        b.setLow(0.0);
        b.setHigh(10.0);
        space->setBounds(b);
        auto ss = std::make_shared<og::SimpleSetup>(space);
        ss->setStateValidityChecker(stickValid);
        ss->getSpaceInformation()->setStateValidityCheckingResolution(0.002);
        ob::ScopedState<ob::SE3StateSpace> start(space), goal(space);
        start->setXYZ(1, 1, 1);
        start->rotation().setIdentity();
        goal->setXYZ(9, 9, 9);
        goal->rotation().setAxisAngle(0, 0, 1, M_PI);
        ss->setStartAndGoalStates(start, goal, 1e-9);
        ss->setOptimizationObjective(
            std::make_shared<ob::PathLengthOptimizationObjective>(ss->getSpaceInformation()));
        return ss;
    }

    /** Independent check of an SE(3) path: the space's interpolation at 1e-4 of the extent per state. */
    bool se3Free(const og::SimpleSetup &ss)
    {
        const og::PathGeometric &path = ss.getSolutionPath();
        const ob::SpaceInformationPtr &si = ss.getSpaceInformation();
        ob::State *q = si->allocState();
        bool ok = true;
        for (std::size_t i = 1; i < path.getStateCount() && ok; ++i)
        {
            const double len = si->distance(path.getState(i - 1), path.getState(i));
            const auto steps = std::max<std::size_t>(
                1, static_cast<std::size_t>(std::ceil(len / (1e-4 * si->getMaximumExtent()))));
            for (std::size_t s = 0; s <= steps && ok; ++s)
            {
                si->getStateSpace()->interpolate(path.getState(i - 1), path.getState(i), double(s) / steps,
                                                 q);
                ok = stickValid(q);
            }
        }
        si->freeState(q);
        return ok;
    }

    std::vector<std::string> splitList(const std::string &s)
    {
        std::vector<std::string> out;
        std::stringstream in(s);
        std::string item;
        while (std::getline(in, item, ','))
            if (!item.empty())
                out.push_back(item);
        return out;
    }

    struct Problem
    {
        std::string key;
        std::string label;
        std::function<og::SimpleSetupPtr()> make;
        std::function<bool(const og::SimpleSetup &)> independentlyFree;
    };

    Problem worldProblem(const std::string &key, const std::string &label, const std::string &file)
    {
        auto world = std::make_shared<World>(loadWorld(file));
        Problem p;
        p.key = key;
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

    /** A 3D YAML world's first query (docs/worlds3d.md), checked by the dense mesh check at 1e-3 of the
        volume's diagonal (as `mhplan plan`). */
    Problem world3dProblemOf(const std::string &key, const std::string &label, const std::string &file)
    {
        const auto world = std::make_shared<const World3d>(
            parseWorld3d(readInputFile(file, kMaxYamlBytes, "world file"), file));
        auto loaded = std::make_shared<LoadedCfgProblem>(loadCfgProblem(world3dProblem(world, "")));
        Problem p;
        p.key = key;
        p.label = label;
        p.make = [loaded]() { return makeMeshSetup(loaded->spec); };
        p.independentlyFree = [loaded](const og::SimpleSetup &ss)
        {
            const double step = 1e-3 * loaded->spec.volume.diagonal().norm();
            long contact = -1;
            denseMeshPathCheck(*loaded->spec.model, *ss.getSpaceInformation(), ss.getSolutionPath(), step,
                               contact);
            return contact < 0;
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
    std::vector<std::string> plannerList, problemList;
    const char *usage =
        "usage: mhplan_space_table [--time S] [--seeds N] [--environments DIR] [--planners A,B,...] "
        "[--problems r2,r4,r6,se2,dubins,reeds_shepp,se3,se3w]\n";
    for (int i = 1; i < argc; i += 2)
    {
        const std::string key = argv[i];
        if (key == "--help" || key == "-h")
        {
            std::cout << usage;
            return 0;
        }
        if (i + 1 >= argc)
        {
            std::cerr << "mhplan_space_table: option '" << key << "' needs a value\n" << usage;
            return 1;
        }
        if (key == "--time" || key == "--seeds")
        {
            // The whole value is the number, within its range ("1s" or "2.5" seeds are refused, not read as 1
            // and 2; src/base/Parameters.h).
            const ParamRange range = key == "--time" ? ParamRange{"--time", 1e-3, 0.0, 1e6}
                                                     : ParamRange{"--seeds", 1.0, 1.0, 1000.0};
            try
            {
                const double v = parseParameter(range, argv[i + 1]);
                checkParameterRange(range.name, v, range.lo, range.hi);
                if (key == "--seeds" && v != std::floor(v))
                    throw std::invalid_argument("parameter '--seeds' must be a whole number; got '" +
                                                std::string(argv[i + 1]) + "'");
                if (key == "--time")
                    timeLimit = v;
                else
                    seeds = static_cast<unsigned int>(v);
            }
            catch (const std::invalid_argument &e)
            {
                std::cerr << "mhplan_space_table: " << e.what() << "\n" << usage;
                return 1;
            }
        }
        else if (key == "--environments")
            environments = argv[i + 1];
        else if (key == "--planners")
            plannerList = splitList(argv[i + 1]);
        else if (key == "--problems")
            problemList = splitList(argv[i + 1]);
        else
        {
            std::cerr << "mhplan_space_table: unknown option '" << key
                      << "'; accepted: --time S, --seeds N, --environments DIR, --planners A,B,..., "
                         "--problems r2,r4,r6,se2,dubins,reeds_shepp,se3,se3w\n";
            return 1;
        }
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(1);

    const std::vector<Problem> all = {
        worldProblem("r2", "R^2 (bfo_case2)", environments + "/bfo_case2.yaml"),
        {"r4", "R^4 (hypersphere)", [] { return sphereProblem(4); },
         [](const og::SimpleSetup &ss) { return sphereFree(ss.getSolutionPath(), 4); }},
        {"r6", "R^6 (hypersphere)", [] { return sphereProblem(6); },
         [](const og::SimpleSetup &ss) { return sphereFree(ss.getSolutionPath(), 6); }},
        worldProblem("se2", "SE(2) (se2_narrow_passage)", environments + "/se2_narrow_passage.yaml"),
        worldProblem("dubins", "Dubins (dubins_circles)", environments + "/dubins_circles.yaml"),
        worldProblem("reeds_shepp", "Reeds-Shepp (reeds_shepp_parking)",
                     environments + "/reeds_shepp_parking.yaml"),
        {"se3", "SE(3) (stick among balls)", se3Problem, se3Free},
        world3dProblemOf("se3w", "SE(3) (narrow_passage_se3)", environments + "/3d/narrow_passage_se3.yaml"),
    };
    std::vector<Problem> problems;
    for (const Problem &p : all)
        if (problemList.empty() ||
            std::find(problemList.begin(), problemList.end(), p.key) != problemList.end())
            problems.push_back(p);
    if (problems.empty())
    {
        std::cerr
            << "mhplan_space_table: --problems names none of r2,r4,r6,se2,dubins,reeds_shepp,se3,se3w\n";
        return 1;
    }
    const PlannerRegistry &registry = builtinPlanners();
    std::vector<std::string> planners = plannerList;
    if (planners.empty())
    {
        for (const std::string &name : registry.names())
        {
            const PlannerEntry &e = registry.get(name);
            if (e.origin == "mhplan" && e.runsOn(cap::SE2)) // mhplan's planners that run off the plane
                planners.push_back(name);
        }
        planners.push_back("RRTstar");
        planners.push_back("InformedRRTstar");
    }
    for (const std::string &name : planners)
        if (!registry.has(name))
        {
            std::cerr << "mhplan_space_table: --planners: unknown planner '" << name << "'\n";
            return 1;
        }

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
                // mhplan's planners take the seed (their default decoding, auto, fits every space).
                if (registry.get(name).origin != "ompl")
                    params = {{"seed", std::to_string(seed)}};
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

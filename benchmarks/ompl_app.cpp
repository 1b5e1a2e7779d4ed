// SPDX-License-Identifier: BSD-3-Clause
/* mhplan_ompl_app: planners as an OMPL user's program runs them (docs/variants.md, "In an OMPL program"):
   a world of disjoint circles (the scaling suite's circle family), the user's own point checker (a loop over
   the circles, no mhplan collision model), OMPL's DiscreteMotionValidator at a stated resolution, the path
   length objective, one run of each planner per random query. Per planner it prints: exact runs; returned
   paths that fail an independent dense check (the circles, every 1 cm along the path) and the deepest cut;
   the gap to the exact optimum (median, 75th, 90th percentile); the first-solution time and the time to
   within 1 % of the optimum (medians over the runs that got there); the validity-checker and
   motion-validator calls per run (counted in the checker and the validator, for every planner alike) and,
   for the memetic planners, per improvement of the best cost.

   mhplan_ompl_app [--time S] [--queries N] [--count C] [--resolution R] [--planners A,B,...]
                   [--params KEY=VALUE,...] [--seed N] [--verbose 1]
   --verbose 1 also prints one line per run (query, planner, gap, first-solution time, time to 1 %, checks);
   --verbose 2 also the circles ("disc x y r") and every returned path ("path x y x y ...").
 */
#include "benchmarks/WorldFamilies.h"

#include "src/io/Generators.h"
#include "src/optimum/Optimum.h"
#include "ompl_planners/memetic/MemeticPlanner.h"
#include "src/registry/Registry.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
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
    struct Disc
    {
        double x, y, r;
    };

    /** \brief A DiscreteMotionValidator that counts its calls. */
    class CountingValidator : public ob::DiscreteMotionValidator
    {
      public:
        CountingValidator(const ob::SpaceInformationPtr &si, std::atomic<unsigned long> &count)
            : ob::DiscreteMotionValidator(si), count_(count)
        {
        }
        bool checkMotion(const ob::State *s1, const ob::State *s2) const override
        {
            ++count_;
            return ob::DiscreteMotionValidator::checkMotion(s1, s2);
        }
        bool checkMotion(const ob::State *s1, const ob::State *s2,
                         std::pair<ob::State *, double> &lastValid) const override
        {
            ++count_;
            return ob::DiscreteMotionValidator::checkMotion(s1, s2, lastValid);
        }

      private:
        std::atomic<unsigned long> &count_;
    };

    /** \brief Deepest penetration of the polyline into any disc, sampled every \e step (0 when free); \e at
        the arc length where it is. */
    double deepestCut(const std::vector<std::array<double, 2>> &pts, const std::vector<Disc> &discs,
                      double step, double &at)
    {
        double deepest = 0.0, before = 0.0;
        at = 0.0;
        for (std::size_t i = 1; i < pts.size(); ++i)
        {
            const double dx = pts[i][0] - pts[i - 1][0], dy = pts[i][1] - pts[i - 1][1];
            const auto n =
                std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(std::hypot(dx, dy) / step)));
            for (std::size_t k = 0; k <= n; ++k)
            {
                const double x = pts[i - 1][0] + dx * double(k) / double(n);
                const double y = pts[i - 1][1] + dy * double(k) / double(n);
                for (const Disc &d : discs)
                    if (d.r - std::hypot(x - d.x, y - d.y) > deepest)
                    {
                        deepest = d.r - std::hypot(x - d.x, y - d.y);
                        at = before + std::hypot(dx, dy) * double(k) / double(n);
                    }
            }
            before += std::hypot(dx, dy);
        }
        return deepest;
    }

    double percentile(std::vector<double> v, double q)
    {
        if (v.empty())
            return std::nan("");
        std::sort(v.begin(), v.end());
        const double pos = q * double(v.size() - 1);
        const auto lo = static_cast<std::size_t>(std::floor(pos));
        const std::size_t hi = std::min(v.size() - 1, lo + 1);
        return v[lo] + (v[hi] - v[lo]) * (pos - double(lo));
    }

    std::vector<std::string> splitList(const std::string &s, char sep = ',')
    {
        std::vector<std::string> out;
        std::stringstream in(s);
        std::string item;
        while (std::getline(in, item, sep))
            if (!item.empty())
                out.push_back(item);
        return out;
    }

    struct Row
    {
        unsigned int runs{0}, exact{0}, cut{0}, within{0};
        double deepest{0.0};
        std::vector<double> gaps, first, toOnePercent, stateChecks, motionChecks, perImprovement, cutLength;
    };

    std::string fixed(double v, int digits)
    {
        std::ostringstream out;
        if (std::isnan(v))
            return "-";
        out << std::fixed << std::setprecision(digits) << v;
        return out.str();
    }
} // namespace

int main(int argc, char **argv)
{
    double timeLimit = 1.0, resolution = 0.002;
    unsigned int queries = 20, count = 70;
    std::uint64_t seed = 31;
    bool verbose = false, paths = false;
    std::vector<std::string> planners = {"GA-MEM",          "SMA-MEM", "LRSMA-MEM", "MGO-MEM",
                                         "InformedRRTstar", "RRTstar", "ABITstar"};
    std::map<std::string, std::string> extra;
    const char *usage = "usage: mhplan_ompl_app [--time S] [--queries N] [--count C] [--resolution R] "
                        "[--planners A,B,...] [--params KEY=VALUE,...] [--seed N] [--verbose 0|1|2]\n";
    // A number option's whole value must be the number ("1s" or "" is refused, not read as 1 or 0).
    bool badNumber = false;
    std::string badKey;
    const auto number = [&](const std::string &key, const std::string &value)
    {
        char *end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || end == nullptr || *end != '\0' || !std::isfinite(v))
        {
            badNumber = true;
            badKey = key + " '" + value + "' (a number expected)";
        }
        return v;
    };
    const auto integer = [&](const std::string &key, const std::string &value)
    {
        const double v = number(key, value);
        if (!badNumber && (v < 0.0 || v > 4294967295.0 || v != std::floor(v)))
        {
            badNumber = true;
            badKey = key + " '" + value + "' (a whole number from 0 to 4294967295 expected)";
        }
        return badNumber ? 0.0 : v;
    };
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
            std::cerr << "mhplan_ompl_app: option '" << key << "' wants a value\n" << usage;
            return 1;
        }
        const std::string value = argv[i + 1];
        if (key == "--time")
            timeLimit = number(key, value);
        else if (key == "--queries")
            queries = static_cast<unsigned int>(integer(key, value));
        else if (key == "--count")
            count = static_cast<unsigned int>(integer(key, value));
        else if (key == "--resolution")
            resolution = number(key, value);
        else if (key == "--planners")
            planners = splitList(value);
        else if (key == "--verbose")
        {
            verbose = value != "0";
            paths = value == "2";
        }
        else if (key == "--seed")
            seed = static_cast<std::uint64_t>(integer(key, value));
        else if (key == "--params")
            for (const std::string &kv : splitList(value))
            {
                const auto eq = kv.find('=');
                if (eq == std::string::npos)
                {
                    std::cerr << "mhplan_ompl_app: --params wants KEY=VALUE,...; got '" << kv << "'\n";
                    return 1;
                }
                extra[kv.substr(0, eq)] = kv.substr(eq + 1);
            }
        else
        {
            std::cerr << "mhplan_ompl_app: unknown option '" << key
                      << "'; accepted: --time S, --queries N, --count C, --resolution R, --planners A,B,..., "
                         "--params KEY=VALUE,..., --seed N, --verbose 0|1|2\n";
            return 1;
        }
    }
    if (badNumber)
    {
        std::cerr << "mhplan_ompl_app: " << badKey << ": not accepted\n" << usage;
        return 1;
    }
    if (!(timeLimit > 0.0) || queries == 0 || queries > 1000 || count == 0 || !(resolution > 0.0) ||
        resolution > 0.5)
    {
        std::cerr << "mhplan_ompl_app: --time > 0, --queries in [1, 1000], --count >= 1, --resolution in (0, "
                     "0.5] expected\n";
        return 1;
    }
    const PlannerRegistry &registry = builtinPlanners();
    for (const std::string &name : planners)
        if (!registry.has(name))
        {
            std::cerr << "mhplan_ompl_app: --planners: unknown planner '" << name << "'\n";
            return 1;
        }
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed));

    FamilyOptions fo;
    fo.kind = "circles";
    fo.count = count;
    fo.coverage = 0.3;
    fo.seed = seed;
    World world = generateFamilyWorld(fo);
    QueryOptions qo;
    qo.count = queries;
    qo.seed = seed;
    addRandomQueries(world, qo);
    std::vector<Disc> discs;
    for (const Circle &c : world.circles)
        discs.push_back({c.center.x, c.center.y, c.radius});
    std::cout << "World: " << discs.size() << " circles in [" << world.bounds.xmin << ", "
              << world.bounds.xmax << "] x [" << world.bounds.ymin << ", " << world.bounds.ymax << "], "
              << queries << " queries; point checker over the circles, DiscreteMotionValidator at "
              << resolution << " (sample spacing "
              << resolution * std::hypot(world.bounds.width(), world.bounds.height()) << " m), " << timeLimit
              << " s per run\n";

    if (paths)
        for (const Disc &d : discs)
            std::cout << "disc " << std::setprecision(17) << d.x << " " << d.y << " " << d.r
                      << std::setprecision(6) << "\n";
    std::map<std::string, Row> rows;
    for (unsigned int q = 0; q < queries; ++q)
    {
        const Query &query = world.queries[q];
        const double optimum = computeOptimum(world, query).length;
        for (const std::string &name : planners)
        {
            Row &row = rows[name];
            ++row.runs;
            std::atomic<unsigned long> stateChecks{0}, motionChecks{0};
            auto space = std::make_shared<ob::RealVectorStateSpace>(2);
            ob::RealVectorBounds b(2);
            b.setLow(0, world.bounds.xmin);
            b.setHigh(0, world.bounds.xmax);
            b.setLow(1, world.bounds.ymin);
            b.setHigh(1, world.bounds.ymax);
            space->setBounds(b);
            auto si = std::make_shared<ob::SpaceInformation>(space);
            // The user's checker: a loop over the circles (touching counts as free).
            si->setStateValidityChecker(
                [&discs, &stateChecks](const ob::State *s)
                {
                    ++stateChecks;
                    const double *v = s->as<ob::RealVectorStateSpace::StateType>()->values;
                    for (const Disc &d : discs)
                        if ((v[0] - d.x) * (v[0] - d.x) + (v[1] - d.y) * (v[1] - d.y) < d.r * d.r)
                            return false;
                    return true;
                });
            si->setMotionValidator(std::make_shared<CountingValidator>(si, motionChecks));
            si->setStateValidityCheckingResolution(resolution);
            si->setup();
            auto ss = std::make_shared<og::SimpleSetup>(si);
            ob::ScopedState<> start(space), goal(space);
            start[0] = query.start.x;
            start[1] = query.start.y;
            goal[0] = query.goal.x;
            goal[1] = query.goal.y;
            ss->setStartAndGoalStates(start, goal);
            ss->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
            std::map<std::string, std::string> params;
            if (registry.get(name).origin == "mhplan")
            {
                params = extra;
                params["seed"] = std::to_string(seed * 1000 + q + 1);
            }
            ob::PlannerPtr planner = registry.create(name, si, params);
            ss->setPlanner(planner);
            ss->setup();
            double firstTime = std::nan(""), within = std::nan("");
            const ompl::time::point t0 = ompl::time::now();
            ss->getProblemDefinition()->setIntermediateSolutionCallback(
                [&](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost cost)
                {
                    const double t = ompl::time::seconds(ompl::time::now() - t0);
                    if (std::isnan(firstTime))
                        firstTime = t;
                    if (std::isnan(within) && cost.value() <= 1.01 * optimum)
                        within = t;
                });
            const ob::PlannerStatus status = ss->solve(timeLimit);
            if (status != ob::PlannerStatus::EXACT_SOLUTION || !ss->haveExactSolutionPath())
                continue;
            ++row.exact;
            const og::PathGeometric &path = ss->getSolutionPath();
            std::vector<std::array<double, 2>> pts;
            for (std::size_t i = 0; i < path.getStateCount(); ++i)
            {
                const double *v = path.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
                pts.push_back({v[0], v[1]});
            }
            const double length = path.length();
            if (std::isnan(firstTime))
                firstTime = ompl::time::seconds(ompl::time::now() - t0); // planners without callbacks
            if (std::isnan(within) && length <= 1.01 * optimum)
                within = firstTime;
            double cutAt = 0.0;
            const double cut = deepestCut(pts, discs, 0.01, cutAt);
            if (cut > 0.0)
            {
                ++row.cut;
                row.deepest = std::max(row.deepest, cut);
            }
            row.gaps.push_back(100.0 * (length - optimum) / optimum);
            row.first.push_back(firstTime);
            if (!std::isnan(within))
            {
                ++row.within;
                row.toOnePercent.push_back(within);
            }
            if (verbose)
                std::cout << "run: query " << q << " " << name << " gap " << fixed(row.gaps.back(), 3)
                          << " % (optimum " << fixed(optimum, 3) << ") first " << fixed(firstTime, 4)
                          << " s within-1% " << fixed(within, 4) << " s state checks " << stateChecks.load()
                          << " motion checks " << motionChecks.load();
            if (verbose && cut > 0.0)
                std::cout << " cut " << fixed(1000.0 * cut, 3) << " mm at " << fixed(cutAt, 3) << " of "
                          << fixed(length, 3) << " m";
            if (verbose)
                std::cout << "\n";
            if (paths)
            {
                std::cout << "path";
                for (const auto &p : pts)
                    std::cout << " " << std::setprecision(17) << p[0] << " " << p[1];
                std::cout << std::setprecision(6) << "\n";
            }
            row.stateChecks.push_back(double(stateChecks.load()));
            row.motionChecks.push_back(double(motionChecks.load()));
            if (const auto mp = std::dynamic_pointer_cast<MemeticPlanner>(planner))
                if (mp->improvementCount() > 0)
                    row.perImprovement.push_back(double(motionChecks.load()) /
                                                 double(mp->improvementCount()));
        }
    }
    std::cout
        << "\n| planner | exact | cut by the dense check (deepest, mm) | gap median / p75 / p90 [%] | "
           "first solution [s] | within 1 %: runs, median time [s] | state checks / run | motion checks "
           "/ run | motion checks / improvement |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const std::string &name : planners)
    {
        const Row &r = rows[name];
        std::cout << "| " << name << " | " << r.exact << "/" << r.runs << " | " << r.cut << " ("
                  << fixed(1000.0 * r.deepest, 2) << ") | " << fixed(percentile(r.gaps, 0.5), 3) << " / "
                  << fixed(percentile(r.gaps, 0.75), 3) << " / " << fixed(percentile(r.gaps, 0.9), 3) << " | "
                  << fixed(percentile(r.first, 0.5), 3) << " | " << r.within << ", "
                  << fixed(percentile(r.toOnePercent, 0.5), 3) << " | "
                  << fixed(percentile(r.stateChecks, 0.5), 0) << " | "
                  << fixed(percentile(r.motionChecks, 0.5), 0) << " | "
                  << fixed(percentile(r.perImprovement, 0.5), 0) << " |\n";
    }
    return 0;
}

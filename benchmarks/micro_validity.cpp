// SPDX-License-Identifier: BSD-3-Clause
/* mhplan micro-benchmarks of the collision back ends (analytic, FCL, spatial hash): state validity, clearance
   and exact motion checks, on the 12-circle world of [BFO] case 2 and on generated worlds of 1,000 and
   10,000 circles. Query points and segments
   are drawn before the timed loops. Run: mhplan_microbench --benchmark_min_time=0.2 */
#include "src/base/Geometry.h"
#include "src/collision/Collision.h"
#include "src/collision/FclCollision.h"
#include "src/collision/Problem.h"
#include "src/collision/Validity.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Console.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace mhplan;

namespace
{
    /** [BFO] case 2 (docs/algorithms.md 9): 12 circles in [0, 10]^2, point robot, (0, 0) to (10, 10). */
    World bfoCase2World()
    {
        World w;
        w.name = "bfo_case2";
        w.bounds = {0.0, 10.0, 0.0, 10.0};
        w.robotRadius = 0.0;
        const double c[12][3] = {{1.0, 1.3, 2.5}, {0.8, 1.7, 6.0}, {0.5, 7.6, 9.0}, {1.3, 4.5, 4.5},
                                 {0.9, 1.2, 5.5}, {1.4, 8.0, 3.0}, {1.2, 6.6, 7.7}, {0.8, 3.2, 1.5},
                                 {0.7, 7.5, 5.5}, {0.6, 8.7, 7.0}, {0.8, 3.5, 6.6}, {0.5, 4.5, 9.0}};
        for (const auto &o : c)
            w.circles.push_back({{o[1], o[2]}, o[0]});
        w.queries.push_back({"default", {0.0, 0.0}, {10.0, 10.0}});
        return w;
    }

    /** \e count circles of radius 0.5..3 in [0, side]^2 (fixed seed), none covering the query's endpoints:
        10,000 in [0, 1000]^2, 1,000 in [0, 316]^2 (the same density, about 11 % covered). */
    World manyCirclesWorld(std::size_t count = 10000, double side = 1000.0, const char *name = "circles10k")
    {
        World w;
        w.name = name;
        w.bounds = {0.0, side, 0.0, side};
        w.robotRadius = 0.0;
        w.queries.push_back({"default", {1.0, 1.0}, {side - 1.0, side - 1.0}});
        std::mt19937_64 rng(20240611);
        std::uniform_real_distribution<double> pos(0.0, side);
        std::uniform_real_distribution<double> rad(0.5, 3.0);
        while (w.circles.size() < count)
        {
            const Circle c{{pos(rng), pos(rng)}, rad(rng)};
            if (distance(c.center, w.queries[0].start) > c.radius &&
                distance(c.center, w.queries[0].goal) > c.radius)
                w.circles.push_back(c);
        }
        return w;
    }

    /** Pregenerated queries: points uniform in the bounds, segments from those points in a random direction
        with a length uniform in [0, 5% of the bounds' width]. */
    struct Queries
    {
        static constexpr std::size_t kCount = 4096; // a power of two: index with & (kCount - 1)
        std::vector<Vec2> points;
        std::vector<Vec2> ends;

        explicit Queries(const World &w)
        {
            std::mt19937_64 rng(7);
            std::uniform_real_distribution<double> x(w.bounds.xmin, w.bounds.xmax);
            std::uniform_real_distribution<double> y(w.bounds.ymin, w.bounds.ymax);
            std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
            std::uniform_real_distribution<double> length(0.0, 0.05 * w.bounds.width());
            for (std::size_t i = 0; i < kCount; ++i)
            {
                const Vec2 p{x(rng), y(rng)};
                const double a = angle(rng);
                const double l = length(rng);
                Vec2 q{p.x + l * std::cos(a), p.y + l * std::sin(a)};
                q.x = std::min(std::max(q.x, w.bounds.xmin), w.bounds.xmax);
                q.y = std::min(std::max(q.y, w.bounds.ymin), w.bounds.ymax);
                points.push_back(p);
                ends.push_back(q);
            }
        }
    };

    /** One world, one back end, and its OMPL setup. */
    struct Case
    {
        World world;
        CollisionModelPtr model;
        ompl::geometric::SimpleSetupPtr setup;
        std::shared_ptr<Queries> queries;
        std::vector<ompl::base::State *> states;
        std::vector<ompl::base::State *> endStates;
        /** Share of the valid query points and segments, in percent (a sanity check on the workload). */
        double validPoints{0.0};
        double validSegments{0.0};

        Case(const World &w, CollisionBackend backend, std::shared_ptr<Queries> q)
            : world(w), model(makeCollisionModel(w, backend)), queries(std::move(q))
        {
            setup = makeSimpleSetup(world, world.queries.front(), model);
            setup->setup();
            const auto &si = setup->getSpaceInformation();
            for (std::size_t i = 0; i < Queries::kCount; ++i)
            {
                states.push_back(si->allocState());
                endStates.push_back(si->allocState());
                setStatePosition(states.back(), queries->points[i]);
                setStatePosition(endStates.back(), queries->ends[i]);
                validPoints += model->isValid(queries->points[i]) ? 100.0 / Queries::kCount : 0.0;
                validSegments +=
                    model->segmentValid(queries->points[i], queries->ends[i]) ? 100.0 / Queries::kCount : 0.0;
            }
        }
        ~Case()
        {
            const auto &si = setup->getSpaceInformation();
            for (auto *s : states)
                si->freeState(s);
            for (auto *s : endStates)
                si->freeState(s);
        }
        Case(const Case &) = delete;
        Case &operator=(const Case &) = delete;
    };

    void registerCase(const std::shared_ptr<Case> &c)
    {
        const std::string suffix = "/" + c->world.name + "/" + c->model->name();
        constexpr std::size_t mask = Queries::kCount - 1;

        benchmark::RegisterBenchmark(("isValid" + suffix).c_str(),
                                     [c](benchmark::State &st)
                                     {
                                         std::size_t i = 0;
                                         for (auto _ : st)
                                             benchmark::DoNotOptimize(
                                                 c->model->isValid(c->queries->points[i++ & mask]));
                                         st.counters["valid%"] = c->validPoints;
                                     });
        benchmark::RegisterBenchmark(("clearance" + suffix).c_str(),
                                     [c](benchmark::State &st)
                                     {
                                         std::size_t i = 0;
                                         for (auto _ : st)
                                             benchmark::DoNotOptimize(
                                                 c->model->clearance(c->queries->points[i++ & mask]));
                                     });
        benchmark::RegisterBenchmark(("segmentValid" + suffix).c_str(),
                                     [c](benchmark::State &st)
                                     {
                                         std::size_t i = 0;
                                         for (auto _ : st)
                                         {
                                             const std::size_t k = i++ & mask;
                                             benchmark::DoNotOptimize(c->model->segmentValid(
                                                 c->queries->points[k], c->queries->ends[k]));
                                         }
                                         st.counters["valid%"] = c->validSegments;
                                     });
        benchmark::RegisterBenchmark(("ompl.isValid" + suffix).c_str(),
                                     [c](benchmark::State &st)
                                     {
                                         const auto &si = c->setup->getSpaceInformation();
                                         std::size_t i = 0;
                                         for (auto _ : st)
                                             benchmark::DoNotOptimize(si->isValid(c->states[i++ & mask]));
                                     });
        benchmark::RegisterBenchmark(("ompl.checkMotion" + suffix).c_str(),
                                     [c](benchmark::State &st)
                                     {
                                         const auto &si = c->setup->getSpaceInformation();
                                         std::size_t i = 0;
                                         for (auto _ : st)
                                         {
                                             const std::size_t k = i++ & mask;
                                             benchmark::DoNotOptimize(
                                                 si->checkMotion(c->states[k], c->endStates[k]));
                                         }
                                     });
    }

    /** \brief Simplicity check of an n-vertex star-shaped polygon (issue 19: an O(n log n) sweep; the
        all-pairs test it replaced took 5 s at 20,000 vertices). */
    void polygonSimplicity(benchmark::State &st)
    {
        const auto n = static_cast<std::size_t>(st.range(0));
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> radius(0.9, 1.0);
        std::vector<Vec2> poly;
        for (std::size_t i = 0; i < n; ++i)
        {
            const double t = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
            const double r = radius(rng);
            poly.push_back({r * std::cos(t), r * std::sin(t)});
        }
        for (auto _ : st)
            benchmark::DoNotOptimize(polygonIsSimple(poly));
        st.SetComplexityN(static_cast<benchmark::IterationCount>(n));
    }
} // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    for (const World &w :
         {bfoCase2World(), manyCirclesWorld(1000, 316.22776601683796, "circles1k"), manyCirclesWorld()})
    {
        auto queries = std::make_shared<Queries>(w);
        for (CollisionBackend b : {CollisionBackend::Analytic, CollisionBackend::FCL, CollisionBackend::Hash})
            registerCase(std::make_shared<Case>(w, b, queries));
    }
    benchmark::RegisterBenchmark("polygonIsSimple", polygonSimplicity)
        ->RangeMultiplier(10)
        ->Range(20, 200000)
        ->Unit(benchmark::kMicrosecond)
        ->Complexity(benchmark::oNLogN);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

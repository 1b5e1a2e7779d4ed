// SPDX-License-Identifier: BSD-3-Clause
/* mhplan micro-benchmarks of reading a world file with many queries (benchmarks/README.md, "Overhead"): the
   world reader (parseWorldYaml: the queries from yaml-cpp's parse events, src/io/QueryList.h), yaml-cpp's
   tree of the same text (YAML::LoadAll, what the reader built before) and yaml-cpp's parse events alone (the
   floor of any reading with yaml-cpp), for worlds of 10^3, 10^4 and 10^5 queries (3.7 MB).
   Run: mhplan_world_microbench --benchmark_min_time=0.5 */
#include "src/io/WorldIO.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>
#include <yaml-cpp/yaml.h>

#include <benchmark/benchmark.h>

#include <map>
#include <sstream>
#include <string>

using namespace mhplan;

namespace
{
    /** A world of \e n queries in one circle's world (as written by a script that lists thousands of
        start-goal pairs): "  - {start: [x, y], goal: [x', y']}" per query. */
    const std::string &worldText(std::size_t n)
    {
        static std::map<std::size_t, std::string> texts;
        std::string &text = texts[n];
        if (text.empty())
        {
            text = "name: many\nbounds: {xmin: 0, xmax: 100, ymin: 0, ymax: 100}\nrobot: {radius: 0.1}\n"
                   "obstacles:\n  - circle: {center: [90, 10], radius: 3}\nqueries:\n";
            for (std::size_t i = 0; i < n; ++i)
            {
                const std::size_t a = (i * 37) % 50 + 1, b = (i * 53) % 50 + 1;
                text += "  - {start: [" + std::to_string(a) + ", " + std::to_string(b) + "], goal: [" +
                        std::to_string(99 - a) + ", " + std::to_string(99 - b) + "]}\n";
            }
        }
        return text;
    }

    void BM_ParseWorld(benchmark::State &state)
    {
        const std::string &text = worldText(static_cast<std::size_t>(state.range(0)));
        for (auto _ : state)
        {
            World w = parseWorldYaml(text, "many.yaml");
            benchmark::DoNotOptimize(w.queries.data());
        }
        state.SetItemsProcessed(state.iterations() * state.range(0));
    }

    void BM_YamlTree(benchmark::State &state)
    {
        const std::string &text = worldText(static_cast<std::size_t>(state.range(0)));
        for (auto _ : state)
        {
            std::vector<YAML::Node> docs = YAML::LoadAll(text);
            benchmark::DoNotOptimize(docs.data());
        }
        state.SetItemsProcessed(state.iterations() * state.range(0));
    }

    class CountingEvents : public YAML::EventHandler
    {
      public:
        void OnDocumentStart(const YAML::Mark &) override {}
        void OnDocumentEnd() override {}
        void OnNull(const YAML::Mark &, YAML::anchor_t) override { ++nodes; }
        void OnAlias(const YAML::Mark &, YAML::anchor_t) override { ++nodes; }
        void OnScalar(const YAML::Mark &, const std::string &, YAML::anchor_t, const std::string &) override
        {
            ++nodes;
        }
        void OnSequenceStart(const YAML::Mark &, const std::string &, YAML::anchor_t,
                             YAML::EmitterStyle::value) override
        {
            ++nodes;
        }
        void OnSequenceEnd() override {}
        void OnMapStart(const YAML::Mark &, const std::string &, YAML::anchor_t,
                        YAML::EmitterStyle::value) override
        {
            ++nodes;
        }
        void OnMapEnd() override {}
        std::size_t nodes{0};
    };

    void BM_YamlEvents(benchmark::State &state)
    {
        const std::string &text = worldText(static_cast<std::size_t>(state.range(0)));
        for (auto _ : state)
        {
            std::istringstream in(text);
            YAML::Parser parser(in);
            CountingEvents events;
            while (parser.HandleNextDocument(events))
            {
            }
            benchmark::DoNotOptimize(events.nodes);
        }
        state.SetItemsProcessed(state.iterations() * state.range(0));
    }
} // namespace

BENCHMARK(BM_ParseWorld)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_YamlTree)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_YamlEvents)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

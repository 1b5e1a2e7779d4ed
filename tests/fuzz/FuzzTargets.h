// SPDX-License-Identifier: BSD-3-Clause
/* mhplan fuzz targets: how each target turns its input bytes into a reader call. Shared by the libFuzzer
   executables (fuzz_<target>.cpp) and the regression test (tests/test_fuzz_regressions.cpp), which feeds the
   kept crashing inputs tests/data/fuzz_regressions/<target>-* through the same function and expects each to
   be refused with an InputError. A reader given any bytes either returns or throws mhplan::InputError; any
   other exception, a crash, a leak, undefined behaviour or an allocation beyond libFuzzer's -malloc_limit_mb
   is a defect. */
#ifndef MHPLAN_FUZZ_TARGETS_H
#define MHPLAN_FUZZ_TARGETS_H

#include "src/base/PlannerRegistry.h"
#include "benchmarks/Campaign.h"
#include "src/cli/Args.h"
#include "src/io/GridIO.h"
#include "src/io/ScenIO.h"
#include "src/io/WorldIO.h"
#include "src/registry/Registry.h"
#include "src/sim/ScenarioIO.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>

#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace mhplan::fuzz
{
    /** \brief World YAML (parseWorldYaml), the whole reader including validation of the queries. Relative
        grid files resolve against a directory that does not exist: the target reads no files. */
    inline void worldYaml(const std::string &input)
    {
        parseWorldYaml(input, "/nonexistent/fuzz.yaml");
    }

    /** \brief MovingAI .map files (parseMovingAIMap). */
    inline void map(const std::string &input)
    {
        std::istringstream in(input);
        parseMovingAIMap(in, "fuzz.map");
    }

    /** \brief PGM images, P2 and P5 (parsePgm); the first byte gives the threshold (low 7 bits / 127) and
        negation (high bit). */
    inline void pgm(const std::string &input)
    {
        if (input.empty())
            return;
        const unsigned char b = static_cast<unsigned char>(input[0]);
        std::istringstream in(input.substr(1));
        parsePgm(in, "fuzz.pgm", 1.0, (b & 0x7f) / 127.0, (b & 0x80) != 0);
    }

    /** \brief Inline grids of world files ("grid: {rows: [...]}"): the input's lines become the rows (any
        bytes), read by readWorldNode; a first line starting with '#' gives further grid keys as YAML (e.g.
        "# {cell_size: 0.5, origin: [1, 2]}"). */
    inline void gridRows(const std::string &input)
    {
        std::istringstream in(input);
        YAML::Node grid(YAML::NodeType::Map);
        YAML::Node rows(YAML::NodeType::Sequence);
        bool first = true;
        for (std::string line; std::getline(in, line); first = false)
        {
            if (first && !line.empty() && line[0] == '#')
            {
                YAML::Node extra;
                try
                {
                    extra = YAML::Load(line.substr(1));
                }
                catch (const YAML::Exception &)
                {
                    continue;
                }
                if (extra.IsMap())
                    for (const auto &kv : extra)
                        grid[kv.first] = kv.second;
            }
            else
                rows[rows.size()] = line; // a scalar in the sequence's own node memory (push_back(line)
                                          // would give every row a memory of its own and merge it: that
                                          // took about 2/3 of each execution)
        }
        grid["rows"] = rows;
        YAML::Node root(YAML::NodeType::Map);
        root["grid"] = grid;
        readWorldNode(YamlReader("fuzz.yaml"), root);
    }

    /** \brief MovingAI .scen files (parseMovingAIScen) against a fixed 8 x 6 map with blocked cells. */
    inline void scen(const std::string &input)
    {
        static const OccupancyGrid grid = []
        {
            std::istringstream m("type octile\nheight 6\nwidth 8\nmap\n........\n..@@....\n..@@..T.\n"
                                 "........\n.....@@.\n........\n");
            return parseMovingAIMap(m, "fuzz.map");
        }();
        std::istringstream in(input);
        parseMovingAIScen(in, "fuzz.scen", grid);
    }

    /** \brief Scenario YAML files (parseScenarioYaml). */
    inline void scenario(const std::string &input)
    {
        parseScenarioYaml(input, "/nonexistent/fuzz.yaml");
    }

    /** \brief Campaign YAML files (parseCampaign, checked against the built-in registry). */
    inline void campaign(const std::string &input)
    {
        bench::parseCampaign(input, "/nonexistent/fuzz.yaml");
    }

    /** \brief The command line's value parsing: each input line after the first byte is one argument of a
        command taking --start, --goal, --bounds, --time, --seed and any number of --set KEY=VALUE; the first
        byte picks the registered planner (on a 2D space) --set applies to. Each value is parsed on its own:
        the first InputError of any of them is rethrown after all were tried. */
    inline void cliValues(const std::string &input)
    {
        if (input.empty())
            return;
        static const ompl::base::SpaceInformationPtr si = []
        {
            auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
            space->setBounds(0.0, 10.0);
            auto info = std::make_shared<ompl::base::SpaceInformation>(space);
            info->setStateValidityChecker([](const ompl::base::State *) { return true; });
            info->setup();
            return info;
        }();
        const PlannerRegistry &registry = builtinPlanners();
        static const std::vector<std::string> names = registry.names();
        const std::string planner = names[static_cast<unsigned char>(input[0]) % names.size()];
        std::vector<std::string> argv;
        std::istringstream in(input.substr(1));
        for (std::string line; std::getline(in, line);)
            argv.push_back(line);
        const cli::Args args("fuzz", argv, {{"start", "goal", "bounds", "time", "seed"}, {"set"}, {"flag"}});
        std::string firstError;
        const auto attempt = [&](const std::function<void()> &f)
        {
            try
            {
                f();
            }
            catch (const InputError &e)
            {
                if (firstError.empty())
                    firstError = e.what();
            }
        };
        attempt([&] { args.point("start"); });
        attempt([&] { args.point("goal"); });
        attempt([&] { args.number("time", 1.0); });
        attempt([&] { args.integer("seed", 1); });
        attempt(
            [&]
            {
                const std::vector<double> b = cli::parseNumberList("--bounds", args.get("bounds"));
                if (b.size() == 4)
                {
                    const std::string problem = boundsProblem({b[0], b[1], b[2], b[3]});
                    if (!problem.empty())
                        throw InputError("--bounds: " + problem);
                }
            });
        attempt(
            [&]
            {
                std::map<std::string, std::string> params;
                for (const auto &item : args.all("set"))
                    parseKeyValue(item, params);
                registry.create(planner, si, params);
            });
        if (!firstError.empty())
            throw InputError(firstError);
    }

    /** \brief Every target by name (the names of scripts/fuzz.sh and of the regression files). */
    inline const std::map<std::string, std::function<void(const std::string &)>> &targets()
    {
        static const std::map<std::string, std::function<void(const std::string &)>> all{
            {"world_yaml", worldYaml},
            {"map", map},
            {"pgm", pgm},
            {"grid_rows", gridRows},
            {"scen", scen},
            {"scenario", scenario},
            {"campaign", campaign},
            {"cli_values", cliValues}};
        return all;
    }
} // namespace mhplan::fuzz

/** \brief The libFuzzer entry point of target \e FN: InputError is the expected outcome of bad input,
    anything else aborts (a finding). */
#define MHPLAN_FUZZ_TARGET(FN)                                                                               \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)                        \
    {                                                                                                        \
        static const bool quiet = []                                                                         \
        {                                                                                                    \
            ompl::msg::setLogLevel(ompl::msg::LOG_NONE);                                                     \
            return true;                                                                                     \
        }();                                                                                                 \
        (void)quiet;                                                                                         \
        try                                                                                                  \
        {                                                                                                    \
            FN(std::string(reinterpret_cast<const char *>(data), size));                                     \
        }                                                                                                    \
        catch (const mhplan::InputError &)                                                                   \
        {                                                                                                    \
        }                                                                                                    \
        catch (const std::exception &e)                                                                      \
        {                                                                                                    \
            std::fprintf(stderr, "mhplan fuzz: escaped exception (not InputError): %s\n", e.what());         \
            std::abort();                                                                                    \
        }                                                                                                    \
        return 0;                                                                                            \
    }

#endif

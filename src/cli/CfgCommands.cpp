// SPDX-License-Identifier: BSD-3-Clause
/* mhplan plan PROBLEM.cfg and mhplan bench PROBLEM.cfg: OMPL.app's problem files (docs/omplapp.md). */
#include "src/cli/Args.h"
#include "src/cli/CfgDraw.h"
#include "src/cli/Commands.h"
#include "src/draw/Svg.h"

#include "src/io/CfgIO.h"
#include "src/io/World3dIO.h"
#include "src/registry/Registry.h"

#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Time.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <mutex>
#include <set>

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace fs = std::filesystem;

namespace mhplan::cli
{
    namespace
    {
        /** The problem context with an instance's own on top (OMPL.app: the instance's keys win). */
        std::map<std::string, std::string> contextOf(const LoadedCfgProblem &p,
                                                     const CfgPlannerInstance *instance)
        {
            std::map<std::string, std::string> out = p.spec.context;
            if (instance != nullptr)
                for (const auto &[k, v] : instance->context)
                    out[k] = v.value;
            return out;
        }

        /** Planner \e instance allocated with its parameters; errors name the file, line and key. */
        ob::PlannerPtr allocateInstance(const CfgProblem &cfg, const CfgPlannerInstance &instance,
                                        const ob::SpaceInformationPtr &si)
        {
            const std::string where =
                cfg.file + ":" + std::to_string(instance.line) + ": key 'planner." + instance.name + "'";
            const PlannerEntry *entry = nullptr;
            try
            {
                entry = &builtinPlanners().get(instance.name);
            }
            catch (const InputError &e)
            {
                throw InputError(where + ": " + e.what());
            }
            ob::PlannerPtr planner = entry->allocate(si);
            for (const auto &[key, value] : instance.params)
                try
                {
                    applyPlannerParameters(*planner, {{key, value.value}});
                }
                catch (const InputError &e)
                {
                    throw InputError(cfg.file + ":" + std::to_string(value.line) + ": key 'planner." +
                                     instance.name + "." + key + "': " + e.what());
                }
            return planner;
        }

        std::string spaceLabel(const CfgProblem &cfg)
        {
            return cfg.spaceLabel();
        }

        /** The dense check's step: 1e-3 of the volume's diagonal (x, y, and z for SE(3)). */
        double denseStep(const LoadedCfgProblem &p)
        {
            return 1e-3 * p.spec.volume.diagonal().head(p.cfg.se3 ? 3 : 2).norm();
        }

        void printNotes(const CfgProblem &cfg)
        {
            for (const auto &n : cfg.notes)
                std::cerr << "note: " << n << "\n";
        }

        void applyContextOrFail(const LoadedCfgProblem &p, const CfgPlannerInstance *instance,
                                const ob::SpaceInformationPtr &si)
        {
            try
            {
                applyMeshContext(si, contextOf(p, instance));
            }
            catch (const InputError &e)
            {
                throw InputError(p.cfg.file + (instance ? ":" + std::to_string(instance->line) : "") + ": " +
                                 e.what());
            }
        }

        LoadedCfgProblem loadOrFail(const std::string &path, const std::string &validator,
                                    const std::string &query = "")
        {
            LoadedCfgProblem p = loadCfgProblem(loadCfg(path, query));
            if (!validator.empty())
            {
                if (validator != "certified" && validator != "discrete")
                    throw InputError("--validator: expected certified or discrete, got '" + validator + "'");
                p.spec.motionValidator = validator;
            }
            return p;
        }

        og::SimpleSetupPtr setupOrFail(const LoadedCfgProblem &p)
        {
            try
            {
                return makeMeshSetup(p.spec);
            }
            catch (const InputError &e)
            {
                throw InputError(p.cfg.file + ": " + e.what());
            }
        }
    } // namespace

    bool isCfgArgument(const Argv &argv)
    {
        for (const auto &a : argv)
            if (a.rfind("--", 0) != 0 &&
                ((a.size() > 4 && a.compare(a.size() - 4, 4, ".cfg") == 0) || isWorld3dFile(a)))
                return true;
        return false;
    }

    int cmdPlanCfg(const Argv &argv)
    {
        const Args args(
            "plan", argv,
            {{"planner", "time", "seed", "validator", "path", "svg", "query"}, {"set"}, {"quiet"}});
        checkOutputFile(args, "svg");
        const std::uint_fast32_t seed = seedFromArgs(args);
        if (args.positional().size() != 1)
            throw InputError("mhplan plan: expected one PROBLEM.cfg or 3D WORLD.yaml");
        const LoadedCfgProblem p = loadOrFail(args.positional()[0], args.get("validator"), args.get("query"));
        printNotes(p.cfg);
        og::SimpleSetupPtr ss = setupOrFail(p);
        const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
        // The planner: --planner with --set, else the file's first instance with its parameters.
        ob::PlannerPtr planner;
        std::string plannerName;
        if (args.has("planner") || p.cfg.planners.empty())
        {
            plannerName = builtinPlanners().get(args.get("planner", "RRTConnect")).name;
            const std::string whyNot = builtinPlanners().whyNotApplicable(plannerName, *si);
            if (!whyNot.empty())
                throw InputError("mhplan plan: " + whyNot);
            std::map<std::string, std::string> params;
            for (const auto &kv : args.all("set"))
                parseKeyValue(kv, params);
            planner = builtinPlanners().create(plannerName, si, params);
        }
        else
        {
            if (!args.all("set").empty())
                throw InputError(
                    "mhplan plan: --set needs --planner (the file's planner has its parameters)");
            const CfgPlannerInstance &first = p.cfg.planners.front();
            applyContextOrFail(p, &first, si);
            planner = allocateInstance(p.cfg, first, si);
            plannerName = builtinPlanners().get(first.name).name;
        }
        ss->setPlanner(planner);
        ss->setup();
        const double timeLimit = args.number("time", p.cfg.timeLimit.value_or(1.0));
        if (!(timeLimit > 0.0))
            throw InputError("mhplan plan: --time must be > 0 seconds");
        const auto &volume = p.spec.volume;
        std::cout << "problem:   " << p.cfg.name << " (" << spaceLabel(p.cfg) << ", "
                  << (p.cfg.world3d
                          ? std::to_string(p.spec.model->obstacles().size()) + " obstacles (" +
                                std::to_string(p.spec.model->environmentTriangles()) + " mesh triangles), "
                          : std::to_string(p.spec.model->environmentTriangles()) + " environment triangles, ")
                  << (p.spec.model->robotRadius() < 0.0
                          ? std::to_string(p.spec.model->robotTriangles()) + " robot triangles"
                      : p.spec.model->robotRadius() > 0.0 ? "sphere robot"
                                                          : "point robot")
                  << ", robot reach " << p.spec.model->reach() << ")\n"
                  << "volume:    [" << volume.min().transpose() << "] .. [" << volume.max().transpose() << "]"
                  << (p.cfg.volume ? "" : " (inferred from the environment)") << "\n"
                  << "planner:   " << plannerName << "\nseed:      " << seed << "\n"
                  << "motions:   "
                  << (p.spec.motionValidator == "certified"
                          ? "certified (clearance-bounded steps, docs/meshes.md)"
                          : "OMPL's discrete validator at longest_valid_segment_fraction " +
                                std::to_string(si->getStateValidityCheckingResolution()))
                  << "\n";
        const ompl::time::point t0 = ompl::time::now();
        const ob::PlannerStatus status = ss->solve(timeLimit);
        const double seconds = ompl::time::seconds(ompl::time::now() - t0);
        std::cout << "status:    " << status.asString() << "\n"
                  << std::setprecision(6) << "time:      " << seconds << " s\n";
        if (!ss->haveSolutionPath())
        {
            if (args.has("svg"))
                writeTextFile(args.get("svg"), cfgProblemSvg(p, si, nullptr));
            std::cout << "no path\n";
            return 3;
        }
        const og::PathGeometric &path = ss->getSolutionPath();
        long contact = -1;
        const std::size_t poses = denseMeshPathCheck(*p.spec.model, *si, path, denseStep(p), contact);
        std::cout << std::setprecision(9) << "cost:      " << path.length() << " (path length in the "
                  << spaceLabel(p.cfg) << " metric)\n"
                  << "valid:     " << (contact < 0 ? "yes" : "NO (motion " + std::to_string(contact) + ")")
                  << " (independent dense check: " << poses << " poses, robot points at most " << denseStep(p)
                  << " apart)\n"
                  << "path:      " << path.getStateCount() << " states\n";
        if (!args.has("quiet"))
            path.printAsMatrix(std::cout);
        if (args.has("svg"))
        {
            writeTextFile(args.get("svg"), cfgProblemSvg(p, si, &path));
            std::cout << "svg:       " << args.get("svg") << "\n";
        }
        if (args.has("path"))
        {
            std::ofstream out(args.get("path"));
            // Every digit: the saved path is the path checked above, not a rounded neighbour of it.
            out << std::setprecision(std::numeric_limits<double>::max_digits10);
            path.printAsMatrix(out);
            if (!out)
                throw InputError("mhplan plan: cannot write " + args.get("path"));
        }
        return status == ob::PlannerStatus::EXACT_SOLUTION && contact < 0 ? 0 : 3;
    }

    int cmdBenchCfg(const Argv &argv)
    {
        const Args args("bench", argv,
                        {{"runs", "time", "seed", "database", "logs", "validator"}, {}, {"no-progress"}});
        if (args.positional().size() != 1)
            throw InputError("mhplan bench: expected one PROBLEM.cfg");
        const std::uint_fast32_t seed = seedFromArgs(args);
        const LoadedCfgProblem p = loadOrFail(args.positional()[0], args.get("validator"));
        const CfgProblem &cfg = p.cfg;
        printNotes(cfg);
        if (cfg.world3d)
            throw InputError(cfg.file +
                             ": a 3D world names no planners or runs: benchmark it as a campaign "
                             "world entry {cfg: FILE} (docs/worlds3d.md), or plan it with mhplan plan");
        if (cfg.planners.empty())
            throw InputError(cfg.file + ": the [planner] section names no planner");
        if (!args.has("time") && !cfg.timeLimit)
            throw InputError(cfg.file + ": key 'benchmark.time_limit' is missing (or give --time)");
        if (!args.has("runs") && !cfg.runCount)
            throw InputError(cfg.file + ": key 'benchmark.run_count' is missing (or give --runs)");
        const double timeLimit = args.number("time", cfg.timeLimit.value_or(1.0));
        const long long runs = args.integer("runs", cfg.runCount.value_or(1));
        if (!(timeLimit > 0.0) || runs < 1 || runs > 1000000)
            throw InputError("mhplan bench: --time must be > 0 and --runs in [1, 1000000]");

        og::SimpleSetupPtr ss = setupOrFail(p);
        const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
        // Check every instance (name, parameters, context) before anything runs.
        std::vector<std::string> names;
        std::map<std::string, int> seen;
        for (const auto &instance : cfg.planners)
        {
            applyContextOrFail(p, &instance, si);
            const ob::PlannerPtr probe = allocateInstance(cfg, instance, si);
            std::string name = instance.displayName.empty() ? probe->getName() : instance.displayName;
            // OMPL's log keys planners by name: repeated instances get a number.
            if (++seen[name] > 1)
                name += "_" + std::to_string(seen[name]);
            names.push_back(name);
        }
        applyMeshContext(si, p.spec.context);

        const fs::path cfgDir = fs::absolute(cfg.file).parent_path();
        const fs::path logDir = args.has("logs") ? fs::path(args.get("logs"))
                                                 : (cfg.output.empty() ? cfgDir : cfgDir / cfg.output);
        fs::create_directories(logDir);
        const std::string stem = fs::path(cfg.file).stem().string();
        const fs::path log = logDir / (stem + ".log");
        const fs::path database =
            args.has("database") ? fs::path(args.get("database")) : logDir / (stem + ".db");

        ompl::tools::Benchmark benchmark(*ss, cfg.name);
        std::map<const ob::Planner *, std::size_t> instanceOf;
        for (std::size_t i = 0; i < cfg.planners.size(); ++i)
            benchmark.addPlannerAllocator(
                [&, i](const ob::SpaceInformationPtr &s)
                {
                    ob::PlannerPtr planner = allocateInstance(cfg, cfg.planners[i], s);
                    planner->setName(names[i]);
                    instanceOf[planner.get()] = i;
                    return planner;
                });
        benchmark.setPlannerSwitchEvent(
            [&](const ob::PlannerPtr &planner)
            { applyMeshContext(si, contextOf(p, &cfg.planners[instanceOf[planner.get()]])); });
        // After each run: the independent dense check of the path, and the paths save_paths asks for.
        std::map<std::string, std::pair<double, std::string>> shortest; // planner -> (length, text)
        std::size_t checked = 0, invalid = 0;
        const double step = denseStep(p);
        benchmark.setPostRunEvent(
            [&](const ob::PlannerPtr &planner, ompl::tools::Benchmark::RunProperties &run)
            {
                const ob::ProblemDefinitionPtr pdef = planner->getProblemDefinition();
                if (!pdef->hasSolution())
                    return;
                const auto path = std::dynamic_pointer_cast<og::PathGeometric>(pdef->getSolutionPath());
                long contact = -1;
                const std::size_t poses = denseMeshPathCheck(*p.spec.model, *si, *path, step, contact);
                ++checked;
                invalid += contact >= 0 ? 1 : 0;
                run["dense check valid BOOLEAN"] = contact < 0 ? "1" : "0";
                run["dense check poses INTEGER"] = std::to_string(poses);
                const auto &status = benchmark.getStatus();
                const std::string file =
                    cfg.name + "_" + status.activePlanner + "_" + std::to_string(status.activeRun) + ".path";
                std::ostringstream text;
                path->printAsMatrix(text);
                if (cfg.savePaths == "all")
                    std::ofstream(logDir / file) << text.str();
                else if (cfg.savePaths == "shortest" && !pdef->hasApproximateSolution())
                {
                    auto &best = shortest[status.activePlanner];
                    if (best.second.empty() || path->length() < best.first)
                        best = {path->length(), file + "\n" + text.str()};
                }
            });
        ompl::tools::Benchmark::Request request;
        request.maxTime = timeLimit;
        request.maxMem = cfg.memLimit.value_or(4096.0);
        request.runCount = static_cast<unsigned>(runs);
        request.displayProgress = !args.has("no-progress");
        request.simplify = cfg.simplify;
        request.saveConsoleOutput = false;
        std::cout << "problem:  " << cfg.name << " (" << spaceLabel(cfg) << ") seed " << seed << ", "
                  << names.size() << " planners x " << runs << " runs x " << timeLimit << " s\n";
        benchmark.benchmark(request);
        if (!benchmark.saveResultsToFile(log.string().c_str()))
            throw std::runtime_error("cannot write " + log.string());
        for (const auto &[planner, best] : shortest)
        {
            const auto nl = best.second.find('\n');
            std::ofstream(logDir / best.second.substr(0, nl)) << best.second.substr(nl + 1);
        }
        const std::string command = "/usr/bin/ompl_benchmark_statistics '" + log.string() + "' -d '" +
                                    database.string() + "' > /dev/null";
        const bool merged = std::system(command.c_str()) == 0;
        const auto &data = benchmark.getRecordedExperimentData();
        for (const auto &planner : data.planners)
        {
            std::size_t solved = 0;
            for (const auto &run : planner.runs)
            {
                const auto it = run.find("solved BOOLEAN");
                solved += it != run.end() && it->second == "1" ? 1 : 0;
            }
            std::cout << "  " << std::left << std::setw(24) << planner.name << " solved " << solved << "/"
                      << planner.runs.size() << "\n";
        }
        std::cout << "paths:    " << checked << " checked densely, " << invalid << " invalid\n"
                  << "log:      " << log.string() << "\n"
                  << "database: "
                  << (merged ? database.string() : "NOT written (ompl_benchmark_statistics failed)") << "\n";
        return merged && invalid == 0 ? 0 : 3;
    }
} // namespace mhplan::cli

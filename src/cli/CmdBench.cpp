// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench CAMPAIGN: run a benchmark campaign (benchmarks/README.md) and build its database. */
#include "mhplan/cli/Args.h"
#include "mhplan/cli/Commands.h"

#include "mhplan/bench/Campaign.h"
#include "mhplan/bench/CampaignRunner.h"

#include <filesystem>
#include <iomanip>
#include <iostream>

namespace mhplan::cli
{
    namespace
    {
        void parseShard(const std::string &text, unsigned int &part, unsigned int &parts)
        {
            const auto slash = text.find('/');
            try
            {
                if (slash == std::string::npos)
                    throw std::invalid_argument("no slash");
                std::size_t used = 0;
                const unsigned long i = std::stoul(text.substr(0, slash), &used);
                if (used != slash)
                    throw std::invalid_argument("trailing characters");
                const std::string rest = text.substr(slash + 1);
                const unsigned long n = std::stoul(rest, &used);
                if (used != rest.size())
                    throw std::invalid_argument("trailing characters");
                part = static_cast<unsigned int>(i);
                parts = static_cast<unsigned int>(n);
            }
            catch (const std::exception &)
            {
                throw InputError("mhplan bench: --shard expects i/N (e.g. 2/8), got '" + text + "'");
            }
            if (parts < 1 || part < 1 || part > parts)
                throw InputError("mhplan bench: --shard i/N needs 1 <= i <= N (got '" + text + "')");
        }
    } // namespace

    int cmdBench(const Argv &argv)
    {
        const Args args("bench", argv,
                        {{"jobs", "shard", "database", "logs", "runs", "time", "seed"},
                         {},
                         {"merge-only", "no-merge", "no-progress", "list"}});
        if (args.positional().size() != 1)
            throw InputError("mhplan bench: expected one CAMPAIGN file (e.g. benchmarks/seeds.yaml)");
        bench::Campaign campaign = bench::loadCampaign(args.positional()[0]);
        if (args.has("database"))
        {
            campaign.database = args.get("database");
            if (!args.has("logs"))
                campaign.logDir = campaign.database + ".logs";
        }
        if (args.has("logs"))
            campaign.logDir = args.get("logs");
        if (args.has("runs"))
        {
            const long long runs = args.integer("runs", 1);
            if (runs < 1 || runs > 1000000)
                throw InputError("mhplan bench: --runs must be in [1, 1000000] (got " + args.get("runs") +
                                 ")");
            campaign.runs = static_cast<unsigned int>(runs);
        }
        if (args.has("time"))
        {
            const double t = args.number("time", 1.0);
            if (!(t > 0.0))
                throw InputError("mhplan bench: --time must be > 0 seconds (got " + args.get("time") + ")");
            campaign.timeLimit = t;
        }
        if (args.has("seed"))
        {
            const long long seed = args.integer("seed", 1);
            if (seed < 1 || seed > 4294967295LL)
                throw InputError("mhplan bench: --seed must be in [1, 4294967295] (got " + args.get("seed") +
                                 ")");
            campaign.seed = static_cast<std::uint32_t>(seed);
        }

        bench::RunOptions options;
        const long long jobs = args.integer("jobs", 1);
        if (jobs < 1 || jobs > 256)
            throw InputError("mhplan bench: --jobs must be in [1, 256] (got " + args.get("jobs") + ")");
        options.jobs = static_cast<unsigned int>(jobs);
        if (args.has("shard"))
            parseShard(args.get("shard"), options.shardIndex, options.shardCount);
        if (args.has("merge-only") && args.has("no-merge"))
            throw InputError("mhplan bench: --merge-only and --no-merge exclude each other");
        options.run = !args.has("merge-only");
        // A shard only writes its logs; one final 'mhplan bench CAMPAIGN --merge-only' builds the database.
        options.merge = !args.has("no-merge") && (!args.has("shard") || args.has("merge-only"));
        options.progressBar = !args.has("no-progress");
        options.messages = &std::cerr;
        options.resolveWorld = resolveWorldPath;

        if (args.has("list"))
        {
            const auto all = bench::enumerateExperiments(campaign, options.resolveWorld);
            const auto mine = bench::shardExperiments(all, options.shardIndex, options.shardCount);
            for (const auto &e : mine)
                std::cout << e.index << "\t" << e.name << "\t"
                          << (bench::logIsComplete(bench::logFile(campaign, e), e.configHash) ? "complete"
                                                                                              : "to do")
                          << "\t" << bench::logFile(campaign, e) << "\n";
            return 0;
        }

        std::cout << "campaign " << campaign.name << ": seed " << campaign.seed;
        if (!campaign.planners.empty())
            std::cout << ", " << campaign.planners.size() << " planner(s), " << campaign.runs
                      << " runs each, " << campaign.timeLimit << " s per run";
        if (!campaign.simulations.empty())
        {
            std::size_t controllers = 0;
            for (const auto &sim : campaign.simulations)
                controllers += sim.controllers.size();
            std::cout << ", " << campaign.simulations.size() << " simulation scenario(s) with " << controllers
                      << " scenario-controller pair(s)";
        }
        if (options.shardCount > 1)
            std::cout << ", shard " << options.shardIndex << "/" << options.shardCount;
        std::cout << ", " << options.jobs << " job(s)\n";
        const bench::CampaignSummary s = bench::runCampaign(campaign, options);
        std::cout << std::fixed << std::setprecision(1);
        std::cout << "experiments: " << s.experiments << " (" << s.completed << " run now, " << s.skipped
                  << " already complete, " << s.failed << " failed)\n";
        std::cout << "runs:        " << s.runs << " (" << s.crashes << " recorded as Crash)\n";
        std::cout << "wall time:   " << s.wallSeconds << " s (solve " << s.solveSeconds
                  << " s, experiment processes " << s.workerSeconds << " s, database " << s.mergeSeconds
                  << " s)\n";
        if (s.workerSeconds > 0.0)
            std::cout << "overhead:    " << std::setprecision(2) << 100.0 * s.overheadFraction()
                      << " % of the time outside the planners' solve calls\n";
        std::cout << std::defaultfloat;
        std::cout << "logs:        " << campaign.logDir << "\n";
        if (options.merge)
            std::cout << "database:    " << campaign.database << " (" << s.mergedLogs << " log(s) appended)\n"
                      << "next:        mhplan report " << campaign.database
                      << " -o REPORT_DIR; Planner Arena; or "
                      << "ompl_benchmark_statistics -d " << campaign.database << " -p (plots in "
                      << std::filesystem::path(campaign.database).replace_extension(".pdf").string() << ")\n";
        const std::string simulations = mhplan::bench::simulationDatabaseFile(campaign);
        if (options.merge && !campaign.simulations.empty() && simulations != campaign.database)
            std::cout << "simulations: " << simulations
                      << " (their own database: Planner Arena lists every experiment column as a problem "
                         "parameter)\n";
        else if (options.shardCount > 1)
            std::cout << "database:    not built by a shard; after all shards: mhplan bench "
                      << args.positional()[0] << " --merge-only\n";
        for (const auto &e : s.errors)
            std::cerr << "mhplan bench: " << e << "\n";
        return s.failed > 0 ? 3 : 0;
    }
} // namespace mhplan::cli

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench CAMPAIGN: run a benchmark campaign (benchmarks/README.md) and build its database. */
#include "src/cli/Args.h"
#include "src/cli/Commands.h"
#include "src/cli/Help.h"

#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignRunner.h"
#include "benchmarks/Slurm.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>
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
        /** A Slurm time ("HH:MM:SS", "D-HH:MM:SS", "MM:SS") rather than seconds per run. */
        bool isClockTime(const std::string &text)
        {
            return text.find(':') != std::string::npos;
        }

        /** mhplan bench CAMPAIGN --status: every experiment that is not complete, and a count. */
        int printStatus(const bench::Campaign &campaign, const std::vector<bench::Experiment> &experiments)
        {
            std::size_t count[4] = {0, 0, 0, 0};
            for (const auto &e : experiments)
            {
                std::string why;
                const bench::ExperimentState state = bench::experimentState(campaign, e, why);
                ++count[static_cast<int>(state)];
                if (state != bench::ExperimentState::Complete)
                    std::cout << bench::stateName(state) << "\t" << e.name << (why.empty() ? "" : "\t") << why
                              << "\n";
            }
            std::cout << "campaign " << campaign.name << ": " << experiments.size() << " experiments, "
                      << count[0] << " complete, " << count[1] << " missing, " << count[3] << " failed, "
                      << count[2] << " running (logs in " << campaign.logDir << ")\n";
            std::ifstream submitted(std::filesystem::path(campaign.logDir) / "slurm" / "submitted");
            std::string line, last;
            while (std::getline(submitted, line))
                last = line;
            if (!last.empty())
                std::cout << "last Slurm submission: " << last << "\n";
            return count[0] == experiments.size() ? 0 : 1;
        }

        /** mhplan bench CAMPAIGN --slurm: write (and with --submit, submit) the array and merge jobs. */
        int slurmCampaign(const Args &args, const bench::Campaign &campaign,
                          const std::vector<bench::Experiment> &experiments)
        {
            namespace fs = std::filesystem;
            bench::SlurmOptions o;
            if (!args.has("shards"))
                throw InputError(
                    "mhplan bench --slurm: --shards N is required (array tasks, each one shard i/N)");
            o.shards = static_cast<unsigned int>(std::clamp<long long>(args.integer("shards", 1), 0, 100000));
            o.cpus = static_cast<unsigned int>(std::clamp<long long>(args.integer("cpus", 1), 0, 100000));
            if (args.has("mem"))
            {
                const long long mem = args.integer("mem", 0);
                if (mem < 1 || mem > 100000000)
                    throw InputError("mhplan bench --slurm: --mem must be in [1, 100000000] MB (got " +
                                     args.get("mem") + ")");
                o.memoryMB = static_cast<unsigned long>(mem);
            }
            o.partition = args.get("partition");
            if (args.has("time") && isClockTime(args.get("time")))
                o.timeLimit = args.get("time");
            for (const char *unused : {"jobs", "shard"})
                if (args.has(unused))
                    throw InputError(
                        std::string("mhplan bench --slurm: --") + unused +
                        " is set per task (--cpus C gives each task --jobs C; --shards N the shards)");
            bench::checkSlurmOptions(o);
            std::error_code ec;
            o.executable = fs::read_symlink("/proc/self/exe", ec).string();
            if (ec)
                throw std::runtime_error("cannot find the mhplan executable (/proc/self/exe): " +
                                         ec.message());
            o.campaignFile = fs::absolute(args.positional()[0]).lexically_normal().string();
            o.workDir = fs::current_path().string();
            // The tasks and the merge see the campaign exactly as this command line does.
            o.passThrough = {"--database", fs::absolute(campaign.database).lexically_normal().string(),
                             "--logs", fs::absolute(campaign.logDir).lexically_normal().string()};
            for (const char *name : {"runs", "seed"})
                if (args.has(name))
                    o.passThrough.insert(o.passThrough.end(), {std::string("--") + name, args.get(name)});
            if (args.has("time") && !isClockTime(args.get("time")))
                o.passThrough.insert(o.passThrough.end(), {"--time", args.get("time")});

            const bench::SlurmScripts scripts = bench::writeSlurmScripts(campaign, experiments, o);
            const std::string todo = scripts.missingShards.empty() ? "none" : scripts.missingShards;
            std::cout << "campaign " << campaign.name << ": " << experiments.size() << " experiments in "
                      << o.shards << " shard(s), " << o.cpus << " CPU(s) and " << scripts.taskTime
                      << " per task\n"
                      << "array job:    " << scripts.arrayScript << "\n"
                      << "merge job:    " << scripts.mergeScript << "\n"
                      << "to run:       shards " << todo << "\n";
            if (!args.has("submit"))
            {
                std::cout << "submit:       the same command with --submit (or: sbatch --array=" << todo
                          << " " << scripts.arrayScript << "; sbatch --dependency=afterok:ARRAY_JOB_ID "
                          << "--kill-on-invalid-dep=yes " << scripts.mergeScript << ")\n";
                return 0;
            }
            // --status must see the same fingerprints (--runs, --seed, --time) and logs.
            std::string same;
            for (const auto &a : o.passThrough)
                same += " " + a;
            const bench::SlurmSubmission job = bench::submitSlurmJobs(scripts);
            std::cout << "array job id: "
                      << (job.arrayJob.empty() ? "none (every experiment is complete)" : job.arrayJob)
                      << "\nmerge job id: " << job.mergeJob << "\n"
                      << "status:       mhplan bench " << args.positional()[0] << same << " --status\n";
            return 0;
        }
    } // namespace

    const CommandDoc &benchDoc()
    {
        // One OptionDoc per option of the parser below (the tests check that they agree).
        static const CommandDoc doc{
            "bench CAMPAIGN [options]",
            "run a benchmark campaign (benchmarks/README.md): one log per experiment, then one OMPL "
            "benchmark "
            "database",
            "Every experiment runs in its own process and writes its OMPL log; complete logs are skipped, so "
            "an "
            "interrupted campaign resumes where it stopped. Shards split the experiments between machines; "
            "one final --merge-only builds the database from all logs. An OMPL.app problem file "
            "(PROBLEM.cfg, docs/omplapp.md) runs its own benchmark (its planners, parameters, run_count, "
            "time_limit, mem_limit, save_paths) in this process; it takes --runs, --time, --seed, "
            "--database, "
            "--logs, --no-progress and --validator certified|discrete.",
            {{"CAMPAIGN",
              "a campaign file (e.g. benchmarks/seeds.yaml), or an OMPL.app problem file (.cfg)"}},
            {{"--jobs", "N", "experiments run in parallel, 1..256 (default 1)"},
             {"--shard", "i/N",
              "run only the i-th of N shares of the experiments (writes logs, no database)"},
             {"--merge-only", "", "run nothing; build the database from the logs"},
             {"--no-merge", "", "run the experiments but do not build the database"},
             {"--list", "", "list the experiments (index, name, complete or to do, log file) and exit"},
             {"--database", "FILE",
              "the database to write (default: the campaign's; its logs then go to FILE.logs unless --logs)"},
             {"--logs", "DIR", "directory of the experiments' logs (default: the campaign's)"},
             {"--runs", "N", "runs per planner and experiment, 1..1000000 (default: the campaign's)"},
             {"--time", "S",
              "time limit per run in seconds, 0.001..1000000 (default: the campaign's); with --slurm, "
              "HH:MM:SS is the "
              "task's wall-time limit instead"},
             {"--seed", "N", "campaign seed, 1..4294967295 (default: the campaign's)"},
             {"--no-progress", "", "no progress bar on stderr"},
             {"--oversubscribe", "",
              "allow --jobs above the cores this process may use (time-limited runs then share cores)"},
             {"--status", "", "say which experiments are complete, missing, running or failed, and exit"},
             {"--slurm", "",
              "write an sbatch array job (task i runs --shard i/N) and a merge job after it (afterok)"},
             {"--shards", "N", "with --slurm: array tasks, one shard each (required)"},
             {"--partition", "P", "with --slurm: the Slurm partition"},
             {"--mem", "MB", "with --slurm: memory per task in MB, 1..100000000"},
             {"--cpus", "C", "with --slurm: CPUs per task; each task runs --jobs C (default 1)"},
             {"--submit", "", "with --slurm: submit both jobs with sbatch and print their ids"}},
            {"bench benchmarks/seeds.yaml --jobs 2",
             "bench benchmarks/seeds.yaml --runs 5 --time 0.2 --database /tmp/s.db",
             "bench benchmarks/scaling.yaml --shard 1/4 && mhplan bench benchmarks/scaling.yaml "
             "--merge-only",
             "bench benchmarks/seeds.yaml --slurm --shards 4 --cpus 2 --time 01:00:00 --submit",
             "bench environments/omplapp/bugtrap.cfg --runs 5 --database /tmp/bugtrap.db"},
            "0 every experiment completed, 1 bad input, 2 internal error, 3 some experiment failed, or "
            "(merging) the database lacks experiments of the campaign or a log was not taken"};
        return doc;
    }

    int cmdBench(const Argv &argv)
    {
        if (isCfgArgument(argv))
            return cmdBenchCfg(argv);
        const Args args("bench", argv,
                        {{"jobs", "shard", "database", "logs", "runs", "time", "seed",
                          // --slurm
                          "shards", "partition", "mem", "cpus"},
                         {},
                         {"merge-only", "no-merge", "no-progress", "list", "status", "oversubscribe", "slurm",
                          "submit"}});
        if (!args.has("slurm"))
            for (const char *name : {"shards", "partition", "mem", "cpus", "submit"})
                if (args.has(name))
                    throw InputError(std::string("mhplan bench: --") + name + " belongs to --slurm");
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
            for (auto &p : campaign.planners) // --runs overrides the planners' own counts too
                p.runs = 0;
        }
        if (args.has("slurm") && args.has("time") && !isClockTime(args.get("time")))
        {
            const std::string t = args.get("time");
            char *end = nullptr;
            std::strtod(t.c_str(), &end);
            if (t.empty() || end != t.c_str() + t.size())
                throw InputError(
                    "mhplan bench --slurm: --time expects Slurm's time format per task (HH:MM:SS, "
                    "D-HH:MM:SS) or seconds per run (a number), got '" +
                    t + "'");
        }
        if (args.has("time") && !(args.has("slurm") && isClockTime(args.get("time"))))
        {
            campaign.timeLimit = args.timeLimit(1.0);
        }
        if (args.has("seed"))
        {
            const long long seed = args.integer("seed", 1);
            if (seed < 1 || seed > 4294967295LL)
                throw InputError("mhplan bench: --seed must be in [1, 4294967295] (got " + args.get("seed") +
                                 ")");
            campaign.seed = static_cast<std::uint32_t>(seed);
        }

        if (args.has("status"))
            return printStatus(campaign, bench::enumerateExperiments(campaign, resolveWorldPath));
        // Output paths are checked before any experiment runs.
        if (!args.has("list") && !args.has("status"))
        {
            checkOutputDirectory("bench", "logs", campaign.logDir);
            checkOutputDirectory("bench", "database",
                                 std::filesystem::absolute(campaign.database).parent_path().string());
            if (std::filesystem::is_directory(campaign.database))
                throw InputError("mhplan bench: --database '" + campaign.database + "': is a directory");
        }
        if (args.has("slurm"))
            return slurmCampaign(args, campaign, bench::enumerateExperiments(campaign, resolveWorldPath));

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
        options.oversubscribe = args.has("oversubscribe");
        options.messages = &std::cerr;
        options.resolveWorld = resolveWorldPath;

        if (args.has("list"))
        {
            const auto all = bench::enumerateExperiments(campaign, options.resolveWorld);
            // Unsharded, the list is all of them (not copied: a world may have 10^5 queries).
            const auto shard = options.shardCount > 1
                                   ? bench::shardExperiments(all, options.shardIndex, options.shardCount)
                                   : std::vector<bench::Experiment>{};
            // The log directory is read once: only the logs in it are opened (not 10^5 missing files).
            std::set<std::string> present;
            bool listed = true; // else (a directory that cannot be listed) every log is opened
            std::error_code ec;
            if (std::filesystem::exists(campaign.logDir, ec))
            {
                for (std::filesystem::directory_iterator it(campaign.logDir, ec), end; !ec && it != end;
                     it.increment(ec))
                    present.insert(it->path().filename().string());
                listed = !ec;
            }
            for (const auto &e : options.shardCount > 1 ? shard : all)
            {
                const std::string log = bench::logFile(campaign, e);
                const bool complete =
                    (!listed || present.count(std::filesystem::path(log).filename().string()) != 0) &&
                    bench::logIsComplete(log, e.configHash);
                std::cout << e.index << "\t" << e.name << "\t" << (complete ? "complete" : "to do") << "\t"
                          << log << "\n";
            }
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
        std::cout << "wall time:   " << s.wallSeconds << " s (solve " << s.solveSeconds << " s wall, "
                  << s.cpuSeconds << " s CPU; experiment processes " << s.workerSeconds << " s, database "
                  << s.mergeSeconds << " s)\n";
        if (s.workerSeconds > 0.0)
            std::cout << "overhead:    " << std::setprecision(2) << 100.0 * s.overheadFraction()
                      << " % of the time outside the planners' solve calls\n";
        if (s.solveSeconds > 1.0 && s.cpuSeconds < 0.8 * s.solveSeconds)
            std::cout << "load:        the planners had " << std::setprecision(0)
                      << 100.0 * s.cpuSeconds / s.solveSeconds
                      << " % of a core while they planned (other load on the cores); time-limited planners "
                         "did that much less (time_limit_kind: cpu bounds CPU time instead)\n";
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
        return s.failed > 0 || s.missing > 0 || s.rejected > 0 ? 3 : 0;
    }
} // namespace mhplan::cli

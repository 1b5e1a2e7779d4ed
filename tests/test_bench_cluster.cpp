// SPDX-License-Identifier: BSD-3-Clause
/* Campaigns beyond one process: the cores a campaign may use (oversubscription refused or warned), the CPU
   time of every run, CPU-time limits, --status, and the Slurm batch scripts (their submission on a real
   cluster is tests/slurm/slurm_test.sh). */
#include "BenchSupport.h"
#include "CliSupport.h"

#include "benchmarks/Slurm.h"

#include <sched.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <thread>

namespace mhplan::test
{
    namespace
    {
        /** Sets an environment variable for one scope. */
        class ScopedEnv
        {
          public:
            ScopedEnv(const char *name, const char *value) : name_(name)
            {
                const char *old = std::getenv(name);
                had_ = old != nullptr;
                if (had_)
                    old_ = old;
                if (value)
                    ::setenv(name, value, 1);
                else
                    ::unsetenv(name);
            }
            ~ScopedEnv()
            {
                if (had_)
                    ::setenv(name_.c_str(), old_.c_str(), 1);
                else
                    ::unsetenv(name_.c_str());
            }

          private:
            std::string name_, old_;
            bool had_{false};
        };

        unsigned int affinityCount()
        {
            cpu_set_t set;
            CPU_ZERO(&set);
            EXPECT_EQ(::sched_getaffinity(0, sizeof(set), &set), 0);
            return static_cast<unsigned int>(CPU_COUNT(&set));
        }

        std::string readText(const std::string &file)
        {
            std::ifstream in(file);
            std::stringstream s;
            s << in.rdbuf();
            return s.str();
        }

        /** One world, RRT* alone (time-bounded), two runs. */
        Campaign rrtCampaign(const std::string &dir, const std::string &extra = "")
        {
            const std::string yaml =
                "campaign: cluster\ntime_limit: 0.2\nruns: 2\nseed: 5\nplanner_data: false\n" + extra +
                "worlds: [bfo_case1]\nplanners: [RRTstar]\n";
            Campaign c = parseCampaign(yaml, dir + "/cluster.yaml", testRegistry());
            c.database = dir + "/cluster.db";
            c.logDir = dir + "/logs";
            return c;
        }

        std::string freshDir(const std::string &name)
        {
            const std::string dir =
                (fs::temp_directory_path() / ("mhplan_cluster_" + name + "_" + std::to_string(::getpid())))
                    .string();
            fs::remove_all(dir);
            fs::create_directories(dir);
            return dir;
        }
    } // namespace

    TEST(Cores, AffinityOutsideSlurmAndTheAllocationInsideIt)
    {
        const ScopedEnv job("SLURM_JOB_ID", nullptr);
        EXPECT_EQ(availableCores(), affinityCount());
        {
            // In a Slurm task without CPU binding the affinity mask is the whole node: the allocation rules.
            const ScopedEnv id("SLURM_JOB_ID", "42");
            const ScopedEnv cpus("SLURM_CPUS_PER_TASK", "1");
            EXPECT_EQ(availableCores(), 1u);
        }
        {
            const ScopedEnv id("SLURM_JOB_ID", "42");
            const ScopedEnv cpus("SLURM_CPUS_PER_TASK", nullptr);
            const ScopedEnv node("SLURM_JOB_CPUS_PER_NODE", "1(x2)");
            EXPECT_EQ(availableCores(), 1u);
        }
        {
            // An allocation larger than the mask does not add cores.
            const ScopedEnv id("SLURM_JOB_ID", "42");
            const ScopedEnv cpus("SLURM_CPUS_PER_TASK", "512");
            EXPECT_EQ(availableCores(), affinityCount());
        }
    }

    TEST(Cores, OversubscriptionIsRefusedOrWarned)
    {
        EXPECT_NO_THROW(checkOversubscription(2, 2, false, nullptr));
        try
        {
            checkOversubscription(8, 2, false, nullptr);
            ADD_FAILURE() << "8 jobs on 2 cores accepted";
        }
        catch (const InputError &e)
        {
            const std::string what = e.what();
            EXPECT_NE(what.find("8 experiments at once"), std::string::npos) << what;
            EXPECT_NE(what.find("2 core(s)"), std::string::npos) << what;
            EXPECT_NE(what.find("25 % of a core"), std::string::npos) << what;
            EXPECT_NE(what.find("--oversubscribe"), std::string::npos) << what;
        }
        std::ostringstream warn;
        EXPECT_NO_THROW(checkOversubscription(8, 2, true, &warn));
        EXPECT_NE(warn.str().find("warning"), std::string::npos) << warn.str();
    }

    TEST(Cores, RunCampaignRefusesMoreJobsThanCoresBeforeAnyRun)
    {
        const std::string dir = freshDir("oversub");
        Campaign c = rrtCampaign(dir);
        // Two experiments (bfo_case1 has one query; add a second world) on one allocated core.
        c.worlds.push_back(c.worlds.front());
        c.worlds.back().world = "lrsma_scenario1";
        const ScopedEnv id("SLURM_JOB_ID", "42");
        const ScopedEnv cpus("SLURM_CPUS_PER_TASK", "1");
        ASSERT_EQ(availableCores(), 1u);
        RunOptions o = options(2);
        EXPECT_THROW(runCampaign(c, o), InputError);
        EXPECT_FALSE(fs::exists(c.database));
        EXPECT_FALSE(fs::exists(dir + "/logs/bfo_case1-default.log"));
        // One job is fine; so is --oversubscribe (with a warning).
        std::ostringstream messages;
        o.oversubscribe = true;
        o.messages = &messages;
        const CampaignSummary s = runCampaign(c, o);
        EXPECT_EQ(s.completed, 2u);
        EXPECT_NE(messages.str().find("warning: 2 experiments at once"), std::string::npos) << messages.str();
        fs::remove_all(dir);
    }

    TEST(CpuTime, EveryRunRecordsItsCpuTimeBesideItsWallTime)
    {
        const std::string dir = freshDir("cputime");
        const Campaign c = rrtCampaign(dir);
        const CampaignSummary s = runCampaign(c, options(1));
        ASSERT_EQ(s.completed, 1u);
        EXPECT_GT(s.cpuSeconds, 0.0);
        Sql db(c.database);
        const auto rows = db.rows("SELECT time, cpu_time FROM runs");
        ASSERT_EQ(rows.size(), 2u);
        for (const auto &r : rows)
        {
            const double wall = std::atof(r[0].c_str()), cpu = std::atof(r[1].c_str());
            ASSERT_NE(r[1], "NULL");
            // A single-threaded planner cannot use more CPU than wall time (plus OMPL's sampling thread).
            EXPECT_GT(cpu, 0.0);
            EXPECT_LE(cpu, 1.2 * wall + 0.01) << "wall " << wall;
        }
        fs::remove_all(dir);
    }

    TEST(CpuTime, CpuLimitsBoundCpuSecondsUnderLoad)
    {
        const std::string dir = freshDir("cpulimit");
        const Campaign c = rrtCampaign(dir, "time_limit_kind: cpu\n");
        ASSERT_TRUE(c.cpuTimeLimit);
        // The campaign's runs share one core with a busy thread of this process (the children inherit the
        // affinity): their wall time grows, their CPU budget does not.
        cpu_set_t old, one;
        ASSERT_EQ(::sched_getaffinity(0, sizeof(old), &old), 0);
        CPU_ZERO(&one);
        for (int i = 0; i < CPU_SETSIZE; ++i)
            if (CPU_ISSET(i, &old))
            {
                CPU_SET(i, &one);
                break;
            }
        ASSERT_EQ(::sched_setaffinity(0, sizeof(one), &one), 0);
        std::atomic<bool> stop{false};
        std::thread busy(
            [&]
            {
                ::sched_setaffinity(0, sizeof(one), &one);
                volatile unsigned long x = 0;
                while (!stop.load(std::memory_order_relaxed))
                    x = x + 1;
            });
        CampaignSummary s;
        try
        {
            s = runCampaign(c, options(1));
        }
        catch (...)
        {
            stop = true;
            busy.join();
            ::sched_setaffinity(0, sizeof(old), &old);
            throw;
        }
        stop = true;
        busy.join();
        ASSERT_EQ(::sched_setaffinity(0, sizeof(old), &old), 0);
        ASSERT_EQ(s.completed, 1u);
        Sql db(c.database);
        const auto rows = db.rows("SELECT time, cpu_time, status FROM runs");
        ASSERT_EQ(rows.size(), 2u);
        for (const auto &r : rows)
        {
            const double wall = std::atof(r[0].c_str()), cpu = std::atof(r[1].c_str());
            EXPECT_GE(cpu, 0.2 - 1e-3) << "stopped before its CPU budget";
            EXPECT_LE(cpu, 0.2 + 0.1) << "ran past its CPU budget";
            EXPECT_GE(wall, cpu - 1e-3);
            std::cout << "cpu-limited RRT* run beside a busy thread: cpu " << cpu << " s, wall " << wall
                      << " s\n";
        }
        // The kind of limit is part of the fingerprint (a wall-limited log is not reused).
        const auto wall = enumerateExperiments(rrtCampaign(dir), resolveShipped);
        const auto cpu = enumerateExperiments(c, resolveShipped);
        EXPECT_NE(wall.front().configHash, cpu.front().configHash);
        fs::remove_all(dir);
    }

    TEST(CpuTime, BadTimeLimitKindIsRefusedWithFileAndLine)
    {
        try
        {
            parseCampaign("campaign: x\ntime_limit_kind: process\nworlds: [bfo_case1]\nplanners: [RRTstar]\n",
                          "bad.yaml", testRegistry());
            ADD_FAILURE() << "accepted time_limit_kind: process";
        }
        catch (const InputError &e)
        {
            const std::string what = e.what();
            EXPECT_NE(what.find("bad.yaml:2"), std::string::npos) << what;
            EXPECT_NE(what.find("time_limit_kind"), std::string::npos) << what;
            EXPECT_NE(what.find("cpu"), std::string::npos) << what;
        }
    }

    TEST(Status, CompleteMissingFailedAndRunning)
    {
        const std::string dir = freshDir("status");
        Campaign c = rrtCampaign(dir);
        c.runs = 1;
        c.worlds.push_back(c.worlds.front());
        c.worlds.back().world = "lrsma_scenario1";
        const auto all = enumerateExperiments(c, resolveShipped);
        ASSERT_EQ(all.size(), 2u);
        std::string why;
        EXPECT_EQ(experimentState(c, all[0], why), ExperimentState::Missing);
        RunOptions o = options(1);
        o.shardIndex = 1;
        o.shardCount = 2;
        o.merge = false;
        runCampaign(c, o);
        EXPECT_EQ(experimentState(c, all[0], why), ExperimentState::Complete);
        EXPECT_FALSE(fs::exists(runningMarker(c, all[0]))) << "marker left after success";
        EXPECT_EQ(experimentState(c, all[1], why), ExperimentState::Missing);
        // The marker of an experiment process that died (killed with its campaign): failed.
        fs::create_directories(c.logDir);
        std::ofstream(runningMarker(c, all[1])) << currentHostName() << " 999999999\n";
        EXPECT_EQ(experimentState(c, all[1], why), ExperimentState::Failed);
        EXPECT_NE(why.find("killed"), std::string::npos) << why;
        // A live process on this host: running; a process on another host: running there (or interrupted).
        std::ofstream(runningMarker(c, all[1])) << currentHostName() << " " << ::getpid() << "\n";
        EXPECT_EQ(experimentState(c, all[1], why), ExperimentState::Running);
        std::ofstream(runningMarker(c, all[1])) << "elsewhere.example 12\n";
        EXPECT_EQ(experimentState(c, all[1], why), ExperimentState::Running);
        EXPECT_NE(why.find("elsewhere.example"), std::string::npos) << why;
        fs::remove(runningMarker(c, all[1]));
        std::ofstream(failedMarker(c, all[1])) << "exit code 4 on node7\n";
        EXPECT_EQ(experimentState(c, all[1], why), ExperimentState::Failed);
        EXPECT_EQ(why, "exit code 4 on node7");
        // Running the rest completes it and clears the failure.
        o.shardIndex = 2;
        runCampaign(c, o);
        EXPECT_EQ(experimentState(c, all[1], why), ExperimentState::Complete);
        EXPECT_FALSE(fs::exists(failedMarker(c, all[1])));
        fs::remove_all(dir);
    }

    TEST(Slurm, ScriptsRunTheShardsAndTheMerge)
    {
        const std::string dir = freshDir("slurm");
        Campaign c = rrtCampaign(dir);
        for (const char *w : {"bfo_case2", "lrsma_scenario1", "lrsma_scenario2", "lrsma_scenario3"})
        {
            c.worlds.push_back(c.worlds.front());
            c.worlds.back().world = w;
        }
        const auto all = enumerateExperiments(c, resolveShipped);
        ASSERT_EQ(all.size(), 5u);
        SlurmOptions o;
        o.shards = 3;
        o.cpus = 2;
        o.memoryMB = 2000;
        o.partition = "short";
        o.executable = "/opt/mhplan bin/mhplan";
        o.campaignFile = dir + "/cluster.yaml";
        o.workDir = dir;
        o.passThrough = {"--database", c.database, "--logs", c.logDir};
        SlurmScripts s = writeSlurmScripts(c, all, o);
        EXPECT_EQ(s.missingShards, "1-3");
        const std::string array = readText(s.arrayScript);
        for (const char *line :
             {"#SBATCH --array=1-3\n", "#SBATCH --cpus-per-task=2\n", "#SBATCH --mem=2000\n",
              "#SBATCH --partition=short\n", "--shard \"$SLURM_ARRAY_TASK_ID/3\" --jobs 2\n",
              "exec '/opt/mhplan bin/mhplan' bench "})
            EXPECT_NE(array.find(line), std::string::npos) << line << " not in\n" << array;
        const std::string merge = readText(s.mergeScript);
        EXPECT_NE(merge.find("--merge-only\n"), std::string::npos) << merge;
        EXPECT_EQ(merge.find("--shard"), std::string::npos) << merge;
        EXPECT_TRUE((fs::status(s.arrayScript).permissions() & fs::perms::owner_exec) != fs::perms::none);
        // 5 experiments x 2 runs x (0.2 + 1) s in the largest shard (2 experiments), doubled, on 2 CPUs,
        // + 10 min: 604.8 s -> 11 minutes.
        EXPECT_EQ(s.taskTime, "0-00:11:00");

        // Shard 2 (experiments 1 and 4) done: only shards 1 and 3 are left.
        RunOptions ro = options(1);
        ro.shardIndex = 2;
        ro.shardCount = 3;
        ro.merge = false;
        runCampaign(c, ro);
        s = writeSlurmScripts(c, all, o);
        EXPECT_EQ(s.missingShards, "1,3");
        fs::remove_all(dir);
    }

    TEST(Slurm, OptionsAndFormats)
    {
        EXPECT_EQ(arrayList({1, 2, 3, 5, 7, 8}), "1-3,5,7-8");
        EXPECT_EQ(arrayList({}), "");
        EXPECT_EQ(slurmTime(61), "0-00:02:00");
        EXPECT_EQ(slurmTime(90000), "1-01:00:00");
        SlurmOptions o;
        o.shards = 4;
        EXPECT_NO_THROW(checkSlurmOptions(o));
        for (const char *t : {"12:00:00", "30", "1-00:00:00", "05:00"})
        {
            o.timeLimit = t;
            EXPECT_NO_THROW(checkSlurmOptions(o)) << t;
        }
        for (const char *t : {"12::00", "1h", ":30", "1-", "1:2:3:4"})
        {
            o.timeLimit = t;
            EXPECT_THROW(checkSlurmOptions(o), InputError) << t;
        }
        o.timeLimit.clear();
        o.shards = 0;
        EXPECT_THROW(checkSlurmOptions(o), InputError);
        o.shards = 2;
        o.partition = "a b";
        EXPECT_THROW(checkSlurmOptions(o), InputError);
    }

    TEST(Slurm, SubmissionFailureNamesSbatchAndItsMessage)
    {
        const std::string dir = freshDir("sbatch");
        const Campaign c = rrtCampaign(dir);
        SlurmOptions o;
        o.shards = 1;
        o.executable = "/bin/true";
        o.campaignFile = dir + "/cluster.yaml";
        o.workDir = dir;
        const SlurmScripts s = writeSlurmScripts(c, enumerateExperiments(c, resolveShipped), o);
        // A stand-in sbatch that refuses, and one that prints job ids as sbatch --parsable does.
        const std::string refuse = dir + "/sbatch-refuses", accept = dir + "/sbatch-accepts";
        std::ofstream(refuse) << "#!/bin/sh\necho 'sbatch: error: invalid partition' >&2\nexit 1\n";
        std::ofstream(accept) << "#!/bin/sh\necho \"$*\" >> " << dir << "/calls\necho '77;cluster'\n";
        fs::permissions(refuse, fs::perms::owner_all);
        fs::permissions(accept, fs::perms::owner_all);
        try
        {
            submitSlurmJobs(s, refuse);
            ADD_FAILURE() << "a refused submission passed";
        }
        catch (const std::runtime_error &e)
        {
            EXPECT_NE(std::string(e.what()).find("invalid partition"), std::string::npos) << e.what();
        }
        const SlurmSubmission job = submitSlurmJobs(s, accept);
        EXPECT_EQ(job.arrayJob, "77");
        EXPECT_EQ(job.mergeJob, "77");
        const std::string calls = readText(dir + "/calls");
        EXPECT_NE(calls.find("--array=1 " + s.arrayScript), std::string::npos) << calls;
        EXPECT_NE(calls.find("--dependency=afterok:77 --kill-on-invalid-dep=yes " + s.mergeScript),
                  std::string::npos)
            << calls;
        EXPECT_NE(readText(s.directory + "/submitted").find("array 77 (shards 1)\tmerge 77"),
                  std::string::npos);
        fs::remove_all(dir);
    }

    TEST(SlurmCli, OptionsAreCheckedAndTheScriptsWrittenWithoutSubmitting)
    {
        const std::string dir = freshDir("slurmcli");
        const std::string campaign = std::string(MHPLAN_TEST_DATA_DIR) + "/bench_slurm.yaml";
        const std::string db = " --database " + dir + "/s.db";
        struct Refused
        {
            std::string args, message;
        };
        for (const Refused &r : std::vector<Refused>{
                 {" --shards 4", "--shards belongs to --slurm"},
                 {" --submit", "--submit belongs to --slurm"},
                 {" --slurm", "--shards N is required"},
                 {" --slurm --shards 0", "--shards must be in [1, 10000]"},
                 {" --slurm --shards 4 --time 1h", "--time expects Slurm's time format"},
                 {" --slurm --shards 4 --mem 0", "--mem must be in"},
                 {" --slurm --shards 4 --jobs 2", "--jobs is set per task"},
             })
        {
            const CliResult res = runCli("bench " + campaign + db + r.args);
            EXPECT_NE(res.code, 0) << r.args;
            EXPECT_TRUE(contains(res.out, r.message)) << r.args << ":\n" << res.out;
        }
        // A per-run --time (seconds) is passed on to the tasks; a Slurm --time is the task limit.
        CliResult res = runCli("bench " + campaign + db + " --slurm --shards 4 --time 0.1 --runs 2");
        ASSERT_EQ(res.code, 0) << res.out;
        EXPECT_TRUE(contains(res.out, "to run:       shards 1-4")) << res.out;
        std::string array = readText(dir + "/s.db.logs/slurm/array.sbatch");
        EXPECT_TRUE(contains(array, "'--runs' '2' '--time' '0.1'")) << array;
        res = runCli("bench " + campaign + db + " --slurm --shards 4 --time 1-00:00:00 --partition long");
        ASSERT_EQ(res.code, 0) << res.out;
        array = readText(dir + "/s.db.logs/slurm/array.sbatch");
        EXPECT_TRUE(contains(array, "#SBATCH --time=1-00:00:00\n")) << array;
        EXPECT_TRUE(contains(array, "#SBATCH --partition=long\n")) << array;
        EXPECT_FALSE(contains(array, "'--time'")) << array;
        EXPECT_FALSE(fs::exists(dir + "/s.db.logs/slurm/submitted")) << "submitted without --submit";
        // --status of a campaign nothing ran of: every experiment missing, exit code 1.
        res = runCli("bench " + campaign + db + " --status");
        EXPECT_EQ(res.code, 1) << res.out;
        EXPECT_TRUE(contains(res.out, "8 experiments, 0 complete, 8 missing, 0 failed, 0 running"))
            << res.out;
        fs::remove_all(dir);
    }
} // namespace mhplan::test

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench --slurm: the batch scripts of a campaign's array and merge jobs, and their submission. */
#include "benchmarks/Slurm.h"

#include "src/base/World.h"
#include "benchmarks/CampaignRunner.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace mhplan::bench
{
    namespace
    {
        /** \e s as one word for sh. */
        std::string shellQuote(const std::string &s)
        {
            std::string out = "'";
            for (const char ch : s)
                out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
            return out + "'";
        }

        /** Slurm accepts MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS. */
        bool isSlurmTime(const std::string &t)
        {
            if (t.empty() || t.size() > 16 || t.find_first_not_of("0123456789:-") != std::string::npos)
                return false;
            const std::size_t dash = t.find('-');
            if (dash != t.rfind('-') || dash == 0 || dash + 1 == t.size())
                return false;
            const std::string clock = dash == std::string::npos ? t : t.substr(dash + 1);
            std::size_t fields = 1;
            for (std::size_t i = 0; i < clock.size(); ++i)
                if (clock[i] == ':')
                {
                    if (i == 0 || i + 1 == clock.size() || clock[i + 1] == ':')
                        return false;
                    ++fields;
                }
            return fields <= 3;
        }

        void writeScript(const std::string &file, const std::string &text)
        {
            const std::string tmp = temporaryFile(file);
            {
                std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
                out << text;
                out.close();
                if (!out)
                    throw InputError("cannot write '" + tmp + "': " + std::strerror(errno ? errno : EIO));
            }
            fs::permissions(tmp, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
            fs::rename(tmp, file);
        }

        /** Run \e argv, return its exit status and what it wrote (stdout and stderr). */
        int runCommand(const std::vector<std::string> &argv, std::string &output)
        {
            int fds[2];
            if (::pipe(fds) != 0)
                throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
            const pid_t pid = ::fork();
            if (pid < 0)
                throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
            if (pid == 0)
            {
                ::dup2(fds[1], 1);
                ::dup2(fds[1], 2);
                ::close(fds[0]);
                ::close(fds[1]);
                std::vector<char *> args;
                for (const auto &a : argv)
                    args.push_back(const_cast<char *>(a.c_str()));
                args.push_back(nullptr);
                ::execvp(args[0], args.data());
                std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
                ::_exit(127);
            }
            ::close(fds[1]);
            char buf[4096];
            ssize_t n;
            while ((n = ::read(fds[0], buf, sizeof(buf))) > 0 || (n < 0 && errno == EINTR))
                if (n > 0)
                    output.append(buf, static_cast<std::size_t>(n));
            ::close(fds[0]);
            int status = 0;
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
            {
            }
            return status;
        }

        /** sbatch --parsable prints "JOBID" or "JOBID;CLUSTER". */
        std::string submit(const std::vector<std::string> &argv)
        {
            std::string out;
            const int status = runCommand(argv, out);
            std::string id = out.substr(0, out.find_first_of(";\n"));
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || id.empty() ||
                id.find_first_not_of("0123456789") != std::string::npos)
            {
                std::string cmd;
                for (const auto &a : argv)
                    cmd += (cmd.empty() ? "" : " ") + a;
                throw std::runtime_error("'" + cmd + "' failed: " + out);
            }
            return id;
        }
    } // namespace

    void checkSlurmOptions(const SlurmOptions &o)
    {
        if (o.shards < 1 || o.shards > 10000)
            throw InputError("mhplan bench --slurm: --shards must be in [1, 10000] (got " +
                             std::to_string(o.shards) + ")");
        if (o.cpus < 1 || o.cpus > 256)
            throw InputError("mhplan bench --slurm: --cpus must be in [1, 256] (got " +
                             std::to_string(o.cpus) + ")");
        if (!o.timeLimit.empty() && !isSlurmTime(o.timeLimit))
            throw InputError("mhplan bench --slurm: --time expects Slurm's time format per task (HH:MM:SS, "
                             "MM:SS, D-HH:MM:SS; got '" +
                             o.timeLimit + "')");
        if (o.partition.find_first_of(" \t\n'\"\\") != std::string::npos)
            throw InputError("mhplan bench --slurm: --partition must be one name (got '" + o.partition +
                             "')");
    }

    std::string slurmTime(double seconds)
    {
        long long minutes = static_cast<long long>(std::ceil(std::max(seconds, 60.0) / 60.0));
        const long long days = minutes / (24 * 60);
        minutes -= days * 24 * 60;
        char buf[48];
        std::snprintf(buf, sizeof(buf), "%lld-%02lld:%02lld:00", days, minutes / 60, minutes % 60);
        return buf;
    }

    double estimateTaskSeconds(const Campaign &c, const std::vector<Experiment> &all, const SlurmOptions &o)
    {
        std::vector<double> perShard(o.shards, 0.0);
        for (const auto &e : all)
        {
            const std::size_t configs = e.simulation == Experiment::kNoSimulation
                                            ? c.planners.size()
                                            : c.simulations[e.simulation].controllers.size();
            const double perRun = e.simulation == Experiment::kNoSimulation
                                      ? c.timeLimit + 1.0
                                      : std::min(c.simulations[e.simulation].wallLimit, 60.0);
            perShard[e.index % o.shards] += static_cast<double>(configs * e.runs) * perRun;
        }
        const double worst = *std::max_element(perShard.begin(), perShard.end());
        return 2.0 * worst / o.cpus + 600.0;
    }

    std::string arrayList(const std::vector<unsigned int> &shards)
    {
        std::string out;
        for (std::size_t i = 0; i < shards.size();)
        {
            std::size_t j = i;
            while (j + 1 < shards.size() && shards[j + 1] == shards[j] + 1)
                ++j;
            out += (out.empty() ? "" : ",") + std::to_string(shards[i]);
            if (j > i)
                out += "-" + std::to_string(shards[j]);
            i = j + 1;
        }
        return out;
    }

    SlurmScripts writeSlurmScripts(const Campaign &c, const std::vector<Experiment> &all,
                                   const SlurmOptions &o)
    {
        checkSlurmOptions(o);
        SlurmScripts s;
        s.directory = (fs::absolute(c.logDir) / "slurm").lexically_normal().string();
        std::error_code ec;
        fs::create_directories(s.directory, ec);
        if (ec)
            throw InputError("cannot create '" + s.directory + "': " + ec.message());
        s.arrayScript = s.directory + "/array.sbatch";
        s.mergeScript = s.directory + "/merge.sbatch";
        s.taskTime = o.timeLimit.empty() ? slurmTime(estimateTaskSeconds(c, all, o)) : o.timeLimit;

        std::vector<bool> missing(o.shards, false);
        for (const auto &e : all)
            if (!logIsComplete(logFile(c, e), e.configHash))
                missing[e.index % o.shards] = true;
        std::vector<unsigned int> todo;
        for (unsigned int i = 0; i < o.shards; ++i)
            if (missing[i])
                todo.push_back(i + 1);
        s.missingShards = arrayList(todo);

        std::string command = shellQuote(o.executable) + " bench " + shellQuote(o.campaignFile);
        for (const auto &a : o.passThrough)
            command += " " + shellQuote(a);
        command += " --no-progress";
        const std::string name = "mhplan-" + safeFileStem(c.name);
        std::ostringstream head;
        head << "#!/bin/sh\n"
             << "# Written by mhplan bench --slurm for campaign " << c.name << " (" << all.size()
             << " experiments).\n";
        const auto common = [&](std::ostream &out)
        {
            if (!o.partition.empty())
                out << "#SBATCH --partition=" << o.partition << "\n";
            if (o.memoryMB > 0)
                out << "#SBATCH --mem=" << o.memoryMB << "\n";
        };

        std::ostringstream array;
        array << head.str() << "# Task i runs shard i/" << o.shards
              << " into the shared log directory; resubmit with mhplan bench --slurm --submit.\n"
              << "#SBATCH --job-name=" << name << "\n"
              << "#SBATCH --array=1-" << o.shards << "\n"
              << "#SBATCH --ntasks=1\n"
              << "#SBATCH --cpus-per-task=" << o.cpus << "\n"
              << "#SBATCH --time=" << s.taskTime << "\n"
              << "#SBATCH --output=" << s.directory << "/task-%A_%a.out\n";
        common(array);
        array << "cd " << shellQuote(o.workDir) << " || exit 1\n"
              << "exec " << command << " --shard \"$SLURM_ARRAY_TASK_ID/" << o.shards << "\" --jobs "
              << o.cpus << "\n";
        writeScript(s.arrayScript, array.str());

        std::ostringstream merge;
        merge << head.str() << "# Builds the database from every complete log once the array succeeded.\n"
              << "#SBATCH --job-name=" << name << "-merge\n"
              << "#SBATCH --ntasks=1\n"
              << "#SBATCH --cpus-per-task=1\n"
              << "#SBATCH --time=" << slurmTime(600.0 + 0.2 * static_cast<double>(all.size())) << "\n"
              << "#SBATCH --output=" << s.directory << "/merge-%j.out\n";
        common(merge);
        merge << "cd " << shellQuote(o.workDir) << " || exit 1\n"
              << "exec " << command << " --merge-only\n";
        writeScript(s.mergeScript, merge.str());
        return s;
    }

    SlurmSubmission submitSlurmJobs(const SlurmScripts &s, const std::string &sbatch)
    {
        SlurmSubmission out;
        if (!s.missingShards.empty())
            out.arrayJob = submit({sbatch, "--parsable", "--array=" + s.missingShards, s.arrayScript});
        std::vector<std::string> merge{sbatch, "--parsable"};
        if (!out.arrayJob.empty())
        {
            // Slurm cancels the merge when a task fails, instead of leaving it pending for ever.
            merge.push_back("--dependency=afterok:" + out.arrayJob);
            merge.push_back("--kill-on-invalid-dep=yes");
        }
        merge.push_back(s.mergeScript);
        out.mergeJob = submit(merge);
        std::ofstream record(s.directory + "/submitted", std::ios::app);
        const std::time_t now = std::time(nullptr);
        char when[32];
        std::strftime(when, sizeof(when), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
        record << when << "\tarray " << (out.arrayJob.empty() ? "-" : out.arrayJob) << " (shards "
               << (s.missingShards.empty() ? "none" : s.missingShards) << ")\tmerge " << out.mergeJob << "\n";
        return out;
    }
} // namespace mhplan::bench

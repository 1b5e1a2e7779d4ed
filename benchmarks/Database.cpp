// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: the SQLite wrapper and the merge of a campaign's logs into its database. The merge is
   atomic: it builds the new database in a work file next to the target (a copy of the existing database),
   appends the logs there with ompl_benchmark_statistics, records them in mhplan_logs in the same file and
   only then renames the work file over the target. A merge killed at any moment leaves the old database
   as it was, and the next merge appends exactly what is missing. */
#include "benchmarks/Database.h"

#include "benchmarks/CampaignRunner.h"
#include "benchmarks/ChildProcess.h"
#include "benchmarks/ExperimentRuns.h"
#include "benchmarks/Improvements.h"
#include "src/io/InputFile.h"

#include <sqlite3.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace mhplan::bench
{
    namespace detail
    {
        Database::Database(const std::string &file)
        {
            if (sqlite3_open(file.c_str(), &db_) != SQLITE_OK)
            {
                const std::string err = db_ ? sqlite3_errmsg(db_) : "out of memory";
                sqlite3_close(db_);
                throw std::runtime_error("cannot open database '" + file + "': " + err);
            }
            sqlite3_busy_timeout(db_, 10000);
            exec("PRAGMA foreign_keys = ON");
        }

        Database::~Database()
        {
            sqlite3_close(db_);
        }

        void Database::exec(const std::string &sql)
        {
            char *err = nullptr;
            if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK)
            {
                const std::string e = err ? err : "?";
                sqlite3_free(err);
                throw std::runtime_error("database: " + e + " in: " + sql);
            }
        }

        bool Database::hasTable(const std::string &name)
        {
            Statement st(*this, "SELECT count(*) FROM sqlite_master WHERE type='table' AND name=?");
            st.bind(1, name);
            return st.step() && st.integer(0) > 0;
        }

        Database::Statement::Statement(Database &db, const std::string &sql) : db_(db)
        {
            if (sqlite3_prepare_v2(db.db_, sql.c_str(), -1, &st_, nullptr) != SQLITE_OK)
                throw std::runtime_error("database: " + std::string(sqlite3_errmsg(db.db_)) + " in: " + sql);
        }

        Database::Statement::~Statement()
        {
            sqlite3_finalize(st_);
        }

        void Database::Statement::bind(int i, const std::string &v)
        {
            sqlite3_bind_text(st_, i, v.c_str(), -1, SQLITE_TRANSIENT);
        }

        void Database::Statement::bind(int i, long long v)
        {
            sqlite3_bind_int64(st_, i, v);
        }

        void Database::Statement::bind(int i, double v)
        {
            sqlite3_bind_double(st_, i, v);
        }

        bool Database::Statement::step()
        {
            const int rc = sqlite3_step(st_);
            if (rc == SQLITE_ROW)
                return true;
            if (rc != SQLITE_DONE)
                throw std::runtime_error("database: " + std::string(sqlite3_errmsg(db_.db_)));
            return false;
        }

        void Database::Statement::reset()
        {
            sqlite3_reset(st_);
            sqlite3_clear_bindings(st_);
        }

        long long Database::Statement::integer(int col)
        {
            return sqlite3_column_int64(st_, col);
        }

        std::string Database::Statement::text(int col)
        {
            const auto *t = sqlite3_column_text(st_, col);
            return t ? reinterpret_cast<const char *>(t) : "";
        }
    } // namespace detail

    namespace
    {
        using detail::Database;

        /** Run a program with arguments; its standard output goes to \e outputFile. Returns the exit code. */
        int runProgram(const std::vector<std::string> &argv, const std::string &outputFile)
        {
            std::cout.flush();
            std::cerr.flush();
            const pid_t pid = ::fork();
            if (pid < 0)
                throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
            if (pid == 0)
            {
                const int fd = ::open(outputFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
                if (fd >= 0)
                {
                    ::dup2(fd, 1);
                    ::dup2(fd, 2);
                    ::close(fd);
                }
                std::vector<char *> args;
                for (const auto &a : argv)
                    args.push_back(const_cast<char *>(a.c_str()));
                args.push_back(nullptr);
                ::execv(args[0], args.data());
                ::_exit(127);
            }
            int status = 0;
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
            {
            }
            return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        }

        std::string readAll(const std::string &file)
        {
            std::ifstream in(file);
            std::ostringstream ss;
            ss << in.rdbuf();
            return ss.str();
        }

        std::string errnoText(const std::string &what, const std::string &file)
        {
            return what + " '" + file + "': " + std::strerror(errno);
        }

        /** The work file of a merge, locked (flock) against other merges into the same database. It keeps
            its name while it is locked: a merge that renamed it over the target leaves its waiters the old
            inode, and they open the name again. */
        class WorkFile
        {
          public:
            explicit WorkFile(std::string name) : name_(std::move(name))
            {
                while (true)
                {
                    // Not close-on-exec: ompl_benchmark_statistics inherits the descriptor, so that the lock
                    // is held until it ends even when this process is killed alone.
                    fd_ = ::open(name_.c_str(), O_RDWR | O_CREAT, 0644);
                    if (fd_ < 0)
                        throw std::runtime_error(errnoText("cannot create the database work file", name_));
                    while (::flock(fd_, LOCK_EX) < 0 && errno == EINTR)
                    {
                    }
                    struct stat held
                    {
                    }, named{};
                    if (::fstat(fd_, &held) == 0 && ::stat(name_.c_str(), &named) == 0 &&
                        held.st_dev == named.st_dev && held.st_ino == named.st_ino)
                        break;
                    ::close(fd_);
                }
                // Journals of a merge killed earlier must not be rolled back into the fresh copy.
                for (const char *suffix : {"-journal", "-wal", "-shm"})
                    ::unlink((name_ + suffix).c_str());
            }
            ~WorkFile()
            {
                if (!committed_)
                    ::unlink(name_.c_str());
                ::close(fd_); // releases the lock
            }
            WorkFile(const WorkFile &) = delete;
            WorkFile &operator=(const WorkFile &) = delete;

            const std::string &name() const { return name_; }

            /** Make the work file a copy of \e source (empty when \e source does not exist). */
            void copyFrom(const std::string &source)
            {
                if (::ftruncate(fd_, 0) != 0)
                    throw std::runtime_error(errnoText("cannot write", name_));
                const int in = ::open(source.c_str(), O_RDONLY | O_CLOEXEC);
                if (in < 0)
                {
                    if (errno == ENOENT)
                        return;
                    throw std::runtime_error(errnoText("cannot read the database", source));
                }
                char buf[1 << 16];
                off_t at = 0;
                while (true)
                {
                    const ssize_t n = ::read(in, buf, sizeof(buf));
                    if (n < 0 && errno == EINTR)
                        continue;
                    if (n < 0)
                    {
                        ::close(in);
                        throw std::runtime_error(errnoText("cannot read the database", source));
                    }
                    if (n == 0)
                        break;
                    for (ssize_t done = 0; done < n;)
                    {
                        const ssize_t w = ::pwrite(fd_, buf + done, static_cast<std::size_t>(n - done), at);
                        if (w < 0 && errno == EINTR)
                            continue;
                        if (w <= 0)
                        {
                            ::close(in);
                            throw std::runtime_error(errnoText("cannot write", name_));
                        }
                        done += w;
                        at += w;
                    }
                }
                ::close(in);
            }

            /** Flush the work file to disk and make it \e target: renamed over it, with the target's
                permissions; a target with other hard links is updated in place instead (SQLite's backup
                into it, atomic through the target's own journal), so that every link sees the new
                database. */
            void commit(const std::string &target)
            {
                if (::fsync(fd_) != 0)
                    throw std::runtime_error(errnoText("cannot write", name_));
                struct stat st
                {
                };
                if (::stat(target.c_str(), &st) == 0)
                {
                    if (st.st_nlink > 1)
                    {
                        Database to(target), from(name_);
                        sqlite3_backup *b = sqlite3_backup_init(to.handle(), "main", from.handle(), "main");
                        if (!b)
                            throw std::runtime_error("cannot update the database '" + target +
                                                     "': " + sqlite3_errmsg(to.handle()));
                        const int rc = sqlite3_backup_step(b, -1);
                        sqlite3_backup_finish(b);
                        if (rc != SQLITE_DONE)
                            throw std::runtime_error("cannot update the database '" + target +
                                                     "': " + sqlite3_errstr(rc));
                        return; // the work file is removed by the destructor
                    }
                    if (::fchmod(fd_, st.st_mode & 07777) != 0 ||
                        (::fchown(fd_, st.st_uid, st.st_gid) != 0 && errno != EPERM))
                        throw std::runtime_error(errnoText("cannot set the permissions of", name_));
                }
                if (::rename(name_.c_str(), target.c_str()) != 0)
                    throw std::runtime_error(errnoText("cannot replace the database", target));
                committed_ = true;
            }

          private:
            std::string name_;
            int fd_{-1};
            bool committed_{false};
        };
    } // namespace

    void detail::checkDatabaseFile(const std::string &file)
    {
        std::error_code ec;
        if (!fs::exists(fs::symlink_status(file, ec)) && !fs::is_symlink(file, ec))
            return; // made by the merge
        struct stat st
        {
        };
        if (::stat(file.c_str(), &st) != 0 && errno == ENOENT)
            return; // a link to a file the merge will create
        if (::stat(file.c_str(), &st) != 0)
            throw InputError("the database '" + file + "': " +
                             (errno == ELOOP ? std::string("too many levels of symbolic links (a loop?)")
                                             : std::string(std::strerror(errno))));
        if (S_ISDIR(st.st_mode))
            throw InputError("the database '" + file + "' is a directory");
        if (!S_ISREG(st.st_mode))
            throw InputError("the database '" + file + "' is not a regular file (a FIFO, a device)");
        if (st.st_size == 0)
            return; // an empty file is an empty SQLite database
        char magic[16] = {};
        {
            std::ifstream in(file, std::ios::binary);
            if (!in.read(magic, sizeof magic) || std::memcmp(magic, "SQLite format 3", 16) != 0)
                throw InputError(
                    "the database '" + file +
                    "' is not an SQLite database (choose another --database, or move the file away)");
        }
        std::string verdict;
        try
        {
            Database db(file);
            Database::Statement st2(db, "PRAGMA quick_check");
            if (st2.step())
                verdict = st2.text(0);
        }
        catch (const std::runtime_error &e)
        {
            verdict = e.what();
        }
        if (verdict != "ok")
            throw InputError("the database '" + file + "' is damaged (" + verdict +
                             "); restore it or move it away before merging into it");
    }

    namespace
    {
        /** The value of experiment property \e name in the head of log text \e log ("" when absent). */
        std::string logProperty(const std::string &log, const std::string &name)
        {
            const std::string key = "\n" + name + " TEXT = ";
            const std::size_t at = log.find(key);
            if (at == std::string::npos)
                return "";
            const std::size_t from = at + key.size();
            return log.substr(from, log.find('\n', from) - from);
        }

        /** The bytes of \e file, or "" when it does not exist (an absent side file is an empty one). */
        std::string readSideFile(const std::string &file)
        {
            std::error_code ec;
            if (!fs::exists(file, ec))
                return "";
            return readInputFile(file, std::size_t{1} << 31, "side file");
        }

        /** The file the database name stands for: a symbolic link's target (the link is kept, the file it
            points to is updated). */
        std::string realDatabase(const std::string &target)
        {
            std::error_code ec;
            if (!fs::is_symlink(target, ec))
                return target;
            const fs::path real = fs::weakly_canonical(target, ec);
            return ec ? target : real.string();
        }
    } // namespace

    /** Append the complete logs of \e experiments to the database \e target (static: this file's own). A log
        is identified by its experiment (campaign and name) and its content fingerprint, not by where it
        lies: the same log merged again from a moved or copied folder is recognised, a re-run replaces the
        old rows. A log is taken only together with its side files (their fingerprints are in the log) and
        only while the world or scenario file is still the one the campaign fingerprinted; \e problems
        receives why a log was not taken. */
    static std::size_t mergeInto(const std::string &databaseName, const Campaign &campaign,
                                 const std::vector<Experiment> &experiments,
                                 const std::string &statisticsTool, std::vector<std::string> &problems)
    {
        struct Pending
        {
            const Experiment *experiment;
            std::string log;     // the log's bytes, checked
            std::string content; // their fingerprint
            std::string paths;   // the side files' bytes, checked against the log
            std::string improvements;
        };
        const std::string target = realDatabase(databaseName);
        const fs::path dbPath(target);
        if (dbPath.has_parent_path())
            fs::create_directories(dbPath.parent_path());
        // A hot journal of the target (a database written in place by an older mhplan and killed) is
        // rolled back by opening it once; the copy below is then a consistent database.
        if (fs::exists(target + "-journal"))
            Database(target).hasTable("experiments");
        WorkFile work(target + ".merging");
        work.copyFrom(target);

        // The input files as they are now (each read once), against the campaign's fingerprints.
        std::map<std::string, std::string> inputNow;
        const auto inputChanged = [&](const Experiment &e)
        {
            const std::string &file =
                e.simulation == Experiment::kNoSimulation ? e.worldFile : e.scenarioFile;
            if (e.inputHash.empty() || file.empty())
                return false;
            auto it = inputNow.find(file);
            if (it == inputNow.end())
            {
                it = inputNow.emplace(file, inputFingerprint(e)).first; // a .cfg: with its meshes
            }
            return it->second != e.inputHash;
        };

        std::vector<Pending> pending;
        long long maxBefore = 0;
        {
            Database db(work.name());
            db.exec("CREATE TABLE IF NOT EXISTS mhplan_logs (file TEXT PRIMARY KEY, experiment TEXT, "
                    "experimentid INTEGER, log_fingerprint TEXT, merged DATETIME)");
            bool haveCampaign = false;
            {
                Database::Statement cols(db, "SELECT name FROM pragma_table_info('mhplan_logs')");
                while (cols.step())
                    haveCampaign = haveCampaign || cols.text(0) == "campaign";
            }
            if (!haveCampaign)
                db.exec("ALTER TABLE mhplan_logs ADD COLUMN campaign TEXT");
            // Merged before: experiment -> (campaign or "" for rows of older versions, fingerprint, id).
            struct Merged
            {
                std::string campaign, content;
                long long id;
            };
            std::multimap<std::string, Merged> merged;
            {
                Database::Statement st(db, "SELECT experiment, coalesce(campaign, ''), log_fingerprint, "
                                           "experimentid FROM mhplan_logs");
                while (st.step())
                    merged.emplace(st.text(0), Merged{st.text(1), st.text(2), st.integer(3)});
            }
            const bool haveExperiments = db.hasTable("experiments");
            for (const auto &e : experiments)
            {
                const std::string log = logFile(campaign, e);
                if (!logIsComplete(log, e.configHash))
                    continue;
                if (inputChanged(e))
                {
                    problems.push_back(
                        "experiment " + e.name + ": '" +
                        (e.simulation == Experiment::kNoSimulation ? e.worldFile : e.scenarioFile) +
                        "' changed since the campaign started; its log is not merged (re-run "
                        "the campaign)");
                    continue;
                }
                Pending p{&e, readSideFile(log), "", "", ""};
                p.content = fingerprint(p.log);
                bool same = false;
                std::vector<long long> replaced;
                const auto range = merged.equal_range(e.name);
                for (auto it = range.first; it != range.second; ++it)
                    if (it->second.campaign.empty() || it->second.campaign == campaign.name)
                    {
                        if (it->second.content == p.content)
                            same = true;
                        else
                            replaced.push_back(it->second.id);
                    }
                if (same)
                    continue;
                // The side files, taken with the log or not at all.
                p.paths = readSideFile(pathsFile(campaign, e));
                p.improvements = readSideFile(improvementsFile(campaign, e));
                const std::string expected = logProperty(p.log, detail::kSidecarsProperty);
                const std::string found = fingerprint(p.paths) + "/" + fingerprint(p.improvements);
                if (!expected.empty() && expected != found)
                {
                    // Truncated or edited: this log cannot be trusted with them. Set it aside so that the
                    // next run of the campaign runs the experiment again.
                    const std::string aside = log + ".rejected";
                    std::error_code ec;
                    fs::rename(log, aside, ec);
                    problems.push_back("experiment " + e.name + ": its side files (" +
                                       pathsFile(campaign, e) + ", " + improvementsFile(campaign, e) +
                                       ") are not those its log was written with (truncated or edited); "
                                       "the log is set aside as " +
                                       aside + " and the experiment runs again with the next 'mhplan bench'");
                    continue;
                }
                if (haveExperiments)
                    for (long long id : replaced)
                    {
                        // The experiment was re-run (another configuration, or again): replace its old rows.
                        Database::Statement del(db, "DELETE FROM experiments WHERE id = ?");
                        del.bind(1, id);
                        del.step();
                        Database::Statement del2(db, "DELETE FROM mhplan_logs WHERE experimentid = ?");
                        del2.bind(1, id);
                        del2.step();
                    }
                pending.push_back(std::move(p));
            }
            if (haveExperiments)
            {
                Database::Statement st(db, "SELECT coalesce(max(id), 0) FROM experiments");
                if (st.step())
                    maxBefore = st.integer(0);
            }
        }
        if (pending.empty())
        {
            // Nothing to append: a new database is still created (with its mhplan_logs table).
            if (!fs::exists(target))
                work.commit(target);
            return 0;
        }

        // ompl_benchmark_statistics reads exactly the bytes that were checked: private copies of the logs.
        const fs::path copies = work.name() + ".logs";
        std::error_code ec;
        fs::remove_all(copies, ec);
        fs::create_directories(copies);
        std::vector<std::string> argv{statisticsTool, "-a", "-d", work.name()};
        for (std::size_t i = 0; i < pending.size(); ++i)
        {
            const std::string copy = (copies / (std::to_string(i) + ".log")).string();
            std::ofstream out(copy, std::ios::binary | std::ios::trunc);
            out << pending[i].log;
            out.close();
            if (!out)
                throw std::runtime_error(errnoText("cannot write", copy));
            argv.push_back(copy);
        }
        const std::string output = target + ".merge-output.txt";
        const int rc = runProgram(argv, output);
        fs::remove_all(copies, ec);
        if (rc != 0)
            throw std::runtime_error(statisticsTool + " failed with exit code " + std::to_string(rc) + ":\n" +
                                     readAll(output));
        fs::remove(output);

        {
            Database db(work.name());
            db.exec("BEGIN");
            db.exec("CREATE TABLE IF NOT EXISTS paths (runid INTEGER PRIMARY KEY, points TEXT, "
                    "FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE)");
            std::vector<long long> ids;
            {
                Database::Statement st(db, "SELECT id FROM experiments WHERE id > ? ORDER BY id");
                st.bind(1, maxBefore);
                while (st.step())
                    ids.push_back(st.integer(0));
            }
            if (ids.size() != pending.size())
                throw std::runtime_error(
                    "database '" + target + "': expected " + std::to_string(pending.size()) +
                    " new experiments after the merge, found " + std::to_string(ids.size()));
            Database::Statement record(
                db, "INSERT OR REPLACE INTO mhplan_logs (file, experiment, experimentid, log_fingerprint, "
                    "merged, campaign) VALUES (?, ?, ?, ?, datetime('now'), ?)");
            Database::Statement findRun(
                db, "SELECT runs.id FROM runs JOIN plannerConfigs ON runs.plannerid = "
                    "plannerConfigs.id WHERE runs.experimentid = ? AND plannerConfigs.name = ? "
                    "AND runs.run_index = ?");
            Database::Statement insertPath(db, "INSERT OR REPLACE INTO paths VALUES (?, ?)");
            for (std::size_t i = 0; i < pending.size(); ++i)
            {
                const Experiment &e = *pending[i].experiment;
                // Where the log was when it was merged (for people; the identity is experiment + content).
                record.bind(1, fs::absolute(logFile(campaign, e)).lexically_normal().string());
                record.bind(2, e.name);
                record.bind(3, ids[i]);
                record.bind(4, pending[i].content);
                record.bind(5, campaign.name);
                record.step();
                record.reset();
                std::istringstream in(pending[i].paths);
                std::string line;
                while (std::getline(in, line))
                {
                    if (line.empty() || line[0] == '#')
                        continue;
                    const std::vector<std::string> cols = detail::splitOn(line, '\t');
                    if (cols.size() != 3)
                        continue;
                    findRun.bind(1, ids[i]);
                    findRun.bind(2, cols[0]);
                    findRun.bind(3, std::atoll(cols[1].c_str()));
                    const bool found = findRun.step();
                    const long long runId = found ? findRun.integer(0) : -1;
                    findRun.reset();
                    if (!found)
                        continue;
                    insertPath.bind(1, runId);
                    insertPath.bind(2, cols[2]);
                    insertPath.step();
                    insertPath.reset();
                }
                std::istringstream improvements(pending[i].improvements);
                insertImprovements(db.handle(), ids[i], improvements);
            }
            db.exec("COMMIT");
        }
        work.commit(target);
        return pending.size();
    }

    std::size_t mergeDatabase(const Campaign &campaign, const std::vector<Experiment> &experiments,
                              const std::string &statisticsTool, std::vector<std::string> &problems)
    {
        const std::string simulations = simulationDatabaseFile(campaign);
        if (simulations == campaign.database)
            return mergeInto(campaign.database, campaign, experiments, statisticsTool, problems);
        std::vector<Experiment> planning, moving;
        for (const Experiment &e : experiments)
            (e.simulation == Experiment::kNoSimulation ? planning : moving).push_back(e);
        // No simulation, no simulation database (an empty one would only be refused by `mhplan report`).
        return mergeInto(campaign.database, campaign, planning, statisticsTool, problems) +
               (moving.empty() ? 0 : mergeInto(simulations, campaign, moving, statisticsTool, problems));
    }
} // namespace mhplan::bench

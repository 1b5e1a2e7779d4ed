// SPDX-License-Identifier: BSD-3-Clause
/* Test support for the campaign tests (test_bench, test_bench_sim): planners that crash or hang on purpose,
   the registry holding them, shipped world names, run options, the campaign's crash messages on stderr and
   read-only SQL access to a database. */
#ifndef MHPLAN_TESTS_BENCH_SUPPORT_H
#define MHPLAN_TESTS_BENCH_SUPPORT_H

#include "benchmarks/CampaignRunner.h"
#include "ompl_planners/lattice/ThetaStar.h"
#include "src/registry/Registry.h"

#include <ompl/base/Planner.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace mhplan::test
{
    namespace ob = ompl::base;
    namespace fs = std::filesystem;
    using namespace mhplan::bench;

    /** A planner that never returns normally: "throw" raises an ompl::Exception (a std::runtime_error, which
        OMPL's benchmark catches), "abort" kills its process, "segfault" raises SIGSEGV (under
       AddressSanitizer its handler reports the signal and exits with code 1 instead), "hang" ignores its
       termination condition and sleeps in small steps forever (only a watchdog ends it). */
    class CrashPlanner : public ob::Planner
    {
      public:
        explicit CrashPlanner(const ob::SpaceInformationPtr &si) : ob::Planner(si, "CrashTest")
        {
            declareParam<std::string>("mode", this, &CrashPlanner::setMode, &CrashPlanner::getMode,
                                      "throw,abort,segfault,hang");
        }
        void setMode(const std::string &m) { mode_ = m; }
        std::string getMode() const { return mode_; }
        ob::PlannerStatus solve(const ob::PlannerTerminationCondition &) override
        {
            checkValidity();
            if (mode_ == "throw")
                throw ompl::Exception("CrashTest", "deliberate failure");
            if (mode_ == "segfault")
                std::raise(SIGSEGV);
            if (mode_ == "hang")
                while (true)
                    std::this_thread::sleep_for(std::chrono::milliseconds(10));
            std::abort();
        }

      private:
        std::string mode_{"abort"};
    };

    inline const PlannerRegistry &testRegistry()
    {
        static const PlannerRegistry registry = []
        {
            PlannerRegistry r = builtinPlanners();
            r.add({"CrashTest", "test", "always fails",
                   [](const ob::SpaceInformationPtr &si) { return std::make_shared<CrashPlanner>(si); }});
            r.add({"ThetaStarHere", "test", "Theta* under a name only this registry knows",
                   allocatorFor<ThetaStar>()});
            return r;
        }();
        return registry;
    }

    inline std::string resolveShipped(const std::string &name)
    {
        if (fs::exists(name))
            return name;
        return std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml";
    }

    inline RunOptions options(unsigned int jobs = 1)
    {
        RunOptions o;
        o.jobs = jobs;
        o.progressBar = false;
        o.registry = &testRegistry();
        o.resolveWorld = resolveShipped;
        return o;
    }

    /** True in a build with AddressSanitizer (scripts/sanitize.sh): its SIGSEGV handler reports the signal
       and ends the process with exit code 1 instead of letting the signal kill it. */
#if defined(__SANITIZE_ADDRESS__)
    constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    constexpr bool kAddressSanitizer = true;
#else
    constexpr bool kAddressSanitizer = false;
#endif
#else
    constexpr bool kAddressSanitizer = false;
#endif

    /** While it lives, everything written to file descriptor 2, by this process and by the processes it
        starts (the campaign's experiment processes report crashed runs there), goes to \e file. */
    class StderrToFile
    {
      public:
        explicit StderrToFile(std::string file) : file_(std::move(file))
        {
            std::cerr.flush();
            std::fflush(stderr);
            saved_ = ::dup(2);
            const int fd = ::open(file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (fd >= 0)
            {
                ::dup2(fd, 2);
                ::close(fd);
            }
        }
        ~StderrToFile() { restore(); }
        StderrToFile(const StderrToFile &) = delete;
        StderrToFile &operator=(const StderrToFile &) = delete;
        /** Restore stderr and return what was written meanwhile. */
        std::string text()
        {
            restore();
            std::ifstream in(file_);
            std::ostringstream s;
            s << in.rdbuf();
            return s.str();
        }

      private:
        void restore()
        {
            if (saved_ < 0)
                return;
            std::cerr.flush();
            std::fflush(stderr);
            ::dup2(saved_, 2);
            ::close(saved_);
            saved_ = -1;
        }
        std::string file_;
        int saved_{-1};
    };

    /** Why the campaign says run \e run of planner \e planner in experiment \e experiment crashed: REASON
        of its line "mhplan bench: EXPERIMENT: planner NAME run K crashed (REASON); recorded as Crash" on
        stderr; empty when there is no such line (a run whose own process recorded its crash, e.g. a
        throwing solve(), has none). */
    inline std::string crashReason(const std::string &stderrText, const std::string &experiment,
                                   const std::string &planner, std::size_t run)
    {
        const std::string head =
            experiment + ": planner " + planner + " run " + std::to_string(run) + " crashed (";
        const std::size_t at = stderrText.find(head);
        if (at == std::string::npos)
            return "";
        const std::size_t from = at + head.size();
        const std::size_t end = stderrText.find("); recorded as Crash", from);
        return end == std::string::npos ? "" : stderrText.substr(from, end - from);
    }

    /** \e reason (crashReason()) is a segfault's: the signal, or in a build with AddressSanitizer ASan's exit
        code 1 with its report in \e stderrText (the signal too, should ASAN_OPTIONS say handle_segv=0). */
    inline ::testing::AssertionResult segfaulted(const std::string &reason, const std::string &stderrText)
    {
        if (reason == "signal 11 (Segmentation fault)")
            return ::testing::AssertionSuccess();
        if (kAddressSanitizer && reason == "exit code 1" &&
            stderrText.find("ERROR: AddressSanitizer: SEGV") != std::string::npos)
            return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure()
               << "crash reason '" << reason << "', expected "
               << (kAddressSanitizer ? "exit code 1 with AddressSanitizer's SEGV report, or " : "")
               << "signal 11 (Segmentation fault)";
    }

    /** Minimal read-only SQL access for the assertions. */
    class Sql
    {
      public:
        explicit Sql(const std::string &file)
        {
            if (sqlite3_open_v2(file.c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK)
                ADD_FAILURE() << "cannot open " << file;
        }
        ~Sql() { sqlite3_close(db_); }
        /** Rows of text values (NULL as "NULL"). */
        std::vector<std::vector<std::string>> rows(const std::string &sql) const
        {
            std::vector<std::vector<std::string>> out;
            sqlite3_stmt *st = nullptr;
            if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &st, nullptr) != SQLITE_OK)
            {
                ADD_FAILURE() << sqlite3_errmsg(db_) << " in " << sql;
                return out;
            }
            while (sqlite3_step(st) == SQLITE_ROW)
            {
                std::vector<std::string> row;
                for (int i = 0; i < sqlite3_column_count(st); ++i)
                {
                    const auto *t = sqlite3_column_text(st, i);
                    row.push_back(t ? reinterpret_cast<const char *>(t) : "NULL");
                }
                out.push_back(row);
            }
            sqlite3_finalize(st);
            return out;
        }
        /** The first column of every row as a double, exactly as stored (NULL as NaN). */
        std::vector<double> numbers(const std::string &sql) const
        {
            std::vector<double> out;
            sqlite3_stmt *st = nullptr;
            if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &st, nullptr) != SQLITE_OK)
            {
                ADD_FAILURE() << sqlite3_errmsg(db_) << " in " << sql;
                return out;
            }
            while (sqlite3_step(st) == SQLITE_ROW)
                out.push_back(sqlite3_column_type(st, 0) == SQLITE_NULL ? std::nan("")
                                                                        : sqlite3_column_double(st, 0));
            sqlite3_finalize(st);
            return out;
        }
        long long count(const std::string &sql) const
        {
            const auto r = rows(sql);
            return r.empty() ? -1 : std::atoll(r[0][0].c_str());
        }
        std::set<std::string> columns(const std::string &table) const
        {
            std::set<std::string> out;
            for (const auto &r : rows("PRAGMA table_info(" + table + ")"))
                out.insert(r[1]);
            return out;
        }

      private:
        sqlite3 *db_{nullptr};
    };
} // namespace mhplan::test

#endif

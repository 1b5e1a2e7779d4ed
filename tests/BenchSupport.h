// SPDX-License-Identifier: BSD-3-Clause
/* Test support for the campaign tests (test_bench, test_bench_sim): planners that crash on purpose, the
   registry holding them, shipped world names, run options and read-only SQL access to a database. */
#ifndef MHPLAN_TESTS_BENCH_SUPPORT_H
#define MHPLAN_TESTS_BENCH_SUPPORT_H

#include "mhplan/bench/CampaignRunner.h"
#include "mhplan/planners/lattice/ThetaStar.h"
#include "mhplan/registry/Registry.h"

#include <ompl/base/Planner.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace mhplan::test
{
    namespace ob = ompl::base;
    namespace fs = std::filesystem;
    using namespace mhplan::bench;

    /** A planner that never returns normally: "throw" raises an ompl::Exception (a std::runtime_error, which
        OMPL's benchmark catches), "abort" kills its process, "segfault" raises SIGSEGV. */
    class CrashPlanner : public ob::Planner
    {
      public:
        explicit CrashPlanner(const ob::SpaceInformationPtr &si) : ob::Planner(si, "CrashTest")
        {
            declareParam<std::string>("mode", this, &CrashPlanner::setMode, &CrashPlanner::getMode,
                                      "throw,abort,segfault");
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

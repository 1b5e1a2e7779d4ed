// SPDX-License-Identifier: BSD-3-Clause
#include "benchmarks/Improvements.h"

#include <ompl/base/OptimizationObjective.h>

#include <sqlite3.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;
namespace ob = ompl::base;

namespace mhplan::bench
{
    ImprovementRecorder::~ImprovementRecorder()
    {
        end();
    }

    double ImprovementRecorder::now() const
    {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

    void ImprovementRecorder::attach(const ob::ProblemDefinitionPtr &pdef,
                                     std::function<std::string()> bestCost, double pollInterval)
    {
        if (!(pollInterval > 0.0))
            throw std::invalid_argument("ImprovementRecorder: the poll interval must be > 0");
        bestCost_ = std::move(bestCost);
        pollInterval_ = pollInterval;
        start_ = std::chrono::steady_clock::now();
        pdef->setIntermediateSolutionCallback(
            [this](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost cost)
            { record(cost.value(), true); });
    }

    void ImprovementRecorder::record(double cost, bool fromCallback)
    {
        if (!std::isfinite(cost))
            return;
        const double t = now();
        std::lock_guard<std::mutex> lock(mutex_);
        if (fromCallback)
            sawCallback_ = true;
        std::vector<Improvement> &rows = fromCallback ? callbackRows_ : pollRows_;
        if (!rows.empty() && !(cost < rows.back().cost))
            return; // not an improvement (planners may report the same solution again)
        rows.push_back({t, cost, fromCallback ? "callback" : "poll"});
    }

    void ImprovementRecorder::begin()
    {
        start_ = std::chrono::steady_clock::now();
        running_ = true;
        if (!bestCost_)
            return;
        poller_ = std::thread(
            [this]()
            {
                const auto period = std::chrono::duration<double>(pollInterval_);
                while (running_ && !sawCallback_)
                {
                    const std::string text = bestCost_();
                    char *end = nullptr;
                    const double cost = std::strtod(text.c_str(), &end);
                    if (end != text.c_str())
                        record(cost, false);
                    std::this_thread::sleep_for(period);
                }
            });
    }

    void ImprovementRecorder::end()
    {
        if (running_)
            endSeconds_ = now();
        running_ = false;
        if (poller_.joinable())
            poller_.join();
    }

    std::vector<Improvement> ImprovementRecorder::finish(const ob::ProblemDefinition &pdef)
    {
        end();
        std::vector<Improvement> rows;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            rows = callbackRows_.empty() ? pollRows_ : callbackRows_;
        }
        if (pdef.hasExactSolution())
        {
            const ob::OptimizationObjectivePtr &opt = pdef.getOptimizationObjective();
            const ob::PathPtr path = pdef.getSolutionPath();
            const double cost = opt ? path->cost(opt).value() : path->length();
            // A polled cost is the planner's property text, rounded (OMPL 1.5.2's PRM* prints it with
            // std::to_string: 6 decimals): within that rounding of the final cost it is that solution, and
            // takes its exact cost.
            const double tolerance =
                1e-12 * std::abs(cost) + (!rows.empty() && rows.back().source == "poll" ? 5e-7 : 0.0);
            const bool same = !rows.empty() && std::abs(cost - rows.back().cost) <= tolerance;
            if (std::isfinite(cost) && same)
                rows.back().cost = cost;
            else if (std::isfinite(cost) && (rows.empty() || cost < rows.back().cost))
                rows.push_back({endSeconds_, cost, "final"});
        }
        return rows;
    }

    std::string encodeImprovements(const std::vector<Improvement> &rows)
    {
        std::string out;
        char buf[96];
        for (const Improvement &r : rows)
        {
            std::snprintf(buf, sizeof(buf), "%.17g %.17g ", r.time, r.cost);
            out += buf + r.source + ";";
        }
        return out;
    }

    std::vector<Improvement> decodeImprovements(const std::string &text)
    {
        std::vector<Improvement> out;
        std::istringstream in(text);
        std::string item;
        while (std::getline(in, item, ';'))
        {
            std::istringstream fields(item);
            Improvement r;
            if (fields >> r.time >> r.cost >> r.source)
                out.push_back(r);
        }
        return out;
    }

    std::string improvementsFile(const Campaign &campaign, const Experiment &experiment)
    {
        return (fs::path(campaign.logDir) / (safeFileStem(experiment.name) + ".improvements")).string();
    }

    std::string improvementsFileText(const std::vector<std::string> &plannerNames,
                                     const std::vector<std::vector<std::string>> &encodedRuns)
    {
        std::ostringstream out;
        out << "# mhplan solution improvements: planner <TAB> run index <TAB> time cost source;... "
               "(time: seconds since solve() began; source: callback, poll or final)\n";
        for (std::size_t p = 0; p < plannerNames.size() && p < encodedRuns.size(); ++p)
            for (std::size_t k = 0; k < encodedRuns[p].size(); ++k)
                if (!encodedRuns[p][k].empty())
                    out << plannerNames[p] << "\t" << k << "\t" << encodedRuns[p][k] << "\n";
        return out.str();
    }

    namespace
    {
        void execSql(sqlite3 *db, const char *sql)
        {
            char *err = nullptr;
            if (sqlite3_exec(db, sql, nullptr, nullptr, &err) != SQLITE_OK)
            {
                const std::string e = err ? err : "?";
                sqlite3_free(err);
                throw std::runtime_error("database: " + e + " in: " + sql);
            }
        }

        /** A prepared statement, finalized on scope exit. */
        struct Stmt
        {
            sqlite3_stmt *st{nullptr};
            Stmt(sqlite3 *db, const char *sql)
            {
                if (sqlite3_prepare_v2(db, sql, -1, &st, nullptr) != SQLITE_OK)
                    throw std::runtime_error("database: " + std::string(sqlite3_errmsg(db)) + " in: " + sql);
            }
            ~Stmt() { sqlite3_finalize(st); }
            Stmt(const Stmt &) = delete;
            Stmt &operator=(const Stmt &) = delete;
        };
    } // namespace

    std::size_t insertImprovements(sqlite3 *db, long long experimentId, const std::string &file)
    {
        std::ifstream in(file);
        if (!in)
        {
            std::istringstream none;
            return insertImprovements(db, experimentId, none);
        }
        return insertImprovements(db, experimentId, in);
    }

    std::size_t insertImprovements(sqlite3 *db, long long experimentId, std::istream &in)
    {
        execSql(db,
                "CREATE TABLE IF NOT EXISTS improvements (runid INTEGER, time REAL, cost REAL, source TEXT, "
                "FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE)");
        execSql(db, "CREATE INDEX IF NOT EXISTS improvements_runid ON improvements (runid)");
        Stmt findRun(db, "SELECT runs.id FROM runs JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id "
                         "WHERE runs.experimentid = ? AND plannerConfigs.name = ? AND runs.run_index = ?");
        Stmt remove(db, "DELETE FROM improvements WHERE runid = ?");
        Stmt insert(db, "INSERT INTO improvements VALUES (?, ?, ?, ?)");
        std::size_t rows = 0;
        std::string line;
        while (std::getline(in, line))
        {
            if (line.empty() || line[0] == '#')
                continue;
            const std::size_t t1 = line.find('\t');
            const std::size_t t2 = t1 == std::string::npos ? t1 : line.find('\t', t1 + 1);
            if (t2 == std::string::npos)
                continue;
            const std::string planner = line.substr(0, t1);
            const long long run = std::atoll(line.substr(t1 + 1, t2 - t1 - 1).c_str());
            sqlite3_bind_int64(findRun.st, 1, experimentId);
            sqlite3_bind_text(findRun.st, 2, planner.c_str(), -1, SQLITE_TRANSIENT);
            sqlite3_bind_int64(findRun.st, 3, run);
            const bool found = sqlite3_step(findRun.st) == SQLITE_ROW;
            const long long runId = found ? sqlite3_column_int64(findRun.st, 0) : -1;
            sqlite3_reset(findRun.st);
            sqlite3_clear_bindings(findRun.st);
            if (!found)
                continue;
            sqlite3_bind_int64(remove.st, 1, runId);
            sqlite3_step(remove.st);
            sqlite3_reset(remove.st);
            for (const Improvement &r : decodeImprovements(line.substr(t2 + 1)))
            {
                sqlite3_bind_int64(insert.st, 1, runId);
                sqlite3_bind_double(insert.st, 2, r.time);
                sqlite3_bind_double(insert.st, 3, r.cost);
                sqlite3_bind_text(insert.st, 4, r.source.c_str(), -1, SQLITE_TRANSIENT);
                if (sqlite3_step(insert.st) != SQLITE_DONE)
                    throw std::runtime_error("database: " + std::string(sqlite3_errmsg(db)));
                sqlite3_reset(insert.st);
                ++rows;
            }
        }
        return rows;
    }
} // namespace mhplan::bench

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: exact time-to-quality. Every improvement of a run's solution is recorded when it happens (time
   since solve() began, on the steady clock, and the cost), kept per run in a side file next to the
   experiment's log (<experiment>.improvements) and in the database table improvements(runid, time, cost,
   source) beside OMPL's progress table (which stays for Planner Arena; both Planner Arena and
   ompl_benchmark_statistics ignore tables they do not know).

   Sources of a row (column source):
   - "callback": ProblemDefinition's intermediate solution callback, called by the planner itself whenever
     it finds a better solution (OMPL 1.5.2: RRT*, Informed RRT*, BIT* and the other tree planners that
     test pdef_->getIntermediateSolutionCallback(); every mhplan planner, which must call it);
   - "poll": for planners that never call it (OMPL 1.5.2's PRM* and PRM, LazyPRM*, mhplan's A* lattice), the
     planner's "best cost" progress property read every poll interval (1 ms in campaigns) until the first
     callback arrives; the time is that of the first poll that saw the cost, so at most one interval late,
     and the cost is the property's text (PRM*: 6 decimals) except for the last row, which takes the exact
     cost of the returned solution;
   - "final": the run's exact solution at the end of solve() when its cost is below the last recorded row
     (or there is none): planners without callback and without "best cost" (A*, an iteration-bounded
     metaheuristic that reports nothing), or a last improvement the planner did not report. Its time is the
     end of solve(), an upper bound.
   When a run has callback rows its poll rows are dropped (the callback is exact). Costs strictly decrease
   along a run's rows; only exact solutions are recorded. */
#ifndef MHPLAN_BENCH_IMPROVEMENTS_H
#define MHPLAN_BENCH_IMPROVEMENTS_H

#include "benchmarks/Campaign.h"

#include <ompl/base/ProblemDefinition.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

struct sqlite3;

namespace mhplan::bench
{
    /** \brief Seconds between two polls of a planner's "best cost" in campaigns (planners without callback).
     */
    constexpr double kImprovementPollInterval = 1e-3;

    /** \brief One improvement of a run's solution. */
    struct Improvement
    {
        /** \brief Seconds since solve() began (steady clock). */
        double time{0.0};
        /** \brief Cost of the new solution under the problem's objective (path length in mhplan). */
        double cost{0.0};
        /** \brief "callback", "poll" or "final" (see the file comment). */
        std::string source;
    };

    /** \brief Records the improvements of one run. attach() before the run (it registers the
        ProblemDefinition's intermediate solution callback), begin() when solve() starts, end() when it
        returns, finish() afterwards. The callback may come from any thread. */
    class ImprovementRecorder
    {
      public:
        ImprovementRecorder() = default;
        ~ImprovementRecorder();
        ImprovementRecorder(const ImprovementRecorder &) = delete;
        ImprovementRecorder &operator=(const ImprovementRecorder &) = delete;

        /** \brief Register the callback on \e pdef (replacing any other) and remember \e bestCost (the
            planner's "best cost" progress function, may be empty: no polling) and the poll interval in
            seconds (> 0). */
        void attach(const ompl::base::ProblemDefinitionPtr &pdef, std::function<std::string()> bestCost,
                    double pollInterval);
        /** \brief solve() starts: the clock starts, the poll thread (if any) too. */
        void begin();
        /** \brief solve() returned: the poll thread stops. */
        void end();
        /** \brief The run's rows: the callback rows (or, without any, the poll rows), then a "final" row
            when \e pdef's exact solution costs less than the last row. */
        std::vector<Improvement> finish(const ompl::base::ProblemDefinition &pdef);

      private:
        void record(double cost, bool fromCallback);
        double now() const;

        std::mutex mutex_;
        std::vector<Improvement> callbackRows_;
        std::vector<Improvement> pollRows_;
        std::function<std::string()> bestCost_;
        double pollInterval_{1e-3};
        std::chrono::steady_clock::time_point start_;
        double endSeconds_{0.0};
        std::atomic<bool> running_{false};
        std::atomic<bool> sawCallback_{false};
        std::thread poller_;
    };

    /** \brief "time cost source;time cost source;..." (full precision). */
    std::string encodeImprovements(const std::vector<Improvement> &rows);
    /** \brief Inverse of encodeImprovements (malformed entries are skipped). */
    std::vector<Improvement> decodeImprovements(const std::string &text);

    /** \brief The improvements side file of an experiment's log (tab-separated: planner, run index, rows). */
    std::string improvementsFile(const Campaign &campaign, const Experiment &experiment);
    /** \brief The side file's text: one line per run with rows, planners named as in the log. */
    std::string improvementsFileText(const std::vector<std::string> &plannerNames,
                                     const std::vector<std::vector<std::string>> &encodedRuns);

    /** \brief Create the table improvements(runid, time, cost, source) if missing and insert the rows of
        \e file (a side file; missing: nothing) for experiment \e experimentId, matching runs by planner
        name and run index. Returns the number of rows inserted. */
    std::size_t insertImprovements(sqlite3 *db, long long experimentId, const std::string &file);
    /** \brief As above, from the side file's text \e in (the bytes the merge has checked). */
    std::size_t insertImprovements(sqlite3 *db, long long experimentId, std::istream &in);
} // namespace mhplan::bench

#endif

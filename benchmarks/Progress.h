// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: the terminal progress bar of a campaign. */
#ifndef MHPLAN_BENCH_PROGRESS_H
#define MHPLAN_BENCH_PROGRESS_H

#include "benchmarks/ChildProcess.h"

#include <string>
#include <vector>

namespace mhplan::bench::detail
{
    /** "42s", "3m07s", "2h05m"; "--" when unknown (negative or not finite). */
    std::string formatDuration(double seconds);

    /** Terminal progress: experiments and runs done, crashes, elapsed time and ETA. The ETA weighs the
        runs still to do by each planner's mean run time so far (the time limit for planners not seen yet)
        and scales by the ratio of elapsed time to the run time done (parallelism and overhead). */
    class ProgressBar
    {
      public:
        /** \e slotRuns: runs to do per slot (a planner, or a controller of a simulation); \e guess: the
            seconds assumed per run of a slot not seen yet. */
        ProgressBar(bool enabled, std::size_t experiments, std::vector<std::size_t> slotRuns, double guess);
        void recordRun(std::size_t slot, double seconds);
        /** Seconds still needed, or a negative number when unknown. */
        double eta() const;
        /** Redraw (at most every 0.2 s unless \e force). */
        void update(std::size_t expDone, std::size_t runsDone, std::size_t crashes, bool force = false);
        void finish();

      private:
        bool enabled_;
        std::size_t experiments_;
        std::size_t runs_{0};
        Clock::time_point start_;
        Clock::time_point lastDraw_{};
        double guess_;
        std::vector<std::size_t> total_;
        std::vector<double> sum_;
        std::vector<std::size_t> count_;
    };
} // namespace mhplan::bench::detail

#endif

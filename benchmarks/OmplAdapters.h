// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: adapters between mhplan's run processes and OMPL's benchmark: OMPL's experiment record
   opened for runs gathered from several processes, OMPL's error text captured, and a planner wrapper that
   exports planner data and progress properties only as the campaign asks. */
#ifndef MHPLAN_BENCH_OMPL_ADAPTERS_H
#define MHPLAN_BENCH_OMPL_ADAPTERS_H

#include "benchmarks/Improvements.h"

#include <ompl/base/Planner.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace mhplan::bench::detail
{
    /** Gives access to the experiment record so that runs gathered from several processes can be
        written with OMPL's own log writer. */
    class AssembledBenchmark : public ompl::tools::Benchmark
    {
      public:
        using ompl::tools::Benchmark::Benchmark;
        CompleteExperiment &experiment() { return exp_; }
    };

    /** Captures what OMPL's benchmark writes to std::cerr when a planner throws. */
    class CerrCapture
    {
      public:
        CerrCapture() : old_(std::cerr.rdbuf(buffer_.rdbuf())) {}
        ~CerrCapture() { std::cerr.rdbuf(old_); }
        std::string take()
        {
            std::string s = buffer_.str();
            buffer_.str("");
            return s;
        }

      private:
        std::ostringstream buffer_;
        std::streambuf *old_;
    };

    /** Runs another planner unchanged (same name, parameters, specs) but hands OMPL's benchmark its
       planner data only when asked (exporting the roadmap of a PRM* run costs about as much time as the
       run itself) and only the progress properties the campaign selects. */
    class PlannerDataSwitch : public ompl::base::Planner
    {
      public:
        PlannerDataSwitch(ompl::base::PlannerPtr inner, bool plannerData,
                          const std::vector<std::string> &progress)
            : ompl::base::Planner(inner->getSpaceInformation(), inner->getName()), inner_(std::move(inner)),
              plannerData_(plannerData)
        {
            specs_ = inner_->getSpecs();
            params_ = inner_->params();
            for (const auto &kv : inner_->getPlannerProgressProperties())
            {
                // "best cost REAL" is selected by "best cost".
                const std::string name = kv.first.substr(0, kv.first.find_last_of(' '));
                if (progress.empty() || std::find(progress.begin(), progress.end(), name) != progress.end())
                    addPlannerProgressProperty(kv.first, kv.second);
            }
        }
        void setProblemDefinition(const ompl::base::ProblemDefinitionPtr &pdef) override
        {
            ompl::base::Planner::setProblemDefinition(pdef);
            inner_->setProblemDefinition(pdef);
        }
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override
        {
            if (recorder_)
                recorder_->begin();
            const double cpu0 = cpuClock_ ? cpuClock_() : 0.0;
            ompl::base::PlannerStatus status;
            if (cpuClock_ && cpuLimit_ > 0.0)
            {
                // The CPU clock is read in OMPL's checking thread every 1/100 of the limit (at most 10 ms),
                // not in the planner's loop (reading it is a system call).
                const auto clock = cpuClock_;
                const double limit = cpuLimit_;
                const ompl::base::PlannerTerminationCondition cpu(
                    [clock, cpu0, limit] { return clock() - cpu0 >= limit; }, std::min(0.01, limit / 100.0));
                status = inner_->solve(ompl::base::plannerOrTerminationCondition(ptc, cpu));
            }
            else
                status = inner_->solve(ptc);
            cpuSeconds_ = cpuClock_ ? cpuClock_() - cpu0 : 0.0;
            if (recorder_)
                recorder_->end();
            return status;
        }
        /** Measure the CPU time of every solve() with \e clock (seconds, monotone), and end solve() when
            it has used \e limit CPU seconds (0: no CPU limit; the caller's condition still applies). */
        void setCpuClock(std::function<double()> clock, double limit)
        {
            cpuClock_ = std::move(clock);
            cpuLimit_ = limit;
        }
        /** CPU seconds the last solve() used (0 without a clock). */
        double cpuSeconds() const { return cpuSeconds_; }
        /** Times solve() for \e recorder (Improvements.h). */
        void setRecorder(ImprovementRecorder *recorder) { recorder_ = recorder; }
        void clear() override
        {
            ompl::base::Planner::clear();
            inner_->clear();
        }
        void setup() override
        {
            ompl::base::Planner::setup();
            inner_->setup();
        }
        void checkValidity() override { inner_->checkValidity(); }
        void printProperties(std::ostream &out) const override { inner_->printProperties(out); }
        void printSettings(std::ostream &out) const override { inner_->printSettings(out); }
        void getPlannerData(ompl::base::PlannerData &data) const override
        {
            if (plannerData_)
                inner_->getPlannerData(data);
        }

      private:
        ompl::base::PlannerPtr inner_;
        bool plannerData_;
        ImprovementRecorder *recorder_{nullptr};
        std::function<double()> cpuClock_;
        double cpuLimit_{0.0};
        double cpuSeconds_{0.0};
    };
} // namespace mhplan::bench::detail

#endif

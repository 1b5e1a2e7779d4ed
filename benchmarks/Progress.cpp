// SPDX-License-Identifier: BSD-3-Clause
#include "benchmarks/Progress.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace mhplan::bench::detail
{
    std::string formatDuration(double seconds)
    {
        if (!std::isfinite(seconds) || seconds < 0)
            return "--";
        const long total = std::lround(seconds);
        std::ostringstream out;
        if (total >= 3600)
            out << total / 3600 << "h" << std::setw(2) << std::setfill('0') << (total / 60) % 60 << "m";
        else if (total >= 60)
            out << total / 60 << "m" << std::setw(2) << std::setfill('0') << total % 60 << "s";
        else
            out << total << "s";
        return out.str();
    }

    ProgressBar::ProgressBar(bool enabled, std::size_t experiments, std::vector<std::size_t> slotRuns,
                             double guess)
        : enabled_(enabled), experiments_(experiments), start_(Clock::now()), guess_(guess),
          total_(std::move(slotRuns)), sum_(total_.size(), 0.0), count_(total_.size(), 0)
    {
        for (std::size_t n : total_)
            runs_ += n;
    }

    void ProgressBar::recordRun(std::size_t slot, double seconds)
    {
        if (slot < sum_.size())
        {
            sum_[slot] += seconds;
            ++count_[slot];
        }
    }

    double ProgressBar::eta() const
    {
        double done = 0.0, todo = 0.0;
        for (std::size_t p = 0; p < sum_.size(); ++p)
        {
            done += sum_[p];
            const double mean = count_[p] ? sum_[p] / static_cast<double>(count_[p]) : guess_;
            todo += mean * static_cast<double>(total_[p] > count_[p] ? total_[p] - count_[p] : 0);
        }
        if (!(done > 0.0))
            return -1.0;
        return todo * secondsSince(start_) / done;
    }

    void ProgressBar::update(std::size_t expDone, std::size_t runsDone, std::size_t crashes, bool force)
    {
        if (!enabled_)
            return;
        if (!force && secondsSince(lastDraw_) < 0.2)
            return;
        lastDraw_ = Clock::now();
        const double elapsed = secondsSince(start_);
        const double frac = runs_ ? static_cast<double>(runsDone) / static_cast<double>(runs_) : 1.0;
        const double remaining = eta();
        const int width = 28;
        const int filled = static_cast<int>(frac * width);
        std::ostringstream line;
        line << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
             << std::string(static_cast<std::size_t>(width - filled), '.') << "] " << std::setw(3)
             << static_cast<int>(100.0 * frac) << "% experiments " << expDone << "/" << experiments_
             << " runs " << runsDone << "/" << runs_;
        if (crashes > 0)
            line << " crashes " << crashes;
        line << " elapsed " << formatDuration(elapsed) << " ETA " << formatDuration(remaining) << "   ";
        std::cerr << line.str() << std::flush;
    }

    void ProgressBar::finish()
    {
        if (enabled_)
            std::cerr << "\n";
    }
} // namespace mhplan::bench::detail

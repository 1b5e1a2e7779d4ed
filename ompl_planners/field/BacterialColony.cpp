// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/field/BacterialColony.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace mhplan
{
    void ColonyProblem::randomDirection(double *phi, unsigned int dim, ompl::RNG &rng)
    {
        double n2 = 0.0;
        while (n2 < 1e-24)
        {
            n2 = 0.0;
            for (unsigned int j = 0; j < dim; ++j)
            {
                phi[j] = rng.uniformReal(-1.0, 1.0);
                n2 += phi[j] * phi[j];
            }
        }
        const double inv = 1.0 / std::sqrt(n2);
        for (unsigned int j = 0; j < dim; ++j)
            phi[j] *= inv;
    }

    void BacterialColony::start(unsigned int dim, unsigned int size, ColonyProblem &problem)
    {
        dim_ = dim;
        size_ = size;
        const std::size_t n = std::size_t(size_) * dim_;
        const double inf = std::numeric_limits<double>::infinity();
        x_.assign(n, 0.0);
        dir_.assign(n, 0.0);
        scratchX_.assign(n, 0.0);
        scratchDir_.assign(n, 0.0);
        trial_.assign(dim_, 0.0);
        cost_.assign(size_, inf);
        scratchCost_.assign(size_, inf);
        health_.assign(size_, 0.0);
        known_.assign(size_, 0);
        keep_.assign(size_, 0);
        scratchKnown_.assign(size_, 0);
        scratchKeep_.assign(size_, 0);
        order_.resize(size_);
        for (unsigned int i = 0; i < size_; ++i)
            problem.randomPosition(row(x_, i));
        cursor_ = chemo_ = repro_ = elim_ = 0;
        started_ = true;
    }

    void BacterialColony::reserve(unsigned int dim, unsigned int size)
    {
        const std::size_t n = std::size_t(size) * dim;
        for (std::vector<double> *v : {&x_, &dir_, &scratchX_, &scratchDir_})
            v->reserve(n);
        trial_.reserve(dim);
        for (std::vector<double> *v : {&cost_, &scratchCost_, &health_})
            v->reserve(size);
        for (std::vector<std::uint8_t> *v : {&known_, &keep_, &scratchKnown_, &scratchKeep_})
            v->reserve(size);
        order_.reserve(size);
    }

    void BacterialColony::reset()
    {
        started_ = false;
        cursor_ = chemo_ = repro_ = elim_ = 0;
        size_ = 0;
    }

    bool BacterialColony::evaluateAll(ColonyProblem &problem)
    {
        for (unsigned int i = 0; i < size_; ++i)
        {
            if (known_[i])
                continue;
            if (problem.halt())
                return false;
            cost_[i] = problem.cost(row(x_, i));
            known_[i] = 1;
        }
        return true;
    }

    double BacterialColony::cellToCell(const double *x, unsigned int self) const
    {
        const ColonySettings &s = *settings_;
        if (!s.cellToCell)
            return 0.0;
        double sum = 0.0;
        for (unsigned int k = 0; k < size_; ++k)
        {
            if (k == self)
                continue;
            const double *y = row(x_, k);
            double d2 = 0.0;
            for (unsigned int j = 0; j < dim_; ++j)
                d2 += (x[j] - y[j]) * (x[j] - y[j]);
            sum += -s.attractDepth * std::exp(-s.attractWidth * d2) +
                   s.repelHeight * std::exp(-s.repelWidth * d2);
        }
        return sum;
    }

    bool BacterialColony::moveBacterium(unsigned int i, ColonyProblem &problem, ompl::RNG &rng)
    {
        const ColonySettings &s = *settings_;
        double *xi = row(x_, i);
        if (!known_[i])
        {
            if (problem.halt())
                return false;
            cost_[i] = problem.cost(xi);
            known_[i] = 1;
        }
        double jLast = cost_[i] + cellToCell(xi, i);
        double *phi = row(dir_, i);
        if (!(s.adaptiveTumble && keep_[i]))
            problem.randomDirection(phi, dim_, rng);

        // Tumble: one unconditional step along phi.
        for (unsigned int j = 0; j < dim_; ++j)
            trial_[j] = xi[j] + s.stepSize * phi[j];
        problem.constrain(trial_.data());
        if (problem.halt())
            return false;
        double raw = problem.cost(trial_.data());
        double jNow = raw + cellToCell(trial_.data(), i);
        std::copy(trial_.begin(), trial_.end(), xi);
        cost_[i] = raw;

        // Swim while the last move improved J, at most Ns further moves. ATBFO's imp_count counts the
        // improving swim (run) moves only, not the tumble ([BFO] Pseudo code 1; docs/algorithms.md 6.2).
        unsigned int improvements = 0, swims = 0;
        while (jNow < jLast)
        {
            if (swims > 0)
                ++improvements;
            jLast = jNow;
            if (swims == s.swimLength || problem.halt())
                break;
            ++swims;
            for (unsigned int j = 0; j < dim_; ++j)
                trial_[j] = xi[j] + s.stepSize * phi[j];
            problem.constrain(trial_.data());
            raw = problem.cost(trial_.data());
            jNow = raw + cellToCell(trial_.data(), i);
            std::copy(trial_.begin(), trial_.end(), xi);
            cost_[i] = raw;
        }
        health_[i] += jNow;
        keep_[i] = s.adaptiveTumble && improvements > s.improvementThreshold ? 1 : 0;
        return true;
    }

    BacterialColony::Step BacterialColony::step(ColonyProblem &problem, ompl::RNG &rng)
    {
        const ColonySettings &s = *settings_;
        while (cursor_ < size_)
        {
            if (!moveBacterium(cursor_, problem, rng))
                return Step::Interrupted;
            ++cursor_;
        }
        cursor_ = 0;
        if (++chemo_ < s.chemotacticSteps)
            return Step::StepDone;
        chemo_ = 0;
        reproduce();
        if (++repro_ < s.reproductionSteps)
            return Step::StepDone;
        repro_ = 0;
        disperse(problem, rng);
        if (++elim_ < s.eliminationEvents)
            return Step::StepDone;
        elim_ = 0;
        return Step::RunComplete;
    }

    void BacterialColony::reproduce()
    {
        std::iota(order_.begin(), order_.end(), 0u);
        std::stable_sort(order_.begin(), order_.end(),
                         [this](unsigned int a, unsigned int b) { return health_[a] < health_[b]; });
        // The healthier half splits; for odd S the median bacterium survives without splitting.
        const unsigned int split = size_ / 2, survivors = size_ - split;
        for (unsigned int s = 0; s < size_; ++s)
        {
            const unsigned int src = s < survivors ? order_[s] : order_[s - survivors];
            std::copy_n(row(x_, src), dim_, row(scratchX_, s));
            std::copy_n(row(dir_, src), dim_, row(scratchDir_, s));
            scratchCost_[s] = cost_[src];
            scratchKnown_[s] = known_[src];
            scratchKeep_[s] = keep_[src];
        }
        x_.swap(scratchX_);
        dir_.swap(scratchDir_);
        cost_.swap(scratchCost_);
        known_.swap(scratchKnown_);
        keep_.swap(scratchKeep_);
        std::fill(health_.begin(), health_.end(), 0.0);
    }

    void BacterialColony::disperse(ColonyProblem &problem, ompl::RNG &rng)
    {
        for (unsigned int i = 0; i < size_; ++i)
            if (rng.uniform01() < settings_->eliminationProbability)
            {
                problem.randomPosition(row(x_, i));
                known_[i] = 0;
                keep_[i] = 0;
            }
    }
} // namespace mhplan

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the state mode of SMA-MEM, LRSMA-MEM and MGO-MEM (docs/spaces.md, "The memetic planners off the
   plane"): station displacements along the reference path of states. */
#include "ompl_planners/memetic/MemeticOffsetPlanners.h"

#include <algorithm>
#include <cmath>

namespace mhplan
{
    void OffsetMemeticPlanner::buildStateStations()
    {
        MemeticStateToolkit &tk = stateToolkit();
        const StateParametrisation &param = tk.parametrisation();
        const StatePath &ref = reference_.states;
        stateDim_ = param.dimension();
        coordScale_.resize(stateDim_);
        for (unsigned int c = 0; c < stateDim_; ++c)
            coordScale_[c] = (param.upper(c) - param.lower(c)) / scale();
        const auto interior = static_cast<unsigned int>(ref.size() >= 2 ? ref.size() - 2 : 0);
        const unsigned int k = std::min(getMaxStations(), 8u + interior);
        StatePath samples;
        std::vector<std::size_t> segments;
        tk.resample(ref, k + 2, samples, &segments);
        rs_.assign(samples.begin() + 1, samples.end() - 1);
        seg_.assign(segments.begin() + 1, segments.end() - 1);
    }

    void OffsetMemeticPlanner::encodeStates(const StatePath &path, std::vector<double> &x)
    {
        const auto k = static_cast<unsigned int>(rs_.size());
        x.assign(std::size_t(k) * stateDim_, 0.0);
        if (path.size() < 2 || k == 0)
            return;
        StatePath samples;
        stateToolkit().resample(path, k + 2, samples, nullptr);
        for (unsigned int s = 0; s < k; ++s)
            for (unsigned int c = 0; c < stateDim_; ++c)
                x[s * stateDim_ + c] =
                    coordScale_[c] > 0.0 ? (samples[s + 1][c] - rs_[s][c]) / coordScale_[c] : 0.0;
        clampPosition(x);
    }

    bool OffsetMemeticPlanner::decodeEvaluateStates(std::vector<double> &x, Individual &out)
    {
        MemeticStateToolkit &tk = stateToolkit();
        const StateParametrisation &param = tk.parametrisation();
        const StatePath &ref = reference_.states;
        const auto k = static_cast<unsigned int>(rs_.size());
        x.resize(std::size_t(k) * stateDim_, 0.0);
        clampPosition(x);
        // Stations 0 and K + 1 are the start and the goal (on the reference, no displacement).
        StatePath q(k + 2);
        q[0] = ref.front();
        q[k + 1] = ref.back();
        StatePoint c(stateDim_);
        for (unsigned int s = 0; s < k; ++s)
        {
            q[s + 1] = rs_[s];
            double f = 1.0;
            bool zero = true;
            for (unsigned int j = 0; j < stateDim_; ++j)
                zero = zero && x[s * stateDim_ + j] == 0.0;
            for (int halving = 0; halving < 3 && !zero; ++halving, f *= 0.5)
            {
                for (unsigned int j = 0; j < stateDim_; ++j)
                    c[j] = rs_[s][j] + f * x[s * stateDim_ + j] * coordScale_[j];
                param.enforce(c.data());
                // Both directions: the fallback below may leave and rejoin the reference here.
                if (tk.pointValid(c) && tk.motionValid(rs_[s], c) && tk.motionValid(c, rs_[s]))
                {
                    q[s + 1] = c;
                    break;
                }
            }
        }
        auto station = [&](unsigned int s) -> const StatePoint & {
            return s == 0 ? ref.front() : s == k + 1 ? ref.back() : rs_[s - 1];
        };
        auto segment = [&](unsigned int s) {
            return s == 0 ? std::size_t(0) : s == k + 1 ? ref.size() - 2 : seg_[s - 1];
        };
        StatePath &path = out.states;
        path.clear();
        path.push_back(q[0]);
        for (unsigned int s = 1; s <= k + 1; ++s)
        {
            if (stopRequested())
                return false;
            if (tk.motionValid(path.back(), q[s]))
            {
                path.push_back(q[s]);
                continue;
            }
            // Back to the reference, along it, and out to the next station's state.
            if (path.back() != station(s - 1))
                path.push_back(station(s - 1));
            for (std::size_t v = segment(s - 1) + 1; v <= segment(s); ++v)
                if (path.back() != ref[v])
                    path.push_back(ref[v]);
            if (path.back() != station(s))
                path.push_back(station(s));
            if (path.back() != q[s])
                path.push_back(q[s]);
        }
        if (!improveAndEvaluate(out))
            return false;
        encode(out, x);
        return true;
    }
} // namespace mhplan

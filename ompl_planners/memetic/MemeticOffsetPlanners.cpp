// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/memetic/MemeticOffsetPlanners.h"

#include "src/base/Parameters.h"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kIterations{"iterations", 1, 1, 1000000,
                                         "T, schedule length of the first epoch"};
        constexpr ParamRange kMaxStations{"max_stations", 8, 1, 1024,
                                          "largest number of stations K along the path"};
        constexpr ParamRange kOffsetRange{"offset_range", 0.001, 0.001, 1,
                                          "offset bound D as a share of the bounds' larger side"};
        constexpr ParamRange kZ{"z", 0, 0.01, 1, "probability of a random restart of one individual"};
        constexpr ParamRange kLevyStep{"levy_step", 0, 0.01, 1, "Levy step as a share of the offset range"};
        constexpr ParamRange kRotationFraction{"rotation_fraction", 0, 0.05, 1,
                                               "share of the population rotated on stagnation"};
    } // namespace

    // ---------------------------------------------------------------- OffsetMemeticPlanner

    OffsetMemeticPlanner::OffsetMemeticPlanner(const ob::SpaceInformationPtr &si, const std::string &name,
                                               unsigned int populationSize)
        : MemeticPlanner(si, name, populationSize)
    {
        setEliteRewalks(4);
        declareRanged<unsigned int>(params(), this, kIterations, &OffsetMemeticPlanner::setIterations,
                                    &OffsetMemeticPlanner::getIterations);
        declareRanged<unsigned int>(params(), this, kMaxStations, &OffsetMemeticPlanner::setMaxStations,
                                    &OffsetMemeticPlanner::getMaxStations);
        declareRanged<double>(params(), this, kOffsetRange, &OffsetMemeticPlanner::setOffsetRange,
                              &OffsetMemeticPlanner::getOffsetRange);
    }

    void OffsetMemeticPlanner::setIterations(unsigned int t)
    {
        storeChecked(kIterations, iterations_, t);
    }

    void OffsetMemeticPlanner::setMaxStations(unsigned int k)
    {
        storeChecked(kMaxStations, maxStations_, k);
    }

    void OffsetMemeticPlanner::setOffsetRange(double r)
    {
        storeChecked(kOffsetRange, offsetRange_, r);
    }

    void OffsetMemeticPlanner::clearAlgorithm()
    {
        x_.clear();
        haveReference_ = false;
        reference_ = Individual();
        r_.clear();
        n_.clear();
        seg_.clear();
        rs_.clear();
        coordScale_.clear();
    }

    double OffsetMemeticPlanner::scheduleFraction(unsigned long t) const
    {
        const unsigned long tt = (t - 1) % epochLength_ + 1;
        return double(tt) / double(epochLength_);
    }

    void OffsetMemeticPlanner::buildStations()
    {
        if (stateMode())
        {
            buildStateStations();
            return;
        }
        const MemeticPath &ref = reference_.path;
        double turn = 0.0;
        for (std::size_t i = 1; i + 1 < ref.size(); ++i)
        {
            const Vec2 u = ref[i] - ref[i - 1], w = ref[i + 1] - ref[i];
            turn += std::atan2(std::abs(cross(u, w)), dot(u, w));
        }
        const auto k =
            static_cast<unsigned int>(std::min<double>(maxStations_, 8.0 + std::ceil(turn / 0.25)));
        const double total = MemeticToolkit::length(ref);
        r_.clear();
        n_.clear();
        seg_.clear();
        for (unsigned int s = 1; s <= k; ++s)
        {
            std::size_t seg = 0;
            const Vec2 p = MemeticToolkit::pointAt(ref, total * double(s) / double(k + 1), seg);
            const Vec2 d = ref[seg + 1] - ref[seg];
            const double l = norm(d);
            r_.push_back(p);
            n_.push_back(l > 0.0 ? Vec2(-d.y / l, d.x / l) : Vec2(0.0, 1.0));
            seg_.push_back(seg);
        }
    }

    void OffsetMemeticPlanner::encode(const Individual &ind, std::vector<double> &x)
    {
        if (stateMode())
        {
            encodeStates(ind.states, x);
            return;
        }
        const MemeticPath &path = ind.path;
        const double bound = offsetBound();
        x.assign(stations(), 0.0);
        for (unsigned int k = 0; k < stations(); ++k)
        {
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t i = 1; i < path.size(); ++i)
            {
                const Vec2 p = path[i - 1], d = path[i] - path[i - 1];
                const double den = cross(n_[k], d);
                if (std::abs(den) < 1e-15)
                    continue;
                const double t = cross(p - r_[k], d) / den;
                const double u = cross(p - r_[k], n_[k]) / den;
                if (u >= 0.0 && u <= 1.0 && std::abs(t) < std::abs(best))
                    best = t;
            }
            x[k] = std::abs(best) <= bound ? best : 0.0;
        }
    }

    void OffsetMemeticPlanner::randomPosition(std::vector<double> &x)
    {
        const double bound = offsetBound();
        x.resize(stations());
        for (double &v : x)
            v = rng_.uniformReal(-bound, bound);
    }

    void OffsetMemeticPlanner::clampPosition(std::vector<double> &x) const
    {
        const double bound = offsetBound();
        for (double &v : x)
            v = std::min(bound, std::max(-bound, std::isfinite(v) ? v : 0.0));
    }

    void OffsetMemeticPlanner::updateReference()
    {
        if (pop_.empty())
            return;
        const std::size_t b = bestIndex();
        if (haveReference_ && pop_[b].cost >= reference_.cost)
            return;
        reference_ = pop_[b];
        haveReference_ = true;
        buildStations();
        x_.resize(pop_.size());
        for (std::size_t i = 0; i < pop_.size(); ++i)
            encode(pop_[i], x_[i]);
    }

    void OffsetMemeticPlanner::populationChanged()
    {
        x_.resize(pop_.size());
        for (std::size_t i = 0; i < pop_.size(); ++i)
            encode(pop_[i], x_[i]);
        updateReference();
    }

    void OffsetMemeticPlanner::startAlgorithm()
    {
        epochLength_ = iterations_;
        haveReference_ = false;
        updateReference();
    }

    void OffsetMemeticPlanner::restartAlgorithm()
    {
        epochLength_ = std::min<unsigned long>(epochLength_ * 2, 1ul << 40);
        x_.resize(pop_.size());
        for (std::size_t i = 0; i < pop_.size(); ++i)
            encode(pop_[i], x_[i]);
        updateReference();
    }

    bool OffsetMemeticPlanner::decodeEvaluate(std::vector<double> &x, Individual &out)
    {
        if (stateMode())
            return decodeEvaluateStates(x, out);
        MemeticToolkit &tk = toolkit();
        const MemeticPath &ref = reference_.path;
        const unsigned int k = stations();
        x.resize(k, 0.0);
        clampPosition(x);
        // Stations 0 and K + 1 are the start and the goal (on the reference, offset 0).
        MemeticPath q(k + 2);
        q[0] = ref.front();
        q[k + 1] = ref.back();
        for (unsigned int s = 0; s < k; ++s)
        {
            double off = x[s];
            Vec2 p = r_[s];
            for (int halving = 0; halving < 3 && off != 0.0; ++halving, off *= 0.5)
            {
                const Vec2 c = r_[s] + n_[s] * off;
                if (tk.pointValid(c) && tk.motionValid(r_[s], c))
                {
                    p = c;
                    break;
                }
            }
            q[s + 1] = p;
        }
        auto station = [&](unsigned int s) {
            return s == 0 ? ref.front() : s == k + 1 ? ref.back() : r_[s - 1];
        };
        auto segment = [&](unsigned int s) {
            return s == 0 ? std::size_t(0) : s == k + 1 ? ref.size() - 2 : seg_[s - 1];
        };
        MemeticPath &path = out.path;
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
            // Back to the reference along the normal, along it, and out along the next normal.
            const Vec2 from = station(s - 1);
            if (path.back() != from)
                path.push_back(from);
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

    // ---------------------------------------------------------------- SMA-MEM

    MemeticSlimeMould::MemeticSlimeMould(const ob::SpaceInformationPtr &si, const std::string &name)
        : OffsetMemeticPlanner(si, name, 20)
    {
        declareRanged<double>(params(), this, kZ, &MemeticSlimeMould::setZ, &MemeticSlimeMould::getZ);
    }

    void MemeticSlimeMould::setZ(double z)
    {
        storeChecked(kZ, z_, z);
    }

    bool MemeticSlimeMould::slimeMouldStep(unsigned long t)
    {
        const std::size_t n = pop_.size();
        const unsigned int d = stations();
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return pop_[a].cost < pop_[b].cost; });
        const double bF = pop_[order.front()].cost, wF = pop_[order.back()].cost;
        const double span = bF - wF - std::numeric_limits<double>::epsilon();
        std::vector<std::vector<double>> w(n, std::vector<double>(d, 1.0));
        for (std::size_t rank = 0; rank < n; ++rank)
        {
            const std::size_t i = order[rank];
            const double ratio = std::log10((bF - pop_[i].cost) / span + 1.0);
            const bool betterHalf = double(rank + 1) <= double(n) / 2.0;
            for (unsigned int j = 0; j < d; ++j)
            {
                const double r = rng_.uniform01();
                w[i][j] = betterHalf ? 1.0 + r * ratio : 1.0 - r * ratio;
            }
        }
        const double frac = scheduleFraction(t);
        const double a = std::atanh(std::max(0.0, std::min(1.0 - 1e-12, 1.0 - frac)));
        const double b = std::max(0.0, 1.0 - frac);
        const double DF = bF;
        std::vector<std::vector<double>> next = x_;
        for (std::size_t i = 0; i < n; ++i)
        {
            std::vector<double> &xi = next[i];
            xi.resize(d, 0.0);
            if (rng_.uniform01() < z_)
            {
                randomPosition(xi);
                continue;
            }
            const double p = std::tanh(std::abs(pop_[i].cost - DF));
            for (unsigned int j = 0; j < d; ++j)
            {
                const double vb = rng_.uniformReal(-a, a), vc = rng_.uniformReal(-b, b);
                const auto A = static_cast<std::size_t>(rng_.uniformInt(0, int(n) - 1));
                const auto B = static_cast<std::size_t>(rng_.uniformInt(0, int(n) - 1));
                const double xa = j < next[A].size() ? next[A][j] : 0.0,
                             xb = j < next[B].size() ? next[B][j] : 0.0;
                // X_best = 0: the reference is the best individual.
                xi[j] = rng_.uniform01() < p ? vb * (w[i][j] * xa - xb) : vc * xi[j];
            }
        }
        for (std::size_t i = 0; i < n; ++i)
        {
            if (stopRequested())
                return false;
            Individual ind;
            if (!decodeEvaluate(next[i], ind))
                return false;
            pop_[i] = std::move(ind);
            x_[i] = next[i];
        }
        updateReference();
        return true;
    }

    bool MemeticSlimeMould::generation(unsigned long t)
    {
        return slimeMouldStep(t);
    }

    // ---------------------------------------------------------------- LRSMA-MEM

    MemeticLRSMA::MemeticLRSMA(const ob::SpaceInformationPtr &si) : MemeticSlimeMould(si, "LRSMA-MEM")
    {
        declareRanged<double>(params(), this, kLevyStep, &MemeticLRSMA::setLevyStep,
                              &MemeticLRSMA::getLevyStep);
        declareRanged<double>(params(), this, kRotationFraction, &MemeticLRSMA::setRotationFraction,
                              &MemeticLRSMA::getRotationFraction);
    }

    void MemeticLRSMA::setLevyStep(double s)
    {
        storeChecked(kLevyStep, levyStep_, s);
    }

    void MemeticLRSMA::setRotationFraction(double f)
    {
        storeChecked(kRotationFraction, rotationFraction_, f);
    }

    void MemeticLRSMA::startAlgorithm()
    {
        MemeticSlimeMould::startAlgorithm();
        const double beta = 1.5, pi = boost::math::constants::pi<double>();
        sigmaU_ = std::pow(std::tgamma(1.0 + beta) * std::sin(pi * beta / 2.0) /
                               (std::tgamma((1.0 + beta) / 2.0) * beta * std::pow(2.0, (beta - 1.0) / 2.0)),
                           1.0 / beta);
        previousBest_ = bestCost();
        flat_ = 0;
    }

    double MemeticLRSMA::levy()
    {
        const double u = rng_.gaussian(0.0, sigmaU_);
        const double v = rng_.gaussian01();
        return u / std::pow(std::abs(v), 1.0 / 1.5);
    }

    bool MemeticLRSMA::generation(unsigned long t)
    {
        if (!slimeMouldStep(t))
            return false;
        const std::size_t n = pop_.size();
        const unsigned int d = stations();
        // Levy flight around the elite (X_best = 0), replacing the worst individual when better.
        std::vector<double> trial(d);
        for (unsigned int index = 0; index < 3; ++index)
        {
            const double alpha = 1.0 + index * rng_.uniformReal(0.0, 0.5);
            for (unsigned int j = 0; j < d; ++j)
                trial[j] = alpha * levyStep_ * 2.0 * offsetBound() * levy();
            if (stopRequested())
                return false;
            Individual ind;
            if (!decodeEvaluate(trial, ind))
                return false;
            std::size_t worst = 0;
            for (std::size_t i = 1; i < n; ++i)
                if (pop_[i].cost > pop_[worst].cost)
                    worst = i;
            if (ind.cost < pop_[worst].cost)
            {
                pop_[worst] = std::move(ind);
                x_[worst] = trial;
                break;
            }
        }
        updateReference();
        // Rotation perturbation on stagnation.
        const double best = bestCost();
        flat_ = std::abs(best - previousBest_) <= 1e-9 * std::abs(best) ? flat_ + 1 : 0;
        previousBest_ = best;
        if (flat_ >= 5)
        {
            flat_ = 0;
            std::vector<std::size_t> order(n);
            std::iota(order.begin(), order.end(), std::size_t(0));
            std::stable_sort(order.begin(), order.end(),
                             [&](std::size_t a, std::size_t b) { return pop_[a].cost < pop_[b].cost; });
            const auto count = static_cast<std::size_t>(std::ceil(rotationFraction_ * double(n) - 1e-9));
            for (std::size_t r = 0; r < count && r < n; ++r)
            {
                const std::size_t i = order[r];
                const std::vector<double> &xi = x_[i];
                double len = 0.0;
                for (double v : xi)
                    len += v * v;
                len = std::sqrt(len);
                const double omega = rng_.uniformReal(0.1, 1.0);
                for (unsigned int j = 0; j < d; ++j)
                {
                    const double xj = j < xi.size() ? xi[j] : 0.0;
                    // A zero position (the reference itself) is rotated by a random vector of length D.
                    trial[j] = len > 0.0 ? xj + omega * rng_.uniformReal(-1.0, 1.0) * xj / len * offsetBound()
                                         : omega * rng_.uniformReal(-1.0, 1.0) * offsetBound();
                }
                if (stopRequested())
                    return false;
                Individual ind;
                if (!decodeEvaluate(trial, ind))
                    return false;
                if (ind.cost < pop_[i].cost)
                {
                    pop_[i] = std::move(ind);
                    x_[i] = trial;
                }
            }
            updateReference();
        }
        return true;
    }

    // ---------------------------------------------------------------- MGO-MEM

    MemeticGazelle::MemeticGazelle(const ob::SpaceInformationPtr &si)
        : OffsetMemeticPlanner(si, "MGO-MEM", 12)
    {
    }

    bool MemeticGazelle::generation(unsigned long t)
    {
        const std::size_t n = pop_.size();
        const unsigned int d = stations();
        const double frac = scheduleFraction(t);
        const double a = -1.0 - frac;
        const std::size_t third = (n + 2) / 3;
        std::vector<std::size_t> perm(n);
        std::iota(perm.begin(), perm.end(), std::size_t(0));
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t p, std::size_t q) { return pop_[p].cost < pop_[q].cost; });
        std::vector<Individual> children;
        std::vector<std::vector<double>> childX;
        std::vector<double> cof(4 * std::size_t(d)), bh(d), f(d), dv(d);
        for (std::size_t i = 0; i < n; ++i)
        {
            std::vector<double> x = x_[i];
            x.resize(d, 0.0);
            const double r3 = rng_.uniform01(), r5 = rng_.uniform01();
            for (unsigned int j = 0; j < d; ++j)
            {
                cof[j] = (a + 1.0) + r3;
                cof[d + j] = a * rng_.gaussian01();
                cof[2 * d + j] = rng_.uniform01();
                const double n3 = rng_.gaussian01(), n4 = rng_.gaussian01();
                cof[3 * d + j] = n3 * n4 * n4 * std::cos(2.0 * r5 * n3);
            }
            auto cofR = [&]() { return cof.data() + std::size_t(rng_.uniformInt(0, 3)) * d; };
            const std::size_t ra =
                order[static_cast<std::size_t>(rng_.uniformInt(int(third) - 1, int(n) - 1))];
            for (std::size_t k = 0; k < third; ++k)
                std::swap(perm[k], perm[static_cast<std::size_t>(rng_.uniformInt(int(k), int(n) - 1))]);
            const double r1 = rng_.uniform01(), r2 = rng_.uniform01();
            auto xj = [&](std::size_t g, unsigned int j) { return j < x_[g].size() ? x_[g][j] : 0.0; };
            for (unsigned int j = 0; j < d; ++j)
            {
                double mean = 0.0;
                for (std::size_t k = 0; k < third; ++k)
                    mean += xj(perm[k], j);
                mean /= double(third);
                bh[j] = xj(ra, j) * std::floor(r1) + mean * std::ceil(r2);
            }
            const double decay = std::exp(2.0 - 2.0 * frac);
            for (unsigned int j = 0; j < d; ++j)
                f[j] = rng_.gaussian01() * decay;
            const double r6 = rng_.uniform01();
            for (unsigned int j = 0; j < d; ++j)
                dv[j] = std::abs(x[j]) * (2.0 * r6 - 1.0); // |X| + |male|, male = 0
            int ri[6];
            for (int &v : ri)
                v = rng_.uniformInt(1, 2);
            const auto xr = static_cast<std::size_t>(rng_.uniformInt(0, int(n) - 1));
            std::vector<double> tsm(d), mh(d), bmh(d), msf;
            {
                const double *cr = cofR();
                for (unsigned int j = 0; j < d; ++j)
                    tsm[j] = -std::abs((ri[0] * bh[j] - ri[1] * x[j]) * f[j]) * cr[j];
            }
            {
                const double *ca = cofR();
                const double *cb = cofR();
                for (unsigned int j = 0; j < d; ++j)
                    mh[j] = (bh[j] + ca[j]) + (-ri[3] * xj(xr, j)) * cb[j];
            }
            {
                const double *cr = cofR();
                for (unsigned int j = 0; j < d; ++j)
                    bmh[j] = (x[j] - dv[j]) + (-ri[5] * bh[j]) * cr[j];
            }
            randomPosition(msf);
            for (std::vector<double> *c : {&tsm, &mh, &bmh, &msf})
            {
                if (stopRequested())
                    return false;
                Individual ind;
                if (!decodeEvaluate(*c, ind))
                    return false;
                children.push_back(std::move(ind));
                childX.push_back(*c);
            }
        }
        // Merge and keep the best N.
        for (std::size_t i = 0; i < n; ++i)
        {
            children.push_back(std::move(pop_[i]));
            childX.push_back(std::move(x_[i]));
        }
        std::vector<std::size_t> idx(children.size());
        std::iota(idx.begin(), idx.end(), std::size_t(0));
        std::stable_sort(idx.begin(), idx.end(),
                         [&](std::size_t p, std::size_t q) { return children[p].cost < children[q].cost; });
        for (std::size_t k = 0; k < n; ++k)
        {
            pop_[k] = std::move(children[idx[k]]);
            x_[k] = std::move(childX[idx[k]]);
        }
        updateReference();
        return true;
    }
} // namespace mhplan

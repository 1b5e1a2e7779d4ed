// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/Operators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_set>

namespace mhplan
{
    PathOperators::PathOperators(PathFitness &fitness, ompl::RNG &rng, const Box &bounds, double step)
        : fitness_(fitness), rng_(rng), bounds_(bounds), step_(step)
    {
        if (fitness.spaceDimension() != 2)
            throw std::invalid_argument("PathOperators: the [GMS] operators are planar; the fitness is "
                                        "configured for dimension " +
                                        std::to_string(fitness.spaceDimension()));
    }

    bool PathOperators::inBounds(const Vec2 &p) const
    {
        return bounds_.contains(p);
    }

    Vec2 PathOperators::randomFreePoint(unsigned int tries)
    {
        Vec2 p;
        for (unsigned int k = 0; k < tries; ++k)
        {
            p = Vec2(rng_.uniformReal(bounds_.xmin, bounds_.xmax),
                     rng_.uniformReal(bounds_.ymin, bounds_.ymax));
            if (fitness_.pointValid(p))
                return p;
        }
        return p;
    }

    bool PathOperators::repairNode(Vec2 &p)
    {
        if (fitness_.pointValid(p))
            return true;
        const double twoPi = 2.0 * kPi;
        const double offset = rng_.uniformReal(0.0, twoPi);
        for (unsigned int k = 1; k <= 200; ++k)
        {
            const double r = k * step_;
            for (unsigned int a = 0; a < 16; ++a)
            {
                const double angle = offset + twoPi * a / 16.0;
                const Vec2 q = p + Vec2(std::cos(angle), std::sin(angle)) * r;
                if (inBounds(q) && fitness_.pointValid(q))
                {
                    p = q;
                    return true;
                }
            }
        }
        return false;
    }

    void PathOperators::repairNodes(std::vector<Vec2> &path)
    {
        for (std::size_t i = 1; i + 1 < path.size(); ++i)
            repairNode(path[i]);
    }

    void PathOperators::repairSegments(std::vector<Vec2> &path, unsigned int maxTries)
    {
        for (std::size_t i = 1; i < path.size(); ++i)
        {
            const Vec2 a = path[i - 1], b = path[i];
            if (fitness_.segmentValid(a, b) || !fitness_.pointValid(a) || !fitness_.pointValid(b))
                continue;
            const double len = distance(a, b);
            if (len <= 0.0)
                continue;
            const Vec2 mid = (a + b) * 0.5;
            const Vec2 normal = Vec2(-(b.y - a.y), b.x - a.x) / len;
            const double delta = std::max(0.02 * len, step_);
            for (unsigned int k = 1; k <= maxTries; ++k)
            {
                const double off = delta * ((k + 1) / 2) * (k % 2 == 1 ? 1.0 : -1.0);
                const Vec2 p = mid + normal * off;
                if (inBounds(p) && fitness_.pointValid(p) && fitness_.segmentValid(a, p) &&
                    fitness_.segmentValid(p, b))
                {
                    path.insert(path.begin() + static_cast<std::ptrdiff_t>(i), p);
                    ++i; // both halves are valid
                    break;
                }
            }
        }
    }

    void PathOperators::simplify(std::vector<Vec2> &path)
    {
        bool changed = true;
        while (changed)
        {
            changed = false;
            for (std::size_t i = 0; i + 2 < path.size();)
            {
                if (fitness_.segmentValid(path[i], path[i + 2]))
                {
                    path.erase(path.begin() + static_cast<std::ptrdiff_t>(i + 1));
                    changed = true;
                }
                else
                    ++i;
            }
        }
    }

    void PathOperators::revise(std::vector<Vec2> &path)
    {
        for (std::size_t i = 0; i < path.size(); ++i)
        {
            // The last visit of path[i] (the goal is never cut away: it is the last point).
            std::size_t last = i;
            for (std::size_t j = i + 1; j < path.size(); ++j)
                if (path[j] == path[i])
                    last = j;
            if (last > i)
                path.erase(path.begin() + static_cast<std::ptrdiff_t>(i + 1),
                           path.begin() + static_cast<std::ptrdiff_t>(last + 1));
        }
    }

    bool PathOperators::improveNodes(std::vector<Vec2> &path)
    {
        if (!fitness_.pathValid(path))
            return false;
        static const double kDirs[8][2] = {
            {1, 0},  {0.7071068, 0.7071068},   {0, 1},  {-0.7071068, 0.7071068},
            {-1, 0}, {-0.7071068, -0.7071068}, {0, -1}, {0.7071068, -0.7071068}};
        double current = fitness_.gmsFeasibleFitness(path);
        for (std::size_t i = 1; i + 1 < path.size(); ++i)
        {
            for (double scale : {4.0, 2.0, 1.0})
            {
                bool moved = false;
                for (const auto &d : kDirs)
                {
                    const Vec2 old = path[i];
                    const Vec2 q = old + Vec2(d[0], d[1]) * (scale * step_);
                    if (!inBounds(q) || !fitness_.segmentValid(path[i - 1], q) ||
                        !fitness_.segmentValid(q, path[i + 1]))
                        continue;
                    path[i] = q;
                    const double f = fitness_.gmsFeasibleFitness(path);
                    if (f < current)
                    {
                        current = f;
                        moved = true;
                        break;
                    }
                    path[i] = old;
                }
                if (moved)
                    break;
            }
        }
        return true;
    }

    bool PathOperators::randomLatticePath(std::vector<Vec2> &path, const Vec2 &start, const Vec2 &goal,
                                          unsigned int maxExpansions, double noise)
    {
        static const int kMoves[8][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1},
                                         {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
        auto key = [](long ix, long iy)
        { return (std::uint64_t(std::uint32_t(ix)) << 32) | std::uint64_t(std::uint32_t(iy)); };
        auto at = [&](long ix, long iy) { return start + Vec2(ix * step_, iy * step_); };
        std::unordered_set<std::uint64_t> visited{key(0, 0)};
        std::vector<std::array<long, 2>> stack{{0, 0}};
        for (unsigned int e = 0; e < maxExpansions && !stack.empty(); ++e)
        {
            const long ix = stack.back()[0], iy = stack.back()[1];
            const Vec2 p = at(ix, iy);
            if (fitness_.segmentValid(p, goal))
            {
                path.clear();
                for (const auto &node : stack)
                    path.push_back(at(node[0], node[1]));
                path.front() = start;
                path.push_back(goal);
                return true;
            }
            const Vec2 toGoal = goal - p;
            const double dist = norm(toGoal);
            double score[8];
            for (int m = 0; m < 8; ++m)
            {
                const Vec2 d(kMoves[m][0], kMoves[m][1]);
                score[m] = visited.count(key(ix + kMoves[m][0], iy + kMoves[m][1])) != 0
                               ? -std::numeric_limits<double>::infinity()
                               : dot(d, toGoal) / (norm(d) * dist) + rng_.uniformReal(0.0, noise);
            }
            bool moved = false;
            for (int tries = 0; tries < 8 && !moved; ++tries)
            {
                const int m = static_cast<int>(std::max_element(score, score + 8) - score);
                if (score[m] == -std::numeric_limits<double>::infinity())
                    break;
                score[m] = -std::numeric_limits<double>::infinity();
                const long jx = ix + kMoves[m][0], jy = iy + kMoves[m][1];
                const Vec2 q = at(jx, jy);
                if (!inBounds(q) || !fitness_.segmentValid(p, q))
                    continue;
                visited.insert(key(jx, jy));
                stack.push_back({jx, jy});
                moved = true;
            }
            if (!moved)
                stack.pop_back(); // a dead end: back out
        }
        return false;
    }
} // namespace mhplan

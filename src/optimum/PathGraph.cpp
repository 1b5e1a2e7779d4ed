// SPDX-License-Identifier: BSD-3-Clause
#include "src/optimum/detail/PathGraph.h"

#include <algorithm>

namespace mhplan
{
    namespace optimum_detail
    {
        void finish(OptimumResult &res, const Graph &g, int s, int t, const Query &query, double scale,
                    const Box &inner, const OptimumOptions &opt)
        {
            double length = kInf;
            const std::vector<int> nodes = g.shortestPath(s, t, length);
            res.graphNodes = g.pos.size();
            res.graphEdges = g.edgeCount;
            if (nodes.empty())
                return;
            res.found = true;
            res.pieces = g.pieces(nodes);
            res.length = 0.0;
            for (const auto &p : res.pieces)
                res.length += p.length;
            if (res.pieces.empty())
                res.path = {query.start, query.goal};
            else
                res.path = piecesToPolyline(res.pieces, opt.arcDeviation * scale, 1e-10 * scale);
            // Points pushed off an arc that touches the bounds return onto them.
            for (Vec2 &p : res.path)
                p = {std::clamp(p.x, inner.xmin, inner.xmax), std::clamp(p.y, inner.ymin, inner.ymax)};
            res.path.front() = query.start;
            res.path.back() = query.goal;
        }
    } // namespace optimum_detail
} // namespace mhplan

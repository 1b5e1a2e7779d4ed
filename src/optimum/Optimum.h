// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: exact shortest paths (the optimum every benchmark run is compared with). */
#ifndef MHPLAN_OPTIMUM_H
#define MHPLAN_OPTIMUM_H

#include "src/base/World.h"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief One piece of an exact optimal path: a straight segment, or an arc of a circle. An arc with
        sweep 0 (length 0) marks a point where the path touches a disc between two segments. */
    struct OptimumPiece
    {
        /** \brief True for an arc, false for a straight segment. */
        bool arc{false};
        /** \brief Where the piece starts. */
        Vec2 from;
        /** \brief Where the piece ends. */
        Vec2 to;
        /** \brief Arcs: the circle's centre (a circle obstacle's centre or a polygon's convex vertex). */
        Vec2 center;
        /** \brief Arcs: the circle's radius (obstacle radius plus robot radius, or the robot radius). */
        double radius{0.0};
        /** \brief Arcs: the angle swept from \e from to \e to (radians, counter-clockwise positive). */
        double sweep{0.0};
        /** \brief Exact length: |to - from| for a segment, radius * |sweep| for an arc. */
        double length{0.0};
    };

    /** \brief The optimum of one (world, query) pair. */
    struct OptimumResult
    {
        /** \brief Exact length of the shortest valid path in metres (arcs measured as arcs); +infinity when
            no path exists. */
        double length{std::numeric_limits<double>::infinity()};
        /** \brief The same length in grid cell units (length / cellSize) for grid worlds; 0 otherwise. */
        double lengthCells{0.0};
        /** \brief A polyline for drawing and for the motion validator: start, the pieces' end points, and
            every arc replaced by a circumscribed polyline (split at the axis directions; vertices at most
            OptimumOptions::arcDeviation times the world's size outside the circle, every chord tangent to
           it), all points on discs pushed outwards by 1e-10 of the world's size, then clamped into the
           admissible box. So the polyline touches no obstacle in floating point and passes the exact motion
           validator, except in degenerate worlds where an arc of the optimum touches another obstacle (not
           the bounds) within the arc deviation. Its length is slightly above \e length; \e length and \e
           pieces are exact. */
        std::vector<Vec2> path;
        /** \brief The exact path as segments and arcs (empty when not found). */
        std::vector<OptimumPiece> pieces;
        /** \brief Wall-clock time spent (graph construction and search), seconds. */
        double seconds{0.0};
        /** \brief Nodes of the (last) graph searched (tangent points, corners or cells, start and goal
            included). */
        std::size_t graphNodes{0};
        /** \brief Undirected edges of the graph searched (segments and arcs). */
        std::size_t graphEdges{0};
        /** \brief True when a path exists. */
        bool found{false};
        /** \brief "tangent-graph", "grid-any-angle", "grid-tangent-graph" or "grid-octile". */
        std::string method;
    };

    /** \brief Options of computeOptimum. */
    struct OptimumOptions
    {
        /** \brief Largest distance of a polyline vertex of \e path outside an arc's circle, relative to the
            world's size (max of width and height); in (0, 0.1]. */
        double arcDeviation{1e-6};
        /** \brief Geometric worlds: index the edges of every polygon of more than 32 vertices in a bucket
            grid, so that checking a segment or arc against it visits only the edges nearby (same results,
            see docs/conventions.md). Only tests turn it off, to compare with the plain per-edge checks. */
        bool polygonEdgeIndex{true};
    };

    /** \brief The exact shortest collision-free path for the world's disc robot, under the validity semantics
        of Collision.h (closed obstacles, touching allowed, the robot's centre inside the bounds shrunk by
        the robot radius r).

        Geometric worlds (circles, polygons, mixed): the reduced visibility (tangent) graph. Every circle of
        radius R becomes a disc of radius R + r; every convex vertex of a polygon (convex or not) becomes a
        disc of radius r (a point when r = 0: the ordinary visibility graph); start and goal are discs of
        radius 0. Nodes are the tangent points of the common tangents of every pair of discs; edges are
        those tangent segments that keep clear of every inflated obstacle and inside the admissible box,
        and the arcs between consecutive tangent points of one disc that do the same. Tangent points inside
        another obstacle or outside the box are discarded; the bounds need no nodes because the admissible
        box is convex (a shortest path may run along it as a straight segment, never bend on it). Checks
        use a tolerance of 1e-9 of the world's size, so paths that touch obstacles are kept. A uniform
        bucket grid over the obstacles makes every segment check visit only the buckets it crosses, and
        polygons of more than 32 vertices get one over their edges, so that a check visits only the edges
        nearby (same results as checking every edge; OptimumOptions::polygonEdgeIndex). Only discs meeting
        the ellipse {x : |x - start| + |x - goal| <= U} and tangent segments that fit on a path of length
        <= U are built, for U = 1.05, then 1.4 times the straight-line distance, then unbounded, until the
        graph's shortest path is no longer than U (then it is the optimum: shorter paths never leave the
        ellipse). A* with the Euclidean heuristic finds the shortest path in the graph, which is the exact
        optimum (shortest paths in the plane among such obstacles consist of tangent segments and arcs of
        these discs).

        Grid worlds, point robot (any-angle): blocked cells are closed squares, cells outside the grid are
        blocked, and a "pinch" corner where two blocked cells meet diagonally blocks passage (see
        GridCollision.h). The optimum is a shortest path in the visibility graph of the convex corners of
        the blocked region (lattice points with exactly one blocked cell among their four), restricted to
        edges taut at both ends; the visible corners of each node are found by an octant sweep of the cells
        (shadow casting, exact slopes from lattice points) and every edge is confirmed exactly by
        GridCollisionModel::segmentValid. Only corners and edges inside the ellipse of the bound U
        are used, U = 1.02 times the straight-line distance first, then the length of the 8-connected
        optimum joined to the exact start and goal (a valid path, so always enough). method
        "grid-any-angle".

        Grid worlds, disc robot (r > 0): the tangent graph above over the blocked cells on the region's
        boundary taken as squares, with discs of radius r at the convex corners of the blocked region only
        (pinches need no rule: the inflated squares overlap there). All pairs of corner discs are tried, so
        grids with more than 4000 convex corners throw InputError. method "grid-tangent-graph".

        Throws InputError for a start or goal that is not valid (validateQuery) and for the too-large disc
        robot grids above; returns found = false when start and goal are not connected. \e seconds includes
        building the collision model used to validate the query. */
    OptimumResult computeOptimum(const World &world, const Query &query, const OptimumOptions &options = {});

    /** \brief Throws InputError "no exact optimum for space S: ..." for an SE(2)-based world (se2, dubins,
        reeds_shepp): computeOptimum and computeGridOctileOptimum call it first. */
    void requirePlanarSpace(const World &world);

    /** \brief The 8-connected grid optimum with MovingAI semantics: moves between free cells, straight moves
        cost 1 cell, diagonal moves sqrt(2) cells and need both side cells free. Start and goal are the free
        cells containing the query's start and goal (a point on a cell border takes a free cell whose closed
        square contains it). \e length is in metres (cells * cellSize) between the cells' centres,
        \e lengthCells in cell units; \e path is the sequence of cell centres. A* with the octile
        heuristic. Throws InputError for a geometric world or a start or goal without a free cell. */
    OptimumResult computeGridOctileOptimum(const World &world, const Query &query);

    /** \brief Optimality gap of a path: (pathLength - optimum) / optimum (0 when the optimum is 0); NaN when
        the optimum was not found. */
    double optimalityGap(double pathLength, const OptimumResult &optimum);

    /** \brief The polyline of a piecewise path: every arc replaced by a circumscribed polyline whose
        vertices lie at most \e maxDeviation outside its circle (chords tangent to it), all points on arcs
        pushed outwards by \e push. Used for OptimumResult::path. */
    std::vector<Vec2> piecesToPolyline(const std::vector<OptimumPiece> &pieces, double maxDeviation,
                                       double push);
} // namespace mhplan

#endif

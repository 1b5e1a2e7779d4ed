// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: path operators of the memetic (-MEM) planners: randomised multi-resolution lattice walks for
   feasible initial paths, local search (shortcuts, pulling waypoints tight, adaptive subdivision), path
   crossover at close points and detour mutation. Planar; validity only through the space information. */
#ifndef MHPLAN_MEMETIC_TOOLKIT_H
#define MHPLAN_MEMETIC_TOOLKIT_H

#include "src/base/Geometry.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/util/RandomNumbers.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

namespace mhplan
{
    using MemeticPath = std::vector<Vec2>;

    /** \brief Path operators of the memetic planners (MemeticPlanner). A path is a polyline of planar points
        from the start to the goal (both never moved). The toolkit sees the problem only through the space
        information: the state space's bounds, the validity checker (isValid) and the motion validator
        (checkMotion); every motion check is counted (motionChecks()).

        Local search (tighten()), the memetic improvement of an individual, repeats passes of
        - shortcut: drop waypoint i when waypoint i-1 sees waypoint i+1;
        - pull tight: move waypoint i toward the closest point of the chord (i-1, i+1), then slide it toward
          each neighbour along the segment to that neighbour (so that a waypoint held by an obstacle corner
          or circle slides into the corner or along the arc); each move is the largest fraction found by
          bisection (\c bisections steps) that keeps both adjacent segments valid; a move never lengthens
          the path (the chord move and the slides cannot, by the triangle inequality); a waypoint none of
          whose moves is possible is held by a contact inside one of its segments (a long segment in a
          narrow corridor touching a corner): in the precise mode (the elite polish) the bisection goes on
          halving down to 1e-9 of the bounds, and the motion validator's last valid point toward the chord
          (checkMotion with lastValid) locates the contact, and a waypoint is inserted there, around which
          the held waypoint can then turn (without this, string pulling stalls in mazes);
        - adaptive subdivision: a waypoint whose turn exceeds \e maxTurn gets the midpoints of its two
          segments inserted (a polyline wrapped round a circle with per-vertex turn x is longer than the arc
          by about x^2 / 12: maxTurn 0.1 bounds that excess to 0.08 % of the arcs); an inserted point is kept
          only when both halves of its segment pass the motion validator (a sampling validator may refuse a
          piece of a segment it accepted);
        until a pass shortens the path by less than \e relTol of its length, or \e maxPasses passes. Only
        waypoints whose neighbourhood changed in the previous pass are moved again.

        Feasible paths (randomWalk()): a randomised weighted best-first search on the lattice start + h (i, j)
        over the 8 compass moves (edge checks by the motion validator, lazily when a node is taken from the
        queue), priority g + w d(goal) (\e weight w: 1 is A*, larger is greedier) with every edge's cost
       multiplied by 1 + noise (1 + f(m)) / 2 at the edge's midpoint m, f a random smooth field in [-1, 1]
       (six plane waves of random direction, phase and wavelength between 1/24 and 1/3 of the bounds'
       diagonal, drawn by randomiseField()): spatially correlated noise, so that walks take different homotopy
       classes (independent noise per edge averages out along a path and sends every walk the same way). A
       walk ends when a node sees the goal within 2 h, when the queue is exhausted (no path at this
       resolution: the caller halves h) or after \e maxExpansions nodes. */
    class MemeticToolkit
    {
      public:
        MemeticToolkit(ompl::base::SpaceInformationPtr si, ompl::RNG &rng);
        ~MemeticToolkit();
        MemeticToolkit(const MemeticToolkit &) = delete;
        MemeticToolkit &operator=(const MemeticToolkit &) = delete;

        /** \brief Bounds of the first two coordinates (points outside are invalid). */
        void setBounds(const Box &bounds) { bounds_ = bounds; }
        const Box &bounds() const { return bounds_; }
        /** \brief Bisection steps of every pull move (4..40). */
        void setBisections(unsigned int n) { bisections_ = n; }

        /** \brief The validator margin (docs/variants.md, "No corner the validator cannot see"): \e m the
            distance at which obstacles beside a segment are looked for (its two copies shifted by m sampled
            every 2m; 0: no margin at all), \e clearance the distance kept from the obstacles found (the
            copies shifted by it checked every 2 x clearance within 2m along the segment of where an obstacle
            was found; 0: a segment with an obstacle within m is refused, the plain sideways-copy margin). The
            start and goal are never shifted. \e minClearance: where the copies on both sides of a window find
            obstacles (a passage narrower than 2 x clearance) the clearance is halved for that window while it
            stays at or above \e minClearance (0 or >= clearance: never). */
        void setMargin(double m, double clearance = 0.0, double minClearance = 0.0)
        {
            margin_ = m;
            clearance_ = clearance;
            minClearance_ = minClearance;
        }
        double margin() const { return margin_; }
        /** \brief The fine check of reported paths (docs/variants.md, "The fine check"): \e spacing the
           motion validator's sample spacing s (the sideways copies fan out from the start and the goal over
           min(s, the segment's length)), \e step the spacing of the validity checker's samples along every
           segment of a path before it is reported (0: no fine check). */
        void setFineCheck(double spacing, double step)
        {
            spacing_ = spacing;
            fineStep_ = step;
        }
        /** \brief The points never shifted by the margin (the query's start and goal). */
        void setFixedPoints(const Vec2 &a, const Vec2 &b)
        {
            fixedA_ = a;
            fixedB_ = b;
        }

        /** \brief The motion validator's verdict on a segment (both ends inside the bounds), and in the
            strict mode (setStrict) the margin's. Counted. */
        bool motionValid(const Vec2 &a, const Vec2 &b);
        /** \brief The strict mode: motionValid() and pathValid() ask the margin too (the paths the planner
            reports, docs/variants.md); the search runs without it. */
        void setStrict(bool strict) { strict_ = strict; }
        bool strict() const { return strict_; }
        /** \brief The strict mode (or, with \e strict false, the loose one) for a scope. */
        class StrictScope
        {
          public:
            explicit StrictScope(MemeticToolkit &t, bool strict = true) : t_(t), old_(t.strict_)
            {
                t_.strict_ = strict;
            }
            ~StrictScope() { t_.strict_ = old_; }
            StrictScope(const StrictScope &) = delete;
            StrictScope &operator=(const StrictScope &) = delete;

          private:
            MemeticToolkit &t_;
            bool old_;
        };
        /** \brief Make \e path pass the strict mode and the fine check: the waypoints of every segment the
            margin refuses are shifted away from the obstacle it found (or pushed outward, away from their
            neighbours' chord, 2c, 4c, ... up to 8 rounds; a push whose point is invalid is halved down to 2 x
            the smallest clearance, for narrow passages); a segment the fine check refuses gets a waypoint
            beside its first failing sample (mendBeside). True when every segment passes both (always without
            a margin). \e refused, when given, receives the number of segments the margin still refuses at
            the end. */
        bool makeStrict(MemeticPath &path, const std::function<bool()> &stop, std::size_t *refused = nullptr);
        /** \brief An approximate path made reportable: makeStrict() (at most its 12 rounds), then cut before
            its first segment that still fails the strict mode or the fine check. */
        void makeReportablePrefix(MemeticPath &path);
        /** \brief Segments the margin checked (a check of its own, beside motionChecks()). */
        unsigned long marginChecks() const { return marginChecks_; }
        /** \brief motionValid(); when invalid, \e fraction is the motion validator's last valid fraction
            of the segment (checkMotion with lastValid). Counted. */
        bool motionValid(const Vec2 &a, const Vec2 &b, double &fraction);
        /** \brief Every segment of \e path passes motionValid(). */
        bool pathValid(const MemeticPath &path);
        /** \brief The validity checker's verdict on a point inside the bounds. */
        bool pointValid(const Vec2 &p);
        unsigned long motionChecks() const { return motionChecks_; }
        /** \brief Verdicts of motionValid(a, b) answered from the segment cache (not counted as checks). */
        unsigned long cacheHits() const { return cacheHits_; }
        void resetCounts()
        {
            motionChecks_ = 0;
            marginChecks_ = 0;
            cacheHits_ = 0;
        }
        /** \brief Forget every cached segment verdict (a new problem, clear()). The cache is keyed by the
            exact coordinates of the segment's two ends and holds valid and invalid verdicts (margin
            included), up to 2^20 entries, then starts over (docs/variants.md, "Checks"). */
        void clearCache();

        /** \brief Lazy roadmap (docs/variants.md, "First paths: a lazy roadmap"): forget every sample. */
        void roadmapClear();
        /** \brief Rebuild the roadmap on \e start, \e goal, the kept samples and \e n new ones drawn
            uniformly in the bounds, keeping only samples q with |start q| + |q goal| < \e bound (the
            informed set of the incumbent: a point outside it lies on no shorter path; infinity keeps all);
            each sample costs one validity check, the edges (k nearest, k = 4.1 ln n) none until used.
            Penalties restart. */
        void roadmapGrow(unsigned int n, const Vec2 &start, const Vec2 &goal, double bound);
        /** \brief The next path of the roadmap: the shortest under the penalties (A*), its unknown edges
            checked in order (motion validator, cached); an invalid edge is removed and the search repeated
            (lazy PRM). On success the path's nodes and their neighbours are penalised, so that the next
            call returns another route (the penalty method for alternative routes). False when the start is
            cut off from the goal in the roadmap, after \e maxInvalid refused edges, or when stopped. */
        bool roadmapPath(MemeticPath &path, unsigned int maxInvalid, const std::function<bool()> &stop);
        std::size_t roadmapSize() const { return rmPoints_.size(); }
        /** \brief The tube reroute (docs/variants.md, "The tube reroute"): a separate lazy roadmap of \e n
            states drawn within \e radius of points drawn uniformly along \e path (a state costs one validity
            check; invalid ones are dropped), its ends and k-nearest edges; into \e out its shortest route
            from the path's start to its end (A*, the route's unknown edges checked, an invalid one removed
            and the search repeated, at most \e maxInvalid times). The path's own waypoints are not nodes, so
            the route is the tube's shortest in whatever homotopy class, not the path again. False when the
            tube holds no route, or when stopped. */
        bool tubeRoute(const MemeticPath &path, double radius, unsigned int n, unsigned int maxInvalid,
                       MemeticPath &out, const std::function<bool()> &stop);

        enum class WalkResult
        {
            Found,     ///< \e path runs from start to goal, every segment valid
            Exhausted, ///< no path on this lattice
            Budget,    ///< maxExpansions reached
            Stopped    ///< \e stop() became true
        };
        /** \brief One randomised lattice walk with step \e h (see the class doc). On Found \e path is the
            lattice path (start, nodes, goal); \e closest is updated with the node closest to the goal seen
            so far (for approximate solutions) when it is closer than \e closestDistance. */
        WalkResult randomWalk(MemeticPath &path, const Vec2 &start, const Vec2 &goal, double h, double noise,
                              unsigned int maxExpansions, const std::function<bool()> &stop,
                              MemeticPath &closest, double &closestDistance, double weight = 2.0);

        /** \brief Draw a new random field for the following walks, wavelengths between \e size / 24 and
            \e size / 3 (the bounds' diagonal for whole walks, the span of a re-walk). */
        void randomiseField(double size);

        /** \brief Greedy shortcut: from each kept waypoint jump to the farthest later waypoint it sees
            (doubling, then bisection on the index). */
        void shortcut(MemeticPath &path, const std::function<bool()> &stop);
        /** \brief Local search (class doc); returns false when \e stop() interrupted it (the path is valid
            and no longer than before either way). \e afterPass, when given, sees the path after each pass
            (an anytime report of a long tightening). */
        bool tighten(MemeticPath &path, double maxTurn, double relTol, unsigned int maxPasses,
                     const std::function<bool()> &stop, unsigned int maxPoints = 4000, bool precise = false,
                     const std::function<void(const MemeticPath &)> &afterPass = nullptr);

        /** \brief Crossover: child = a[..p] -> b[q..] (one point) or a[..p1] -> b[q1..q2] -> a[p2..] (two
            points), joined where the parents pass within \e radius of each other (resampled at 48 points
            each), through the motion validator. False when no joint was found in a few tries. */
        bool splice(const MemeticPath &a, const MemeticPath &b, double radius, bool twoPoint,
                    MemeticPath &child);
        /** \brief Detour mutation: replace the piece between arc positions s1 < s2 (span a random share of
            the length, heavier for larger \e scale) by two segments through a random point off the chord;
            false when no valid detour was found in a few tries. */
        bool detour(MemeticPath &path, double scale);

        /** \brief Flip mutation: move a random turning waypoint to the other side of the chord of its
            neighbours (its mirror image, then 1.5 and 2.5 times as far), so that the path passes the obstacle
            that held it on the other side; false when no mirrored point gave valid segments (4 waypoints
            tried). */
        bool flip(MemeticPath &path);

        /** \brief Re-walk mutation: replace the piece between arc positions s1 < s2 (span a random share of
            the length, heavier for larger \e scale) by a new randomised lattice walk between its ends (step
            span / 24, field wavelengths from span / 8 to span, at most \e maxExpansions nodes, a fresh random
           field of strength \e noise); false when the walk did not connect them. */
        bool rewalk(MemeticPath &path, double scale, double noise, unsigned int maxExpansions,
                    const std::function<bool()> &stop);

        /** \brief \e n points at equal arc length (first = start, last = goal). */
        static void resample(const MemeticPath &path, unsigned int n, MemeticPath &out);
        static double length(const MemeticPath &path);
        /** \brief The point at arc length \e s and the index of the segment it is on. */
        static Vec2 pointAt(const MemeticPath &path, double s, std::size_t &segment);
        /** \brief Largest turn angle at an interior waypoint (0 for a straight path). */
        static double maxTurnAngle(const MemeticPath &path);

      private:
        /** \brief One pull-tight pass; returns true when a waypoint moved or was dropped. */
        bool pullPass(MemeticPath &path, std::vector<char> &dirty, const std::function<bool()> &stop);
        bool subdivide(MemeticPath &path, std::vector<char> &dirty, double maxTurn, unsigned int maxPoints);
        /** \brief Largest t in [0, 1] (bisection) with a -> v + t d -> b valid (t = 0 assumed valid). */
        double bisectMove(const Vec2 &a, const Vec2 &v, const Vec2 &d, const Vec2 &b);
        bool inBounds(const Vec2 &p) const { return bounds_.contains(p); }
        bool marginValid(const Vec2 &a, const Vec2 &b);
        /** \brief The strict verdict of a segment and its fine check (cached; docs/variants.md). */
        bool reportableSegment(const Vec2 &a, const Vec2 &b);
        /** \brief The validity checker at the fine step along a -> b (ends excluded), the samples of the
            arc window [from, to] of the segment only; false with \e t the first failing sample's fraction. */
        bool fineCheck(const Vec2 &a, const Vec2 &b, double &t, double from = 0.0,
                       double to = std::numeric_limits<double>::infinity());
        /** \brief Insert a waypoint beside the first sample of segment i - 1 -> i the fine check refused:
            shifted sideways by c, 2c, 4c, ... up to 4 s, the first shift (either side, the shorter) whose
            point and motions the validator accepts and whose new segments pass the fine check within s of
            it. False when none does. */
        bool mendBeside(MemeticPath &path, std::size_t i);
        /** \brief The margin refused a -> b with obstacles on both sides at the smallest clearance, and one
           of the segment's own points within 2 s of the refusal (every c) is inside an obstacle: its fraction
            replaces the refusal's (refusedAt), for mendBeside. Looked at once per segment. */
        bool crossesObstacle(const Vec2 &a, const Vec2 &b);
        /** \brief The fine check refused the segment (cached verdict). */
        bool fineRefused(const Vec2 &a, const Vec2 &b) const;
        /** \brief The fine check's samples of a -> b near the points where it once failed (hazards_);
            false with \e t the first failing sample's fraction. */
        bool nearHazardsValid(const Vec2 &a, const Vec2 &b, double &t);
        /** \brief Where the fine check failed (a sample inside an obstacle), at most 2^16. */
        MemeticPath hazards_;
        bool checkPoint(const Vec2 &p);
        void pushOut(MemeticPath &path, std::size_t j, double step);
        /** \brief Twice the smallest clearance the margin accepts: the least a shift is halved to. */
        double smallestShift() const;
        /** \brief \e base + \e dir x h for h = \e step, halved down to smallestShift(), the first that is
           valid with both motions from \e a and to \e b (the validator's verdicts); false when none is. */
        bool validShift(const Vec2 &base, const Vec2 &dir, double step, const Vec2 &a, const Vec2 &b,
                        Vec2 &q);
        /** \brief Shift waypoint j by \e step along the unit \e dir (halved while the result is invalid). */
        void shiftAway(MemeticPath &path, std::size_t j, const Vec2 &dir, double step);
        /** \brief Insert a waypoint before i where the margin met a one-sided obstacle on path[i - 1] ->
            path[i], shifted by \e step along the unit \e dir; false (nothing inserted) when that place is
            within s of an end or no shifted point is valid with both motions. */
        bool insertAway(MemeticPath &path, std::size_t i, const Vec2 &dir, double step);
        /** \brief The side (+1 left of a -> b, -1 right, 0 unknown) of the obstacle for which the margin
            refused the segment (cached verdict), and in \e clearance the clearance it was refused at. */
        int refusedSide(const Vec2 &a, const Vec2 &b, double &clearance) const;
        int hitSide_{0};
        int hitLevel_{0};
        double hitAt_{0.5}; ///< where along the segment the margin refused it (a fraction)
        bool strict_{false};
        unsigned long marginChecks_{0};
        double margin_{0.0};
        double clearance_{0.0};
        double minClearance_{0.0};
        double spacing_{0.0};
        double fineStep_{0.0};
        std::vector<std::pair<double, double>> windows_;
        Vec2 fixedA_, fixedB_;

        ompl::base::SpaceInformationPtr si_;
        ompl::RNG &rng_;
        Box bounds_;
        unsigned int bisections_{10};
        /** \brief tighten(precise): tiny moves and contact splits (the elite polish). */
        bool precise_{false};
        ompl::base::State *a_{nullptr};
        ompl::base::State *b_{nullptr};
        ompl::base::State *c_{nullptr};
        unsigned long motionChecks_{0};
        unsigned long cacheHits_{0};

      public:
        /** \brief A segment by the exact coordinates of its two ends (the caches' key). */
        struct SegmentKey
        {
            double ax, ay, bx, by;
            bool operator==(const SegmentKey &o) const
            {
                return ax == o.ax && ay == o.ay && bx == o.bx && by == o.by;
            }
        };

      private:
        /** \brief The verdict cache and where refused segments were refused (detail/SegmentCaches.h). */
        struct SegmentCaches;
        std::unique_ptr<SegmentCaches> caches_;
        /** \brief Cache a new verdict (the cache starts over at 2^20 entries); its code, to update at once.
         */
        char &remember(const SegmentKey &key, char code);
        /** \brief The strict verdict code of a segment the validator accepts (the margin, the hazards' fine
            check); records where it was refused. */
        char strictCode(const Vec2 &a, const Vec2 &b, const SegmentKey &key);

        // The lazy roadmap: points (0 = start, 1 = goal), edges with a state (0 unknown, 1 valid, 2 invalid).
        struct RoadmapEdge
        {
            std::uint32_t a, b;
            double length;
            char state;
        };
        /** \brief Symmetric k-nearest edges (k = 4.1 ln n) of \e points (within \e box), none checked. */
        static void nearestEdges(const MemeticPath &points, const Box &box, std::vector<RoadmapEdge> &edges,
                                 std::vector<std::vector<std::uint32_t>> &adjacent);
        /** \brief A* over a lazy roadmap from point 0 to point 1 under \e penalty; unknown edges of each
           route are checked, invalid ones skipped by the next search. False when cut off, after \e maxInvalid
            refused edges or when stopped; else the route's point indices in \e nodes. */
        bool lazyRoute(const MemeticPath &points, std::vector<RoadmapEdge> &edges,
                       const std::vector<std::vector<std::uint32_t>> &adjacent,
                       const std::vector<double> &penalty, unsigned int maxInvalid,
                       const std::function<bool()> &stop, std::vector<std::uint32_t> &nodes);
        MemeticPath rmPoints_;
        std::vector<RoadmapEdge> rmEdges_;
        std::vector<std::vector<std::uint32_t>> rmAdjacent_; ///< edge ids per point
        std::vector<double> rmPenalty_;

        // Walk buffers (reused).
        struct Node
        {
            long ix, iy;
            std::uint32_t parent;
            double g;
            bool closed;
        };
        std::vector<Node> nodes_;
        std::unordered_map<std::uint64_t, std::uint32_t> index_;
        MemeticPath sa_, sb_;
        struct Wave
        {
            double kx, ky, phase, amplitude;
        };
        std::vector<Wave> field_;
        double fieldAt(const Vec2 &p) const;
    };
} // namespace mhplan

#endif

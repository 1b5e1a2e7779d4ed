// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: collision models of a World for a disc robot. Every planner, metric and tool goes through one of
   these (wrapped by the OMPL validity checker and motion validator in Validity.h). */
#ifndef MHPLAN_COLLISION_H
#define MHPLAN_COLLISION_H

#include "src/base/World.h"

#include <memory>
#include <string>

namespace mhplan
{
    /** \brief Exact collision queries for the disc robot of a World.

        Semantics shared by all implementations (the analytic model is the oracle for the others):
        - clearance(p): signed distance from the robot disc centred at p to the nearest obstacle, i.e. the
          distance from p to the obstacle set minus the robot radius (negative when the disc overlaps an
          obstacle; for a point inside an obstacle, minus the penetration depth minus the radius). The
          world's bounds are \b not obstacles for clearance; +infinity when there is no obstacle.
        - isValid(p): the disc lies inside the bounds (p within [xmin + r, xmax - r] x [ymin + r, ymax - r])
          and clearance(p) >= -e, e = contactTolerance() (touching an obstacle is allowed: obstacles are
          closed, free space is closed too; e absorbs rounding, docs/contact.md).
        - segmentValid(a, b): every point of the closed segment has clearance >= -e / 2 (exact, no
          sampling), so every point computed along it passes isValid.
        - segmentClearance(a, b): the minimum of clearance over the segment.
        Implementations are immutable after construction and safe to query from several threads. */
    class CollisionModel
    {
      public:
        explicit CollisionModel(const World &world);
        virtual ~CollisionModel() = default;

        virtual double clearance(const Vec2 &p) const = 0;
        virtual bool isValid(const Vec2 &p) const;
        virtual bool segmentValid(const Vec2 &a, const Vec2 &b) const = 0;
        virtual double segmentClearance(const Vec2 &a, const Vec2 &b) const = 0;
        /** \brief Short name of the back end ("analytic", "fcl", "grid", "hash"). */
        virtual std::string name() const = 0;

        /** \brief True when the robot disc centred at p lies inside the world's bounds. */
        bool inBounds(const Vec2 &p) const
        {
            return p.x >= inner_.xmin && p.x <= inner_.xmax && p.y >= inner_.ymin && p.y <= inner_.ymax;
        }
        /** \brief True when the whole segment keeps the disc inside the bounds (the box is convex). */
        bool segmentInBounds(const Vec2 &a, const Vec2 &b) const { return inBounds(a) && inBounds(b); }

        double robotRadius() const { return radius_; }
        /** \brief The contact tolerance e of docs/contact.md (ContactRule.h): a point is valid when it
            penetrates by at most e, a segment when it penetrates by at most e / 2 everywhere. */
        double contactTolerance() const { return tol_; }
        const Box &bounds() const { return bounds_; }

      protected:
        Box bounds_;
        /** \brief Bounds shrunk by the robot radius: the admissible positions of the disc's centre. */
        Box inner_;
        double radius_;
        double tol_;
    };

    using CollisionModelPtr = std::shared_ptr<const CollisionModel>;

    /** \brief Brute-force exact model over circles and polygons: the test oracle, and the fastest choice for
        worlds with few obstacles. */
    class AnalyticCollisionModel : public CollisionModel
    {
      public:
        explicit AnalyticCollisionModel(const World &world);
        double clearance(const Vec2 &p) const override;
        bool isValid(const Vec2 &p) const override;
        bool segmentValid(const Vec2 &a, const Vec2 &b) const override;
        double segmentClearance(const Vec2 &a, const Vec2 &b) const override;
        std::string name() const override { return "analytic"; }

        /** \brief The circle obstacles (used by fitness functions with a per-circle formula). */
        const std::vector<Circle> &circles() const { return circles_; }
        /** \brief The polygon obstacles. */
        const std::vector<Polygon> &polygons() const { return polygons_; }

      private:
        std::vector<Circle> circles_;
        std::vector<Polygon> polygons_;
    };

    /** \brief Which collision back end to build. */
    enum class CollisionBackend
    {
        Auto,     ///< grid model for grids; analytic for small geometric worlds, the spatial hash otherwise
        Analytic, ///< brute force (geometric worlds only)
        FCL,      ///< FCL broadphase with exact narrow phase (geometric worlds only)
        Grid,     ///< occupancy grid with exact Euclidean distance transform (grid worlds only)
        Hash      ///< uniform bucket grid over the analytic tests (geometric worlds only; SpatialHash.h)
    };

    /** \brief Parse "auto", "analytic", "fcl", "grid", "hash"; throws InputError listing the accepted names.
     */
    CollisionBackend parseCollisionBackend(const std::string &name);
    std::string toString(CollisionBackend backend);

    /** \brief Geometric worlds with at most this many obstacles use the analytic model under Auto, larger
       ones the spatial hash (a point check at 10,000 circles costs about what it costs at 12). */
    constexpr std::size_t kAutoAnalyticMaxObstacles = 64;

    /** \brief Build the collision model of a world; throws InputError if the back end does not fit the
        world type. */
    CollisionModelPtr makeCollisionModel(const World &world,
                                         CollisionBackend backend = CollisionBackend::Auto);
} // namespace mhplan

#endif

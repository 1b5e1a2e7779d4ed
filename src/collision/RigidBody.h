// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: collision queries for a rigid robot (a polygon, or a disc) at an SE(2) pose, through FCL, and the
   independent check of the same question with mhplan's own geometry (docs/spaces.md, "Rigid-body and car
   worlds"). */
#ifndef MHPLAN_RIGID_BODY_H
#define MHPLAN_RIGID_BODY_H

#include "src/base/World.h"

#include <cmath>
#include <memory>
#include <vector>

namespace mhplan
{
    /** \brief A planar pose: position and heading (radians, counter-clockwise from +x). */
    struct Pose2
    {
        double x{0.0};
        double y{0.0};
        double yaw{0.0};
    };

    /** \brief The world-frame point of robot-frame point \e v at pose \e p. */
    inline Vec2 placePoint(const Pose2 &p, const Vec2 &v)
    {
        const double c = std::cos(p.yaw);
        const double s = std::sin(p.yaw);
        return {p.x + c * v.x - s * v.y, p.y + s * v.x + c * v.y};
    }

    /** \brief The robot of an SE(2)-based world against its obstacles (circles, polygons or an occupancy
       grid) through FCL: the robot is a prism over its polygon (split into convex pieces when it is not
       convex) or a cylinder (a disc robot; a point robot is a disc of radius 1e-9), every obstacle a prism or
       cylinder (a grid's blocked cells as rectangular prisms, one per horizontal run of blocked cells; FCL's
       own GJK solver, the robot first in every pair: docs/spaces.md says why), all of one height so that
       FCL's 3D distances are the planar ones.

        - inBounds(p): every point of the robot lies in the closed bounds (every vertex of the polygon, or
          the disc).
        - boundsDistance(p): how far the robot is from leaving the bounds (min over the polygon's vertices of
          the distance to the four sides, or the centre's minus the radius; negative when outside).
        - isValid(p): inBounds(p) and FCL's collision test finds no contact between the robot and any
          obstacle. Obstacles and the robot are closed sets and touching is allowed, as everywhere in mhplan;
          exact touching is decided by FCL's GJK within its tolerance, so a pose in exact contact may go
          either way (the motion validator never accepts such a pose: it needs a positive distance).
        - clearance(p): FCL's distance from the robot to the nearest obstacle minus a safety margin (which
          covers GJK's tolerance: margin() = 1e-5 (1 + the scene's largest coordinate)), so a lower bound of
          the true distance; a negative value (-1) when FCL finds a contact; +infinity without obstacles.
        Immutable after construction; queries share nothing mutable (safe from several threads). */
    class RigidBodyModel
    {
      public:
        explicit RigidBodyModel(const World &world);
        ~RigidBodyModel();
        RigidBodyModel(const RigidBodyModel &) = delete;
        RigidBodyModel &operator=(const RigidBodyModel &) = delete;

        bool inBounds(const Pose2 &p) const;
        double boundsDistance(const Pose2 &p) const;
        bool isValid(const Pose2 &p) const;
        double clearance(const Pose2 &p) const;
        /** \brief min(clearance(p), boundsDistance(p)): the distance every robot point may move from pose p
            without touching an obstacle or leaving the bounds (what the motion validator certifies with). */
        double freeDistance(const Pose2 &p) const;

        /** \brief The distance subtracted from FCL's distances. */
        double margin() const;
        /** \brief The farthest robot point from the robot's origin (polygon vertex, or the disc radius). */
        double reach() const { return reach_; }
        /** \brief The radius that rotation moves robot points on: reach() for a polygon, 0 for a disc (a disc
            is the same set at every heading). */
        double rotationReach() const { return polygon_.empty() ? 0.0 : reach_; }
        /** \brief The robot polygon in its own frame (empty for a disc robot). */
        const std::vector<Vec2> &polygon() const { return polygon_; }
        double radius() const { return radius_; }
        const Box &bounds() const { return bounds_; }

      private:
        struct Impl;
        std::unique_ptr<Impl> impl_;
        std::vector<Vec2> polygon_;
        double radius_{0.0};
        double reach_{0.0};
        Box bounds_;
    };

    using RigidBodyModelPtr = std::shared_ptr<const RigidBodyModel>;

    /** \brief The robot polygon of a world placed at pose \e p (empty for a disc robot). */
    std::vector<Vec2> placedRobot(const World &world, const Pose2 &p);

    /** \brief Independent check of one pose with mhplan's own geometry (src/base/Geometry.h), no FCL: true
       when the robot lies in the closed bounds and overlaps the interior of no obstacle. Polygon robot: no
       edge of the placed polygon crosses an obstacle polygon's edge properly, no vertex of either lies
       strictly inside the other, and the signed distance of every circle's centre to the polygon is at least
       the radius; disc robot: the analytic disc tests. Grid worlds: every blocked cell overlapping the
       robot's bounding box is a square polygon. Touching is allowed. */
    bool independentPoseFree(const World &world, const Pose2 &p);

    /** \brief Independent lower-bound-free distance used by tests: the planar distance of the placed robot to
        the nearest obstacle by Geometry.h (0 when they overlap), ignoring the bounds; +infinity without
        obstacles. */
    double independentPoseDistance(const World &world, const Pose2 &p);
} // namespace mhplan

#endif

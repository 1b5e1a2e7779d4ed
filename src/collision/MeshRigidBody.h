// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: a rigid mesh robot among mesh obstacles in SE(2) or SE(3), as OMPL.app's rigid-body problems
   (docs/meshes.md): the validity checker, the certified conservative motion validator, the independent
   dense path check and the OMPL set-up. */
#ifndef MHPLAN_MESH_RIGID_BODY_H
#define MHPLAN_MESH_RIGID_BODY_H

#include "src/collision/Mesh.h"
#include "src/collision/Problem.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>

#include <atomic>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief The state space of a rigid problem: SE(2) (planar), SE(3), or R^3 (translation only, the
        robot keeps the orientation of its file; docs/worlds3d.md). */
    enum class RigidSpace
    {
        SE2,
        SE3,
        R3
    };

    /** \brief "se2", "se3" or "r3". */
    std::string toString(RigidSpace space);

    /** \brief One obstacle of a scene: a shape (mesh, box or sphere) at a fixed placement. */
    struct SceneObstacle
    {
        std::shared_ptr<const MeshShape> shape;
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};
        /** \brief Its triangles for pictures and exports (a box's 12, a sphere's coarse polyhedron, a mesh's
            own), in the scene's frame. */
        TriangleMesh drawn;
    };

    /** \brief A robot against obstacles. The mesh robot is moved so that the mean of its vertices
        (OMPL.app's robot centre; for a planar problem only in x and y) is its origin, the point a state's
        position places and its rotation turns about; a sphere robot (radius 0: a point) is centred on it.
        A planar (SE(2)) robot stays at z = 0 and turns about +z. Meshes are surfaces: touching or crossing
        triangles is a contact (a robot wholly inside a closed mesh obstacle is not, as in OMPL.app); boxes
        and spheres are solid. Immutable; queries are safe from several threads. */
    class MeshRigidModel
    {
      public:
        /** \brief OMPL.app's problem: one environment mesh, one robot mesh, SE(2) or SE(3). */
        MeshRigidModel(const TriangleMesh &environment, const TriangleMesh &robot, bool planar);
        /** \brief A scene of obstacles and a mesh robot (docs/worlds3d.md). */
        MeshRigidModel(std::vector<SceneObstacle> obstacles, const TriangleMesh &robot, RigidSpace space);
        /** \brief A scene of obstacles and a sphere robot of \e radius (0: a point). */
        MeshRigidModel(std::vector<SceneObstacle> obstacles, double radius, RigidSpace space);

        bool planar() const { return space_ == RigidSpace::SE2; }
        RigidSpace space() const { return space_; }
        /** \brief The robot's placement for a state of the SE(2), SE(3) or R^3 state space. */
        Eigen::Isometry3d placement(const ompl::base::State *state) const;
        /** \brief True when the robot at \e pose touches an obstacle (FCL's collide). */
        bool collides(const Eigen::Isometry3d &pose) const;
        /** \brief FCL's distance from the robot at \e pose to the nearest obstacle minus margin(): a lower
            bound of the true distance, <= 0 at a contact. */
        double clearance(const Eigen::Isometry3d &pose) const;
        /** \brief What clearance() subtracts: 1e-6 (1 + the scene's largest coordinate), above FCL's
            rounding. */
        double margin() const { return margin_; }
        /** \brief The farthest robot vertex from the robot's origin: the radius its rotation moves points on
            (0 for a sphere robot, which a rotation about its centre leaves in place). */
        double reach() const { return reach_; }
        /** \brief The robot's shift (minus its vertex centroid) and the meshes as used (a scene's obstacles
            and a sphere robot as drawn, for pictures and exports). */
        const Eigen::Vector3d &robotShift() const { return shift_; }
        const TriangleMesh &environmentMesh() const { return environment_; }
        const TriangleMesh &robotMesh() const { return robot_; }
        /** \brief The triangles of the mesh obstacles and of the robot (0 for a sphere robot). */
        std::size_t environmentTriangles() const;
        std::size_t robotTriangles() const { return robotShape_->triangleCount(); }
        const std::vector<SceneObstacle> &obstacles() const { return obstacles_; }
        /** \brief The sphere robot's radius; negative for a mesh robot. */
        double robotRadius() const { return radius_; }

      private:
        void finish();

        RigidSpace space_;
        std::vector<SceneObstacle> obstacles_;
        TriangleMesh environment_;
        TriangleMesh robot_;
        Eigen::Vector3d shift_{Eigen::Vector3d::Zero()};
        std::unique_ptr<MeshShape> robotShape_;
        double radius_{-1.0};
        double reach_{0.0};
        double margin_{0.0};
    };

    /** \brief A box's 12 triangles (edge lengths \e size, centred on the origin) and a sphere's coarse
        polyhedron (vertices on the sphere), for pictures. */
    TriangleMesh boxTriangles(const Eigen::Vector3d &size, const Eigen::Isometry3d &pose);
    TriangleMesh sphereTriangles(double radius, const Eigen::Vector3d &center);

    using MeshRigidModelPtr = std::shared_ptr<const MeshRigidModel>;

    /** \brief The bound on how far any robot point moves along the motion s1 -> s2 as OMPL's SE(2) or SE(3)
        space interpolates it: the distance of the positions plus reach times the rotation angle (the
        heading change the shorter way round, or the angle between the quaternions); interpolation is
        uniform in the path parameter, so the piece [ta, tb] has the bound (tb - ta) times this
        (docs/meshes.md, "Certified motions"). */
    double meshMotionBound(const MeshRigidModel &model, const ompl::base::State *s1,
                           const ompl::base::State *s2);
    /** \brief meshMotionBound for a motion of \e space: on mhplan's Dubins space (SafeDubinsStateSpace) and
        OMPL's Reeds-Shepp space the curve's length plus reach times the heading it turns (its length over
        the turning radius), else the SE(2)/SE(3) bound above. */
    double meshMotionBound(const MeshRigidModel &model, const ompl::base::StateSpace &space,
                           const ompl::base::State *s1, const ompl::base::State *s2);

    /** \brief Valid: the state's position within the space's bounds and no contact (as OMPL.app's FCL
        checker); clearance: MeshRigidModel::clearance. */
    class MeshValidityChecker : public ompl::base::StateValidityChecker
    {
      public:
        MeshValidityChecker(const ompl::base::SpaceInformationPtr &si, MeshRigidModelPtr model);
        bool isValid(const ompl::base::State *state) const override;
        double clearance(const ompl::base::State *state) const override;

      private:
        MeshRigidModelPtr model_;
    };

    /** \brief The certified conservative motion validator on meshes: from the start of the motion it steps
        along the path parameter, each step as long as the clearance d at its start allows (d divided by
        meshMotionBound), so that no robot point of any pose inside the step comes within d of where it was,
        hence none touches an obstacle. A motion is refused when a step's clearance falls below
        \e resolution (metres; conservative: it passes about that close to an obstacle) or the end lies
        outside the bounds; the positions move on a segment, so bounds hold between two ends inside them. */
    class MeshCertifiedMotionValidator : public ompl::base::MotionValidator
    {
      public:
        MeshCertifiedMotionValidator(const ompl::base::SpaceInformationPtr &si, MeshRigidModelPtr model,
                                     double resolution);
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
        bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                         std::pair<ompl::base::State *, double> &lastValid) const override;
        /** \brief Clearance evaluations since construction. */
        std::size_t evaluations() const { return evaluations_; }

      private:
        /** The parameter up to which the motion is certified (1 when it all is). */
        double certify(const ompl::base::State *s1, const ompl::base::State *s2) const;

        MeshRigidModelPtr model_;
        double resolution_;
        mutable std::atomic<std::size_t> evaluations_{0};
    };

    /** \brief A pose of a problem: position, and orientation (for SE(2) a rotation about +z). */
    struct RigidPose
    {
        Eigen::Vector3d position{Eigen::Vector3d::Zero()};
        Eigen::Quaterniond orientation{Eigen::Quaterniond::Identity()};
    };

    /** \brief Everything an OMPL set-up of a mesh problem needs (docs/meshes.md). */
    struct MeshProblemSpec
    {
        MeshRigidModelPtr model;
        /** \brief The positions' bounds (x, y, and z for SE(3)). */
        Eigen::AlignedBox3d volume;
        RigidPose start;
        RigidPose goal;
        /** \brief A planar problem's car: "" (SE(2)), "dubins" (forward only) or "reeds_shepp" (forward and
            back), turning with \c turningRadius (OMPL.app's statespace and turningradius keys). */
        std::string car;
        double turningRadius{1.0};
        /** \brief Goal tolerance in the state space's distance. */
        double threshold{1e-6};
        /** \brief "length" or "max_min_clearance". */
        std::string objective{"length"};
        /** \brief The objective's cost threshold; NaN: the objective's default. */
        double objectiveThreshold{std::numeric_limits<double>::quiet_NaN()};
        /** \brief "certified" (MeshCertifiedMotionValidator) or "discrete" (OMPL's DiscreteMotionValidator,
            OMPL.app's set-up, at longestValidSegmentFraction of the space's extent). */
        std::string motionValidator{"certified"};
        double longestValidSegmentFraction{0.01};
        /** \brief The certified validator's resolution in metres; NaN: 1e-4 of the volume's diagonal. */
        double resolution{std::numeric_limits<double>::quiet_NaN()};
        /** \brief Space information parameters (OMPL's names, e.g. longest_valid_segment_fraction) and
            "sampler" (uniform, gaussian, obstacle_based, max_clearance), as OMPL.app's problem context. */
        std::map<std::string, std::string> context;
    };

    /** \brief Apply a problem context (MeshProblemSpec::context) to a set-up's space information; throws
        InputError naming an unknown key or a value OMPL refuses. */
    void applyMeshContext(const ompl::base::SpaceInformationPtr &si,
                          const std::map<std::string, std::string> &context);

    /** \brief The SE(2) or SE(3) set-up of \e spec: space and bounds, validity checker, motion validator,
        start and goal (refused, InputError, when invalid), objective; its space information is set up, the
        planner and SimpleSetup::setup() are left to the caller. */
    ompl::geometric::SimpleSetupPtr makeMeshSetup(const MeshProblemSpec &spec);
    /** \brief makeMeshSetup, configuring the object \e make returns (a campaign's runs use a subclass). */
    ompl::geometric::SimpleSetupPtr makeMeshSetup(const MeshProblemSpec &spec,
                                                  const SimpleSetupFactory &make);

    /** \brief Write a pose into a state of the SE(2) (heading from the orientation about +z) or SE(3) space.
     */
    void setRigidState(ompl::base::State *state, const RigidPose &pose, bool planar);
    /** \brief The same for \e space (R^3: the position only). */
    void setRigidState(ompl::base::State *state, const RigidPose &pose, RigidSpace space);
    /** \brief The robot's placement at \e pose in \e space (SE(2): at z = 0 turned about +z only; R^3: the
        position only). */
    Eigen::Isometry3d rigidPlacement(const RigidPose &pose, RigidSpace space);

    /** \brief Independent dense check of a path (docs/meshes.md): every motion followed as the space
        interpolates it at poses no robot point moves more than \e step between, each tested by FCL's
        collide (not the distance the validators use) and against the bounds. Returns the number of poses
        checked; \e firstContact gets the index of the first motion in contact, or -1. */
    std::size_t denseMeshPathCheck(const MeshRigidModel &model, const ompl::base::SpaceInformation &si,
                                   const ompl::geometric::PathGeometric &path, double step,
                                   long &firstContact);
} // namespace mhplan

#endif

// SPDX-License-Identifier: BSD-3-Clause
#include "src/collision/MeshRigidBody.h"

#include "src/base/World.h"
#include "src/collision/CarSpaces.h"

#include <ompl/base/goals/GoalState.h>
#include <ompl/base/objectives/MaximizeMinClearanceObjective.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/samplers/GaussianValidStateSampler.h>
#include <ompl/base/samplers/MaximizeClearanceValidStateSampler.h>
#include <ompl/base/samplers/ObstacleBasedValidStateSampler.h>
#include <ompl/base/samplers/UniformValidStateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include <cmath>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{
    std::string toString(RigidSpace space)
    {
        return space == RigidSpace::SE2 ? "se2" : space == RigidSpace::SE3 ? "se3" : "r3";
    }

    TriangleMesh boxTriangles(const Eigen::Vector3d &size, const Eigen::Isometry3d &pose)
    {
        TriangleMesh m;
        m.source = "box";
        for (int i = 0; i < 8; ++i)
            m.vertices.push_back(pose * Eigen::Vector3d(((i & 1) ? 0.5 : -0.5) * size.x(),
                                                        ((i & 2) ? 0.5 : -0.5) * size.y(),
                                                        ((i & 4) ? 0.5 : -0.5) * size.z()));
        // Two triangles per face: corners differing in one coordinate bit.
        const std::uint32_t faces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                           {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
        for (const auto &f : faces)
        {
            m.triangles.push_back({f[0], f[1], f[2]});
            m.triangles.push_back({f[0], f[2], f[3]});
        }
        return m;
    }

    TriangleMesh sphereTriangles(double radius, const Eigen::Vector3d &center)
    {
        // A latitude-longitude polyhedron: 8 slices round, 6 stacks, vertices on the sphere.
        TriangleMesh m;
        m.source = "sphere";
        const int slices = 8, stacks = 6;
        m.vertices.push_back(center + Eigen::Vector3d(0, 0, radius));
        for (int i = 1; i < stacks; ++i)
            for (int j = 0; j < slices; ++j)
            {
                const double th = M_PI * i / stacks, ph = 2.0 * M_PI * j / slices;
                m.vertices.push_back(center + radius * Eigen::Vector3d(std::sin(th) * std::cos(ph),
                                                                       std::sin(th) * std::sin(ph),
                                                                       std::cos(th)));
            }
        m.vertices.push_back(center - Eigen::Vector3d(0, 0, radius));
        const auto at = [&](int i, int j)
        { return static_cast<std::uint32_t>(1 + (i - 1) * slices + j % slices); };
        const auto bottom = static_cast<std::uint32_t>(m.vertices.size() - 1);
        for (int j = 0; j < slices; ++j)
        {
            m.triangles.push_back({0, at(1, j), at(1, j + 1)});
            m.triangles.push_back({bottom, at(stacks - 1, j + 1), at(stacks - 1, j)});
            for (int i = 1; i + 1 < stacks; ++i)
            {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
        return m;
    }

    MeshRigidModel::MeshRigidModel(const TriangleMesh &environment, const TriangleMesh &robot, bool planar)
        : MeshRigidModel({SceneObstacle{std::make_shared<const MeshShape>(environment),
                                        Eigen::Isometry3d::Identity(), environment}},
                         robot, planar ? RigidSpace::SE2 : RigidSpace::SE3)
    {
    }

    MeshRigidModel::MeshRigidModel(std::vector<SceneObstacle> obstacles, const TriangleMesh &robot,
                                   RigidSpace space)
        : space_(space), obstacles_(std::move(obstacles))
    {
        Eigen::Vector3d centre = robot.vertexCentroid();
        if (planar())
            centre.z() = 0.0;
        shift_ = -centre;
        robot_ = robot.translated(shift_);
        robotShape_ = std::make_unique<MeshShape>(robot_);
        reach_ = robot_.reachFrom(Eigen::Vector3d::Zero());
        finish();
    }

    MeshRigidModel::MeshRigidModel(std::vector<SceneObstacle> obstacles, double radius, RigidSpace space)
        : space_(space), obstacles_(std::move(obstacles)), radius_(radius)
    {
        robotShape_ = MeshShape::sphere(radius);
        if (radius > 0.0)
            robot_ = sphereTriangles(radius, Eigen::Vector3d::Zero());
        robot_.source = radius > 0.0 ? "sphere robot" : "point robot";
        reach_ = 0.0; // a rotation about the centre leaves a ball in place
        finish();
    }

    void MeshRigidModel::finish()
    {
        if (obstacles_.empty())
            throw InputError("a scene needs at least one obstacle");
        double extent = std::max(reach_, std::max(radius_, 0.0));
        for (const auto &o : obstacles_)
        {
            // The environment as drawn: every obstacle's triangles in one mesh.
            const auto base = static_cast<std::uint32_t>(environment_.vertices.size());
            environment_.vertices.insert(environment_.vertices.end(), o.drawn.vertices.begin(),
                                         o.drawn.vertices.end());
            for (const auto &t : o.drawn.triangles)
                environment_.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
            const Eigen::AlignedBox3d box = o.drawn.box();
            if (!box.isEmpty())
                extent = std::max({extent, box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff()});
        }
        environment_.source = obstacles_.size() == 1 ? obstacles_.front().drawn.source : "scene";
        margin_ = 1e-6 * (1.0 + extent);
    }

    std::size_t MeshRigidModel::environmentTriangles() const
    {
        std::size_t n = 0;
        for (const auto &o : obstacles_)
            n += o.shape->triangleCount();
        return n;
    }

    Eigen::Isometry3d MeshRigidModel::placement(const ob::State *state) const
    {
        Eigen::Isometry3d tf = Eigen::Isometry3d::Identity();
        if (space_ == RigidSpace::SE2)
        {
            const auto *s = state->as<ob::SE2StateSpace::StateType>();
            tf.translation() = Eigen::Vector3d(s->getX(), s->getY(), 0.0);
            tf.linear() = Eigen::AngleAxisd(s->getYaw(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
        }
        else if (space_ == RigidSpace::SE3)
        {
            const auto *s = state->as<ob::SE3StateSpace::StateType>();
            const auto &r = s->rotation();
            tf.translation() = Eigen::Vector3d(s->getX(), s->getY(), s->getZ());
            tf.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
        }
        else
        {
            const double *v = state->as<ob::RealVectorStateSpace::StateType>()->values;
            tf.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
        }
        return tf;
    }

    bool MeshRigidModel::collides(const Eigen::Isometry3d &pose) const
    {
        for (const auto &o : obstacles_)
            if (robotShape_->collides(pose, *o.shape, o.pose))
                return true;
        return false;
    }

    double MeshRigidModel::clearance(const Eigen::Isometry3d &pose) const
    {
        double d = std::numeric_limits<double>::infinity();
        for (const auto &o : obstacles_)
        {
            d = std::min(d, robotShape_->distance(pose, *o.shape, o.pose));
            if (d <= 0.0)
                break;
        }
        return d - margin_;
    }

    double meshMotionBound(const MeshRigidModel &model, const ob::State *s1, const ob::State *s2)
    {
        double translation = 0.0, angle = 0.0;
        if (model.space() == RigidSpace::R3)
        {
            const double *a = s1->as<ob::RealVectorStateSpace::StateType>()->values;
            const double *b = s2->as<ob::RealVectorStateSpace::StateType>()->values;
            return std::sqrt(std::pow(b[0] - a[0], 2) + std::pow(b[1] - a[1], 2) + std::pow(b[2] - a[2], 2));
        }
        if (model.planar())
        {
            const auto *a = s1->as<ob::SE2StateSpace::StateType>();
            const auto *b = s2->as<ob::SE2StateSpace::StateType>();
            translation = std::hypot(b->getX() - a->getX(), b->getY() - a->getY());
            // OMPL's SO(2) turns the shorter way round: at most pi.
            angle = std::fabs(std::remainder(b->getYaw() - a->getYaw(), 2.0 * M_PI));
        }
        else
        {
            const auto *a = s1->as<ob::SE3StateSpace::StateType>();
            const auto *b = s2->as<ob::SE3StateSpace::StateType>();
            translation = std::sqrt(std::pow(b->getX() - a->getX(), 2) + std::pow(b->getY() - a->getY(), 2) +
                                    std::pow(b->getZ() - a->getZ(), 2));
            const auto &p = a->rotation();
            const auto &q = b->rotation();
            const double dot = std::fabs(p.x * q.x + p.y * q.y + p.z * q.z + p.w * q.w) /
                               std::sqrt((p.x * p.x + p.y * p.y + p.z * p.z + p.w * p.w) *
                                         (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w));
            // OMPL's SO(3) interpolates on the shorter arc (slerp): the rotation angle is 2 acos |<p, q>|.
            angle = 2.0 * std::acos(std::min(1.0, dot));
        }
        return translation + model.reach() * angle;
    }

    namespace
    {
        /** A car's space: OMPL interpolates along its Dubins or Reeds-Shepp curve. */
        bool isCarSpace(const ob::StateSpace &space)
        {
            return dynamic_cast<const ob::DubinsStateSpace *>(&space) != nullptr ||
                   dynamic_cast<const ob::ReedsSheppStateSpace *>(&space) != nullptr;
        }
    } // namespace

    double meshMotionBound(const MeshRigidModel &model, const ob::StateSpace &space, const ob::State *s1,
                           const ob::State *s2)
    {
        // A car's interpolation runs along its Dubins or Reeds-Shepp curve at constant speed in the path
        // parameter: the position moves by at most the curve's length rho * n, the heading turns by at most n
        // radians (n the curve's length in units of rho: arcs of radius rho, straight lines do not turn).
        if (const auto *d = dynamic_cast<const SafeDubinsStateSpace *>(&space))
        {
            const double n = d->shortestPath(s1, s2).length(); // the path its interpolation follows
            return n * (d->turningRadius() + model.reach());
        }
        if (dynamic_cast<const ob::DubinsStateSpace *>(&space) != nullptr)
            throw InputError("meshMotionBound: a Dubins space other than mhplan's (SafeDubinsStateSpace)");
        if (const auto *r = dynamic_cast<const ob::ReedsSheppStateSpace *>(&space))
            return r->distance(s1, s2) + model.reach() * r->reedsShepp(s1, s2).length();
        return meshMotionBound(model, s1, s2);
    }

    MeshValidityChecker::MeshValidityChecker(const ob::SpaceInformationPtr &si, MeshRigidModelPtr model)
        : ob::StateValidityChecker(si), model_(std::move(model))
    {
        specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::BOUNDED_APPROXIMATE;
    }

    bool MeshValidityChecker::isValid(const ob::State *state) const
    {
        return si_->satisfiesBounds(state) && !model_->collides(model_->placement(state));
    }

    double MeshValidityChecker::clearance(const ob::State *state) const
    {
        return model_->clearance(model_->placement(state));
    }

    MeshCertifiedMotionValidator::MeshCertifiedMotionValidator(const ob::SpaceInformationPtr &si,
                                                               MeshRigidModelPtr model, double resolution)
        : ob::MotionValidator(si), model_(std::move(model)), resolution_(resolution)
    {
        if (!(resolution > 0.0) || !std::isfinite(resolution))
            throw std::invalid_argument("the certified motion validator's resolution must be > 0");
    }

    double MeshCertifiedMotionValidator::certify(const ob::State *s1, const ob::State *s2) const
    {
        const double bound = meshMotionBound(*model_, *si_->getStateSpace(), s1, s2);
        // A car's curve may leave the bounds between its ends: the position's distance to the bounds counts
        // as a clearance too (the position moves no faster than the bound allows, docs/meshes.md).
        const bool curved = isCarSpace(*si_->getStateSpace());
        ob::State *pose = si_->allocState();
        double t = 0.0;
        double certified = 0.0;
        while (true)
        {
            si_->getStateSpace()->interpolate(s1, s2, t, pose);
            ++evaluations_;
            double d = model_->clearance(model_->placement(pose));
            if (curved)
            {
                const auto *q = pose->as<ob::SE2StateSpace::StateType>();
                const ob::RealVectorBounds &box = si_->getStateSpace()->as<ob::SE2StateSpace>()->getBounds();
                d = std::min({d, q->getX() - box.low[0], box.high[0] - q->getX(), q->getY() - box.low[1],
                              box.high[1] - q->getY()});
            }
            if (!(d >= resolution_))
                break; // too close to certify (or in contact): refused, certified up to t
            certified = t;
            if (bound <= 0.0 || t + d / bound >= 1.0)
            {
                certified = 1.0;
                break;
            }
            t += d / bound;
        }
        si_->freeState(pose);
        return certified;
    }

    bool MeshCertifiedMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2) const
    {
        const bool ok = si_->satisfiesBounds(s2) && si_->satisfiesBounds(s1) && certify(s1, s2) >= 1.0;
        if (ok)
            valid_++;
        else
            invalid_++;
        return ok;
    }

    bool MeshCertifiedMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2,
                                                   std::pair<ob::State *, double> &lastValid) const
    {
        double t = si_->satisfiesBounds(s1) ? certify(s1, s2) : 0.0;
        if (t >= 1.0 && !si_->satisfiesBounds(s2))
            t = 0.0;
        const bool ok = t >= 1.0;
        if (!ok)
        {
            if (lastValid.first != nullptr)
            {
                si_->getStateSpace()->interpolate(s1, s2, t, lastValid.first);
                // A planner takes the motion s1 -> lastValid.first as valid. On a car's space that motion is
                // the shortest curve between them, which need not be the prefix just certified: it is
                // certified on its own, halving t until it is (or t is 0).
                const bool curved = isCarSpace(*si_->getStateSpace());
                for (int halving = 0; curved && t > 0.0 && certify(s1, lastValid.first) < 1.0; ++halving)
                {
                    t = halving < 30 ? 0.5 * t : 0.0;
                    si_->getStateSpace()->interpolate(s1, s2, t, lastValid.first);
                }
            }
            lastValid.second = t;
            invalid_++;
        }
        else
            valid_++;
        return ok;
    }

    void setRigidState(ob::State *state, const RigidPose &pose, RigidSpace space)
    {
        if (space != RigidSpace::R3)
            return setRigidState(state, pose, space == RigidSpace::SE2);
        double *v = state->as<ob::RealVectorStateSpace::StateType>()->values;
        for (int i = 0; i < 3; ++i)
            v[i] = pose.position[i];
    }

    Eigen::Isometry3d rigidPlacement(const RigidPose &pose, RigidSpace space)
    {
        Eigen::Isometry3d tf = Eigen::Isometry3d::Identity();
        tf.translation() = pose.position;
        if (space == RigidSpace::SE2)
        {
            tf.translation().z() = 0.0;
            const Eigen::Vector3d x = pose.orientation * Eigen::Vector3d::UnitX();
            tf.linear() =
                Eigen::AngleAxisd(std::atan2(x.y(), x.x()), Eigen::Vector3d::UnitZ()).toRotationMatrix();
        }
        else if (space == RigidSpace::SE3)
            tf.linear() = pose.orientation.normalized().toRotationMatrix();
        return tf;
    }

    void setRigidState(ob::State *state, const RigidPose &pose, bool planar)
    {
        if (planar)
        {
            auto *s = state->as<ob::SE2StateSpace::StateType>();
            s->setXY(pose.position.x(), pose.position.y());
            const Eigen::Vector3d x = pose.orientation * Eigen::Vector3d::UnitX();
            // atan2 answers in [-pi, pi], OMPL's SO(2) holds [-pi, pi): a heading of pi (a goal.theta of
            // 3.141592653589793, as OMPL.app's problem files write it) is the same heading as -pi.
            double yaw = std::atan2(x.y(), x.x());
            if (yaw >= M_PI)
                yaw -= 2.0 * M_PI;
            s->setYaw(yaw);
        }
        else
        {
            auto *s = state->as<ob::SE3StateSpace::StateType>();
            s->setXYZ(pose.position.x(), pose.position.y(), pose.position.z());
            const Eigen::Quaterniond q = pose.orientation.normalized();
            s->rotation().x = q.x();
            s->rotation().y = q.y();
            s->rotation().z = q.z();
            s->rotation().w = q.w();
        }
    }

    void applyMeshContext(const ob::SpaceInformationPtr &si,
                          const std::map<std::string, std::string> &context)
    {
        si->clearValidStateSamplerAllocator();
        for (const auto &[key, value] : context)
        {
            if (key == "sampler")
            {
                ob::ValidStateSamplerAllocator alloc;
                if (value == "uniform")
                    alloc = [](const ob::SpaceInformation *s)
                    { return std::make_shared<ob::UniformValidStateSampler>(s); };
                else if (value == "gaussian")
                    alloc = [](const ob::SpaceInformation *s)
                    { return std::make_shared<ob::GaussianValidStateSampler>(s); };
                else if (value == "obstacle_based")
                    alloc = [](const ob::SpaceInformation *s)
                    { return std::make_shared<ob::ObstacleBasedValidStateSampler>(s); };
                else if (value == "max_clearance")
                    alloc = [](const ob::SpaceInformation *s)
                    { return std::make_shared<ob::MaximizeClearanceValidStateSampler>(s); };
                else
                    throw InputError("sampler '" + value +
                                     "': expected uniform, gaussian, obstacle_based or max_clearance");
                si->setValidStateSamplerAllocator(alloc);
                continue;
            }
            if (!si->params().hasParam(key))
            {
                std::vector<std::string> names;
                si->params().getParamNames(names);
                std::string list = "sampler";
                for (const auto &n : names)
                    list += ", " + n;
                throw InputError("unknown problem setting '" + key + "'; accepted: " + list);
            }
            if (!si->params().setParam(key, value))
                throw InputError("problem setting '" + key + "': OMPL does not accept '" + value + "'");
        }
    }

    namespace
    {
        /** The first \e dims coordinates of \e volume as OMPL bounds. */
        ob::RealVectorBounds positionBounds(const Eigen::AlignedBox3d &volume, int dims)
        {
            ob::RealVectorBounds b(static_cast<unsigned>(dims));
            for (int i = 0; i < dims; ++i)
            {
                b.setLow(static_cast<unsigned>(i), volume.min()[i]);
                b.setHigh(static_cast<unsigned>(i), volume.max()[i]);
            }
            return b;
        }
    } // namespace

    og::SimpleSetupPtr makeMeshSetup(const MeshProblemSpec &spec)
    {
        return makeMeshSetup(spec, nullptr);
    }

    og::SimpleSetupPtr makeMeshSetup(const MeshProblemSpec &spec, const SimpleSetupFactory &make)
    {
        const bool planar = spec.model->planar();
        ob::StateSpacePtr space;
        if (spec.model->space() == RigidSpace::R3)
        {
            auto r3 = std::make_shared<ob::RealVectorStateSpace>(3);
            r3->setBounds(positionBounds(spec.volume, 3));
            space = r3;
        }
        else if (planar)
        {
            std::shared_ptr<ob::SE2StateSpace> se2;
            if (spec.car == "dubins")
                se2 = std::make_shared<SafeDubinsStateSpace>(spec.turningRadius);
            else if (spec.car == "reeds_shepp")
                se2 = std::make_shared<ob::ReedsSheppStateSpace>(spec.turningRadius);
            else if (spec.car.empty())
                se2 = std::make_shared<ob::SE2StateSpace>();
            else
                throw InputError("car '" + spec.car + "': expected dubins or reeds_shepp");
            se2->setBounds(positionBounds(spec.volume, 2));
            space = se2;
        }
        else
        {
            auto se3 = std::make_shared<ob::SE3StateSpace>();
            se3->setBounds(positionBounds(spec.volume, 3));
            space = se3;
        }
        const og::SimpleSetupPtr ss = make ? make(space) : std::make_shared<og::SimpleSetup>(space);
        const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
        ss->setStateValidityChecker(std::make_shared<MeshValidityChecker>(si, spec.model));
        si->setStateValidityCheckingResolution(spec.longestValidSegmentFraction);
        if (spec.motionValidator == "certified")
        {
            const double resolution = std::isnan(spec.resolution)
                                          ? 1e-4 * spec.volume.diagonal().head(planar ? 2 : 3).norm()
                                          : spec.resolution;
            si->setMotionValidator(
                std::make_shared<MeshCertifiedMotionValidator>(si, spec.model, resolution));
        }
        else if (spec.motionValidator != "discrete")
            throw InputError("motion validator '" + spec.motionValidator +
                             "': expected certified or discrete");
        applyMeshContext(si, spec.context);
        si->setup(); // the planner and SimpleSetup::setup() are the caller's

        ob::ScopedState<> start(space), goal(space);
        setRigidState(start.get(), spec.start, spec.model->space());
        setRigidState(goal.get(), spec.goal, spec.model->space());
        for (const auto &[what, state] :
             {std::pair<const char *, const ob::State *>{"start", start.get()}, {"goal", goal.get()}})
        {
            if (!si->satisfiesBounds(state))
                throw InputError(std::string("the ") + what + " pose lies outside the volume");
            if (!si->isValid(state))
                throw InputError(std::string("the ") + what + " pose is in collision");
        }
        ss->setStartAndGoalStates(start, goal, spec.threshold);
        ob::OptimizationObjectivePtr objective;
        if (spec.objective == "length")
            objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
        else if (spec.objective == "max_min_clearance")
            objective = std::make_shared<ob::MaximizeMinClearanceObjective>(si);
        else
            throw InputError("objective '" + spec.objective + "': expected length or max_min_clearance");
        if (!std::isnan(spec.objectiveThreshold))
            objective->setCostThreshold(ob::Cost(spec.objectiveThreshold));
        ss->setOptimizationObjective(objective);
        return ss;
    }

    std::size_t denseMeshPathCheck(const MeshRigidModel &model, const ob::SpaceInformation &si,
                                   const og::PathGeometric &path, double step, long &firstContact)
    {
        firstContact = -1;
        std::size_t checked = 0;
        ob::State *pose = si.allocState();
        // The volume holds positions: OMPL's SO(2) holds [-pi, pi), but its interpolation toward a heading
        // of -pi can end at +pi, the same heading; the test sees the heading folded into the range.
        const auto *se2 = dynamic_cast<const ob::SE2StateSpace *>(si.getStateSpace().get());
        const auto inVolume = [&](ob::State *s)
        {
            if (se2 != nullptr)
                se2->getSubspace(1)->enforceBounds(s->as<ob::SE2StateSpace::StateType>()->components[1]);
            return si.satisfiesBounds(s);
        };
        const std::size_t n = path.getStateCount();
        for (std::size_t i = 0; i < n && firstContact < 0; ++i)
        {
            const ob::State *a = path.getState(i);
            const ob::State *b = i + 1 < n ? path.getState(i + 1) : a;
            const double bound = meshMotionBound(model, *si.getStateSpace(), a, b);
            const auto pieces = static_cast<std::size_t>(std::ceil(bound / step));
            const std::size_t last = i + 1 < n ? pieces : 0;
            for (std::size_t k = 0; k <= last; ++k)
            {
                si.getStateSpace()->interpolate(a, b, pieces == 0 ? 0.0 : double(k) / double(pieces), pose);
                ++checked;
                if (!inVolume(pose) || model.collides(model.placement(pose)))
                {
                    firstContact = static_cast<long>(i);
                    break;
                }
            }
        }
        si.freeState(pose);
        return checked;
    }
} // namespace mhplan

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
#include <ompl/base/spaces/SE3StateSpace.h>

#include <cmath>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{
    MeshRigidModel::MeshRigidModel(const TriangleMesh &environment, const TriangleMesh &robot, bool planar)
        : planar_(planar), environment_(environment)
    {
        Eigen::Vector3d centre = robot.vertexCentroid();
        if (planar)
            centre.z() = 0.0;
        shift_ = -centre;
        robot_ = robot.translated(shift_);
        envShape_ = std::make_unique<MeshShape>(environment_);
        robotShape_ = std::make_unique<MeshShape>(robot_);
        reach_ = robot_.reachFrom(Eigen::Vector3d::Zero());
        double extent = reach_;
        const Eigen::AlignedBox3d box = environment_.box();
        if (!box.isEmpty())
            extent = std::max({extent, box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff()});
        margin_ = 1e-6 * (1.0 + extent);
    }

    Eigen::Isometry3d MeshRigidModel::placement(const ob::State *state) const
    {
        Eigen::Isometry3d tf = Eigen::Isometry3d::Identity();
        if (planar_)
        {
            const auto *s = state->as<ob::SE2StateSpace::StateType>();
            tf.translation() = Eigen::Vector3d(s->getX(), s->getY(), 0.0);
            tf.linear() = Eigen::AngleAxisd(s->getYaw(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
        }
        else
        {
            const auto *s = state->as<ob::SE3StateSpace::StateType>();
            const auto &r = s->rotation();
            tf.translation() = Eigen::Vector3d(s->getX(), s->getY(), s->getZ());
            tf.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
        }
        return tf;
    }

    bool MeshRigidModel::collides(const Eigen::Isometry3d &pose) const
    {
        return robotShape_->collides(pose, *envShape_, Eigen::Isometry3d::Identity());
    }

    double MeshRigidModel::clearance(const Eigen::Isometry3d &pose) const
    {
        return robotShape_->distance(pose, *envShape_, Eigen::Isometry3d::Identity()) - margin_;
    }

    double meshMotionBound(const MeshRigidModel &model, const ob::State *s1, const ob::State *s2)
    {
        double translation = 0.0, angle = 0.0;
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

    void setRigidState(ob::State *state, const RigidPose &pose, bool planar)
    {
        if (planar)
        {
            auto *s = state->as<ob::SE2StateSpace::StateType>();
            s->setXY(pose.position.x(), pose.position.y());
            const Eigen::Vector3d x = pose.orientation * Eigen::Vector3d::UnitX();
            s->setYaw(std::atan2(x.y(), x.x()));
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

    og::SimpleSetupPtr makeMeshSetup(const MeshProblemSpec &spec)
    {
        return makeMeshSetup(spec, nullptr);
    }

    og::SimpleSetupPtr makeMeshSetup(const MeshProblemSpec &spec, const SimpleSetupFactory &make)
    {
        const bool planar = spec.model->planar();
        ob::StateSpacePtr space;
        if (planar)
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
            ob::RealVectorBounds b(2);
            for (int i = 0; i < 2; ++i)
            {
                b.setLow(i, spec.volume.min()[i]);
                b.setHigh(i, spec.volume.max()[i]);
            }
            se2->setBounds(b);
            space = se2;
        }
        else
        {
            auto se3 = std::make_shared<ob::SE3StateSpace>();
            ob::RealVectorBounds b(3);
            for (int i = 0; i < 3; ++i)
            {
                b.setLow(i, spec.volume.min()[i]);
                b.setHigh(i, spec.volume.max()[i]);
            }
            se3->setBounds(b);
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
        setRigidState(start.get(), spec.start, planar);
        setRigidState(goal.get(), spec.goal, planar);
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
                if (!si.satisfiesBounds(pose) || model.collides(model.placement(pose)))
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

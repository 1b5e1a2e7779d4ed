// SPDX-License-Identifier: BSD-3-Clause
#include "src/collision/RigidValidity.h"

#include "src/collision/CarSpaces.h"

#include <ompl/base/spaces/SE2StateSpace.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{
    Pose2 statePose(const ob::State *state)
    {
        const auto *s = state->as<ob::SE2StateSpace::StateType>();
        return {s->getX(), s->getY(), s->getYaw()};
    }

    void setStatePose(ob::State *state, const Pose2 &p)
    {
        auto *s = state->as<ob::SE2StateSpace::StateType>();
        s->setXY(p.x, p.y);
        s->setYaw(p.yaw);
    }

    namespace
    {
        /** The heading change of OMPL's SO(2) interpolation: the shorter way round, in [0, pi]. */
        double headingChange(double a, double b)
        {
            double d = std::fmod(std::fabs(a - b), 2.0 * kPi);
            return d > kPi ? 2.0 * kPi - d : d;
        }
    } // namespace

    SpaceMotion::SpaceMotion(const ob::StateSpace *space, SpaceType type, double rotationReach,
                             double turningRadius, const ob::State *from, const ob::State *to)
        : space_(space), type_(type), from_(from), to_(to)
    {
        switch (type)
        {
        case SpaceType::Dubins:
            if (const auto *safe = dynamic_cast<const SafeDubinsStateSpace *>(space))
                dubins_ = safe->shortestPath(from, to);
            else
                dubins_ = space->as<ob::DubinsStateSpace>()->dubins(from, to);
            length_ = turningRadius * dubins_.length();
            bound_ = length_ * (1.0 + rotationReach / turningRadius);
            break;
        case SpaceType::ReedsShepp:
            reedsShepp_ = space->as<ob::ReedsSheppStateSpace>()->reedsShepp(from, to);
            length_ = turningRadius * reedsShepp_.length();
            bound_ = length_ * (1.0 + rotationReach / turningRadius);
            break;
        default:
        {
            const Pose2 a = statePose(from);
            const Pose2 b = statePose(to);
            length_ = space->distance(from, to);
            bound_ = std::hypot(b.x - a.x, b.y - a.y) + rotationReach * headingChange(a.yaw, b.yaw);
        }
        }
    }

    void SpaceMotion::at(double t, ob::State *out) const
    {
        bool firstTime = false; // the path is computed: interpolate along it
        if (t <= 0.0)
            space_->copyState(out, from_);
        else if (t >= 1.0)
            space_->copyState(out, to_);
        else if (type_ == SpaceType::Dubins)
            space_->as<ob::DubinsStateSpace>()->interpolate(from_, to_, t, firstTime, dubins_, out);
        else if (type_ == SpaceType::ReedsShepp)
            space_->as<ob::ReedsSheppStateSpace>()->interpolate(from_, to_, t, firstTime, reedsShepp_, out);
        else
            space_->interpolate(from_, to_, t, out);
    }

    RigidValidityChecker::RigidValidityChecker(const ob::SpaceInformationPtr &si, RigidBodyModelPtr model)
        : CountingStateValidityChecker(si), model_(std::move(model))
    {
        specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::BOUNDED_APPROXIMATE;
        specs_.hasValidDirectionComputation = false;
    }

    bool RigidValidityChecker::isValid(const ob::State *state) const
    {
        countCheck();
        return model_->isValid(statePose(state));
    }

    bool RigidValidityChecker::isValid(const ob::State *state, double &dist) const
    {
        countCheck();
        const Pose2 p = statePose(state);
        dist = model_->clearance(p);
        return model_->inBounds(p) && dist >= 0.0;
    }

    double RigidValidityChecker::clearance(const ob::State *state) const
    {
        return model_->clearance(statePose(state));
    }

    CertifiedMotionValidator::CertifiedMotionValidator(const ob::SpaceInformationPtr &si,
                                                       RigidBodyModelPtr model, SpaceType type,
                                                       double turningRadius, double resolution)
        : ob::MotionValidator(si), model_(std::move(model)), type_(type), turningRadius_(turningRadius),
          resolution_(resolution)
    {
        if (!(resolution > 0.0))
            throw std::invalid_argument("CertifiedMotionValidator: resolution must be > 0");
    }

    namespace
    {
        /** A piece [ta, tb] of a motion with the free distances at its ends. */
        struct Piece
        {
            double ta, tb, fa, fb;
        };
    } // namespace

    double CertifiedMotionValidator::certify(const ob::State *s1, const ob::State *s2, bool prefix) const
    {
        const double f1 = model_->freeDistance(statePose(s1));
        const double f2 = model_->freeDistance(statePose(s2));
        evaluations_ += 2;
        if (!(f1 > 0.0))
            return 0.0;
        const SpaceMotion motion(si_->getStateSpace().get(), type_, model_->rotationReach(), turningRadius_,
                                 s1, s2);
        const double total = motion.bound();
        if (total < std::max(f1, f2))
            return 1.0;
        ob::State *mid = si_->allocState();
        std::vector<Piece> stack;
        stack.reserve(64);
        // A non-free end certifies nothing: the pieces next to it are halved down to the resolution.
        stack.push_back({0.0, 1.0, f1, std::max(f2, 0.0)});
        double certified = 0.0; // pieces are certified left to right: [0, certified] is safe
        bool failed = false;
        while (!stack.empty())
        {
            const Piece p = stack.back();
            stack.pop_back();
            const double d = (p.tb - p.ta) * total;
            if (d < std::max(p.fa, p.fb))
            {
                certified = p.tb;
                continue;
            }
            if (d < resolution_)
            {
                failed = true;
                break; // nothing after this piece can be certified
            }
            const double tm = 0.5 * (p.ta + p.tb);
            motion.at(tm, mid);
            const double fm = model_->freeDistance(statePose(mid));
            ++evaluations_;
            if (!(fm > 0.0))
            {
                failed = true;
                if (!prefix)
                    break;
                // Only the part before tm can still be certified: forget the pieces after it.
                stack.clear();
                stack.push_back({p.ta, tm, p.fa, 0.0});
                continue;
            }
            stack.push_back({tm, p.tb, fm, p.fb});
            stack.push_back({p.ta, tm, p.fa, fm});
        }
        si_->freeState(mid);
        return failed ? certified : 1.0;
    }

    bool CertifiedMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2) const
    {
        const bool ok = certify(s1, s2, false) >= 1.0;
        if (ok)
            ++valid_;
        else
            ++invalid_;
        return ok;
    }

    bool CertifiedMotionValidator::checkMotion(const ob::State *s1, const ob::State *s2,
                                               std::pair<ob::State *, double> &lastValid) const
    {
        const double c = certify(s1, s2, true);
        if (c >= 1.0)
        {
            ++valid_;
            return true;
        }
        ++invalid_;
        if (lastValid.first != nullptr)
        {
            const SpaceMotion motion(si_->getStateSpace().get(), type_, model_->rotationReach(),
                                     turningRadius_, s1, s2);
            motion.at(c, lastValid.first);
        }
        lastValid.second = c;
        return false;
    }

    std::vector<Pose2> densePathPoses(const World &world, const ob::SpaceInformation &si,
                                      const og::PathGeometric &path, double step)
    {
        if (!(step > 0.0))
            throw std::invalid_argument("densePathPoses: step must be > 0");
        std::vector<Pose2> out;
        if (path.getStateCount() == 0)
            return out;
        const double rotation = world.robotPolygon.empty() ? 0.0 : world.robotReach();
        ob::State *tmp = si.allocState();
        for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
        {
            const SpaceMotion m(si.getStateSpace().get(), world.space, rotation, world.turningRadius,
                                path.getState(i), path.getState(i + 1));
            const double pieces = std::min(1e6, std::max(1.0, std::ceil(m.bound() / step)));
            const auto n = static_cast<std::size_t>(pieces);
            for (std::size_t k = 0; k < n; ++k)
            {
                m.at(static_cast<double>(k) / static_cast<double>(n), tmp);
                out.push_back(statePose(tmp));
            }
        }
        si.freeState(tmp);
        out.push_back(statePose(path.getState(path.getStateCount() - 1)));
        return out;
    }

    bool independentPosesFree(const World &world, const std::vector<Pose2> &poses)
    {
        for (const Pose2 &p : poses)
            if (!independentPoseFree(world, p))
                return false;
        return true;
    }
} // namespace mhplan

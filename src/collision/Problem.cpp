// SPDX-License-Identifier: BSD-3-Clause
#include "mhplan/collision/Problem.h"

#include "mhplan/collision/CarSpaces.h"
#include "mhplan/collision/RigidValidity.h"
#include "mhplan/collision/Validity.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>

#include <cmath>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mhplan
{
    namespace
    {
        void checkEndpoint(const World &world, const Query &query, const CollisionModel &model, const Vec2 &p,
                           const char *field)
        {
            const auto where = [&] // only for a message: a campaign checks every query of every world
            {
                std::ostringstream out;
                out << (world.file.empty() ? world.name : world.file) << ": query '" << query.name
                    << "' field '" << field << "' (" << p.x << ", " << p.y << ")";
                return out.str();
            };
            if (!model.inBounds(p))
                throw InputError(where() + " is out of bounds: the robot disc (radius " +
                                 std::to_string(world.robotRadius) + ") must lie inside the world's bounds");
            if (!model.isValid(p))
                throw InputError(where() + " is in collision (clearance " +
                                 std::to_string(model.clearance(p)) + ")");
        }
    } // namespace

    namespace
    {
        void checkPose(const World &world, const Query &query, const RigidBodyModel &model, const Pose2 &p,
                       const char *field)
        {
            const auto where = [&]
            {
                std::ostringstream out;
                out << (world.file.empty() ? world.name : world.file) << ": query '" << query.name
                    << "' field '" << field << "' (" << p.x << ", " << p.y << ", yaw " << p.yaw << ")";
                return out.str();
            };
            if (!model.inBounds(p))
                throw InputError(where() + " is out of bounds: the robot must lie inside the world's bounds");
            if (!model.isValid(p))
                throw InputError(where() + " is in collision (the robot overlaps an obstacle)");
        }
    } // namespace

    std::string ValiditySetup::describe() const
    {
        if (!app())
            return "exact";
        std::ostringstream out;
        out << "app (point checker, DiscreteMotionValidator at resolution " << resolution << ")";
        return out.str();
    }

    ValiditySetup makeValiditySetup(const std::string &kind, double resolution)
    {
        ValiditySetup s;
        if (kind == "exact")
        {
            if (!std::isnan(resolution))
                throw InputError(
                    "a resolution belongs to the app set-up only; the exact set-up decides every "
                    "point of a motion (accepted: exact, or app with a resolution)");
            return s;
        }
        if (kind != "app")
            throw InputError(
                "unknown set-up '" + kind +
                "'; accepted: exact (mhplan's exact checker and motion validator) or app (a point "
                "checker and OMPL's DiscreteMotionValidator at a resolution)");
        s.kind = ValiditySetup::Kind::App;
        if (!std::isnan(resolution))
        {
            if (!(resolution >= kMinAppResolution && resolution <= kMaxAppResolution))
            {
                std::ostringstream out;
                out << "resolution " << resolution << " is out of range; accepted: " << kMinAppResolution
                    << " to " << kMaxAppResolution << " (a fraction of the space's maximum extent)";
                throw InputError(out.str());
            }
            s.resolution = resolution;
        }
        return s;
    }

    void validateRigidQuery(const World &world, const Query &query, const RigidBodyModel &model)
    {
        checkPose(world, query, model, {query.start.x, query.start.y, query.startYaw}, "start");
        checkPose(world, query, model, {query.goal.x, query.goal.y, query.goalYaw}, "goal");
    }

    void validateQuery(const World &world, const Query &query, const CollisionModel &model)
    {
        if (world.isRigid())
        {
            validateRigidQuery(world, query, RigidBodyModel(world));
            return;
        }
        checkEndpoint(world, query, model, query.start, "start");
        checkEndpoint(world, query, model, query.goal, "goal");
    }

    namespace
    {
        /** Identity projection of the 2D position with cells of 1/20 of the bounds. Registered as the default
            projection because OMPL 1.5.2's own RealVector projections trip an Eigen 3.4 assertion when
            KPIECE1 or SBL call them (they assign into an Eigen::Ref of another size). */
        class PositionProjection : public ob::ProjectionEvaluator
        {
          public:
            PositionProjection(const ob::StateSpace *space, const Box &bounds)
                : ob::ProjectionEvaluator(space)
            {
                cellSizes_ = {bounds.width() / 20.0, bounds.height() / 20.0};
            }
            unsigned int getDimension() const override { return 2; }
            void defaultCellSizes() override {}
            void project(const ob::State *state, Eigen::Ref<Eigen::VectorXd> projection) const override
            {
                const auto *s = state->as<ob::RealVectorStateSpace::StateType>();
                projection[0] = s->values[0];
                projection[1] = s->values[1];
            }
        };

        /** RealVectorStateSpace whose default projection is PositionProjection. */
        class PlaneStateSpace : public ob::RealVectorStateSpace
        {
          public:
            explicit PlaneStateSpace(const Box &bounds) : ob::RealVectorStateSpace(2), box_(bounds) {}
            void registerProjections() override
            {
                registerDefaultProjection(std::make_shared<PositionProjection>(this, box_));
            }

          private:
            Box box_;
        };
    } // namespace

    ob::StateSpacePtr makeStateSpace(const World &world)
    {
        if (world.isRigid())
        {
            std::shared_ptr<ob::SE2StateSpace> se2;
            if (world.space == SpaceType::Dubins)
                se2 = std::make_shared<SafeDubinsStateSpace>(world.turningRadius);
            else if (world.space == SpaceType::ReedsShepp)
                se2 = std::make_shared<ob::ReedsSheppStateSpace>(world.turningRadius);
            else
                se2 = std::make_shared<ob::SE2StateSpace>();
            ob::RealVectorBounds b(2);
            b.setLow(0, world.bounds.xmin);
            b.setHigh(0, world.bounds.xmax);
            b.setLow(1, world.bounds.ymin);
            b.setHigh(1, world.bounds.ymax);
            se2->setBounds(b);
            return se2;
        }
        auto space = std::make_shared<PlaneStateSpace>(world.bounds);
        ob::RealVectorBounds b(2);
        b.setLow(0, world.bounds.xmin);
        b.setHigh(0, world.bounds.xmax);
        b.setLow(1, world.bounds.ymin);
        b.setHigh(1, world.bounds.ymax);
        space->setBounds(b);
        return space;
    }

    double motionResolution(const World &world)
    {
        return 1e-4 * std::hypot(world.bounds.width(), world.bounds.height());
    }

    namespace
    {
        og::SimpleSetupPtr makeRigidSetup(const World &world, const Query &query,
                                          const SimpleSetupFactory &make, const ValiditySetup &setup)
        {
            auto rigid = std::make_shared<const RigidBodyModel>(world);
            validateRigidQuery(world, query, *rigid);
            og::SimpleSetupPtr ss = make(makeStateSpace(world));
            const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
            if (setup.app())
            {
                si->setStateValidityChecker(std::make_shared<FunctionValidityChecker>(
                    si, [rigid](const ob::State *s) { return rigid->isValid(statePose(s)); }));
                si->setMotionValidator(std::make_shared<ob::DiscreteMotionValidator>(si));
                si->setStateValidityCheckingResolution(setup.resolution);
            }
            else
            {
                si->setStateValidityChecker(std::make_shared<RigidValidityChecker>(si, rigid));
                si->setMotionValidator(std::make_shared<CertifiedMotionValidator>(
                    si, rigid, world.space, world.turningRadius, motionResolution(world)));
            }
            ob::ScopedState<> start(ss->getStateSpace());
            ob::ScopedState<> goal(ss->getStateSpace());
            setStatePose(start.get(), {query.start.x, query.start.y, query.startYaw});
            setStatePose(goal.get(), {query.goal.x, query.goal.y, query.goalYaw});
            ss->getStateSpace()->enforceBounds(start.get()); // the heading into (-pi, pi]
            ss->getStateSpace()->enforceBounds(goal.get());
            const double diag = std::hypot(world.bounds.width(), world.bounds.height());
            ss->setStartAndGoalStates(start, goal, 1e-9 * diag);
            ss->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
            return ss;
        }
    } // namespace

    namespace
    {
        /** Every command plans on the same problem definition as a benchmark run, which registers an
            intermediate-solution callback (benchmarks/Improvements.h) that replaces this one. A callback
            changes what OMPL's planners do: RRT* and its relatives skip a sample equal to its nearest tree
            state when one is registered, so without it `mhplan plan` solved start == goal exactly (length 0)
            while the benchmark's runs of the same seed were approximate. */
        void registerIntermediateCallback(const og::SimpleSetupPtr &ss)
        {
            ss->getProblemDefinition()->setIntermediateSolutionCallback(
                [](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost &) {});
        }
    } // namespace

    og::SimpleSetupPtr makeSimpleSetup(const World &world, const Query &query, const CollisionModelPtr &model,
                                       const ValiditySetup &setup)
    {
        return makeSimpleSetup(
            world, query, model,
            [](const ob::StateSpacePtr &space) { return std::make_shared<og::SimpleSetup>(space); }, setup);
    }

    og::SimpleSetupPtr makeSimpleSetup(const World &world, const Query &query, const CollisionModelPtr &model,
                                       const SimpleSetupFactory &make, const ValiditySetup &setup)
    {
        if (world.isRigid())
        {
            og::SimpleSetupPtr rigid = makeRigidSetup(world, query, make, setup);
            registerIntermediateCallback(rigid);
            return rigid;
        }
        validateQuery(world, query, *model);
        og::SimpleSetupPtr ss = make(makeStateSpace(world));
        const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
        if (setup.app())
        {
            si->setStateValidityChecker(std::make_shared<PointValidityChecker>(si, model));
            si->setMotionValidator(std::make_shared<ob::DiscreteMotionValidator>(si));
            si->setStateValidityCheckingResolution(setup.resolution);
        }
        else
        {
            si->setStateValidityChecker(std::make_shared<WorldValidityChecker>(si, model));
            si->setMotionValidator(std::make_shared<ExactMotionValidator>(si, model));
        }
        ob::ScopedState<> start(ss->getStateSpace());
        ob::ScopedState<> goal(ss->getStateSpace());
        start[0] = query.start.x;
        start[1] = query.start.y;
        goal[0] = query.goal.x;
        goal[1] = query.goal.y;
        const double diag = std::hypot(world.bounds.width(), world.bounds.height());
        ss->setStartAndGoalStates(start, goal, 1e-9 * diag);
        ss->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
        registerIntermediateCallback(ss);
        return ss;
    }

    double polylineLength(const std::vector<Vec2> &points)
    {
        double len = 0.0;
        for (std::size_t i = 1; i < points.size(); ++i)
            len += distance(points[i - 1], points[i]);
        return len;
    }

    std::vector<Vec2> pathPoints(const og::PathGeometric &path)
    {
        std::vector<Vec2> out;
        out.reserve(path.getStateCount());
        const bool se2 = dynamic_cast<const ob::SE2StateSpace *>(
                             path.getSpaceInformation()->getStateSpace().get()) != nullptr;
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
        {
            if (se2)
            {
                const Pose2 p = statePose(path.getState(i));
                out.emplace_back(p.x, p.y);
            }
            else
                out.push_back(statePosition(path.getState(i)));
        }
        return out;
    }
} // namespace mhplan

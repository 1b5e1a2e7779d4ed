#include "Problem.h"

#include "Validity.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

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
            std::ostringstream where;
            where << (world.file.empty() ? world.name : world.file) << ": query '" << query.name
                  << "' field '" << field << "' (" << p.x << ", " << p.y << ")";
            if (!model.inBounds(p))
                throw InputError(where.str() + " is out of bounds: the robot disc (radius " +
                                 std::to_string(world.robotRadius) + ") must lie inside the world's bounds");
            if (!model.isValid(p))
                throw InputError(where.str() + " is in collision (clearance " +
                                 std::to_string(model.clearance(p)) + ")");
        }
    } // namespace

    void validateQuery(const World &world, const Query &query, const CollisionModel &model)
    {
        checkEndpoint(world, query, model, query.start, "start");
        checkEndpoint(world, query, model, query.goal, "goal");
    }

    ob::StateSpacePtr makeStateSpace(const World &world)
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        ob::RealVectorBounds b(2);
        b.setLow(0, world.bounds.xmin);
        b.setHigh(0, world.bounds.xmax);
        b.setLow(1, world.bounds.ymin);
        b.setHigh(1, world.bounds.ymax);
        space->setBounds(b);
        return space;
    }

    og::SimpleSetupPtr makeSimpleSetup(const World &world, const Query &query, const CollisionModelPtr &model)
    {
        validateQuery(world, query, *model);
        auto ss = std::make_shared<og::SimpleSetup>(makeStateSpace(world));
        const ob::SpaceInformationPtr &si = ss->getSpaceInformation();
        si->setStateValidityChecker(std::make_shared<WorldValidityChecker>(si, model));
        si->setMotionValidator(std::make_shared<ExactMotionValidator>(si, model));
        ob::ScopedState<> start(ss->getStateSpace());
        ob::ScopedState<> goal(ss->getStateSpace());
        start[0] = query.start.x;
        start[1] = query.start.y;
        goal[0] = query.goal.x;
        goal[1] = query.goal.y;
        const double diag = std::hypot(world.bounds.width(), world.bounds.height());
        ss->setStartAndGoalStates(start, goal, 1e-9 * diag);
        ss->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
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
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
            out.push_back(statePosition(path.getState(i)));
        return out;
    }
} // namespace mhplan

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: a time-stepped 2D multi-robot simulator for planning while the world moves (moving obstacles and
   targets, robots joining and goals assigned during a run), docs/algorithms.md 6.3, 8 and 9 (case 3). */
#ifndef MHPLAN_SIMULATION_H
#define MHPLAN_SIMULATION_H

#include "src/collision/Collision.h"
#include "src/base/World.h"

#include <ompl/util/RandomNumbers.h>

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief A trajectory in the plane as a function of time: a fixed point, a back-and-forth motion on a
        line segment, or uniform motion on a circle. Used by moving obstacles and moving targets. */
    struct Motion
    {
        enum class Kind
        {
            Fixed, ///< stays at \c from
            Line,  ///< from \c from to \c to at \c speed, then back (ping-pong), forever
            Circle ///< on the circle (\c center, \c radius), angle(t) = \c phase + \c angularSpeed * t
        };
        Kind kind{Kind::Fixed};
        /** \brief Fixed: the point. Line: the first end (the position at t = 0). */
        Vec2 from;
        /** \brief Line: the other end. */
        Vec2 to;
        /** \brief Line: speed in m/s (> 0). */
        double speed{0.0};
        /** \brief Circle: its centre. */
        Vec2 center;
        /** \brief Circle: its radius (> 0). */
        double radius{0.0};
        /** \brief Circle: angular speed in rad/s (positive = counter-clockwise; may be negative). */
        double angularSpeed{0.0};
        /** \brief Circle: angle at t = 0 in radians. */
        double phase{0.0};

        /** \brief Position at time \e t >= 0. */
        Vec2 positionAt(double t) const;
        /** \brief Velocity at time \e t (the derivative of positionAt; at a Line's turning point, the new
            direction). */
        Vec2 velocityAt(double t) const;
    };

    /** \brief A disc obstacle that moves along a Motion. Static obstacles come from the world. */
    struct MovingObstacle
    {
        std::string name;
        double radius{0.4};
        Motion motion;
    };

    /** \brief One goal of a robot: where (possibly moving) and from when it is known to the robot. */
    struct Task
    {
        /** \brief The goal's trajectory (Kind::Fixed for an ordinary goal point). */
        Motion goal;
        /** \brief Simulation time at which the task is assigned (>= the robot's join time). The robot works
            on its tasks in order; a task assigned later than the previous task's completion makes the robot
            wait (idle) until then. */
        double assignedAt{0.0};
    };

    /** \brief A robot of a scenario: a disc with unicycle (differential-drive) limits. Defaults: a
        TurtleBot3 Burger (docs/algorithms.md 8). */
    struct RobotSpec
    {
        std::string name;
        double radius{0.105};
        /** \brief Maximum forward speed in m/s. */
        double maxSpeed{0.22};
        /** \brief Maximum turn rate in rad/s. */
        double maxTurnRate{2.84};
        Vec2 start;
        /** \brief Initial heading in radians (0 = +x). */
        double heading{0.0};
        /** \brief Simulation time at which the robot appears at its start (0 = from the beginning). */
        double joinTime{0.0};
        /** \brief The goals, in order (at least one). */
        std::vector<Task> tasks;
    };

    /** \brief Settings of a run. */
    struct SimulationSettings
    {
        /** \brief Time step in seconds. */
        double dt{0.05};
        /** \brief The run ends at this simulation time (robots not done by then are unfinished). */
        double timeLimit{300.0};
        /** \brief A robot whose distance to its current goal has not dropped by at least stuckDistance
            within this many seconds (while it has a task) is declared stuck and stops. */
        double stuckTimeout{30.0};
        /** \brief See stuckTimeout (metres). */
        double stuckDistance{0.05};
        /** \brief A goal counts as reached when the robot's centre is within this distance of it. */
        double goalTolerance{0.05};
        /** \brief Record every k-th state into the trajectories (1 = every step). */
        unsigned int recordEvery{1};
    };

    /** \brief A scenario: a static world (bounds, static obstacles; its robot radius and queries are
        ignored), moving obstacles, robots and settings. Loaded from a scenario file (ScenarioIO.h). */
    struct Scenario
    {
        std::string name;
        std::string description;
        std::string source;
        std::string assumptions;
        std::string file;
        World world;
        std::vector<MovingObstacle> movingObstacles;
        std::vector<RobotSpec> robots;
        SimulationSettings settings;
        /** \brief Paper figures to compare with (e.g. "traversal_time_reduction_percent": 35), shown by the
            report beside what mhplan measures. */
        std::map<std::string, double> reference;
    };

    /** \brief What a robot is doing. */
    enum class RobotStatus
    {
        Waiting, ///< not joined yet, or between tasks
        Moving,  ///< has a goal and drives
        Done,    ///< reached its last goal
        Stuck    ///< stopped by the stuck timeout
    };

    /** \brief The dynamic state of one robot. */
    struct RobotState
    {
        Vec2 position;
        double heading{0.0};
        /** \brief Velocity applied during the last step (world frame). */
        Vec2 velocity;
        RobotStatus status{RobotStatus::Waiting};
        /** \brief True once the robot has joined. */
        bool joined{false};
        /** \brief Index of the current task in RobotSpec::tasks. */
        std::size_t task{0};
        /** \brief Position of the current goal at the current time (moving targets move). */
        Vec2 goal;
        double pathLength{0.0};
        /** \brief Time the robot joined; time it finished its last task (or stopped). */
        double joinedAt{0.0}, finishedAt{0.0};
        /** \brief Time spent moving toward goals (excludes waiting for tasks): the traversal time. */
        double traversalTime{0.0};
    };

    /** \brief A velocity command in the world frame (the holonomic intention of a controller). The
        simulator turns it into unicycle motion: the robot turns toward its direction at most maxTurnRate,
        drives at min(|v|, maxSpeed) scaled by max(0, cos(heading error)) along its heading. */
    struct Command
    {
        Vec2 velocity;
        /** \brief When true, the command is already a unicycle command (a ROS geometry_msgs/Twist, src/ros):
            the robot turns by \c turn radians (clamped to maxTurnRate * dt), then drives \c forward m/s
            (clamped to [0, maxSpeed]) along its new heading; \c velocity is ignored. */
        bool unicycle{false};
        /** \brief Unicycle command: the turn of this step (radians). */
        double turn{0.0};
        /** \brief Unicycle command: the forward speed (m/s). */
        double forward{0.0};
    };

    struct RobotSpec;

    /** \brief The unicycle motion the simulator makes from the world-frame command \e velocity for a robot
        at \e heading in one step of \e dt (see Command): the turn toward the command's direction, at most
        maxTurnRate * dt, and the forward speed min(|v|, maxSpeed) max(0, cos(remaining error)). Returned as
        a unicycle Command (a zero command when |v| is zero or not finite: the robot neither turns nor
        drives). */
    Command unicycleCommand(const RobotSpec &spec, double heading, const Vec2 &velocity, double dt);

    class Simulation;

    /** \brief A decentralised controller: computes each robot's command from what the simulation shows
        (static world, moving obstacles, other robots). One instance drives all robots of a run; it may keep
        per-robot state (sized in reset()). Deterministic given the RNG it is handed. */
    class Controller
    {
      public:
        virtual ~Controller() = default;
        /** \brief Registry name ("dapf", "aapf", "bfo", "atbfo", "plan:<planner>"). */
        virtual std::string name() const = 0;
        /** \brief Called once before the run starts (robots not joined yet). */
        virtual void reset(const Simulation &sim, ompl::RNG &rng) = 0;
        /** \brief Called when robot \e i joins or gets a new task (plan-then-follow plans here). */
        virtual void taskStarted(const Simulation &sim, std::size_t i) = 0;
        /** \brief The command of robot \e i (status Moving) at the current time. */
        virtual Command command(const Simulation &sim, std::size_t i) = 0;
        /** \brief Controller-specific counters reported with the run (e.g. "replans", "evaluations"). */
        virtual std::map<std::string, double> counters() const { return {}; }
        /** \brief Set a parameter by name; throws InputError naming the parameter, its range and the value
            for an unknown name or an out-of-range value. */
        virtual void setParameter(const std::string &name, const std::string &value);
        /** \brief Parameter names and their current values. */
        virtual std::map<std::string, std::string> parameters() const { return {}; }
    };

    using ControllerPtr = std::shared_ptr<Controller>;

    /** \brief One robot's results. */
    struct RobotResult
    {
        std::string name;
        RobotStatus status{RobotStatus::Waiting};
        /** \brief Seconds spent moving toward goals (join/assignment to arrival, waiting excluded). */
        double traversalTime{0.0};
        double pathLength{0.0};
        /** \brief Minimum over the run of (distance to static obstacles and moving obstacles) minus radius.
         */
        double minObstacleClearance{std::numeric_limits<double>::infinity()};
        /** \brief Minimum surface distance to another robot. */
        double minRobotDistance{std::numeric_limits<double>::infinity()};
        unsigned int collisions{0};
        /** \brief Recorded (time, position, heading) samples. */
        std::vector<double> times;
        std::vector<Vec2> positions;
        std::vector<double> headings;
    };

    /** \brief The result of a run. Flowtime is the sum of the robots' traversal times; makespan is the
        simulation time at which the last robot reached its last goal. A robot that is not done counts in
        the makespan with the time the run ended and in the flowtime with the time it moved, so both are
        lower bounds when \c allDone is false. */
    struct SimulationResult
    {
        std::string scenario, controller;
        std::uint32_t seed{0};
        std::vector<RobotResult> robots;
        /** \brief Positions of the moving obstacles at the recorded times (outer index: obstacle). */
        std::vector<std::vector<Vec2>> obstaclePositions;
        /** \brief Goal positions at the recorded times (outer index: robot). */
        std::vector<std::vector<Vec2>> goalPositions;
        std::vector<double> times;
        bool allDone{false};
        unsigned int done{0}, stuck{0}, unfinished{0};
        double flowtime{0.0}, makespan{0.0};
        double minRobotDistance{std::numeric_limits<double>::infinity()};
        double minObstacleClearance{std::numeric_limits<double>::infinity()};
        /** \brief Contact episodes: robot-static obstacle, robot-moving obstacle, robot-robot (a pair in
            contact over consecutive steps counts once). */
        unsigned int staticCollisions{0}, movingCollisions{0}, robotCollisions{0};
        unsigned long steps{0};
        /** \brief Robot-steps simulated (active robots summed over steps). */
        unsigned long robotSteps{0};
        /** \brief Wall-clock seconds of the run (controller included). */
        double wallTime{0.0};
        double simulatedTime{0.0};
        std::map<std::string, double> counters;

        unsigned int collisions() const { return staticCollisions + movingCollisions + robotCollisions; }
    };

    /** \brief Steps a scenario with a controller.

        Physics (chosen where the papers are silent):
        - Unicycle kinematics per robot (see Command); a robot never enters a static obstacle or leaves the
          bounds: a step that would is cut at the last free position along it (exact segment check) and a
          static collision is recorded. Moving obstacles and other robots do not block: an overlap with them
          is recorded as a collision (the controller's failure), motion continues.
        - Robots are updated in index order from the state at the start of the step (synchronous update).
        - A goal (possibly moving) is reached when the centre is within goalTolerance; the next task starts
          when assigned. */
    class Simulation
    {
      public:
        Simulation(Scenario scenario, ControllerPtr controller, std::uint32_t seed);

        /** \brief Run to the end (all robots done or stuck, or the time limit). */
        SimulationResult run();
        /** \brief Advance one step; false when the run has ended. */
        bool step();
        /** \brief The result so far (complete after run() or once step() returned false). */
        SimulationResult result() const;

        const Scenario &scenario() const { return scenario_; }
        double time() const { return time_; }
        double dt() const { return scenario_.settings.dt; }
        std::size_t robotCount() const { return robots_.size(); }
        const RobotSpec &spec(std::size_t i) const { return scenario_.robots[i]; }
        const RobotState &state(std::size_t i) const { return robots_[i]; }
        /** \brief True when robot \e i is in the world (joined and neither done nor stuck nor waiting
            before its join time). Done robots stay in the world as obstacles at their goal. */
        bool present(std::size_t i) const { return robots_[i].joined; }
        /** \brief Positions and velocities of the moving obstacles at the current time. */
        const std::vector<Vec2> &obstaclePositions() const { return obstaclePos_; }
        const std::vector<Vec2> &obstacleVelocities() const { return obstacleVel_; }
        /** \brief Static world clearance for a point robot (distance to the nearest static obstacle, bounds
            not included); subtract a robot's radius for its clearance. */
        const CollisionModel &staticModel() const { return *pointModel_; }
        /** \brief True when a disc of radius \e r at \e p is inside the bounds and off static obstacles. */
        bool staticFree(const Vec2 &p, double r) const;
        /** \brief Same for every point of the segment [a, b] (exact). */
        bool staticSegmentFree(const Vec2 &a, const Vec2 &b, double r) const;

        /** \brief Hooks for running the simulator and its controllers as separate processes (src/ros).
            The world side: append a task to robot \e i during the run (a robot that was done waits for it,
            and is done again when it reaches it); move the join time of a robot that has not joined yet
            (a robot that joins when its controller starts). Throw std::out_of_range for a bad index and
            std::logic_error for a robot that has joined already (setJoinTime). */
        void addTask(std::size_t i, const Task &task);
        void setJoinTime(std::size_t i, double t);
        /** \brief The controller side: set the dynamic state from outside (the time, every robot's state,
            the moving obstacles' positions and velocities), so that a controller computes a robot's command
            from observed states. The first call resets the controller. An observed simulation is a mirror:
            step() and run() do nothing on it (they return false / the empty result). */
        void observe(double time, const std::vector<RobotState> &robots, const std::vector<Vec2> &obstaclePos,
                     const std::vector<Vec2> &obstacleVel);

      private:
        void start();
        /** \brief Positions of moving obstacles and goals at time_. */
        void updateWorld();
        /** \brief Joins, goal arrivals, task starts and the stuck rule at time_. */
        void admit();
        void beginTask(std::size_t i);
        /** \brief Clearances, distances and contact episodes at time_. */
        void measure();
        void record();

        Scenario scenario_;
        ControllerPtr controller_;
        std::uint32_t seed_;
        ompl::RNG rng_;
        CollisionModelPtr pointModel_;
        std::vector<RobotState> robots_;
        std::vector<Command> commands_;
        std::vector<Vec2> obstaclePos_, obstacleVel_;
        double time_{0.0};
        bool started_{false}, ended_{false}, observed_{false};
        // Bookkeeping (implementation).
        std::vector<double> progressBest_, progressSince_;
        std::vector<std::uint8_t> staticContact_, movingContact_;
        std::vector<std::uint8_t> robotContact_;
        SimulationResult result_;
        double wallStart_{0.0};
    };

    /** \brief "waiting", "moving", "done", "stuck". */
    std::string toString(RobotStatus status);
} // namespace mhplan

#endif

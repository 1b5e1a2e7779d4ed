// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: controllers for the simulator (Simulation.h): classic distributed APF, the adaptive APF of
   [MAPF], the online BFO/ATBFO-APF step of [BFO], and plan-then-follow with any registered planner. */
#ifndef MHPLAN_CONTROLLERS_H
#define MHPLAN_CONTROLLERS_H

#include "ompl_planners/field/BacterialColony.h"
#include "src/registry/Registry.h"
#include "src/sim/Simulation.h"

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace mhplan
{
    /** \brief The controller names makeController accepts: "dapf", "aapf", "bfo", "atbfo", and
        "plan:<PLANNER>" for every planner name of \e registry (e.g. "plan:ThetaStar"). */
    std::vector<std::string> controllerNames(const PlannerRegistry &registry = builtinPlanners());

    /** \brief A controller by name with its default parameters; "plan:<PLANNER>" plans with the planners of
        \e registry (which must outlive the controller). Throws InputError listing the accepted names for an
        unknown one. */
    ControllerPtr makeController(const std::string &name,
                                 const PlannerRegistry &registry = builtinPlanners());

    /** \brief One declared controller parameter as `mhplan` lists it (like a planner's: name, default, OMPL
        range suggestion, what it does). */
    struct ControllerParameterInfo
    {
        std::string name;
        std::string defaultValue;
        /** \brief OMPL's range suggestion form: "lo:hi" for numbers, "lo:1:hi" for integers. */
        std::string range;
        std::string description;
    };

    /** \brief Numeric controller parameters by name: each bound to a member, declared once with its range,
        an integer flag and what it does; the range is kept as an OMPL range suggestion and values are checked
        by checkAgainstRange, as planners' parameters are (applyPlannerParameters). set() throws InputError
        naming the controller, the parameter, the range and the value given (and listing the parameters for
        an unknown name). */
    class ControllerParameters
    {
      public:
        /** \brief Declare parameter \e name bound to \e value (its current value is the default) with the
            range [lo, hi], described by \e description. */
        void add(const std::string &name, double *value, double lo, double hi, bool integer,
                 const std::string &description);
        /** \brief True when \e name is declared. */
        bool has(const std::string &name) const { return entries_.count(name) != 0; }
        /** \brief Parse and set; \e controller is used in messages. */
        void set(const std::string &controller, const std::string &name, const std::string &value);
        /** \brief Every parameter and its current value. */
        std::map<std::string, std::string> values() const;
        /** \brief Every parameter's declaration, by name. */
        std::vector<ControllerParameterInfo> describe() const;
        /** \brief The declared names, comma separated (for messages). */
        std::string list() const;

      private:
        struct Entry
        {
            double *value;
            double lo, hi;
            bool integer;
            std::string defaultValue, range, description;
        };
        std::map<std::string, Entry> entries_;
    };

    /** \brief The declared parameters of controller \e name (as makeController accepts it; "plan:<PLANNER>"
        lists the follower's own parameters, not the planner's: those are planner.<name>, see
        `mhplan planners`). Throws InputError for an unknown controller. */
    std::vector<ControllerParameterInfo>
    controllerParameters(const std::string &name, const PlannerRegistry &registry = builtinPlanners());

    /** \brief Print the controllers \e names (all field controllers and "plan:<PLANNER>" when empty) with
        their parameters, defaults, ranges and descriptions, in the layout of `mhplan planners`. */
    void printControllers(std::ostream &out, const std::vector<std::string> &names = {},
                          const PlannerRegistry &registry = builtinPlanners());

    /** \brief An obstacle as a controller senses it (a view: no ownership). */
    struct SensedObstacle
    {
        /** \brief Its geometry. */
        enum class Shape
        {
            Disc,    ///< \c center, \c radius
            Polygon, ///< \c polygon (a static obstacle of the world)
            Grid,    ///< the static grid, through the simulator's clearance (nearest blocked cell)
            Wall     ///< a side of the bounds: \c center on it, \c normal pointing inside
        };
        /** \brief What it is. */
        enum class Source
        {
            Static, ///< the static world (obstacles and walls)
            Moving, ///< a moving obstacle
            Robot   ///< another robot
        };
        Shape shape{Shape::Disc};
        Source source{Source::Static};
        Vec2 center;
        double radius{0.0};
        const Polygon *polygon{nullptr};
        Vec2 normal;
        /** \brief Moving obstacles and robots: the velocity (a robot's: that of its last step). */
        Vec2 velocity;
    };

    /** \brief Shared plumbing of mhplan's controllers: the parameter table behind setParameter() and
        parameters(), and the safety brake.

        Safety brake (parameter \c safety_brake, 1 = on, the default; not in the papers): the step the
        simulator will make from the command (Command: the turn toward it, limited by the turn rate, then
        the drive along the new heading) is predicted, and the speed limited so that the step's component
        toward each static obstacle or wall covers at most 90% of the gap (toward the nearest point of a
        convex obstacle; its length for non-convex polygons and grids), and toward another robot at most
        45% (two braking robots then never touch), of the gap left after a margin (parameter \c brake_margin,
        0 .. 1 m, default 1e-6 m: braked robots come that close to walls, static obstacles and each other
        without overlapping; in the 15-robot runs aapf robots came within 3e-5 m of each other, which is
        contact for a real robot). A physical safety distance (e.g. 0.01 m) is available, but then a follower
        of a plan or a BFO step that grazes an obstacle creeps to a halt there: with 0.01 m, plan:ThetaStar in
        mapf_u_trap and atbfo on a static world end stuck. It acts
        only within a few centimetres of contact at TurtleBot speeds, so the controllers' own behaviour is
       what the metrics show, and it keeps a controller from ever being cut by the simulator at a static
       obstacle. Moving obstacles are not braked for (they do not yield; plan:<PLANNER> evades them,
       PlanFollowController). */
    class ControllerBase : public Controller
    {
      public:
        ControllerBase();
        ControllerBase(const ControllerBase &) = delete;
        ControllerBase &operator=(const ControllerBase &) = delete;

        void setParameter(const std::string &name, const std::string &value) override;
        std::map<std::string, std::string> parameters() const override { return params_.values(); }
        /** \brief The declared parameters (names, defaults, ranges, descriptions). */
        const ControllerParameters &parameterTable() const { return params_; }

      protected:
        /** \brief Apply the safety brake (if on) to the world-frame velocity \e v of robot \e i; \e limited
            (if given) tells whether it slowed the command down. */
        Vec2 brake(const Simulation &sim, std::size_t i, const Vec2 &v, bool *limited = nullptr) const;

        /** \brief The parameter table (derived classes add to it in their constructors). */
        ControllerParameters params_;
        /** \brief 1 = the safety brake is on. */
        double safetyBrake_{1.0};
        /** \brief Distance the safety brake keeps from what it brakes for (m). */
        double brakeMargin_{1e-6};
    };

    /** \brief Distributed artificial potential fields for many robots: the classic baseline "dapf" and the
        adaptive field "aapf" of [MAPF] (docs/algorithms.md 8). Robot i at r_i, heading psi_i, goal g_i:

        v_i = F_A + sum over obstacles within rho of F_O + sum over robots within rho of F_R, capped at
        v_max (the robot's maxSpeed), then the safety brake (ControllerBase).
        - Attraction F_A = C_a (g_i - r_i), capped at v_max (both).
        - An obstacle is a static circle or polygon of the world (its nearest surface point), a wall of the
          bounds (the bounds stop robots in the simulator, so they repel like obstacles), a moving obstacle
          (disc at its current position), or, in grid worlds, the nearest blocked cell (nearest point from
          the numerical gradient of the static clearance, central differences with a step of 1/20 cell).
          d = the gap between the robot's surface and the obstacle's, floored at 1 mm.
        - Repulsion magnitude C_o (1/d - 1/rho) for d < rho (0 beyond), for other present robots (done
          robots stay as obstacles at their goals) C_r (1/d - 1/rho). Both controllers use this magnitude
          (the [MAPF] form; Khatib's force has an extra 1/d^2: with the same form in both, the comparison
          isolates the rotation and the adaptation). Direction: from the obstacle's nearest point to r_i.
        - dapf: no rotation, no adaptation.
        - aapf, rotation (open in [MAPF]; the recommended choice): an obstacle whose nearest point lies
          within +-phi_M of the heading psi_i gets its repulsion rotated by 90 degrees toward the side of
          the target: counter-clockwise when cross(g_i - r_i, o - r_i) >= 0 (the obstacle is left of, or on,
          the line to the target: the robot is pushed right and passes with the obstacle on its left),
          clockwise otherwise; outside the cone the repulsion stays radial, so obstacles beside or behind
          the robot push it away as in dapf. A robot k ahead within the cone is treated the same way but
          always rotated counter-clockwise (every robot yields to its right: the right-hand rule, so two
          robots meeting head-on both swerve right and pass left side to left side).
        - aapf, adaptation (open; the recommended choice): C_r,i = C_r (1 + k_a n_i), n_i the number of
          other moving robots (speed > 1 mm/s) whose surface is within 2 rho of robot i and whose predicted
          motion over the horizon (the segment r_k -> r_k + v_k horizon, v_k the velocity of k's last step)
          passes within R_i + R_k + rho of robot i's predicted position r_i + v_i horizon.

        Parameters (setParameter; both controllers unless noted):
        | name         | range         | default | meaning |
        | C_a          | 0 .. 100      | 1       | attraction gain (1/s) |
        | C_o          | 0 .. 100      | 0.02    | obstacle repulsion gain (m^2/s) |
        | C_r          | 0 .. 100      | 0.02    | robot repulsion gain (m^2/s) |
        | rho          | 0.01 .. 100   | 0.4     | range of the repulsion (m) |
        | phi_M        | 0 .. 180      | 60      | aapf: half angle of the rotation cone (degrees) |
        | k_a          | 0 .. 100      | 1       | aapf: adaptive gain factor |
        | horizon      | 0 .. 100      | 1       | aapf: prediction horizon (s) |
        | safety_brake | 0 .. 1 (int)  | 1       | see ControllerBase |
        | brake_margin | 0 .. 1        | 1e-6    | see ControllerBase (m) |
        Measured (tests/test_controllers.cpp, environments/scenarios/mapf_u_trap.yaml): in a U-shaped obstacle
        open toward the robot, dapf stops in front of the back wall (the classic local minimum) and aapf is
        trapped too: the rotation slides it along the back wall, but the side "facing the target" flips
        when it crosses the U's axis, so it settles on the axis. The rotation resolves obstacles and robots
        met head-on (no equilibrium behind a pillar on the line to the goal), not concave traps.
        Deterministic (no randomness); no heap allocation per command. */
    class ApfController : public ControllerBase
    {
      public:
        /** \brief "aapf" when \e adaptive, else "dapf". */
        explicit ApfController(bool adaptive);
        std::string name() const override { return adaptive_ ? "aapf" : "dapf"; }
        void reset(const Simulation &sim, ompl::RNG &rng) override;
        void taskStarted(const Simulation &sim, std::size_t i) override;
        Command command(const Simulation &sim, std::size_t i) override;

      private:
        /** \brief n_i of the adaptive gain. */
        unsigned int crowding(const Simulation &sim, std::size_t i) const;

        bool adaptive_;
        double attraction_{1.0}, obstacleGain_{0.02}, robotGain_{0.02}, rho_{0.4};
        double coneDegrees_{60.0}, adaptiveGain_{1.0}, horizon_{1.0};
    };

    /** \brief The online BFO/ATBFO-APF step of [BFO] section 5 (docs/algorithms.md 6.3) as a controller
        ("bfo", "atbfo"): each robot walks from waypoint to waypoint, one BFO run per decision.

        A decision for robot i at r (radius R) toward its current goal g: the sensed obstacles are the
        static circles and polygons, the moving obstacles and the other present robots (as discs at their
        current positions) whose surface lies within D_sense of r's surface (grid worlds: the nearest
        blocked cell through the static clearance). The cost of a position P is
        J = 0.5 xi |P - g|^2 + sum over sensed obstacles of 0.5 eta max(0, 1/d(P) - 1/d0), d(P) the gap
        between the robot disc at P and the obstacle's surface; J = +infinity when d(P) <= 0, when the disc
        at P leaves the bounds, or when the straight segment r -> P is not free (static world exactly, and
        the sensed discs): what the robot cannot reach in a straight line it does not rate (the choice of
        mhplan's online BFO planner, BacterialWalk.h). S bacteria start uniformly (by area) in the sector of
        +-sector_angle about the direction to g, up to D_sense from r; a move that leaves that sensing disc
        or the bounds is projected back (as in the planner). Then Passino's loops (6.1): Ned x Nre x Nc
        chemotactic steps, each bacterium tumbles along phi = Delta/|Delta|, Delta ~ U(-1, 1)^2, moves C phi
        unconditionally and swims while J improves (at most Ns more moves); health = sum of J after each
        chemotactic step; the healthier half splits (ties by index), the rest dies; after each reproduction
        series every bacterium is dispersed with probability Ped. ATBFO (6.2): a bacterium that improved
        more than F_improv times in a chemotactic step keeps its direction (inherited at reproduction).
        The best position is the lowest finite J evaluated during the run.

        The waypoint is r + lambda unit(best - r) (the goal itself when it is within lambda and the segment
        to it is free); if the segment to it is not free (static world or a sensed disc) the step is halved
        up to 3 times; if all four fail the robot stays this step and decides again at the next one (the
        stuck rule of the simulator ends a robot that never gets out). The robot drives toward the waypoint
        at full speed (unicycle limits apply); a new decision is made when the waypoint is within one
        step's travel (maxSpeed dt), when a moving obstacle or robot now crosses the segment to it, or when
        the safety brake slowed the robot down (the way to the waypoint grazes something).

        Parameters ([BFO] section 6 defaults): S 100 (2..100000), Nc 8, Ns 6, Nre 2, Ned 1 (1..100000;
        Ns 0..100000), Ped 0.15 (0..1), C 0.1, xi 0.1, eta 0.06, d0 1.5, lambda 0.2, D_sense 1.2 (C, d0,
        lambda, D_sense 1e-6..1e6; xi, eta 0..1e6), F_improv 3 (0..100000, used by atbfo), sector_angle 45
        (0..180 degrees), safety_brake 1, predict 1 (0 or 1; not in [BFO]): when on, the straight-segment
        test against moving obstacles and robots (for bacteria and for the waypoint step) grows each disc by
        the distance it travels at its current speed while the robot drives lambda at full speed (the cost
        J itself uses the discs as they are); without it the robot often steps into the path of an obstacle
        that then runs into it. Counters: "evaluations" (J evaluations), "decisions" (BFO runs).
        Deterministic given the RNG of reset(); the colony is allocated in reset(), so a command allocates
        nothing. */
    class BfoController : public ControllerBase
    {
      public:
        /** \brief "atbfo" when \e adaptiveTumble, else "bfo". */
        explicit BfoController(bool adaptiveTumble);
        std::string name() const override { return adaptive_ ? "atbfo" : "bfo"; }
        void reset(const Simulation &sim, ompl::RNG &rng) override;
        void taskStarted(const Simulation &sim, std::size_t i) override;
        Command command(const Simulation &sim, std::size_t i) override;
        std::map<std::string, double> counters() const override;

      private:
        /** \brief Collect the sensed obstacles of robot \e i into sensed_. */
        void sense(const Simulation &sim, std::size_t i);
        /** \brief J at \e p for the current decision (counts one evaluation, tracks the best). */
        double cost(const Simulation &sim, const Vec2 &p);
        /** \brief True when the robot disc can sweep the segment [a, b] (static world and sensed discs). */
        bool segmentFree(const Simulation &sim, const Vec2 &a, const Vec2 &b) const;
        /** \brief One BFO run (colony_) from robot i's position; leaves the best position in best_. */
        void runColony(const Simulation &sim);
        class Adapter;
        /** \brief Draw a bacterium in the sector; \e x is constrained to the sensing disc and bounds. */
        Vec2 randomBacterium();
        Vec2 constrain(const Vec2 &x) const;
        /** \brief Decide robot i's next waypoint. */
        void decide(const Simulation &sim, std::size_t i);

        bool adaptive_;
        double colonySize_{100}, chemotactic_{8}, swim_{6}, reproduction_{2}, elimination_{1};
        double dispersal_{0.15}, stepSize_{0.1}, xi_{0.1}, eta_{0.06}, d0_{1.5}, lambda_{0.2};
        double sensing_{1.2}, improvement_{3}, sectorDegrees_{45.0}, predict_{1.0};

        ompl::RNG *rng_{nullptr};
        std::vector<Vec2> waypoint_;
        std::vector<std::uint8_t> hasWaypoint_;
        std::vector<SensedObstacle> sensed_;
        /** \brief The colony's settings, copied from the parameters at each decision. */
        ColonySettings colonySettings_;
        BacterialColony colony_{colonySettings_};
        /** \brief The simulation of the decision in progress (for the colony's cost). */
        const Simulation *sim_{nullptr};
        // The decision in progress.
        Vec2 robot_, goal_;
        double radius_{0.0};
        /** \brief With \c predict: the time to drive lambda at full speed, else 0. */
        double travelTime_{0.0};
        /** \brief Bounds shrunk by the robot's radius. */
        Box inner_;
        bool bestKnown_{false};
        double bestJ_{0.0};
        Vec2 best_;
        double evaluations_{0.0}, decisions_{0.0};
    };

    /** \brief Plan-then-follow with any planner of the registry ("plan:<PLANNER>").

        When robot i starts a task, its planner plans on the static world (a copy of the scenario's world
        with the robot's radius plus \c clearance; Query from the robot's position to the goal's current
        position; the project's collision model, validity checker and exact motion validator via
        makeSimpleSetup) for \c plan_time seconds of wall clock (the one use of the clock). The path is the
        first exact solution found in: that world, then the world with the bare radius (narrow passages);
        else the first approximate one; else the straight segment to the goal. The clearance keeps the
        corners that pure pursuit cuts off the obstacles. The robot follows the path by pure pursuit: it
        steers toward the point \c lookahead metres further along the path than its projection onto the path
        (the projection only advances), pulled back (halved up to 6 times) while the straight way there is
        not free; at full speed, slowing linearly within \c slowdown metres of the path's end; within
        \c lookahead of the end it steers to the goal's current position when the straight way there is
        free.

        Replanning (counted in counters()["replans"]; first plans in "plans"): when a moving obstacle or
        another present robot whose surface is within \c sense_range of the robot overlaps the robot disc
        swept along the next \c sense_range metres of the remaining path, at its current position or at a
        position predicted at its current velocity up to \c predict_time ahead (a robot's velocity is that
        of its last step), or when the goal has moved more than \c goal_tolerance from the path's end
        (moving targets; also an approximate path that ends short of the goal). The new plan starts at the
        robot's position in a world where each such disc is added as circles of its radius plus \c margin,
        at its current and its predicted positions (at most one radius of travel apart; grid worlds: the
        cells the circles overlap are blocked in a copy of the grid); a circle that would cover the start or
        the goal is shrunk to the room left and dropped when that is less than the disc's own radius. If
        that world refuses the query, the static worlds above are used. Replans are at least
        \c replan_interval seconds apart (a blocking robot that stays put would otherwise cause one per
        step); while a robot blocks the path within \c lookahead and a replan is not yet allowed, the robot
        waits (it does not wait for moving obstacles: they do not yield).

        Evasion (parameter \c evade, 1 = on, the default; docs/algorithms.md 8.1): a path planned on a
        snapshot does not keep the robot off a moving obstacle that then runs into it, and the safety brake
        does not brake for moving obstacles. So each step's command passes a reactive layer before the
        brake. It sees what the replanning sees: the moving obstacles whose surface is within
        \c sense_range of the robot's (centre, radius, velocity); of those, the ones that could come
        within \c evade_margin during the horizon (\c evade_horizon, rounded up to whole steps). Each
        candidate velocity is held constant over the horizon and rolled out with the simulator's unicycle
        kinematics (unicycleCommand: turn at most maxTurnRate dt per step, drive along the new heading
        scaled by the cosine of the heading error left), the robot staying where the next position would
        leave the static free space (Simulation::staticFree, as the brake would stop it), each disc moving
        on at its sensed velocity; its score is the smallest gap between the robot and any disc over the
        horizon, and its progress the displacement after the horizon along the pursuit direction. The
        candidates: the follower's command, the same at 1/2 and 1/4 of its speed, stop, and
        \c evade_headings headings at full speed evenly spread from the robot's heading. A candidate is
        safe when its gap stays at least \c evade_margin. The follower's command is kept when it is safe
        (the layer is then invisible); otherwise the safe candidate with the most progress (ties: the
        larger gap) is taken, and when none is safe the one with the largest gap (ties: progress).
        Counted in counters()["evasions"] (commands replaced). Robots are left to the brake, the wait and
        the replans (they brake too; the brake keeps an evasion off them and off static obstacles).

        Parameters: plan_time 0.5 (0.001..600 s), lookahead 0.3 (0.01..100 m), slowdown 0.3 (0..100 m),
        sense_range 1.0 (0..1000 m), margin 0.1 (0..100 m), clearance 0.05 (0..100 m), predict_time 3
        (0..100 s), goal_tolerance 0.2 (0.001..1000 m), replan_interval 0.5 (0..1000 s), evade 1 (0 or 1),
        evade_horizon 2 (0.01..20 s), evade_margin 0.05 (0..10 m), evade_headings 16 (4..360), safety_brake
        1, and planner.<name> = value, forwarded to the planner with applyPlannerParameters (checked when
        set, on a throwaway planner). A planner with a "seed" parameter (mhplan's population planners) gets
        a seed drawn from the run's RNG unless planner.seed is set.
        Determinism: ThetaStar and AStar are deterministic (they finish far within the budget), so runs
        repeat exactly per seed; sampling planners (RRT*, PRM, ...) draw from OMPL's global RNG and any
        planner stopped by the plan_time budget depends on the machine's speed: those runs do not repeat.
        Planning allocates (unavoidable); following, the blocked check and the evasion do not. */
    class PlanFollowController : public ControllerBase
    {
      public:
        /** \brief Plans with planner \e planner of \e registry, which must outlive the controller (throws
            InputError for an unknown one). */
        explicit PlanFollowController(std::string planner,
                                      const PlannerRegistry &registry = builtinPlanners());
        std::string name() const override { return "plan:" + planner_; }
        void reset(const Simulation &sim, ompl::RNG &rng) override;
        void taskStarted(const Simulation &sim, std::size_t i) override;
        Command command(const Simulation &sim, std::size_t i) override;
        std::map<std::string, double> counters() const override;
        void setParameter(const std::string &name, const std::string &value) override;
        std::map<std::string, std::string> parameters() const override;

      private:
        /** \brief The followed path of one robot. */
        struct Track
        {
            std::vector<Vec2> path;
            /** \brief Segment of the robot's projection and its parameter on that segment. */
            std::size_t segment{0};
            double along{0.0};
            double lastPlan{0.0};
        };

        /** \brief Plan for robot i; \e withDiscs adds the sensed moving obstacles and robots. */
        void plan(const Simulation &sim, std::size_t i, bool withDiscs);
        /** \brief Calls f(centre) for the predicted centres of a moving disc at its current velocity up to
            predict_time ahead, at most one radius of travel apart, the last at predict_time. */
        template <class F> void forEachPrediction(const SensedObstacle &o, F &&f) const;
        /** \brief Advance robot i's projection onto its path. */
        void project(const Simulation &sim, std::size_t i);
        /** \brief Path distance from the projection at which a sensed disc blocks the path (infinity when
            none does); \e byRobot tells whether the nearest blocker is a robot. */
        double blockedAt(const Simulation &sim, std::size_t i, bool &byRobot) const;
        /** \brief What a velocity held over the evasion horizon leads to: the smallest gap to the threats
            and the displacement along the pursuit direction at the end. */
        struct Rollout
        {
            double gap;
            double progress;
        };
        /** \brief The evasion layer: \e follow (the follower's command) or the velocity that replaces it;
            \e toward is the unit pursuit direction (zero when there is none). */
        Vec2 evade(const Simulation &sim, std::size_t i, const Vec2 &follow, const Vec2 &toward);
        /** \brief Roll velocity \e v out over \e steps steps from robot i's state against threats_. */
        Rollout rollout(const Simulation &sim, std::size_t i, const Vec2 &v, const Vec2 &toward,
                        int steps) const;

        std::string planner_;
        const PlannerRegistry *registry_;
        std::map<std::string, std::string> plannerParams_;
        double planTime_{0.5}, lookahead_{0.3}, slowdown_{0.3}, senseRange_{1.0}, margin_{0.1};
        double goalTolerance_{0.2}, replanInterval_{0.5}, clearance_{0.05}, predictTime_{3.0};
        double evade_{1.0}, evadeHorizon_{2.0}, evadeMargin_{0.05}, evadeHeadings_{16.0};
        ompl::RNG *rng_{nullptr};
        std::vector<Track> tracks_;
        /** \brief The moving obstacles the evasion of the current command considers (capacity: all of
            them, reserved in reset(), so a command allocates nothing). */
        std::vector<SensedObstacle> threats_;
        double plans_{0.0}, replans_{0.0}, evasions_{0.0};
    };
} // namespace mhplan

#endif

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the dapf / aapf controllers (see Controllers.h). */
#include "src/sim/Controllers.h"

#include "src/sim/detail/Sensing.h"

#include <algorithm>
#include <cmath>

namespace mhplan
{
    using namespace detail;

    // ---------------------------------------------------------------------------------------------------
    // dapf / aapf

    ApfController::ApfController(bool adaptive) : adaptive_(adaptive)
    {
        params_.add("C_a", &attraction_, 0.0, 100.0, false, "attraction gain (1/s)");
        params_.add("C_o", &obstacleGain_, 0.0, 100.0, false, "obstacle repulsion gain (m^2/s)");
        params_.add("C_r", &robotGain_, 0.0, 100.0, false, "robot repulsion gain (m^2/s)");
        params_.add("rho", &rho_, 0.01, 100.0, false, "range of the repulsion (m)");
        if (adaptive_)
        {
            params_.add("phi_M", &coneDegrees_, 0.0, 180.0, false,
                        "half angle of the rotation cone (degrees)");
            params_.add("k_a", &adaptiveGain_, 0.0, 100.0, false,
                        "adaptive gain factor (robot repulsion grows by k_a per crowding robot)");
            params_.add("horizon", &horizon_, 0.0, 100.0, false,
                        "prediction horizon of the crowding count (s)");
        }
    }

    void ApfController::reset(const Simulation & /*sim*/, ompl::RNG & /*rng*/) {}

    void ApfController::taskStarted(const Simulation & /*sim*/, std::size_t /*i*/) {}

    unsigned int ApfController::crowding(const Simulation &sim, std::size_t i) const
    {
        const RobotState &me = sim.state(i);
        const double ri = sim.spec(i).radius;
        const Vec2 next = me.position + me.velocity * horizon_;
        unsigned int n = 0;
        for (std::size_t k = 0; k < sim.robotCount(); ++k)
        {
            if (k == i || !sim.present(k))
                continue;
            const RobotState &other = sim.state(k);
            const double rk = sim.spec(k).radius;
            if (norm(other.velocity) <= 1e-3 || distance(me.position, other.position) - ri - rk > 2.0 * rho_)
                continue;
            if (pointSegmentDistance(next, other.position, other.position + other.velocity * horizon_) <
                ri + rk + rho_)
                ++n;
        }
        return n;
    }

    Command ApfController::command(const Simulation &sim, std::size_t i)
    {
        const RobotState &s = sim.state(i);
        const double vmax = sim.spec(i).maxSpeed;
        const Vec2 p = s.position;
        const Vec2 toGoal = s.goal - p;
        Vec2 v = capped(toGoal * attraction_, vmax);
        const Vec2 heading(std::cos(s.heading), std::sin(s.heading));
        const double cosCone = std::cos(coneDegrees_ * kPi / 180.0);
        const double robotGain =
            adaptive_ ? robotGain_ * (1.0 + adaptiveGain_ * crowding(sim, i)) : robotGain_;
        forEachObstacle(sim, i, p, rho_, true,
                        [&](const SensedObstacle &o, double gap, const Vec2 &nearest)
                        {
                            if (gap >= rho_)
                                return;
                            const bool robot = o.source == SensedObstacle::Source::Robot;
                            const double d = std::max(gap, 1e-3);
                            const double magnitude =
                                (robot ? robotGain : obstacleGain_) * (1.0 / d - 1.0 / rho_);
                            const Vec2 to =
                                o.shape == SensedObstacle::Shape::Disc ? o.center - p : nearest - p;
                            Vec2 n = unit(Vec2() - to);
                            if (adaptive_ && dot(to, heading) >= cosCone * norm(to))
                            {
                                // Rotated by 90 degrees: counter-clockwise pushes the robot to its right of
                                // the obstacle.
                                const bool counterClockwise = robot || cross(toGoal, to) >= 0.0;
                                n = counterClockwise ? Vec2(-n.y, n.x) : Vec2(n.y, -n.x);
                            }
                            v = v + n * magnitude;
                        });
        return {brake(sim, i, capped(v, vmax))};
    }
} // namespace mhplan

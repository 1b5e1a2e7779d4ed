// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the controllers' parameter table and the safety brake (see Controllers.h). */
#include "src/sim/Controllers.h"

#include "src/sim/detail/Sensing.h"

#include "src/base/PlannerRegistry.h"

#include <cstdlib>

#include <algorithm>
#include <cmath>

namespace mhplan
{
    using namespace detail;

    namespace
    {
        /** \brief Smallest speed a braked command keeps (the simulator turns only for a nonzero speed). */
        constexpr double kCreepSpeed = 1e-11;
    } // namespace

    // ---------------------------------------------------------------------------------------------------
    // Parameters and the shared base

    void ControllerParameters::add(const std::string &name, double *value, double lo, double hi, bool integer,
                                   const std::string &description)
    {
        // The range written once, as planners declare theirs (OMPL range suggestion).
        const std::string range = formatNumber(lo) + (integer ? ":1:" : ":") + formatNumber(hi);
        entries_[name] = Entry{value, lo, hi, integer, formatNumber(*value), range, description};
    }

    std::vector<ControllerParameterInfo> ControllerParameters::describe() const
    {
        std::vector<ControllerParameterInfo> out;
        for (const auto &kv : entries_)
            out.push_back({kv.first, kv.second.defaultValue, kv.second.range, kv.second.description});
        return out;
    }

    std::string ControllerParameters::list() const
    {
        std::string out;
        for (const auto &kv : entries_)
            out += (out.empty() ? "" : ", ") + kv.first;
        return out;
    }

    void ControllerParameters::set(const std::string &controller, const std::string &name,
                                   const std::string &value)
    {
        const auto it = entries_.find(name);
        if (it == entries_.end())
            throw InputError("controller '" + controller + "' has no parameter '" + name + "' (value '" +
                             value + "'); its parameters: " + list());
        const Entry &e = it->second;
        char *end = nullptr;
        const double v = value.empty() ? std::nan("") : std::strtod(value.c_str(), &end);
        const bool parsed = end != nullptr && *end == '\0' && std::isfinite(v);
        if (!parsed || !checkAgainstRange(value, e.range).empty() || (e.integer && v != std::floor(v)))
            throw InputError("controller '" + controller + "' parameter '" + name + "': value '" + value +
                             "' is out of range; expected " + (e.integer ? "an integer" : "a number") +
                             " in [" + formatNumber(e.lo) + ", " + formatNumber(e.hi) + "]");
        *e.value = v;
    }

    std::map<std::string, std::string> ControllerParameters::values() const
    {
        std::map<std::string, std::string> out;
        for (const auto &kv : entries_)
            out[kv.first] = formatNumber(*kv.second.value);
        return out;
    }

    ControllerBase::ControllerBase()
    {
        params_.add("safety_brake", &safetyBrake_, 0.0, 1.0, true,
                    "1 = limit the speed so a step never closes a gap to a static obstacle, wall or robot");
        params_.add("brake_margin", &brakeMargin_, 0.0, 1.0, false, "distance the safety brake keeps (m)");
    }

    void ControllerBase::setParameter(const std::string &name, const std::string &value)
    {
        params_.set(this->name(), name, value);
    }

    Vec2 ControllerBase::brake(const Simulation &sim, std::size_t i, const Vec2 &v, bool *limited) const
    {
        const RobotSpec &spec = sim.spec(i);
        const double speed = std::min(norm(v), spec.maxSpeed);
        if (safetyBrake_ == 0.0 || !(speed > 0.0))
            return v;
        const double dt = sim.dt();
        const RobotState &s = sim.state(i);
        // The step the simulator makes per unit of speed (Command): turn toward v by at most maxTurnRate dt,
        // then drive along the new heading, scaled by the cosine of the heading error left.
        const double error = std::remainder(std::atan2(v.y, v.x) - s.heading, 2.0 * kPi);
        const double turn = std::clamp(error, -spec.maxTurnRate * dt, spec.maxTurnRate * dt);
        const Vec2 step = Vec2(std::cos(s.heading + turn), std::sin(s.heading + turn)) *
                          (std::max(0.0, std::cos(error - turn)) * dt);
        double limit = speed;
        forEachObstacle(sim, i, s.position, speed * dt / 0.45 + brakeMargin_, true,
                        [&](const SensedObstacle &o, double gap, const Vec2 &nearest)
                        {
                            using Source = SensedObstacle::Source;
                            if (o.source == Source::Moving)
                                return;
                            // Toward a convex obstacle only the step's component along the direction of its
                            // nearest point counts (the supporting half-plane bounds the distance); the grid
                            // and non-convex polygons are braked for in every direction.
                            const bool convex = o.shape != SensedObstacle::Shape::Grid &&
                                                (o.polygon == nullptr || o.polygon->convex);
                            const double approach =
                                convex ? dot(step, unit(nearest - s.position)) : norm(step);
                            if (approach <= 0.0)
                                return;
                            const double share = o.source == Source::Robot ? 0.45 : 0.9;
                            limit = std::min(limit, share * std::max(gap - brakeMargin_, 0.0) / approach);
                        });
        if (limited != nullptr)
            *limited = limit < speed;
        if (limit >= speed)
            return v;
        return unit(v) * std::max(limit, kCreepSpeed);
    }
} // namespace mhplan

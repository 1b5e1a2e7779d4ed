// SPDX-License-Identifier: BSD-3-Clause
#include "ompl_planners/common/GmsSettings.h"

#include "src/base/Parameters.h"

#include <stdexcept>
#include <utility>

namespace mhplan
{
    namespace
    {
        constexpr ParamRange kReplaceFraction{
            "gms_replace_fraction", 0, 0.05, 1,
            "[GMS] replacement: share of the worst individuals redrawn each iteration (0 = off)"};
    } // namespace

    std::string GmsSettings::switchedOn() const
    {
        std::string on;
        for (const auto &s : {std::make_pair("gms_initial", initial), std::make_pair("gms_repair", repair),
                              std::make_pair("gms_revise", revise), std::make_pair("gms_simplify", simplify),
                              std::make_pair("gms_improve", improve),
                              std::make_pair(kReplaceFraction.name, replaceFraction > 0.0)})
            if (s.second)
                on += (on.empty() ? "'" : ", '") + std::string(s.first) + "'";
        return on;
    }

    void GmsSettings::setScope(const std::string &scope)
    {
        if (scope != "best" && scope != "all")
            throw std::invalid_argument("parameter 'gms_scope' must be 'best' or 'all'; got '" + scope + "'");
        scopeAll = scope == "all";
    }

    void GmsSettings::check() const
    {
        checkParameter(kReplaceFraction, replaceFraction);
    }

    std::string GmsSettings::refusal(bool exposesPopulation, const std::string &otherSpace,
                                     unsigned int dimension) const
    {
        if (!enabled())
            return "";
        const std::string on = switchedOn();
        if (!exposesPopulation)
            return "the [GMS] operator switches (" + on +
                   ") need an algorithm that exposes a waypoint population (SMA, LRSMA, MGO); this one does "
                   "not: switch them off";
        if (!otherSpace.empty())
            return "the [GMS] operator switches (" + on +
                   ") are planar (node/segment repair, simplification, improvement work on points of "
                   "R^2); the state space '" +
                   otherSpace + "' is not a RealVectorStateSpace: switch them off (docs/spaces.md)";
        if (dimension != 2)
            return "the [GMS] operator switches (" + on +
                   ") are planar (node/segment repair, simplification, improvement work on 2D points); the "
                   "space has dimension " +
                   std::to_string(dimension) + ": switch them off";
        return "";
    }

    void declareGmsParameters(ompl::base::ParamSet &params, GmsSettings &settings,
                              const std::function<void()> &changed)
    {
        declareSwitchField(
            params, "gms_initial", settings.initial,
            "[GMS] repair and node improvement of the initial population and of new individuals", changed);
        declareSwitchField(params, "gms_repair", settings.repair,
                           "[GMS] node and line-segment repair after every iteration", changed);
        declareSwitchField(params, "gms_revise", settings.revise,
                           "[GMS] revision (remove repeated nodes and loops) after every iteration", changed);
        declareSwitchField(params, "gms_simplify", settings.simplify,
                           "[GMS] simplification (drop waypoints that a straight segment can skip)", changed);
        declareSwitchField(params, "gms_improve", settings.improve,
                           "[GMS] node improvement after every iteration", changed);
        declareChoice(params, &settings, "gms_scope", &GmsSettings::setScope, &GmsSettings::scope, "best,all",
                      "individuals the [GMS] operators act on: the iteration's best or all");
        declareRangedField(params, kReplaceFraction, settings.replaceFraction, changed);
    }
} // namespace mhplan

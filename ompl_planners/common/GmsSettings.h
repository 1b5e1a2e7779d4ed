// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the switches of a population planner's [GMS] operator step (docs/algorithms.md 1.5) as one settings
   object: its fields, its OMPL parameters (gms_*, declared once by declareGmsParameters) and its checks. */
#ifndef MHPLAN_GMS_SETTINGS_H
#define MHPLAN_GMS_SETTINGS_H

#include <ompl/base/GenericParam.h>

#include <functional>
#include <string>

namespace mhplan
{
    /** \brief The [GMS] operator switches of a PopulationPlanner (all off by default; see its class doc). */
    struct GmsSettings
    {
        /** \brief gms_initial: node repair, line-segment repair and node improvement on the initial
            population and on every replacement individual ([GMS]'s placement). */
        bool initial{false};
        /** \brief gms_repair: node repair + line-segment repair on the operated individuals. */
        bool repair{false};
        /** \brief gms_revise: removal of repeated nodes and loops. */
        bool revise{false};
        /** \brief gms_simplify: simplification. */
        bool simplify{false};
        /** \brief gms_improve: node improvement. */
        bool improve{false};
        /** \brief gms_scope: the path operators act on every individual ("all") or on the iteration's best
            ("best", false). */
        bool scopeAll{false};
        /** \brief gms_replace_fraction: share of the population (the worst) redrawn each iteration (0..1,
            0 = off). */
        double replaceFraction{0.0};

        /** \brief True when a per-iteration path operator (repair, revise, simplify, improve) is on. */
        bool pathOperators() const { return repair || revise || simplify || improve; }
        /** \brief True when any switch is on (gms_scope alone is not a switch). */
        bool enabled() const { return initial || pathOperators() || replaceFraction > 0.0; }
        /** \brief The names of the switches that are on, quoted and comma-separated
            ("'gms_initial', 'gms_revise'"), for setup()'s refusals. */
        std::string switchedOn() const;

        /** \brief "best" or "all". */
        std::string scope() const { return scopeAll ? "all" : "best"; }
        /** \brief Set gms_scope; throws std::invalid_argument naming the parameter unless "best" or "all". */
        void setScope(const std::string &scope);
        /** \brief Throws std::invalid_argument naming the parameter, its range and the value when
            replaceFraction is outside [0, 1]. */
        void check() const;
        /** \brief Why setup() must refuse these switches ("" when it need not): a switch is on and the
            algorithm does not expose its population (\e exposesPopulation false), or the space is not
            R^2 (\e otherSpace: the name of a space that is not a RealVectorStateSpace, else ""; \e dimension:
            the RealVectorStateSpace's); the message names the switches that are on. */
        std::string refusal(bool exposesPopulation, const std::string &otherSpace,
                            unsigned int dimension) const;
    };

    /** \brief Declare the seven gms_* parameters on \e params, bound to \e settings (which must outlive
        \e params); \e changed is called after every change of a switch that setup() checks against the
        problem (all but gms_scope). */
    void declareGmsParameters(ompl::base::ParamSet &params, GmsSettings &settings,
                              const std::function<void()> &changed);
} // namespace mhplan

#endif

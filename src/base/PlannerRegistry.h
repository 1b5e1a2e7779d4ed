// SPDX-License-Identifier: BSD-3-Clause
/* mhplan: the string-keyed planner registry shared by the CLI, the benchmark driver and the tests (the
   generic class; the built-in planners are registered by the registry layer, src/registry/Registry.h). */
#ifndef MHPLAN_PLANNER_REGISTRY_H
#define MHPLAN_PLANNER_REGISTRY_H

#include "src/base/World.h"

#include <ompl/base/Planner.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mhplan
{
    using PlannerAllocator = std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr &)>;

    /** \brief What a planner declares it can do (PlannerEntry::capabilities; docs/spaces.md "Which planner
        runs where"): flags combined with |, e.g. cap::Planar | cap::Anytime | cap::Improved. The state-space
        flags name the spaces whose problems the planner's setup() accepts with its default parameters; the
        tests check every declaration against the planner's behaviour (tests/test_capabilities.cpp). */
    namespace cap
    {
        // The state spaces (a problem's space is exactly one of these; spaceFlag()).
        constexpr unsigned R2 = 1u << 0;         ///< ompl::base::RealVectorStateSpace of dimension 2
        constexpr unsigned Rk = 1u << 1;         ///< RealVectorStateSpace of any other dimension k >= 1
        constexpr unsigned SE2 = 1u << 2;        ///< SE2StateSpace (a rigid body in the plane)
        constexpr unsigned Dubins = 1u << 3;     ///< DubinsStateSpace (forward-only car)
        constexpr unsigned ReedsShepp = 1u << 4; ///< ReedsSheppStateSpace (car that reverses)
        constexpr unsigned SE3 = 1u << 5;        ///< SE3StateSpace (a rigid body in space)
        /** \brief Any other space (SO(2), SO(3), users' compounds): the planner tries, its setup() decides.
         */
        constexpr unsigned OtherSpace = 1u << 6;
        constexpr unsigned Planar = R2;
        constexpr unsigned AllSpaces = R2 | Rk | SE2 | Dubins | ReedsShepp | SE3 | OtherSpace;
        constexpr unsigned SpaceMask = AllSpaces;

        // Properties.
        /** \brief Needs a state validity checker that computes clearance (clearanceComputationType != NONE).
         */
        constexpr unsigned NeedsClearance = 1u << 8;
        /** \brief With its default parameters it keeps improving its solution until the termination
            condition holds (reporting each improvement); without it, it returns once it has a solution. */
        constexpr unsigned Anytime = 1u << 9;
        /** \brief Draws no random numbers: the same problem gives the same path whatever the seed. */
        constexpr unsigned Deterministic = 1u << 10;
        /** \brief An improved variant (not in the paper, docs/variants.md); without it the planner is
            faithful to its publication. */
        constexpr unsigned Improved = 1u << 11;
    } // namespace cap

    /** \brief The cap:: flag of a state space: cap::R2, cap::Rk, cap::SE2, cap::Dubins, cap::ReedsShepp,
        cap::SE3, else cap::OtherSpace. */
    unsigned spaceFlag(const ompl::base::StateSpace &space);

    /** \brief The cap:: flag of a world's configuration space (r2 -> cap::R2, se2 -> cap::SE2, ...). */
    unsigned spaceFlag(SpaceType space);

    /** \brief The readable name of one space flag ("R^2", "R^k", "SE(2)", "Dubins", "Reeds-Shepp", "SE(3)",
        "other spaces"). */
    std::string spaceName(unsigned flag);

    /** \brief The spaces among \e capabilities, comma-separated ("R^2, R^k, SE(2), ..."). */
    std::string spaceList(unsigned capabilities);

    /** \brief One registry entry. */
    struct PlannerEntry
    {
        std::string name;
        /** \brief "ompl" for OMPL's own planners, "mhplan" for this project's. */
        std::string origin;
        std::string description;
        PlannerAllocator allocate;
        /** \brief What the planner declares (cap:: flags combined with |). */
        unsigned capabilities{cap::AllSpaces};

        /** \brief True when every flag of \e flags is declared. */
        bool has(unsigned flags) const { return (capabilities & flags) == flags; }
        /** \brief True when the planner declares the space flag \e space (spaceFlag()). */
        bool runsOn(unsigned space) const { return (capabilities & space) != 0; }
        bool improved() const { return has(cap::Improved); }
    };

    /** \brief The allocator of planner type \e P constructed as P(si). */
    template <typename P> PlannerAllocator allocatorFor()
    {
        return [](const ompl::base::SpaceInformationPtr &si) -> ompl::base::PlannerPtr
        { return std::make_shared<P>(si); };
    }

    /** \brief Planner name -> allocator: a generic registry, filled by whoever owns one. The built-in
        registry, every planner mhplan knows, belongs to the registry layer (builtinPlanners() in
        src/registry/Registry.h); adding a planner is one line in its family's registration
        (ompl_planners/Registration.cpp). Campaigns, controllers and the CLI take the registry they are
        handed. */
    class PlannerRegistry
    {
      public:
        /** \brief Add an entry; throws std::invalid_argument if the name is taken (names and aliases are
            compared ignoring case). */
        void add(PlannerEntry entry);
        /** \brief Let \e alias name the entry \e name as well (e.g. OMPL.app's "kpiece" for "KPIECE1");
            throws std::invalid_argument when \e name is not registered or \e alias is taken. */
        void addAlias(const std::string &alias, const std::string &name);
        /** \brief True when \e name is an entry's name or alias, ignoring case. */
        bool has(const std::string &name) const;
        /** \brief The entry that \e name names (its name or an alias, ignoring case); throws InputError
            listing every registered name. The entry's own name is get(name).name. */
        const PlannerEntry &get(const std::string &name) const;
        /** \brief The entries' names (aliases not included). */
        std::vector<std::string> names() const;
        /** \brief Alias -> entry name. */
        const std::map<std::string, std::string> &aliases() const { return aliases_; }

        /** \brief Allocate planner \e name on \e si and apply \e params (applyPlannerParameters). */
        ompl::base::PlannerPtr create(const std::string &name, const ompl::base::SpaceInformationPtr &si,
                                      const std::map<std::string, std::string> &params = {}) const;

        /** \brief Empty when planner \e name declares the state space \e space (and, when \e clearance is
            false, does not need a checker that computes clearance); else one sentence saying why it cannot
           run there and naming a registered planner that does run there with its default parameters. Throws
            InputError for an unknown name. */
        std::string whyNotApplicable(const std::string &name, const ompl::base::StateSpace &space,
                                     bool clearance = true) const;
        /** \brief whyNotApplicable() for the problem of \e si (its space and its validity checker's
         * clearance). */
        std::string whyNotApplicable(const std::string &name, const ompl::base::SpaceInformation &si) const;
        /** \brief whyNotApplicable() for space flag \e space (cap::R2, ...); \e spaceLabel names it in the
            sentence (e.g. "the SE(2) world 'se2_narrow_passage'"). */
        std::string whyNotApplicable(const std::string &name, unsigned space, const std::string &spaceLabel,
                                     bool clearance = true) const;

      private:
        /** The entry's name for \e name (exact, then alias, then ignoring case); empty when unknown. */
        std::string resolve(const std::string &name) const;

        std::map<std::string, PlannerEntry> entries_;
        std::map<std::string, std::string> aliases_;
        /** Lower-cased name or alias -> entry name. */
        std::map<std::string, std::string> folded_;
    };

    /** \brief Set parameters on a planner, refusing (InputError) an unknown name (the message lists the
        planner's parameters) or a value that checkAgainstRange or OMPL's own setter refuses. The ranges of
        mhplan's own parameters (DescribedParam) are limits; OMPL's numeric range suggestions are hints for
        GUIs, not limits: any finite value the setter takes is accepted (docs/cli.md, "Planner parameters").
     */
    void applyPlannerParameters(ompl::base::Planner &planner,
                                const std::map<std::string, std::string> &params);

    /** \brief Check \e value against a range suggestion as a limit (the controllers' parameters use it);
        returns an empty string when it fits, else a description of what is accepted. Planners' parameters
        read OMPL's suggestions as hints instead (applyPlannerParameters). */
    std::string checkAgainstRange(const std::string &value, const std::string &range);

    /** \brief Parse "key=value" into the map; throws InputError on a malformed item. */
    void parseKeyValue(const std::string &item, std::map<std::string, std::string> &out);
} // namespace mhplan

#endif

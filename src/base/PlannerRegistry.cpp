// SPDX-License-Identifier: BSD-3-Clause
#include "src/base/PlannerRegistry.h"

#include "src/base/Parameters.h"
#include "src/base/World.h"

#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace ob = ompl::base;

namespace mhplan
{
    namespace
    {
        bool parseDouble(const std::string &s, double &out)
        {
            if (s.empty())
                return false;
            char *end = nullptr;
            errno = 0;
            out = std::strtod(s.c_str(), &end);
            return errno == 0 && end == s.c_str() + s.size() && std::isfinite(out);
        }

        /** \brief "nan", "inf", "-inf", "1e999" and the like: a number that is not finite. */
        bool notFinite(const std::string &s)
        {
            if (s.empty())
                return false;
            char *end = nullptr;
            const double v = std::strtod(s.c_str(), &end);
            return end == s.c_str() + s.size() && !std::isfinite(v);
        }

        /** \brief An integer range "lo:step:hi" (all three integers, as OMPL declares integer parameters). */
        bool integerRange(const std::vector<std::string> &parts)
        {
            if (parts.size() != 3)
                return false;
            for (const auto &p : parts)
                if (p.empty() || p.find_first_not_of("+-0123456789") != std::string::npos)
                    return false;
            return true;
        }

        std::vector<std::string> split(const std::string &s, char sep)
        {
            std::vector<std::string> out;
            std::stringstream ss(s);
            std::string item;
            while (std::getline(ss, item, sep))
                out.push_back(item);
            return out;
        }
        /** \brief OMPL's range suggestion \e range read as a hint (docs/cli.md, "Planner parameters"): a
            numeric one ("lo:step:hi", "lo:hi") asks for a finite number (an integer when all three are
            integers), not below zero when lo is not; its upper end is not enforced. A list asks for one of
            its items (checkAgainstRange). Empty when \e value is acceptable, else what is accepted. */
        std::string checkAgainstHint(const std::string &value, const std::string &range)
        {
            if (range.find(':') == std::string::npos)
                return checkAgainstRange(value, range);
            const std::vector<std::string> parts = split(range, ':');
            double lo = 0.0, hi = 0.0, v = 0.0;
            if ((parts.size() != 2 && parts.size() != 3) || !parseDouble(parts.front(), lo) ||
                !parseDouble(parts.back(), hi))
                return ""; // not a numeric range: nothing to enforce
            const bool integer = integerRange(parts);
            const bool nonNegative = lo >= 0.0;
            const std::string what = std::string(integer ? "an integer" : "a finite number") +
                                     (nonNegative ? " >= 0" : "") + " (OMPL suggests " + parts.front() +
                                     " to " + parts.back() + ")";
            if (!parseDouble(value, v) || (integer && v != std::floor(v)) || (nonNegative && v < 0.0))
                return what;
            return "";
        }
    } // namespace

    namespace
    {
        std::string folded(std::string s)
        {
            for (char &c : s)
                c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            return s;
        }
    } // namespace

    unsigned spaceFlag(const ob::StateSpace &space)
    {
        // Subclasses first: the Dubins and Reeds-Shepp spaces are SE2StateSpaces.
        if (const auto *rv = dynamic_cast<const ob::RealVectorStateSpace *>(&space))
            return rv->getDimension() == 2 ? cap::R2 : cap::Rk;
        if (dynamic_cast<const ob::DubinsStateSpace *>(&space) != nullptr)
            return cap::Dubins;
        if (dynamic_cast<const ob::ReedsSheppStateSpace *>(&space) != nullptr)
            return cap::ReedsShepp;
        if (dynamic_cast<const ob::SE2StateSpace *>(&space) != nullptr)
            return cap::SE2;
        if (dynamic_cast<const ob::SE3StateSpace *>(&space) != nullptr)
            return cap::SE3;
        return cap::OtherSpace;
    }

    unsigned spaceFlag(SpaceType space)
    {
        switch (space)
        {
        case SpaceType::R2:
            return cap::R2;
        case SpaceType::SE2:
            return cap::SE2;
        case SpaceType::Dubins:
            return cap::Dubins;
        case SpaceType::ReedsShepp:
            return cap::ReedsShepp;
        }
        return cap::OtherSpace;
    }

    std::string spaceName(unsigned flag)
    {
        switch (flag)
        {
        case cap::R2:
            return "R^2";
        case cap::Rk:
            return "R^k";
        case cap::SE2:
            return "SE(2)";
        case cap::Dubins:
            return "Dubins";
        case cap::ReedsShepp:
            return "Reeds-Shepp";
        case cap::SE3:
            return "SE(3)";
        case cap::OtherSpace:
            return "other spaces";
        default:
            return "?";
        }
    }

    std::string spaceList(unsigned capabilities)
    {
        std::string out;
        for (unsigned flag = 1; flag <= cap::OtherSpace; flag <<= 1)
            if ((capabilities & flag) != 0)
                out += (out.empty() ? "" : ", ") + spaceName(flag);
        return out.empty() ? "no state space" : out;
    }

    void PlannerRegistry::add(PlannerEntry entry)
    {
        if (entry.name.empty() || !entry.allocate)
            throw std::invalid_argument("planner registry: an entry needs a name and an allocator");
        const std::string name = entry.name;
        const auto taken = folded_.find(folded(name));
        if (taken != folded_.end())
            throw std::invalid_argument("planner registry: '" + name + "' is registered twice (as '" +
                                        taken->second + "')");
        entries_.emplace(name, std::move(entry));
        folded_.emplace(folded(name), name);
    }

    void PlannerRegistry::addAlias(const std::string &alias, const std::string &name)
    {
        if (entries_.count(name) == 0)
            throw std::invalid_argument("planner registry: alias '" + alias + "' names '" + name +
                                        "', which is not registered");
        const auto taken = folded_.find(folded(alias));
        if (alias.empty() || taken != folded_.end())
            throw std::invalid_argument("planner registry: alias '" + alias + "' is taken");
        aliases_.emplace(alias, name);
        folded_.emplace(folded(alias), name);
    }

    std::string PlannerRegistry::resolve(const std::string &name) const
    {
        if (entries_.count(name) != 0)
            return name;
        const auto alias = aliases_.find(name);
        if (alias != aliases_.end())
            return alias->second;
        const auto f = folded_.find(folded(name));
        return f == folded_.end() ? std::string() : f->second;
    }

    bool PlannerRegistry::has(const std::string &name) const
    {
        return !resolve(name).empty();
    }

    const PlannerEntry &PlannerRegistry::get(const std::string &name) const
    {
        const std::string resolved = resolve(name);
        if (!resolved.empty())
            return entries_.at(resolved);
        std::ostringstream msg;
        msg << "unknown planner '" << name << "'; registered planners:";
        for (const auto &n : names())
            msg << " " << n;
        if (!aliases_.empty())
        {
            msg << "; aliases (case is ignored):";
            for (const auto &kv : aliases_)
                msg << " " << kv.first;
        }
        throw InputError(msg.str());
    }

    std::vector<std::string> PlannerRegistry::names() const
    {
        std::vector<std::string> out;
        for (const auto &kv : entries_)
            out.push_back(kv.first);
        return out;
    }

    ob::PlannerPtr PlannerRegistry::create(const std::string &name, const ob::SpaceInformationPtr &si,
                                           const std::map<std::string, std::string> &params) const
    {
        ob::PlannerPtr planner = get(name).allocate(si);
        applyPlannerParameters(*planner, params);
        return planner;
    }

    std::string PlannerRegistry::whyNotApplicable(const std::string &name, unsigned space,
                                                  const std::string &spaceLabel, bool clearance) const
    {
        const PlannerEntry &entry = get(name);
        const bool spaceOk = entry.runsOn(space);
        const bool clearanceOk = clearance || !entry.has(cap::NeedsClearance);
        if (spaceOk && clearanceOk)
            return "";
        // A planner that does run there with its defaults: of the same origin if one does, faithful before
        // improved, then by name (the registry's order).
        const auto fits = [&](const PlannerEntry &e)
        { return e.runsOn(space) && (clearance || !e.has(cap::NeedsClearance)); };
        const PlannerEntry *alternative = nullptr;
        int bestRank = 4;
        for (const auto &kv : entries_)
        {
            const PlannerEntry &e = kv.second;
            if (!fits(e))
                continue;
            const int rank = (e.origin == entry.origin ? 0 : 2) + (e.improved() ? 1 : 0);
            if (rank < bestRank)
            {
                bestRank = rank;
                alternative = &e;
            }
        }
        std::string why = name + " cannot run on " + spaceLabel + ": ";
        why += spaceOk ? "it needs a state validity checker that computes clearance"
                       : "it plans on " + spaceList(entry.capabilities) + " only";
        if (alternative != nullptr)
            why += "; " + alternative->name + " runs there";
        return why;
    }

    std::string PlannerRegistry::whyNotApplicable(const std::string &name, const ob::StateSpace &space,
                                                  bool clearance) const
    {
        const unsigned flag = spaceFlag(space);
        std::string label = "the " + spaceName(flag) + " state space";
        if (flag == cap::Rk)
            label = "the R^" + std::to_string(space.getDimension()) + " state space";
        if (flag == cap::OtherSpace)
            label = "the state space '" + space.getName() + "'";
        return whyNotApplicable(name, flag, label, clearance);
    }

    std::string PlannerRegistry::whyNotApplicable(const std::string &name,
                                                  const ob::SpaceInformation &si) const
    {
        const ob::StateValidityCheckerPtr &checker = si.getStateValidityChecker();
        const bool clearance =
            checker && checker->getSpecs().clearanceComputationType != ob::StateValidityCheckerSpecs::NONE;
        return whyNotApplicable(name, *si.getStateSpace(), clearance);
    }

    std::string checkAgainstRange(const std::string &value, const std::string &range)
    {
        if (range.empty())
            return "";
        if (range.find(':') != std::string::npos)
        {
            const std::vector<std::string> parts = split(range, ':');
            double lo = 0.0, hi = 0.0, v = 0.0;
            if ((parts.size() != 2 && parts.size() != 3) || !parseDouble(parts.front(), lo) ||
                !parseDouble(parts.back(), hi))
                return ""; // not a numeric range: nothing to enforce
            const bool integer = integerRange(parts);
            const std::string what = integer ? "an integer in [" : "a finite number in [";
            if (!parseDouble(value, v) || v < lo || v > hi || (integer && v != std::floor(v)))
                return what + parts.front() + ", " + parts.back() + "]";
            return "";
        }
        const std::vector<std::string> options = split(range, ',');
        for (const auto &o : options)
            if (o == value)
                return "";
        // Booleans are declared as "0,1"; accept the usual spellings too.
        if (range == "0,1" && (value == "true" || value == "false"))
            return "";
        return "one of {" + range + "}";
    }

    void applyPlannerParameters(ob::Planner &planner, const std::map<std::string, std::string> &params)
    {
        ob::ParamSet &ps = planner.params();
        for (const auto &kv : params)
        {
            if (!ps.hasParam(kv.first))
            {
                std::ostringstream msg;
                msg << "planner '" << planner.getName() << "' has no parameter '" << kv.first
                    << "'; its parameters:";
                std::vector<std::string> names;
                ps.getParamNames(names);
                if (names.empty())
                    msg << " (none)";
                for (const auto &n : names)
                    msg << " " << n;
                throw InputError(msg.str());
            }
            const std::string range = ps[kv.first].getRangeSuggestion();
            // The planner's own current value is always accepted (some OMPL defaults sit outside their
            // declared range suggestion, e.g. PRM's max_nearest_neighbors).
            if (kv.second == ps[kv.first].getValue())
                continue; // nothing to change (OMPL's own default may be "inf" or outside its suggestion)
            // mhplan's own parameters (declared with a description, src/base/Parameters.h) have ranges
            // that are limits, checked by their setters too; OMPL's suggestions are hints.
            const bool limit = dynamic_cast<const ParameterDescription *>(&ps[kv.first]) != nullptr;
            std::string problem =
                limit ? checkAgainstRange(kv.second, range) : checkAgainstHint(kv.second, range);
            if (problem.empty() && notFinite(kv.second))
                problem = "a finite number";
            double number = 0.0;
            const bool numeric = range.find(':') != std::string::npos;
            if (!problem.empty() && numeric && !parseDouble(kv.second, number) && !notFinite(kv.second))
                throw InputError("planner '" + planner.getName() + "' parameter '" + kv.first + "': value '" +
                                 kv.second + "' is not a number; expected " + problem);
            if (!problem.empty())
                throw InputError("planner '" + planner.getName() + "' parameter '" + kv.first + "': value '" +
                                 kv.second + "' is out of range; expected " + problem);
            std::string value = kv.second;
            const std::string old = ps[kv.first].getValue();
            if (range == "0,1" && (value == "true" || value == "false"))
                value = value == "true" ? "1" : "0";
            bool ok = false;
            try
            {
                ok = ps.setParam(kv.first, value);
            }
            catch (const std::exception &e)
            {
                throw InputError("planner '" + planner.getName() + "' parameter '" + kv.first +
                                 "': " + e.what());
            }
            if (!ok)
                throw InputError("planner '" + planner.getName() + "' parameter '" + kv.first +
                                 "': cannot set value '" + kv.second + "'" +
                                 (range.empty() ? "" : " (expected " + range + ")"));
            // What OMPL stored must be the number given: its setters cast to the parameter's type, so an
            // unsigned parameter would keep 2 for 2.5 and 4294967295 for -1 (docs/cli.md, "Planner
            // parameters"). OMPL prints doubles to six significant digits: compare to that precision.
            double given = 0.0, stored = 0.0;
            const std::string storedText = ps[kv.first].getValue();
            if (parseDouble(value, given) && parseDouble(storedText, stored) &&
                std::fabs(stored - given) > 1e-5 * std::max(1.0, std::fabs(given)))
            {
                ps.setParam(kv.first, old);
                throw InputError("planner '" + planner.getName() + "' parameter '" + kv.first + "': value '" +
                                 kv.second + "' is out of range; OMPL would store it as " + storedText +
                                 (range.empty() ? "" : " (OMPL suggests " + range + ")"));
            }
        }
    }

    void parseKeyValue(const std::string &item, std::map<std::string, std::string> &out)
    {
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError("expected key=value, got '" + item + "'");
        out[item.substr(0, eq)] = item.substr(eq + 1);
    }

} // namespace mhplan

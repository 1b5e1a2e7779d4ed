// SPDX-License-Identifier: BSD-3-Clause
/* mhplan CLI: a small argument parser that refuses what it does not know. */
#ifndef MHPLAN_CLI_ARGS_H
#define MHPLAN_CLI_ARGS_H

#include "src/optimum/Optimum.h"
#include "src/base/World.h"
#include "src/collision/Problem.h"

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace mhplan::cli
{
    /** \brief The range of every time limit (--time of plan, compare and bench; a campaign's time_limit):
        1 ms to 10^6 s. Beyond 1e9 s OMPL's deadline overflows (it stopped after 3 ms at 1e10). */
    constexpr double kMinTimeLimit = 1e-3;
    constexpr double kMaxTimeLimit = 1e6;

    /** \brief Parsed command line of one subcommand: positionals, single-valued options, repeatable options
        and flags. Unknown options, missing values and repeated single options raise InputError naming the
        option and listing the accepted ones. */
    class Args
    {
      public:
        struct Spec
        {
            std::set<std::string> valued;     ///< --name VALUE (at most once)
            std::set<std::string> repeatable; ///< --name VALUE (any number of times)
            std::set<std::string> flags;      ///< --name
        };

        Args(const std::string &command, const std::vector<std::string> &argv, const Spec &spec);

        const std::vector<std::string> &positional() const { return positional_; }
        bool has(const std::string &name) const
        {
            return values_.count(name) != 0 || flags_.count(name) != 0;
        }
        std::string get(const std::string &name, const std::string &fallback = "") const;
        const std::vector<std::string> &all(const std::string &name) const;

        double number(const std::string &name, double fallback) const;
        long long integer(const std::string &name, long long fallback) const;
        /** \brief --time: seconds per run in [kMinTimeLimit, kMaxTimeLimit], the range of a campaign's
            time_limit (one range for plan, compare and bench). */
        double timeLimit(double fallback) const;
        /** \brief "x,y" */
        Vec2 point(const std::string &name) const;

        const std::string &command() const { return command_; }

      private:
        std::string command_;
        std::vector<std::string> positional_;
        std::map<std::string, std::string> values_;
        std::map<std::string, std::vector<std::string>> repeated_;
        std::set<std::string> flags_;
    };

    /** \brief The one WORLD positional argument (a file or a shipped world name), loaded and validated. */
    World loadWorldArg(const Args &args);
    /** \brief --start/--goal, else --query NAME, else the world's first query. */
    Query queryFromArgs(const World &world, const Args &args);
    /** \brief --setup exact|app and --resolution R (app only; docs/setups.md). Refuses (InputError naming
        the option and what is accepted) an unknown set-up, a resolution out of range or one without
        --setup app. */
    ValiditySetup setupFromArgs(const Args &args);

    /** \brief Apply --seed (1..2^32-1) to OMPL's RNG before any generator exists; returns the seed in use. */
    std::uint_fast32_t seedFromArgs(const Args &args);

    /** \brief The exact optimum, or why there is none (a world type it does not support, no path). */
    struct OptimumOrReason
    {
        OptimumResult result;
        std::string reason;
    };
    OptimumOrReason optimumOrReason(const World &world, const Query &query);

    /** \brief Refuse an output file before any work: when option \e name is given, its value must not be a
        directory and its directory must exist and be writable. Throws InputError naming the option, the path
        and what is wrong. */
    void checkOutputFile(const Args &args, const std::string &name);
    /** \brief The same for an output directory \e path (option \e name): an existing writable directory,
        or a path whose nearest existing ancestor is a writable directory (it is created later). */
    void checkOutputDirectory(const std::string &command, const std::string &name, const std::string &path);

    /** \brief Parse a list of numbers "a,b,c" for option \e name; throws InputError naming the option. */
    std::vector<double> parseNumberList(const std::string &name, const std::string &text);
} // namespace mhplan::cli

#endif

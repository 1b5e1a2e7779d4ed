// SPDX-License-Identifier: BSD-3-Clause
/* mhplan CLI: the help of every subcommand, one table each (arguments, options, examples, exit codes).
   `mhplan SUBCOMMAND --help` prints it; `mhplan --help` lists every subcommand's synopsis. A subcommand joins
   by one entry in main.cpp's command table; a new option by one OptionDoc line in its command's table (the
   tests check that the help lists exactly the options the parser accepts). */
#ifndef MHPLAN_CLI_HELP_H
#define MHPLAN_CLI_HELP_H

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace mhplan::cli
{
    /** \brief One option of a subcommand: "--name", its value's placeholder (empty for a flag) and what
        it does (the default included). */
    struct OptionDoc
    {
        std::string name;
        std::string value;
        std::string text;
    };

    /** \brief The help of one subcommand. */
    struct CommandDoc
    {
        /** \brief The command and its arguments, e.g. "plan WORLD [options]". */
        std::string synopsis;
        /** \brief One line: what it does (shown by `mhplan --help`). */
        std::string summary;
        /** \brief More about it (may be empty). */
        std::string details;
        /** \brief Positional arguments: name, meaning. */
        std::vector<std::pair<std::string, std::string>> arguments;
        std::vector<OptionDoc> options;
        /** \brief Complete command lines (without the leading "mhplan "). */
        std::vector<std::string> examples;
        /** \brief The exit codes and what they mean. */
        std::string exitCodes{"0 success, 1 bad input, 2 internal error"};
    };

    /** \brief The full help text of \e doc. */
    void printCommandHelp(std::ostream &out, const CommandDoc &doc);

    /** \brief Options several subcommands share (the same text everywhere). */
    namespace options
    {
        OptionDoc seed();
        OptionDoc query();
        OptionDoc start();
        OptionDoc goal();
        OptionDoc json(const std::string &what);
        OptionDoc svg(const std::string &what);
        /** \brief --setup exact|app and --resolution R (docs/setups.md). */
        OptionDoc setup();
        OptionDoc resolution();
    } // namespace options

    /** \brief The environment variables mhplan reads: name, meaning. */
    const std::vector<std::pair<std::string, std::string>> &environmentVariables();

    /** \brief Help tables of the subcommands (defined beside each command). */
    const CommandDoc &planDoc();
    const CommandDoc &generateDoc();
    const CommandDoc &worldsDoc();
    const CommandDoc &plannersDoc();
    const CommandDoc &controllersDoc();
    const CommandDoc &scenariosDoc();
    const CommandDoc &compareDoc();
    const CommandDoc &benchDoc();
    const CommandDoc &reportDoc();
    const CommandDoc &arenaDoc();
    const CommandDoc &scenDoc();
    const CommandDoc &optimumDoc();
    const CommandDoc &simDoc();
} // namespace mhplan::cli

#endif

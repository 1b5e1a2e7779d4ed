// SPDX-License-Identifier: BSD-3-Clause
#include "src/cli/Help.h"

#include <algorithm>
#include <sstream>

namespace mhplan::cli
{
    namespace
    {
        /** \e text wrapped at \e width columns, every line after the first indented by \e indent. */
        std::string wrap(const std::string &text, std::size_t indent, std::size_t width = 100)
        {
            std::string out;
            std::size_t column = indent;
            std::istringstream words(text);
            std::string word;
            bool first = true;
            while (words >> word)
            {
                if (!first && column + 1 + word.size() > width)
                {
                    out += "\n" + std::string(indent, ' ');
                    column = indent;
                    first = true;
                }
                out += (first ? "" : " ") + word;
                column += word.size() + (first ? 0 : 1);
                first = false;
            }
            return out;
        }
    } // namespace

    void printCommandHelp(std::ostream &out, const CommandDoc &doc)
    {
        out << "usage: mhplan " << doc.synopsis << "\n\n" << wrap(doc.summary, 0) << "\n";
        if (!doc.details.empty())
            out << "\n" << wrap(doc.details, 0) << "\n";
        std::size_t column = 0;
        for (const auto &a : doc.arguments)
            column = std::max(column, a.first.size());
        for (const auto &o : doc.options)
            column = std::max(column, o.name.size() + (o.value.empty() ? 0 : 1 + o.value.size()));
        column = std::min<std::size_t>(column + 4, 30);
        const auto row = [&](const std::string &left, const std::string &text)
        {
            out << "  " << left;
            if (left.size() + 2 >= column)
                out << "\n" << std::string(column + 2, ' ');
            else
                out << std::string(column - left.size(), ' ');
            out << wrap(text, column + 2) << "\n";
        };
        if (!doc.arguments.empty())
        {
            out << "\narguments:\n";
            for (const auto &a : doc.arguments)
                row(a.first, a.second);
        }
        out << "\noptions:\n";
        for (const auto &o : doc.options)
            row(o.name + (o.value.empty() ? "" : " " + o.value), o.text);
        row("--help, -h", "print this help and exit");
        if (!doc.examples.empty())
        {
            out << "\nexamples:\n";
            for (const auto &e : doc.examples)
                out << "  mhplan " << e << "\n";
        }
        out << "\nexit codes: " << wrap(doc.exitCodes, 12) << "\n";
    }

    namespace options
    {
        OptionDoc setup()
        {
            return {"--setup", "exact|app",
                    "how validity is checked (docs/setups.md): exact (default: mhplan's exact checker and "
                    "motion validator) or app (as a user's OMPL program: a plain point checker and OMPL's "
                    "DiscreteMotionValidator at --resolution); the path is still checked exactly"};
        }

        OptionDoc resolution()
        {
            return {"--resolution", "R",
                    "with --setup app: the validity-checking resolution, a fraction of the space's maximum "
                    "extent, 0.00001..0.5 (default 0.002)"};
        }

        OptionDoc seed()
        {
            return {
                "--seed", "N",
                "seed of OMPL's random number generator, 1..4294967295 (default: from the clock; the seed "
                "in use is printed). Giving it again reproduces a run bounded by iterations "
                "(max_iterations); a run bounded by time ends wherever the clock stops it, so its path "
                "may differ"};
        }
        OptionDoc query()
        {
            return {"--query", "NAME", "the world's query of that name (default: the world's first query)"};
        }
        OptionDoc start()
        {
            return {"--start", "X,Y", "start position (with --goal; instead of --query)"};
        }
        OptionDoc goal()
        {
            return {"--goal", "X,Y", "goal position (with --start)"};
        }
        OptionDoc json(const std::string &what)
        {
            return {"--json", "",
                    "print " + what +
                        " as one JSON document on stdout instead of the text (field names: "
                        "docs/cli.md)"};
        }
        OptionDoc svg(const std::string &what)
        {
            return {"--svg", "FILE",
                    "write " + what +
                        " as an SVG picture (the directory must exist and be writable; checked "
                        "before the run)"};
        }
    } // namespace options

    const std::vector<std::pair<std::string, std::string>> &environmentVariables()
    {
        static const std::vector<std::pair<std::string, std::string>> vars = {
            {"MHPLAN_ENVIRONMENTS", "directory of the shipped worlds and scenarios (default: the installed "
                                    "share/mhplan/environments, "
                                    "else the source tree's environments/)"},
            {"MHPLAN_ANALYSIS",
             "directory holding report.py for 'mhplan report' (default: the installed share/mhplan/analysis, "
             "else the source tree's analysis/)"},
            {"MHPLAN_PYTHON", "Python interpreter for 'mhplan report' (default: /usr/bin/python3)"},
            {"MHPLAN_BIN",
             "set by 'mhplan report' for report.py: the mhplan program it asks for worlds (mhplan worlds "
             "FILE --json)"},
            {"MHPLAN_VERBOSE",
             "when set, OMPL's debug messages are printed (default: warnings and errors only)"},
        };
        return vars;
    }
} // namespace mhplan::cli

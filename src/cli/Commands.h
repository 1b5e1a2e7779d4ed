/* mhplan CLI: one function per subcommand. */
#ifndef MHPLAN_CLI_COMMANDS_H
#define MHPLAN_CLI_COMMANDS_H

#include <string>
#include <vector>

namespace mhplan::cli
{
    using Args = std::vector<std::string>;
    int cmdPlan(const Args &args);
    int cmdGenerate(const Args &args);
    int cmdWorlds(const Args &args);
    int cmdPlanners(const Args &args);
}  // namespace mhplan::cli

#endif

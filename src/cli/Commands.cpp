#include "Commands.h"
namespace mhplan::cli
{
    int cmdPlan(const Args &) { return 1; }
    int cmdGenerate(const Args &) { return 1; }
    int cmdWorlds(const Args &) { return 1; }
    int cmdPlanners(const Args &) { return 1; }
}

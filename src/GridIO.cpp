#include "GridIO.h"

namespace mhplan
{
    OccupancyGrid parseMovingAIMap(std::istream &, const std::string &fileName, double)
    {
        throw InputError(fileName + ": MovingAI maps not supported yet");
    }
    OccupancyGrid loadMovingAIMap(const std::string &path, double) { throw InputError(path + ": not supported yet"); }
    std::string movingAIMapText(const OccupancyGrid &) { return ""; }
    OccupancyGrid parsePgm(std::istream &, const std::string &fileName, double, double, bool)
    {
        throw InputError(fileName + ": PGM not supported yet");
    }
    OccupancyGrid loadPgm(const std::string &path, double, double, bool) { throw InputError(path + ": not supported yet"); }
    World gridWorld(const std::string &name, std::shared_ptr<const OccupancyGrid> grid)
    {
        World w;
        w.name = name;
        w.bounds = grid->bounds();
        w.grid = std::move(grid);
        return w;
    }
}  // namespace mhplan

// SPDX-License-Identifier: BSD-3-Clause
#include "src/cli/Commands.h"

#include "src/cli/Args.h"
#include "src/collision/Collision.h"
#include "src/io/Generators.h"
#include "src/io/GridIO.h"
#include "src/optimum/Optimum.h"
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "src/sim/Controllers.h"
#include "src/draw/Svg.h"
#include "src/collision/Validity.h"
#include "src/io/WorldIO.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/RandomNumbers.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace fs = std::filesystem;

namespace mhplan::cli
{
    std::string environmentsDir()
    {
        if (const char *env = std::getenv("MHPLAN_ENVIRONMENTS"))
            return env;
        // An installed program uses its share/mhplan/environments; a build tree the source tree's worlds.
        std::error_code ec;
        const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        if (!ec)
        {
            const fs::path installed = exe.parent_path().parent_path() / MHPLAN_INSTALLED_ENVIRONMENTS_DIR;
            if (fs::is_directory(installed))
                return installed.string();
        }
        return MHPLAN_ENVIRONMENTS_DIR;
    }

    std::string resolveWorldPath(const std::string &arg)
    {
        if (fs::exists(arg))
            return arg;
        for (const WorldFormat &format : worldFormats()) // the formats loadWorld reads, in their order
            for (const std::string &ext : format.extensions)
            {
                const fs::path p = fs::path(environmentsDir()) / (arg + "." + ext);
                if (fs::exists(p))
                    return p.string();
            }
        throw InputError("world '" + arg + "': no such file, and no shipped world of that name in " +
                         environmentsDir() + " (see 'mhplan worlds')");
    }

    std::vector<std::string> shippedWorldFiles()
    {
        std::vector<std::string> out;
        if (!fs::is_directory(environmentsDir()))
            return out;
        for (const auto &e : fs::directory_iterator(environmentsDir()))
        {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".yaml" || ext == ".yml"))
                out.push_back(e.path().string());
        }
        std::sort(out.begin(), out.end());
        return out;
    }

    World loadWorldArg(const Args &args)
    {
        if (args.positional().size() != 1)
            throw InputError("mhplan " + args.command() +
                             ": expected exactly one WORLD argument (a file or a shipped "
                             "world name; see 'mhplan worlds')");
        return loadWorld(resolveWorldPath(args.positional()[0]));
    }

    Query queryFromArgs(const World &world, const Args &args)
    {
        if (args.has("start") || args.has("goal"))
        {
            if (!(args.has("start") && args.has("goal")))
                throw InputError("mhplan " + args.command() + ": give both --start X,Y and --goal X,Y");
            if (args.has("query"))
                throw InputError("mhplan " + args.command() + ": give either --query or --start/--goal");
            return {"command-line", args.point("start"), args.point("goal")};
        }
        return world.queryOrDefault(args.get("query"));
    }

    std::uint_fast32_t seedFromArgs(const Args &args)
    {
        const long long seed = args.integer("seed", 0);
        if (args.has("seed") && (seed <= 0 || seed > 0xFFFFFFFFLL))
            throw InputError("mhplan " + args.command() + ": --seed must be in [1, 4294967295] (got " +
                             args.get("seed") + ")");
        // Without --seed, OMPL's own first seed (from the clock; on 64-bit Linux wider than 32 bits) is
        // folded into [1, 2^32 - 1] and set, so that the printed seed, given as --seed, reproduces the run.
        const std::uint_fast32_t used =
            args.has("seed") ? static_cast<std::uint_fast32_t>(seed)
                             : static_cast<std::uint_fast32_t>(ompl::RNG::getSeed() % 0xFFFFFFFFULL + 1);
        ompl::RNG::setSeed(used);
        return used;
    }

    OptimumOrReason optimumOrReason(const World &world, const Query &query)
    {
        OptimumOrReason out;
        try
        {
            out.result = computeOptimum(world, query);
            if (!out.result.found)
                out.reason = "start and goal are not connected";
        }
        catch (const InputError &e)
        {
            out.reason = e.what();
        }
        return out;
    }

    std::string resolveScenarioPath(const std::string &arg)
    {
        if (fs::exists(arg))
            return arg;
        for (const fs::path &dir : {fs::path(environmentsDir()) / "scenarios", fs::path(environmentsDir())})
            for (const char *ext : {".yaml", ".yml"})
            {
                const fs::path p = dir / (arg + ext);
                if (fs::exists(p))
                    return p.string();
            }
        throw InputError("scenario '" + arg + "': no such file, and no shipped scenario of that name in " +
                         (fs::path(environmentsDir()) / "scenarios").string() + " (see 'mhplan scenarios')");
    }
} // namespace mhplan::cli

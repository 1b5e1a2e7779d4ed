// SPDX-License-Identifier: BSD-3-Clause
/* mhplan ROS 1 component: shared plumbing of the node programs (see NodeSupport.h). */
#include "NodeSupport.h"

#include "src/base/World.h"

#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <iostream>
#include <vector>

namespace mhplan::ros1
{
    cli::Args nodeArgs(const std::string &program, int argc, char **argv, const cli::Args::Spec &spec)
    {
        std::vector<std::string> args;
        for (int i = 1; i < argc; ++i)
        {
            const std::string a = argv[i];
            if (a.find(":=") == std::string::npos)
                args.push_back(a);
        }
        return cli::Args(program, args, spec);
    }

    std::uint32_t applySeed(const cli::Args &args)
    {
        const long long seed = args.integer("seed", 1);
        if (seed <= 0 || seed > 0xFFFFFFFFLL)
            throw InputError(args.command() + ": --seed must be in [1, 4294967295] (got " + args.get("seed") +
                             ")");
        ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed));
        return static_cast<std::uint32_t>(seed);
    }

    int runNode(const std::string &program, const std::function<int()> &body)
    {
        try
        {
            return body();
        }
        catch (const InputError &e)
        {
            std::cerr << program << ": " << e.what() << "\n";
            return 2;
        }
        catch (const std::exception &e)
        {
            std::cerr << program << ": " << e.what() << "\n";
            return 1;
        }
    }

    double wallNow()
    {
        using clock = std::chrono::steady_clock;
        return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
    }
} // namespace mhplan::ros1

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan ROS 1 component: what the node programs share: their command line, the seed, error reporting. */
#ifndef MHPLAN_ROS_NODE_SUPPORT_H
#define MHPLAN_ROS_NODE_SUPPORT_H

#include "src/cli/Args.h"

#include <cstdint>
#include <functional>
#include <string>

namespace mhplan::ros1
{
    /** \brief The program's arguments without ROS's remappings (NAME:=VALUE), parsed by the CLI's parser
        (unknown options are refused with the accepted ones). */
    cli::Args nodeArgs(const std::string &program, int argc, char **argv, const cli::Args::Spec &spec);
    /** \brief --seed (1 .. 2^32-1, default 1) set as OMPL's seed before any generator exists. */
    std::uint32_t applySeed(const cli::Args &args);
    /** \brief Run \e body; an InputError or other exception is printed as "PROGRAM: message" with exit code 2
        (bad input) or 1. */
    int runNode(const std::string &program, const std::function<int()> &body);
    /** \brief Wall-clock seconds (steady clock). */
    double wallNow();
} // namespace mhplan::ros1

#endif

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: OMPL.app problem files as campaign worlds. An entry {cfg: FILE} (FILE relative to the
   campaign file) is one planning experiment on the problem's meshes: its start and goal, volume, robot,
   objective and problem context; the campaign's planners, runs and limits (docs/omplapp.md, "Campaigns"). */
#ifndef MHPLAN_BENCH_CFG_WORLDS_H
#define MHPLAN_BENCH_CFG_WORLDS_H

#include "benchmarks/Campaign.h"
#include "src/io/CfgIO.h"
#include "src/io/YamlReader.h"

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace mhplan::bench::detail
{
    /** \brief Read a world entry {cfg: FILE} into \e w; InputError names the campaign file, line and field.
     */
    void readCfgWorld(const YamlReader &r, const YAML::Node &entry, const std::string &field, WorldSpec &w);

    /** \brief The inputs of the problem file \e cfgFile: its bytes and both meshes' bytes, each once. */
    struct CfgInputs
    {
        CfgProblem cfg;
        /** \brief fingerprint() of the .cfg text, the environment mesh and the robot mesh, with labels. */
        std::string hash;
    };

    /** \brief Read and parse \e cfgFile and fingerprint it with its meshes (InputError names the file). */
    CfgInputs readCfgInputs(const std::string &cfgFile);

    /** \brief Append the experiment of entry \e spec (campaign.worlds[\e index]): the problem is read, its
        meshes loaded and its start and goal checked (makeMeshSetup) before anything runs; a planner that
        cannot plan on its SE(2) or SE(3) space is refused or skipped as for any world. \e common is the
        campaign part of the fingerprint; the experiment's fingerprint adds the .cfg and both meshes. */
    void appendCfgExperiment(const Campaign &campaign, const WorldSpec &spec, std::size_t index,
                             const std::function<std::string(const std::string &)> &locate,
                             const std::string &common, std::set<std::string> &names,
                             std::vector<Experiment> &out);

    /** \brief Planners of \e campaign that cannot run on a space of flag \e space (cap::): their indices
        with skip_inapplicable, else InputError naming the planner's line and the world. */
    std::vector<std::size_t> inapplicablePlanners(const Campaign &campaign, unsigned space, std::size_t world,
                                                  const std::string &worldName);
} // namespace mhplan::bench::detail

#endif

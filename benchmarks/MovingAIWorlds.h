// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: MovingAI benchmark sets as campaign worlds. An entry {map: FILE.map, scen: FILE.map.scen}
   (optionally problems_per_bucket: K, buckets: [..], every: k) makes each selected .scen problem one planning
   experiment "MAP-b<bucket>-l<line>" of the campaign. */
#ifndef MHPLAN_BENCH_MOVINGAI_WORLDS_H
#define MHPLAN_BENCH_MOVINGAI_WORLDS_H

#include "benchmarks/Campaign.h"
#include "src/io/YamlReader.h"

#include <set>
#include <string>
#include <vector>

namespace mhplan::bench::detail
{
    /** \brief Read a MovingAI world entry (a mapping with the key "map") into \e w; InputError names the
        campaign file, line and field. */
    void readMovingAIWorld(const YamlReader &r, const YAML::Node &entry, const std::string &field,
                           WorldSpec &w);

    /** \brief Append the experiments of MovingAI entry \e spec (campaign.worlds[\e index]) to \e out. The map
        and scenario are found with \e locate. Each selected problem's .scen optimum is checked against
        mhplan's octile optimum (scenOptimumMatches): a disagreement is refused naming the .scen file and
        line, both values and the tolerance. \e common is the campaign part of the fingerprint. */
    void appendMovingAIExperiments(const Campaign &campaign, const WorldSpec &spec, std::size_t index,
                                   const std::function<std::string(const std::string &)> &locate,
                                   const std::string &common, std::set<std::string> &names,
                                   std::vector<Experiment> &out);
} // namespace mhplan::bench::detail

#endif

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: the 'setup' key of a campaign and of its world entries (docs/setups.md). */
#ifndef MHPLAN_BENCH_CAMPAIGN_SETUPS_H
#define MHPLAN_BENCH_CAMPAIGN_SETUPS_H

#include "benchmarks/Campaign.h"
#include "src/io/YamlReader.h"

#include <string>
#include <vector>

namespace mhplan::bench
{
    /** \brief Read a 'setup' value: exact, app, {app: {resolution: R}} or a non-empty list of these (each
        at most once). InputError names the campaign file, line and field and the accepted forms. */
    std::vector<ValiditySetup> readSetups(const YamlReader &r, const YAML::Node &n, const std::string &field);
} // namespace mhplan::bench

#endif

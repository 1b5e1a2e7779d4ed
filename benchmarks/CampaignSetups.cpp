// SPDX-License-Identifier: BSD-3-Clause
/* mhplan bench: the 'setup' key of a campaign and of its world entries (docs/setups.md,
   benchmarks/README.md "Set-ups"): which validity checker and motion validator the experiments run with. */
#include "mhplan/bench/CampaignSetups.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>

namespace mhplan::bench
{
    namespace
    {
        const char *const kSetupForms = "expected exact, app, {app: {resolution: R}} or a list of these";

        ValiditySetup readOne(const YamlReader &r, const YAML::Node &n, const std::string &field)
        {
            try
            {
                if (n.IsScalar())
                    return makeValiditySetup(r.nonEmptyText(n, field), std::nan(""));
                if (!n.IsMap() || n.size() != 1)
                    r.fail(n, field, kSetupForms);
                const std::string kind = r.key(n.begin()->first, field);
                const YAML::Node body = n.begin()->second;
                const std::string sub = field + "." + kind;
                if (kind != "app")
                    r.fail(n, field,
                           "unknown set-up '" + kind + "'; " + kSetupForms + " (exact takes no settings)");
                double resolution = std::nan("");
                if (body.IsDefined() && !body.IsNull())
                {
                    if (!body.IsMap())
                        r.fail(body, sub, "expected a mapping {resolution: R}");
                    r.allowKeys(body, sub, {"resolution"});
                    if (body["resolution"].IsDefined())
                        resolution = r.number(body["resolution"], sub + ".resolution");
                }
                try
                {
                    return makeValiditySetup(kind, resolution);
                }
                catch (const InputError &e)
                {
                    r.fail(body["resolution"], sub + ".resolution", e.what());
                }
            }
            catch (const InputError &e)
            {
                const std::string what = e.what();
                if (what.find(r.file()) == 0) // already located
                    throw;
                r.fail(n, field, what);
            }
        }
    } // namespace

    std::vector<ValiditySetup> readSetups(const YamlReader &r, const YAML::Node &n, const std::string &field)
    {
        std::vector<ValiditySetup> out;
        if (n.IsSequence())
        {
            if (n.size() == 0)
                r.fail(n, field, kSetupForms);
            for (std::size_t i = 0; i < n.size(); ++i)
            {
                const std::string f = field + "[" + std::to_string(i) + "]";
                const ValiditySetup s = readOne(r, n[i], f);
                for (const ValiditySetup &t : out)
                    if (t == s)
                        r.fail(n[i], f, "set-up '" + s.describe() + "' listed twice");
                out.push_back(s);
            }
            return out;
        }
        out.push_back(readOne(r, n, field));
        return out;
    }

    std::string setupSuffix(const ValiditySetup &setup)
    {
        if (!setup.app())
            return "";
        if (setup.resolution == kDefaultAppResolution)
            return "-app";
        char buf[40];
        std::snprintf(buf, sizeof buf, "-app%.6g", setup.resolution);
        return buf;
    }
} // namespace mhplan::bench

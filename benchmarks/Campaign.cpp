// SPDX-License-Identifier: BSD-3-Clause
#include "benchmarks/Campaign.h"
#include "benchmarks/CampaignSetups.h"
#include "benchmarks/CfgWorlds.h"
#include "benchmarks/MovingAIWorlds.h"

#include "src/collision/Collision.h"
#include "src/sim/Controllers.h"
#include "src/collision/Problem.h"
#include "src/collision/RigidBody.h"
#include "src/sim/ScenarioIO.h"
#include "src/base/World.h"
#include "src/io/InputFile.h"
#include "src/io/WorldIO.h"
#include "src/io/YamlReader.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace mhplan::bench
{
    namespace
    {
        std::string readFile(const std::string &path, const std::string &what)
        {
            return readInputFile(path, kMaxYamlBytes, what);
        }

        /** Names that OMPL's log format and the database accept unchanged: no blanks, no ';' or ','. */
        bool plainName(const std::string &s)
        {
            if (s.empty())
                return false;
            for (char c : s)
                if (std::isspace(static_cast<unsigned char>(c)) || c == ';' || c == ',' || c == '"' ||
                    c == '\'')
                    return false;
            return true;
        }

        /** \brief The planner of \e p exists in \e registry, takes its parameters (names, ranges, integers)
            and reports the progress properties asked for; checked on a plain 2D space, so that a campaign
            (and --list) refuses a bad entry with its file, line and field before any run. */
        void checkPlannerSpec(const YamlReader &r, const YAML::Node &node, const std::string &field,
                              const PlannerSpec &p, const PlannerRegistry &registry)
        {
            if (!registry.has(p.planner))
            {
                std::string known;
                for (const auto &name : registry.names())
                    known += (known.empty() ? "" : " ") + name;
                r.fail(node.IsMap() ? node["planner"] : node, node.IsMap() ? field + ".planner" : field,
                       "unknown planner '" + p.planner + "'; registered planners: " + known);
            }
            static const ompl::base::SpaceInformationPtr si = []
            {
                auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
                space->setBounds(0.0, 1.0);
                auto info = std::make_shared<ompl::base::SpaceInformation>(space);
                info->setStateValidityChecker([](const ompl::base::State *) { return true; });
                info->setup();
                return info;
            }();
            ompl::base::PlannerPtr planner = registry.get(p.planner).allocate(si);
            try
            {
                applyPlannerParameters(*planner, p.params);
            }
            catch (const InputError &e)
            {
                r.fail(node["params"], field + ".params", e.what());
            }
            const auto &properties = planner->getPlannerProgressProperties();
            for (std::size_t k = 0; k < p.progress.size(); ++k)
                if (std::none_of(
                        properties.begin(), properties.end(),
                        [&](const auto &kv) // "best cost" names "best cost REAL" (type word optional)
                        { return kv.first == p.progress[k] || kv.first.rfind(p.progress[k] + " ", 0) == 0; }))
                {
                    std::string known;
                    for (const auto &kv : properties)
                        known += (known.empty() ? "'" : ", '") + kv.first + "'";
                    r.fail(node["progress"][k], field + ".progress[" + std::to_string(k) + "]",
                           "planner '" + p.planner + "' has no progress property '" + p.progress[k] +
                               "'; its properties: " + (known.empty() ? std::string("(none)") : known));
                }
        }

        void readPlanners(const YamlReader &r, const YAML::Node &n, Campaign &c,
                          const PlannerRegistry &registry)
        {
            if (!n.IsSequence() || n.size() == 0)
                r.fail(n, "planners", "expected a non-empty list of {planner, name, params}");
            std::set<std::string> names;
            for (std::size_t i = 0; i < n.size(); ++i)
            {
                const std::string field = "planners[" + std::to_string(i) + "]";
                PlannerSpec p;
                if (n[i].IsScalar())
                    p.planner = r.nonEmptyText(n[i], field);
                else
                {
                    r.allowKeys(n[i], field, {"planner", "name", "params", "progress", "runs"});
                    if (n[i]["runs"].IsDefined())
                        p.runs =
                            static_cast<unsigned int>(r.integer(n[i]["runs"], field + ".runs", 1, 1000000));
                    if (!n[i]["planner"].IsDefined())
                        r.fail(n[i], field + ".planner", "missing");
                    p.planner = r.nonEmptyText(n[i]["planner"], field + ".planner");
                    if (n[i]["name"].IsDefined())
                        p.displayName = r.nonEmptyText(n[i]["name"], field + ".name");
                    const YAML::Node progress = n[i]["progress"];
                    if (progress.IsDefined() && !progress.IsNull())
                    {
                        if (!progress.IsSequence() || progress.size() == 0)
                            r.fail(progress, field + ".progress",
                                   "expected a non-empty list of progress property names");
                        for (std::size_t k = 0; k < progress.size(); ++k)
                            p.progress.push_back(
                                r.nonEmptyText(progress[k], field + ".progress[" + std::to_string(k) + "]"));
                    }
                    const YAML::Node params = n[i]["params"];
                    if (params.IsDefined() && !params.IsNull())
                    {
                        if (!params.IsMap())
                            r.fail(params, field + ".params", "expected a mapping of parameter: value");
                        r.uniqueKeys(params, field + ".params");
                        for (const auto &kv : params)
                        {
                            const std::string key = r.key(kv.first, field + ".params");
                            p.params[key] = r.nonEmptyText(kv.second, field + ".params." + key);
                        }
                    }
                }
                checkPlannerSpec(r, n[i], field, p, registry);
                p.line = n[i].Mark().line + 1;
                p.capabilities = registry.get(p.planner).capabilities;
                for (const SpaceType s :
                     {SpaceType::R2, SpaceType::SE2, SpaceType::Dubins, SpaceType::ReedsShepp})
                {
                    const unsigned flag = spaceFlag(s);
                    const std::string why =
                        registry.whyNotApplicable(p.planner, flag, spaceName(flag) + " worlds");
                    if (!why.empty())
                        p.refusals[flag] = why;
                }
                // SE(3) and R^3: the OMPL.app problems and 3D YAML worlds of {cfg: FILE} entries.
                for (const auto &[flag, label] :
                     {std::pair<unsigned, const char *>{cap::SE3, "SE(3) problems"},
                      {cap::Rk, "R^3 problems"}})
                {
                    const std::string why = registry.whyNotApplicable(p.planner, flag, label);
                    if (!why.empty())
                        p.refusals[flag] = why;
                }
                if (p.displayName.empty())
                    p.displayName = p.planner;
                if (!plainName(p.displayName))
                    r.fail(n[i], field + ".name",
                           "'" + p.displayName + "' must not contain blanks, quotes, ';' or ','");
                if (!names.insert(p.displayName).second)
                    r.fail(n[i], field + ".name",
                           "duplicate planner name '" + p.displayName +
                               "'; give each configuration of a planner its own 'name'");
                c.planners.push_back(std::move(p));
            }
        }

        std::string joinNames(const std::vector<std::string> &names)
        {
            std::string out;
            for (const auto &n : names)
                out += (out.empty() ? "" : ", ") + n;
            return out;
        }

        void readControllers(const YamlReader &r, const YAML::Node &n, const std::string &base,
                             SimulationSpec &sim, const PlannerRegistry &registry)
        {
            if (!n.IsSequence() || n.size() == 0)
                r.fail(n, base,
                       "expected a non-empty list of controllers (names or {controller, name, params})");
            const std::vector<std::string> known = controllerNames(registry);
            std::set<std::string> names;
            for (std::size_t i = 0; i < n.size(); ++i)
            {
                const std::string field = base + "[" + std::to_string(i) + "]";
                ControllerSpec spec;
                spec.line = n[i].Mark().line + 1;
                if (n[i].IsScalar())
                    spec.controller = r.nonEmptyText(n[i], field);
                else
                {
                    r.allowKeys(n[i], field, {"controller", "name", "params"});
                    if (!n[i]["controller"].IsDefined())
                        r.fail(n[i], field + ".controller", "missing");
                    spec.controller = r.nonEmptyText(n[i]["controller"], field + ".controller");
                    if (n[i]["name"].IsDefined())
                        spec.displayName = r.nonEmptyText(n[i]["name"], field + ".name");
                    const YAML::Node params = n[i]["params"];
                    if (params.IsDefined() && !params.IsNull())
                    {
                        if (!params.IsMap())
                            r.fail(params, field + ".params", "expected a mapping of parameter: value");
                        r.uniqueKeys(params, field + ".params");
                        for (const auto &kv : params)
                        {
                            const std::string key = r.key(kv.first, field + ".params");
                            spec.params[key] = r.nonEmptyText(kv.second, field + ".params." + key);
                        }
                    }
                }
                if (std::find(known.begin(), known.end(), spec.controller) == known.end())
                    r.fail(n[i], field,
                           "unknown controller '" + spec.controller + "'; known: " + joinNames(known));
                if (spec.displayName.empty())
                    spec.displayName = spec.controller;
                if (!plainName(spec.displayName))
                    r.fail(n[i], field + ".name",
                           "'" + spec.displayName + "' must not contain blanks, quotes, ';' or ','");
                if (!names.insert(spec.displayName).second)
                    r.fail(n[i], field + ".name",
                           "duplicate controller name '" + spec.displayName +
                               "'; give each configuration of a controller its own 'name'");
                sim.controllers.push_back(std::move(spec));
            }
        }

        void readSimulations(const YamlReader &r, const YAML::Node &n, Campaign &c,
                             const PlannerRegistry &registry)
        {
            if (!n.IsSequence() || n.size() == 0)
                r.fail(n, "simulations", "expected a non-empty list of {scenario, controllers, ...}");
            for (std::size_t i = 0; i < n.size(); ++i)
            {
                const std::string field = "simulations[" + std::to_string(i) + "]";
                const YAML::Node s = n[i];
                if (!s.IsMap())
                    r.fail(s, field, "expected a mapping {scenario, controllers, runs, seed, ...}");
                r.allowKeys(s, field,
                            {"scenario", "controllers", "runs", "seed", "start_jitter", "heading_jitter",
                             "wall_limit"});
                SimulationSpec sim;
                sim.line = s.Mark().line + 1;
                sim.scenario =
                    r.nonEmptyText(r.require(s, "scenario", field + ".scenario"), field + ".scenario");
                if (s["runs"].IsDefined())
                    sim.runs = static_cast<unsigned int>(r.integer(s["runs"], field + ".runs", 1, 1000000));
                if (s["seed"].IsDefined())
                    sim.seed =
                        static_cast<std::uint32_t>(r.integer(s["seed"], field + ".seed", 1, 4294967295LL));
                if (s["start_jitter"].IsDefined())
                    sim.startJitter = r.number(s["start_jitter"], field + ".start_jitter", 0.0, 1e6);
                if (s["heading_jitter"].IsDefined())
                    sim.headingJitter = r.number(s["heading_jitter"], field + ".heading_jitter", 0.0, 3.15);
                if (s["wall_limit"].IsDefined())
                    sim.wallLimit = r.number(s["wall_limit"], field + ".wall_limit", 1e-3, 1e7);
                readControllers(r, r.require(s, "controllers", field + ".controllers"),
                                field + ".controllers", sim, registry);
                c.simulations.push_back(std::move(sim));
            }
        }

        void readWorlds(const YamlReader &r, const YAML::Node &n, Campaign &c)
        {
            if (!n.IsSequence() || n.size() == 0)
                r.fail(n, "worlds", "expected a non-empty list of worlds");
            for (std::size_t i = 0; i < n.size(); ++i)
            {
                const std::string field = "worlds[" + std::to_string(i) + "]";
                WorldSpec w;
                if (n[i].IsScalar())
                    w.world = r.nonEmptyText(n[i], field);
                else if (n[i].IsMap() && n[i]["map"].IsDefined())
                    detail::readMovingAIWorld(r, n[i], field, w);
                else if (n[i].IsMap() && n[i]["cfg"].IsDefined())
                    detail::readCfgWorld(r, n[i], field, w);
                else
                {
                    r.allowKeys(n[i], field, {"world", "queries", "generate", "name", "setup"});
                    if (n[i]["setup"].IsDefined())
                        w.setups = readSetups(r, n[i]["setup"], field + ".setup");
                    if (n[i]["generate"].IsDefined())
                    {
                        if (n[i]["world"].IsDefined())
                            r.fail(n[i]["world"], field + ".world",
                                   "a world entry has either world or generate");
                        w.generated = readGeneratedWorld(r, n[i], field);
                        c.worlds.push_back(std::move(w));
                        continue;
                    }
                    if (n[i]["name"].IsDefined())
                        r.fail(n[i]["name"], field + ".name", "only generated worlds take a name");
                    if (!n[i]["world"].IsDefined())
                        r.fail(n[i], field + ".world", "missing");
                    w.world = r.nonEmptyText(n[i]["world"], field + ".world");
                    const YAML::Node q = n[i]["queries"];
                    if (q.IsDefined() && !q.IsNull())
                    {
                        if (q.IsScalar())
                            w.queries.push_back(r.nonEmptyText(q, field + ".queries"));
                        else if (q.IsSequence())
                            for (std::size_t k = 0; k < q.size(); ++k)
                                w.queries.push_back(
                                    r.nonEmptyText(q[k], field + ".queries[" + std::to_string(k) + "]"));
                        else
                            r.fail(q, field + ".queries", "expected a query name or a list of names");
                    }
                }
                c.worlds.push_back(std::move(w));
            }
        }
    } // namespace

    Query experimentQuery(const World &world, const Experiment &e)
    {
        if (e.scenLine == 0)
            return world.query(e.query);
        Query q;
        q.name = e.query;
        q.start = {e.startX, e.startY};
        q.goal = {e.goalX, e.goalY};
        return q;
    }

    std::string simulationDatabaseFile(const Campaign &campaign)
    {
        if (!campaign.simulationDatabase.empty())
            return campaign.simulationDatabase;
        if (campaign.worlds.empty())
            return campaign.database;
        const fs::path db(campaign.database);
        fs::path sim = db.parent_path() / (db.stem().string() + "-sim" + db.extension().string());
        return db.has_parent_path() ? sim.string() : sim.filename().string();
    }

    Campaign parseCampaign(const std::string &text, const std::string &fileName,
                           const PlannerRegistry &registry)
    {
        const YAML::Node root = loadYamlMapping(text, fileName, "campaign file", "benchmarks/README.md");
        const YamlReader r(fileName);
        r.allowKeys(root, "",
                    {"campaign", "database", "simulation_database", "logs", "time_limit", "time_limit_kind",
                     "wall_limit", "memory_limit", "runs", "seed", "progress_interval", "planner_data",
                     "collision", "worlds", "planners", "simulations", "skip_inapplicable", "setup"});
        Campaign c;
        c.file = fileName;
        c.name = root["campaign"].IsDefined() ? r.nonEmptyText(root["campaign"], "campaign")
                                              : fs::path(fileName).stem().string();
        if (root["time_limit"].IsDefined())
            c.timeLimit = r.number(root["time_limit"], "time_limit", 1e-3, 1e6);
        if (root["time_limit_kind"].IsDefined())
        {
            const std::string kind = r.nonEmptyText(root["time_limit_kind"], "time_limit_kind");
            if (kind != "wall" && kind != "cpu")
                r.fail(root["time_limit_kind"], "time_limit_kind",
                       "expected wall (elapsed seconds, OMPL's) or cpu (CPU seconds of the run), got '" +
                           kind + "'");
            c.cpuTimeLimit = kind == "cpu";
        }
        if (root["wall_limit"].IsDefined())
        {
            c.wallLimit = r.number(root["wall_limit"], "wall_limit", 1e-3, 1e7);
            if (c.wallLimit <= c.timeLimit)
            {
                std::ostringstream why;
                why << "must exceed time_limit (" << c.timeLimit << " s): every planning run would be killed";
                r.fail(root["wall_limit"], "wall_limit", why.str());
            }
        }
        if (root["memory_limit"].IsDefined())
            c.memoryLimit = r.number(root["memory_limit"], "memory_limit", 1.0, 1e9);
        if (root["runs"].IsDefined())
            c.runs = static_cast<unsigned int>(r.integer(root["runs"], "runs", 1, 1000000));
        if (root["seed"].IsDefined())
            c.seed = static_cast<std::uint32_t>(r.integer(root["seed"], "seed", 1, 4294967295LL));
        if (root["progress_interval"].IsDefined())
            c.progressInterval = r.number(root["progress_interval"], "progress_interval", 1e-3, 1e6);
        if (root["planner_data"].IsDefined())
        {
            try
            {
                c.plannerData = root["planner_data"].as<bool>();
            }
            catch (const YAML::Exception &)
            {
                r.fail(root["planner_data"], "planner_data", "expected true or false");
            }
        }
        if (root["skip_inapplicable"].IsDefined())
        {
            try
            {
                c.skipInapplicable = root["skip_inapplicable"].as<bool>();
            }
            catch (const YAML::Exception &)
            {
                r.fail(root["skip_inapplicable"], "skip_inapplicable", "expected true or false");
            }
        }
        if (root["collision"].IsDefined())
        {
            c.collision = r.nonEmptyText(root["collision"], "collision");
            try
            {
                parseCollisionBackend(c.collision);
            }
            catch (const InputError &e)
            {
                r.fail(root["collision"], "collision", e.what());
            }
        }
        if (root["setup"].IsDefined())
            c.setups = readSetups(r, root["setup"], "setup");
        c.database =
            root["database"].IsDefined() ? r.nonEmptyText(root["database"], "database") : c.name + ".db";
        c.logDir = root["logs"].IsDefined() ? r.nonEmptyText(root["logs"], "logs") : c.database + ".logs";
        if (root["simulation_database"].IsDefined())
            c.simulationDatabase = r.nonEmptyText(root["simulation_database"], "simulation_database");
        // A campaign may consist of simulations only; planning experiments need both worlds and planners.
        const bool simulations = root["simulations"].IsDefined() && !root["simulations"].IsNull();
        const bool planning = root["worlds"].IsDefined() || root["planners"].IsDefined() || !simulations;
        if (planning)
        {
            if (!root["worlds"].IsDefined())
                r.fail(root, "worlds", "missing");
            readWorlds(r, root["worlds"], c);
            const bool app =
                std::any_of(c.setups.begin(), c.setups.end(), [](const ValiditySetup &s) { return s.app(); });
            for (std::size_t i = 0; app && i < c.worlds.size(); ++i)
                if (!c.worlds[i].scen.empty() || !c.worlds[i].cfg.empty())
                    r.fail(root["setup"], "setup",
                           "worlds[" + std::to_string(i) + "] is " +
                               (c.worlds[i].cfg.empty() ? "a MovingAI set" : "an OMPL.app problem") +
                               ", which runs the exact set-up only; give the app set-up to the other world "
                               "entries (their key setup) instead");
            if (!root["planners"].IsDefined())
                r.fail(root, "planners", "missing");
            readPlanners(r, root["planners"], c, registry);
        }
        if (simulations)
            readSimulations(r, root["simulations"], c, registry);
        return c;
    }

    Campaign loadCampaign(const std::string &path, const PlannerRegistry &registry)
    {
        return parseCampaign(readFile(path, "campaign file"), path, registry);
    }

    namespace
    {
        /** Everything that shapes every experiment's results, hashed into each experiment's fingerprint. */
        std::string commonFingerprintText(const Campaign &campaign)
        {
            std::ostringstream common;
            common.precision(17);
            common << "time " << campaign.timeLimit << "\nmemory " << campaign.memoryLimit << "\nruns "
                   << campaign.runs << "\nseed " << campaign.seed << "\ninterval "
                   << campaign.progressInterval << "\ncollision " << campaign.collision << "\nplanner data "
                   << campaign.plannerData << "\n";
            if (campaign.cpuTimeLimit) // absent for wall-clock limits: older logs keep their fingerprints
                common << "time limit kind cpu\n";
            if (campaign.wallLimit > 0.0) // absent by default, likewise
                common << "wall limit " << campaign.wallLimit << "\n";
            for (const auto &p : campaign.planners)
            {
                common << "planner " << p.displayName << " " << p.planner;
                for (const auto &kv : p.params)
                    common << " " << kv.first << "=" << kv.second;
                for (const auto &name : p.progress)
                    common << " progress:" << name;
                if (p.runs > 0)
                    common << " runs:" << p.runs;
                common << "\n";
            }
            return common.str();
        }

        using Locate = std::function<std::string(const std::string &)>;

        /** The world file of entry \e wi: generated now, or found with \e locate; loaded (its bytes in
            \e text). Errors name the campaign file and the entry. */
        World loadCampaignWorld(const Campaign &campaign, const WorldSpec &spec, std::size_t wi,
                                const Locate &locate, std::string &file, std::string &text)
        {
            try
            {
                file = spec.generated.present
                           ? materializeGeneratedWorld(spec.generated,
                                                       (fs::path(campaign.logDir) / "worlds").string())
                           : locate(spec.world);
            }
            catch (const InputError &e)
            {
                const std::string line =
                    spec.generated.present ? ":" + std::to_string(spec.generated.line) : "";
                throw InputError(campaign.file + line + ": worlds[" + std::to_string(wi) + "]: " + e.what());
            }
            try
            {
                return loadWorld(file, &text);
            }
            catch (const InputError &e)
            {
                throw InputError(campaign.file + ": worlds[" + std::to_string(wi) + "]: " + e.what());
            }
        }

        /** The queries of \e world that entry \e spec selects (all when it names none), in its order. */
        std::vector<const Query *> selectedQueries(const Campaign &campaign, const World &world,
                                                   const WorldSpec &spec, const std::string &file)
        {
            std::vector<const Query *> queries;
            if (spec.queries.empty())
                for (const auto &q : world.queries)
                    queries.push_back(&q);
            else
            {
                std::map<std::string, const Query *> byName;
                for (const auto &q : world.queries)
                    byName.emplace(q.name, &q);
                for (const auto &qname : spec.queries)
                {
                    const auto it = byName.find(qname);
                    queries.push_back(it != byName.end() ? it->second : &world.query(qname)); // throws
                }
            }
            if (queries.empty())
                throw InputError(campaign.file + ": world '" + world.name + "' (" + file +
                                 ") has no queries");
            return queries;
        }

        /** One experiment per selected query of the world of entry \e wi. */
        void appendWorldExperiments(const Campaign &campaign, const WorldSpec &spec, std::size_t wi,
                                    const Locate &locate, const std::string &common,
                                    std::set<std::string> &names, std::vector<Experiment> &out)
        {
            std::string file;
            std::string worldText; // the bytes parsed: hashed once for all the world's queries
            const World world = loadCampaignWorld(campaign, spec, wi, locate, file, worldText);
            // A planner that cannot run on the world's space: refused here, before anything runs, or skipped.
            const std::vector<std::size_t> skipped =
                detail::inapplicablePlanners(campaign, spaceFlag(world.space), wi, world.name);
            const CollisionModelPtr model =
                makeCollisionModel(world, parseCollisionBackend(campaign.collision));
            // An SE(2)-based world's robot model, built once for all its queries (validateQuery would build
            // one per query).
            const std::unique_ptr<const RigidBodyModel> rigid =
                world.isRigid() ? std::make_unique<const RigidBodyModel>(world) : nullptr;
            const std::vector<const Query *> queries = selectedQueries(campaign, world, spec, file);
            // Experiment names go into OMPL's logs, whose reader keeps only the last word of a name with
            // blanks ("lab one" and "hall one" would both become "one"): such names are refused.
            if (!plainName(world.name))
                throw InputError(campaign.file + ": worlds[" + std::to_string(wi) + "]: world name '" +
                                 world.name + "' (" + file +
                                 ") cannot name an experiment: no blanks, ';', ',' or quotes (rename it)");
            Fingerprint prefix;
            prefix.add(common);
            prefix.add("world ");
            prefix.add(worldText);
            const std::string inputHash = fingerprint(worldText);
            out.reserve(out.size() + queries.size());
            const std::vector<ValiditySetup> &setups = spec.setups.empty() ? campaign.setups : spec.setups;
            for (const Query *qp : queries)
                for (const ValiditySetup &setup : setups)
                {
                    const Query &q = *qp;
                    if (!plainName(q.name))
                        throw InputError(
                            campaign.file + ": worlds[" + std::to_string(wi) + "]: query name '" + q.name +
                            "' of world '" + world.name + "' (" + file +
                            ") cannot name an experiment: no blanks, ';', ',' or quotes (rename it)");
                    if (rigid)
                        validateRigidQuery(world, q, *rigid);
                    else
                        validateQuery(world, q, *model);
                    Experiment e;
                    e.index = out.size();
                    e.name = world.name + "-" + q.name + setupSuffix(setup);
                    e.setup = setup;
                    e.worldFile = file;
                    e.worldName = world.name;
                    e.query = q.name;
                    e.runs = campaign.runs;
                    e.skipped = skipped;
                    if (!names.insert(e.name).second)
                        throw InputError(campaign.file + ": experiment '" + e.name +
                                         "' appears twice (the same world and query listed twice)");
                    // The seed of the world and query alone: both set-ups of a query run the same seeds.
                    e.seed = deriveSeed(campaign.seed, world.name + "-" + q.name, 0);
                    // After the world's bytes (the same fingerprint as before): the query's name and points
                    // as an ostream of precision 17 writes them ("%.17g"; a world may have 10^5 queries).
                    char points[4 * 32];
                    std::snprintf(points, sizeof points, " %.17g %.17g %.17g %.17g\n", q.start.x, q.start.y,
                                  q.goal.x, q.goal.y);
                    Fingerprint all = prefix;
                    all.add("\nquery " + q.name + points);
                    if (setup.app()) // exact experiments keep the fingerprints they had before set-ups
                    {
                        char res[48];
                        std::snprintf(res, sizeof res, "setup app %.17g\n", setup.resolution);
                        all.add(res);
                    }
                    e.configHash = all.hex();
                    e.inputHash = inputHash;
                    out.push_back(std::move(e));
                }
        }

        /** The experiment of simulation entry \e si: its scenario found (relative to the campaign, else a
            shipped one) and loaded. */
        void appendSimulationExperiment(const Campaign &campaign, std::size_t si, const Locate &locate,
                                        const WorldResolver &resolve, std::set<std::string> &names,
                                        std::vector<Experiment> &out)
        {
            const SimulationSpec &spec = campaign.simulations[si];
            const std::string where = campaign.file + ":" + std::to_string(spec.line) + ": simulations[" +
                                      std::to_string(si) + "]: ";
            std::string file;
            Scenario scenario;
            try
            {
                try
                {
                    file = locate(spec.scenario);
                    if (!fs::is_regular_file(file))
                        throw InputError("no such file");
                }
                catch (const InputError &)
                {
                    // Shipped scenarios live in environments/scenarios/: "mapf_2robots" names one.
                    try
                    {
                        file = resolve("scenarios/" + spec.scenario);
                    }
                    catch (const InputError &)
                    {
                        throw InputError("scenario '" + spec.scenario +
                                         "': no such file, and no shipped scenario of that name "
                                         "(environments/scenarios/)");
                    }
                }
                scenario = loadScenario(file);
            }
            catch (const InputError &e)
            {
                throw InputError(where + e.what());
            }
            Experiment e;
            e.index = out.size();
            e.simulation = si;
            e.scenarioFile = file;
            e.scenarioName = scenario.name;
            e.name =
                safeFileStem(scenario.name.empty() ? fs::path(file).stem().string() : scenario.name) + "-sim";
            e.runs = spec.runs > 0 ? spec.runs : campaign.runs;
            if (!names.insert(e.name).second)
                throw InputError(where + "experiment '" + e.name +
                                 "' appears twice (list every controller of a scenario in one entry)");
            e.seed = deriveSeed(spec.seed > 0 ? spec.seed : campaign.seed, e.name, 0);
            std::ostringstream all;
            all.precision(17);
            all << "simulation v1\nruns " << e.runs << "\nseed " << e.seed << "\nstart jitter "
                << spec.startJitter << "\nheading jitter " << spec.headingJitter << "\nwall limit "
                << spec.wallLimit << "\n";
            for (const auto &ctl : spec.controllers)
            {
                all << "controller " << ctl.displayName << " " << ctl.controller;
                for (const auto &kv : ctl.params)
                    all << " " << kv.first << "=" << kv.second;
                all << "\n";
            }
            const std::string scenarioText = readFile(file, "scenario file");
            all << "scenario " << scenarioText << "\n";
            e.configHash = fingerprint(all.str());
            e.inputHash = fingerprint(scenarioText);
            out.push_back(std::move(e));
        }
    } // namespace

    std::vector<Experiment> enumerateExperiments(const Campaign &campaign, const WorldResolver &resolve)
    {
        const std::string common = commonFingerprintText(campaign);
        const fs::path base = fs::path(campaign.file).parent_path();
        const Locate locate = [&](const std::string &arg)
        {
            const fs::path relative = base / arg;
            if (!fs::path(arg).is_absolute() && fs::is_regular_file(relative))
                return relative.string();
            return resolve(arg);
        };
        std::vector<Experiment> out;
        std::set<std::string> names;
        for (std::size_t wi = 0; wi < campaign.worlds.size(); ++wi)
        {
            const WorldSpec &spec = campaign.worlds[wi];
            if (!spec.scen.empty())
                detail::appendMovingAIExperiments(campaign, spec, wi, locate, common, names, out);
            else if (!spec.cfg.empty())
                detail::appendCfgExperiment(campaign, spec, wi, locate, common, names, out);
            else
                appendWorldExperiments(campaign, spec, wi, locate, common, names, out);
        }
        for (std::size_t si = 0; si < campaign.simulations.size(); ++si)
            appendSimulationExperiment(campaign, si, locate, resolve, names, out);
        return out;
    }

    std::string inputFingerprint(const Experiment &e)
    {
        const std::string &file = e.simulation == Experiment::kNoSimulation ? e.worldFile : e.scenarioFile;
        try
        {
            if (e.cfg)
                return detail::readCfgInputs(file).hash;
            return fingerprint(readInputFile(file, kMaxGridFileBytes, "input file"));
        }
        catch (const InputError &)
        {
            return "(unreadable)";
        }
    }

    std::uint32_t simulationRunSeed(const Experiment &experiment, const std::string &displayName,
                                    std::size_t run)
    {
        return deriveSeed(experiment.seed, "controller " + displayName, run);
    }

    std::uint32_t simulationStartSeed(const Experiment &experiment, std::size_t run)
    {
        return deriveSeed(experiment.seed, "start", run);
    }

    std::vector<Experiment> shardExperiments(const std::vector<Experiment> &all, unsigned int part,
                                             unsigned int parts)
    {
        if (parts == 0 || part == 0 || part > parts)
            throw InputError("shard " + std::to_string(part) + "/" + std::to_string(parts) +
                             ": expected i/N with 1 <= i <= N");
        std::vector<Experiment> out;
        out.reserve(all.size() / parts + 1);
        for (const auto &e : all)
            if (e.index % parts == part - 1)
                out.push_back(e);
        return out;
    }
} // namespace mhplan::bench

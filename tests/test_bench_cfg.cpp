// SPDX-License-Identifier: BSD-3-Clause
/* Campaign world entries {cfg: FILE} (docs/omplapp.md, "Campaigns"): an OMPL.app problem beside a 2D world
   in one campaign, its experiment's fingerprint covering the .cfg and both meshes, the refusals (missing
   file, unknown key, a planner that cannot plan in SE(2)/SE(3), a .cfg error naming its own file and line),
   and a round trip through `mhplan bench` into the database with every path checked densely. */
#include "benchmarks/Campaign.h"
#include "BenchSupport.h"
#include "CliSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace mhplan;
using namespace mhplan::bench;
namespace fs = std::filesystem;

namespace
{
    const fs::path kOmplApp = fs::path(MHPLAN_ENVIRONMENTS_DIR) / "omplapp";

    /** A fresh folder with the bug trap's .cfg and meshes copied in, and a 2D world. */
    fs::path problemFolder(const std::string &tag)
    {
        const fs::path dir =
            fs::temp_directory_path() / ("mhplan_test_bench_cfg_" + std::to_string(::getpid())) / tag;
        fs::remove_all(dir);
        fs::create_directories(dir / "problems");
        for (const char *f : {"bugtrap.cfg", "bugtrap_env.obj", "bar_robot.dae"})
            fs::copy_file(kOmplApp / f, dir / "problems" / f);
        fs::copy_file(fs::path(MHPLAN_ENVIRONMENTS_DIR) / "bfo_case1.yaml", dir / "bfo_case1.yaml");
        return dir;
    }

    std::string campaignText(const std::string &planners, const std::string &worlds)
    {
        return "campaign: meshes\nruns: 1\ntime_limit: 0.3\nworlds:\n" + worlds + "planners:\n" + planners;
    }

    const std::string kWorlds = "  - bfo_case1.yaml\n  - {cfg: problems/bugtrap.cfg}\n";

    std::vector<Experiment> enumerate(const fs::path &dir, const std::string &text)
    {
        const Campaign c = parseCampaign(text, (dir / "c.yaml").string());
        return enumerateExperiments(
            c, [](const std::string &s) -> std::string { throw InputError("'" + s + "': no such world"); });
    }

    void expectRefused(const fs::path &dir, const std::string &text, const std::vector<std::string> &parts)
    {
        try
        {
            enumerate(dir, text);
            ADD_FAILURE() << "accepted:\n" << text;
        }
        catch (const InputError &e)
        {
            for (const auto &p : parts)
                EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what() << "\nmissing: " << p;
        }
    }
} // namespace

TEST(CampaignCfg, MixesAProblemFileWithAWorld)
{
    const fs::path dir = problemFolder("mix");
    const auto all = enumerate(dir, campaignText("  - RRTConnect\n  - SMA\n", kWorlds));
    ASSERT_EQ(all.size(), 2u);
    EXPECT_FALSE(all[0].cfg);
    EXPECT_TRUE(all[1].cfg);
    EXPECT_EQ(all[1].name, "bugtrap");
    EXPECT_EQ(fs::path(all[1].worldFile).filename(), "bugtrap.cfg");
    EXPECT_TRUE(all[1].skipped.empty());
    EXPECT_EQ(inputFingerprint(all[1]), all[1].inputHash);
    EXPECT_NE(all[0].configHash, all[1].configHash);
}

TEST(CampaignCfg, FingerprintCoversTheFileAndBothMeshes)
{
    const fs::path dir = problemFolder("fingerprint");
    const std::string text = campaignText("  - RRTConnect\n", kWorlds);
    const Experiment before = enumerate(dir, text)[1];
    for (const char *f : {"bugtrap_env.obj", "bar_robot.dae", "bugtrap.cfg"})
    {
        const fs::path file = dir / "problems" / f;
        const std::uintmax_t size = fs::file_size(file);
        {
            std::ofstream(file, std::ios::app)
                << (std::string(f).find(".dae") != std::string::npos ? "<!-- edited -->\n" : "# edited\n");
        }
        EXPECT_NE(inputFingerprint(before), before.inputHash) << f; // the merge sees the change
        const Experiment after = enumerate(dir, text)[1];
        EXPECT_NE(after.configHash, before.configHash) << f;
        EXPECT_NE(after.inputHash, before.inputHash) << f;
        fs::resize_file(file, size); // back as it was: the same fingerprints again
        const Experiment again = enumerate(dir, text)[1];
        EXPECT_EQ(again.configHash, before.configHash) << f;
    }
}

TEST(CampaignCfg, RefusesWithFileLineAndField)
{
    const fs::path dir = problemFolder("refusals");
    expectRefused(dir, campaignText("  - RRTConnect\n", "  - {cfg: problems/nothere.cfg}\n"),
                  {"c.yaml:5: worlds[0].cfg:", "nothere.cfg"});
    expectRefused(dir, campaignText("  - RRTConnect\n", "  - {cfg: problems/bugtrap.cfg, queries: a}\n"),
                  {"c.yaml:5", "worlds[0]", "queries"});
    // APF plans on R^2 only.
    expectRefused(dir, campaignText("  - RRTConnect\n  - APF\n", kWorlds),
                  {"planners[1] (APF) on worlds[1] 'bugtrap'", "skip_inapplicable"});
    const Campaign skip =
        parseCampaign(campaignText("  - RRTConnect\n  - APF\n", kWorlds) + "skip_inapplicable: true\n",
                      (dir / "c.yaml").string());
    const auto all = enumerateExperiments(skip, [](const std::string &s) { return s; });
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[1].skipped, std::vector<std::size_t>{1});
    // An error of the .cfg names the campaign's entry and the .cfg's own line and key.
    {
        std::ofstream(dir / "problems" / "bugtrap.cfg", std::ios::app)
            << "\n[problem]\nobjective = mechanical_work\n";
    }
    expectRefused(dir, campaignText("  - RRTConnect\n", kWorlds),
                  {"c.yaml:6: worlds[1].cfg: ", "bugtrap.cfg:", "objective"});
}

TEST(CampaignCfg, BenchRunsTheProblemIntoTheDatabase)
{
    const fs::path dir = problemFolder("bench");
    std::ofstream(dir / "c.yaml") << campaignText("  - RRTConnect\n", kWorlds)
                                  << "database: " << (dir / "c.db").string() << "\n";
    const auto r = test::runCli("bench " + (dir / "c.yaml").string() + " --no-progress --seed 3");
    ASSERT_EQ(r.code, 0) << r.out;
    test::Sql sql((dir / "c.db").string());
    const auto rows = sql.rows("SELECT e.name, e.world_type, e.space, r.solved, r.collision_free, "
                               "r.path_length > 0 FROM runs r JOIN experiments e ON r.experimentid = e.id "
                               "ORDER BY e.name");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1], (std::vector<std::string>{"bugtrap", "omplapp", "se2", "1", "1", "1"}));
    EXPECT_EQ(rows[0][1], "circles");
    // The paths sidecar holds the SE(2) poses (x y yaw;...) of the run.
    bool poses = false;
    for (const auto &f : fs::recursive_directory_iterator(dir))
        if (f.path().filename().string().rfind("bugtrap", 0) == 0 && f.path().extension() == ".paths")
        {
            std::ifstream in(f.path());
            std::string line;
            while (std::getline(in, line))
                poses = poses || line.rfind("geometric_RRTConnect\t0\t0 0 0;", 0) == 0;
        }
    EXPECT_TRUE(poses);
}

TEST(CampaignCfg, ShippedOmplAppCampaignEnumerates)
{
    // benchmarks/omplapp.yaml (benchmarks/README.md, "OMPL.app problems"): five problems, every planner
    // runs on each of their spaces (SE(2), Dubins, SE(3)).
    const Campaign c = loadCampaign(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/../benchmarks/omplapp.yaml");
    const auto all = enumerateExperiments(c, [](const std::string &s) { return s; });
    ASSERT_EQ(all.size(), 5u);
    for (const auto &e : all)
    {
        EXPECT_TRUE(e.cfg) << e.name;
        EXPECT_TRUE(e.skipped.empty()) << e.name;
    }
    EXPECT_EQ(all[2].name, "bugtrap_dubins");
    // benchmarks/worlds3d.yaml: the two 3D worlds (R^3 and SE(3)), every planner runs on both.
    const Campaign w = loadCampaign(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/../benchmarks/worlds3d.yaml");
    const auto worlds = enumerateExperiments(w, [](const std::string &s) { return s; });
    ASSERT_EQ(worlds.size(), 2u);
    for (const auto &e : worlds)
        EXPECT_TRUE(e.cfg && e.skipped.empty()) << e.name;
}

TEST(CampaignCfg, A3dYamlWorldIsAnEntryToo)
{
    // docs/worlds3d.md: {cfg: WORLD.yaml} names a 3D YAML world; its fingerprint covers the world file and
    // the meshes it names (here the SE(3) example's robot), its space decides which planners apply.
    const fs::path dir = problemFolder("world3d");
    fs::create_directories(dir / "3d");
    fs::create_directories(dir / "omplapp");
    for (const char *f : {"narrow_passage.yaml", "narrow_passage_se3.yaml"})
        fs::copy_file(fs::path(MHPLAN_ENVIRONMENTS_DIR) / "3d" / f, dir / "3d" / f);
    fs::copy_file(kOmplApp / "rod_robot.ply", dir / "omplapp" / "rod_robot.ply");
    const std::string worlds = "  - {cfg: 3d/narrow_passage.yaml}\n  - {cfg: 3d/narrow_passage_se3.yaml}\n";
    const std::string text = campaignText("  - RRTConnect\n", worlds);
    const auto all = enumerate(dir, text);
    ASSERT_EQ(all.size(), 2u);
    EXPECT_TRUE(all[0].cfg);
    EXPECT_EQ(all[0].name, "narrow_passage_3d");
    EXPECT_EQ(all[1].name, "narrow_passage_se3");
    {
        std::ofstream(dir / "omplapp" / "rod_robot.ply", std::ios::app) << "\n";
    }
    EXPECT_NE(inputFingerprint(all[1]), all[1].inputHash);
    EXPECT_EQ(inputFingerprint(all[0]), all[0].inputHash); // names no mesh
    EXPECT_NE(enumerate(dir, text)[1].configHash, all[1].configHash);
    // APF plans on R^2 only: refused on the R^3 world, naming it.
    expectRefused(dir, campaignText("  - RRTConnect\n  - APF\n", worlds),
                  {"planners[1] (APF) on worlds[0] 'narrow_passage_3d'", "R^3"});
    // A world error names the campaign's entry and the world's own line and field.
    {
        std::ofstream(dir / "3d" / "narrow_passage.yaml", std::ios::app) << "colour: red\n";
    }
    expectRefused(dir, text,
                  {"c.yaml:5: worlds[0].cfg: ", "narrow_passage.yaml:", "field '(top level).colour'"});
    fs::copy_file(fs::path(MHPLAN_ENVIRONMENTS_DIR) / "3d" / "narrow_passage.yaml",
                  dir / "3d" / "narrow_passage.yaml", fs::copy_options::overwrite_existing);
    // A run into the database: every path checked densely (RRTConnect stops at its first path; the SE(3)
    // example takes up to about a second).
    std::string slow = text;
    slow.replace(slow.find("time_limit: 0.3"), 15, "time_limit: 5");
    std::ofstream(dir / "c.yaml") << slow << "database: " << (dir / "c.db").string() << "\n";
    const auto r = test::runCli("bench " + (dir / "c.yaml").string() + " --no-progress --seed 3");
    ASSERT_EQ(r.code, 0) << r.out;
    test::Sql sql((dir / "c.db").string());
    const auto rows = sql.rows("SELECT e.name, e.world_type, e.space, r.solved, r.collision_free "
                               "FROM runs r JOIN experiments e ON r.experimentid = e.id ORDER BY e.name");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{"narrow_passage_3d", "world3d", "r3", "1", "1"}));
    EXPECT_EQ(rows[1], (std::vector<std::string>{"narrow_passage_se3", "world3d", "se3", "1", "1"}));
}

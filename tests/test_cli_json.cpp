// SPDX-License-Identifier: BSD-3-Clause
/* The mhplan program's help and JSON output: every subcommand's --help lists exactly the options its parser
   accepts, with examples; every --json document parses (with Python's json module, an independent parser)
   and its values equal the text output, the exact optimum or a recomputation; output paths are refused
   before a run. */
#include "CliSupport.h"

#include "src/metrics/MetricList.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using mhplan::test::contains;
using mhplan::test::pyJson;
using mhplan::test::runCli;
using mhplan::test::runCliStdout;

namespace
{
    std::vector<std::string> subcommands()
    {
        const auto r = runCli("--help");
        std::vector<std::string> out;
        std::istringstream in(r.out);
        std::string line;
        bool inList = false;
        while (std::getline(in, line))
        {
            if (line == "subcommands:")
                inList = true;
            else if (inList && line.empty())
                break;
            else if (inList)
            {
                std::istringstream words(line);
                std::string name;
                words >> name;
                if (name != "version")
                    out.push_back(name);
            }
        }
        return out;
    }

    /** The "--name" words of \e text matched by \e pattern's first group. */
    std::set<std::string> options(const std::string &text, const std::regex &pattern)
    {
        std::set<std::string> out;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator();
             ++it)
            out.insert((*it)[1]);
        return out;
    }

    /** The value after "key:" on a line of the text output. */
    std::string field(const std::string &text, const std::string &key)
    {
        std::istringstream in(text);
        std::string line;
        while (std::getline(in, line))
            if (line.compare(0, key.size() + 1, key + ":") == 0)
            {
                std::istringstream rest(line.substr(key.size() + 1));
                std::string v;
                rest >> v;
                return v;
            }
        return "";
    }
} // namespace

TEST(CliHelp, EverySubcommandDocumentsExactlyTheOptionsItAccepts)
{
    const std::vector<std::string> commands = subcommands();
    ASSERT_GE(commands.size(), 12u);
    const auto top = runCli("--help");
    EXPECT_EQ(top.code, 0);
    for (const char *env : {"MHPLAN_ENVIRONMENTS", "MHPLAN_ANALYSIS", "MHPLAN_PYTHON", "MHPLAN_VERBOSE"})
        EXPECT_TRUE(contains(top.out, env)) << env;
    const std::regex helpOption(R"(\n  (--[a-z][a-z-]*))");
    const std::regex accepted(R"((--[a-z][a-z-]*))");
    for (const std::string &c : commands)
    {
        const auto help = runCli(c + " --help");
        EXPECT_EQ(help.code, 0) << c;
        EXPECT_TRUE(contains(help.out, "usage: mhplan " + c)) << help.out;
        EXPECT_TRUE(contains(help.out, "examples:\n  mhplan " + c)) << c;
        EXPECT_TRUE(contains(help.out, "exit codes:")) << c;
        EXPECT_EQ(runCli("help " + c).out, help.out) << c;
        EXPECT_EQ(runCli(c + " -h").out, help.out) << c;
        if (c == "report")
            continue; // its options are report.py's (argparse); its help is checked above
        // The parser's list of accepted options, from the message refusing an unknown one.
        const auto refused = runCli(c + " --no-such-option-xyz");
        ASSERT_EQ(refused.code, 1) << c << ": " << refused.out;
        const auto at = refused.out.find("accepted: ");
        ASSERT_NE(at, std::string::npos) << refused.out;
        std::set<std::string> parsed = options(refused.out.substr(at), accepted);
        parsed.erase("--no-such-option-xyz");
        std::set<std::string> documented = options(help.out.substr(help.out.find("options:")), helpOption);
        documented.erase("--help");
        EXPECT_EQ(documented, parsed) << c;
    }
}

TEST(CliJson, PlanEqualsTheTextOutputAndTheOptimum)
{
    // Iteration-bounded, so both runs are the same run.
    const std::string args =
        "plan bfo_case1 --planner SMA --seed 11 --time 30 --set max_iterations=25 --set population_size=20";
    const auto text = runCli(args);
    const auto json = runCliStdout(args + " --json");
    ASSERT_EQ(text.code, 0) << text.out;
    ASSERT_EQ(json.code, 0) << json.out;
    EXPECT_EQ(
        pyJson(json.out, "d['command'], d['planner'], d['seed'], d['exact'], d['valid'], d['exit_code']"),
        "plan SMA 11 True True 0");
    EXPECT_EQ(pyJson(json.out, "'%.9g' % d['length']"), field(text.out, "length"));
    EXPECT_EQ(pyJson(json.out, "'%.9g' % d['optimum']['length']"), field(text.out, "optimum"));
    // The gap from length and optimum; the length from the path's points; the path from start to goal.
    EXPECT_EQ(pyJson(json.out, "abs(d['gap_percent'] - 100 * (d['length'] - d['optimum']['length']) / "
                               "d['optimum']['length']) < 1e-9"),
              "True");
    EXPECT_EQ(pyJson(json.out, "abs(sum(math.dist(a, b) for a, b in zip(d['path'], d['path'][1:])) - "
                               "d['length']) < 1e-9"),
              "True");
    EXPECT_EQ(pyJson(json.out, "d['path'][0] == d['query']['start'] and d['path'][-1] == d['query']['goal']"),
              "True");
    EXPECT_EQ(pyJson(json.out, "d['parameters']['population_size'], d['parameters']['max_iterations']"),
              "20 25");
    // --quiet: no waypoint dump.
    const auto quiet = runCli(args + " --quiet");
    EXPECT_TRUE(contains(quiet.out, "path:      "));
    EXPECT_FALSE(contains(quiet.out, "\n  0 0\n"));
    EXPECT_TRUE(contains(text.out, "\n  0 0\n"));
}

TEST(CliJson, OptimumPiecesAddUpToTheLength)
{
    const auto text = runCli("optimum lrsma_scenario1");
    const auto json = runCliStdout("optimum lrsma_scenario1 --json");
    ASSERT_EQ(json.code, 0);
    EXPECT_EQ(pyJson(json.out, "'%.12g' % d['length']"), field(text.out, "length"));
    EXPECT_EQ(pyJson(json.out,
                     "d['found'], d['method'], abs(sum(p['length'] for p in d['pieces']) - d['length']) "
                     "< 1e-9"),
              "True tangent-graph True");
    const auto grid = runCliStdout("optimum gms_grid10 --octile --json");
    EXPECT_EQ(pyJson(grid.out, "d['method'], abs(d['length_cells'] * d['cell_size'] - d['length']) < 1e-9"),
              "grid-octile True");
    const auto quiet = runCli("optimum lrsma_scenario1 --quiet");
    EXPECT_FALSE(contains(quiet.out, "  segment"));
    EXPECT_TRUE(contains(text.out, "  segment"));
}

TEST(CliJson, WorldsExportTheirGeometry)
{
    const auto json = runCliStdout("worlds --json");
    ASSERT_EQ(json.code, 0);
    const auto text = runCli("worlds");
    // Every shipped world, in the text listing's order, with its obstacles and its queries.
    const std::string names = pyJson(json.out, "' '.join(w['name'] for w in d['worlds'])");
    std::istringstream in(text.out);
    std::string line, expected;
    std::getline(in, line);                         // header
    while (std::getline(in, line) && !line.empty()) // a blank line ends the table (footnotes follow)
        expected += (expected.empty() ? "" : " ") + line.substr(0, line.find(' '));
    EXPECT_EQ(names, expected);
    EXPECT_EQ(pyJson(json.out,
                     "all(w['obstacles'] == (w['grid']['blocked'] if w['grid'] else len(w['circles']) + "
                     "len(w['polygons'])) for w in d['worlds'])"),
              "True");
    EXPECT_EQ(pyJson(json.out,
                     "all(len(w['grid']['rows']) == w['grid']['height'] and all(len(r) == "
                     "w['grid']['width'] for r in w['grid']['rows']) and sum(r.count('@') for r in "
                     "w['grid']['rows']) == w['grid']['blocked'] for w in d['worlds'] if w['grid'])"),
              "True");
    // A MovingAI map's rows are the file's rows ('@' blocked).
    const auto map = runCliStdout(std::string("worlds ") + MHPLAN_TEST_DATA_DIR "/grid_small.map --json");
    std::ifstream f(std::string(MHPLAN_TEST_DATA_DIR) + "/grid_small.map");
    std::string row, rows;
    while (std::getline(f, row) && row != "map")
        ;
    while (std::getline(f, row))
    {
        for (char &c : row)
            c = (c == '.' || c == 'G' || c == 'S') ? '.' : (c == '\r' ? c : '@');
        if (!row.empty() && row.back() == '\r')
            row.pop_back();
        rows += (rows.empty() ? "" : ",") + row;
    }
    EXPECT_EQ(pyJson(map.out, "','.join(d['worlds'][0]['grid']['rows'])"), rows);
}

TEST(CliJson, PlannersDescribeTheirParametersWithoutOmplNoise)
{
    const auto text = runCli("planners"); // stdout and stderr together
    EXPECT_EQ(text.code, 0);
    EXPECT_FALSE(contains(text.out, "Warning:")) << text.out.substr(0, 400);
    EXPECT_FALSE(contains(text.out, "Error:"));
    EXPECT_TRUE(contains(text.out, "iterations versus max_iterations"));
    const auto json = runCliStdout("planners --json");
    EXPECT_EQ(pyJson(json.out, "len(d['planners']) > 20, 'SMA' in [p['name'] for p in d['planners']]"),
              "True True");
    // Every parameter of mhplan's own planners says what it does.
    EXPECT_EQ(pyJson(json.out,
                     "[p['name'] + '.' + q['name'] for p in d['planners'] if p['origin'] == 'mhplan' for q "
                     "in p['parameters'] if not q['description']]"),
              "[]");
    EXPECT_EQ(runCli("planners NoSuchPlanner").code, 1);
}

TEST(CliJson, CompareAndScenEqualTheirTextAndTheFilesOptima)
{
    const auto plan = runCli("plan gms_grid10 --planner AStar --quiet");
    const auto cmp = runCliStdout("compare gms_grid10 --planners AStar,ThetaStar --runs 2 --seed 3 --json");
    ASSERT_EQ(cmp.code, 0);
    EXPECT_EQ(pyJson(cmp.out, "[(r['planner'], r['exact'], r['runs']) for r in d['results']]"),
              "[('AStar', 2, 2), ('ThetaStar', 2, 2)]");
    EXPECT_EQ(pyJson(cmp.out, "'%.9g' % d['results'][0]['best_length']"), field(plan.out, "length"));
    const std::string data = std::string(MHPLAN_TEST_DATA_DIR) + "/";
    const auto scen = runCliStdout("scen " + data + "astar_random.map " + data + "astar_random.scen --json");
    ASSERT_EQ(scen.code, 0);
    EXPECT_EQ(pyJson(scen.out, "d['problems'], d['matched'], len(d['results'])"), "80 80 80");
    EXPECT_EQ(
        pyJson(scen.out, "all(r['match'] and abs(r['length'] - r['optimal']) < 1e-4 for r in d['results'])"),
        "True");
}

// plan and compare show every registered path metric (src/metrics/MetricList.h) by its column name, in
// registration order, prepared as a campaign prepares the path; the length they print is the list's.
TEST(CliJson, PlanAndCompareShowEveryRegisteredMetric)
{
    std::string columns;
    for (const mhplan::PathMetric &m : mhplan::pathMetrics())
        columns += (columns.empty() ? "" : " ") + mhplan::metricColumn(m.property);
    const auto plan = runCliStdout("plan gms_grid10 --planner AStar --json");
    ASSERT_EQ(plan.code, 0);
    EXPECT_EQ(pyJson(plan.out, "' '.join(d['metrics'])"), columns);
    EXPECT_EQ(pyJson(plan.out, "d['metrics']['path_length'] == d['length'], d['metrics']['collision_free']"),
              "True True");
    EXPECT_TRUE(contains(runCli("plan gms_grid10 --planner AStar --quiet").out, "metrics:   path_length "));
    // A car's cusps: the list's, as the cusps field (a path is not certain in the time given).
    const auto car = runCliStdout("plan reeds_shepp_parking --planner RRTstar --time 1 --seed 3 --json");
    EXPECT_EQ(pyJson(car.out, "d['metrics'] is None or (' '.join(d['metrics']) == '" + columns +
                                  "' and d['metrics']['cusps'] == d['cusps'])"),
              "True");
    const auto cmp = runCliStdout("compare gms_grid10 --planners AStar --runs 2 --seed 3 --json");
    ASSERT_EQ(cmp.code, 0);
    const std::string r = "d['results'][0]";
    EXPECT_EQ(pyJson(cmp.out, "' '.join(" + r + "['median_metrics'])"), columns);
    EXPECT_EQ(pyJson(cmp.out, r + "['median_metrics']['path_length'] == " + r + "['median_length']"), "True");
}

TEST(CliOutputs, UnwritableOutputsAreRefusedBeforeTheRun)
{
    const auto svg = runCli("plan bfo_case1 --planner AStar --svg /nonexistent_dir/x.svg");
    EXPECT_EQ(svg.code, 1);
    EXPECT_TRUE(
        contains(svg.out, "--svg '/nonexistent_dir/x.svg': the directory '/nonexistent_dir' does not exist"))
        << svg.out;
    EXPECT_FALSE(contains(svg.out, "status:")); // nothing ran
    const auto dir = runCli("optimum bfo_case1 --svg " + testing::TempDir());
    EXPECT_EQ(dir.code, 1);
    EXPECT_TRUE(contains(dir.out, "is a directory")) << dir.out;
    const auto gif = runCli("sim mapf_2robots --controller aapf --gif /nonexistent_dir/run.gif");
    EXPECT_EQ(gif.code, 1);
    EXPECT_TRUE(contains(gif.out, "--gif '/nonexistent_dir/run.gif'")) << gif.out;
    // bench: a log directory below a regular file.
    const std::string file = testing::TempDir() + "/mhplan_cli_json_file";
    std::ofstream(file) << "x";
    const auto bench = runCli(std::string("bench ") + MHPLAN_TEST_DATA_DIR +
                              "/bench_tiny.yaml --no-progress --logs " + file + "/logs");
    EXPECT_EQ(bench.code, 1);
    EXPECT_TRUE(contains(bench.out, "--logs")) << bench.out;
    EXPECT_FALSE(contains(bench.out, "experiments:"));
}

TEST(CliListings, ScenariosListsEveryShippedScenario)
{
    const auto r = runCli("scenarios");
    EXPECT_EQ(r.code, 0);
    for (const char *s : {"mapf_2robots", "mapf_15robots", "bfo_case3_lines"})
        EXPECT_TRUE(contains(r.out, std::string(s) + " (")) << s;
    EXPECT_TRUE(contains(r.out, "time_limit"));
    EXPECT_EQ(runCli("scenarios no_such_scenario").code, 1);
}

TEST(CliListings, PlanControllersListAndCheckThePlannersParameters)
{
    const auto r = runCli("controllers plan:SMA");
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(contains(r.out, "planner.population_size      default 30")) << r.out;
    EXPECT_TRUE(contains(r.out, "planner.iterations"));
    EXPECT_FALSE(contains(r.out, "Warning:"));
    // A planner parameter out of its declared range is refused by the controller, naming it.
    const auto bad = runCli("sim mapf_2robots --controller plan:SMA --set planner.population_size=1");
    EXPECT_EQ(bad.code, 1);
    EXPECT_TRUE(contains(bad.out, "planner.population_size")) << bad.out;
}

TEST(CliJson, DocsNameEveryFieldOfPlanJson)
{
    // docs/cli.md: from "Shared objects" (world summary, query) to the end of the plan section.
    std::ifstream in(std::string(MHPLAN_SOURCE_DIR) + "/docs/cli.md");
    std::stringstream all;
    all << in.rdbuf();
    const std::string text = all.str();
    const auto from = text.find("Shared objects:");
    const auto to = text.find("### `mhplan optimum WORLD --json`");
    ASSERT_NE(from, std::string::npos);
    ASSERT_NE(to, std::string::npos);
    const std::string docs = text.substr(from, to - from);
    // An R^2 world and an SE(2) world with a polygon robot (its extra fields).
    for (const std::string world : {"bfo_case1 --planner RRTstar", "se2_narrow_passage --planner RRTstar"})
    {
        const auto json = runCliStdout("plan " + world + " --time 0.3 --seed 3 --json");
        ASSERT_FALSE(json.out.empty()) << world;
        const std::string keys =
            pyJson(json.out, "' '.join(sorted(set(d) | set(d['world']) | set(d['query'])))", "fields");
        ASSERT_FALSE(contains(keys, "PARSE ERROR")) << keys;
        std::istringstream words(keys);
        std::string key;
        int count = 0;
        while (words >> key)
        {
            ++count;
            // A table's `key`, or a key inside a documented object: "{name, start: [x, y], ...}".
            EXPECT_TRUE(contains(docs, "`" + key + "`") || contains(docs, key + ",") ||
                        contains(docs, key + "}") || contains(docs, key + ": ["))
                << "docs/cli.md does not document plan --json field '" << key << "' (" << world << ")";
        }
        EXPECT_GE(count, 20) << keys;
    }
}

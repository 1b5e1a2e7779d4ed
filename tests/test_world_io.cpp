// SPDX-License-Identifier: BSD-3-Clause
/* World files: every malformed input is refused with the file, the line and the field; shipped worlds load.
 */
#include "src/collision/Collision.h"
#include "src/io/Generators.h"
#include "src/io/GridIO.h"
#include "src/io/QueryList.h"
#include "src/io/WorldIO.h"
#include "src/io/YamlReader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

using namespace mhplan;

namespace
{
    /** The error message of parsing \e text, or "" when it parses. */
    std::string parseError(const std::string &text)
    {
        try
        {
            parseWorldYaml(text, "test.yaml");
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "";
    }

    const char *kHeader = "name: t\nbounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}\n";
} // namespace

TEST(WorldIO, ParsesAllObstacleKinds)
{
    const World w = parseWorldYaml(std::string(kHeader) + R"(robot: {radius: 0.25}
obstacles:
  - circle: {center: [5, 5], radius: 1}
  - rectangle: {min: [1, 6], max: [2, 8]}
  - rectangle: {center: [8, 2], size: [1, 2], angle: 30}
  - polygon: {points: [[6, 7], [9, 7], [9, 9], [8, 9], [8, 8], [6, 8]]}
queries:
  - {name: a, start: [0.5, 0.5], goal: [9.5, 9.5]}
  - {start: [0.5, 9.5], goal: [9.5, 0.5]}
)",
                                   "test.yaml");
    EXPECT_EQ(w.circles.size(), 1u);
    ASSERT_EQ(w.polygons.size(), 3u);
    EXPECT_TRUE(w.polygons[0].convex);
    EXPECT_TRUE(w.polygons[1].convex);
    EXPECT_FALSE(w.polygons[2].convex);
    EXPECT_EQ(w.polygons[1].kind, "rectangle");
    EXPECT_DOUBLE_EQ(w.robotRadius, 0.25);
    ASSERT_EQ(w.queries.size(), 2u);
    EXPECT_EQ(w.queries[0].name, "a");
    EXPECT_EQ(w.queries[1].name, "q1");
    EXPECT_EQ(w.type(), "mixed");
    // The rotated rectangle keeps its area (1 x 2) and centre.
    EXPECT_NEAR(std::abs(signedArea2(w.polygons[1].vertices)) / 2.0, 2.0, 1e-12);
    EXPECT_THROW(w.query("nope"), InputError);
}

TEST(WorldIO, ErrorsNameFileLineAndField)
{
    struct Case
    {
        std::string text;
        std::string expect; // substrings separated by '|'
    };
    const std::vector<Case> cases = {
        {"name: [unclosed\n", "test.yaml:|malformed YAML"},
        {std::string(kHeader) + "colour: red\n", "test.yaml:3|unknown key 'colour'|accepted:"},
        {std::string(kHeader) + "obstacles:\n  - circle: {center: [1, 1], radius: -2}\n",
         "test.yaml:4|obstacles[0].circle.radius|must be > 0"},
        {std::string(kHeader) + "obstacles:\n  - circle: {center: [1, 1], radius: 1, colour: 2}\n",
         "obstacles[0].circle.colour|unknown key"},
        {std::string(kHeader) + "obstacles:\n  - blob: {x: 1}\n",
         "obstacles[0]|unknown obstacle type 'blob'"},
        {std::string(kHeader) + "obstacles:\n  - polygon: {points: [[0, 0], [2, 2], [2, 0], [0, 2]]}\n",
         "test.yaml:4|obstacles[0].polygon.points|not simple"},
        {std::string(kHeader) + "obstacles:\n  - circle: {center: [1, x], radius: 1}\n",
         "obstacles[0].circle.center[1]|expected a number"},
        {std::string(kHeader) + "robot: {radius: -1}\n", "test.yaml:3|robot.radius|must be >= 0"},
        {"name: t\nbounds: {xmin: 5, xmax: 1, ymin: 0, ymax: 1}\n", "test.yaml:2|bounds|xmin < xmax"},
        {"name: t\n", "field 'bounds'|missing"},
        {std::string(kHeader) + "queries:\n  - {start: [11, 1], goal: [5, 5]}\n",
         "test.yaml:4|queries[0].start|out of bounds"},
        {std::string(kHeader) + "obstacles:\n  - circle: {center: [5, 5], radius: 1}\nqueries:\n"
                                "  - {start: [1, 1], goal: [5.5, 5]}\n",
         "test.yaml:6|queries[0].goal|in collision"},
        {std::string(kHeader) + "robot: {radius: 0.5}\nqueries:\n  - {start: [0.2, 5], goal: [5, 5]}\n",
         "queries[0].start|out of bounds"},
        {std::string(kHeader) + "queries:\n  - {name: a, start: [1, 1], goal: [2, 2]}\n"
                                "  - {name: a, start: [1, 1], goal: [2, 2]}\n",
         "test.yaml:5|duplicate query name 'a'"},
        {std::string(kHeader) + "queries:\n  - {start: [1, 1]}\n", "queries[0].goal|missing"},
        {"name: t\ngrid: {rows: ['..', '..']}\nbounds: [0, 1, 0, 1]\n", "bounds|come from its grid"},
        {"name: t\ngrid: {file: nowhere.map}\n", "grid.file|nowhere.map"},
        {"name: t\ngrid: {file: x.txt}\n", "grid.file|.map or .pgm"},
        {"- 1\n- 2\n", "must be a YAML mapping"},
    };
    for (const auto &c : cases)
    {
        const std::string msg = parseError(c.text);
        ASSERT_FALSE(msg.empty()) << "accepted:\n" << c.text;
        std::stringstream parts(c.expect);
        std::string part;
        while (std::getline(parts, part, '|'))
            EXPECT_NE(msg.find(part), std::string::npos) << "message '" << msg << "' lacks '" << part << "'";
    }
}

TEST(WorldIO, MissingFileAndUnknownExtension)
{
    EXPECT_THROW(loadWorld("/nonexistent/world.yaml"), InputError);
    const std::string path = std::string(MHPLAN_TEST_DATA_DIR) + "/worldio_not_a_world.txt";
    try
    {
        loadWorld(path);
        FAIL() << "accepted a .txt world";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("unknown world file type"), std::string::npos) << e.what();
    }
}

TEST(WorldIO, YamlRoundTripKeepsGeometry)
{
    GeneratorOptions o;
    o.seed = 7;
    o.count = 15;
    o.robotRadius = 0.1;
    for (const World &w : {generateCircles(o), generateRectangles(o)})
    {
        const World back = parseWorldYaml(worldToYaml(w), "roundtrip.yaml");
        ASSERT_EQ(back.circles.size(), w.circles.size());
        ASSERT_EQ(back.polygons.size(), w.polygons.size());
        for (std::size_t i = 0; i < w.circles.size(); ++i)
        {
            EXPECT_EQ(back.circles[i].center, w.circles[i].center);
            EXPECT_EQ(back.circles[i].radius, w.circles[i].radius);
        }
        for (std::size_t i = 0; i < w.polygons.size(); ++i)
            EXPECT_EQ(back.polygons[i].vertices, w.polygons[i].vertices);
        ASSERT_EQ(back.queries.size(), 1u);
        EXPECT_EQ(back.queries[0].start, w.queries[0].start);
        EXPECT_EQ(back.robotRadius, w.robotRadius);
    }
}

TEST(WorldIO, GeneratorsAreReproducibleAndKeepQueriesFree)
{
    GeneratorOptions o;
    o.seed = 42;
    o.count = 200;
    o.minSize = 0.1;
    o.maxSize = 0.6;
    EXPECT_EQ(worldToYaml(generateCircles(o)), worldToYaml(generateCircles(o)));
    EXPECT_EQ(worldToYaml(generateRectangles(o)), worldToYaml(generateRectangles(o)));
    GeneratorOptions other = o;
    other.seed = 43;
    EXPECT_NE(worldToYaml(generateCircles(o)), worldToYaml(generateCircles(other)));
    for (const World &w : {generateCircles(o), generateRectangles(o)})
    {
        const auto model = makeCollisionModel(w, CollisionBackend::Analytic);
        EXPECT_TRUE(model->isValid(w.queries[0].start));
        EXPECT_TRUE(model->isValid(w.queries[0].goal));
        EXPECT_EQ(w.obstacleCount(), 200u);
    }
    o.count = 3;
    o.minSize = 15.0; // every such circle in [0,10]^2 covers both corners
    o.maxSize = 16.0;
    EXPECT_THROW(generateCircles(o), InputError);
    o.minSize = -1.0;
    EXPECT_THROW(generateCircles(o), InputError);
}

TEST(WorldIO, GridAndMazeGeneratorsAreConnected)
{
    GeneratorOptions o;
    o.width = 30;
    o.height = 20;
    o.density = 0.3;
    for (std::uint64_t seed = 1; seed <= 10; ++seed)
    {
        o.seed = seed;
        const World g = generateGrid(o);
        ASSERT_TRUE(g.isGrid());
        EXPECT_TRUE(gridCellsConnected(*g.grid, 0, 0, 29, 19));
        const double share = static_cast<double>(g.grid->blockedCount()) / (30.0 * 20.0);
        EXPECT_GT(share, 0.15);
        EXPECT_LT(share, 0.45);
        const World m = generateMaze(o);
        EXPECT_EQ(m.grid->width(), 61);
        EXPECT_EQ(m.grid->height(), 41);
        EXPECT_TRUE(gridCellsConnected(*m.grid, 1, 1, 59, 39));
        // A perfect maze on w x h cells has w*h - 1 passages: free cells = w*h + (w*h - 1).
        EXPECT_EQ(static_cast<std::size_t>(61 * 41) - m.grid->blockedCount(),
                  static_cast<std::size_t>(2 * 600 - 1));
    }
    o.density = 1.5;
    EXPECT_THROW(generateGrid(o), InputError);
}

TEST(WorldIO, ShippedWorldsLoadWithValidQueries)
{
    std::size_t count = 0;
    for (const auto &e : std::filesystem::directory_iterator(MHPLAN_ENVIRONMENTS_DIR))
    {
        if (e.path().extension() != ".yaml")
            continue;
        ++count;
        World w;
        ASSERT_NO_THROW(w = loadWorld(e.path().string())) << e.path();
        EXPECT_FALSE(w.queries.empty()) << e.path();
        EXPECT_FALSE(w.source.empty()) << e.path() << " must say where it comes from";
        const auto model = makeCollisionModel(w);
        for (const auto &q : w.queries)
        {
            EXPECT_TRUE(model->isValid(q.start)) << e.path();
            EXPECT_TRUE(model->isValid(q.goal)) << e.path();
        }
    }
    EXPECT_GE(count, 6u);
}

TEST(WorldIO, BfoCase2MatchesTheSpecification)
{
    const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case2.yaml");
    ASSERT_EQ(w.circles.size(), 12u);
    EXPECT_EQ(w.circles[3].center, Vec2(4.5, 4.5));
    EXPECT_DOUBLE_EQ(w.circles[3].radius, 1.3);
    EXPECT_EQ(w.queries[0].start, Vec2(0, 0));
    EXPECT_EQ(w.queries[0].goal, Vec2(10, 10));
    EXPECT_NE(w.assumptions.find("assumed"), std::string::npos);
}

namespace
{
    /** What the world reader makes of \e text: the world as YAML with its queries (or the error), and whether
        it took the quick reading of the queries (QueryList.h). */
    std::string readBoth(const std::string &text, bool &quick)
    {
        const std::size_t before = splitQueriesCount();
        std::string out;
        try
        {
            out = worldToYaml(parseWorldYaml(text, "w.yaml"));
        }
        catch (const InputError &e)
        {
            out = std::string("error: ") + e.what();
        }
        quick = splitQueriesCount() > before;
        return out;
    }

    /** The same with yaml-cpp's tree only (the reader before the quick reading). */
    std::string readTree(const std::string &text)
    {
        try
        {
            const YAML::Node root = loadYamlMapping(text, "w.yaml", "world file", "environments/README.md");
            return worldToYaml(readWorldNode(YamlReader("w.yaml"), root));
        }
        catch (const InputError &e)
        {
            return std::string("error: ") + e.what();
        }
    }
} // namespace

// The quick reading of the queries (src/io/QueryList.cpp) reads what yaml-cpp's tree reads, and leaves every
// other form and every problem to the tree: same worlds, same errors with the same lines.
TEST(WorldIO, QuickQueryReadingReadsWhatTheTreeReads)
{
    const std::string se2 =
        "space: se2\nrobot: {polygon: [[-0.2, -0.1], [0.2, -0.1], [0.2, 0.1], [-0.2, 0.1]]}\n";
    struct Case
    {
        std::string text;
        bool quick; // the quick reading takes it
    };
    const std::vector<Case> cases = {
        {std::string(kHeader) +
             "queries:\n  - {start: [1, 1], goal: [9, 9]}\n  - {name: b, start: [1, 2], goal: [9, 8]}\n",
         true},
        // the list first, then more keys (their lines must stay), comments and blank lines inside
        {"queries:\n  # first\n  - start: [1, 1]\n    goal: [9, 9]\n\n  - {name: 'x y', start: ['1.5', 2e0], "
         "goal: "
         "[9.25, -0]}\nname: t\n# c\nbounds: {xmin: 0, xmax: 10, ymin: 0, ymax: 10}\nobstacles:\n  - circle: "
         "{center: [5, 5], radius: 1}\n",
         true},
        {"name: t\nqueries: [{start: [1, 1], goal: [9, 9]}, {name: z, goal: [2, 2], start: [3, 3]}]\nbounds: "
         "[0, 10, 0, "
         "10]\n",
         true},
        {"name: t\r\nbounds: [0, 10, 0, 10]\r\nqueries:\r\n  - {start: [1, 1], goal: [9, 9]}\r\n", true},
        {std::string(kHeader) + se2 + "queries:\n  - {start: [1, 1, 0.5], goal: [9, 9]}\n", true},
        // forms left to the tree (all read, or refused, as before)
        {std::string(kHeader) + "queries:\n- {start: [1, 1], goal: [9, 9]}\n", false},    // indentless
        {std::string(kHeader) + "queries:\n  - {start: [.5, 1], goal: [9, 9]}\n", false}, // ".5"
        {std::string(kHeader) + "queries:\n  - {start: [+1, 1], goal: [9, 9]}\n", false},
        {std::string(kHeader) +
             "queries:\n  - {start: &a [1, 1], goal: [9, 9]}\n  - {start: *a, goal: [8, 8]}\n",
         false},
        {std::string(kHeader) + "queries:\n  - {start: [!!float 1, 1], goal: [9, 9]}\n", false},
        {"{name: t, bounds: [0, 10, 0, 10], queries: [{start: [1, 1], goal: [9, 9]}]}\n", false},
        // problems: the same message as the tree's
        {std::string(kHeader) + "queries:\n  - {start: [1, 1, 0.5], goal: [9, 9]}\n", true},
        {std::string(kHeader) +
             "queries:\n  - {start: [1, 1], goal: [9, 9]}\n  - {start: [1, 1], goal: [11, 9]}\n",
         true},
        {std::string(kHeader) +
             "obstacles:\n  - circle: {center: [9, 9], radius: 0.5}\nqueries:\n  - {start: [1, 1], "
             "goal: [9, 9]}\n",
         true},
        {std::string(kHeader) +
             "queries:\n  - {name: a, start: [1, 1], goal: [9, 9]}\n  - {name: a, start: [1, 2], "
             "goal: [9, 9]}\n",
         false},
        {std::string(kHeader) + "queries:\n  - {start: [1, 1], goal: [9, 9], via: [2, 2]}\n", false},
        {std::string(kHeader) + "queries:\n  - {start: [1, 1]}\n", false},
        {std::string(kHeader) + "queries:\n  - {start: [1, 1], start: [2, 2], goal: [9, 9]}\n", false},
        {std::string(kHeader) + "queries:\n  - {name: ~, start: [1, 1], goal: [9, 9]}\n", false},
        {std::string(kHeader) + "queries:\n  - {start: [1e400, 1], goal: [9, 9]}\n", false},
        {std::string(kHeader) + "queries:\n  - {start: [1, 1], goal: [9, 9]}\nqueries: []\n", false},
        {std::string(kHeader) + "queries:\n  - {start: [1, 1], goal: [9, 9]\n", false},
        {std::string(kHeader) + "queries:\n  - {start: [1, 1], goal: [9, 9]}\n---\nname: u\n", false},
        {std::string(kHeader) + "bounds: [0, 1, 0, 1]\nqueries:\n  - {start: [1, 1], goal: [9, 9]}\n", true},
        {"name: t\nqueries:\n  - {start: [1, 1], goal: [9, 9]}\nbounds: {xmin: 0, xmax: -10, ymin: 0, ymax: "
         "10}\n",
         true},
    };
    for (const Case &c : cases)
    {
        bool quick = false;
        const std::string got = readBoth(c.text, quick);
        EXPECT_EQ(got, readTree(c.text)) << c.text;
        EXPECT_EQ(quick, c.quick) << c.text << got;
    }
    // Every shipped world with queries: the same world either way.
    for (const auto &e : std::filesystem::directory_iterator(MHPLAN_ENVIRONMENTS_DIR))
    {
        if (e.path().extension() != ".yaml")
            continue;
        std::ifstream in(e.path());
        std::stringstream text;
        text << in.rdbuf();
        bool quick = false;
        EXPECT_EQ(readBoth(text.str(), quick), readTree(text.str())) << e.path();
    }
}

// docs/conventions.md, "Adding a world format": a format is a parser and one registration (WorldFormat in
// src/io/WorldIO.h; the built-in ones are the list in WorldIO.cpp). Registered, loadWorld reads its files by
// their extension, names it among the accepted ones and refuses bad input through its parser; the built-in
// messages are those of the list.
TEST(WorldFormats, ANewFormatIsOneParserAndOneRegistration)
{
    // The new format: rows of '.' (free) and '@' (blocked), the top row first.
    const auto parseRows = [](const std::string &text, const std::string &path)
    {
        std::vector<std::string> rows;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);)
            rows.push_back(line);
        if (rows.empty() || rows[0].empty())
            throw InputError(path + ":1: expected a row of '.' and '@'");
        const int width = static_cast<int>(rows[0].size()), height = static_cast<int>(rows.size());
        auto grid = std::make_shared<OccupancyGrid>(width, height, 1.0);
        for (int r = 0; r < height; ++r)
        {
            if (static_cast<int>(rows[r].size()) != width)
                throw InputError(path + ":" + std::to_string(r + 1) + ": a row of " +
                                 std::to_string(rows[r].size()) + " cells; expected " +
                                 std::to_string(width));
            for (int c = 0; c < width; ++c)
                grid->setBlocked(c, height - 1 - r, rows[r][c] == '@');
        }
        return gridWorld("rows", grid);
    };
    const std::string dir = ::testing::TempDir();
    const std::string good = dir + "/mhplan_format_good.rows", bad = dir + "/mhplan_format_bad.rows";
    std::ofstream(good) << "....\n.@@.\n....\n";
    std::ofstream(bad) << "....\n..\n";
    const auto errorOf = [](const std::string &path)
    {
        try
        {
            loadWorld(path);
        }
        catch (const InputError &e)
        {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(errorOf(good), good + ": unknown world file type '.rows'; accepted: .yaml, .yml, .map, .pgm");
    EXPECT_EQ(errorOf(dir), dir + ": is a directory, not a world file (.yaml, .yml, .map or .pgm)");

    registerWorldFormat({{"rows"}, 1 << 20, parseRows, ""});
    const World w = loadWorld(good);
    ASSERT_TRUE(w.isGrid());
    EXPECT_EQ(w.grid->width(), 4);
    EXPECT_EQ(w.grid->height(), 3);
    EXPECT_EQ(w.grid->blockedCount(), 2u);
    EXPECT_TRUE(w.grid->blocked(1, 1));
    EXPECT_EQ(errorOf(bad), bad + ":2: a row of 2 cells; expected 4");
    const std::string txt = std::string(MHPLAN_TEST_DATA_DIR) + "/worldio_not_a_world.txt";
    EXPECT_EQ(errorOf(txt),
              txt + ": unknown world file type '.txt'; accepted: .yaml, .yml, .map, .pgm, .rows");
    EXPECT_THROW(registerWorldFormat({{"map"}, 1, parseRows, ""}), std::invalid_argument);
    EXPECT_FALSE(unregisterWorldFormat("yaml")); // built-in formats stay
    EXPECT_TRUE(unregisterWorldFormat("rows"));
    EXPECT_EQ(errorOf(good), good + ": unknown world file type '.rows'; accepted: .yaml, .yml, .map, .pgm");
    std::filesystem::remove(good);
    std::filesystem::remove(bad);
}

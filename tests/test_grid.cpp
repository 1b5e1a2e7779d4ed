// SPDX-License-Identifier: BSD-3-Clause
/* Occupancy grids: MovingAI and PGM parsing, and the exact grid collision model against brute force over
   every blocked square (drawings are y-up: row 0 of a file is the top). */
#include "src/collision/Collision.h"
#include "src/collision/GridCollision.h"
#include "src/io/GridIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

using namespace mhplan;

namespace
{
    const std::string kData = MHPLAN_TEST_DATA_DIR;
    constexpr double kInf = std::numeric_limits<double>::infinity();

    OccupancyGrid parseMap(const std::string &text, const std::string &name = "t.map")
    {
        std::istringstream in(text);
        return parseMovingAIMap(in, name);
    }

    /** \brief The InputError message of parsing \e text (fails the test if nothing is thrown). */
    std::string mapError(const std::string &text)
    {
        try
        {
            parseMap(text);
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        ADD_FAILURE() << "no InputError for:\n" << text;
        return "";
    }

    OccupancyGrid pgm(const std::string &bytes, double threshold = 0.5, bool negate = false)
    {
        std::istringstream in(bytes);
        return parsePgm(in, "t.pgm", 1.0, threshold, negate);
    }

    std::string pgmError(const std::string &bytes)
    {
        try
        {
            pgm(bytes);
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        ADD_FAILURE() << "no InputError";
        return "";
    }

    /** \brief Blocked-row strings, top row first, as in a map file. */
    std::string rowsOf(const OccupancyGrid &g)
    {
        std::string out;
        for (int row = 0; row < g.height(); ++row)
        {
            for (int ix = 0; ix < g.width(); ++ix)
                out += g.blocked(ix, g.rowToIy(row)) ? '@' : '.';
            out += '/';
        }
        return out;
    }

    std::shared_ptr<OccupancyGrid> randomGrid(int w, int h, double density, unsigned seed, double cell = 1.0,
                                              Vec2 origin = {0.0, 0.0})
    {
        auto g = std::make_shared<OccupancyGrid>(w, h, cell, origin);
        std::mt19937 rng(seed);
        std::bernoulli_distribution blocked(density);
        for (int iy = 0; iy < h; ++iy)
            for (int ix = 0; ix < w; ++ix)
                g->setBlocked(ix, iy, blocked(rng));
        return g;
    }

    /** \brief A grid from rows drawn top row first ('#' blocked). */
    std::shared_ptr<OccupancyGrid> drawnGrid(const std::vector<std::string> &rows, double cell = 1.0,
                                             Vec2 origin = {0.0, 0.0})
    {
        auto g = std::make_shared<OccupancyGrid>(static_cast<int>(rows[0].size()),
                                                 static_cast<int>(rows.size()), cell, origin);
        for (int row = 0; row < g->height(); ++row)
            for (int ix = 0; ix < g->width(); ++ix)
                g->setBlocked(ix, g->rowToIy(row), rows[static_cast<std::size_t>(row)][ix] == '#');
        return g;
    }

    std::shared_ptr<GridCollisionModel> modelOf(std::shared_ptr<const OccupancyGrid> g, double radius)
    {
        World w = gridWorld("test", std::move(g));
        w.robotRadius = radius;
        return std::make_shared<GridCollisionModel>(w);
    }

    std::vector<Vec2> square(const Box &b)
    {
        return {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}};
    }

    double pointBoxDistance(const Vec2 &p, const Box &b)
    {
        const double dx = std::max({0.0, b.xmin - p.x, p.x - b.xmax});
        const double dy = std::max({0.0, b.ymin - p.y, p.y - b.ymax});
        return std::hypot(dx, dy);
    }

    /** \brief Brute-force reference: every blocked square, the outside of the grid, every pinch corner. */
    struct Oracle
    {
        const OccupancyGrid &g;
        double r;

        double outsideDistance(const Vec2 &p) const
        {
            const Box b = g.bounds();
            return std::max(0.0, std::min({p.x - b.xmin, b.xmax - p.x, p.y - b.ymin, b.ymax - p.y}));
        }
        double distanceToBlocked(const Vec2 &p) const
        {
            double best = outsideDistance(p);
            for (int iy = 0; iy < g.height(); ++iy)
                for (int ix = 0; ix < g.width(); ++ix)
                    if (g.blocked(ix, iy))
                        best = std::min(best, pointBoxDistance(p, g.cellBox(ix, iy)));
            return best;
        }
        double distanceToFree(const Vec2 &p) const
        {
            double best = kInf;
            for (int iy = 0; iy < g.height(); ++iy)
                for (int ix = 0; ix < g.width(); ++ix)
                    if (!g.blocked(ix, iy))
                        best = std::min(best, pointBoxDistance(p, g.cellBox(ix, iy)));
            return best;
        }
        double clearance(const Vec2 &p) const
        {
            const double d = distanceToBlocked(p);
            return d > 0.0 ? d - r : -distanceToFree(p) - r;
        }
        Vec2 vertex(int vx, int vy) const { return {g.cellBox(vx, vy).xmin, g.cellBox(vx, vy).ymin}; }
        bool pinchAt(int vx, int vy) const
        {
            const bool bl = g.blocked(vx - 1, vy - 1), br = g.blocked(vx, vy - 1);
            const bool tl = g.blocked(vx - 1, vy), tr = g.blocked(vx, vy);
            return (bl && tr && !br && !tl) || (br && tl && !bl && !tr);
        }
        bool isPinch(const Vec2 &p) const
        {
            for (int vy = 0; vy <= g.height(); ++vy)
                for (int vx = 0; vx <= g.width(); ++vx)
                    if (p == vertex(vx, vy))
                        return pinchAt(vx, vy);
            return false;
        }
        bool inBounds(const Vec2 &p) const { return g.bounds().inflated(-r).contains(p); }
        bool isValid(const Vec2 &p) const
        {
            if (!inBounds(p) || isPinch(p))
                return false;
            if (r > 0.0)
                return distanceToBlocked(p) >= r;
            // Point robot: not in the interior of B (in B and away from free space).
            return !(distanceToBlocked(p) == 0.0 && distanceToFree(p) > 0.0);
        }
        /** \brief Distance from the segment to B (0 when they meet). */
        double segmentDistance(const Vec2 &a, const Vec2 &b) const
        {
            double best = std::min(outsideDistance(a), outsideDistance(b));
            for (int iy = 0; iy < g.height(); ++iy)
                for (int ix = 0; ix < g.width(); ++ix)
                    if (g.blocked(ix, iy))
                        best = std::min(best, segmentPolygonDistance(a, b, square(g.cellBox(ix, iy))));
            return best;
        }
        /** \brief Valid for generic segments (not lying on grid lines). */
        bool segmentValid(const Vec2 &a, const Vec2 &b) const
        {
            if (!inBounds(a) || !inBounds(b))
                return false;
            const Box sb = boundingBox({a, b}).inflated(r + 1e-9);
            for (int iy = 0; iy < g.height(); ++iy)
                for (int ix = 0; ix < g.width(); ++ix)
                {
                    const Box cb = g.cellBox(ix, iy);
                    if (!g.blocked(ix, iy) || !cb.overlaps(sb))
                        continue;
                    if (r > 0.0 && segmentPolygonDistance(a, b, square(cb)) < r)
                        return false;
                    if (r == 0.0 && segmentEntersPolygonInterior(a, b, square(cb)))
                        return false;
                }
            if (r == 0.0)
                for (int vy = 0; vy <= g.height(); ++vy)
                    for (int vx = 0; vx <= g.width(); ++vx)
                    {
                        if (pinchAt(vx, vy) && pointSegmentDistance(vertex(vx, vy), a, b) == 0.0)
                            return false;
                    }
            return r == 0.0 || std::min(outsideDistance(a), outsideDistance(b)) >= r;
        }
    };

    /** \brief Random segments: uniform start, random direction, length up to \e maxLen, inside bounds. */
    std::vector<std::pair<Vec2, Vec2>> randomSegments(const Box &b, double maxLen, int n, unsigned seed)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> ux(b.xmin, b.xmax), uy(b.ymin, b.ymax), ua(0.0, 2.0 * kPi),
            ul(0.0, maxLen);
        std::vector<std::pair<Vec2, Vec2>> out;
        while (static_cast<int>(out.size()) < n)
        {
            const Vec2 a{ux(rng), uy(rng)};
            const double ang = ua(rng);
            const double len = ul(rng);
            const Vec2 c = a + Vec2{std::cos(ang), std::sin(ang)} * len;
            if (b.contains(c))
                out.emplace_back(a, c);
        }
        return out;
    }
} // namespace

// ---------------------------------------------------------------------------------------------- MovingAI

TEST(GridIO, MovingAIParsesCharactersAndFlipsRows)
{
    // @...    row 0 = top (iy 2)
    // .TG.
    // ..SW    row 2 = bottom (iy 0)
    const OccupancyGrid g = loadMovingAIMap(kData + "/grid_small.map");
    ASSERT_EQ(g.width(), 4);
    ASSERT_EQ(g.height(), 3);
    EXPECT_EQ(rowsOf(g), "@.../.@../...@/");
    EXPECT_TRUE(g.blocked(0, 2)); // first text row, first column: top-left of the world
    EXPECT_FALSE(g.blocked(0, 0));
    EXPECT_TRUE(g.blocked(3, 0)); // 'W' in the last text row: bottom-right
    EXPECT_EQ(g.blockedCount(), 3u);

    // A blocked cell in the first text row is at the top of the world.
    auto model = modelOf(std::make_shared<const OccupancyGrid>(g), 0.0);
    EXPECT_FALSE(model->isValid({0.5, 2.5}));
    EXPECT_TRUE(model->isValid({0.5, 0.5}));
}

TEST(GridIO, MovingAIToleratesCarriageReturnsAndScalesCells)
{
    std::ifstream probe(kData + "/grid_crlf.map");
    ASSERT_TRUE(probe.good());
    const OccupancyGrid g = loadMovingAIMap(kData + "/grid_crlf.map", 0.5);
    EXPECT_EQ(rowsOf(g), ".@./.../");
    EXPECT_DOUBLE_EQ(g.cellSize(), 0.5);
    EXPECT_DOUBLE_EQ(g.bounds().xmax, 1.5);
    EXPECT_DOUBLE_EQ(g.bounds().ymax, 1.0);
}

TEST(GridIO, MovingAIRoundTrip)
{
    auto g = randomGrid(13, 7, 0.3, 11);
    const std::string text = movingAIMapText(*g);
    const OccupancyGrid back = parseMap(text);
    ASSERT_EQ(back.width(), 13);
    ASSERT_EQ(back.height(), 7);
    for (int iy = 0; iy < 7; ++iy)
        for (int ix = 0; ix < 13; ++ix)
            EXPECT_EQ(back.blocked(ix, iy), g->blocked(ix, iy)) << ix << "," << iy;
    EXPECT_EQ(movingAIMapText(back), text);
    // The first text row is the top row.
    EXPECT_EQ(text.substr(text.find("map\n") + 4, 13).front(), g->blocked(0, 6) ? '@' : '.');
}

TEST(GridIO, MovingAIErrorsNameFileAndLine)
{
    const std::string head = "type octile\nheight 2\nwidth 3\nmap\n";
    struct Case
    {
        std::string text;
        std::string where;
        std::string what;
    };
    const std::vector<Case> cases = {
        {"", "t.map:1:", "empty"},
        {"tipe octile\nheight 2\nwidth 3\nmap\n...\n...\n", "t.map:1:", "type octile"},
        {"type tile\nheight 2\nwidth 3\nmap\n...\n...\n", "t.map:1:", "octile"},
        {"type octile\nheight two\nwidth 3\nmap\n...\n...\n", "t.map:2:", "height"},
        {"type octile\nheight 0\nwidth 3\nmap\n", "t.map:2:", "positive"},
        {"type octile\nheight 2\nwidth -3\nmap\n", "t.map:3:", "positive"},
        // End of file: the last line of the file, never one past it (issue 19).
        {"type octile\nheight 2\n", "t.map:2:", "end of file"},
        {"type octile\nheight 2\nwidth 3\nmapp\n...\n...\n", "t.map:4:", "'map'"},
        {"type octile\nheight 2\nheight 3\nmap\n", "t.map:3:", "duplicate"},
        {head + "...\n....\n", "t.map:6:", "expected width 3"},
        {head + "..\n...\n", "t.map:5:", "expected width 3"},
        {head + "...\n", "t.map:5:", "missing map rows"},
        {head + "...\n.x.\n", "t.map:6:", "column 2"},
        {head + "...\n...\n@@@\n", "t.map:7:", "after"},
    };
    for (const auto &c : cases)
    {
        const std::string msg = mapError(c.text);
        EXPECT_NE(msg.find(c.where), std::string::npos) << msg;
        EXPECT_NE(msg.find(c.what), std::string::npos) << msg;
    }
    // From files: the path and the line.
    try
    {
        loadMovingAIMap(kData + "/grid_bad_char.map");
        FAIL();
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("grid_bad_char.map:6:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("column 2: unknown map character 'x'"), std::string::npos);
    }
    try
    {
        loadMovingAIMap(kData + "/grid_missing_rows.map");
        FAIL();
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("grid_missing_rows.map:6:"), std::string::npos) << e.what();
    }
    EXPECT_THROW(loadMovingAIMap(kData + "/grid_no_such_file.map"), InputError);
    std::istringstream ok(head + "...\n...\n");
    EXPECT_THROW(parseMovingAIMap(ok, "t.map", 0.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------- PGM

TEST(GridIO, PgmAsciiThresholdAndNegate)
{
    // Pixels (top row first): 0 100 200 255 / 127 128 10 250, maxval 255, cut at 127.5.
    const OccupancyGrid g = loadPgm(kData + "/grid_image.pgm");
    ASSERT_EQ(g.width(), 4);
    ASSERT_EQ(g.height(), 2);
    EXPECT_EQ(rowsOf(g), "@@../@.@./"); // dark = blocked, top row at iy 1
    EXPECT_TRUE(g.blocked(0, 1));
    const OccupancyGrid n = loadPgm(kData + "/grid_image.pgm", 1.0, 0.5, true);
    EXPECT_EQ(rowsOf(n), "..@@/.@.@/"); // bright = blocked
    const OccupancyGrid t = loadPgm(kData + "/grid_image.pgm", 2.0, 0.9);
    EXPECT_EQ(rowsOf(t), "@@@./@@@./"); // cut at 229.5
    EXPECT_DOUBLE_EQ(t.bounds().xmax, 8.0);
    EXPECT_THROW(loadPgm(kData + "/grid_image.pgm", 1.0, 1.5), std::invalid_argument);
}

TEST(GridIO, PgmBinary8And16Bit)
{
    const OccupancyGrid p5 = loadPgm(kData + "/grid_image_p5.pgm");
    const OccupancyGrid p2 = loadPgm(kData + "/grid_image.pgm");
    EXPECT_EQ(rowsOf(p5), rowsOf(p2));

    // 16 bit, big-endian, maxval 1000: 0 999 / 500 499 -> cut at 500.
    std::string bytes = "P5 2 2 1000\n";
    for (int v : {0, 999, 500, 499})
    {
        bytes += static_cast<char>(v >> 8);
        bytes += static_cast<char>(v & 0xff);
    }
    EXPECT_EQ(rowsOf(pgm(bytes)), "@./.@/");
    EXPECT_EQ(rowsOf(pgm(bytes, 0.5, true)), ".@/../");
}

TEST(GridIO, PgmErrorsNameFileAndLine)
{
    EXPECT_NE(pgmError("P3\n1 1\n255\n0\n").find("t.pgm:1:"), std::string::npos);
    EXPECT_NE(pgmError("P2\n# c\n0 2\n255\n").find("t.pgm:3:"), std::string::npos);
    EXPECT_NE(pgmError("P2\n2 1\n0\n0 0\n").find("maxval"), std::string::npos);
    const std::string big = pgmError("P2\n2 1\n255\n0\n\n300\n");
    EXPECT_NE(big.find("t.pgm:6:"), std::string::npos) << big;
    EXPECT_NE(big.find("exceeds maxval"), std::string::npos) << big;
    const std::string short_ = pgmError("P2\n2 2\n255\n0 1 2\n");
    EXPECT_NE(short_.find("t.pgm:5: unexpected end of file, expected pixel 4 of 4"), std::string::npos)
        << short_;
    EXPECT_NE(pgmError("P2\n2 1\n255\n0 x\n").find("t.pgm:4:"), std::string::npos);
    EXPECT_NE(pgmError(std::string("P5\n2 2\n255\n") + '\0').find("truncated"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------- collision

TEST(GridCollision, AutoBackendBuildsGridModel)
{
    const World w = gridWorld("g", drawnGrid({"..", ".#"}));
    const CollisionModelPtr m = makeCollisionModel(w);
    EXPECT_EQ(m->name(), "grid");
    EXPECT_TRUE(m->isValid({0.5, 1.5}));
    EXPECT_FALSE(m->isValid({1.5, 0.5}));
    EXPECT_EQ(makeCollisionModel(w, CollisionBackend::Grid)->name(), "grid");
    World geometric;
    geometric.name = "circles";
    geometric.bounds = {0, 1, 0, 1};
    EXPECT_THROW(GridCollisionModel{geometric}, InputError);
}

TEST(GridCollision, PointRulesOnGridLines)
{
    // y
    // 3 . . . .
    // 2 . # # .
    // 1 . # . .       (row text: top first)
    // 0 . . # .
    //   0 1 2 3 x
    auto g = drawnGrid({"....", ".##.", ".#..", "..#."});
    auto m = modelOf(g, 0.0);
    EXPECT_FALSE(m->isValid({1.5, 1.5}));  // inside a blocked cell
    EXPECT_TRUE(m->isValid({1.0, 1.5}));   // on the face of a blocked cell (touching)
    EXPECT_FALSE(m->isValid({1.5, 2.0}));  // on the edge between two blocked cells
    EXPECT_FALSE(m->isValid({2.0, 2.5}));  // idem, vertical edge
    EXPECT_TRUE(m->isValid({2.0, 2.0}));   // three blocked cells around, one free: touching
    EXPECT_FALSE(m->isValid({2.0, 1.0}));  // pinch corner: (1,1) and (2,0) blocked, (1,0) and (2,1) free
    EXPECT_TRUE(m->isValid({3.0, 1.0}));   // convex corner of (2,0): touching
    EXPECT_TRUE(m->isValid({0.0, 0.0}));   // grid corner (outside is blocked, touching)
    EXPECT_FALSE(m->isValid({-0.1, 0.5})); // out of bounds
    EXPECT_DOUBLE_EQ(m->clearance({1.5, 1.5}), -0.5);
    EXPECT_DOUBLE_EQ(m->clearance({2.5, 1.5}), 0.5);
    EXPECT_DOUBLE_EQ(m->clearance({0.5, 0.5}), 0.5);
    EXPECT_DOUBLE_EQ(m->clearance({1.5, 2.0}), -0.5); // between two blocked cells: 0.5 to free space
}

TEST(GridCollision, PinchRule)
{
    // Two cells whose two side cells are blocked: the diagonal between them passes a pinch corner.
    // 1 # .
    // 0 . #
    // Only one side blocked:
    // 1 . .
    // 0 . #
    // Cell size 1 at the origin, then cell size 0.25 at (10, -5).
    const std::vector<std::pair<double, Vec2>> frames = {{1.0, {0.0, 0.0}}, {0.25, {10.0, -5.0}}};
    for (const auto &frame : frames)
    {
        const double cell = frame.first;
        const Vec2 origin = frame.second;
        auto sc = [&](double x, double y) { return Vec2{origin.x + x * cell, origin.y + y * cell}; };
        auto bothS = drawnGrid({"#.", ".#"}, cell, origin);
        auto oneS = drawnGrid({"..", ".#"}, cell, origin);
        auto m0 = modelOf(bothS, 0.0);
        EXPECT_FALSE(m0->isValid(sc(1, 1)));                                // the pinch corner itself
        EXPECT_FALSE(m0->segmentValid(sc(0.5, 0.5), sc(1.5, 1.5)));         // through it
        EXPECT_FALSE(m0->segmentValid(sc(0.5, 0.5), sc(1, 1)));             // ending on it
        EXPECT_TRUE(m0->segmentValid(sc(0.5, 0.5), sc(0.9, 0.9)));          // short of it
        EXPECT_TRUE(m0->segmentValid(sc(0.5, 0.5), sc(0.5, 0.9)));          // free cell
        EXPECT_LT(m0->segmentClearance(sc(0.5, 0.5), sc(1.5, 1.5)), 1e-12); // touches B
        auto m1 = modelOf(oneS, 0.0);
        EXPECT_TRUE(m1->isValid(sc(1, 1)));                        // a convex corner: touching
        EXPECT_TRUE(m1->segmentValid(sc(0.5, 0.5), sc(1.5, 1.5))); // touches the corner only
        EXPECT_DOUBLE_EQ(m1->segmentClearance(sc(0.5, 0.5), sc(1.5, 1.5)), 0.0);
        auto m1r = modelOf(oneS, 0.1 * cell);
        EXPECT_FALSE(m1r->segmentValid(sc(0.5, 0.5), sc(1.5, 1.5))); // a disc does not fit
        EXPECT_TRUE(m1r->segmentValid(sc(0.5, 0.5), sc(0.5, 1.5)));
        EXPECT_NEAR(m1r->segmentClearance(sc(0.5, 0.5), sc(1.5, 1.5)), -0.1 * cell, 1e-12);
    }
}

TEST(GridCollision, SegmentsAlongGridLines)
{
    // 2 . . .
    // 1 # # .
    // 0 . . .
    auto g = drawnGrid({"...", "##.", "..."});
    auto m = modelOf(g, 0.0);
    EXPECT_TRUE(m->segmentValid({0.0, 2.0}, {2.0, 2.0}));  // along the top faces: touching
    EXPECT_TRUE(m->segmentValid({0.0, 1.0}, {3.0, 1.0}));  // along the bottom faces
    EXPECT_FALSE(m->segmentValid({1.0, 1.2}, {1.0, 1.8})); // on the edge between the two blocked cells
    EXPECT_TRUE(m->segmentValid({2.0, 0.5}, {2.0, 2.5}));  // along the right face
    EXPECT_TRUE(m->segmentValid({0.0, 0.0}, {0.0, 1.0}));  // along the grid's left border, free cell
    EXPECT_FALSE(m->segmentValid({0.0, 1.0}, {0.0, 2.0})); // along the border beside a blocked cell
    EXPECT_FALSE(m->segmentValid({0.5, 0.5}, {0.5, 2.5})); // through a blocked cell
    EXPECT_TRUE(m->segmentValid({2.5, 0.5}, {2.5, 2.5}));
    EXPECT_DOUBLE_EQ(m->segmentClearance({2.5, 0.5}, {2.5, 2.5}), 0.5);
    EXPECT_DOUBLE_EQ(m->segmentClearance({0.5, 0.5}, {0.5, 2.5}), -0.5);
    EXPECT_DOUBLE_EQ(m->segmentClearance({0.2, 0.5}, {1.5, 1.5}), -0.5);
}

namespace
{
    void checkClearanceAgainstBruteForce(const std::shared_ptr<OccupancyGrid> &g, double r, int n,
                                         unsigned seed)
    {
        auto m = modelOf(g, r);
        const Oracle o{*g, r};
        const Box b = g->bounds();
        const double s = g->cellSize();
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> ux(b.xmin - s, b.xmax + s), uy(b.ymin - s, b.ymax + s);
        std::uniform_int_distribution<int> snap(0, 3);
        int valid = 0;
        for (int k = 0; k < n; ++k)
        {
            Vec2 p{ux(rng), uy(rng)};
            // A quarter of the points snapped to half-cells: grid lines, vertices, centres.
            if (snap(rng) == 0)
                p = {b.xmin + std::round((p.x - b.xmin) / (0.5 * s)) * 0.5 * s,
                     b.ymin + std::round((p.y - b.ymin) / (0.5 * s)) * 0.5 * s};
            const double expected = o.clearance(p);
            ASSERT_NEAR(m->clearance(p), expected, 1e-9 * s) << p.x << "," << p.y;
            const bool v = o.isValid(p);
            ASSERT_EQ(m->isValid(p), v) << p.x << "," << p.y;
            valid += v;
        }
        EXPECT_GT(valid, n / 5);
        EXPECT_LT(valid, n * 19 / 20);
    }

    void checkSegmentsAgainstBruteForce(const std::shared_ptr<OccupancyGrid> &g, double r, int n,
                                        unsigned seed)
    {
        auto m = modelOf(g, r);
        const Oracle o{*g, r};
        const double s = g->cellSize();
        const auto segs = randomSegments(g->bounds(), 8.0 * s, n, seed);
        int valid = 0;
        int sampled = 0;
        for (const auto &[a, b] : segs)
        {
            const bool v = m->segmentValid(a, b);
            ASSERT_EQ(v, o.segmentValid(a, b)) << a.x << "," << a.y << " -> " << b.x << "," << b.y;
            valid += v;
            if (v && sampled < 2000)
            {
                // Dense sampling: an accepted segment never has an invalid sample.
                ++sampled;
                for (int k = 0; k <= 200; ++k)
                    ASSERT_TRUE(m->isValid(a + (b - a) * (k / 200.0)));
            }
        }
        EXPECT_GT(valid, n / 10);
        EXPECT_LT(valid, n * 9 / 10);
    }
} // namespace

TEST(GridCollision, ClearanceMatchesBruteForcePointRobot)
{
    checkClearanceAgainstBruteForce(randomGrid(64, 64, 0.2, 1), 0.0, 20000, 2);
}

TEST(GridCollision, ClearanceMatchesBruteForceDisc)
{
    checkClearanceAgainstBruteForce(randomGrid(64, 64, 0.2, 3), 0.3, 20000, 4);
}

TEST(GridCollision, ClearanceMatchesBruteForceScaledShifted)
{
    checkClearanceAgainstBruteForce(randomGrid(40, 30, 0.2, 5, 0.37, {-3.3, 7.1}), 0.0, 5000, 6);
    checkClearanceAgainstBruteForce(randomGrid(40, 30, 0.2, 7, 0.37, {-3.3, 7.1}), 0.2, 5000, 8);
}

TEST(GridCollision, SparseAndDenseGrids)
{
    // Far from obstacles (long row scans) and nearly full grids (penetration).
    checkClearanceAgainstBruteForce(randomGrid(48, 32, 0.01, 9), 1.5, 3000, 10);
    auto dense = randomGrid(32, 32, 0.85, 11);
    auto m = modelOf(dense, 0.0);
    const Oracle o{*dense, 0.0};
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> u(-1.0, 33.0);
    for (int k = 0; k < 3000; ++k)
    {
        const Vec2 p{u(rng), u(rng)};
        ASSERT_NEAR(m->clearance(p), o.clearance(p), 1e-9);
    }
    // No free cell at all.
    auto full = randomGrid(4, 4, 1.0, 13);
    EXPECT_EQ(modelOf(full, 0.0)->clearance({1.5, 1.5}), -kInf);
    EXPECT_FALSE(modelOf(full, 0.0)->segmentValid({0.5, 0.5}, {3.5, 3.5}));
}

TEST(GridCollision, SegmentValidMatchesBruteForcePointRobot)
{
    checkSegmentsAgainstBruteForce(randomGrid(64, 64, 0.2, 21), 0.0, 20000, 22);
}

TEST(GridCollision, SegmentValidMatchesBruteForceDisc)
{
    checkSegmentsAgainstBruteForce(randomGrid(64, 64, 0.2, 23), 0.3, 20000, 24);
}

TEST(GridCollision, SegmentValidScaledShifted)
{
    checkSegmentsAgainstBruteForce(randomGrid(40, 30, 0.2, 25, 0.37, {-3.3, 7.1}), 0.0, 4000, 26);
    checkSegmentsAgainstBruteForce(randomGrid(40, 30, 0.2, 27, 0.37, {-3.3, 7.1}), 0.1, 4000, 28);
}

TEST(GridCollision, LongSegmentsOnLargeGrid)
{
    // Segments spanning most of a 512 x 512 map, against the sampled check.
    auto g = randomGrid(512, 512, 0.002, 31);
    auto m = modelOf(g, 0.25);
    const auto segs = randomSegments(g->bounds(), 400.0, 200, 32);
    int valid = 0;
    for (const auto &[a, b] : segs)
    {
        const bool v = m->segmentValid(a, b);
        valid += v;
        if (v)
        {
            for (int k = 0; k <= 4000; ++k)
                ASSERT_TRUE(m->isValid(a + (b - a) * (k / 4000.0)));
        }
        EXPECT_EQ(v, m->segmentClearance(a, b) >= 0.0);
    }
    EXPECT_GT(valid, 0);
    EXPECT_LT(valid, 200);
}

TEST(GridCollision, SegmentClearanceMatchesBruteForce)
{
    for (double r : {0.0, 0.3})
    {
        auto g = randomGrid(48, 48, 0.25, 41 + static_cast<unsigned>(r * 10));
        auto m = modelOf(g, r);
        const Oracle o{*g, r};
        const auto segs = randomSegments(g->bounds(), 5.0, 3000, 42);
        int free = 0;
        int penetrating = 0;
        for (const auto &[a, b] : segs)
        {
            const double got = m->segmentClearance(a, b);
            const double d = o.segmentDistance(a, b);
            if (d > 0.0)
            {
                ++free;
                ASSERT_NEAR(got, d - r, 1e-9);
                continue;
            }
            if (++penetrating > 300)
                continue;
            // Penetrating: the minimum of the point clearance along the segment. Dense samples bound it
            // from above; the function is 1-Lipschitz, so it lies within one step below them.
            const int n = 200;
            double sampled = kInf;
            for (int k = 0; k <= n; ++k)
                sampled = std::min(sampled, o.clearance(a + (b - a) * (static_cast<double>(k) / n)));
            ASSERT_LE(got, sampled + 1e-9);
            ASSERT_GE(got, sampled - distance(a, b) / n - 1e-9);
        }
        EXPECT_GT(free, 300);
    }
}

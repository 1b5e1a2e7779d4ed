// SPDX-License-Identifier: BSD-3-Clause
/* The lattice baselines: A* equals the 8-connected (MovingAI) optimum, computed here by a plain Dijkstra and
   by the foundation's computeGridOctileOptimum; Theta* lies between the any-angle optimum and A*; geometric
   worlds, off-centre endpoints, disc robots, continuation, determinism; the 'mhplan scen' tool end to end. */
#include "ompl_planners/lattice/AStar.h"
#include "src/io/Generators.h"
#include "src/io/GridIO.h"
#include "src/optimum/Optimum.h"
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "ompl_planners/lattice/ThetaStar.h"
#include "src/collision/Validity.h"
#include "src/io/WorldIO.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/Console.h>

#include "CliSupport.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <sstream>
#include <sys/wait.h>

using namespace mhplan;
using mhplan::test::CliResult;
using mhplan::test::contains;
using mhplan::test::runCli;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    const std::string kData = MHPLAN_TEST_DATA_DIR;

    /** \brief A grid world of 1 m cells from rows of '.' and '@' (first row = top). */
    World gridFromRows(const std::vector<std::string> &rows)
    {
        auto grid = std::make_shared<OccupancyGrid>(static_cast<int>(rows[0].size()),
                                                    static_cast<int>(rows.size()), 1.0);
        for (std::size_t r = 0; r < rows.size(); ++r)
            for (std::size_t c = 0; c < rows[r].size(); ++c)
                grid->setBlocked(static_cast<int>(c), grid->rowToIy(static_cast<int>(r)), rows[r][c] == '@');
        return gridWorld("handmade", grid);
    }

    /** \brief Plain Dijkstra with the MovingAI rules, in cell units; infinity when unreachable. */
    double dijkstraCells(const OccupancyGrid &grid, int sx, int sy, int gx, int gy)
    {
        const int w = grid.width(), h = grid.height();
        std::vector<double> dist(static_cast<std::size_t>(w) * h, std::numeric_limits<double>::infinity());
        using Entry = std::pair<double, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
        dist[sy * w + sx] = 0.0;
        queue.push({0.0, sy * w + sx});
        while (!queue.empty())
        {
            const auto [d, c] = queue.top();
            queue.pop();
            if (d > dist[c])
                continue;
            const int x = c % w, y = c / w;
            if (x == gx && y == gy)
                return d;
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                {
                    if ((dx == 0 && dy == 0) || grid.blocked(x + dx, y + dy))
                        continue;
                    if (dx != 0 && dy != 0 && (grid.blocked(x + dx, y) || grid.blocked(x, y + dy)))
                        continue;
                    const double nd = d + (dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0);
                    const int n = (y + dy) * w + x + dx;
                    if (nd < dist[n])
                    {
                        dist[n] = nd;
                        queue.push({nd, n});
                    }
                }
        }
        return std::numeric_limits<double>::infinity();
    }

    struct PlanRun
    {
        ob::PlannerStatus status;
        std::vector<Vec2> points;
        double length{0.0};
        double bestCost{0.0};
        unsigned long iterations{0};
        bool valid{false}; ///< every segment passes the exact collision model
    };

    PlanRun plan(const World &world, const Query &query, const std::string &planner,
                 const std::map<std::string, std::string> &params = {})
    {
        const CollisionModelPtr model = makeCollisionModel(world);
        og::SimpleSetupPtr ss = makeSimpleSetup(world, query, model);
        ob::PlannerPtr p = builtinPlanners().create(planner, ss->getSpaceInformation(), params);
        ss->setPlanner(p);
        ss->setup();
        PlanRun r;
        r.status = p->solve(ob::plannerNonTerminatingCondition());
        if (ss->haveSolutionPath())
        {
            r.points = pathPoints(ss->getSolutionPath());
            r.length = polylineLength(r.points);
            r.valid = true;
            for (std::size_t i = 1; i < r.points.size(); ++i)
                r.valid = r.valid && model->segmentValid(r.points[i - 1], r.points[i]);
        }
        r.bestCost = std::stod(p->getPlannerProgressProperties().at("best cost REAL")());
        r.iterations = std::stoul(p->getPlannerProgressProperties().at("iterations INTEGER")());
        return r;
    }

    Query cellQuery(const OccupancyGrid &grid, int sx, int sy, int gx, int gy)
    {
        return {"cells", grid.cellCenter(sx, sy), grid.cellCenter(gx, gy)};
    }

    /** \brief Random pairs of free cells connected under the MovingAI rules. */
    std::vector<std::array<int, 4>> connectedPairs(const OccupancyGrid &grid, unsigned seed, int count)
    {
        std::mt19937 rng(seed);
        std::vector<std::array<int, 2>> free;
        for (int y = 0; y < grid.height(); ++y)
            for (int x = 0; x < grid.width(); ++x)
                if (!grid.blocked(x, y))
                    free.push_back({x, y});
        std::vector<std::array<int, 4>> out;
        for (int tries = 0; tries < 50 * count && static_cast<int>(out.size()) < count; ++tries)
        {
            const auto a = free[rng() % free.size()], b = free[rng() % free.size()];
            if (gridCellsConnected(grid, a[0], a[1], b[0], b[1]))
                out.push_back({a[0], a[1], b[0], b[1]});
        }
        return out;
    }

    std::vector<std::string> readLines(const std::string &path)
    {
        std::ifstream in(path);
        std::vector<std::string> lines;
        for (std::string l; std::getline(in, l);)
            lines.push_back(l);
        return lines;
    }

    std::string writeTemp(const std::string &name, const std::vector<std::string> &lines)
    {
        const std::string path = testing::TempDir() + "/mhplan_astar_" + name;
        std::ofstream out(path);
        for (const auto &l : lines)
            out << l << "\n";
        return path;
    }

    class Quiet : public ::testing::Test
    {
      protected:
        void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }
    };
} // namespace

using AStarGrid = Quiet;
using ThetaStarGrid = Quiet;
using LatticeGeometric = Quiet;
using LatticeContract = Quiet;
using ScenTool = Quiet;

TEST_F(AStarGrid, HandMadeGridsMatchTheOctileOptimum)
{
    // Each case: rows (top first), start and goal as (column, row) from the top.
    struct Case
    {
        std::vector<std::string> rows;
        int sc, sr, gc, gr;
        double cells; // the expected length, worked out by hand
    };
    const double r2 = std::sqrt(2.0);
    const std::vector<Case> cases = {
        // Open 5 x 4: three diagonals and one straight move.
        {{".....", ".....", ".....", "....."}, 0, 3, 4, 0, 3 * r2 + 1},
        // A pinch (two blocked cells meeting at a corner): no diagonal squeeze, go around.
        {{".@", "@."}, 0, 0, 1, 1, std::numeric_limits<double>::infinity()},
        {{"..@", ".@.", "..."}, 0, 0, 2, 1, 5.0},
        // Corner cutting refused: a diagonal past one blocked side cell is not a move.
        {{"..", ".@"}, 0, 1, 1, 0, 2.0},
        // A wall with a gap at the bottom.
        {{"..@..", "..@..", "..@..", "....."}, 0, 0, 4, 0, 6 + 2 * r2},
        // A spiral.
        {{".......", ".@@@@@.", ".@...@.", ".@.@.@.", ".@.@@@.", ".@.....", ".@@@@@@"},
         4,
         3,
         0,
         6,
         std::numeric_limits<double>::quiet_NaN()},
    };
    for (std::size_t k = 0; k < cases.size(); ++k)
    {
        const Case &c = cases[k];
        World w = gridFromRows(c.rows);
        const OccupancyGrid &g = *w.grid;
        const Query q = cellQuery(g, c.sc, g.rowToIy(c.sr), c.gc, g.rowToIy(c.gr));
        const double dijkstra = dijkstraCells(g, c.sc, g.rowToIy(c.sr), c.gc, g.rowToIy(c.gr));
        // The test's own oracle agrees with the hand-worked length.
        if (std::isinf(c.cells))
        {
            EXPECT_TRUE(std::isinf(dijkstra)) << "case " << k;
        }
        else if (!std::isnan(c.cells))
        {
            EXPECT_NEAR(dijkstra, c.cells, 1e-12) << "case " << k;
        }
        const PlanRun r = plan(w, q, "AStar");
        if (std::isinf(dijkstra))
        {
            EXPECT_EQ(r.status, ob::PlannerStatus::APPROXIMATE_SOLUTION) << "case " << k;
            EXPECT_TRUE(std::isinf(r.bestCost)) << "case " << k;
            continue;
        }
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION) << "case " << k;
        EXPECT_NEAR(r.length, dijkstra, 1e-9) << "case " << k;
        EXPECT_NEAR(r.bestCost, r.length, 1e-9) << "case " << k;
        EXPECT_TRUE(r.valid) << "case " << k;
        EXPECT_EQ(r.points.front(), q.start);
        EXPECT_EQ(r.points.back(), q.goal);
        const OptimumResult opt = computeGridOctileOptimum(w, q);
        EXPECT_NEAR(r.length, opt.length, 1e-9) << "case " << k;
    }
}

TEST_F(AStarGrid, GeneratedGridsMatchDijkstraAndTheFoundationsOptimum)
{
    int compared = 0;
    for (const double density : {0.15, 0.3, 0.4})
        for (std::uint64_t seed = 1; seed <= 4; ++seed)
        {
            GeneratorOptions o;
            o.seed = seed;
            o.width = 37;
            o.height = 23;
            o.density = density;
            const World w = generateGrid(o);
            const OccupancyGrid &g = *w.grid;
            for (const auto &pr : connectedPairs(g, static_cast<unsigned>(seed * 7 + density * 100), 6))
            {
                const Query q = cellQuery(g, pr[0], pr[1], pr[2], pr[3]);
                const PlanRun r = plan(w, q, "AStar");
                ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
                const double d = dijkstraCells(g, pr[0], pr[1], pr[2], pr[3]);
                EXPECT_NEAR(r.length, d, 1e-9) << "seed " << seed << " density " << density;
                EXPECT_NEAR(r.length, computeGridOctileOptimum(w, q).length, 1e-9);
                EXPECT_TRUE(r.valid);
                ++compared;
            }
        }
    EXPECT_GE(compared, 60);
}

TEST_F(AStarGrid, MazeAndExpansionCount)
{
    GeneratorOptions o;
    o.seed = 3;
    o.width = 20;
    o.height = 15; // 41 x 31 cells
    const World w = generateMaze(o);
    const PlanRun r = plan(w, w.queries[0], "AStar");
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_NEAR(r.length, computeGridOctileOptimum(w, w.queries[0]).length, 1e-9);
    EXPECT_TRUE(r.valid);
    // Every expansion closes a distinct free cell.
    EXPECT_GT(r.iterations, 0u);
    EXPECT_LE(r.iterations, w.grid->width() * w.grid->height() - w.grid->blockedCount());
}

TEST_F(AStarGrid, OffCentreStartAndGoalJoinTheirCells)
{
    World w = gridFromRows({"......", ".@@@@.", "......"});
    const Query q{"off", {0.2, 0.9}, {5.0, 2.5}}; // the goal on the border of two cells
    const PlanRun r = plan(w, q, "AStar");
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(r.valid);
    EXPECT_EQ(r.points.front(), q.start);
    EXPECT_EQ(r.points.back(), q.goal);
    // start -> (0.5, 0.5) -> ... -> (4.5, 2.5) or (5.5, 2.5) -> goal
    const double cells = dijkstraCells(*w.grid, 0, 0, 4, 2);
    EXPECT_NEAR(r.length, distance(q.start, {0.5, 0.5}) + cells + 0.5, 1e-9);
}

TEST_F(AStarGrid, DiscRobotOnAGridUsesTheValidator)
{
    World w =
        gridFromRows({"..........", "..........", "...@@@....", "...@@@....", "..........", ".........."});
    w.robotRadius = 0.3;
    const Query q{"disc", {0.5, 0.5}, {9.5, 5.5}};
    const PlanRun r = plan(w, q, "AStar");
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(r.valid);
    const PlanRun t = plan(w, q, "ThetaStar");
    ASSERT_EQ(t.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(t.valid);
    EXPECT_LE(t.length, r.length + 1e-9);
}

TEST_F(ThetaStarGrid, BetweenTheAnyAngleOptimumAndAStar)
{
    int compared = 0, shorter = 0;
    for (const double density : {0.1, 0.25, 0.35})
        for (std::uint64_t seed = 1; seed <= 4; ++seed)
        {
            GeneratorOptions o;
            o.seed = seed + 100;
            o.width = 30;
            o.height = 26;
            o.density = density;
            const World w = generateGrid(o);
            const OccupancyGrid &g = *w.grid;
            for (const auto &pr : connectedPairs(g, static_cast<unsigned>(seed * 13 + density * 100), 5))
            {
                const Query q = cellQuery(g, pr[0], pr[1], pr[2], pr[3]);
                const PlanRun a = plan(w, q, "AStar");
                const PlanRun t = plan(w, q, "ThetaStar");
                ASSERT_EQ(t.status, ob::PlannerStatus::EXACT_SOLUTION);
                EXPECT_TRUE(t.valid);
                EXPECT_LE(t.length, a.length + 1e-9) << "seed " << seed << " density " << density;
                const OptimumResult opt = computeOptimum(w, q);
                ASSERT_TRUE(opt.found);
                EXPECT_GE(t.length, opt.length - 1e-9) << "seed " << seed << " density " << density;
                shorter += t.length < a.length - 1e-6 ? 1 : 0;
                ++compared;
            }
        }
    EXPECT_GE(compared, 50);
    EXPECT_GT(shorter, compared / 2); // any-angle paths are usually strictly shorter
}

TEST_F(LatticeGeometric, ShippedWorldsGiveValidPathsAboveTheOptimum)
{
    for (const char *name : {"bfo_case1", "bfo_case2", "lrsma_scenario3"})
    {
        const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/" + name + ".yaml");
        const Query &q = w.queries[0];
        const double optimum = computeOptimum(w, q).length;
        const PlanRun a = plan(w, q, "AStar");
        const PlanRun t = plan(w, q, "ThetaStar");
        for (const PlanRun *r : {&a, &t})
        {
            ASSERT_EQ(r->status, ob::PlannerStatus::EXACT_SOLUTION) << name;
            EXPECT_TRUE(r->valid) << name;
            EXPECT_GE(r->length, optimum - 1e-9) << name;
            EXPECT_NEAR(r->bestCost, r->length, 1e-9) << name;
        }
        EXPECT_LE(a.length, optimum * (1.0 + (std::sqrt(2.0) - 1.0)) + 1e-9) << name; // octile bound
        EXPECT_LE(t.length, a.length + 1e-9) << name;
        EXPECT_LE(t.length, optimum * 1.01) << name; // Theta* is close to any-angle optimal here
    }
}

TEST_F(LatticeGeometric, ResolutionSetsTheLattice)
{
    const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case1.yaml");
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
    auto astar = std::make_shared<AStar>(ss->getSpaceInformation());
    ss->setPlanner(astar);
    ss->setup();
    ASSERT_EQ(astar->solve(ob::plannerNonTerminatingCondition()), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(astar->lattice().kind(), LatticeKind::Sampled);
    EXPECT_EQ(astar->lattice().width(), 100); // default: 1/100 of the larger extent
    EXPECT_NEAR(astar->lattice().spacing(), 0.1, 1e-12);
    EXPECT_TRUE(astar->params().setParam("resolution", "0.25"));
    ss->getProblemDefinition()->clearSolutionPaths();
    ASSERT_EQ(astar->solve(ob::plannerNonTerminatingCondition()), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(astar->lattice().width(), 40);
    EXPECT_TRUE(ss->getSolutionPath().check());

    // A lattice too fine to hold is refused, not allocated.
    EXPECT_TRUE(astar->params().setParam("resolution", "0.000001"));
    EXPECT_EQ(astar->solve(ob::plannerNonTerminatingCondition()), ob::PlannerStatus::ABORT);

    // On a grid world, lattice=sampled gives one validated node per cell centre.
    const World g = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/gms_grid20.yaml");
    const PlanRun cells = plan(g, g.queries[0], "AStar");
    const PlanRun sampled = plan(g, g.queries[0], "AStar", {{"lattice", "sampled"}});
    ASSERT_EQ(sampled.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(sampled.valid);
    // The validator lets diagonals pass a blocked side cell (touching a corner), so never longer.
    EXPECT_LE(sampled.length, cells.length + 1e-9);
}

TEST_F(LatticeContract, ContinuesAfterABudgetAndIsDeterministic)
{
    const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/gms_grid30.yaml");
    const PlanRun once = plan(w, w.queries[0], "AStar");
    ASSERT_EQ(once.status, ob::PlannerStatus::EXACT_SOLUTION);
    const PlanRun again = plan(w, w.queries[0], "AStar");
    EXPECT_EQ(once.points, again.points);
    EXPECT_EQ(once.iterations, again.iterations);

    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
    ob::PlannerPtr p =
        builtinPlanners().create("AStar", ss->getSpaceInformation(), {{"max_iterations", "7"}});
    ss->setPlanner(p);
    ss->setup();
    unsigned calls = 0;
    ob::PlannerStatus s = ob::PlannerStatus::TIMEOUT;
    do
    {
        s = p->solve(ob::plannerNonTerminatingCondition());
        ++calls;
        if (s != ob::PlannerStatus::EXACT_SOLUTION)
        {
            EXPECT_EQ(s, ob::PlannerStatus::APPROXIMATE_SOLUTION);
            EXPECT_EQ(std::stoul(p->getPlannerProgressProperties().at("iterations INTEGER")()), 7u * calls);
        }
    } while (s != ob::PlannerStatus::EXACT_SOLUTION && calls < 10000);
    EXPECT_EQ(std::stoul(p->getPlannerProgressProperties().at("iterations INTEGER")()), once.iterations);
    EXPECT_EQ(pathPoints(ss->getSolutionPath()), once.points);
    EXPECT_EQ(calls, (once.iterations + 6) / 7 + (once.iterations % 7 == 0 ? 1 : 0));
}

TEST_F(LatticeContract, PlannerDataHoldsThePath)
{
    const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/gms_grid20.yaml");
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
    ob::PlannerPtr p = builtinPlanners().create("ThetaStar", ss->getSpaceInformation());
    ss->setPlanner(p);
    ss->setup();
    ASSERT_EQ(p->solve(ob::plannerNonTerminatingCondition()), ob::PlannerStatus::EXACT_SOLUTION);
    const std::vector<Vec2> points = pathPoints(ss->getSolutionPath());
    ob::PlannerData data(ss->getSpaceInformation());
    p->getPlannerData(data);
    ASSERT_EQ(data.numVertices(), points.size());
    EXPECT_EQ(data.numEdges(), points.size() - 1);
    EXPECT_EQ(data.numStartVertices(), 1u);
    EXPECT_EQ(data.numGoalVertices(), 1u);
    for (unsigned int i = 0; i < data.numVertices(); ++i)
        EXPECT_EQ(statePosition(data.getVertex(i).getState()), points[i]) << i;
}

TEST_F(LatticeContract, ParametersAreCheckedByName)
{
    const World w = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case1.yaml");
    og::SimpleSetupPtr ss = makeSimpleSetup(w, w.queries[0], makeCollisionModel(w));
    for (const char *name : {"AStar", "ThetaStar"})
    {
        ob::PlannerPtr p = builtinPlanners().create(name, ss->getSpaceInformation());
        auto *lp = dynamic_cast<LatticePlanner *>(p.get());
        ASSERT_NE(lp, nullptr);
        try
        {
            lp->setResolution(-1.0);
            ADD_FAILURE() << "resolution -1 accepted";
        }
        catch (const std::invalid_argument &e)
        {
            EXPECT_TRUE(contains(e.what(), "parameter 'resolution' must be in [0, 1000000]; got -1"))
                << e.what();
        }
        EXPECT_THROW(lp->setLattice("hexagonal"), std::invalid_argument);
        EXPECT_THROW(
            builtinPlanners().create(name, ss->getSpaceInformation(), {{"max_iterations", "2000000000"}}),
            InputError);
        EXPECT_EQ(lp->getLattice(), "auto");
    }
}

TEST_F(ScenTool, TheShippedScenarioMatchesTheTestsOwnDijkstra)
{
    // The scenario's optima come from the generator script's Dijkstra; check them with this file's.
    const OccupancyGrid grid = loadMovingAIMap(kData + "/astar_random.map");
    const std::vector<std::string> lines = readLines(kData + "/astar_random.scen");
    ASSERT_GE(lines.size(), 2u);
    EXPECT_EQ(lines[0], "version 1");
    for (std::size_t k = 1; k < lines.size(); ++k)
    {
        std::istringstream in(lines[k]);
        int bucket, width, height, sx, sy, gx, gy;
        std::string map;
        double optimal;
        ASSERT_TRUE(in >> bucket >> map >> width >> height >> sx >> sy >> gx >> gy >> optimal) << lines[k];
        EXPECT_NEAR(dijkstraCells(grid, sx, grid.rowToIy(sy), gx, grid.rowToIy(gy)), optimal, 1e-7)
            << lines[k];
    }
}

TEST_F(ScenTool, AllLengthsMatch)
{
    const CliResult r = runCli("scen " + kData + "/astar_random.map " + kData + "/astar_random.scen");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(contains(r.out, "80 of 80 lengths match")) << r.out;
}

TEST_F(ScenTool, AWrongOptimumIsReportedWithItsLine)
{
    std::vector<std::string> lines = readLines(kData + "/astar_random.scen");
    // Line 4 of the file: replace its optimal length by a wrong one.
    std::string &l = lines[3];
    l = l.substr(0, l.rfind('\t')) + "\t123.5";
    const std::string path = writeTemp("wrong.scen", lines);
    const CliResult r = runCli("scen " + kData + "/astar_random.map " + path);
    EXPECT_EQ(r.code, 3) << r.out;
    EXPECT_TRUE(contains(r.out, "79 of 80 lengths match")) << r.out;
    EXPECT_TRUE(contains(r.out, path + ":4:")) << r.out;
    EXPECT_TRUE(contains(r.out, "MISMATCH")) << r.out;
}

TEST_F(ScenTool, MalformedFilesNameTheLine)
{
    const std::string map = kData + "/astar_random.map";
    const std::vector<std::string> good = readLines(kData + "/astar_random.scen");
    struct Bad
    {
        std::vector<std::string> lines;
        std::string expect;
    };
    const std::vector<Bad> cases = {
        {{"version 2", good[1]}, ":1: unsupported scenario version"},
        {{"bucket", good[1]}, ":1: expected the header 'version 1'"},
        {{"version 1", good[1], "0\tx.map\t48\t32\t1\t2\t3"}, ":3: expected 9 fields"},
        {{"version 1", "0\tx.map\t48\t32\t1\tabc\t3\t4\t5.0"}, ":2: field 'start-y': expected an integer"},
        {{"version 1", "0\tx.map\t40\t32\t1\t2\t3\t4\t5.0"}, ":2: map size 40 x 32 does not match"},
        {{"version 1", "0\tx.map\t48\t32\t48\t2\t3\t4\t5.0"}, ":2: start (48, 2) is outside the map"},
        {{"version 1", "0\tx.map\t48\t32\t1\t2\t3\t4\tfast"}, ":2: field 'optimal-length'"},
        {{"version 1"}, "has no problems"},
    };
    for (std::size_t k = 0; k < cases.size(); ++k)
    {
        const std::string path = writeTemp("bad" + std::to_string(k) + ".scen", cases[k].lines);
        const CliResult r = runCli("scen " + map + " " + path);
        EXPECT_EQ(r.code, 1) << r.out;
        EXPECT_TRUE(contains(r.out, cases[k].expect)) << "case " << k << ": " << r.out;
    }
    // A blocked start cell: find one in the map.
    const OccupancyGrid grid = loadMovingAIMap(map);
    int bx = -1, by = -1;
    for (int y = 0; y < grid.height() && bx < 0; ++y)
        for (int x = 0; x < grid.width() && bx < 0; ++x)
            if (grid.blocked(x, grid.rowToIy(y)))
                bx = x, by = y;
    const std::string blocked =
        writeTemp("blocked.scen", {"version 1", "0\tx.map\t48\t32\t" + std::to_string(bx) + "\t" +
                                                    std::to_string(by) + "\t0\t0\t1"});
    const CliResult r = runCli("scen " + map + " " + blocked);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_TRUE(contains(r.out, ":2: start")) << r.out;
    EXPECT_TRUE(contains(r.out, "is a blocked cell")) << r.out;
    EXPECT_EQ(runCli("scen " + map).code, 1);
}

// SPDX-License-Identifier: BSD-3-Clause
/* The planner registry: every entry allocates, its parameters round-trip, bad names and values are refused,
   and every registered planner solves a seed world through the shared exact validity checking. */
#include "src/base/Parameters.h"
#include "src/collision/ContactRule.h"
#include "src/collision/Problem.h"
#include "src/registry/Registry.h"
#include "src/io/WorldIO.h"
#include "ompl_planners/common/PlannerBase.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include "TimeScale.h"

#include <gtest/gtest.h>

#include <cxxabi.h>

#include <algorithm>
#include <iomanip>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <typeinfo>
#include <stdexcept>
#include <limits>
#include <utility>

using namespace mhplan;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
    ob::SpaceInformationPtr unitSquare()
    {
        auto space = std::make_shared<ob::RealVectorStateSpace>(2);
        space->setBounds(0.0, 1.0);
        auto si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker([](const ob::State *) { return true; });
        si->setup();
        return si;
    }

    std::string errorOf(const std::function<void()> &f)
    {
        try
        {
            f();
        }
        catch (const InputError &e)
        {
            return e.what();
        }
        return "";
    }
} // namespace

TEST(Registry, HoldsOmplBaselines)
{
    const PlannerRegistry &reg = builtinPlanners();
    for (const char *name :
         {"RRT", "RRTConnect", "RRTstar", "InformedRRTstar", "PRM", "PRMstar", "BITstar", "FMTstar"})
        EXPECT_TRUE(reg.has(name)) << name;
    PlannerRegistry copy;
    copy.add({"X", "test", "", [](const ob::SpaceInformationPtr &) { return ob::PlannerPtr(); }});
    EXPECT_THROW(
        copy.add({"X", "test", "", [](const ob::SpaceInformationPtr &) { return ob::PlannerPtr(); }}),
        std::invalid_argument);
}

TEST(Registry, UnknownPlannerListsRegisteredNames)
{
    const std::string msg = errorOf([] { builtinPlanners().get("RRTsharp!"); });
    EXPECT_NE(msg.find("unknown planner 'RRTsharp!'"), std::string::npos) << msg;
    for (const auto &name : builtinPlanners().names())
        EXPECT_NE(msg.find(name), std::string::npos) << name;
}

TEST(Registry, EveryParameterRoundTripsThroughItsDefault)
{
    const auto si = unitSquare();
    for (const auto &name : builtinPlanners().names())
    {
        const ob::PlannerPtr planner = builtinPlanners().create(name, si);
        ASSERT_TRUE(planner) << name;
        std::map<std::string, std::string> defaults;
        planner->params().getParams(defaults);
        ASSERT_NO_THROW(applyPlannerParameters(*planner, defaults)) << name;
        std::map<std::string, std::string> again;
        planner->params().getParams(again);
        EXPECT_EQ(defaults, again) << name;
    }
}

TEST(Registry, ParametersAreSetAndValidated)
{
    const auto si = unitSquare();
    const PlannerRegistry &reg = builtinPlanners();
    ob::PlannerPtr p =
        reg.create("RRTstar", si, {{"range", "0.25"}, {"goal_bias", "0.1"}, {"use_k_nearest", "false"}});
    EXPECT_EQ(p->params()["range"].getValue(), "0.25");
    EXPECT_EQ(p->params()["goal_bias"].getValue(), "0.1");
    EXPECT_EQ(p->params()["use_k_nearest"].getValue(), "0");

    std::string msg = errorOf([&] { reg.create("RRTstar", si, {{"goal_bias", "-0.5"}}); });
    EXPECT_NE(msg.find("'goal_bias'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(">= 0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("-0.5"), std::string::npos) << msg;
    msg = errorOf([&] { reg.create("RRTstar", si, {{"goal_bias", "lots"}}); });
    EXPECT_NE(msg.find("'goal_bias'"), std::string::npos) << msg;
    msg = errorOf([&] { reg.create("RRTstar", si, {{"use_k_nearest", "maybe"}}); });
    EXPECT_NE(msg.find("one of {0,1}"), std::string::npos) << msg;
    msg = errorOf([&] { reg.create("PRM", si, {{"rnage", "1"}}); });
    EXPECT_NE(msg.find("no parameter 'rnage'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("max_nearest_neighbors"), std::string::npos) << msg;
}

TEST(Registry, RangeChecks)
{
    EXPECT_EQ(checkAgainstRange("5", "0:1:10"), "");
    EXPECT_EQ(checkAgainstRange("10", "0:10"), "");
    EXPECT_NE(checkAgainstRange("11", "0:1:10"), "");
    EXPECT_NE(checkAgainstRange("-0.5", "0.:.1:1."), "");
    EXPECT_NE(checkAgainstRange("x", "0:1:10"), "");
    EXPECT_EQ(checkAgainstRange("b", "a,b,c"), "");
    EXPECT_NE(checkAgainstRange("d", "a,b,c"), "");
    EXPECT_EQ(checkAgainstRange("anything", ""), "");
    std::map<std::string, std::string> kv;
    parseKeyValue("a=1", kv);
    parseKeyValue("b=x=y", kv);
    EXPECT_EQ(kv.at("a"), "1");
    EXPECT_EQ(kv.at("b"), "x=y");
    EXPECT_THROW(parseKeyValue("=1", kv), InputError);
    EXPECT_THROW(parseKeyValue("novalue", kv), InputError);
}

// Every registered planner, run on a seed world through the shared validity checker and exact motion
// validator, returns a path that an independent exact check finds collision-free, or no exact solution.
TEST(Parameters, RangeWrittenOnceAndNumbersPrintedExactly)
{
    constexpr ParamRange weight{"penalty_weight", 0, 1, 1e9};
    EXPECT_EQ(rangeSuggestion(weight), "0:1:1000000000");
    EXPECT_NO_THROW(checkParameter(weight, 1e9));
    try
    {
        checkParameter(weight, -1);
        ADD_FAILURE() << "-1 accepted";
    }
    catch (const std::invalid_argument &e)
    {
        EXPECT_EQ(std::string(e.what()), "parameter 'penalty_weight' must be in [0, 1000000000]; got -1");
    }
    // OMPL's own printing of a double parameter keeps six digits (1234567 -> 1.23457e+06); ours reads back.
    for (const double v : {1234567.0, 0.1, 1.0 / 3.0, 1e-9, 4294967295.0, 0.0})
        EXPECT_EQ(std::strtod(formatParameter(v).c_str(), nullptr), v) << formatParameter(v);
    EXPECT_EQ(formatParameter(1234567.0), "1234567");
    EXPECT_EQ(formatParameter(0.1), "0.1");
    EXPECT_EQ(parseParameter(weight, "2.5"), 2.5);
    EXPECT_THROW(parseParameter(weight, "2.5x"), std::invalid_argument);
    EXPECT_THROW(parseParameter(weight, ""), std::invalid_argument);
}

TEST(Parameters, DeclaredOntoAFieldCheckStoreThenTellTheOwner)
{
    // declareRangedField / declareSwitchField: the range check, the store, then the owner's callback; a
    // refused value leaves the field and calls nothing.
    ompl::base::ParamSet params;
    double weight = 1.0;
    unsigned int steps = 5;
    bool on = false;
    int changes = 0;
    declareRangedField(params, ParamRange{"weight", 0, 0.1, 10, "w"}, weight, [&] { ++changes; });
    declareRangedField(params, ParamRange{"steps", 1, 1, 100}, steps);
    declareSwitchField(params, "on", on, "a switch", [&] { ++changes; });
    EXPECT_EQ(params["weight"].getRangeSuggestion(), "0:0.1:10");
    EXPECT_EQ(params["on"].getRangeSuggestion(), "0,1");
    EXPECT_EQ(parameterDescription(params["on"]), "a switch");
    EXPECT_TRUE(params.setParam("weight", "0.3"));
    EXPECT_EQ(weight, 0.3);
    EXPECT_EQ(params["weight"].getValue(), "0.3");
    EXPECT_FALSE(params.setParam("weight", "11"));
    EXPECT_FALSE(params.setParam("steps", "0"));
    EXPECT_EQ(weight, 0.3);
    EXPECT_EQ(steps, 5u);
    EXPECT_TRUE(params.setParam("steps", "100"));
    EXPECT_EQ(steps, 100u);
    EXPECT_TRUE(params.setParam("on", "1"));
    EXPECT_TRUE(on);
    EXPECT_EQ(changes, 2);
}

TEST(Registry, EveryPlannerSolvesASeedWorldWithAValidPath)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const World world = loadWorld(std::string(MHPLAN_ENVIRONMENTS_DIR) + "/bfo_case1.yaml");
    const CollisionModelPtr model = makeCollisionModel(world);
    ASSERT_TRUE(world.polygons.empty() && !world.circles.empty())
        << "the independent check below knows circles only";
    for (const auto &name : builtinPlanners().names())
    {
        // LBTRRT ignores the objective's cost threshold and always runs to the time limit, so this test
        // could only time it out; tests/test_ompl_planners.cpp solves with it on a bounded budget.
        if (name == "LBTRRT")
            continue;
        ompl::geometric::SimpleSetupPtr ss = makeSimpleSetup(world, world.queries[0], model);
        // SST's default radii (selection 5, pruning 3) are half and a third of this 10 m world: it prunes
        // nearly every node and reaches the goal, a zero-tolerance state, only by chance. Scaled, as a user
        // would.
        std::map<std::string, std::string> params;
        if (name == "SST")
            params = {{"selection_radius", "0.5"}, {"pruning_radius", "0.2"}};
        ss->setPlanner(builtinPlanners().create(name, ss->getSpaceInformation(), params));
        // Any path satisfies the objective, so every planner stops at its first exact solution (10 s is only
        // a safety net): no assertion depends on the machine's speed.
        ss->getProblemDefinition()->getOptimizationObjective()->setCostThreshold(
            ob::Cost(std::numeric_limits<double>::infinity()));
        const ompl::time::point t0 = ompl::time::now();
        const ob::PlannerStatus status = ss->solve(10.0 * mhplan::test::timeScale());
        const double seconds = ompl::time::seconds(ompl::time::now() - t0);
        if (seconds > 1.0)
            std::cout << name << " took " << seconds << " s to a first solution\n";
        ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << name;
        const std::vector<Vec2> pts = pathPoints(ss->getSolutionPath());
        ASSERT_GE(pts.size(), 2u) << name;
        EXPECT_EQ(pts.front(), world.queries[0].start) << name;
        EXPECT_LT(distance(pts.back(), world.queries[0].goal), 1e-6) << name;
        // Independent of the planner's collision model: the world's circles themselves, checked by the
        // exact segment-to-disc distance (bfo_case1 is a point robot among circles), touching allowed within
        // the contact rule's segment tolerance e / 2 (docs/contact.md).
        const double touch = contact::tolerance(world.bounds) / 2.0;
        for (std::size_t i = 1; i < pts.size(); ++i)
            for (const Circle &c : world.circles)
                EXPECT_GE(pointSegmentDistance(c.center, pts[i - 1], pts[i]),
                          c.radius + world.robotRadius - touch)
                    << name << " segment " << i << " enters the circle at (" << c.center.x << ", "
                    << c.center.y << ")";
        EXPECT_GE(polylineLength(pts), 14.2734 - 1e-3) << name << " beats the exact optimum";
    }
}

TEST(Registry, BenchmarkPlannerTextsParseOrSayWhatIsAccepted)
{
    BenchmarkPlanner p = parseBenchmarkPlanner("SMA[population_size=60,max_iterations=5]@SMA-60");
    EXPECT_EQ(p.name, "SMA");
    EXPECT_EQ(p.displayName, "SMA-60");
    EXPECT_EQ(p.params,
              (std::map<std::string, std::string>{{"population_size", "60"}, {"max_iterations", "5"}}));
    p = parseBenchmarkPlanner("RRTstar");
    EXPECT_EQ(p.name, "RRTstar");
    EXPECT_TRUE(p.params.empty());
    EXPECT_TRUE(p.displayName.empty());
    p = parseBenchmarkPlanner("pagmo:de@DE");
    EXPECT_EQ(p.name, "pagmo:de");
    EXPECT_EQ(p.displayName, "DE");
    for (const char *bad : {"SMA[population_size=60", "SMA[population_size]", "SMA@", "[a=1]", "SMA]"})
    {
        const std::string e = errorOf([&] { parseBenchmarkPlanner(bad); });
        EXPECT_NE(e.find("NAME[key=value,...]@DISPLAY"), std::string::npos) << bad << ": " << e;
        EXPECT_NE(e.find(bad), std::string::npos) << e;
    }
}

TEST(Registry, AddPlannersToBenchmarkTakesParametersAndDisplayNames)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    space->setBounds(0.0, 10.0);
    og::SimpleSetup ss(space);
    ss.setStateValidityChecker([](const ob::State *s)
                               { return s->as<ob::RealVectorStateSpace::StateType>()->values[0] > -1.0; });
    ob::ScopedState<> start(space), goal(space);
    start[0] = start[1] = 1.0;
    goal[0] = goal[1] = 9.0;
    ss.setStartAndGoalStates(start, goal);
    {
        ompl::tools::Benchmark refused(ss, "refused");
        EXPECT_NE(errorOf(
                      [&] {
                          addPlannersToBenchmark(refused, {"SMA@X", "GA@X"});
                      })
                      .find("two planners named 'X'"),
                  std::string::npos);
        EXPECT_NE(errorOf([&] { addPlannersToBenchmark(refused, {"SMA[no_such=1]"}); }).find("no_such"),
                  std::string::npos);
        EXPECT_NE(errorOf(
                      [&] {
                          addPlannersToBenchmark(refused, {"SMA", "SMA"});
                      })
                      .find("two planners named"),
                  std::string::npos);
    }
    ompl::tools::Benchmark benchmark(ss, "display");
    addPlannersToBenchmark(benchmark,
                           {"SMA[population_size=12,max_iterations=3]@SMA-12", "SMA[max_iterations=3]"});
    addPlannersToBenchmark(benchmark, {BenchmarkPlanner{"GA", {{"max_iterations", "3"}}, "GA-3"}});
    ompl::tools::Benchmark::Request request(5.0, 1024.0, 1);
    request.displayProgress = false;
    request.saveConsoleOutput = false;
    benchmark.benchmark(request);
    const auto &planners = benchmark.getRecordedExperimentData().planners;
    ASSERT_EQ(planners.size(), 3u);
    EXPECT_EQ(planners[0].name, "geometric_SMA-12");
    EXPECT_EQ(planners[1].name, "geometric_SMA");
    EXPECT_EQ(planners[2].name, "geometric_GA-3");
    auto param = [](const ompl::tools::Benchmark::PlannerExperiment &pe, const std::string &name)
    {
        for (const auto &kv : pe.common)
            if (kv.first.rfind(name + " ", 0) == 0 || kv.first == name)
                return kv.second;
        return std::string("(not recorded)");
    };
    EXPECT_EQ(param(planners[0], "population_size"), "12");
    EXPECT_EQ(param(planners[0], "max_iterations"), "3");
    EXPECT_EQ(param(planners[2], "max_iterations"), "3");
}

namespace
{
    std::string demangled(const char *name)
    {
        int status = 0;
        char *d = abi::__cxa_demangle(name, nullptr, nullptr, &status);
        std::string out = status == 0 && d != nullptr ? d : name;
        std::free(d);
        return out;
    }

    /** The header (ompl_planners/FAMILY/FILE.h, installed as include/mhplan/ompl_planners/...) that defines
        class \e cls ("mhplan::SlimeMould"); "" when none does. */
    std::string headerOf(const std::string &cls)
    {
        const std::string bare = cls.substr(cls.rfind(':') + 1);
        const std::regex definition("(^|\\n)\\s*class\\s+" + bare + "\\b[^;]*\\n?\\s*[:{]");
        const std::filesystem::path root = std::filesystem::path(MHPLAN_SOURCE_DIR) / "ompl_planners";
        std::vector<std::filesystem::path> files;
        for (const auto &f : std::filesystem::recursive_directory_iterator(root))
            if (f.path().extension() == ".h")
                files.push_back(f.path());
        std::sort(files.begin(), files.end());
        for (const auto &f : files)
        {
            std::ifstream in(f);
            std::stringstream text;
            text << in.rdbuf();
            if (std::regex_search(text.str(), definition))
                return "ompl_planners/" + std::filesystem::relative(f, root).generic_string();
        }
        return "";
    }
} // namespace

TEST(Registry, TheClassTableListsEveryMhplanPlanner)
{
    // docs/planner_classes.md: one row per registered mhplan planner (pagmo's included), "| `NAME` | `CLASS`
    // | `HEADER` |", generated from the registry (the planner's run-time class, the header that defines it).
    // On a mismatch this test prints the whole table to paste.
    std::ifstream in(std::string(MHPLAN_SOURCE_DIR) + "/docs/planner_classes.md");
    std::stringstream doc;
    doc << in.rdbuf();
    const auto si = unitSquare();
    std::string table, missing;
    for (const std::string &name : builtinPlanners().names())
    {
        if (builtinPlanners().get(name).origin == "ompl")
            continue; // mhplan's own (origin "mhplan") and its pagmo2 bridge (origin "pagmo")
        const ob::PlannerPtr p = builtinPlanners().create(name, si);
        const std::string cls = demangled(typeid(*p).name());
        const std::string header = headerOf(cls);
        EXPECT_FALSE(header.empty()) << name << ": no header under ompl_planners/ defines " << cls;
        const std::string row = "| `" + name + "` | `" + cls + "` | `" + header + "` |";
        table += row + "\n";
        if (doc.str().find(row + "\n") == std::string::npos)
            missing += "  " + row + "\n";
    }
    EXPECT_TRUE(missing.empty()) << "docs/planner_classes.md lacks these rows:\n"
                                 << missing << "the whole table:\n"
                                 << table;
}

// The shared parameters (seed, max_iterations, population_size) have one declaration and one set of limits in
// PlannerBase: every registered mhplan planner declaring one of them advertises the same range, accepts its
// ends and refuses the values just outside, with a message naming the parameter and the accepted range.
TEST(Registry, SharedParametersHaveOneSetOfLimits)
{
    const auto si = unitSquare();
    const PlannerRegistry &reg = builtinPlanners();
    const ParamRange shared[] = {SharedParameterRanges::seed, SharedParameterRanges::maxIterations,
                                 SharedParameterRanges::populationSize};
    std::map<std::string, int> declaring;
    for (const auto &name : reg.names())
    {
        const ob::PlannerPtr planner = reg.create(name, si);
        auto *base = dynamic_cast<PlannerBase *>(planner.get());
        if (base == nullptr)
            continue; // OMPL's own planners
        for (const ParamRange &range : shared)
        {
            if (!planner->params().hasParam(range.name))
                continue;
            ++declaring[range.name];
            const std::string what = std::string(range.name) + " of " + name;
            EXPECT_EQ(planner->params()[range.name].getRangeSuggestion(), rangeSuggestion(range)) << what;
            const auto text = [](double v) { return formatParameter(v); };
            const std::string accepted = "[" + text(range.lo) + ", " + text(range.hi) + "]";
            for (const double v : {range.lo, range.hi})
                EXPECT_EQ(errorOf(
                              [&] {
                                  applyPlannerParameters(*planner, {{range.name, text(v)}});
                              }),
                          "")
                    << what << " = " << v;
            for (const double v : {range.lo - 1, range.hi + 1})
            {
                const std::string msg = errorOf(
                    [&] {
                        applyPlannerParameters(*planner, {{range.name, text(v)}});
                    });
                EXPECT_NE(msg.find("parameter '" + std::string(range.name) + "'"), std::string::npos) << msg;
                EXPECT_NE(msg.find(accepted), std::string::npos) << what << ": " << msg;
            }
            // The setters check too (a program may call them without the registry).
            std::string msg;
            try
            {
                if (range.name == std::string("seed"))
                    base->setSeed(static_cast<unsigned long>(range.hi) + 1);
                else if (range.name == std::string("max_iterations"))
                    base->setMaxIterations(static_cast<unsigned int>(range.hi) + 1);
                else
                    base->setPopulationSize(1);
            }
            catch (const std::invalid_argument &e)
            {
                msg = e.what();
            }
            EXPECT_NE(msg.find("parameter '" + std::string(range.name) + "' must be in " + accepted),
                      std::string::npos)
                << what << ": " << msg;
        }
    }
    // The families that have them: every population, memetic, pagmo, field and lattice planner.
    EXPECT_GE(declaring["seed"], 20);
    EXPECT_GE(declaring["max_iterations"], 22);
    EXPECT_GE(declaring["population_size"], 20);
}

// Every ranged parameter of every registered mhplan planner (pagmo's included) refuses the values just
// outside its range in its own setter, with the one message of docs/conventions.md ("Parameters"): "parameter
// 'name' must be in [lo, hi]; got value", lo and hi as its range suggestion prints them. The setter is
// reached through the parameter itself (applyPlannerParameters checks the range before it), whose OMPL
// wrapper reports the setter's std::invalid_argument as a warning. With MHPLAN_REFUSALS=FILE every message is
// written to FILE (one line each: planner, parameter, message), to compare two builds.
namespace
{
    /** The text of the last OMPL warning. */
    class LastWarning : public ompl::msg::OutputHandler
    {
      public:
        void log(const std::string &text, ompl::msg::LogLevel level, const char *, int) override
        {
            if (level == ompl::msg::LOG_WARN)
                text_ = text;
        }
        std::string take() { return std::exchange(text_, std::string()); }

      private:
        std::string text_;
    };
} // namespace

TEST(Parameters, EverySetterRefusesOutsideItsRangeWithOneMessage)
{
    const auto si = unitSquare();
    std::ostringstream all;
    int refusals = 0;
    LastWarning warnings;
    const ompl::msg::LogLevel level = ompl::msg::getLogLevel();
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ompl::msg::useOutputHandler(&warnings);
    for (const std::string &name : builtinPlanners().names())
    {
        if (builtinPlanners().get(name).origin == "ompl")
            continue;
        const ob::PlannerPtr planner = builtinPlanners().create(name, si);
        std::vector<std::string> params;
        planner->params().getParamNames(params);
        for (const std::string &param : params)
        {
            ob::GenericParam &p = planner->params()[param];
            const std::string range = p.getRangeSuggestion();
            const auto first = range.find(':'), last = range.rfind(':');
            if (dynamic_cast<const ParameterDescription *>(&p) == nullptr || first == std::string::npos ||
                first == last)
                continue;
            const std::string loText = range.substr(0, first), hiText = range.substr(last + 1);
            const double lo = std::stod(loText), hi = std::stod(hiText);
            const bool real = dynamic_cast<const ob::SpecificParam<std::string> *>(&p) != nullptr;
            std::vector<double> outside{hi + 1};
            if (real || lo >= 1)
                outside.push_back(lo - 1);
            for (const double v : outside)
            {
                std::ostringstream text;
                text << std::setprecision(real ? 17 : 12) << v;
                std::ostringstream got;
                got << std::setprecision(12) << v;
                const std::string expected =
                    "parameter '" + param + "' must be in [" + loText + ", " + hiText + "]; got " + got.str();
                warnings.take();
                const bool accepted = p.setValue(text.str());
                std::string msg = warnings.take();
                const std::string prefix = "Invalid value format specified for parameter '" + param + "': ";
                if (msg.compare(0, prefix.size(), prefix) == 0)
                    msg = msg.substr(prefix.size());
                if (accepted)
                    msg = "(accepted)";
                EXPECT_EQ(msg, expected) << name << "." << param << " = " << text.str();
                all << name << " " << param << " " << msg << "\n";
                ++refusals;
            }
        }
    }
    ompl::msg::restorePreviousOutputHandler();
    ompl::msg::setLogLevel(level);
    EXPECT_GE(refusals, 1000);
    if (const char *file = std::getenv("MHPLAN_REFUSALS"))
        std::ofstream(file) << all.str();
}

// SPDX-License-Identifier: BSD-3-Clause
/* mhplan tests: controllers declare their parameters (name, default, range, description) like planners;
   every declared default and range round-trips through setParameter, bad values are refused naming the
   parameter and its range, and the listing shows every parameter. */
#include "src/sim/Controllers.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace mhplan;

namespace
{
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

    /** \brief lo and hi of an OMPL range suggestion "lo:hi" or "lo:step:hi". */
    std::pair<std::string, std::string> bounds(const std::string &range)
    {
        const auto first = range.find(':'), last = range.rfind(':');
        return {range.substr(0, first), range.substr(last + 1)};
    }
} // namespace

TEST(ControllerParameterDeclarations, EveryParameterDeclaredRoundTripsAndIsRefusedOutOfRange)
{
    for (const std::string name : {"dapf", "aapf", "bfo", "atbfo", "plan:ThetaStar"})
    {
        const std::vector<ControllerParameterInfo> infos = controllerParameters(name);
        ControllerPtr c = makeController(name);
        const std::map<std::string, std::string> values = c->parameters();
        ASSERT_FALSE(infos.empty()) << name;
        // The declarations are exactly the parameters the controller reports, with its defaults.
        std::size_t declared = 0;
        for (const ControllerParameterInfo &p : infos)
        {
            SCOPED_TRACE(name + " " + p.name);
            ASSERT_EQ(values.count(p.name), 1u);
            EXPECT_EQ(values.at(p.name), p.defaultValue);
            EXPECT_FALSE(p.description.empty());
            ++declared;
            const auto [lo, hi] = bounds(p.range);
            const bool integer = p.range.find(":1:") != std::string::npos;
            // Both ends of the range are accepted and read back as given.
            for (const std::string &v : {lo, hi})
            {
                c->setParameter(p.name, v);
                EXPECT_EQ(c->parameters().at(p.name), v);
            }
            // Just outside either end: refused, naming the parameter and the range.
            const double outside[2] = {
                std::stod(lo) - (integer ? 1.0 : 1e-3 + std::abs(std::stod(lo)) * 1e-3),
                std::stod(hi) + (integer ? 1.0 : 1e-3 + std::abs(std::stod(hi)) * 1e-3)};
            for (double v : outside)
            {
                std::ostringstream text;
                text.precision(17);
                text << v;
                const std::string msg = errorOf([&] { c->setParameter(p.name, text.str()); });
                EXPECT_NE(msg.find("'" + p.name + "'"), std::string::npos) << msg;
                EXPECT_NE(msg.find("[" + lo + ", " + hi + "]"), std::string::npos) << msg;
            }
            EXPECT_NE(errorOf([&] { c->setParameter(p.name, "x1"); }), "");
            c->setParameter(p.name, p.defaultValue);
            EXPECT_EQ(c->parameters().at(p.name), p.defaultValue);
        }
        // plan:<P> also reports the planner.<name> values it was given, none here.
        EXPECT_EQ(declared, values.size()) << name;
    }
    EXPECT_THROW(controllerParameters("nope"), InputError);
}

TEST(ControllerParameterDeclarations, ListingShowsEveryControllerAndParameter)
{
    std::ostringstream out;
    printControllers(out);
    const std::string text = out.str();
    for (const std::string name : {"dapf", "aapf", "bfo", "atbfo", "plan:<PLANNER>"})
        EXPECT_NE(text.find(name), std::string::npos) << name;
    for (const ControllerParameterInfo &p : controllerParameters("atbfo"))
        EXPECT_NE(text.find(p.name), std::string::npos) << p.name;
    EXPECT_NE(text.find("range 2:1:100000"), std::string::npos) << text; // S, an integer
    EXPECT_NE(text.find("range 0.01:100"), std::string::npos) << text;   // rho
    std::ostringstream one;
    printControllers(one, {"dapf"});
    EXPECT_EQ(one.str().find("aapf"), std::string::npos);
    EXPECT_NE(one.str().find("C_a"), std::string::npos);
}

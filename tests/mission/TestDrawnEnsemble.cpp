// An analytic flow's ensemble drawn from one set of parameters (`current: {type, parameters, members, spread,
// seed}`): the draw's closed form, its bounds and seed, the expansion equal to the same ensemble listed, the
// summary and report, and every refusal naming file, line and field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/mission/EnsembleDraw.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/Report.h"
#include "ompl_glider/output/SummaryJson.h"

using namespace ompl_glider;

namespace
{
const std::string kHead = "name: drawn\nregion: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\nstart: {x: 1, y: -3}\n"
                          "goal: {x: 8, y: 3}\n";
// the jet of the examples (epsilon not given: its default is drawn about)
const std::string kJet = "current: {type: meandering_jet, parameters: {B0: 1.2, k: 0.84, c: 0.12}, members: 24, "
                         "spread: {B0: 0.25, k: 0.25, c: 0.25, epsilon: 0.1}, seed: 7}\n";

std::string messageOf(const std::string &yaml)
{
    try
    {
        parseMission(yaml, "m.yaml");
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

double defaultOf(const std::string &kind, const std::string &name)
{
    for (const auto &[key, value] : findCurrentFieldKind(kind)->parameters)
        if (key == name)
            return value;
    throw std::runtime_error("no parameter " + name);
}

std::string exact(double v)
{
    char s[40];
    std::snprintf(s, sizeof s, "%.17g", v);
    return s;
}
} // namespace

TEST(DrawnEnsemble, ControlRunThenDrawsInTheirBoundsFromTheSeed)
{
    const MissionSpec m = parseMission(kHead + kJet, "m.yaml");
    const CurrentSpec &c = m.current;
    ASSERT_EQ(c.members.size(), 24u);
    ASSERT_TRUE(c.drawn.has_value());
    EXPECT_EQ(c.drawn->seed, 7u);
    const double eps0 = defaultOf("meandering_jet", "epsilon");
    // member 0 is the control run: the parameters as given, the spread one not given at its default
    const std::map<std::string, double> control{{"B0", 1.2}, {"k", 0.84}, {"c", 0.12}, {"epsilon", eps0}};
    EXPECT_EQ(c.members[0].parameters, control);
    EXPECT_EQ(c.parameters, control); // the current's own spec is member 0, as for a listed ensemble
    // the closed form of member 1: mt19937(7)'s outputs in the order of the names (B0, c, epsilon, k)
    std::mt19937 rng(7);
    const auto u = [&rng] { return -1.0 + 2.0 * (static_cast<double>(rng()) + 0.5) / 4294967296.0; };
    const double uB0 = u(), uc = u(), ueps = u(), uk = u();
    EXPECT_EQ(c.members[1].parameters.at("B0"), 1.2 * (1.0 + 0.25 * uB0));
    EXPECT_EQ(c.members[1].parameters.at("c"), 0.12 * (1.0 + 0.25 * uc));
    EXPECT_EQ(c.members[1].parameters.at("epsilon"), eps0 * (1.0 + 0.1 * ueps));
    EXPECT_EQ(c.members[1].parameters.at("k"), 0.84 * (1.0 + 0.25 * uk));
    std::set<double> distinct;
    for (std::size_t i = 1; i < c.members.size(); ++i)
    {
        const auto &p = c.members[i].parameters;
        ASSERT_EQ(p.size(), 4u) << "member " << i; // no parameter without a spread added (omega, theta keep theirs)
        for (const auto &[name, value] : control)
        {
            const double s = c.drawn->spread.at(name);
            EXPECT_LT(std::abs(p.at(name) / value - 1.0), s + 1e-15) << "member " << i << " " << name;
        }
        distinct.insert(p.at("B0"));
    }
    EXPECT_EQ(distinct.size(), 23u); // draws, not copies
    // the same seed draws the same members; another seed others
    const MissionSpec same = parseMission(kHead + kJet, "m.yaml");
    for (std::size_t i = 0; i < 24; ++i)
        EXPECT_EQ(same.current.members[i].parameters, c.members[i].parameters) << i;
    std::string other = kHead + kJet;
    other.replace(other.find("seed: 7"), 7, "seed: 8");
    const MissionSpec eight = parseMission(other, "m.yaml");
    EXPECT_EQ(eight.current.members[0].parameters, control);
    for (std::size_t i = 1; i < 24; ++i)
        EXPECT_NE(eight.current.members[i].parameters.at("B0"), c.members[i].parameters.at("B0")) << i;
    // the seed defaults to 1; a spread of 0 keeps the value
    std::string one = kHead + kJet;
    one.replace(one.find(", seed: 7"), 9, "");
    one.replace(one.find("epsilon: 0.1"), 12, "epsilon: 0");
    const MissionSpec s1 = parseMission(one, "m.yaml");
    EXPECT_EQ(s1.current.drawn->seed, 1u);
    std::mt19937 rng1(1);
    EXPECT_EQ(s1.current.members[1].parameters.at("B0"),
              1.2 * (1.0 + 0.25 * (-1.0 + 2.0 * (static_cast<double>(rng1()) + 0.5) / 4294967296.0)));
    for (const CurrentSpec &member : s1.current.members)
        EXPECT_EQ(member.parameters.at("epsilon"), eps0);
}

TEST(DrawnEnsemble, PlansAsTheSameEnsembleListed)
{
    const std::string tail = "vehicle: {speed: 1.0}\nplanner: {name: zastartve, grid_size: 1.0, sectors: 1, "
                             "global_check: false, objective: worst}\n";
    const std::string drawn = kHead +
                              "current: {type: meandering_jet, parameters: {B0: 1.2, k: 0.84, c: 0.12}, members: 3, "
                              "spread: {B0: 0.1, k: 0.1, c: 0.1}, seed: 7}\n" +
                              tail;
    const MissionSpec d = parseMission(drawn, "m.yaml");
    ASSERT_EQ(d.current.members.size(), 3u);
    std::string list = "current:\n  ensemble:\n";
    for (const CurrentSpec &c : d.current.members)
    {
        list += "    - {type: meandering_jet, parameters: {";
        bool first = true;
        for (const auto &[name, value] : c.parameters)
        {
            list += (first ? "" : ", ") + name + ": " + exact(value);
            first = false;
        }
        list += "}}\n";
    }
    const MissionSpec l = parseMission(kHead + list + tail, "m.yaml");
    ASSERT_EQ(l.current.members.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(l.current.members[i].parameters, d.current.members[i].parameters) << i;
    EXPECT_NE(d.current.members[1].parameters, d.current.members[0].parameters);
    const MissionProblem pd(d), pl(l);
    const PlannedPath a = planRoute(pd, 0.0), b = planRoute(pl, 0.0);
    ASSERT_TRUE(a.solved) << a.reason;
    ASSERT_TRUE(b.solved) << b.reason;
    EXPECT_EQ(a.path.back().t, b.path.back().t); // to the bit
    ASSERT_TRUE(a.ensemble && b.ensemble);
    EXPECT_EQ(a.ensemble->memberTravelTimes, b.ensemble->memberTravelTimes);
    EXPECT_EQ(a.ensemble->chosen, b.ensemble->chosen);
    // the members differ: the plan's arrival is not the same in each (the draw reached the planner)
    EXPECT_NE(a.ensemble->memberTravelTimes[0], a.ensemble->memberTravelTimes[1]);
}

TEST(DrawnEnsemble, SummaryListsTheMembersAndTheReportSaysHowTheyWereDrawn)
{
    const std::string mission = kHead +
                                "current: {type: uniform, parameters: {u: 0.1}, members: 4, spread: {u: 0.5, v: 0.2}, "
                                "seed: 3}\nvehicle: {speed: 0.5}\nplanner: {name: zastartve, grid_size: 0.5, "
                                "global_check: false}\n";
    const MissionProblem problem(parseMission(mission, "m.yaml"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const nlohmann::json j = nlohmann::json::parse(summaryJson(r, problem, {}));
    const nlohmann::json &e = j.at("current_ensemble");
    EXPECT_EQ(e.at("type"), "uniform");
    EXPECT_EQ(e.at("count"), 4);
    EXPECT_EQ(e.at("drawn"), true);
    EXPECT_EQ(e.at("seed"), 3);
    EXPECT_EQ(e.at("spread").at("u").get<double>(), 0.5);
    EXPECT_EQ(e.at("spread").at("v").get<double>(), 0.2);
    ASSERT_EQ(e.at("members").size(), 4u);
    const CurrentSpec &c = problem.getSpec().current;
    for (std::size_t i = 0; i < 4; ++i)
        for (const char *name : {"u", "v"})
            EXPECT_EQ(e.at("members")[i].at(name).get<double>(), c.members[i].parameters.at(name)) << i << name;
    // v is not given: drawn about its default (0), so every member keeps 0
    EXPECT_EQ(e.at("members")[2].at("v").get<double>(), 0.0);
    std::ostringstream report;
    printReport(report, r);
    EXPECT_NE(report.str().find("Current:            uniform ensemble of 4 members (control + 3 drawn, spread u 50 %, "
                                "v 20 %, seed 3)"),
              std::string::npos)
        << report.str();
    // a single source has no ensemble in the summary, nor the line in the report
    const MissionProblem single(parseMission(kHead + "current: {type: uniform, parameters: {u: 0.1}}\n", "m.yaml"));
    const MissionResult s = runMission(single);
    EXPECT_TRUE(nlohmann::json::parse(summaryJson(s, single, {})).at("current_ensemble").is_null());
}

TEST(DrawnEnsemble, RefusalsNameFileLineAndField)
{
    struct Case
    {
        std::string current, phrase;
    };
    const std::string u = "current: {type: uniform, parameters: {u: 0.1}, ";
    const Case cases[] = {
        {u + "members: 1, spread: {u: 0.1}}", "m.yaml:5: field 'current.members': expected an integer in 2..1000"},
        {u + "members: 1001, spread: {u: 0.1}}", "m.yaml:5: field 'current.members'"},
        {u + "members: 2.5, spread: {u: 0.1}}", "m.yaml:5: field 'current.members'"},
        {u + "members: many, spread: {u: 0.1}}", "m.yaml:5: field 'current.members'"},
        {u + "spread: {u: 0.1}}", "m.yaml:5: field 'current.spread': only with members"},
        {u + "seed: 3}", "m.yaml:5: field 'current.seed': only with members"},
        {"current: {type: netcdf, file: x.nc, members: 3, spread: {u: 0.1}}",
         "m.yaml:5: field 'current.spread': an ensemble is drawn from the parameters of an analytic flow"},
        {"current: {type: netcdf, file: x.nc, members: 3}", "m.yaml:5: field 'current.members'"},
        {u + "members: 3, spread: {B0: 0.1}}", "m.yaml:5: unknown field 'current.spread.B0'"},
        {u + "members: 3, spread: {u: .nan}}", "m.yaml:5: field 'current.spread.u'"},
        {u + "members: 3, spread: {u: .inf}}", "m.yaml:5: field 'current.spread.u'"},
        {u + "members: 3, spread: {u: 1}}", "m.yaml:5: field 'current.spread.u': expected a relative spread in [0, 1)"},
        {u + "members: 3, spread: {u: -0.1}}", "m.yaml:5: field 'current.spread.u'"},
        {u + "members: 3, spread: 0.1}", "m.yaml:5: field 'current.spread'"},
        {u + "members: 3, spread: {}}", "m.yaml:5: field 'current.spread': empty"},
        {u + "members: 3}", "m.yaml:5: field 'current.spread': missing"},
        {u + "members: 3, spread: {u: 0.1}, seed: -1}", "m.yaml:5: field 'current.seed'"},
        {u + "members: 3, spread: {u: 0.1}, seed: 1.5}", "m.yaml:5: field 'current.seed'"},
        {u + "members: 3, spread: {u: 0.1}, seed: 4294967296}", "m.yaml:5: field 'current.seed'"},
        {"current: {members: 3, spread: {u: 0.1}, ensemble: [{type: uniform}, {type: uniform}]}",
         "m.yaml:5: field 'current.members': an ensemble is either listed"},
        {"current: {spread: {u: 0.1}, ensemble: [{type: uniform}, {type: uniform}]}",
         "m.yaml:5: field 'current.spread': an ensemble is either listed"},
        {"current: {type: vortex, members: 3, spread: {u: 0.1}}", "m.yaml:5: field 'current.type'"},
        {u + "members: 3, spread: {u: 0.1}, spin: 2}", "m.yaml:5: unknown field 'current.spin'"},
        // the line of the field in a block
        {"current:\n  type: meandering_jet\n  members: 3\n  spread: {k: 2}", "m.yaml:8: field 'current.spread.k'"},
    };
    for (const Case &c : cases)
    {
        const std::string msg = messageOf(kHead + c.current + "\n");
        EXPECT_NE(msg.find(c.phrase), std::string::npos) << c.current << "\n-> " << msg;
    }
    // the library's draw refuses alike
    const auto draw = [](const std::string &name, double s) {
        CurrentSpec::EnsembleDraw d;
        d.spread[name] = s;
        return d;
    };
    CurrentSpec jet, nc;
    nc.type = "netcdf";
    EXPECT_EQ(drawEnsembleMembers(jet, 3, draw("B0", 0.1)).size(), 3u);
    EXPECT_THROW(drawEnsembleMembers(jet, 1, draw("B0", 0.1)), Error);
    EXPECT_THROW(drawEnsembleMembers(jet, 3, draw("u", 0.1)), Error);
    EXPECT_THROW(drawEnsembleMembers(jet, 3, draw("B0", 1.0)), Error);
    EXPECT_THROW(drawEnsembleMembers(nc, 3, draw("u", 0.1)), Error);
}

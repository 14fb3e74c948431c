// Missions of several legs: the chain of legs is the mission and flies as planned, the free order is the best of all
// orders, stays hold in weak currents and are refused in strong ones, and the loader refuses bad via points.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/execution/Reflight.h"
#include "ompl_glider/mission/Fleet.h"
#include "ompl_glider/mission/MissionLegs.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

namespace
{
std::string point(double x, double y)
{
    return "{x: " + std::to_string(x) + ", y: " + std::to_string(y) + "}";
}

/// A mission on @p current over @p region from @p s to @p g with the via points @p via (x, y).
MissionSpec mission(const std::string &current, const std::string &region, Point2 s, Point2 g,
                    const std::vector<Point2> &via, const std::string &extra = "")
{
    std::string y = "current: " + current + "\nregion: " + region + "\nstart: " + point(s.x, s.y) +
                    "\ngoal: " + point(g.x, g.y) + "\nvehicle: {speed: 0.5}\n";
    if (!via.empty())
    {
        y += "waypoints:\n";
        for (std::size_t i = 0; i < via.size(); ++i)
            y += "  - {name: S" + std::to_string(i + 1) + ", x: " + std::to_string(via[i].x) +
                 ", y: " + std::to_string(via[i].y) + "}\n";
    }
    return parseMission(y + extra);
}

const char *kJetCurrent = "{type: meandering_jet}";

/// @p run must throw an Error whose message holds @p what (@p input names the case).
void expectRefused(const std::function<void()> &run, const std::string &what, const std::string &input)
{
    try
    {
        run();
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        return;
    }
    ADD_FAILURE() << "accepted: " << input;
}
const char *kJetRegion = "{x_min: 0, x_max: 10, y_min: -4, y_max: 4}";
} // namespace

// The mission's time is the chain of its legs, each planned as a mission of its own from the previous leg's arrival,
// and its whole route re-flown by the accurate integrator arrives when the mission says.
TEST(MissionLegs, ChainOfLegsIsTheMissionAndFliesAsPlanned)
{
    const std::vector<Point2> via{{3.0, -2.5}, {5.5, -1.5}};
    const std::string grid = "planner: {grid_size: 0.4}\n";
    const MissionSpec m = mission(kJetCurrent, kJetRegion, {1, -3}, {8, 3}, via, grid);
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_EQ(r.legs.size(), 3u);
    std::vector<Point2> stops{{1, -3}, via[0], via[1], {8, 3}};
    double t = 0.0;
    for (std::size_t k = 0; k < 3; ++k)
    {
        MissionSpec leg = mission(kJetCurrent, kJetRegion, stops[k], stops[k + 1], {}, grid);
        leg.departure.time = t;
        const MissionResult one = runMission(MissionProblem(leg));
        ASSERT_TRUE(one.plan.solved) << "leg " << k + 1 << ": " << one.plan.reason;
        EXPECT_NEAR(one.plan.travelTime, r.legs[k].plan.travelTime, 1e-9) << "leg " << k + 1;
        EXPECT_DOUBLE_EQ(r.legs[k].departure(), t);
        t = one.plan.path.back().t;
    }
    EXPECT_NEAR(r.plan.path.back().t, t, 1e-9);
    EXPECT_NEAR(r.plan.travelTime, t, 1e-9);
    // the legs follow each other on one clock and the via points are on the route
    for (std::size_t k = 0; k + 1 < r.legs.size(); ++k)
    {
        EXPECT_DOUBLE_EQ(r.legs[k + 1].departure(), r.legs[k].arrival() + r.legs[k].stay);
        const TimedPoint &end = r.plan.path[r.legs[k].lastPoint];
        EXPECT_LT(std::hypot(end.x - via[k].x, end.y - via[k].y), 1e-6);
    }
    // the whole route flown by the accurate Dormand-Prince re-flight (straight legs, as planned)
    for (const PlannedLeg &l : r.legs)
        ASSERT_FALSE(l.plan.headingRoute()) << "this case is planned as straight legs";
    ReflightSettings s;
    s.speed = 0.5;
    s.keepSlowLegs = true;
    const PathReflight f = reflyPath(r.plan.path, *problem.getField(), problem.getEnvironment().get(), s);
    ASSERT_TRUE(f.feasible) << f.why;
    EXPECT_LT(std::abs(relativeDifference(r.plan.travelTime, f.arrivalTime - r.plan.departure)), 1e-6);
    // and waypoints carry their leg
    EXPECT_EQ(r.waypoints.front().missionLeg, 1);
    EXPECT_EQ(r.waypoints.back().missionLeg, 3);
}

namespace
{
/// Every order of @p m's via points planned by the same pipeline (given order each): the fastest time.
double bestOfAllOrders(const MissionSpec &m, std::size_t &orders)
{
    std::vector<std::size_t> perm(m.waypoints.size());
    std::iota(perm.begin(), perm.end(), std::size_t{0});
    double best = std::numeric_limits<double>::infinity();
    orders = 0;
    do
    {
        MissionSpec p = m;
        p.order = VisitOrder::Given;
        for (std::size_t i = 0; i < perm.size(); ++i)
            p.waypoints[i] = m.waypoints[perm[i]];
        const MissionPlan plan = planMission(MissionProblem(p), 0.0);
        ++orders;
        if (plan.plan.solved)
            best = std::min(best, plan.plan.travelTime);
    } while (std::next_permutation(perm.begin(), perm.end()));
    return best;
}

void checkFreeOrder(const std::string &current, const std::string &region, Box box, std::size_t n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(box.xMin + 0.1 * (box.xMax - box.xMin),
                                              box.xMax - 0.1 * (box.xMax - box.xMin));
    std::uniform_real_distribution<double> uy(box.yMin + 0.1 * (box.yMax - box.yMin),
                                              box.yMax - 0.1 * (box.yMax - box.yMin));
    std::vector<Point2> via;
    for (std::size_t i = 0; i < n; ++i)
        via.push_back({ux(rng), uy(rng)});
    // the property holds for any one pipeline: here the lattice search alone, the cheapest
    MissionSpec m = mission(current, region, {ux(rng), uy(rng)}, {ux(rng), uy(rng)}, via,
                            "planner: {grid_size: " + std::to_string(0.08 * (box.xMax - box.xMin)) +
                                ", global_check: false, refinement: false, smoothing: false}\n");
    m.order = VisitOrder::Free;
    const MissionPlan free = planMission(MissionProblem(m), 0.0);
    std::size_t orders = 0;
    const double best = bestOfAllOrders(m, orders);
    ASSERT_TRUE(std::isfinite(best)) << "no order has a route (seed " << seed << ")";
    ASSERT_TRUE(free.plan.solved) << free.plan.reason;
    ASSERT_TRUE(free.orderSearch.has_value());
    EXPECT_NEAR(free.plan.travelTime, best, 1e-9 * best) << "seed " << seed;
    EXPECT_EQ(free.orderSearch->ordersTotal, orders);
    EXPECT_LE(free.orderSearch->ordersEvaluated, orders);
    EXPECT_GE(free.orderSearch->gain, 0.0);
    EXPECT_NEAR(free.orderSearch->chosenTime, free.plan.travelTime, 1e-12);
    // the chosen order visits every via point once
    std::vector<std::size_t> sorted = free.order;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < n; ++i)
        EXPECT_EQ(sorted[i], i);
}
} // namespace

// Branch and bound over orders returns the fastest of all n! orders, each planned by the same pipeline.
TEST(MissionLegsFreeOrder, BestOfAllOrdersOnTheJetAndTheDoubleGyre)
{
    checkFreeOrder(kJetCurrent, kJetRegion, Box{0, 10, -4, 4}, 4, 7);
    checkFreeOrder("{type: double_gyre}", "{x_min: 0, x_max: 2, y_min: 0, y_max: 1}", Box{0, 2, 0, 1}, 4, 11);
}

// The bound never exceeds a planned time: it is admissible on every prefix the search may drop.
TEST(MissionLegsFreeOrder, BoundIsBelowThePlannedTime)
{
    MissionSpec m =
        mission(kJetCurrent, kJetRegion, {1, -3}, {8, 3}, {{3, 2}, {6, -2}, {5, 0.5}}, "planner: {grid_size: 0.4}\n");
    const MissionProblem problem(m);
    const MissionPlan plan = planMission(problem, 0.0);
    ASSERT_TRUE(plan.plan.solved);
    Region box = problem.getBox();
    const double c = problem.getField()->maxSpeed(box);
    EXPECT_LE(remainingTimeBound(problem, problem.getStart(), 0.0, {0, 1, 2}, 0.5, c), plan.plan.travelTime);
    EXPECT_LE(remainingTimeBound(problem, problem.getViaPoints()[0], plan.legs[0].arrival(), {1, 2}, 0.5, c),
              plan.plan.path.back().t);
    // a closed form: no current, no via points left: the straight distance at V
    MissionSpec still = mission("{type: uniform, parameters: {u: 0, v: 0}}",
                                "{x_min: 0, x_max: 10, y_min: -4, y_max: 4}", {1, 0}, {9, 0}, {{5, 3}});
    const MissionProblem p2(still);
    EXPECT_NEAR(remainingTimeBound(p2, {1, 0}, 0.0, {0}, 0.5, 0.0), (5.0 + 5.0) / 0.5, 1e-12); // two 3-4-5 legs
}

// A stay in a weak current holds in place for its duration; the next leg leaves when it ends.
TEST(MissionLegs, StayHoldsInPlaceInAWeakCurrent)
{
    MissionSpec m = parseMission("current: {type: uniform, parameters: {u: 0.1, v: 0}}\n"
                                 "region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                                 "start: {x: 1, y: 0}\ngoal: {x: 9, y: 1}\nvehicle: {speed: 0.5}\n"
                                 "waypoints:\n  - {name: M, x: 5, y: -2, stay: 3}\n");
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_EQ(r.legs.size(), 2u);
    const TimedPoint a = r.plan.path[r.legs[0].lastPoint], b = r.plan.path[r.legs[1].firstPoint];
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_NEAR(b.t - a.t, 3.0, 1e-12);
    EXPECT_NEAR(r.plan.holdTime, 3.0, 1e-9);
    // closed form: a straight leg in a uniform current, |d| / (c.p + sqrt(V^2 - |c x p|^2)), twice, plus the stay
    auto leg = [](Point2 p, Point2 q) {
        const double d = std::hypot(q.x - p.x, q.y - p.y), ux = (q.x - p.x) / d, uy = (q.y - p.y) / d;
        const double along = 0.1 * ux, cross = 0.1 * uy;
        return d / (along + std::sqrt(0.25 - cross * cross));
    };
    EXPECT_NEAR(r.plan.travelTime, leg({1, 0}, {5, -2}) + 3.0 + leg({5, -2}, {9, 1}), 1e-6);
    ReflightSettings s;
    s.speed = 0.5;
    s.keepSlowLegs = true;
    const PathReflight f = reflyPath(r.plan.path, *problem.getField(), nullptr, s);
    ASSERT_TRUE(f.feasible) << f.why;
    EXPECT_NEAR(f.arrivalTime, r.plan.path.back().t, 1e-6);
}

// Where the current is faster than the glider, no stay is invented: the reason names the leg and the current.
TEST(MissionLegs, StayInACurrentFasterThanTheGliderIsRefused)
{
    MissionSpec m = parseMission("current: {type: uniform, parameters: {u: 0.8, v: 0}}\n"
                                 "region: {x_min: 0, x_max: 20, y_min: -4, y_max: 4}\n"
                                 "start: {x: 1, y: 0}\ngoal: {x: 15, y: 0}\nvehicle: {speed: 0.5}\n"
                                 "waypoints:\n  - {name: M, x: 6, y: 0, stay: 2}\n");
    const MissionResult r = runMission(MissionProblem(m));
    EXPECT_FALSE(r.plan.solved);
    EXPECT_EQ(r.plan.status, PlanStatus::NoPath);
    EXPECT_NE(r.plan.reason.find("leg 1, start to M"), std::string::npos) << r.plan.reason;
    EXPECT_NE(r.plan.reason.find("cannot hold position"), std::string::npos) << r.plan.reason;
    EXPECT_FALSE(r.plan.badInput.any());
    EXPECT_TRUE(r.waypoints.empty()); // never a partial plan presented as whole
    // without the stay the same mission plans
    m.waypoints[0].stay = 0.0;
    EXPECT_TRUE(runMission(MissionProblem(m)).plan.solved);
}

// Bad via points are refused naming the field and line.
TEST(MissionLegs, BadViaPointsNameTheFieldAndLine)
{
    const std::string head = "current: {type: meandering_jet}\nregion: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                             "start: {x: 1, y: -3}\ngoal: {x: 8, y: 3}\n";
    const auto refused = [&](const std::string &tail, const std::string &what) {
        expectRefused([&] { runMission(MissionProblem(parseMission(head + tail, "m.yaml"))); }, what, tail);
    };
    refused("waypoints:\n  - {x: 3, y: 0, radius: 0}\n", "m.yaml:6: field 'waypoints[0].radius'");
    refused("waypoints:\n  - {x: 3, y: 0, radius: -5}\n", "waypoints[0].radius");
    refused("waypoints:\n  - {name: A, x: 3, y: 0}\n  - {name: A, x: 4, y: 0}\n",
            "m.yaml:7: field 'waypoints[1].name'");
    refused("waypoints:\n  - {name: start, x: 3, y: 0}\n", "waypoints[0].name");
    refused("waypoints:\n  - {name: 'A B', x: 3, y: 0}\n", "not a plain name");
    refused("waypoints:\n  - {x: 30, y: 0}\n", "m.yaml:6: field 'waypoints[0]': lies outside the region");
    refused("waypoints:\n  - {x: 3, y: 0, arrive: {begin: 5, end: 2}}\n", "waypoints[0].arrive.end");
    refused("waypoints:\n  - {x: 3, y: 0, arrive: {end: 0.1}}\n", "before the glider can get there");
    refused("waypoints:\n  - {x: 3, y: 0}\norder: sideways\n", "field 'order'");
    std::string nine = "waypoints:\n";
    for (int i = 0; i < 9; ++i)
        nine += "  - {x: " + std::to_string(1 + i) + ", y: 1}\n";
    refused(nine + "order: free\n", "at most 8");
    refused("waypoints:\n  - {x: 3, y: 0}\nforbidden:\n  obstacles:\n    - {name: rock, points: [[2, -1], [4, -1], "
            "[4, 1], [2, 1]]}\n",
            "(via point 'WP1'): the point is");
}

// A via point on a forecast's land is refused naming it and the nearest water, as a start or goal is; outside the
// forecast it is refused too.
TEST(MissionLegs, ViaPointOnLandOrOutsideTheForecastIsRefused)
{
    const std::string nc = std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/labrador_forecast.nc";
    const auto refused = [&](const std::string &via, const std::string &what) {
        expectRefused(
            [&] {
                MissionProblem(parseMission("current: {type: netcdf, file: '" + nc +
                                                "'}\nstart: {lon: -52.7, lat: 47.9}\ngoal: {lon: -51.5, lat: 48.45}\n"
                                                "waypoints:\n  - " +
                                                via + "\n",
                                            "m.yaml"));
            },
            what, via);
    };
    refused("{name: L, lon: -51.9, lat: 48.62}", "m.yaml:5: field 'waypoints[0]'");
    refused("{name: L, lon: -51.9, lat: 48.62}", "on land");
    refused("{name: F, lon: -40.0, lat: 48.2}", "m.yaml:5: field 'waypoints[0]': (");
    refused("{name: F, lon: -40.0, lat: 48.2}", "lies outside the planning region");
    refused("{name: S, lon: -52.2, lat: 48.0, stay: 10 d}", "m.yaml:5: field 'waypoints[0].stay'");
    refused("{name: S, lon: -52.2, lat: 48.0, stay: 10 d}", "longer than the whole forecast");
}

// A fleet glider with its own via points plans as the same mission planned alone.
TEST(MissionLegs, FleetGliderWithViaPointsPlansAsItsOwnMission)
{
    const MissionSpec m =
        parseMission("current: {type: meandering_jet}\nregion: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                     "vehicle: {speed: 0.5}\nplanner: {grid_size: 0.4}\noutputs: {directory: /tmp/og_fleet_legs}\n"
                     "fleet:\n"
                     "  - {name: a, start: {x: 1, y: -3}, goal: {x: 8, y: 3}, waypoints: [{name: P, x: 3, y: -2.5}]}\n"
                     "  - {name: b, start: {x: 2, y: -3}, goal: {x: 8, y: -3}}\n");
    const std::vector<FleetGlider> fleet = runFleet(m, {});
    ASSERT_EQ(fleet.size(), 2u);
    ASSERT_TRUE(fleet[0].row.solved) << fleet[0].row.reason;
    const MissionSpec alone = fleetGliderMission(m, 0);
    ASSERT_EQ(alone.waypoints.size(), 1u);
    EXPECT_EQ(alone.waypoints[0].name, "P");
    const MissionResult r = runMission(MissionProblem(alone));
    ASSERT_EQ(r.legs.size(), 2u);
    EXPECT_DOUBLE_EQ(fleet[0].row.travelTime, r.plan.travelTime);
    EXPECT_TRUE(fleetGliderMission(m, 1).waypoints.empty());
}

// A via point's window may give one end only. With only its begin, the glider does not arrive before it (it holds
// where the current lets it, here in a weak uniform current); with only its end, an arrival before it is kept. The
// same window dated against an epoch is no error. Closed forms: straight legs in a uniform current.
TEST(MissionLegs, AWindowWithOneEndOnlyIsKept)
{
    const std::string base = "current: {type: uniform, parameters: {u: 0.1, v: 0}}\n"
                             "region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                             "start: {x: 1, y: 0}\ngoal: {x: 9, y: 0}\nvehicle: {speed: 0.5}\n";
    // the straight leg to M (5, 0) takes 4 / 0.6 = 6.67: the window opens at 20
    for (const std::string &begin : {std::string("20"), std::string("'2026-06-01T20:00:00Z'")})
    {
        const std::string epoch = begin == "20" ? "" : "units: {time_s: 3600}\nepoch: '2026-06-01T00:00:00Z'\n";
        const MissionSpec m =
            parseMission(base + epoch + "waypoints:\n  - {name: M, x: 5, y: 0, arrive: {begin: " + begin + "}}\n");
        const MissionResult r = runMission(MissionProblem(m));
        ASSERT_TRUE(r.plan.solved) << begin << ": " << r.plan.reason;
        ASSERT_EQ(r.legs.size(), 2u);
        EXPECT_GE(r.legs[0].arrival(), 20.0 - 1e-9) << begin;
        EXPECT_LT(r.legs[0].arrival(), 20.0 + 1e-6) << begin; // the earliest arrival in the window
        EXPECT_NEAR(r.plan.travelTime, 20.0 + 4.0 / 0.6, 1e-6) << begin;
    }
    // an end only: the fastest arrival (6.67) is within it
    const MissionSpec e = parseMission(base + "waypoints:\n  - {name: M, x: 5, y: 0, arrive: {end: 10}}\n");
    const MissionResult r = runMission(MissionProblem(e));
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    EXPECT_NEAR(r.legs[0].arrival(), 4.0 / 0.6, 1e-6);
    // and one that closes before the glider can get there is refused naming it
    expectRefused(
        [&] {
            runMission(
                MissionProblem(parseMission(base + "waypoints:\n  - {name: M, x: 5, y: 0, arrive: {end: 3}}\n")));
        },
        "waypoints[0].arrive.end", "a window closing at 3");
}

// A via point may not be named as the goal or the start in any case: the Seaglider targets file would hold two GOAL
// targets (goto=GOAL ambiguous).
TEST(MissionLegs, ViaPointNamesAreComparedWithoutCase)
{
    for (const char *name : {"GOAL", "Goal", "START"})
        expectRefused(
            [&] {
                mission(kJetCurrent, kJetRegion, {1, -3}, {8, 3}, {},
                        "waypoints:\n  - {name: " + std::string(name) + ", x: 3, y: 2}\n");
            },
            "names the mission's", name);
    expectRefused(
        [&] {
            mission(kJetCurrent, kJetRegion, {1, -3}, {8, 3}, {},
                    "waypoints:\n  - {name: A1, x: 3, y: 2}\n  - {name: a1, x: 5, y: 0}\n");
        },
        "names another via point", "A1 and a1");
}

// The free order with stays and windows (begin only, end only, both) is still the best of all orders planned by the
// same pipeline: the bounds that prune (a window that closes before the glider can reach it, one that opens late)
// hold with them.
TEST(MissionLegsFreeOrder, BestOfAllOrdersWithStaysAndWindows)
{
    MissionSpec m = parseMission("current: {type: meandering_jet}\nregion: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                                 "start: {x: 1, y: -3}\ngoal: {x: 8, y: 3}\nvehicle: {speed: 0.5}\n"
                                 "planner: {grid_size: 0.8, global_check: false, refinement: false, smoothing: false}\n"
                                 "waypoints:\n"
                                 "  - {name: A, x: 3, y: 3, stay: 1, arrive: {end: 30}}\n"
                                 "  - {name: B, x: 6, y: -3, arrive: {begin: 12}}\n"
                                 "  - {name: D, x: 2, y: -3, stay: 0.5, arrive: {begin: 2, end: 40}}\n");
    m.order = VisitOrder::Free;
    const MissionPlan free = planMission(MissionProblem(m), 0.0);
    std::size_t orders = 0;
    const double best = bestOfAllOrders(m, orders);
    ASSERT_TRUE(std::isfinite(best)) << "no order keeps the windows";
    ASSERT_TRUE(free.plan.solved) << free.plan.reason;
    ASSERT_TRUE(free.orderSearch.has_value());
    EXPECT_TRUE(free.orderSearch->stopped.empty()) << free.orderSearch->stopped;
    EXPECT_NEAR(free.plan.travelTime, best, 1e-9 * best);
    EXPECT_LT(free.orderSearch->ordersEvaluated, orders); // the windows pruned some orders unplanned
}

// A stop request (Ctrl-C in Python, a signal on the command line) ends the free-order search at its next leg: the
// given order's plan stands, and the search says it was not finished.
TEST(MissionLegsFreeOrder, AStopRequestEndsTheSearchWithTheBestSoFar)
{
    MissionSpec m = mission(kJetCurrent, kJetRegion, {1, -3}, {8, 3}, {{3, 2}, {6, -2}, {5, 0.5}, {2, 0}},
                            "planner: {grid_size: 0.8, global_check: false, refinement: false, smoothing: false}\n");
    m.order = VisitOrder::Free;
    const MissionProblem problem(m);
    struct Clear
    {
        ~Clear() { clearStop(); }
    } clear;
    requestStop();
    const MissionPlan stopped = planMission(problem, 0.0);
    clearStop();
    ASSERT_TRUE(stopped.orderSearch.has_value());
    EXPECT_EQ(stopped.orderSearch->stopped, "a stop request");
    EXPECT_EQ(stopped.orderSearch->ordersEvaluated, 1u); // the given order only
    const MissionPlan whole = planMission(problem, 0.0);
    ASSERT_TRUE(whole.orderSearch.has_value());
    EXPECT_TRUE(whole.orderSearch->stopped.empty());
    EXPECT_GT(whole.orderSearch->ordersEvaluated, 1u);
}

// Goals in time ([ThompsonICRA] Sec. III, the earliest valid arrival): a goal window met by holding at
// the goal, by timing the arrival earlier on the path where the goal cannot be held, and a window that cannot be met.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "ompl_glider/output/SummaryJson.h"
#include "ompl_glider/routes/PathSmoother.h"

using namespace ompl_glider;
using json = nlohmann::json;

namespace
{
// uniform current 0.1 along x, V = 0.5: the goal can be held (|c| < V), earliest arrival about 8 / 0.6
const char *kUniformWindow = R"(name: uniform_window
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
vehicle: {speed: 0.5}
planner: {grid_size: 0.5, sectors: 3}
)";

// linear shear u = y, V = 0.5: the start (y = 0) lies in calm water, the goal (y = 1.2) in a current of 1.2 > V
const char *kShear = R"(name: shear_window
current: {type: linear_shear, parameters: {a: 1.0}}
region: {x_min: 0, x_max: 10, y_min: -2, y_max: 2}
start: {x: 1, y: 0}
goal: {x: 8, y: 1.2}
vehicle: {speed: 0.5}
planner: {grid_size: 0.25, sectors: 3}
)";

MissionSpec withWindow(const char *text, double begin, double end)
{
    MissionSpec m = parseMission(text, "m.yaml");
    m.goalWindow = {true, begin, end};
    return m;
}

bool samePosition(const TimedPoint &a, const TimedPoint &b)
{
    return a.x == b.x && a.y == b.y;
}

/// Every motion of the path as the motion validator judges it, and OMPL's PathGeometric::check().
void expectValidPath(const MissionProblem &problem, const PlannedPath &p)
{
    std::shared_ptr<GliderContext> ctx;
    const auto ss = makeSimpleSetup(problem.gliderProblem(p.departure, p.speed), &ctx);
    const auto si = ss->getSpaceInformation();
    const auto mv = std::dynamic_pointer_cast<TravelTimeMotionValidator>(si->getMotionValidator());
    ASSERT_TRUE(mv);
    for (std::size_t i = 1; i < p.path.size(); ++i)
    {
        const TimedPoint &a = p.path[i - 1], &b = p.path[i];
        EXPECT_EQ(mv->classify(a.x, a.y, a.t, b.x, b.y, b.t), MotionVerdict::Valid) << "leg " << i - 1;
    }
    ompl::geometric::PathGeometric path(si);
    waypointsToPath(p.path, path);
    EXPECT_TRUE(path.check());
    EXPECT_TRUE(p.pathChecked);
}
} // namespace

TEST(GoalWindow, HoldAtTheGoal)
{
    const MissionProblem free(parseMission(kUniformWindow, "m.yaml"));
    const PlannedPath early = planRoute(free, 0.0);
    ASSERT_TRUE(early.solved);
    const double earliest = early.path.back().t;
    ASSERT_LT(earliest, 15.0);

    const MissionProblem problem(withWindow(kUniformWindow, 20.0, 25.0));
    const MissionResult r = runMission(problem);
    const PlannedPath &p = r.plan;
    ASSERT_TRUE(p.solved) << p.reason;
    // the earliest valid arrival: the window's begin, the path as without the window, then a hold at the goal
    EXPECT_EQ(p.path.back().t, 20.0);
    ASSERT_EQ(p.path.size(), early.path.size() + 1);
    EXPECT_TRUE(samePosition(p.path[p.path.size() - 2], p.path.back()));
    EXPECT_DOUBLE_EQ(p.path[p.path.size() - 2].t, earliest);
    EXPECT_NEAR(p.holdTime, 20.0 - earliest, 1e-9);
    EXPECT_EQ(p.arrivalTiming, "hold at the goal");
    EXPECT_NEAR(p.travelTime, 20.0, 1e-12);
    expectValidPath(problem, p);

    // summary.json: arrival_time, hold_time, the window
    const json s = json::parse(summaryJson(r, problem));
    EXPECT_DOUBLE_EQ(s["arrival_time"].get<double>(), 20.0);
    EXPECT_NEAR(s["hold_time"].get<double>(), 20.0 - earliest, 1e-9);
    EXPECT_DOUBLE_EQ(s["goal_window"]["begin"].get<double>(), 20.0);
    EXPECT_DOUBLE_EQ(s["goal_window"]["end"].get<double>(), 25.0);
    EXPECT_EQ(s["goal_window"]["timing"], "hold at the goal");
    // the pilot's waypoints show the hold: the goal twice, at the first arrival and at the window's begin
    ASSERT_GE(r.waypoints.size(), 2u);
    EXPECT_DOUBLE_EQ(r.waypoints.back().time, 20.0);
    EXPECT_DOUBLE_EQ(r.waypoints[r.waypoints.size() - 2].time, earliest);

    // without a window: no hold, and summary.json says 0
    const MissionResult r0 = runMission(free);
    EXPECT_EQ(r0.plan.holdTime, 0.0);
    const json s0 = json::parse(summaryJson(r0, free));
    EXPECT_EQ(s0["hold_time"].get<double>(), 0.0);
    EXPECT_FALSE(s0.contains("goal_window"));
}

TEST(GoalWindow, ArrivalInsideTheWindowIsKept)
{
    const MissionProblem free(parseMission(kUniformWindow, "m.yaml"));
    const double earliest = planRoute(free, 0.0).path.back().t;
    const MissionProblem problem(withWindow(kUniformWindow, earliest - 1.0, earliest + 1.0));
    const PlannedPath p = planRoute(problem, 0.0);
    ASSERT_TRUE(p.solved);
    EXPECT_DOUBLE_EQ(p.path.back().t, earliest);
    EXPECT_EQ(p.holdTime, 0.0);
    EXPECT_TRUE(p.arrivalTiming.empty());
}

TEST(GoalWindow, TimingWhereTheGoalCannotBeHeld)
{
    const MissionProblem free(parseMission(kShear, "m.yaml"));
    const PlannedPath early = planRoute(free, 0.0);
    ASSERT_TRUE(early.solved);
    const double earliest = early.path.back().t;
    ASSERT_LT(earliest, 10.0);
    const MissionProblem problem(withWindow(kShear, 30.0, 32.0));
    // the goal lies in a current of 1.2 > V = 0.5: no hold there
    std::shared_ptr<GliderContext> ctx;
    const auto ss = makeSimpleSetup(problem.gliderProblem(0.0, 0.5), &ctx);
    const auto mv =
        std::dynamic_pointer_cast<TravelTimeMotionValidator>(ss->getSpaceInformation()->getMotionValidator());
    ASSERT_FALSE(mv->canHold(8.0, 1.2, earliest, 30.0));

    const PlannedPath p = planRoute(problem, 0.0);
    ASSERT_TRUE(p.solved) << p.reason;
    EXPECT_GE(p.path.back().t, 30.0);
    EXPECT_LE(p.path.back().t, 32.0);
    EXPECT_FALSE(samePosition(p.path[p.path.size() - 2], p.path.back())) << "held at the goal";
    EXPECT_GT(p.holdTime, 0.0);
    EXPECT_EQ(p.arrivalTiming.rfind("hold at waypoint", 0), 0u) << p.arrivalTiming;
    expectValidPath(problem, p);
    // re-fly the path: after its last hold, every leg as fast as possible lands on the planned arrival
    std::size_t lastHold = 0;
    for (std::size_t i = 1; i < p.path.size(); ++i)
        if (samePosition(p.path[i - 1], p.path[i]))
            lastHold = i;
    ASSERT_GT(lastHold, 0u);
    EXPECT_TRUE(mv->canHold(p.path[lastHold].x, p.path[lastHold].y, p.path[lastHold - 1].t, p.path[lastHold].t));
    const std::vector<TimedPoint> rest(p.path.begin() + static_cast<std::ptrdiff_t>(lastHold), p.path.end());
    const double flown = arrivalTime(*ctx, rest, p.path[lastHold].t);
    EXPECT_NEAR(flown, p.path.back().t, 1e-6);
    EXPECT_GE(flown, 30.0 - 1e-6);
    EXPECT_LE(flown, 32.0);
}

TEST(GoalWindow, WindowThatCannotBeMet)
{
    // the window closes before the earliest arrival: no path in the window, with the reason
    const MissionProblem problem(withWindow(kUniformWindow, 1.0, 2.0));
    const MissionResult r = runMission(problem);
    EXPECT_FALSE(r.plan.solved);
    EXPECT_EQ(r.plan.status, PlanStatus::NoPath);
    EXPECT_NE(r.plan.reason.find("after the end of the goal's arrival window"), std::string::npos) << r.plan.reason;
    EXPECT_FALSE(r.plan.badInput.any());
    EXPECT_TRUE(r.waypoints.empty());
}

TEST(GoalWindow, WindowOutsideTheHorizonIsBadInput)
{
    MissionSpec m = withWindow(kUniformWindow, 100.0, 200.0);
    m.planner.horizon = 30.0;
    const MissionProblem problem(m);
    EXPECT_THROW(runMission(problem), Error);
    MissionSpec before = withWindow(kUniformWindow, 1.0, 2.0);
    before.departure.time = 5.0;
    EXPECT_THROW(runMission(MissionProblem(before)), Error);
}

TEST(GoalWindow, MissionFileAndTimes)
{
    const MissionSpec m = parseMission(std::string(kUniformWindow)
                                           .replace(std::string(kUniformWindow).find("goal: {x: 9, y: 0}"), 18,
                                                    "goal: {x: 9, y: 0, window: {begin: 20, end: 25}}"),
                                       "m.yaml");
    EXPECT_TRUE(m.goalWindow.set);
    EXPECT_EQ(m.goalWindow.begin, 20.0);
    EXPECT_EQ(m.goalWindow.end, 25.0);
    EXPECT_EQ(m.place("goal.window.end"), "m.yaml:5: field 'goal.window.end'");
    const GliderProblem gp = MissionProblem(m).gliderProblem(0.0, 0.5);
    EXPECT_EQ(gp.arriveNotBefore, 20.0);
    EXPECT_EQ(gp.arriveNotAfter, 25.0);
    // dates with an epoch, read as the departure's
    MissionSpec dated = parseMission(std::string(kUniformWindow) + "units: {length_m: 1000, time_s: 3600}\n"
                                                                   "epoch: \"2026-01-01T00:00:00Z\"\n",
                                     "m.yaml");
    EXPECT_DOUBLE_EQ(dated.timeOf("2026-01-02T00:00:00Z"), 24.0);
    EXPECT_DOUBLE_EQ(dated.timeOf("7.5"), 7.5);
    EXPECT_THROW(dated.timeOf("soon"), Error);
    EXPECT_THROW(parseMission(kUniformWindow, "m.yaml").timeOf("2026-01-02"), Error);
}

TEST(GoalWindow, DepartureSearchCountsTheHold)
{
    // with a departure window, the arrival is the window's begin whatever the departure: the search prefers the
    // latest departure that still arrives by then (the least travel time, holding included)
    MissionSpec m = withWindow(kUniformWindow, 30.0, 31.0);
    m.departure.window = true;
    m.departure.begin = 0.0;
    m.departure.end = 10.0;
    m.departure.time = 0.0;
    m.departure.spacing = 1.0;
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_TRUE(r.departureSearch);
    EXPECT_GE(r.plan.path.back().t, 30.0);
    EXPECT_LE(r.plan.path.back().t, 31.0);
    EXPECT_GT(r.plan.departure, 9.0); // 30 - 13.3 > 10: the latest departure is best
    EXPECT_NEAR(r.plan.travelTime, r.plan.path.back().t - r.plan.departure, 1e-12);
}

// Every flight ends and stays bounded in memory: a run whose last dive stops a rounding short of its end ends there
// (no endless surfacings at the end), a mission not reaching its goal or a station ends at its end with the reason,
// execution.duration shorter than the trip bounds every strategy's flights, and a station's stay ends with the run.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/execution/Dive.h"
#include "ompl_glider/execution/Execution.h"
#include "ompl_glider/mission/MissionExecution.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

namespace
{
/// The most fixes and track points a flight of @p legs legs from @p t0 to @p end can hold: one fix per surfacing (and
/// the start; each leg begins its dives afresh at its station, one fix more for its hold there), at most
/// @p stepsPerDive steps a dive.
void expectBounded(const FlownTrack &f, double t0, double end, double interval, double stepsPerDive,
                   const std::string &what, double legs = 1.0)
{
    const double dives = std::ceil((end - t0) / interval - 1e-9) + legs - 1.0;
    EXPECT_LE(static_cast<double>(f.fixes.size()), 1.0 + dives + (legs - 1.0)) << what;
    EXPECT_LE(static_cast<double>(f.track.size()), 1.0 + dives * stepsPerDive + (legs - 1.0)) << what;
    EXPECT_LE(f.track.back().t, end) << what;
    EXPECT_LE(f.fixes.back().t, end) << what;
}

/// The uniform mission (1 km / 1 h units) of a glider at V = 0.5 whose truth (u = @p truthU) may hold it back, with
/// @p extra lines in its execution section and @p stations (YAML lines of `waypoints`, or empty).
MissionSpec uniformMission(double truthU, const std::string &strategies, const std::string &extra,
                           const std::string &stations = "")
{
    std::string yaml = R"(name: bounds
units: {length_m: 1000, time_s: 3600}
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 14, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 12, y: 0}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
)";
    if (!stations.empty())
        yaml += "waypoints:\n" + stations;
    yaml += "execution:\n  truth: {type: uniform, parameters: {u: " + std::to_string(truthU) +
            ", v: 0.0}}\n  surfacing_interval: 15 min\n  strategies: " + strategies + "\n  radius: 0.2\n" + extra;
    return parseMission(yaml, "m.yaml");
}
} // namespace

TEST(ExecutionBounds, ALastDiveEndingARoundingShortOfTheRunsEndEndsTheRun)
{
    // 144 dives of 30 steps of 0.25 / 30: the steps' sum falls a rounding short of 36, where the run ends; a fix
    // there once dived no more and surfaced again forever (the fixes filled the memory)
    const UniformCurrent forecast(0.1, 0.0), truth(-0.3, 0.0);
    const std::vector<TimedPoint> plan{{1, 0, 0}, {12, 0, 18.3}};
    ExecutionOptions o;
    o.surfacingInterval = 0.25;
    o.step = 0.25 / 30.0;
    o.radius = 0.2;
    o.endTime = 36.0;
    o.replan = [](double x, double y, double t, const std::vector<TimedPoint> &) {
        return std::vector<TimedPoint>{{x, y, t}, {12, 0, t + (12 - x) / 0.6}};
    };
    o.replanObserved = [&](double x, double y, double t, const std::vector<TimedPoint> &c,
                           const std::shared_ptr<const CurrentField> &) { return o.replan(x, y, t, c); };
    for (ControlStrategy s : controlStrategies())
    {
        const FlownTrack f = flyPlan(plan, 0.5, forecast, truth, nullptr, s, o);
        const std::string name = controlStrategyName(s);
        EXPECT_FALSE(f.reached) << name; // 0.2 over ground: 11 km take 55 h
        expectBounded(f, 0.0, 36.0, 0.25, 30.0, name);
        EXPECT_NEAR(f.track.back().t, 36.0, 1e-9) << name;
        EXPECT_EQ(f.fixes.size(), 145u) << name; // the start and 144 surfacings
    }
}

TEST(ExecutionBounds, AGoalNotReachedEndsEveryFlightAtTwiceThePlannedTripWithTheReason)
{
    // the truth u = -0.3 against the forecast's 0.1: greedy and current_blind make 0.2 over ground, 55 h for the
    // 11 km the plan flies in 18.3 h; the runs end at twice the planned trip, not reached
    const MissionProblem problem(uniformMission(-0.3, "[greedy, current_blind]", ""));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const ExecutionResult &e = *r.execution;
    const ExecutionRun &run = e.runs[0];
    const double end = run.plan.front().t + 2.0 * (run.plan.back().t - run.plan.front().t);
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const FlownTrack &f = run.flown[k];
        const std::string name = controlStrategyName(e.strategies[k]);
        EXPECT_FALSE(f.reached) << name;
        expectBounded(f, run.plan.front().t, end, e.surfacingInterval, 30.0, name);
        EXPECT_NEAR(f.track.back().t, end, 1e-9) << name;
        EXPECT_NE(f.notReachedWhy.find("the goal not reached: not within 200 m of it by t = "), std::string::npos)
            << f.notReachedWhy;
        EXPECT_NE(f.notReachedWhy.find("(twice the planned trip)"), std::string::npos) << f.notReachedWhy;
    }
}

TEST(ExecutionBounds, ADurationShorterThanTheTripBoundsEveryStrategy)
{
    // 5 h of an 18 h trip in the forecast's own ocean: every strategy, the replanning ones too, ends at 5 h
    const std::string all =
        "[current_sensitive, current_blind, greedy, replan, planned_headings, dac, replan_observed]";
    const MissionProblem problem(uniformMission(0.1, all, "  duration: 5 h\n"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const ExecutionResult &e = *r.execution;
    const ExecutionRun &run = e.runs[0];
    ASSERT_EQ(e.strategies.size(), 7u);
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const FlownTrack &f = run.flown[k];
        const std::string name = controlStrategyName(e.strategies[k]);
        EXPECT_FALSE(f.reached) << name;
        expectBounded(f, run.plan.front().t, run.plan.front().t + 5.0, e.surfacingInterval, 30.0, name);
        EXPECT_NEAR(f.track.back().t, run.plan.front().t + 5.0, 1e-9) << name;
        EXPECT_NE(f.notReachedWhy.find("when the run ended (execution.duration)"), std::string::npos)
            << f.notReachedWhy;
    }
}

TEST(ExecutionBounds, AStationNotReachedWithinItsRadiusEndsTheRunWithTheReason)
{
    // station A at 4 km in the truth u = -0.3: greedy, current_blind and dac make 0.2 over ground and reach its 50 m
    // after 14.75 h; B's 50 m lies 25 h of such flight further, past the runs' end (twice the planned trip); the
    // oracle flies the same stations in the truth
    const MissionProblem problem(uniformMission(-0.3, "[greedy, current_blind, dac]", "",
                                                "  - {name: A, x: 4, y: 0, radius: 50 m}\n"
                                                "  - {name: B, x: 9, y: 0.5, radius: 50 m}\n"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const ExecutionResult &e = *r.execution;
    const ExecutionRun &run = e.runs[0];
    const double end = run.plan.front().t + 2.0 * (run.plan.back().t - run.plan.front().t);
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const FlownTrack &f = run.flown[k];
        const std::string name = controlStrategyName(e.strategies[k]);
        EXPECT_FALSE(f.reached) << name;
        EXPECT_EQ(f.stationsReached, 1u) << name;
        expectBounded(f, run.plan.front().t, end, e.surfacingInterval, 30.0, name, 3.0);
        EXPECT_NE(f.notReachedWhy.find("station B not reached: not within 50 m of it by t = "), std::string::npos)
            << f.notReachedWhy;
    }
}

TEST(ExecutionBounds, AStayLongerThanTheRunEndsWithTheRun)
{
    // A reached after about 6 h (0.5 km/h over ground for 2.8 km), then a stay of 40 h: the run's end (execution.
    // duration 10 h) ends the hold; nothing of the flight lies after it, and the goal is said not reached by then
    const MissionProblem problem(uniformMission(0.0, "[greedy, current_sensitive]", "  duration: 10 h\n",
                                                "  - {name: A, x: 4, y: 0, radius: 0.2, stay: 40}\n"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const ExecutionResult &e = *r.execution;
    const ExecutionRun &run = e.runs[0];
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const FlownTrack &f = run.flown[k];
        const std::string name = controlStrategyName(e.strategies[k]);
        EXPECT_EQ(f.stationsReached, 1u) << name;
        EXPECT_FALSE(f.reached) << name;
        EXPECT_NEAR(f.track.back().t, run.plan.front().t + 10.0, 1e-9) << name;
        for (const TimedPoint &p : f.track)
            ASSERT_LE(p.t, run.plan.front().t + 10.0) << name;
        EXPECT_NE(f.notReachedWhy.find("the goal not reached"), std::string::npos) << f.notReachedWhy;
        EXPECT_NE(f.notReachedWhy.find("(execution.duration)"), std::string::npos) << f.notReachedWhy;
    }
}

// A glider carried off a gridded truth's grid is told so, not that it met land: also where the point is still inside
// the grid's bounding box (a grid whose edges are not along x and y, as a lon/lat grid in the planning frame).
TEST(ExecutionBounds, LeavingTheGridIsTheGridsEdgeNotLand)
{
    // a diamond: nodes (a - b) / 2, (a + b) / 2 for a, b in -1, 0, 1; its bounding box is [-1, 1]^2
    GriddedData d;
    d.nx = d.ny = 3;
    for (int b = -1; b <= 1; ++b)
        for (int a = -1; a <= 1; ++a)
        {
            d.nodeX.push_back(0.5 * (a - b));
            d.nodeY.push_back(0.5 * (a + b));
        }
    d.u.assign(9, 0.0f);
    d.v.assign(9, 0.0f);
    const GriddedCurrentField field(d);
    DiveSettings s;
    s.speed = 0.1;
    s.step = 0.05;
    // east from (0, 0.5): off the edge x + y = 1 at x = 0.5, well inside the bounding box
    const DiveEnd e = flyHeading(0.0, 0.5, 0.0, 1.0, 0.0, 20.0, field, nullptr, s, nullptr);
    ASSERT_TRUE(e.grounded);
    EXPECT_NE(e.why.find("edge of the current field's grid (not land)"), std::string::npos) << e.why;
    EXPECT_LT(e.x, 0.5 + 1e-9);
    EXPECT_GT(e.x, 0.5 - 0.1 * s.step - 1e-9);
}

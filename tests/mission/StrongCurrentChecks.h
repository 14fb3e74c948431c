#pragma once
// Shared checks of the strong-current tests: re-flights of a planned route that are independent of the
// planner (a heading route flown again at a much smaller RK4 step; straight legs re-timed at a tight tolerance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/execution/Reflight.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"

namespace strong_checks
{
using namespace ompl_glider;

/// The mission of a YAML text.
inline MissionProblem mission(const std::string &yaml)
{
    return MissionProblem(parseMission(yaml, "strong.yaml"));
}

/// The built-in Gulf Stream mission at another speed (and optionally another planner and its parameters).
inline MissionSpec jetAt(double speed)
{
    MissionSpec m = defaultGulfStreamMission();
    m.vehicle.speed = speed;
    return m;
}

/// A heading route flown again, whole, at 1/8 of the planner's RK4 step and by the accurate Dormand-Prince
/// re-flight (an integrator that shares no code with the planner's): at the reported travel time (the route's end)
/// it must be within the problem's goal radius of the goal, without meeting land or a forbidden region, and the
/// glider must not have come within the radius of the goal much earlier (the reported time is not late either).
inline void expectHeadingReflight(const MissionProblem &problem, const PlannedPath &plan, const std::string &what)
{
    ASSERT_TRUE(plan.headings.has_value()) << what;
    const HeadingRoute &route = *plan.headings;
    const double radius = problem.gliderProblem(plan.departure, plan.speed).goalTolerance;
    const Point2 g = problem.getGoal();
    DiveSettings s;
    s.speed = plan.speed;
    s.step = (route.step > 0.0 ? route.step : route.duration() / 2000.0) / 8.0;
    const HeadingFlight f = flyHeadingRoute(route, *problem.getField(), problem.getEnvironment().get(), s, false);
    EXPECT_FALSE(f.grounded) << what << ": " << f.why;
    EXPECT_NEAR(f.ends.back().t - plan.departure, plan.travelTime, 1e-5 * plan.travelTime) << what;
    EXPECT_LE(std::hypot(f.ends.back().x - g.x, f.ends.back().y - g.y), radius)
        << what << ": the RK4 re-flight at step " << s.step << " ends outside the goal radius";
    ReflightSettings rs;
    rs.speed = plan.speed;
    const HeadingReflight r = reflyHeadingRoute(route, *problem.getField(), problem.getEnvironment().get(), rs);
    ASSERT_TRUE(r.ok) << what << ": " << r.why;
    EXPECT_FALSE(r.grounded) << what << ": " << r.why;
    EXPECT_NEAR(r.end.t - plan.departure, plan.travelTime, 1e-5 * plan.travelTime) << what;
    EXPECT_LE(std::hypot(r.end.x - g.x, r.end.y - g.y), radius)
        << what << ": the Dormand-Prince re-flight ends outside the goal radius";
    // the route does not pass the goal long before its end
    rs.radius = radius;
    rs.goal = g;
    const HeadingReflight e = reflyHeadingRoute(route, *problem.getField(), problem.getEnvironment().get(), rs);
    ASSERT_TRUE(e.reached) << what;
    EXPECT_GE(e.arrivalTime - plan.departure, plan.travelTime * (1.0 - 1e-3))
        << what << ": the route passes the goal long before its reported arrival";
}

/// Straight legs re-timed one after the other with TravelTimeCalculator at eps 1e-9: every waypoint time equals the
/// reported one within 1e-4 of the travel time.
inline void expectStraightLegRetiming(const MissionProblem &problem, const PlannedPath &plan, const std::string &what)
{
    ASSERT_FALSE(plan.headings.has_value()) << what;
    ASSERT_GE(plan.path.size(), 2u) << what;
    TravelTimeParams p = problem.getSpec().travel;
    p.speed = plan.speed;
    p.eps = 1e-9;
    const TravelTimeCalculator calc(problem.getField(), p);
    double t = plan.path.front().t;
    EXPECT_NEAR(t, plan.departure, 1e-12) << what;
    for (std::size_t k = 0; k + 1 < plan.path.size(); ++k)
    {
        const TimedPoint &a = plan.path[k], &b = plan.path[k + 1];
        const double leg = (a.x == b.x && a.y == b.y) ? b.t - a.t : calc.travelTime(a.x, a.y, b.x, b.y, t);
        ASSERT_TRUE(std::isfinite(leg)) << what << ": leg " << k << " impassable when re-timed";
        t += leg;
        EXPECT_NEAR(b.t, t, 1e-4 * plan.travelTime) << what << ": waypoint " << k + 1;
    }
}
} // namespace strong_checks

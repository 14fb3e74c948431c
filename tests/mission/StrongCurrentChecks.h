#pragma once
// Shared checks of the strong-current tests (issue 24): re-flights of a planned route that are independent of the
// planner (a heading route flown again at a much smaller RK4 step; straight legs re-timed at a tight tolerance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/execution/HeadingRoute.h"
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

/// A heading route flown again at 1/8 of the planner's RK4 step, with the problem's goal radius: it must reach the
/// goal, at the reported travel time.
inline void expectHeadingReflight(const MissionProblem &problem, const PlannedPath &plan, const std::string &what)
{
    ASSERT_TRUE(plan.headings.has_value()) << what;
    const HeadingRoute &route = *plan.headings;
    DiveSettings s;
    s.speed = plan.speed;
    s.step = (route.step > 0.0 ? route.step : route.duration() / 2000.0) / 8.0;
    s.radius = problem.gliderProblem(plan.departure, plan.speed).goalTolerance;
    s.goal = problem.getGoal();
    const HeadingFlight f = flyHeadingRoute(route, *problem.getField(), problem.getEnvironment().get(), s, false);
    ASSERT_TRUE(f.reached) << what << ": the re-flight at step " << s.step << " misses the goal radius " << s.radius
                           << " (closest " << f.closestDistance << " at t " << f.closestTime << ")";
    EXPECT_FALSE(f.grounded) << what << ": " << f.why;
    EXPECT_NEAR(f.arrivalTime - plan.departure, plan.travelTime, 1e-5 * plan.travelTime)
        << what << ": re-flight arrival vs reported travel time";
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
}  // namespace strong_checks

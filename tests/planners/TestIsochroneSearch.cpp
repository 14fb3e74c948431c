// The isochrone search and followWithRestarts(): where a path cannot be followed, a new search from where the glider
// stopped closes the route on the goal.
#include <gtest/gtest.h>

#include <cmath>

#include <ompl/base/PlannerTerminationCondition.h>

#include "PostprocessTestUtil.h"
#include "ompl_glider/current/DoubleGyre.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/routes/HeadingTracker.h"
#include "ompl_glider/planners/IsochroneSearch.h"

using namespace ompl_glider;
using namespace ompl_glider::test;

namespace
{
// A uniform current of 1 to the east, three times faster than the glider (V = 0.3). Downstream goals are met
// fastest by heading with the current: T = d / (1 + V).
constexpr double kU = 1.0, kV = 0.3;

std::shared_ptr<GliderContext> eastward()
{
    Region r = box(-3.0, 8.0, -3.0, 3.0);
    r.tMin = 0.0;
    r.tMax = 100.0;
    return makeContext(std::make_shared<UniformCurrent>(kU, 0.0), kV, r);
}

HeadingRefineSettings checkSettings(const GliderContext &ctx, double duration)
{
    HeadingRefineSettings s;
    s.radius = 1e-6;
    s.tEnd = 100.0;
    s.step = headingCheckStep(duration, ctx);
    return s;
}
} // namespace

TEST(IsochroneSearch, MeetsADownstreamGoalAtTheClosedFormTime)
{
    const auto ctx = eastward();
    const Point2 goal{5.0, 1.0};
    const IsochroneSetup setup = makeIsochroneSetup(*ctx, goal, 1e-6);
    ThreadPool pool(2);
    const IsochroneSearch s =
        searchIsochrones(setup, {0.0, 0.0, 0.0}, pool, ompl::base::plannerNonTerminatingCondition());
    ASSERT_TRUE(std::isfinite(s.hit.arrival)) << s.why;
    // the exact first arrival: the disc of radius V t drifting at 1 reaches the goal when |g - (t, 0)| = V t
    const double a = kU * kU - kV * kV, b = -2.0 * goal.x * kU, c = goal.x * goal.x + goal.y * goal.y;
    const double exact = (-b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
    // the search meets the goal within one cell's radius, a step at most later than the optimum
    EXPECT_GT(s.hit.arrival, exact - setup.cell / (kU - kV));
    EXPECT_LT(s.hit.arrival, exact + setup.dt);
    // its own route flies from the start to within the search's radius of the goal
    const HeadingRoute route = searchRoute(s);
    DiveSettings dive = setup.dive;
    dive.radius = 0.0;
    const HeadingFlight f = flyHeadingRoute(route, *ctx->field, nullptr, dive, false);
    EXPECT_LT(std::hypot(f.ends.back().x - goal.x, f.ends.back().y - goal.y), 1.01 * setup.dive.radius);
}

TEST(IsochroneSearch, FollowingThatStopsIsClosedByANewSearchFromWhereTheGliderStopped)
{
    // The path's second point lies upstream, where no heading reaches (the current is faster than the glider): the
    // tracker stops at the start. A new search from there closes the route on the goal.
    const auto ctx = eastward();
    const Point2 goal{5.0, 0.0};
    const std::vector<TimedPoint> path{{0.0, 0.0, 0.0}, {-2.0, 0.0, 1.0}, {goal.x, goal.y, 10.0}};
    const HeadingRefineSettings s = checkSettings(*ctx, 10.0);
    const IsochroneSetup setup = makeIsochroneSetup(*ctx, goal, s.radius);
    ThreadPool pool(2);
    const auto never = ompl::base::plannerNonTerminatingCondition();

    const RefinedHeadings stopped = followWithRestarts(path, nullptr, goal, *ctx, s, 0.0, setup, pool, never, 0);
    ASSERT_FALSE(stopped.ok);
    ASSERT_TRUE(stopped.stoppedAt.has_value());
    EXPECT_EQ(stopped.stoppedAt->x, 0.0);

    const RefinedHeadings closed = followWithRestarts(path, nullptr, goal, *ctx, s, 0.0, setup, pool, never, 1);
    ASSERT_TRUE(closed.ok) << closed.why;
    const TimedPoint &end = closed.flight.ends.back();
    EXPECT_LT(std::hypot(end.x - goal.x, end.y - goal.y), s.radius);
    // no faster route exists than drifting with the current at full speed, and the search's is within a few steps
    const double best = goal.x / (kU + kV);
    EXPECT_GE(end.t, best * (1.0 - 1e-9));
    EXPECT_LT(end.t, best + 3.0 * setup.dt);
    // the route is flown again whole by the checker: the same end
    const HeadingFlight again = verifyHeadingRoute(closed.route, *ctx, goal, s);
    EXPECT_TRUE(again.reached);
    EXPECT_NEAR(again.ends.back().t, end.t, 1e-12 * end.t);
}

TEST(IsochroneSearch, LastSegmentReAimedOnTheAccurateReflight)
{
    // A route flown by RK4 at a coarse step (0.4) through a time-dependent double gyre (flow up to about 0.94, the
    // glider 0.15): aimed so that the coarse flight ends on the goal, the accurate flight ends elsewhere. Re-aiming
    // the last segment on the accurate flight brings that flight to the goal.
    Region r = box(0.0, 2.0, 0.0, 1.0);
    r.tMin = 0.0;
    r.tMax = 50.0;
    const auto ctx = makeContext(std::make_shared<DoubleGyre>(0.3, 1.0, 0.25, 2.0 * M_PI / 10.0), 0.15, r);
    HeadingRoute route;
    route.start = {0.3, 0.3};
    route.departure = 0.0;
    route.step = 0.4;
    route.segments = {{90.0, 1.2}, {45.0, 1.2}, {0.0, 1.2}};
    DiveSettings coarse;
    coarse.speed = 0.15;
    coarse.step = route.step;
    const HeadingFlight planned = flyHeadingRoute(route, *ctx->field, nullptr, coarse, false);
    const Point2 goal{planned.ends.back().x, planned.ends.back().y}; // where the coarse flight ends

    ReflightSettings s;
    s.speed = 0.15;
    const HeadingReflight before = reflyHeadingRoute(route, *ctx->field, nullptr, s);
    const double radius = 1e-6;
    const double missBefore = std::hypot(before.end.x - goal.x, before.end.y - goal.y);
    ASSERT_GT(missBefore, 100.0 * radius); // the coarse and the accurate flights part

    HeadingRoute aimed = route;
    HeadingReflight flight;
    ASSERT_TRUE(reaimOnReflight(aimed, goal, *ctx->field, nullptr, s, radius, flight));
    // only the last segment changed, by little
    for (std::size_t k = 0; k + 1 < route.segments.size(); ++k)
    {
        EXPECT_EQ(aimed.segments[k].bearing, route.segments[k].bearing);
        EXPECT_EQ(aimed.segments[k].duration, route.segments[k].duration);
    }
    EXPECT_LT(std::abs(aimed.segments.back().bearing - route.segments.back().bearing), 10.0);
    // an independent accurate flight of the re-aimed route, at a tighter tolerance, ends on the goal
    ReflightSettings tight = s;
    tight.tolerance.rtol = 1e-12;
    const HeadingReflight check = reflyHeadingRoute(aimed, *ctx->field, nullptr, tight);
    EXPECT_LT(std::hypot(check.end.x - goal.x, check.end.y - goal.y), radius);
    EXPECT_NEAR(flight.end.t, check.end.t, 1e-9);
    ASSERT_EQ(flight.ends.size(), route.segments.size() + 1);
}

TEST(IsochroneSearch, ReAimingRefusesAGoalNoHeldHeadingReaches)
{
    // upstream of a current three times the glider's speed: no heading and duration reach it; the route is unchanged
    const auto ctx = eastward();
    HeadingRoute route;
    route.start = {0.0, 0.0};
    route.departure = 0.0;
    route.segments = {{90.0, 1.0}, {0.0, 1.0}};
    ReflightSettings s;
    s.speed = kV;
    HeadingRoute same = route;
    HeadingReflight flight;
    EXPECT_FALSE(reaimOnReflight(same, {-2.0, 0.0}, *ctx->field, nullptr, s, 1e-6, flight));
    EXPECT_EQ(same.segments.back().bearing, route.segments.back().bearing);
    EXPECT_EQ(same.segments.back().duration, route.segments.back().duration);
}

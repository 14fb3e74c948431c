// The isochrone search and followWithRestarts(): where a path cannot be followed, a new search from where the glider
// stopped closes the route on the goal.
#include <gtest/gtest.h>

#include <cmath>

#include <ompl/base/PlannerTerminationCondition.h>

#include "PostprocessTestUtil.h"
#include "ompl_glider/current/UniformCurrent.h"
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
}  // namespace

TEST(IsochroneSearch, MeetsADownstreamGoalAtTheClosedFormTime)
{
    const auto ctx = eastward();
    const Point2 goal{5.0, 1.0};
    const IsochroneSetup setup = makeIsochroneSetup(*ctx, goal, 1e-6);
    ThreadPool pool(2);
    const IsochroneSearch s = searchIsochrones(setup, {0.0, 0.0, 0.0}, pool, ompl::base::plannerNonTerminatingCondition());
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

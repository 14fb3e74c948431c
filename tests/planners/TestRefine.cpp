// Waypoint refinement: approaches Zermelo's optimum from a poor feasible path in Betts' shear flow, never arrives
// later, keeps every leg valid around an obstacle and inside the region, and leaves infeasible input alone.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "PostprocessTestUtil.h"
#include "planners/TveSearch.h" // internal to the library (src/)
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "ompl_glider/routes/WaypointRefiner.h"

using namespace ompl_glider;
using namespace ompl_glider::test;

TEST(WaypointRefiner, ApproachesZermeloOptimumInShearFlow)
{
    // u = -y, V = 1, (3.5, -1.8) -> (0, 0): the optimal time is 5.26493205 ([BettsOC] Ex. 10.148). Start from a poor
    // feasible polyline (about 5x slower); the refined path must come within 1% of the optimum, never below it
    // by more than the travel-time integration error.
    auto ctx = makeContext(std::make_shared<LinearShear>(-1.0), 1.0, box(-1, 6, -3, 3), nullptr, 1e-5);
    const std::vector<TimedPoint> start = {{3.5, -1.8, 0}, {5.0, -0.8, 0}, {0, 0, 0}};
    const double before = arrivalTime(*ctx, start, 0.0);
    ASSERT_TRUE(std::isfinite(before));
    ASSERT_GT(before, 2 * 5.26493205);
    const RefinementResult r = WaypointRefiner(ctx).refine(start);
    EXPECT_EQ(r.arrivalBefore, before);
    EXPECT_LT(r.arrivalAfter, 5.26493205 * 1.01);
    EXPECT_GT(r.arrivalAfter, 5.26493205 * (1 - 1e-4));
    EXPECT_GT(r.waypointsAfter, 2u);
    EXPECT_EQ(r.waypoints.front().x, 3.5);
    EXPECT_EQ(r.waypoints.back().y, 0.0);
    EXPECT_EQ(arrivalTime(*ctx, r.waypoints, 0.0), r.arrivalAfter);
}

TEST(WaypointRefiner, KeepsLegsFreeAndInsideRegion)
{
    // A box on the jet's axis; the lattice path goes round it; the refined path must keep every leg free.
    auto env = std::make_shared<BoxEnvironment>(4, 5.2, -0.8, 1.5);
    auto jet = std::make_shared<MeanderingJet>();
    auto ctx = makeContext(jet, 0.5, box(0, 10, -4, 4), env);
    const TveResult lat = TveSearch(ctx, 0.5, 2).run(1, -3, 0.0, 8, 3, TveOptions{});
    ASSERT_EQ(lat.outcome, TveOutcome::Exact);
    const SmoothingResult s = PathSmoother(ctx).smooth(lat.waypoints);
    const RefinementResult r = WaypointRefiner(ctx).refine(s.waypoints);
    EXPECT_LE(r.arrivalAfter, s.arrivalAfter);
    EXPECT_LT(r.arrivalAfter, s.arrivalAfter); // there is room to improve on a 0.5 lattice
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        EXPECT_GE(r.waypoints[i].x, 0.0);
        EXPECT_LE(r.waypoints[i].x, 10.0);
        EXPECT_GE(r.waypoints[i].y, -4.0);
        EXPECT_LE(r.waypoints[i].y, 4.0);
        if (i > 0)
        {
            const auto &a = r.waypoints[i - 1], &b = r.waypoints[i];
            EXPECT_TRUE(std::isfinite(b.t));
            EXPECT_TRUE(env->legFree(a.x, a.y, a.t, b.x, b.y, b.t)) << "leg " << i;
        }
    }
}

TEST(WaypointRefiner, NeverLaterThanSmoothedJetPath)
{
    auto jet = std::make_shared<MeanderingJet>();
    auto ctx = makeContext(jet, 0.5, box(0, 10, -4, 4));
    const TveResult lat = TveSearch(ctx, 0.5, 2).run(1, 3, 1.0, 9, -2.5, TveOptions{}); // departure at t = 1
    ASSERT_EQ(lat.outcome, TveOutcome::Exact);
    const SmoothingResult s = PathSmoother(ctx).smooth(lat.waypoints);
    ASSERT_TRUE(std::isfinite(s.arrivalAfter));
    RefinerParams p;
    p.maxEvaluations = 3000;
    const RefinementResult r = WaypointRefiner(ctx, p).refine(s.waypoints);
    EXPECT_LE(r.arrivalAfter, s.arrivalAfter);
    EXPECT_LE(r.evaluations, 3000u + 1u);
    EXPECT_EQ(r.waypoints.front().t, 1.0); // the departure: the first waypoint's time
    EXPECT_EQ(retimeWaypoints(*ctx, r.waypoints, 1.0).back().t, r.arrivalAfter);
}

TEST(WaypointRefiner, StopsWhenTheTerminationConditionSaysSo)
{
    auto jet = std::make_shared<MeanderingJet>();
    auto ctx = makeContext(jet, 0.5, box(0, 10, -4, 4));
    const TveResult lat = TveSearch(ctx, 0.5, 2).run(1, 3, 0.0, 9, -2.5, TveOptions{});
    ASSERT_EQ(lat.outcome, TveOutcome::Exact);
    RefinerParams p;
    p.maxEvaluations = 100000000; // the budget alone would run for minutes
    unsigned asked = 0;
    p.terminate = [&asked] { return ++asked > 25; };
    const RefinementResult r = WaypointRefiner(ctx, p).refine(lat.waypoints);
    EXPECT_LE(r.evaluations, 26u); // at most one evaluation per question before the answer turned to true
    EXPECT_GT(asked, 25u);
    EXPECT_LE(r.arrivalAfter, r.arrivalBefore); // the best path so far, never a worse one
    EXPECT_EQ(retimeWaypoints(*ctx, r.waypoints, 0.0).back().t, r.arrivalAfter);
}

TEST(WaypointRefiner, InfeasibleInputAndBadParameters)
{
    auto ctx = makeContext(std::make_shared<UniformCurrent>(1.0, 0.0), 0.5, box(-10, 10, -10, 10));
    const std::vector<TimedPoint> wp = {{0, 0, 0}, {-1, 0.5, 0}, {-3, 1, 0}};
    const RefinementResult r = WaypointRefiner(ctx).refine(wp);
    EXPECT_FALSE(std::isfinite(r.arrivalBefore));
    ASSERT_EQ(r.waypointsAfter, 3u);
    EXPECT_EQ(r.waypoints[1].x, -1.0);
    EXPECT_TRUE(WaypointRefiner(ctx).refine(std::vector<TimedPoint>{}).waypoints.empty());
    RefinerParams bad;
    bad.maxEvaluations = 0;
    EXPECT_THROW(WaypointRefiner(ctx, bad), Error);
    EXPECT_THROW(WaypointRefiner(nullptr), Error);
}

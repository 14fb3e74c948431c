// Holding in the lattice search (TveOptions::waiting; [ThompsonICRA] Sec. III hold-position actions, the
// earliest valid arrival): a start walled in by a lane closed until T is left by waiting (TVE and ZA*TVE agree, the
// OMPL path checks), goal windows met by holding at the goal or before the goal edge, and a window that cannot be met.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "planners/TveSearch.h" // internal to the library (src/)
#include "ompl_glider/planners/ZAStarTVE.h"

using namespace ompl_glider;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
constexpr double kT = 10.0; // the lane opens at kT

// Still water, V = 1, region [0, 10] x [-2, 2]; a lane x in [3, 4] across the whole region, closed during [0, kT]:
// the start (1, 0) is walled in until kT, the goal (8, 0) lies beyond the lane.
GliderProblem walledIn()
{
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(0.0, 0.0);
    p.travel.speed = 1.0;
    p.xMin = 0.0;
    p.xMax = 10.0;
    p.yMin = -2.0;
    p.yMax = 2.0;
    p.horizon = 40.0;
    p.start.x = 1.0;
    p.start.y = 0.0;
    p.goal.x = 8.0;
    p.goal.y = 0.0;
    auto env = std::make_shared<ForbiddenRegions>();
    env->add(std::make_shared<TimeWindowedZone>("lane", Polygon::rectangle(3.0, -3.0, 4.0, 3.0, "lane"),
                                                std::vector<Interval>{{0.0, kT}}));
    p.environment = env;
    return p;
}

bool samePosition(const TimedPoint &a, const TimedPoint &b)
{
    return a.x == b.x && a.y == b.y;
}

double holdTime(const std::vector<TimedPoint> &w)
{
    double h = 0.0;
    for (std::size_t i = 1; i < w.size(); ++i)
        if (samePosition(w[i - 1], w[i]))
            h += w[i].t - w[i - 1].t;
    return h;
}

/// Every motion valid for the motion validator and PathGeometric::check() on the waypoints.
void expectValid(const og::SimpleSetupPtr &ss, const std::vector<TimedPoint> &w)
{
    const auto si = ss->getSpaceInformation();
    const auto mv = std::dynamic_pointer_cast<TravelTimeMotionValidator>(si->getMotionValidator());
    ASSERT_TRUE(mv);
    for (std::size_t i = 1; i < w.size(); ++i)
        EXPECT_EQ(mv->classify(w[i - 1].x, w[i - 1].y, w[i - 1].t, w[i].x, w[i].y, w[i].t), MotionVerdict::Valid)
            << "leg " << i - 1 << " ("
            << toString(mv->classify(w[i - 1].x, w[i - 1].y, w[i - 1].t, w[i].x, w[i].y, w[i].t)) << ")";
    og::PathGeometric path(si);
    waypointsToPath(w, path);
    EXPECT_TRUE(path.check());
}

TveOptions tveOnly()
{
    TveOptions o;
    o.heuristic = false;
    o.zermelo = false;
    o.tightBounds = false;
    return o;
}
} // namespace

TEST(LatticeWaiting, WalledInStartWaitsForTheLaneToOpen)
{
    const GliderProblem p = walledIn();
    std::shared_ptr<GliderContext> ctx;
    const og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);

    // without waiting the lane can only be passed around, and there is no way around it
    TveOptions noWait;
    noWait.waiting = false;
    TveSearch search(ctx, 0.5, 3);
    EXPECT_EQ(search.run(1.0, 0.0, 0.0, 8.0, 0.0, noWait).outcome, TveOutcome::Exhausted);

    // ZA*TVE (default options) holds before the lane, then passes: arrival >= kT + 5 (the open water from the lane's
    // near edge x = 3 to the goal at V = 1), and the lattice optimum waits at the vertex x = 2.5: kT + 5.5
    const TveResult z = search.run(1.0, 0.0, 0.0, 8.0, 0.0, TveOptions{});
    ASSERT_EQ(z.outcome, TveOutcome::Exact);
    const double arrival = z.waypoints.back().t;
    EXPECT_GE(arrival, kT + 5.0);
    EXPECT_NEAR(arrival, kT + 5.5, 1e-6);
    EXPECT_GT(holdTime(z.waypoints), 0.0);
    // the hold ends when the lane opens, at a vertex outside it
    bool heldToT = false;
    for (std::size_t i = 1; i < z.waypoints.size(); ++i)
        if (samePosition(z.waypoints[i - 1], z.waypoints[i]))
        {
            EXPECT_LT(z.waypoints[i].x, 3.0);
            heldToT = heldToT || std::abs(z.waypoints[i].t - kT) < 1e-6;
        }
    EXPECT_TRUE(heldToT);
    expectValid(ss, z.waypoints);

    // TVE (plain Dijkstra) agrees: the certified search stays exact with waiting edges
    TveSearch plain(ctx, 0.5, 3);
    const TveResult t = plain.run(1.0, 0.0, 0.0, 8.0, 0.0, tveOnly());
    ASSERT_EQ(t.outcome, TveOutcome::Exact);
    EXPECT_NEAR(t.waypoints.back().t, arrival, 1e-9);

    // through OMPL (ZAStarTVE with its smoothing and refinement): the solution path holds and checks
    ss->setPlanner(std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE"));
    ASSERT_EQ(ss->solve(30.0), ob::PlannerStatus::EXACT_SOLUTION);
    const og::PathGeometric &sol = ss->getSolutionPath();
    EXPECT_TRUE(sol.check());
    const std::vector<TimedPoint> w = waypointsFromPath(sol);
    EXPECT_GE(w.back().t, kT + 5.0);
    EXPECT_LE(w.back().t, kT + 5.5 + 1e-6);
}

TEST(LatticeWaiting, GoalWindowHeldAtTheGoal)
{
    GliderProblem p = walledIn();
    p.environment = nullptr; // open water: earliest arrival 7
    p.arriveNotBefore = 12.0;
    p.arriveNotAfter = 13.0;
    std::shared_ptr<GliderContext> ctx;
    const og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);
    TveSearch search(ctx, 0.5, 3);
    const TveResult r = search.run(1.0, 0.0, 0.0, 8.0, 0.0, TveOptions{});
    ASSERT_EQ(r.outcome, TveOutcome::Exact);
    ASSERT_GE(r.waypoints.size(), 3u);
    EXPECT_EQ(r.waypoints.back().t, 12.0);
    EXPECT_TRUE(samePosition(r.waypoints[r.waypoints.size() - 2], r.waypoints.back()));
    EXPECT_NEAR(r.waypoints[r.waypoints.size() - 2].t, 7.0, 1e-9);
    EXPECT_NEAR(holdTime(r.waypoints), 12.0 - 7.0, 1e-9);
    expectValid(ss, r.waypoints);
}

TEST(LatticeWaiting, GoalWindowTimedWhereTheGoalCannotBeHeld)
{
    // shear u = y, V = 0.5: the goal (8, 0.55) lies in a current of 0.55 > V, the vertices below y = 0.5 in weaker
    // current; the arrival is timed by a hold at the vertex before the edge into the goal
    GliderProblem p;
    p.field = std::make_shared<LinearShear>(1.0);
    p.travel.speed = 0.5;
    p.xMin = 0.0;
    p.xMax = 10.0;
    p.yMin = -2.0;
    p.yMax = 2.0;
    p.horizon = 60.0;
    p.start.x = 1.0;
    p.start.y = 0.0;
    p.goal.x = 8.0;
    p.goal.y = 0.55;
    std::shared_ptr<GliderContext> free;
    makeSimpleSetup(p, &free);
    TveSearch s0(free, 0.25, 3);
    const TveResult early = s0.run(1.0, 0.0, 0.0, 8.0, 0.55, TveOptions{});
    ASSERT_EQ(early.outcome, TveOutcome::Exact);
    ASSERT_LT(early.waypoints.back().t, 20.0);

    p.arriveNotBefore = 30.0;
    p.arriveNotAfter = 32.0;
    std::shared_ptr<GliderContext> ctx;
    const og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);
    ASSERT_FALSE(ctx->canHold(8.0, 0.55, early.waypoints.back().t, 30.0, ctx->holdTimeStep()));
    TveSearch search(ctx, 0.25, 3);
    const TveResult r = search.run(1.0, 0.0, 0.0, 8.0, 0.55, TveOptions{});
    ASSERT_EQ(r.outcome, TveOutcome::Exact);
    EXPECT_FALSE(r.goalWindowMissed);
    const auto &w = r.waypoints;
    EXPECT_GE(w.back().t, 30.0 - 1e-9);
    EXPECT_LE(w.back().t, 32.0);
    EXPECT_FALSE(samePosition(w[w.size() - 2], w.back()));
    EXPECT_GT(holdTime(w), 0.0);
    expectValid(ss, w);
    // re-fly: the edge into the goal flown as fast as possible from its departure lands on the arrival
    const TimedPoint &a = w[w.size() - 2];
    EXPECT_NEAR(a.t + ctx->travel->travelTime(a.x, a.y, w.back().x, w.back().y, a.t), w.back().t, 1e-9);
}

TEST(LatticeWaiting, GoalWindowThatCannotBeMet)
{
    GliderProblem p = walledIn();
    p.environment = nullptr;
    p.arriveNotBefore = 1.0;
    p.arriveNotAfter = 5.0; // the earliest arrival is 7
    std::shared_ptr<GliderContext> ctx;
    makeSimpleSetup(p, &ctx);
    TveSearch search(ctx, 0.5, 3);
    // no path in the window: the earliest arrival without it, flagged (the pipeline reports it), or none at all
    const TveResult r = search.run(1.0, 0.0, 0.0, 8.0, 0.0, TveOptions{});
    ASSERT_EQ(r.outcome, TveOutcome::Exact);
    EXPECT_TRUE(r.goalWindowMissed);
    EXPECT_NEAR(r.waypoints.back().t, 7.0, 1e-9);
    TveOptions strict;
    strict.goalWindowFallback = false;
    EXPECT_EQ(search.run(1.0, 0.0, 0.0, 8.0, 0.0, strict).outcome, TveOutcome::Exhausted);
}

TEST(LatticeWaiting, CertifiedZAStarTveEqualsTveWithWaitingOnTheJet)
{
    // the meandering jet with a wall x in [4.6, 5.4] closed during [0, 12]: TVE (plain Dijkstra) and the default
    // ZA*TVE (A* bounds, Zermelo pruning certified, two phases) give the same arrival with waiting edges, without
    // waiting there is no path
    GliderProblem p;
    p.field = std::make_shared<MeanderingJet>();
    p.horizon = 40.0;
    p.start.x = 0.6;
    p.start.y = -2.6;
    p.goal.x = 9.4;
    p.goal.y = 2.6;
    auto env = std::make_shared<ForbiddenRegions>();
    env->add(std::make_shared<TimeWindowedZone>("lane", Polygon::rectangle(4.6, -4.0, 5.4, 4.0, "lane"),
                                                std::vector<Interval>{{0.0, 12.0}}));
    p.environment = env;
    std::shared_ptr<GliderContext> ctx;
    const og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);
    TveSearch a(ctx, 0.4, 3), b(ctx, 0.4, 3), c(ctx, 0.4, 3);
    const TveResult tve = a.run(0.6, -2.6, 0.0, 9.4, 2.6, tveOnly());
    const TveResult za = b.run(0.6, -2.6, 0.0, 9.4, 2.6, TveOptions{});
    TveOptions noWait = tveOnly();
    noWait.waiting = false;
    const TveResult tveNoWait = c.run(0.6, -2.6, 0.0, 9.4, 2.6, noWait);
    ASSERT_EQ(tve.outcome, TveOutcome::Exact);
    ASSERT_EQ(za.outcome, TveOutcome::Exact);
    EXPECT_NEAR(za.travelTime, tve.travelTime, 1e-9 * tve.travelTime);
    EXPECT_LT(za.costFunctionCalls, tve.costFunctionCalls);
    // without waiting the glider can only drift in the jet until the wall opens: 28.7 against 18.85 with a hold
    ASSERT_EQ(tveNoWait.outcome, TveOutcome::Exact);
    EXPECT_LT(tve.travelTime, tveNoWait.travelTime - 1.0);
    EXPECT_GT(za.travelTime, 12.0);
    EXPECT_GT(holdTime(za.waypoints), 0.0);
    expectValid(ss, za.waypoints);
    std::printf("jet + wall closed [0, 12]: TVE %.6f (%llu CFC), ZA*TVE %.6f (%llu CFC), hold %.4f; TVE without "
                "waiting %.6f\n",
                tve.travelTime, static_cast<unsigned long long>(tve.costFunctionCalls), za.travelTime,
                static_cast<unsigned long long>(za.costFunctionCalls), holdTime(za.waypoints),
                tveNoWait.outcome == TveOutcome::Exact ? tveNoWait.travelTime : -1.0);
}

// A search without a context is refused with the documented Error before the lattice reads the context's region.
TEST(TveSearch, MissingContextIsAnErrorNotACrash)
{
    EXPECT_THROW(TveSearch search(nullptr, 0.4, 3), Error);
    auto noField = std::make_shared<GliderContext>();
    EXPECT_THROW(TveSearch search(noField, 0.4, 3), Error);
}

// The level-set solver against closed forms and independent references: the reachable disc of a uniform
// current (also faster than the vehicle), Betts' shear problem, the shooting optimum on the meandering jet, a
// walled-in start, a lane that must be waited out, and isochrones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/reachability/LevelSet.h"
#include "ompl_glider/reference/ZermeloReference.h"

using namespace ompl_glider;

namespace
{
std::shared_ptr<GliderContext> context(std::shared_ptr<const CurrentField> field, double V, double x0, double x1,
                                       double y0, double y1, double horizon = 60.0,
                                       std::shared_ptr<const Environment> env = nullptr)
{
    GliderProblem p;
    p.field = std::move(field);
    p.travel.speed = V;
    p.xMin = x0;
    p.xMax = x1;
    p.yMin = y0;
    p.yMax = y1;
    p.horizon = horizon;
    p.environment = std::move(env);
    p.start.x = 0.5 * (x0 + x1);
    p.start.y = 0.5 * (y0 + y1);
    p.goal.x = p.start.x;
    p.goal.y = p.start.y;
    return makeGliderContext(p);
}

/// The times at which the offset w is on the reachable disc of a uniform current c with speed V: the roots of
/// |w - c t| = V t, smallest first ({t, +inf} when only one is positive, {+inf, +inf} when none).
std::pair<double, double> uniformArrival(double wx, double wy, double cx, double cy, double V)
{
    const double a = V * V - cx * cx - cy * cy, b = 2.0 * (wx * cx + wy * cy), w2 = wx * wx + wy * wy;
    // a t^2 + b t - w2 = 0
    if (std::abs(a) < 1e-15)
        return {b > 0 ? w2 / b : INFINITY, INFINITY};
    const double disc = b * b + 4 * a * w2;
    if (disc < 0)
        return {INFINITY, INFINITY};
    const double r1 = (-b - std::sqrt(disc)) / (2 * a), r2 = (-b + std::sqrt(disc)) / (2 * a);
    const double lo = std::min(r1, r2), hi = std::max(r1, r2);
    if (lo > 0)
        return {lo, hi};
    return {hi > 0 ? hi : INFINITY, INFINITY};
}
} // namespace

TEST(LevelSet, UniformCurrentGivesTheExactDisc)
{
    // A slow and a fast current (|c| > V: the start leaves the set; the splitting schemes fail here).
    for (const auto &cur : {std::pair<double, double>{0.3, 0.1}, std::pair<double, double>{0.9, -0.3}})
    {
        SCOPED_TRACE("current (" + std::to_string(cur.first) + ", " + std::to_string(cur.second) + ")");
        auto ctx = context(std::make_shared<UniformCurrent>(cur.first, cur.second), 0.5, 0, 10, -5, 5);
        LevelSetParams lp;
        lp.cellSize = 0.05;
        const LevelSetSolver solver(ctx, lp);
        const double sx = 2.0, sy = 0.0;
        const Reachability r = solver.solve(sx, sy, 0.0, 8.0, std::nullopt);
        double worst = 0.0, sum = 0.0;
        int compared = 0;
        for (int j = 0; j < r.ny; ++j)
            for (int i = 0; i < r.nx; ++i)
            {
                const double x = r.x0 + i * r.h, y = r.y0 + j * r.h;
                // Nodes away from the start (where a cell is a large part of the distance), reached before the
                // end, and (current faster than V) inside the cone of reachable directions, not grazed by it.
                const auto [T, leave] = uniformArrival(x - sx, y - sy, cur.first, cur.second, 0.5);
                if (!(T > 1.5 && T < 7.5) || leave - T < 1.0)
                    continue;
                const double got = r.arrival[static_cast<std::size_t>(j) * r.nx + i];
                ASSERT_TRUE(std::isfinite(got)) << "node (" << x << ", " << y << ") never reached";
                worst = std::max(worst, std::abs(got - T) / T);
                sum += std::abs(got - T) / T;
                ++compared;
            }
        std::printf("uniform current (%.1f, %.1f): %d nodes, relative error of T: mean %.4f %%, worst %.4f %%\n",
                    cur.first, cur.second, compared, 100 * sum / compared, 100 * worst);
        EXPECT_GT(compared, 1000);
        EXPECT_LT(sum / compared, 0.002);
        EXPECT_LT(worst, 0.015);
        // The isochrone at t = 6: with |c| < V the discs are nested, so the set reached by then is the circle of
        // centre start + 6 c and radius 6 V (with |c| > V it is the union of the discs, a cone).
        if (std::hypot(cur.first, cur.second) >= 0.5)
            continue;
        const auto lines = r.isochrone(6.0);
        ASSERT_FALSE(lines.empty());
        double dev = 0.0;
        std::size_t pts = 0;
        for (const auto &l : lines)
            for (const Point2 &p : l)
            {
                dev = std::max(dev, std::abs(std::hypot(p.x - sx - 6 * cur.first, p.y - sy - 6 * cur.second) - 3.0));
                ++pts;
            }
        EXPECT_GT(pts, 100u);
        EXPECT_LT(dev, 0.5 * lp.cellSize);
    }
}

TEST(LevelSet, BettsShearProblem)
{
    // u = -y, V = 1, (3.5, -1.8) -> (0, 0): 5.26493205 ([BettsOC] Ex. 10.148).
    auto ctx = context(std::make_shared<LinearShear>(-1.0), 1.0, -1.0, 5.0, -3.0, 2.0);
    LevelSetParams lp;
    lp.cellSize = 0.02;
    const Reachability r = LevelSetSolver(ctx, lp).solve(3.5, -1.8, 0.0, 10.0, Point2{0.0, 0.0});
    ASSERT_TRUE(r.goalReached);
    const double T = r.goalTime;
    std::printf("Betts shear: level set %.6f, optimum 5.26493205 (%.3f %%), %llu steps, %.2f s\n", T,
                100 * (T / 5.26493205 - 1), static_cast<unsigned long long>(r.stats.steps), r.stats.seconds);
    EXPECT_NEAR(T, 5.26493205, 5.26493205 * 0.003);
    // The backtracked path starts at the start, ends at the goal and is monotone in time.
    ASSERT_GE(r.path.size(), 10u);
    EXPECT_NEAR(r.path.front().x, 3.5, 1e-12);
    EXPECT_NEAR(r.path.back().x, 0.0, 1e-12);
    // Continuous and physically possible: no step faster than V + |c| (|c| = |y| <= 3 in the region).
    for (std::size_t k = 1; k < r.path.size(); ++k)
    {
        EXPECT_GE(r.path[k].t, r.path[k - 1].t);
        const double d = std::hypot(r.path[k].x - r.path[k - 1].x, r.path[k].y - r.path[k - 1].y);
        EXPECT_LE(d, (1.0 + 3.0) * (r.path[k].t - r.path[k - 1].t) * 1.05 + 1e-12) << "step " << k;
    }
}

TEST(LevelSet, MeanderingJetMatchesShooting)
{
    auto jet = std::make_shared<MeanderingJet>();
    auto ctx = context(jet, 0.5, 0, 10, -4, 4);
    LevelSetParams lp;
    lp.cellSize = 0.05;
    const LevelSetSolver solver(ctx, lp);
    const double pairs[][4] = {{1.0, -3.0, 8.0, 3.0}, {1.0, 3.0, 9.0, -2.5}, {2.0, -3.5, 7.0, 3.5},
                               {0.5, -2.0, 9.5, 2.0}, {2.0, 3.5, 8.0, -3.5}, {0.5, 3.0, 5.0, -3.0},
                               {8.0, 3.0, 2.0, -3.0}, {5.0, -3.5, 4.0, 3.5}};
    ZermeloParams zp;
    zp.speed = 0.5;
    zp.maxTime = 40.0;
    const ZermeloReference ref(jet, zp);
    for (const auto &p : pairs)
    {
        const ZermeloSolution s = ref.solve(p[0], p[1], p[2], p[3], 0.0);
        ASSERT_TRUE(s.found);
        const Reachability r = solver.solve(p[0], p[1], 0.0, 60.0, Point2{p[2], p[3]});
        ASSERT_TRUE(r.goalReached);
        const double rel = (r.goalTime - s.travelTime) / s.travelTime;
        std::printf("jet (%.1f, %.1f) -> (%.1f, %.1f): level set %.4f, shooting %.4f (%+.3f %%) in %.2f s\n", p[0],
                    p[1], p[2], p[3], r.goalTime, s.travelTime, 100 * rel, r.stats.seconds);
        EXPECT_LT(std::abs(rel), 0.003);
    }
}

TEST(LevelSet, CoarseCorridorKeepsTheGoalTimeAndSavesWork)
{
    // Coarse to fine: the corridor of routes the coarse forward and backward fronts leave open gives the same goal
    // time as the whole fine front, within the grid's own error (0.05 %; the fine front is 0.05-0.15 % slow against
    // shooting on these crossings), on the jet in open water and with two islands, for less work (the coarse
    // fronts' included).
    auto jet = std::make_shared<MeanderingJet>();
    auto islands = std::make_shared<ForbiddenRegions>();
    islands->add(std::make_shared<StaticRegion>("A", Polygon::regular(3.0, -1.6, 0.7, 40, 0.1, "A"), "island"));
    islands->add(std::make_shared<StaticRegion>(
        "B", Polygon({{5.2, -0.4}, {6.6, -0.2}, {6.8, 1.2}, {6.1, 0.5}, {5.4, 1.0}}, {}, "B"), "island"));
    const double pairs[][4] = {
        {1.0, -3.0, 8.0, 3.0}, {1.0, 3.0, 9.0, -2.5}, {8.0, 3.0, 2.0, -3.0}, {5.0, -3.5, 4.0, 3.5}};
    for (int withIslands = 0; withIslands < 2; ++withIslands)
    {
        SCOPED_TRACE(withIslands ? "islands" : "open water");
        auto ctx = context(jet, 0.5, 0, 10, -4, 4, 60.0, withIslands ? islands : nullptr);
        LevelSetParams with, without;
        with.cellSize = without.cellSize = 0.05;
        without.corridor = false;
        double workWith = 0, workWithout = 0;
        for (const auto &p : pairs)
        {
            const Reachability a = LevelSetSolver(ctx, with).solve(p[0], p[1], 0.0, 60.0, Point2{p[2], p[3]});
            const Reachability b = LevelSetSolver(ctx, without).solve(p[0], p[1], 0.0, 60.0, Point2{p[2], p[3]});
            ASSERT_TRUE(a.goalReached && b.goalReached);
            std::printf("%s (%.1f, %.1f) -> (%.1f, %.1f): corridor %.5f (%.3g updates), whole front %.5f (%.3g)\n",
                        withIslands ? "islands" : "open water", p[0], p[1], p[2], p[3], a.goalTime,
                        static_cast<double>(a.stats.nodeUpdates), b.goalTime, static_cast<double>(b.stats.nodeUpdates));
            EXPECT_NEAR(a.goalTime, b.goalTime, 5e-4 * b.goalTime);
            EXPECT_FALSE(a.path.empty());
            workWith += static_cast<double>(a.stats.nodeUpdates); // the coarse fronts' work included
            workWithout += static_cast<double>(b.stats.nodeUpdates);
        }
        EXPECT_LT(workWith, 0.8 * workWithout);
    }
}

TEST(LevelSet, WalledInStartReachesNothingOutside)
{
    // A ring-shaped island (an atoll) around the start: the goal outside is never reached, and the reached set stays
    // inside the lagoon.
    std::vector<Point2> outer, lagoon;
    for (int i = 0; i < 48; ++i)
    {
        const double a = 2 * M_PI * i / 48;
        outer.push_back({5 + 2.0 * std::cos(a), 2.0 * std::sin(a)});
        lagoon.push_back({5 + 1.0 * std::cos(a), 1.0 * std::sin(a)});
    }
    auto env = std::make_shared<ForbiddenRegions>();
    env->add(std::make_shared<StaticRegion>("ring", Polygon(outer, {lagoon}, "ring"), "island"));
    auto ctx = context(std::make_shared<UniformCurrent>(0.2, 0.0), 0.5, 0, 10, -4, 4, 60.0, env);
    LevelSetParams lp;
    lp.cellSize = 0.05;
    const Reachability r = LevelSetSolver(ctx, lp).solve(5.0, 0.0, 0.0, 30.0, Point2{9.0, 3.0});
    EXPECT_FALSE(r.goalReached);
    EXPECT_TRUE(r.path.empty());
    for (int j = 0; j < r.ny; ++j)
        for (int i = 0; i < r.nx; ++i)
        {
            if (std::isfinite(r.arrival[static_cast<std::size_t>(j) * r.nx + i]))
            {
                ASSERT_LE(std::hypot(r.x0 + i * r.h - 5, r.y0 + j * r.h), 1.0 + 1e-9);
            }
        }
}

TEST(LevelSet, ClosedLaneIsWaitedOut)
{
    // Still water, V = 0.5; the start sits in a pocket x < 3 walled by islands except for a lane x in [3, 3.5]
    // closed during t in [0, 10]. Once open, the glider crosses: the first arrival at (8, 0) is 10 + 5 / 0.5 = 20
    // (it waits at the lane's edge; the optimum is the pocket's edge point nearest the goal).
    auto env = std::make_shared<ForbiddenRegions>();
    env->add(std::make_shared<StaticRegion>("north", Polygon::rectangle(3.0, 0.5, 3.5, 5.0, "north"), "island"));
    env->add(std::make_shared<StaticRegion>("south", Polygon::rectangle(3.0, -5.0, 3.5, -0.5, "south"), "island"));
    env->add(std::make_shared<TimeWindowedZone>("lane", Polygon::rectangle(3.0, -0.5, 3.5, 0.5, "lane"),
                                                std::vector<Interval>{{0.0, 10.0}}));
    auto ctx = context(std::make_shared<UniformCurrent>(0.0, 0.0), 0.5, 0, 10, -4, 4, 60.0, env);
    LevelSetParams lp;
    lp.cellSize = 0.05;
    const Reachability r = LevelSetSolver(ctx, lp).solve(1.0, 0.0, 0.0, 40.0, Point2{8.0, 0.0});
    ASSERT_TRUE(r.goalReached);
    std::printf("closed lane: arrival %.4f (exact 20)\n", r.goalTime);
    EXPECT_NEAR(r.goalTime, 20.0, 20.0 * 0.003);
    // The path holds: some point of it is at the lane's west edge for a long time.
    double held = 0.0;
    for (std::size_t k = 1; k < r.path.size(); ++k)
        if (r.path[k].x == r.path[k - 1].x && r.path[k].y == r.path[k - 1].y)
            held += r.path[k].t - r.path[k - 1].t;
    EXPECT_GT(held, 5.0);
}

TEST(LevelSet, NodeUpdateBudgetEndsTheSameSolveAtTheSameStep)
{
    // A budget of work, not time: the solve stops at the first step that starts with the budget spent, so it ends
    // with at least that many updates and less than one step more, says so, and does the same every time (threads
    // included); the front is then short of the goal that the solve without a budget reaches.
    auto ctx = context(std::make_shared<UniformCurrent>(0.3, 0.1), 0.5, 0, 10, -5, 5);
    LevelSetParams lp;
    lp.cellSize = 0.1;
    const Reachability whole = LevelSetSolver(ctx, lp).solve(1.0, 0.0, 0.0, 30.0, Point2{9.0, 0.0});
    ASSERT_TRUE(whole.goalReached);
    EXPECT_FALSE(whole.stats.budgetSpent);
    lp.maxNodeUpdates = whole.stats.nodeUpdates / 3;
    const Reachability a = LevelSetSolver(ctx, lp).solve(1.0, 0.0, 0.0, 30.0, Point2{9.0, 0.0});
    const Reachability b = LevelSetSolver(ctx, lp).solve(1.0, 0.0, 0.0, 30.0, Point2{9.0, 0.0});
    EXPECT_TRUE(a.stats.budgetSpent);
    EXPECT_FALSE(a.goalReached);
    EXPECT_GE(a.stats.nodeUpdates, lp.maxNodeUpdates);
    EXPECT_LT(a.stats.steps, whole.stats.steps);
    // one step updates at most every node
    EXPECT_LT(a.stats.nodeUpdates, lp.maxNodeUpdates + a.stats.nodes);
    EXPECT_EQ(a.stats.steps, b.stats.steps);
    EXPECT_EQ(a.stats.nodeUpdates, b.stats.nodeUpdates);
    ASSERT_EQ(a.arrival.size(), b.arrival.size());
    for (std::size_t k = 0; k < a.arrival.size(); ++k)
        ASSERT_EQ(a.arrival[k], b.arrival[k]) << "node " << k;
}

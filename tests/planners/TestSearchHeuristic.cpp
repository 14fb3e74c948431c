// LatticeHeuristic: the jet's velocity boxes enclose sampled currents; the edge bounds never exceed the
// travel time; the heuristic never exceeds the true remaining time (TVE from the vertex, an independent exact search)
// and is consistent; and the default search (tight bounds, certified pruning) equals TVE on random pairs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <cstdio>
#include <random>

#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "planners/detail/SearchHeuristic.h" // internal to the library (src/)
#include "planners/TveSearch.h"              // internal to the library (src/)

using namespace ompl_glider;

namespace
{
GliderProblem heuristicJetProblem()
{
    GliderProblem p;
    p.field = std::make_shared<MeanderingJet>();
    p.start.x = p.start.y = p.goal.x = p.goal.y = 0.0;
    return p;
}

TveOptions heuristicTveOptions()
{
    TveOptions o;
    o.heuristic = o.zermelo = false;
    return o;
}
} // namespace

TEST(SearchHeuristic, JetBoxesEncloseSampledCurrents)
{
    const MeanderingJet jet;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(0.0, 10.0), uy(-4.0, 4.0), ut(0.0, 60.0), w(0.0, 1.0);
    int tight = 0;
    for (int c = 0; c < 200; ++c)
    {
        Region r;
        r.xMin = ux(rng);
        r.xMax = r.xMin + 0.8 * w(rng) + 1e-3;
        r.yMin = uy(rng);
        r.yMax = r.yMin + 0.8 * w(rng) + 1e-3;
        r.tMin = ut(rng);
        r.tMax = r.tMin + 20.0 * w(rng) + 1e-3;
        const VelocityBox b = currentBounds(jet, r, 8);
        for (int k = 0; k < 50; ++k)
        {
            const double x = r.xMin + (r.xMax - r.xMin) * w(rng), y = r.yMin + (r.yMax - r.yMin) * w(rng);
            const double t = r.tMin + (r.tMax - r.tMin) * w(rng);
            const Velocity v = jet.velocity(x, y, 0.0, t);
            ASSERT_GE(v.u, b.uMin);
            ASSERT_LE(v.u, b.uMax);
            ASSERT_GE(v.v, b.vMin);
            ASSERT_LE(v.v, b.vMax);
        }
        const double M = jet.maxSpeed(r);
        if (b.uMax - b.uMin < M && b.vMax - b.vMin < M)
            ++tight;
    }
    EXPECT_GT(tight, 50); // the boxes are local: narrower than the global bound on many cells
}

TEST(SearchHeuristic, EdgeBoundsNeverExceedTheTravelTime)
{
    GliderProblem p = heuristicJetProblem();
    auto ctx = makeGliderContext(p);
    Lattice lat(ctx->region.xMin, ctx->region.xMax, ctx->region.yMin, ctx->region.yMax, 0.4, 3);
    lat.setStart(1.1, 0.3); // off-grid start and goal: their edges use the generic bound
    lat.setGoal(7.3, -1.1);
    LatticeHeuristic hb(lat, *ctx->field, ctx->speed(), 0.0, 0.0, 60.0);
    std::mt19937 rng(3);
    std::uniform_int_distribution<long> ci(0, lat.nx() - 1), cj(0, lat.ny() - 1);
    std::uniform_real_distribution<double> ut(0.0, 40.0);
    int finite = 0, checked = 0;
    for (int k = 0; k < 400; ++k)
    {
        const Lattice::VertexId u = k % 40 == 0 ? lat.startExtra() : lat.gridVertex(ci(rng), cj(rng));
        const double t = ut(rng);
        lat.forEachSuccessor(u, [&](Lattice::VertexId v) {
            if (rng() % 8 != 0 && v != lat.goal())
                return;
            const double w = ctx->travel->travelTime(lat.x(u), lat.y(u), lat.x(v), lat.y(v), t);
            const double lb = hb.edgeLowerBound(u, v);
            ++checked;
            if (std::isfinite(w))
                ++finite;
            ASSERT_LE(lb, w * (1.0 + 1e-12)) << u << " -> " << v << " at " << t;
            // never weaker than [EichhornRAS] Eq. 1's bound
            const double len = std::hypot(lat.x(v) - lat.x(u), lat.y(v) - lat.y(u));
            ASSERT_GE(lb, len / (ctx->speed() + ctx->maxCurrent()) * (1.0 - 1e-9));
        });
    }
    EXPECT_GT(checked, 500);
    EXPECT_GT(finite, 300);
}

TEST(SearchHeuristic, NeverAboveTheTrueRemainingTimeAndConsistent)
{
    // Admissibility: h(v) <= the lattice optimum from v to the goal, which TVE (an exact search that does not use
    // the bounds) computes, on random vertices and departure times. Consistency: h(u) <= w(u, v, t) + h(v).
    GliderProblem p = heuristicJetProblem();
    auto ctx = makeGliderContext(p);
    TveSearch exact(ctx, 0.4, 3);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ux(0.0, 10.0), uy(-4.0, 4.0), ut(0.0, 20.0);
    std::uniform_int_distribution<long> ci(0, 25), cj(0, 20);
    double sumH = 0, sumE = 0, sumT = 0;
    int compared = 0;
    for (int goal = 0; goal < 8; ++goal)
    {
        const double gx = goal % 2 ? ux(rng) : 0.4 * static_cast<double>(ci(rng) % 25);
        const double gy = goal % 2 ? uy(rng) : -4.0 + 0.4 * static_cast<double>(cj(rng) % 20);
        Lattice lat(ctx->region.xMin, ctx->region.xMax, ctx->region.yMin, ctx->region.yMax, 0.4, 3);
        lat.setStart(0.0, 0.0);
        ASSERT_NE(lat.setGoal(gx, gy), Lattice::kNone);
        LatticeHeuristic hb(lat, *ctx->field, ctx->speed(), 0.0, 0.0, ctx->region.tMax);
        hb.reset({});
        for (int k = 0; k < 10; ++k)
        {
            const Lattice::VertexId v = lat.gridVertex(ci(rng) % lat.nx(), cj(rng) % lat.ny());
            const double t = ut(rng);
            const TveResult r = exact.run(lat.x(v), lat.y(v), t, gx, gy, heuristicTveOptions());
            const double h = hb(v);
            if (r.outcome != TveOutcome::Exact)
                continue;
            ++compared;
            EXPECT_LE(h, r.travelTime * (1.0 + 1e-12))
                << "v (" << lat.x(v) << ", " << lat.y(v) << ") t " << t << " goal (" << gx << ", " << gy << ")";
            const double e = std::hypot(lat.x(v) - gx, lat.y(v) - gy) / (ctx->speed() + ctx->maxCurrent());
            EXPECT_GE(h, e * (1.0 - 1e-9));
            sumH += h;
            sumE += e;
            sumT += r.travelTime;
            // consistency on the edges leaving v
            lat.forEachSuccessor(v, [&](Lattice::VertexId w) {
                const double tw = ctx->travel->travelTime(lat.x(v), lat.y(v), lat.x(w), lat.y(w), t);
                if (std::isfinite(tw))
                {
                    EXPECT_LE(h, tw + hb(w) + 1e-12 * (1.0 + h));
                }
            });
        }
    }
    EXPECT_GE(compared, 50);
    // tighter than [EichhornRAS] Eq. 1 on these vertices (it is 1.0 x Eq. 1 at worst by construction)
    std::printf("sum h %.3f, Eq. 1 %.3f, true %.3f\n", sumH, sumE, sumT);
    EXPECT_GT(sumH, 1.2 * sumE) << "h " << sumH << " Eq. 1 " << sumE << " true " << sumT;
}

TEST(SearchHeuristic, DefaultSearchEqualsTveOnRandomPairs)
{
    // The default options (tight bounds, certified Zermelo pruning with tolerance 0) return TVE's lattice optimum
    // within 1e-9 relative, on random pairs (grid and off-grid points) and departure times, with fewer CFC in total.
    GliderProblem p = heuristicJetProblem();
    auto ctx = makeGliderContext(p);
    TveSearch search(ctx, 0.4, 3);
    TveOptions astar; // A* with the tight heuristic, no pruning
    astar.zermelo = false;
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> ux(0.2, 9.8), uy(-3.8, 3.8), ut(0.0, 10.0);
    std::uniform_int_distribution<int> ci(1, 24), cj(1, 19);
    std::uint64_t cfcTve = 0, cfcDefault = 0;
    int compared = 0;
    for (int i = 0; i < 14; ++i)
    {
        const bool grid = i % 2 == 0;
        const double sx = grid ? 0.4 * ci(rng) : ux(rng), sy = grid ? -4.0 + 0.4 * cj(rng) : uy(rng);
        const double gx = grid ? 0.4 * ci(rng) : ux(rng), gy = grid ? -4.0 + 0.4 * cj(rng) : uy(rng);
        const double t0 = i % 3 == 0 ? ut(rng) : 0.0;
        const TveResult a = search.run(sx, sy, t0, gx, gy, heuristicTveOptions());
        const TveResult b = search.run(sx, sy, t0, gx, gy, TveOptions{});
        const TveResult c = search.run(sx, sy, t0, gx, gy, astar);
        ASSERT_EQ(a.outcome, b.outcome);
        ASSERT_EQ(a.outcome, c.outcome);
        if (a.outcome != TveOutcome::Exact)
            continue;
        ++compared;
        EXPECT_NEAR(b.travelTime, a.travelTime, 1e-9 * a.travelTime)
            << "(" << sx << ", " << sy << ") -> (" << gx << ", " << gy << ") t0 " << t0;
        EXPECT_NEAR(c.travelTime, a.travelTime, 1e-9 * a.travelTime);
        EXPECT_NEAR(b.waypoints.back().t - t0, b.travelTime, 1e-12 * b.travelTime);
        cfcTve += a.costFunctionCalls;
        cfcDefault += b.costFunctionCalls;
    }
    EXPECT_GE(compared, 10);
    EXPECT_LT(cfcDefault, cfcTve);
}

TEST(SearchHeuristic, UniformCurrentAgainstTheCurrentIsBoundedByTheSlowSpeed)
{
    // In a uniform current c = (0.3, 0) with V = 0.5, a leg due west progresses at 0.2: the edge bound along x is
    // exactly 0.4 / 0.2 (the fallback box is [-0.3, 0.3]^2, so the bound is 0.4 / 0.8 there).
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(0.3, 0.0);
    p.start.x = p.start.y = p.goal.x = p.goal.y = 0.0;
    auto ctx = makeGliderContext(p);
    Lattice lat(ctx->region.xMin, ctx->region.xMax, ctx->region.yMin, ctx->region.yMax, 0.4, 3);
    LatticeHeuristic hb(lat, *ctx->field, ctx->speed(), 0.0, 0.0, 60.0);
    const Lattice::VertexId a = lat.gridVertex(5, 5), b = lat.gridVertex(4, 5);
    const double w = ctx->travel->travelTime(lat.x(a), lat.y(a), lat.x(b), lat.y(b), 0.0);
    EXPECT_NEAR(w, 0.4 / 0.2, 1e-9);
    const double lb = hb.edgeLowerBound(a, b);
    EXPECT_LE(lb, w);
    EXPECT_NEAR(lb, 0.4 / 0.8, 1e-9);
}

TEST(SearchHeuristic, DeadlineKeepsTheOptimumOrExhausts)
{
    // A deadline at TVE's arrival gives TVE's travel time (the labels up to the deadline do not depend on later
    // arrivals); one just below it leaves no path. Also with the bounds narrowed to the deadline's corridor.
    GliderProblem p = heuristicJetProblem();
    auto ctx = makeGliderContext(p);
    TveSearch search(ctx, 0.4, 3);
    const double sx = 8.8, sy = -1.2, gx = 1.6, gy = 0.4; // goal upstream of the start
    const TveResult tve = search.run(sx, sy, 0.0, gx, gy, heuristicTveOptions());
    ASSERT_EQ(tve.outcome, TveOutcome::Exact);
    for (bool tight : {false, true})
    {
        TveOptions o;
        o.tightBounds = tight;
        o.deadline = tve.travelTime;
        const TveResult at = search.run(sx, sy, 0.0, gx, gy, o);
        ASSERT_EQ(at.outcome, TveOutcome::Exact) << tight;
        EXPECT_NEAR(at.travelTime, tve.travelTime, 1e-9 * tve.travelTime);
        o.deadline = tve.travelTime * (1.0 - 1e-6);
        EXPECT_EQ(search.run(sx, sy, 0.0, gx, gy, o).outcome, TveOutcome::Exhausted) << tight;
    }
}

TEST(SearchHeuristic, StopRequestEndsTheSetupAndLeavesLowerBounds)
{
    // A stop answered during the bounds' setup (the cell boxes, the backward search) ends it: no further box is
    // computed, h() answers 0 for a vertex it has not settled (a lower bound), and a search whose stop answers true
    // once the setup has begun ends Terminated before any backward search or expansion (it used to build every box
    // and settle the backward search first, a minute on a fine lattice).
    GliderProblem p = heuristicJetProblem();
    auto ctx = makeGliderContext(p);
    Lattice lat(ctx->region.xMin, ctx->region.xMax, ctx->region.yMin, ctx->region.yMax, 0.1, 3);
    lat.setStart(0.5, -3.0);
    ASSERT_NE(lat.setGoal(9.5, 3.0), Lattice::kNone);
    const LatticeHeuristic full(lat, *ctx->field, ctx->speed(), 0.0, 0.0, 60.0);
    ASSERT_TRUE(full.informative()); // the jet's local boxes are narrower than its global bound
    int asked = 0;
    LatticeHeuristic stopped(lat, *ctx->field, ctx->speed(), 0.0, 0.0, 60.0, 0, nullptr, [&asked] {
        ++asked;
        return true;
    });
    EXPECT_FALSE(stopped.informative()) << "boxes were computed after the stop";
    EXPECT_EQ(asked, 1);
    stopped.reset({});
    const Lattice::VertexId far = lat.gridVertex(0, 0);
    EXPECT_EQ(stopped(far), 0.0);
    EXPECT_LT(stopped.settled(), 4096u); // the backward search asked the stop and ended
    // the search: its stop turns true on its first question after the setup began
    TveSearch search(ctx, 0.1, 3);
    TveOptions o; // the default: A* with the lattice's bounds
    int questions = 0;
    const TveResult r = search.run(0.5, -3.0, 0.0, 9.5, 3.0, o, [&questions] { return ++questions > 1; });
    EXPECT_EQ(r.outcome, TveOutcome::Terminated);
    EXPECT_EQ(r.heuristicSettled, 0u); // no backward search, no expansion after the stop
    EXPECT_EQ(r.expansions, 0u);
    // and a search after it, not stopped, builds its bounds afresh and finds the route
    const TveResult again = search.run(0.5, -3.0, 0.0, 9.5, 3.0, o);
    EXPECT_EQ(again.outcome, TveOutcome::Exact);
    EXPECT_GT(again.heuristicSettled, 0u);
}

// On a gridded forecast (two meanders, one reversed, and two islands; non-uniform x axis; six records):
// - the gridded field's local bounds (GriddedCurrentField::velocityBounds, rectilinear and curvilinear) enclose every
// velocity() value of their
//   region, and are refused where the schemes could overshoot the nodes;
// - the lattice heuristic built from them never exceeds the true remaining time (TVE from the vertex) and the
//   default search still equals TVE;
// - coarse-to-fine (TveOptions::coarseFactor) returns the full fine search's travel time on random pairs, widening
//   its corridor where the fine path reaches the corridor's outer ring, and reports no path where there is none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>

#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "planners/detail/SearchHeuristic.h" // internal to the library (src/)
#include "planners/TveSearch.h"              // internal to the library (src/)

using namespace ompl_glider;

namespace
{
bool onIsland(double x, double y)
{
    return std::hypot(x - 7.0, y - 1.0) < 1.6 || std::hypot(x - 14.0, y + 2.5) < 1.2;
}

/// A forecast in the layout of a regional model: rectilinear, x spacing growing eastwards, land nodes masked.
GriddedData forecastData()
{
    GriddedData d;
    d.nx = 81;
    d.ny = 61;
    for (std::size_t i = 0; i < d.nx; ++i)
    {
        const double s = double(i) / double(d.nx - 1);
        d.x.push_back(20.0 * (0.8 * s + 0.2 * s * s));
    }
    for (std::size_t j = 0; j < d.ny; ++j)
        d.y.push_back(-7.5 + 0.25 * double(j));
    d.time = {0.0, 5.0, 10.0, 15.0, 20.0, 25.0};
    const MeanderingJet jet;
    for (double t : d.time)
        for (std::size_t j = 0; j < d.ny; ++j)
            for (std::size_t i = 0; i < d.nx; ++i)
            {
                const double x = d.x[i], y = d.y[j];
                const Velocity a = jet.velocity(x, y - 3.0, 0.0, t);
                const Velocity b = jet.velocity(x + 2.0, y + 3.5, 0.0, t);
                d.u.push_back(static_cast<float>(0.35 * (a.u - b.u)));
                d.v.push_back(static_cast<float>(0.35 * (a.v - b.v)));
            }
    for (std::size_t j = 0; j < d.ny; ++j)
        for (std::size_t i = 0; i < d.nx; ++i)
            d.water.push_back(onIsland(d.x[i], d.y[j]) ? 0 : 1);
    return d;
}

std::shared_ptr<GriddedCurrentField> forecast(GriddedFieldOptions o = {})
{
    o.beyond = BeyondForecast::HoldLast;
    return std::make_shared<GriddedCurrentField>(forecastData(), o);
}

std::shared_ptr<const GliderContext> context(std::shared_ptr<const CurrentField> field)
{
    GliderProblem p;
    p.field = std::move(field);
    p.xMin = 0.0;
    p.xMax = 20.0;
    p.yMin = -7.5;
    p.yMax = 7.5;
    p.horizon = 200.0;
    p.travel.speed = 0.5;
    p.start.x = 1.0;
    p.start.y = 0.0;
    p.goal.x = 19.0;
    p.goal.y = 0.0;
    return makeGliderContext(p);
}

TveOptions tveOptions()
{
    TveOptions o;
    o.heuristic = o.zermelo = false;
    o.coarseFactor = 1;
    return o;
}

/// Random water points away from the islands' coasts.
struct WaterPoints
{
    std::mt19937 rng;
    std::uniform_real_distribution<double> ux{0.3, 19.7}, uy{-7.2, 7.2};
    explicit WaterPoints(unsigned seed) : rng(seed) {}
    void next(double &x, double &y)
    {
        do
        {
            x = ux(rng);
            y = uy(rng);
        } while (std::hypot(x - 7.0, y - 1.0) < 2.3 || std::hypot(x - 14.0, y + 2.5) < 1.9);
    }
};
} // namespace

TEST(GriddedBounds, EncloseEveryInterpolatedVelocityOfTheRegion)
{
    const auto field = forecast();
    ASSERT_TRUE(field->hasVelocityBounds());
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ux(-1.0, 21.0), uy(-8.0, 8.0), ut(-3.0, 30.0), w(0.0, 1.0);
    int narrow = 0;
    for (int c = 0; c < 300; ++c)
    {
        Region r;
        r.xMin = ux(rng);
        r.xMax = r.xMin + 2.0 * w(rng);
        r.yMin = uy(rng);
        r.yMax = r.yMin + 2.0 * w(rng);
        r.tMin = ut(rng);
        r.tMax = r.tMin + 8.0 * w(rng);
        double a, b, cc, d;
        ASSERT_TRUE(field->velocityBounds(r, a, b, cc, d));
        for (int k = 0; k < 60; ++k)
        {
            // corners and edges too (queries outside the grid or the records are clamped by the field)
            const double fx = k < 4 ? double(k % 2) : w(rng), fy = k < 4 ? double(k / 2) : w(rng);
            const double x = r.xMin + (r.xMax - r.xMin) * fx, y = r.yMin + (r.yMax - r.yMin) * fy;
            const double t = r.tMin + (r.tMax - r.tMin) * (k % 5 == 0 ? 1.0 : w(rng));
            const Velocity v = field->velocity(x, y, 0.0, t);
            ASSERT_GE(v.u, a) << x << " " << y << " " << t;
            ASSERT_LE(v.u, b);
            ASSERT_GE(v.v, cc);
            ASSERT_LE(v.v, d);
        }
        const double M = field->maxSpeed(r);
        if (b - a < M && d - cc < M)
            ++narrow;
    }
    EXPECT_GT(narrow, 100); // local: narrower than the field's own bound on many regions

    // schemes that can overshoot the nodes get no local bound
    GriddedFieldOptions cubic;
    cubic.xy = Interp2D::Bicubic;
    EXPECT_FALSE(forecast(cubic)->hasVelocityBounds());
    GriddedFieldOptions akima;
    akima.time = Interp1D::Akima;
    Region any;
    double a, b, c, d;
    EXPECT_FALSE(forecast(akima)->velocityBounds(any, a, b, c, d));
    EXPECT_TRUE(LatticeHeuristic::hasLocalBounds(*forecast()));
    EXPECT_FALSE(LatticeHeuristic::hasLocalBounds(*forecast(cubic)));
}

TEST(GriddedBounds, CurvilinearGridBoundsEncloseTheInterpolatedVelocity)
{
    // the same data on a curved, rotated grid (as a geographic forecast looks after projection)
    GriddedData d = forecastData();
    const double th = 0.3;
    for (std::size_t j = 0; j < d.ny; ++j)
        for (std::size_t i = 0; i < d.nx; ++i)
        {
            const double x = d.x[i], y = d.y[j];
            d.nodeX.push_back(x * std::cos(th) - y * std::sin(th) + 0.01 * y * y);
            d.nodeY.push_back(x * std::sin(th) + y * std::cos(th) + 0.015 * x * x);
        }
    d.x.clear();
    d.y.clear();
    const std::vector<double> nodeX = d.nodeX, nodeY = d.nodeY;
    GriddedFieldOptions o;
    o.beyond = BeyondForecast::HoldLast;
    const GriddedCurrentField field(std::move(d), o);
    ASSERT_TRUE(field.hasVelocityBounds());
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> ux(-6.0, 22.0), uy(-6.0, 20.0), ut(-3.0, 30.0), w(0.0, 1.0);
    int local = 0;
    Region all;
    double ga, gb, gc, gd;
    ASSERT_TRUE(field.velocityBounds(all, ga, gb, gc, gd)); // everywhere: the whole grid's extremes
    for (int c = 0; c < 400; ++c)
    {
        Region r;
        r.xMin = ux(rng);
        r.xMax = r.xMin + 1.5 * w(rng);
        r.yMin = uy(rng);
        r.yMax = r.yMin + 1.5 * w(rng);
        r.tMin = ut(rng);
        r.tMax = r.tMin + 8.0 * w(rng);
        double a, b, cc, dd;
        ASSERT_TRUE(field.velocityBounds(r, a, b, cc, dd));
        for (int k = 0; k < 60; ++k)
        {
            const double fx = k < 4 ? double(k % 2) : w(rng), fy = k < 4 ? double(k / 2) : w(rng);
            const double x = r.xMin + (r.xMax - r.xMin) * fx, y = r.yMin + (r.yMax - r.yMin) * fy;
            const double t = r.tMin + (r.tMax - r.tMin) * (k % 5 == 0 ? 1.0 : w(rng));
            const Velocity v = field.velocity(x, y, 0.0, t);
            ASSERT_GE(v.u, a) << x << " " << y << " " << t;
            ASSERT_LE(v.u, b) << x << " " << y << " " << t;
            ASSERT_GE(v.v, cc) << x << " " << y << " " << t;
            ASSERT_LE(v.v, dd) << x << " " << y << " " << t;
        }
    }
    // regions well inside the grid (centred on nodes at least 18 cells from its edge) get local bounds: within the
    // extremes of the nodes at most 16 cells (two blocks) away, over the two records of the window
    const GriddedData ref = forecastData();
    std::uniform_int_distribution<std::size_t> ni(18, 62), nj(18, 40); // a block away from the edge blocks
    for (int c = 0; c < 100; ++c)
    {
        const std::size_t i0 = ni(rng), j0 = nj(rng), n = j0 * 81 + i0;
        double lu = 1e9, hu = -1e9, lv = 1e9, hv = -1e9;
        for (std::size_t rec = 0; rec < 2; ++rec)
            for (std::size_t j = j0 >= 16 ? j0 - 16 : 0; j <= std::min<std::size_t>(60, j0 + 16); ++j)
                for (std::size_t i = i0 >= 16 ? i0 - 16 : 0; i <= std::min<std::size_t>(80, i0 + 16); ++i)
                {
                    const std::size_t q = (rec * 61 + j) * 81 + i;
                    lu = std::min(lu, double(ref.u[q]));
                    hu = std::max(hu, double(ref.u[q]));
                    lv = std::min(lv, double(ref.v[q]));
                    hv = std::max(hv, double(ref.v[q]));
                }
        Region r;
        const double cx = nodeX[n], cy = nodeY[n];
        r.xMin = cx - 0.25;
        r.xMax = cx + 0.25;
        r.yMin = cy - 0.25;
        r.yMax = cy + 0.25;
        r.tMin = 0.0;
        r.tMax = 4.9; // records 0 and 1
        double a, b, cc, dd;
        ASSERT_TRUE(field.velocityBounds(r, a, b, cc, dd));
        if (a >= lu - 1e-6 && b <= hu + 1e-6 && cc >= lv - 1e-6 && dd <= hv + 1e-6)
            ++local;
    }
    EXPECT_GE(local, 95);
}

TEST(GriddedBounds, HeuristicNeverAboveTheTrueRemainingTimeAndSearchEqualsTve)
{
    const auto ctx = context(forecast());
    TveSearch search(ctx, 0.5, 3);
    WaterPoints pts(17);
    std::uniform_real_distribution<double> ut(0.0, 10.0);
    double sumH = 0, sumE = 0;
    int compared = 0;
    std::uint64_t cfcTve = 0, cfcDefault = 0;
    for (int goal = 0; goal < 6; ++goal)
    {
        double gx, gy;
        pts.next(gx, gy);
        Lattice lat(ctx->region.xMin, ctx->region.xMax, ctx->region.yMin, ctx->region.yMax, 0.5, 3);
        lat.setStart(1.0, 0.0);
        ASSERT_NE(lat.setGoal(gx, gy), Lattice::kNone);
        LatticeHeuristic hb(lat, *ctx->field, ctx->speed(), 0.0, 0.0, ctx->region.tMax);
        ASSERT_TRUE(hb.informative());
        hb.reset({});
        for (int k = 0; k < 5; ++k)
        {
            double sx, sy;
            pts.next(sx, sy);
            const Lattice::VertexId v = lat.gridVertex(std::lround(sx / 0.5), std::lround((sy + 7.5) / 0.5));
            const double t = ut(pts.rng);
            const TveResult r = search.run(lat.x(v), lat.y(v), t, gx, gy, tveOptions());
            if (r.outcome != TveOutcome::Exact)
                continue;
            ++compared;
            const double h = hb(v);
            EXPECT_LE(h, r.travelTime * (1.0 + 1e-12)) << "(" << lat.x(v) << ", " << lat.y(v) << ") t " << t;
            sumH += h;
            sumE += std::hypot(lat.x(v) - gx, lat.y(v) - gy) / (ctx->speed() + ctx->maxCurrent());
            cfcTve += r.costFunctionCalls;
            // the default search (these bounds, certified pruning) returns the same lattice optimum
            const TveResult b = search.run(lat.x(v), lat.y(v), t, gx, gy, TveOptions{});
            ASSERT_EQ(b.outcome, TveOutcome::Exact);
            EXPECT_NEAR(b.travelTime, r.travelTime, 1e-9 * r.travelTime);
            cfcDefault += b.costFunctionCalls;
        }
    }
    EXPECT_GE(compared, 20);
    EXPECT_GT(sumH, 1.1 * sumE); // tighter than [EichhornRAS] Eq. 1 on these vertices
    EXPECT_LT(2 * cfcDefault, cfcTve);
}

TEST(CoarseToFine, EqualsTheFullFineSearchOnRandomPairs)
{
    const auto ctx = context(forecast());
    TveSearch search(ctx, 0.1, 3); // 201 x 151 vertices
    TveOptions full;
    full.coarseFactor = 1;
    TveOptions c2f;
    c2f.coarseFactor = 4;
    c2f.corridorBlocks = 1; // a narrow first corridor: the widening must do its work
    WaterPoints pts(23);
    std::uniform_real_distribution<double> ut(0.0, 10.0);
    int compared = 0, widened = 0;
    std::uint64_t cfcFull = 0, cfcC2f = 0;
    for (int k = 0; k < 12; ++k)
    {
        double sx, sy, gx, gy;
        pts.next(sx, sy);
        pts.next(gx, gy);
        const double t0 = k % 3 == 0 ? ut(pts.rng) : 0.0;
        const TveResult a = search.run(sx, sy, t0, gx, gy, full);
        const TveResult b = search.run(sx, sy, t0, gx, gy, c2f);
        ASSERT_EQ(a.outcome, b.outcome);
        EXPECT_EQ(a.corridorRounds, 0u);
        if (a.outcome != TveOutcome::Exact)
            continue;
        ++compared;
        EXPECT_NEAR(b.travelTime, a.travelTime, 1e-9 * a.travelTime)
            << "(" << sx << ", " << sy << ") -> (" << gx << ", " << gy << ") t0 " << t0;
        EXPECT_GE(b.corridorRounds, 1u);
        if (b.corridorRounds > 1)
            ++widened;
        // the path is the lattice path timed by the legs: it ends at the goal at t0 + travel time
        ASSERT_GE(b.waypoints.size(), 2u);
        EXPECT_NEAR(b.waypoints.back().x, gx, 1e-9);
        EXPECT_NEAR(b.waypoints.back().t - t0, b.travelTime, 1e-9 * b.travelTime);
        cfcFull += a.costFunctionCalls;
        cfcC2f += b.costFunctionCalls;
    }
    EXPECT_GE(compared, 10);
    EXPECT_GE(widened, 1);
    EXPECT_LT(cfcC2f, cfcFull);
}

TEST(CoarseToFine, NoPathWhenTheGoalIsWalledIn)
{
    // the goal sits in a lagoon of the first island (water nodes ringed by land): no lattice path reaches it
    GriddedData d = forecastData();
    for (std::size_t j = 0; j < d.ny; ++j)
        for (std::size_t i = 0; i < d.nx; ++i)
        {
            const double r = std::hypot(d.x[i] - 7.0, d.y[j] - 1.0);
            d.water[j * d.nx + i] = r < 0.8 || r > 1.6 ? 1 : 0;
        }
    GriddedFieldOptions o;
    o.beyond = BeyondForecast::HoldLast;
    const auto ctx = context(std::make_shared<GriddedCurrentField>(std::move(d), o));
    TveSearch search(ctx, 0.1, 3);
    TveOptions c2f;
    c2f.coarseFactor = 4;
    const TveResult r = search.run(2.0, 0.0, 0.0, 7.0, 1.0, c2f);
    EXPECT_EQ(r.outcome, TveOutcome::Exhausted);
    TveOptions full;
    full.coarseFactor = 1;
    EXPECT_EQ(search.run(2.0, 0.0, 0.0, 7.0, 1.0, full).outcome, TveOutcome::Exhausted);
}

// Tests of the optimal departure time search ([EichhornRAS] Sec. 5): Akima curve, Brent's method, the whole scheme
// against brute force on functions with several local minima.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/AkimaSpline.h"
#include "ompl_glider/mission/DepartureTimeSearch.h"

using namespace ompl_glider;

TEST(AkimaSpline, ReproducesLinesAndDoesNotOvershootSteps)
{
    const AkimaSpline line({0, 1, 2.5, 4, 7}, {1, 3, 6, 9, 15});
    for (double q = 0; q <= 7; q += 0.13)
        EXPECT_NEAR(line(q), 1 + 2 * q, 1e-12);
    // A step (tide-like): Akima stays within the data's range and flat where the data are flat.
    const AkimaSpline step({0, 1, 2, 3, 4, 5, 6}, {0, 0, 0, 1, 1, 1, 1});
    for (double q = 0; q <= 6; q += 0.01)
    {
        EXPECT_GE(step(q), -1e-12);
        EXPECT_LE(step(q), 1 + 1e-12);
    }
    EXPECT_NEAR(step(0.5), 0.0, 1e-12);
    EXPECT_NEAR(step(1.5), 0.0, 1e-12);
    EXPECT_NEAR(step(4.5), 1.0, 1e-12);
    // Interpolates the nodes.
    const AkimaSpline s({0, 1, 2, 3, 4}, {4, 1, 0.5, 2, 3});
    EXPECT_DOUBLE_EQ(s(2), 0.5);
    const auto m = s.minimum();
    EXPECT_GT(m.first, 1.0);
    EXPECT_LT(m.first, 3.0);
    EXPECT_LE(m.second, 0.5);
    for (double q = 0; q <= 4; q += 0.001)
        EXPECT_GE(s(q), m.second - 1e-12);
    EXPECT_THROW(AkimaSpline({0, 0}, {1, 2}), Error);
}

TEST(Brent, FindsParabolaMinimumQuickly)
{
    std::vector<DepartureSample> calls;
    const auto r =
        brentMinimize([](double x) { return 3 + (x - 1.234567) * (x - 1.234567); }, -2, 5, -2, 1e-8, 60, &calls);
    EXPECT_NEAR(r.first, 1.234567, 1e-6);
    EXPECT_NEAR(r.second, 3.0, 1e-12);
    EXPECT_LE(calls.size(), 12u);
    // Impassable (infinite) on the left part: still converges to the finite minimum.
    const auto s = brentMinimize(
        [](double x) { return x < 0.5 ? std::numeric_limits<double>::infinity() : 2 + std::abs(x - 0.8); }, 0, 3, 0.1,
        1e-6, 80);
    EXPECT_NEAR(s.first, 0.8, 1e-4);
}

namespace
{
/// Travel time against departure with several local minima, period of the meandering jet (2 pi / 0.4).
double wavy(double t)
{
    return 20.0 + 3.0 * std::sin(0.4 * t + 0.3) + 1.2 * std::sin(1.1 * t + 2.0) + 0.02 * t;
}
} // namespace

TEST(DepartureTime, MatchesBruteForceWithAFifthOfTheEvaluations)
{
    DepartureSearchParams p;
    p.windowBegin = 0.0;
    p.windowEnd = 16.0;
    p.spacing = 1.0;
    p.tolerance = 1e-4;
    p.threads = 2;
    std::atomic<int> calls{0};
    auto f = [&](double t) {
        ++calls;
        return wavy(t);
    };
    const DepartureSearchResult r = optimalDepartureTime(f, p);
    ASSERT_TRUE(r.found);
    DepartureSearchParams bp = p;
    bp.spacing = 0.01;
    const DepartureSearchResult b = bruteForceDepartureTime(wavy, bp);
    ASSERT_TRUE(b.found);
    EXPECT_EQ(b.fineEvaluations, 1601u);
    EXPECT_LE(r.travelTime, b.travelTime + 1e-4); // at least as good as the 0.01 sweep (to its resolution)
    EXPECT_NEAR(r.departure, b.departure, 0.011);
    EXPECT_EQ(static_cast<std::size_t>(calls.load()), r.fineEvaluations);
    EXPECT_EQ(r.supportingPoints.size(), 17u);
    EXPECT_LE(r.fineEvaluations, 17u + p.maxBrentEvaluations);
    EXPECT_LE(r.fineEvaluations * 5, static_cast<std::size_t>(161)); // a fifth of a 0.1 sweep
    EXPECT_GE(r.departure, r.bracketLo);
    EXPECT_LE(r.departure, r.bracketHi);
}

TEST(DepartureTime, CoarseSupportingPointsAndFineRefinement)
{
    DepartureSearchParams p;
    p.windowBegin = 0.0;
    p.windowEnd = 16.0;
    p.spacing = 0.8;
    p.tolerance = 1e-5;
    // The coarse search is biased (a coarser graph is slower everywhere), its shape is right.
    std::atomic<int> coarseCalls{0};
    auto coarse = [&](double t) {
        ++coarseCalls;
        return 1.05 * wavy(t) + 0.3;
    };
    const DepartureSearchResult r = optimalDepartureTime(wavy, p, coarse);
    ASSERT_TRUE(r.found);
    EXPECT_EQ(r.coarseEvaluations, static_cast<std::size_t>(coarseCalls.load()));
    EXPECT_EQ(r.coarseEvaluations, 21u);
    EXPECT_EQ(r.fineEvaluations, r.refinements.size());
    DepartureSearchParams bp = p;
    bp.spacing = 0.001;
    const DepartureSearchResult b = bruteForceDepartureTime(wavy, bp);
    EXPECT_NEAR(r.travelTime, b.travelTime, 1e-6);
    for (const auto &s : r.supportingPoints)
        EXPECT_TRUE(s.coarse);
}

TEST(DepartureTime, HorizonCutsTheWindow)
{
    // Travel time decreasing with the departure: the best departure is the latest one the forecast still covers.
    auto f = [](double t) { return 10.0 - 0.2 * t; };
    DepartureSearchParams p;
    p.windowBegin = 0.0;
    p.windowEnd = 30.0;
    p.spacing = 1.0;
    p.tolerance = 1e-6;
    p.horizon = 20.0;        // t + 10 - 0.2 t <= 20  <=>  t <= 12.5
    p.minTripDuration = 4.0; // window cut at 16
    const DepartureSearchResult r = optimalDepartureTime(f, p);
    EXPECT_DOUBLE_EQ(r.windowEnd, 16.0);
    ASSERT_TRUE(r.found);
    EXPECT_NEAR(r.departure, 12.5, 1e-4);
    EXPECT_LE(r.departure + r.travelTime, p.horizon + 1e-12);
    for (const auto &s : r.supportingPoints)
        EXPECT_EQ(std::isinf(s.travelTime), s.tDep > 12.5) << s.tDep;
    // No departure covered at all.
    p.horizon = 3.0;
    const DepartureSearchResult none = optimalDepartureTime(f, p);
    EXPECT_FALSE(none.found);
    EXPECT_EQ(none.fineEvaluations, 0u);
    DepartureSearchParams reversed;
    reversed.windowEnd = -1.0;
    EXPECT_THROW(optimalDepartureTime(f, reversed), Error);
}

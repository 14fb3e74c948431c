// Forbidden regions: point-in-polygon with holes, segment crossing / touching / inside (closed sets), the grid
// index against a brute-force reference on a 5000-vertex coastline, time-windowed zones with analytic times, ice
// zones drifting at constant velocity (closed-form time under ice, limit just above / below), ice carried by the
// current (against an independent fine RK4), the composite's messages, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/Polygon.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"

using namespace ompl_glider;

namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Square [0,4]^2 with the square hole [1,3]^2.
Polygon squareWithHole()
{
    return Polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}, "frame");
}

// Star-shaped polygon r(theta) around the origin with n vertices; the reference test uses the star property.
struct Star
{
    std::vector<double> theta, r;
    Polygon polygon() const
    {
        std::vector<Point2> ring;
        for (std::size_t i = 0; i < theta.size(); ++i)
            ring.push_back({r[i] * std::cos(theta[i]), r[i] * std::sin(theta[i])});
        return Polygon(ring, {}, "star");
    }
    // Independent reference: inside iff the point's radius is below the edge crossed by the ray from the origin.
    bool inside(double x, double y) const
    {
        const double a = std::atan2(y, x) < 0 ? std::atan2(y, x) + 2 * M_PI : std::atan2(y, x);
        const std::size_t n = theta.size();
        std::size_t i = std::upper_bound(theta.begin(), theta.end(), a) - theta.begin();
        const std::size_t i0 = (i + n - 1) % n, i1 = i % n;
        const double ax = r[i0] * std::cos(theta[i0]), ay = r[i0] * std::sin(theta[i0]);
        const double bx = r[i1] * std::cos(theta[i1]), by = r[i1] * std::sin(theta[i1]);
        // ray (cos a, sin a) s meets the edge a + u (b - a): s = cross(a, b - a) / cross(d, b - a)
        const double ex = bx - ax, ey = by - ay, dx = std::cos(a), dy = std::sin(a);
        const double s = (ax * ey - ay * ex) / (dx * ey - dy * ex);
        return std::hypot(x, y) < s;
    }
};

Star makeStar(int n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> rad(0.6, 1.0);
    Star s;
    for (int i = 0; i < n; ++i)
    {
        s.theta.push_back(2 * M_PI * (i + 0.5) / n);
        s.r.push_back(rad(rng));
    }
    return s;
}

bool properCross(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy)
{
    auto o = [](double px, double py, double qx, double qy, double rx, double ry) {
        return (qx - px) * (ry - py) - (qy - py) * (rx - px);
    };
    const double o1 = o(ax, ay, bx, by, cx, cy), o2 = o(ax, ay, bx, by, dx, dy);
    const double o3 = o(cx, cy, dx, dy, ax, ay), o4 = o(cx, cy, dx, dy, bx, by);
    return o1 * o2 < 0 && o3 * o4 < 0;
}
} // namespace

TEST(Polygon, PointInPolygonWithHole)
{
    const Polygon p = squareWithHole();
    EXPECT_DOUBLE_EQ(p.area(), 12.0);
    EXPECT_EQ(p.holeCount(), 1u);
    EXPECT_TRUE(p.contains(0.5, 0.5));
    EXPECT_TRUE(p.contains(3.5, 2.0));
    EXPECT_FALSE(p.contains(2.0, 2.0)); // in the hole
    EXPECT_FALSE(p.contains(1.5, 2.9)); // in the hole
    EXPECT_TRUE(p.contains(1.0, 2.0));  // on the hole's boundary: closed set
    EXPECT_TRUE(p.contains(3.0, 3.0));  // hole vertex
    EXPECT_TRUE(p.contains(4.0, 4.0));  // outer vertex
    EXPECT_TRUE(p.contains(2.0, 0.0));  // outer edge
    EXPECT_FALSE(p.contains(5.0, 2.0));
    EXPECT_FALSE(p.contains(-1e-9, 2.0));      // just outside
    EXPECT_TRUE(p.contains(1e-9, 2.0));        // just inside
    EXPECT_FALSE(p.contains(2.0, 1.0 + 1e-9)); // just inside the hole
    EXPECT_FALSE(p.contains(kNaN, 1.0));
    // a ray through vertices (y = 0 and y = 4 rows, hole corners at y = 1) must not double count
    EXPECT_TRUE(p.contains(0.5, 1.0));
    EXPECT_FALSE(p.contains(-0.5, 1.0));
    EXPECT_FALSE(p.contains(-0.5, 0.0));
}

TEST(Polygon, ConcaveRayThroughVertex)
{
    // A "W" shaped polygon whose reflex vertex (2, 1) lies on rays y = 1.
    const Polygon w({{0, 0}, {4, 0}, {4, 2}, {3, 2}, {2, 1}, {1, 2}, {0, 2}});
    EXPECT_TRUE(w.contains(0.5, 1.0));
    EXPECT_TRUE(w.contains(2.0, 1.0));  // the reflex vertex itself
    EXPECT_FALSE(w.contains(2.0, 1.5)); // in the notch
    EXPECT_TRUE(w.contains(3.5, 1.5));
    EXPECT_FALSE(w.contains(-1.0, 1.0));
    EXPECT_FALSE(w.contains(5.0, 1.0));
}

TEST(Polygon, SegmentCrossingTouchingInside)
{
    const Polygon sq = Polygon::rectangle(0, 0, 2, 2);
    // crossing: inside for s in [0.25, 0.75]
    auto in = sq.segmentInsideIntervals(-1, 1, 3, 1);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_DOUBLE_EQ(in[0].lo, 0.25);
    EXPECT_DOUBLE_EQ(in[0].hi, 0.75);
    EXPECT_TRUE(sq.segmentIntersects(-1, 1, 3, 1));
    // touching a vertex only: one degenerate interval
    in = sq.segmentInsideIntervals(-1, 1, 1, -1);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_DOUBLE_EQ(in[0].lo, 0.5);
    EXPECT_DOUBLE_EQ(in[0].hi, 0.5);
    EXPECT_TRUE(sq.segmentIntersects(-1, 1, 1, -1));
    // running along the bottom edge
    in = sq.segmentInsideIntervals(-1, 0, 3, 0);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_DOUBLE_EQ(in[0].lo, 0.25);
    EXPECT_DOUBLE_EQ(in[0].hi, 0.75);
    EXPECT_TRUE(sq.segmentIntersects(-1, 0, 3, 0));
    // ending exactly on an edge
    in = sq.segmentInsideIntervals(-1, 1, 0, 1);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_DOUBLE_EQ(in[0].lo, 1.0);
    EXPECT_TRUE(sq.segmentIntersects(-1, 1, 0, 1));
    // wholly inside, wholly outside, near miss, degenerate
    in = sq.segmentInsideIntervals(0.5, 0.5, 1.5, 1.5);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_EQ(in[0].lo, 0.0);
    EXPECT_EQ(in[0].hi, 1.0);
    EXPECT_TRUE(sq.segmentIntersects(0.5, 0.5, 1.5, 1.5));
    EXPECT_TRUE(sq.segmentInsideIntervals(3, 3, 4, 5).empty());
    EXPECT_FALSE(sq.segmentIntersects(3, 3, 4, 5));
    EXPECT_FALSE(sq.segmentIntersects(-1, -1e-9, 3, -1e-9));
    EXPECT_TRUE(sq.segmentInsideIntervals(-1, -1e-9, 3, -1e-9).empty());
    EXPECT_FALSE(sq.segmentIntersects(2 + 1e-9, -1, 2 + 1e-9, 3));
    EXPECT_TRUE(sq.segmentIntersects(1, 1, 1, 1));
    EXPECT_FALSE(sq.segmentIntersects(3, 1, 3, 1));
    // diagonal through two opposite vertices: the whole diagonal is inside
    in = sq.segmentInsideIntervals(-1, -1, 3, 3);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_DOUBLE_EQ(in[0].lo, 0.25);
    EXPECT_DOUBLE_EQ(in[0].hi, 0.75);
}

TEST(Polygon, SegmentThroughHole)
{
    const Polygon p = squareWithHole();
    // y = 2 from x = -1 to x = 5: inside for x in [0,1] and [3,4]
    auto in = p.segmentInsideIntervals(-1, 2, 5, 2);
    ASSERT_EQ(in.size(), 2u);
    EXPECT_NEAR(in[0].lo, 1.0 / 6, 1e-15);
    EXPECT_NEAR(in[0].hi, 2.0 / 6, 1e-15);
    EXPECT_NEAR(in[1].lo, 4.0 / 6, 1e-15);
    EXPECT_NEAR(in[1].hi, 5.0 / 6, 1e-15);
    EXPECT_FALSE(p.segmentIntersects(1.5, 1.5, 2.5, 2.5)); // inside the hole
    EXPECT_TRUE(p.segmentIntersects(1.5, 2, 3, 2));        // reaches the hole's boundary
    in = p.segmentInsideIntervals(1.5, 2, 3, 2);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_EQ(in[0].lo, 1.0);
    EXPECT_EQ(in[0].hi, 1.0);
}

TEST(Polygon, ManyVertexRegularPolygon)
{
    const int n = 2000;
    const Polygon p = Polygon::regular(0, 0, 1, n);
    EXPECT_EQ(p.vertexCount(), static_cast<std::size_t>(n));
    EXPECT_NEAR(p.area(), 0.5 * n * std::sin(2 * M_PI / n), 1e-12);
    const double apothem = std::cos(M_PI / n);
    for (int k = 0; k < 50; ++k)
    {
        const double a = 2 * M_PI * (k + 0.37) / 50;
        EXPECT_TRUE(p.contains(0.999999 * apothem * std::cos(a), 0.999999 * apothem * std::sin(a)));
        EXPECT_FALSE(p.contains(1.000001 * std::cos(a), 1.000001 * std::sin(a)));
    }
    auto in = p.segmentInsideIntervals(-2, 0, 2, 0);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_NEAR(in[0].lo, 0.25, 1e-12);
    EXPECT_NEAR(in[0].hi, 0.75, 1e-12);
}

TEST(Polygon, GridIndexMatchesBruteForceOnCoastline)
{
    const Star star = makeStar(5000, 7);
    const Polygon p = star.polygon();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    int insideCount = 0;
    for (int k = 0; k < 4000; ++k)
    {
        const double x = u(rng), y = u(rng);
        const bool ref = star.inside(x, y);
        insideCount += ref;
        ASSERT_EQ(p.contains(x, y), ref) << x << " " << y;
    }
    EXPECT_GT(insideCount, 1000);
    // segments: brute force over all edges (plain orientation tests) + start point inside
    const auto &ring = p.outer();
    int hits = 0;
    for (int k = 0; k < 400; ++k)
    {
        const double ax = u(rng), ay = u(rng);
        const double len = 0.02 + 0.5 * (k % 4);
        const double ang = 2 * M_PI * (k * 0.618);
        const double bx = ax + len * std::cos(ang), by = ay + len * std::sin(ang);
        bool ref = star.inside(ax, ay);
        for (std::size_t i = 0, j = ring.size() - 1; i < ring.size() && !ref; j = i++)
            ref = properCross(ax, ay, bx, by, ring[j].x, ring[j].y, ring[i].x, ring[i].y);
        hits += ref;
        ASSERT_EQ(p.segmentIntersects(ax, ay, bx, by), ref) << k;
        // interval decomposition: midpoints of inside pieces are inside, of gaps outside
        const auto in = p.segmentInsideIntervals(ax, ay, bx, by);
        ASSERT_EQ(!in.empty(), ref) << k;
        double prev = 0.0;
        for (const Interval &iv : in)
        {
            if (iv.hi - iv.lo > 1e-9)
            {
                const double m = 0.5 * (iv.lo + iv.hi);
                EXPECT_TRUE(star.inside(ax + m * (bx - ax), ay + m * (by - ay)));
            }
            if (iv.lo - prev > 1e-9)
            {
                const double m = 0.5 * (prev + iv.lo);
                EXPECT_FALSE(star.inside(ax + m * (bx - ax), ay + m * (by - ay)));
            }
            prev = iv.hi;
        }
    }
    EXPECT_GT(hits, 100);
}

TEST(Polygon, BadInputThrows)
{
    EXPECT_THROW(Polygon({{0, 0}, {1, 1}}), Error);
    EXPECT_THROW(Polygon({{0, 0}, {1, 0}, {1, 0}, {0, 0}}), Error); // 2 distinct vertices
    EXPECT_THROW(Polygon({{0, 0}, {1, 0}, {2, 0}}), Error);         // zero area
    EXPECT_THROW(Polygon({{0, 0}, {1, kNaN}, {1, 1}}), Error);
    EXPECT_THROW(Polygon::rectangle(1, 0, 0, 1), Error);
    try
    {
        Polygon({{0, 0}, {1, 0}}, {}, "Funk Island");
        FAIL();
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("Funk Island"), std::string::npos);
    }
}

std::string polygonError(std::vector<Point2> outer, std::vector<std::vector<Point2>> holes = {})
{
    try
    {
        Polygon(std::move(outer), std::move(holes), "P");
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

TEST(Polygon, RingsMustBeSimpleAndApart)
{
    // a bow tie: edges 0 and 2 cross at (5, 0)
    std::string msg = polygonError({{4, -1}, {6, 1}, {6, -1}, {4, 1}});
    EXPECT_NE(msg.find("outer ring edge 0 (4, -1)-(6, 1) meets outer ring edge 2"), std::string::npos) << msg;
    // a figure eight touching itself at a vertex, and a spike doubling back along its own edge
    EXPECT_NE(polygonError({{0, 0}, {2, 2}, {0, 2}, {2, 0}, {4, 0}, {4, 4}}).find("meets"), std::string::npos);
    EXPECT_NE(polygonError({{0, 0}, {4, 0}, {4, 4}, {4, 2}, {0, 4}}).find("meets"), std::string::npos);
    // a hole crossing the outer ring, and a hole touching it at a vertex
    msg = polygonError({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{3, 1}, {5, 1}, {5, 2}, {3, 2}}});
    EXPECT_NE(msg.find("hole 0 edge"), std::string::npos) << msg;
    EXPECT_NE(polygonError({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{4, 2}, {3, 3}, {3, 1}}}).find("meets"),
              std::string::npos);
    // simple rings pass: a concave ring, a hole strictly inside, collinear consecutive vertices, a 10^4-vertex
    // coastline
    EXPECT_EQ(polygonError({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}), "");
    EXPECT_EQ(polygonError({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}), "");
    EXPECT_EQ(polygonError(makeStar(10000, 7).polygon().outer()), "");
}

TEST(StaticRegion, IslandBlocksLegsAndNamesItself)
{
    ForbiddenRegions env;
    env.add(std::make_shared<StaticRegion>("A", Polygon::rectangle(4, -1, 6, 1), "island"));
    env.add(std::make_shared<StaticRegion>("Zone 7", Polygon::rectangle(8, 2, 9, 3), "restricted area"));
    EXPECT_FALSE(env.pointFree(5, 0, 0));
    EXPECT_EQ(env.whyBlocked(5, 0, 0), "inside island 'A'");
    EXPECT_EQ(env.whyBlocked(8.5, 2.5, 3), "inside restricted area 'Zone 7'");
    EXPECT_EQ(env.whyBlocked(0, 0, 0), "");
    EXPECT_FALSE(env.legFree(0, 0, 0, 10, 0, 10));
    EXPECT_EQ(env.whyLegBlocked(0, 0, 0, 10, 0, 10), "leg crosses island 'A'");
    EXPECT_TRUE(env.legFree(0, 1.5, 0, 10, 1.5, 10));
    EXPECT_EQ(env.whyLegBlocked(0, 1.5, 0, 10, 1.5, 10), "");
    EXPECT_FALSE(env.legFree(0, 1, 0, 10, 1, 10)); // grazes the island's north edge
    EXPECT_FALSE(env.legFree(kNaN, 0, 0, 1, 1, 1));
    EXPECT_FALSE(env.pointFree(kNaN, 0, 0));
}

TEST(TimeWindowedZone, LegBeforeDuringAfterWindow)
{
    // The leg (0,0,t=0) -> (10,0,t=10) is inside [4,6] x [-1,1] exactly during t in [4, 6].
    const Polygon lane = Polygon::rectangle(4, -1, 6, 1);
    auto zone = [&](double a, double b) { return TimeWindowedZone("lane", lane, {{a, b}}); };
    const auto times = zone(0, 1).insideTimes(0, 0, 0, 10, 0, 10);
    ASSERT_EQ(times.size(), 1u);
    EXPECT_DOUBLE_EQ(times[0].lo, 4.0);
    EXPECT_DOUBLE_EQ(times[0].hi, 6.0);
    EXPECT_TRUE(zone(1, 3).legFree(0, 0, 0, 10, 0, 10));    // window before the passage
    EXPECT_FALSE(zone(5, 5.5).legFree(0, 0, 0, 10, 0, 10)); // during
    EXPECT_FALSE(zone(3, 7).legFree(0, 0, 0, 10, 0, 10));   // covering
    EXPECT_TRUE(zone(7, 9).legFree(0, 0, 0, 10, 0, 10));    // after
    EXPECT_FALSE(zone(6, 7).legFree(0, 0, 0, 10, 0, 10));   // touching the exit time: closed
    EXPECT_TRUE(zone(6 + 1e-9, 7).legFree(0, 0, 0, 10, 0, 10));
    EXPECT_TRUE(zone(1, 4 - 1e-9).legFree(0, 0, 0, 10, 0, 10));
    // a slower leg (pace 0.5) passes during [8, 12]; departing later shifts it
    EXPECT_FALSE(zone(11, 11.5).legFree(0, 0, 0, 10, 0, 20));
    EXPECT_TRUE(zone(11, 11.5).legFree(0, 0, 4, 10, 0, 9)); // inside during [6, 7]
    // waiting it out: the same path after the window is free
    const TimeWindowedZone closed("lane", lane, {{0, 5}, {20, 30}});
    EXPECT_FALSE(closed.legFree(0, 0, 0, 10, 0, 10));
    EXPECT_TRUE(closed.legFree(0, 0, 5, 10, 0, 15)); // inside during [9, 11]
    EXPECT_FALSE(closed.pointFree(5, 0, 3));
    EXPECT_TRUE(closed.pointFree(5, 0, 10));
    EXPECT_EQ(closed.whyBlocked(5, 0, 3), "inside closure 'lane'");
    EXPECT_EQ(closed.whyBlocked(5, 0, 10), "");
    EXPECT_THROW(TimeWindowedZone("bad", lane, {{2, 1}}), Error);
    EXPECT_THROW(TimeWindowedZone("bad", lane, {}), Error);
    EXPECT_THROW(TimeWindowedZone("bad", lane, {{kNaN, 1}}), Error);
}

TEST(IceZone, DriftingRectangleClosedFormTimeUnderIce)
{
    // Ice [0,2] x [-1,1] at t = 0 drifting east at 0.3; glider along y = 0 from x = -1 (t = 0) to x = 5 (t = 6),
    // pace 1. Relative position -1 + 0.7 t in [0, 2] <=> t in [1/0.7, 3/0.7]: under ice for 2/0.7.
    const double T = 2.0 / 0.7;
    const IceZone loose("I", Polygon::rectangle(0, -1, 2, 1), 0.0, 0.3, 0.0, 10.0);
    const auto times = loose.underIceTimes(-1, 0, 0, 5, 0, 6);
    ASSERT_EQ(times.size(), 1u);
    EXPECT_NEAR(times[0].lo, 1.0 / 0.7, 1e-13);
    EXPECT_NEAR(times[0].hi, 3.0 / 0.7, 1e-13);
    EXPECT_NEAR(loose.longestUnderIce(-1, 0, 0, 5, 0, 6), T, 1e-13);
    EXPECT_TRUE(
        IceZone("I", Polygon::rectangle(0, -1, 2, 1), 0.0, 0.3, 0.0, T * (1 + 1e-9)).legFree(-1, 0, 0, 5, 0, 6));
    EXPECT_FALSE(
        IceZone("I", Polygon::rectangle(0, -1, 2, 1), 0.0, 0.3, 0.0, T * (1 - 1e-9)).legFree(-1, 0, 0, 5, 0, 6));
    // the same leg flown backwards in x against the drift: relative speed 1.3, time 2/1.3
    EXPECT_NEAR(loose.longestUnderIce(5, 0, 0, -1, 0, 6), 2.0 / 1.3, 1e-13);
    // displacement
    EXPECT_NEAR(loose.displacement(5).x, 1.5, 1e-15);
    EXPECT_NEAR(loose.displacement(-2).x, -0.6, 1e-15);
    // waypoints under ice are blocked (a glider cannot surface there)
    EXPECT_FALSE(loose.pointFree(1.3, 0, 1.0)); // ice covers [0.3, 2.3] at t = 1
    EXPECT_TRUE(loose.pointFree(0.2, 0, 1.0));
    EXPECT_FALSE(loose.legFree(1.3, 0, 1.0, 5, 0, 6));
    EXPECT_EQ(loose.whyLegBlocked(1.3, 0, 1.0, 5, 0, 6), "leg starts under ice zone 'I'");
    EXPECT_EQ(loose.whyBlocked(1.3, 0, 1.0), "under ice zone 'I' (a glider cannot surface there)");
    const IceZone tight("J", Polygon::rectangle(0, -1, 2, 1), 0.0, 0.3, 0.0, 1.0);
    EXPECT_NE(tight.whyLegBlocked(-1, 0, 0, 5, 0, 6).find("leg stays under ice zone 'J' for 2.857"), std::string::npos);
}

TEST(IceZone, CrossingDriftAtRightAngles)
{
    // Ice [2,3] x [-3,-1] drifting north at 0.5; glider along y = 0 from x = 0 (t = 0) to x = 5 (t = 5).
    // Relative position (t, -0.5 t): x in [2,3] <=> t in [2,3], y in [-3,-1] <=> t in [2,6]: under ice t in [2,3].
    const IceZone ice("N", Polygon::rectangle(2, -3, 3, -1), 0.0, 0.0, 0.5, 0.999);
    const auto times = ice.underIceTimes(0, 0, 0, 5, 0, 5);
    ASSERT_EQ(times.size(), 1u);
    EXPECT_NEAR(times[0].lo, 2.0, 1e-14);
    EXPECT_NEAR(times[0].hi, 3.0, 1e-14);
    EXPECT_FALSE(ice.legFree(0, 0, 0, 5, 0, 5));
    EXPECT_TRUE(IceZone("N", Polygon::rectangle(2, -3, 3, -1), 0.0, 0.0, 0.5, 1.001).legFree(0, 0, 0, 5, 0, 5));
    // a glider passing before the ice arrives (fast leg, t in [0, 1]) never is under it
    EXPECT_TRUE(ice.underIceTimes(0, 0, 0, 5, 0, 1).empty());
    EXPECT_THROW(IceZone("bad", Polygon::rectangle(0, 0, 1, 1), 0.0, kNaN, 0.0, 1.0), Error);
    EXPECT_THROW(IceZone("bad", Polygon::rectangle(0, 0, 1, 1), 0.0, 0.0, 0.0, -1.0), Error);
}

TEST(IceZone, CarriedByUniformCurrentEqualsDrift)
{
    const UniformCurrent c(0.3, 0.0);
    const IceZone carried("I", Polygon::rectangle(0, -1, 2, 1), 0.0, c, {1, 0}, -5, 20, 10.0);
    EXPECT_LE(carried.positionTolerance(), 1e-4);
    EXPECT_NEAR(carried.displacement(5).x, 1.5, 1e-12);
    EXPECT_NEAR(carried.displacement(-3).x, -0.9, 1e-12);
    EXPECT_NEAR(carried.displacement(5).y, 0.0, 1e-12);
    EXPECT_NEAR(carried.longestUnderIce(-1, 0, 0, 5, 0, 6), 2.0 / 0.7, 1e-9);
}

TEST(IceZone, CarriedByShearMovesWithItsReferencePoint)
{
    // u = a y: the point (0, 2) moves at constant speed 2a; the zone keeps its shape.
    const LinearShear shear(0.25);
    const IceZone ice("S", Polygon::rectangle(-0.5, 1.5, 0.5, 2.5), 0.0, shear, {0, 2}, 0, 10, 1.0);
    EXPECT_NEAR(ice.displacement(4).x, 2.0, 1e-12);
    EXPECT_NEAR(ice.displacement(4).y, 0.0, 1e-12);
    EXPECT_FALSE(ice.pointFree(2.0, 2.0, 4.0));
    EXPECT_TRUE(ice.pointFree(0.0, 2.0, 4.0));
}

TEST(IceZone, CarriedByMeanderingJetWithinStatedTolerance)
{
    const MeanderingJet jet;
    IceAdvectionParams p;
    p.tolerance = 1e-5;
    const Point2 ref{2.0, 0.5};
    const IceZone ice("M", Polygon::regular(2.0, 0.5, 0.3, 12), 1.0, jet, ref, 0.0, 8.0, 0.5, p);
    EXPECT_LE(ice.positionTolerance(), 1e-5);
    // independent reference: fine fixed-step RK4 (h = 1e-3) from tRef = 1 to t = 7
    double x = ref.x, y = ref.y, t = 1.0;
    const double h = 1e-3;
    for (int k = 0; k < 6000; ++k)
    {
        auto f = [&](double px, double py, double pt) { return jet.velocity(px, py, 0, pt); };
        const Velocity k1 = f(x, y, t), k2 = f(x + h / 2 * k1.u, y + h / 2 * k1.v, t + h / 2),
                       k3 = f(x + h / 2 * k2.u, y + h / 2 * k2.v, t + h / 2), k4 = f(x + h * k3.u, y + h * k3.v, t + h);
        x += h / 6 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u);
        y += h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
        t = 1.0 + (k + 1) * h;
    }
    const Point2 d = ice.displacement(7.0);
    EXPECT_GT(std::hypot(x - ref.x, y - ref.y), 0.5); // the zone really moved
    EXPECT_LE(std::hypot(ref.x + d.x - x, ref.y + d.y - y), 2 * ice.positionTolerance() + 1e-9);
}

TEST(ForbiddenRegions, CompositeListsEveryBlockingRegion)
{
    ForbiddenRegions env;
    env.add(std::make_shared<StaticRegion>("A", Polygon::rectangle(0, 0, 2, 2), "island"));
    env.add(std::make_shared<TimeWindowedZone>("lane", Polygon::rectangle(1, 1, 5, 5), std::vector<Interval>{{0, 1}}));
    env.add(std::make_shared<IceZone>("I", Polygon::rectangle(10, 10, 11, 11), 0.0, 0.0, 0.0, 1.0));
    EXPECT_EQ(env.size(), 3u);
    EXPECT_EQ(env.whyBlocked(1.5, 1.5, 0.5), "inside island 'A'; inside closure 'lane'");
    EXPECT_EQ(env.whyBlocked(1.5, 1.5, 2.0), "inside island 'A'");
    EXPECT_EQ(env.whyBlocked(3, 3, 2.0), "");
    EXPECT_EQ(env.whyBlocked(10.5, 10.5, 2.0), "under ice zone 'I' (a glider cannot surface there)");
    EXPECT_TRUE(env.legFree(9, 10.5, 0, 13, 10.5, 4));  // under ice during [1, 2]: at the limit
    EXPECT_FALSE(env.legFree(9, 10.5, 0, 12, 10.5, 4)); // under ice during [4/3, 8/3]
    EXPECT_EQ(env.whyLegBlocked(3, 0, 0.5, 3, 6, 0.6), "leg crosses closure 'lane'");
    EXPECT_THROW(env.add(nullptr), Error);
    const Environment &base = env;
    EXPECT_FALSE(base.legFree(-1, 1, 0, 3, 1, 1));
}

// The accurate re-flight ("honest times"): closed forms in uniform currents (a straight leg, a heading route's
// end point and its first entry into the goal circle), a current three times the speed (the reachable cone), linear
// shear (closed forms of both kinds of route), the meandering jet against flyHeadingRoute at a tiny RK4 step and
// against TravelTimeCalculator at a tight tolerance, the convergence of the integrator as its tolerance shrinks,
// grounding on land and forbidden regions, infeasible legs, holds, and the figures of the pipeline's default leg
// timing against the re-flight on the jet (printed, not asserted).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>

#include "ompl_glider/Exception.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/execution/Reflight.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

// Straight leg of length L in direction p through the uniform current c at speed V: L / (p.c + sqrt(V^2 - (c x p)^2)),
// or +inf outside the reachable set.
double legClosedForm(double L, double px, double py, Velocity c, double V)
{
    const double pc = px * c.u + py * c.v, cross = c.u * py - c.v * px, disc = V * V - cross * cross;
    if (disc <= 0.0)
        return kInf;
    const double s = pc + std::sqrt(disc);
    return s > 0.0 ? L / s : kInf;
}

// First t >= 0 at which p0 + w t is within R of g (NaN if never).
double firstEntry(Point2 p0, Velocity w, Point2 g, double R)
{
    const double fx = p0.x - g.x, fy = p0.y - g.y;
    const double a = w.u * w.u + w.v * w.v, b = 2.0 * (w.u * fx + w.v * fy), c = fx * fx + fy * fy - R * R;
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0)
        return std::nan("");
    // the smaller root, in the form that does not cancel
    const double q = -0.5 * (b - std::sqrt(disc));
    return c / q;
}

ReflightSettings settings(double V)
{
    ReflightSettings s;
    s.speed = V;
    return s;
}

// Uniform current c with land at x >= 5 (inWater() exact on a half-plane, so the default segment check is exact).
class HalfPlaneLand : public CurrentField
{
public:
    double maxSpeed(const Region &) const override { return 0.1; }
    bool inWater(double x, double, double) const override { return x < 5.0; }
    std::string name() const override { return "half-plane land"; }

protected:
    Velocity evaluate(double, double, double, double) const override { return {0.1, 0.0}; }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }
};
} // namespace

TEST(Reflight, StraightLegInAUniformCurrentIsTheClosedForm)
{
    const double V = 0.5;
    for (Velocity c : {Velocity{0.3, 0.0}, Velocity{-0.2, 0.35}, Velocity{0.1, -0.45}})
    {
        const UniformCurrent field(c.u, c.v);
        for (int k = 0; k < 24; ++k)
        {
            const double a = 2.0 * kPi * k / 24.0, L = 3.7, px = std::cos(a), py = std::sin(a);
            const double expected = legClosedForm(L, px, py, c, V);
            ASSERT_TRUE(std::isfinite(expected)); // |c| < V: every direction
            const LegReflight r = reflyLeg(1.0, -2.0, 1.0 + L * px, -2.0 + L * py, 4.0, field, nullptr, settings(V));
            ASSERT_TRUE(r.feasible) << r.why;
            EXPECT_NEAR(r.duration, expected, 1e-12 * expected) << "direction " << a;
        }
    }
}

TEST(Reflight, PathOfLegsAndAHoldInAUniformCurrent)
{
    const Velocity c{0.15, 0.2};
    const double V = 0.4;
    const UniformCurrent field(c.u, c.v);
    // the hold at (3, 4) keeps its planned 2.5; the planned times of the other waypoints are ignored
    const std::vector<TimedPoint> path{{0, 0, 10.0}, {3, 4, 99.0}, {3, 4, 101.5}, {3, -1, 0.0}};
    const PathReflight r = reflyPath(path, field, nullptr, settings(V));
    ASSERT_TRUE(r.feasible) << r.why;
    ASSERT_EQ(r.times.size(), 4u);
    const double t1 = legClosedForm(5.0, 0.6, 0.8, c, V), t3 = legClosedForm(5.0, 0.0, -1.0, c, V);
    EXPECT_DOUBLE_EQ(r.times[0], 10.0);
    EXPECT_NEAR(r.times[1], 10.0 + t1, 1e-12 * t1);
    EXPECT_NEAR(r.times[2], 10.0 + t1 + 2.5, 1e-12 * t1);
    EXPECT_NEAR(r.times[3], 10.0 + t1 + 2.5 + t3, 1e-12 * (t1 + t3));
    EXPECT_EQ(r.arrivalTime, r.times[3]);
    // one waypoint: it arrives when it leaves
    const PathReflight one = reflyPath({{2, 2, 7.0}}, field, nullptr, settings(V));
    EXPECT_TRUE(one.feasible);
    EXPECT_EQ(one.arrivalTime, 7.0);
}

TEST(Reflight, HeadingRouteInAUniformCurrentEndsAtStartPlusGroundVelocityTimesDuration)
{
    const Velocity c{0.3, -0.1};
    const double V = 0.5;
    const UniformCurrent field(c.u, c.v);
    HeadingRoute route{{1.0, 2.0}, 3.0, {{40.0, 2.0}, {0.0, 0.0}, {200.0, 1.5}, {310.0, 4.25}}};
    const HeadingReflight r = reflyHeadingRoute(route, field, nullptr, settings(V));
    ASSERT_TRUE(r.ok);
    EXPECT_FALSE(r.grounded);
    EXPECT_FALSE(r.reached);
    EXPECT_EQ(r.segmentsFlown, 3u); // the zero-length segment is skipped
    ASSERT_EQ(r.ends.size(), 4u);
    double x = 1.0, y = 2.0, t = 3.0;
    std::size_t k = 1;
    for (const HeadingSegment &s : route.segments)
    {
        if (s.duration <= 0.0)
            continue;
        const Point2 h = bearingVector(s.bearing);
        x += (V * h.x + c.u) * s.duration;
        y += (V * h.y + c.v) * s.duration;
        t += s.duration;
        EXPECT_NEAR(r.ends[k].x, x, 1e-13 * 10.0) << k;
        EXPECT_NEAR(r.ends[k].y, y, 1e-13 * 10.0) << k;
        EXPECT_NEAR(r.ends[k].t, t, 1e-14 * 10.0) << k;
        ++k;
    }
    EXPECT_EQ(r.end.x, r.ends.back().x);
    EXPECT_TRUE(std::isnan(r.finalDistance)); // no goal radius
}

TEST(Reflight, HeadingRouteEntersTheGoalCircleAtTheClosedFormTime)
{
    const Velocity c{0.3, -0.1};
    const double V = 0.5;
    const UniformCurrent field(c.u, c.v);
    ReflightSettings s = settings(V);
    s.radius = 0.2;
    // the first segment passes by the goal's circle, the second enters it
    const HeadingRoute route{{0.0, 0.0}, 1.0, {{90.0, 4.0}, {0.0, 10.0}}};
    const Point2 h1 = bearingVector(90.0), h2 = bearingVector(0.0);
    const Velocity w1{V * h1.x + c.u, V * h1.y + c.v}, w2{V * h2.x + c.u, V * h2.y + c.v};
    const Point2 p1{4.0 * w1.u, 4.0 * w1.v};
    s.goal = {p1.x + 1.5 * w2.u + 0.1, p1.y + 1.5 * w2.v};
    ASSERT_TRUE(std::isnan(firstEntry({0, 0}, w1, s.goal, s.radius)) ||
                firstEntry({0, 0}, w1, s.goal, s.radius) > 4.0); // not during the first segment
    const double T = 1.0 + 4.0 + firstEntry(p1, w2, s.goal, s.radius);
    const HeadingReflight r = reflyHeadingRoute(route, field, nullptr, s);
    ASSERT_TRUE(r.reached);
    EXPECT_NEAR(r.arrivalTime, T, 1e-13 * T);
    EXPECT_NEAR(r.finalDistance, s.radius, 1e-13);
    EXPECT_EQ(r.segmentsFlown, 2u);
    ASSERT_EQ(r.ends.size(), 3u);
    EXPECT_NEAR(r.ends[1].x, p1.x, 1e-13);
    EXPECT_NEAR(r.end.t, T, 1e-13 * T);
    // the same flight with flyHeadingRoute (RK4 on the chords: exact in a uniform current)
    DiveSettings d;
    d.speed = V;
    d.radius = s.radius;
    d.goal = s.goal;
    const HeadingFlight f = flyHeadingRoute(route, field, nullptr, d, false);
    ASSERT_TRUE(f.reached);
    EXPECT_NEAR(f.arrivalTime, r.arrivalTime, 1e-12 * T);
    // a route that starts inside the radius arrives at its departure
    s.goal = {0.05, 0.0};
    const HeadingReflight at = reflyHeadingRoute(route, field, nullptr, s);
    EXPECT_TRUE(at.reached);
    EXPECT_EQ(at.arrivalTime, 1.0);
    EXPECT_EQ(at.ends.size(), 1u);
}

TEST(Reflight, ACurrentThreeTimesTheSpeedLeavesOnlyTheReachableCone)
{
    // |c| = 3 V along +x: a straight leg at angle a from the current is feasible iff sin a < 1/3 (and cos a > 0),
    // the half-angle of the reachable cone asin(1/3) = 19.47 degrees
    const double V = 0.2;
    const Velocity c{3.0 * V, 0.0};
    const UniformCurrent field(c.u, c.v);
    const double cone = std::asin(1.0 / 3.0);
    for (double a : {0.0, 0.5 * cone, 0.95 * cone, -0.9 * cone})
    {
        const double L = 2.0, px = std::cos(a), py = std::sin(a);
        const LegReflight r = reflyLeg(0, 0, L * px, L * py, 0.0, field, nullptr, settings(V));
        const double expected = legClosedForm(L, px, py, c, V);
        ASSERT_TRUE(r.feasible) << a << ": " << r.why;
        EXPECT_NEAR(r.duration, expected, 1e-12 * expected) << a;
    }
    for (double a : {1.05 * cone, 0.5 * kPi, kPi, -2.0 * cone})
    {
        const LegReflight r = reflyLeg(0, 0, 2.0 * std::cos(a), 2.0 * std::sin(a), 0.0, field, nullptr, settings(V));
        EXPECT_FALSE(r.feasible) << a;
        EXPECT_TRUE(std::isinf(r.duration));
        EXPECT_NE(r.why.find("stronger than the speed"), std::string::npos) << r.why;
        EXPECT_EQ(r.where.x, 0.0); // at the leg's start
    }
    // a path whose second leg leaves the cone: that leg is named
    const PathReflight p = reflyPath({{0, 0, 0}, {2, 0.1, 1}, {2, 3, 2}}, field, nullptr, settings(V));
    EXPECT_FALSE(p.feasible);
    EXPECT_EQ(p.failedLeg, 1u);
    EXPECT_EQ(p.times.size(), 2u);
    EXPECT_TRUE(std::isinf(p.arrivalTime));
    EXPECT_EQ(p.why.rfind("leg 1: ", 0), 0u) << p.why;
    // a held heading still drifts to anywhere in the cone: heading north for T ends at (3 V T, V T)
    const HeadingReflight h = reflyHeadingRoute({{0, 0}, 0.0, {{0.0, 5.0}}}, field, nullptr, settings(V));
    EXPECT_NEAR(h.end.x, 3.0 * V * 5.0, 1e-13);
    EXPECT_NEAR(h.end.y, V * 5.0, 1e-13);
}

TEST(Reflight, LinearShearClosedForms)
{
    // u = a y: across the flow from y = 0 to 0.8 at V = 1, a = -1: T = asin(|a| y / V) / |a| ([BettsOC] setting)
    const LinearShear field(-1.0);
    const LegReflight across = reflyLeg(2.0, 0.0, 2.0, 0.8, 0.0, field, nullptr, settings(1.0));
    ASSERT_TRUE(across.feasible) << across.why;
    EXPECT_NEAR(across.duration, std::asin(0.8), 1e-10 * std::asin(0.8));
    // beyond |a y| = V the cross current wins, at y = 1 on the leg
    const LegReflight beyond = reflyLeg(2.0, 0.0, 2.0, 1.2, 0.0, field, nullptr, settings(1.0));
    EXPECT_FALSE(beyond.feasible);
    EXPECT_NEAR(beyond.where.y, 1.0, 1e-9);
    EXPECT_NE(beyond.why.find("cross current"), std::string::npos) << beyond.why;
    // a held heading: y = y0 + V hy t, x = x0 + V hx t + a (y0 t + V hy t^2 / 2)
    const double V = 0.6, a = -1.0, T = 3.0;
    const Point2 h = bearingVector(30.0);
    const HeadingReflight r = reflyHeadingRoute({{1.0, -0.5}, 2.0, {{30.0, T}}}, field, nullptr, settings(V));
    EXPECT_NEAR(r.end.y, -0.5 + V * h.y * T, 1e-12);
    EXPECT_NEAR(r.end.x, 1.0 + V * h.x * T + a * (-0.5 * T + V * h.y * T * T / 2.0), 1e-12);
    EXPECT_DOUBLE_EQ(r.end.t, 5.0);
}

TEST(Reflight, HeadingRouteInTheJetAgreesWithRk4AtATinyStep)
{
    const MeanderingJet jet;
    const double V = 0.3;
    const HeadingRoute route{{1.0, -3.0}, 0.5, {{20.0, 3.0}, {60.0, 4.0}, {350.0, 2.5}, {100.0, 3.0}}};
    DiveSettings d;
    d.speed = V;
    d.step = 1e-4;
    ReflightSettings s = settings(V);
    // without a goal: the end of every segment
    const HeadingFlight f = flyHeadingRoute(route, jet, nullptr, d, false);
    const HeadingReflight r = reflyHeadingRoute(route, jet, nullptr, s);
    ASSERT_EQ(r.ends.size(), f.ends.size());
    for (std::size_t k = 1; k < r.ends.size(); ++k)
    {
        const double flown = std::hypot(f.ends[k].x - 1.0, f.ends[k].y + 3.0);
        EXPECT_LT(std::hypot(r.ends[k].x - f.ends[k].x, r.ends[k].y - f.ends[k].y), 1e-9 * flown) << k;
        EXPECT_NEAR(r.ends[k].t, f.ends[k].t, 1e-10); // RK4's clock sums 1e-4 steps
    }
    // with a goal on the way: the arrival times (durations) agree
    s.radius = d.radius = 0.05;
    s.goal = d.goal = {f.ends[3].x + 0.02, f.ends[3].y - 0.01};
    const HeadingFlight fg = flyHeadingRoute(route, jet, nullptr, d, false);
    const HeadingReflight rg = reflyHeadingRoute(route, jet, nullptr, s);
    ASSERT_TRUE(fg.reached);
    ASSERT_TRUE(rg.reached);
    EXPECT_LT(std::abs(relativeDifference(fg.arrivalTime, rg.arrivalTime, 0.5)), 1e-9)
        << fg.arrivalTime << " " << rg.arrivalTime;
    EXPECT_NEAR(rg.finalDistance, 0.05, 1e-12);
}

TEST(Reflight, StraightLegsInTheJetAgreeWithATightTravelTimeCalculator)
{
    auto jet = std::make_shared<MeanderingJet>();
    const double V = 0.5;
    TravelTimeParams p;
    p.speed = V;
    p.eps = 1e-9;
    p.hMin = 1e-5; // steps at hMin are accepted whatever their error: the default 1e-3 would cap the accuracy
    const TravelTimeCalculator calc(jet, p);
    struct Leg
    {
        double x1, y1, x2, y2, t0;
    };
    for (const Leg &l : {Leg{1.0, -1.0, 1.4, 0.2, 0.0}, Leg{2.0, 2.0, 3.5, -0.5, 4.5}, Leg{8.0, -2.0, 8.4, -0.6, 12.0},
                         Leg{3.0, 1.0, 3.4, -0.2, 9.0}})
    {
        const double ref = calc.travelTime(l.x1, l.y1, l.x2, l.y2, l.t0);
        const LegReflight r = reflyLeg(l.x1, l.y1, l.x2, l.y2, l.t0, *jet, nullptr, settings(V));
        ASSERT_TRUE(std::isfinite(ref));
        ASSERT_TRUE(r.feasible) << r.why;
        EXPECT_LT(std::abs(relativeDifference(ref, r.duration)), 1e-7) << ref << " " << r.duration;
    }
    // a leg that meets a cross current stronger than the speed half-way: both say so
    EXPECT_TRUE(std::isinf(calc.travelTime(1.0, -3.0, 4.0, -1.0, 2.0)));
    const LegReflight no = reflyLeg(1.0, -3.0, 4.0, -1.0, 2.0, *jet, nullptr, settings(V));
    EXPECT_FALSE(no.feasible);
    EXPECT_NE(no.why.find("cross current"), std::string::npos) << no.why;
    EXPECT_GT(no.where.x, 1.5); // not at the start
    EXPECT_LT(no.where.x, 4.0);
}

TEST(Reflight, TheIntegratorConvergesAsItsToleranceShrinks)
{
    // in the jet, on a straight leg and a heading route: the difference to rtol = 1e-12 is bounded by a modest
    // multiple of the tolerance, and shrinks with it
    const MeanderingJet jet;
    ReflightSettings s = settings(0.5);
    s.tolerance.rtol = 1e-12;
    const double legRef = reflyLeg(1.0, -1.0, 1.4, 0.2, 0.0, jet, nullptr, s).duration;
    ASSERT_TRUE(std::isfinite(legRef));
    const HeadingRoute route{{1.0, -3.0}, 0.5, {{20.0, 3.0}, {60.0, 4.0}, {350.0, 2.5}}};
    const TimedPoint routeRef = reflyHeadingRoute(route, jet, nullptr, s).end;
    double lastLeg = kInf, lastRoute = kInf;
    for (double rtol : {1e-4, 1e-6, 1e-8})
    {
        s.tolerance.rtol = rtol;
        const LegReflight leg = reflyLeg(1.0, -1.0, 1.4, 0.2, 0.0, jet, nullptr, s);
        const double legErr = std::abs(relativeDifference(leg.duration, legRef));
        const TimedPoint end = reflyHeadingRoute(route, jet, nullptr, s).end;
        const double routeErr =
            std::hypot(end.x - routeRef.x, end.y - routeRef.y) / std::hypot(routeRef.x - 1.0, routeRef.y + 3.0);
        std::printf("rtol %.0e: leg %zu steps, relative error %.2e; route relative error %.2e\n", rtol, leg.steps,
                    legErr, routeErr);
        EXPECT_LT(legErr, 100.0 * rtol);
        EXPECT_LT(routeErr, 100.0 * rtol);
        EXPECT_LT(legErr, lastLeg);
        EXPECT_LT(routeErr, lastRoute);
        lastLeg = legErr;
        lastRoute = routeErr;
    }
}

TEST(Reflight, GroundsAtTheEdgeOfLandAndOfAForbiddenRegion)
{
    // land at x >= 5; heading east at 0.5 in a 0.1 current: x = 0.6 t reaches the coast at t = 5 / 0.6
    const HalfPlaneLand field;
    const HeadingReflight r = reflyHeadingRoute({{0.0, 0.0}, 0.0, {{90.0, 20.0}}}, field, nullptr, settings(0.5));
    ASSERT_TRUE(r.grounded);
    EXPECT_FALSE(r.reached);
    EXPECT_NE(r.why.find("land"), std::string::npos) << r.why;
    EXPECT_LT(r.end.x, 5.0);
    EXPECT_GT(r.end.x, 5.0 - 1e-7); // located to 1e-9 of the segment's duration
    EXPECT_NEAR(r.end.t, r.end.x / 0.6, 1e-12);
    // a straight leg onto land: the first point on land
    const LegReflight leg = reflyLeg(0, 0, 8, 0, 0.0, field, nullptr, settings(0.5));
    EXPECT_FALSE(leg.feasible);
    EXPECT_NEAR(leg.where.x, 5.0, 1e-9);
    // a forbidden box [3, 4] x [-1, 1], in a calm uniform field: grounded at x = 3 at t = 3 / 0.6
    ForbiddenRegions regions;
    regions.add(std::make_shared<StaticRegion>("Box", Polygon({{3, -1}, {4, -1}, {4, 1}, {3, 1}})));
    const UniformCurrent calm(0.1, 0.0);
    const HeadingReflight b = reflyHeadingRoute({{0.0, 0.0}, 0.0, {{90.0, 20.0}}}, calm, &regions, settings(0.5));
    ASSERT_TRUE(b.grounded);
    EXPECT_NE(b.why.find("Box"), std::string::npos) << b.why;
    EXPECT_GT(b.end.x, 3.0 - 1e-7);
    EXPECT_LE(b.end.x, 3.0);
    const LegReflight bl = reflyLeg(0, 0, 8, 0, 0.0, calm, &regions, settings(0.5));
    EXPECT_FALSE(bl.feasible);
    EXPECT_NEAR(bl.where.x, 3.0, 1e-9);
    EXPECT_NEAR(bl.where.t, 3.0 / 0.6, 1e-9);
}

TEST(Reflight, RelativeDifferenceOfDurations)
{
    EXPECT_NEAR(relativeDifference(10.1, 10.0), 0.01, 1e-15);
    EXPECT_NEAR(relativeDifference(9.9, 10.0), -0.01, 1e-15);
    EXPECT_EQ(relativeDifference(kInf, kInf), 0.0);
    EXPECT_EQ(relativeDifference(3.0, kInf), -kInf);
    EXPECT_EQ(relativeDifference(kInf, 3.0), kInf);
    EXPECT_TRUE(std::isnan(relativeDifference(std::nan(""), 3.0)));
    EXPECT_DOUBLE_EQ(relativeDifference(110.0, 120.0, 100.0), -0.5);
    EXPECT_THROW(reflyLeg(0, 0, 1, 0, 0, UniformCurrent(0, 0), nullptr, settings(0.0)), Error);
}

TEST(Reflight, ThePipelinesDefaultLegTimesOnTheJetMeasured)
{
    // glider_plan --start 1,-3 --goal 8,3 --speed 0.3: the reported times (TravelTimeCalculator, eps = 1e-3 absolute)
    // against the re-flight, printed leg by leg
    MissionSpec spec = defaultGulfStreamMission();
    spec.vehicle.speed = 0.3;
    const MissionProblem problem(spec);
    const MissionResult res = runMission(problem);
    ASSERT_TRUE(res.plan.solved);
    const std::vector<TimedPoint> &path = res.plan.path;
    const CurrentField &field = *problem.getField();
    const std::uint64_t before = field.callCount();
    const PathReflight r = reflyPath(path, field, problem.getEnvironment().get(), settings(0.3));
    const std::uint64_t reflightCalls = field.callCount() - before;
    ASSERT_TRUE(r.feasible) << r.why;
    ASSERT_EQ(r.times.size(), path.size());
    double worst = 0.0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
    {
        // leg by leg, each from its reported departure
        const LegReflight leg = reflyLeg(path[i].x, path[i].y, path[i + 1].x, path[i + 1].y, path[i].t,
                                         *problem.getField(), nullptr, settings(0.3));
        ASSERT_TRUE(leg.feasible) << i << ": " << leg.why;
        const double rd = relativeDifference(path[i + 1].t - path[i].t, leg.duration);
        worst = std::max(worst, std::abs(rd));
        std::printf("leg %2zu: reported %.9f re-flown %.9f relative %+.2e\n", i, path[i + 1].t - path[i].t,
                    leg.duration, rd);
    }
    const double total = relativeDifference(path.back().t, r.arrivalTime, path.front().t);
    std::printf("path: reported %.9f re-flown %.9f relative %+.2e; worst leg %.2e; the re-flight took %zu steps and "
                "%llu current-model calls\n",
                path.back().t - path.front().t, r.arrivalTime - path.front().t, total, worst, r.steps,
                static_cast<unsigned long long>(reflightCalls));
    EXPECT_LT(std::abs(total), 1e-2); // a sanity bound only: the figure is the measurement
}

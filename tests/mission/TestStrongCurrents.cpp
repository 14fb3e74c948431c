// The strong-current planners against answers found without them: a uniform current three times the
// speed (the reachable set is a drifting disc: closed form), the Rankine vortex (radial spirals: closed form), the
// linear shear u = a y (a two-heading route found by brute force in closed form: an upper bound of the optimum),
// and the meandering jet at low speeds (the level set). Every route is flown again independently of the planner
// (StrongCurrentChecks.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "StrongCurrentChecks.h"

using namespace ompl_glider;
using namespace strong_checks;

namespace
{
/// First time t > 0 with |d - c t| = V t + r: the reachable disc of a uniform current c (centre start + c t, radius
/// V t) first touches the ball of radius r about the goal (d = goal - start). +inf when it never does.
double uniformArrival(double dx, double dy, double cx, double cy, double V, double r)
{
    // (c^2 - V^2) t^2 - 2 (d.c + V r) t + (d^2 - r^2) = 0
    const double A = cx * cx + cy * cy - V * V, B = -2.0 * (dx * cx + dy * cy + V * r), C = dx * dx + dy * dy - r * r;
    const double disc = B * B - 4.0 * A * C;
    if (disc < 0.0)
        return std::numeric_limits<double>::infinity();
    const double s = std::sqrt(disc);
    const double t1 = (-B - s) / (2.0 * A), t2 = (-B + s) / (2.0 * A);
    double best = std::numeric_limits<double>::infinity();
    for (double t : {t1, t2})
        if (t > 0.0)
            best = std::min(best, t);
    return best;
}

std::string uniformYaml(double sx, double sy, double gx, double gy)
{
    return "name: strong_uniform\n"
           "current: {type: uniform, parameters: {u: 1.5, v: 0}}\n"
           "region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
           "start: {x: " +
           std::to_string(sx) + ", y: " + std::to_string(sy) +
           "}\n"
           "goal: {x: " +
           std::to_string(gx) + ", y: " + std::to_string(gy) +
           "}\n"
           "vehicle: {speed: 0.5}\n"
           "planner: {horizon: 30}\n";
}
} // namespace

// (1) Uniform current u = 3 V: the goal inside the cone of half-angle asin(1/3) is first reached at the smaller root
// of |g - s - c t| = V t. The straight leg from the start is then that optimum, so the default lattice finds it
// without switching (checked); the heading planner Isochrone, asked directly, must find it too.
TEST(StrongCurrents, UniformCurrentThreeTimesTheSpeedMatchesTheDriftingDisc)
{
    const MissionProblem problem = mission(uniformYaml(1, 0, 8, 1));
    const double tol = problem.gliderProblem(0.0, 0.5).goalTolerance;
    const double exact = uniformArrival(7, 1, 1.5, 0, 0.5, 0.0);
    const double withinRadius = uniformArrival(7, 1, 1.5, 0, 0.5, tol);
    for (const std::string planner : {"", "Isochrone"})
    {
        PlanOptions o;
        o.planner = planner;
        const PlannedPath plan = planRoute(problem, 0.0, o);
        ASSERT_TRUE(plan.solved) << planner << ": " << plan.reason;
        std::printf("uniform 3V: planner %s (switched from '%s'), travel time %.9f, closed form %.9f (rel %.3e), "
                    "%.3f s\n",
                    plan.planner.c_str(), plan.switchedFrom.c_str(), plan.travelTime, exact,
                    plan.travelTime / exact - 1.0, plan.planningSeconds + plan.postprocessSeconds);
        EXPECT_NEAR(plan.travelTime, exact, 0.005 * exact) << plan.planner;
        EXPECT_GE(plan.travelTime, withinRadius * (1.0 - 1e-6)) << plan.planner << ": a route cannot beat the disc";
        if (planner.empty())
            expectStraightLegRetiming(problem, plan, "uniform 3V default");
        else
            expectHeadingReflight(problem, plan, "uniform 3V Isochrone");
    }
}

// (1) Upstream of the start the drifting disc never reaches the goal: no path, and the level set says why.
TEST(StrongCurrents, UniformCurrentThreeTimesTheSpeedUpstreamGoalHasNoPath)
{
    const MissionProblem problem = mission(uniformYaml(8, 0, 2, 0));
    ASSERT_TRUE(std::isinf(uniformArrival(-6, 0, 1.5, 0, 0.5, 0.0)));
    const PlannedPath plan = planRoute(problem, 0.0);
    EXPECT_FALSE(plan.solved);
    EXPECT_EQ(plan.planner, "ZA*TVE"); // no route of any planner: the asked one's outcome, with what the others found
    EXPECT_EQ(plan.status, PlanStatus::NoPath);
    EXPECT_NE(plan.reason.find("no path exists"), std::string::npos) << plan.reason; // proven by the level set
    EXPECT_NE(plan.reason.find("nor Isochrone"), std::string::npos) << plan.reason;
    std::printf("uniform 3V upstream: planner %s, reason: %s\n", plan.planner.c_str(), plan.reason.c_str());
    EXPECT_NE(plan.reason.find("front"), std::string::npos) << plan.reason;
    EXPECT_NE(plan.reason.find("goal"), std::string::npos) << plan.reason;
}

// (2) Rankine vortex (R = 1, vmax = 1 at the origin, no stream): the radial spiral from radius r0 to r1 takes
// |r1 - r0| / V, and no route is faster (the current is azimuthal, so |dr/dt| <= V). The goals are the ends of the
// spirals from (2, 0): T = 10 at V = 0.2 (r1 = 4), T = 6 at V = 0.5 (r1 = 5).
TEST(StrongCurrents, RankineVortexIsochroneMatchesTheRadialSpiral)
{
    struct Case
    {
        double V, gx, gy, T;
    };
    for (const Case &c : {Case{0.2, 1.2612894, 3.7959385, 10.0}, Case{0.5, 4.1266781, 2.8232124, 6.0}})
    {
        const std::string yaml =
            "name: rankine\n"
            "current: {type: rankine_vortex, parameters: {x0: 0, y0: 0, radius: 1, vmax: 1, u: 0, v: 0}}\n"
            "region: {x_min: -6, x_max: 6, y_min: -6, y_max: 6}\n"
            "start: {x: 2, y: 0}\n"
            "goal: {x: " +
            std::to_string(c.gx) + ", y: " + std::to_string(c.gy) +
            "}\n"
            "vehicle: {speed: " +
            std::to_string(c.V) +
            "}\n"
            "planner: {name: Isochrone, horizon: 40}\n";
        const MissionProblem problem = mission(yaml);
        const PlannedPath plan = planRoute(problem, 0.0);
        ASSERT_TRUE(plan.solved) << "V " << c.V << ": " << plan.reason;
        const double tol = problem.gliderProblem(0.0, c.V).goalTolerance;
        const double lower = (std::hypot(c.gx, c.gy) - 2.0 - tol) / c.V;
        std::printf("rankine V %.2f: travel time %.9f, closed form %.9f (rel %.3e), %.2f s\n", c.V, plan.travelTime,
                    c.T, plan.travelTime / c.T - 1.0, plan.planningSeconds + plan.postprocessSeconds);
        EXPECT_NEAR(plan.travelTime, c.T, 0.01 * c.T) << "V " << c.V;
        EXPECT_GE(plan.travelTime, lower * (1.0 - 1e-6)) << "V " << c.V << ": no route beats |r1 - r0| / V";
        expectHeadingReflight(problem, plan, "rankine V " + std::to_string(c.V));
    }
}

// (2b) Convergence: the heading planner's route tends to the continuous optimum as its segments shrink. In the Rankine
// vortex the optimal heading turns continuously (radially outward while the vortex carries the glider round), so a
// route of N held headings is slower by an amount that falls as 1 / N^2 (measured: 4.8e-3, 1.2e-3, 3.0e-4, 7.4e-5,
// 1.9e-5 of T = 10 for N = 4 ... 64); every N stays above the bound |r1 - r0| / V.
TEST(StrongCurrents, IsochroneConvergesToTheRadialSpiralAsItsSegmentsShrink)
{
    std::vector<double> errors;
    for (int n : {4, 8, 16, 32, 64})
    {
        const std::string yaml =
            "name: rankine\n"
            "current: {type: rankine_vortex, parameters: {x0: 0, y0: 0, radius: 1, vmax: 1, u: 0, v: 0}}\n"
            "region: {x_min: -6, x_max: 6, y_min: -6, y_max: 6}\n"
            "start: {x: 2, y: 0}\n"
            "goal: {x: 1.2612894, y: 3.7959385}\n"
            "vehicle: {speed: 0.2}\n"
            "planner: {name: Isochrone, horizon: 40, parameters: {segments: " +
            std::to_string(n) + "}}\n";
        const MissionProblem problem = mission(yaml);
        const PlannedPath plan = planRoute(problem, 0.0);
        ASSERT_TRUE(plan.solved) << n << " segments: " << plan.reason;
        errors.push_back(plan.travelTime / 10.0 - 1.0);
        std::printf("rankine V 0.2, %d segments: travel time %.9f (rel %.3e)\n", n, plan.travelTime, errors.back());
        EXPECT_GE(errors.back(), -1e-5) << n; // the goal tolerance (1e-5 of the distance) is all it may gain
    }
    // second order in the segment length: each doubling of N divides the excess by about 4 (at least 3 here)
    for (std::size_t k = 0; k + 1 < errors.size(); ++k)
        EXPECT_LT(errors[k + 1], errors[k] / 3.0) << "N = " << (4 << k) << " -> " << (8 << k);
    EXPECT_LT(errors.back(), 5e-5);
}

namespace
{
/// Linear shear u = a y, v = 0: the least time of a route of two held headings (theta1 for t1, then one heading to
/// the goal), in closed form: with a held heading y is linear in t, so the x-drift of a segment is a times its mean
/// y, and the second segment is the uniform-current problem with the current a (y1 + gy) / 2. Brute force over
/// (theta1, t1), then a pattern search around the best. An upper bound of the optimum: the route is exact.
struct ShearRoute
{
    double time{std::numeric_limits<double>::infinity()};
    double theta1{0.0}, t1{0.0};
};

double shearTwoHeadings(double a, double V, double sx, double sy, double gx, double gy, double theta1, double t1)
{
    const double y1 = sy + V * std::sin(theta1) * t1;
    const double x1 = sx + V * std::cos(theta1) * t1 + a * t1 * (sy + y1) / 2.0;
    const double m = a * (y1 + gy) / 2.0;
    return t1 + uniformArrival(gx - x1, gy - y1, m, 0.0, V, 0.0);
}

ShearRoute bestShearRoute(double a, double V, double sx, double sy, double gx, double gy, double tMax)
{
    constexpr double kPi = 3.14159265358979323846;
    ShearRoute best;
    const int nTheta = 720, nT = 400;
    for (int i = 0; i < nTheta; ++i)
        for (int j = 0; j <= nT; ++j)
        {
            const double th = 2.0 * kPi * i / nTheta, t1 = tMax * j / nT;
            const double T = shearTwoHeadings(a, V, sx, sy, gx, gy, th, t1);
            if (T < best.time)
                best = {T, th, t1};
        }
    double dth = 2.0 * kPi / nTheta, dt = tMax / nT;
    while (dth > 1e-12)
    {
        bool moved = false;
        for (int di = -1; di <= 1; ++di)
            for (int dj = -1; dj <= 1; ++dj)
            {
                const double th = best.theta1 + di * dth, t1 = std::max(0.0, best.t1 + dj * dt);
                const double T = shearTwoHeadings(a, V, sx, sy, gx, gy, th, t1);
                if (T < best.time)
                {
                    best = {T, th, t1};
                    moved = true;
                }
            }
        if (!moved)
        {
            dth /= 2.0;
            dt /= 2.0;
        }
    }
    return best;
}
} // namespace

// (3) Linear shear u = y with V = 0.5 (the current is up to 8 V in the region, 2 V westward at the start): the
// heading planner's route is no slower than the best route of two held headings, and within 2 % of it.
TEST(StrongCurrents, LinearShearIsochroneBeatsTheBestTwoHeadingRoute)
{
    const double a = 1.0, V = 0.5, sx = 0.0, sy = -1.0, gx = 4.0, gy = 1.0;
    const ShearRoute bound = bestShearRoute(a, V, sx, sy, gx, gy, 12.0);
    ASSERT_TRUE(std::isfinite(bound.time));
    const MissionProblem problem = mission("name: shear\n"
                                           "current: {type: linear_shear, parameters: {a: 1}}\n"
                                           "region: {x_min: -6, x_max: 10, y_min: -4, y_max: 4}\n"
                                           "start: {x: 0, y: -1}\n"
                                           "goal: {x: 4, y: 1}\n"
                                           "vehicle: {speed: 0.5}\n"
                                           "planner: {name: Isochrone, horizon: 40}\n");
    const PlannedPath plan = planRoute(problem, 0.0);
    ASSERT_TRUE(plan.solved) << plan.reason;
    std::printf("shear: travel time %.9f, best two-heading route %.9f (theta1 %.6f rad for %.6f) (rel %.3e), %.2f s\n",
                plan.travelTime, bound.time, bound.theta1, bound.t1, plan.travelTime / bound.time - 1.0,
                plan.planningSeconds + plan.postprocessSeconds);
    EXPECT_LE(plan.travelTime, bound.time * (1.0 + 1e-6));
    EXPECT_NEAR(plan.travelTime, bound.time, 0.02 * bound.time);
    expectHeadingReflight(problem, plan, "shear");
}

// (4, 5) The meandering jet at the speed of the paper: straight legs, their times those of an accurate re-timing.
TEST(StrongCurrents, JetAtHalfSpeedStraightLegsRetimeExactly)
{
    const MissionProblem problem(jetAt(0.5));
    const PlannedPath plan = planRoute(problem, 0.0);
    ASSERT_TRUE(plan.solved) << plan.reason;
    EXPECT_TRUE(plan.switchedFrom.empty());
    expectStraightLegRetiming(problem, plan, "jet V 0.5");
}

namespace
{
/// The default pipeline on the jet at speed V within 1.5 % of the level set at its default resolution; both routes
/// fly again independently.
void expectJetNearLevelSet(double V)
{
    const MissionProblem problem(jetAt(V));
    const PlannedPath plan = planRoute(problem, 0.0);
    ASSERT_TRUE(plan.solved) << "V " << V << ": " << plan.reason;
    PlanOptions ls;
    ls.planner = "LevelSet";
    const PlannedPath level = planRoute(problem, 0.0, ls);
    ASSERT_TRUE(level.solved) << "V " << V << ": " << level.reason;
    std::printf("jet V %.2f: default (%s, switched from '%s') %.6f in %.2f s, LevelSet (%s) %.6f in %.2f s "
                "(rel %.3e)\n",
                V, plan.planner.c_str(), plan.switchedFrom.c_str(), plan.travelTime,
                plan.planningSeconds + plan.postprocessSeconds, level.headings ? "headings" : "straight legs",
                level.travelTime, level.planningSeconds + level.postprocessSeconds,
                plan.travelTime / level.travelTime - 1.0);
    EXPECT_NEAR(plan.travelTime, level.travelTime, 0.015 * level.travelTime) << "V " << V;
    const std::string what = "jet V " + std::to_string(V);
    if (plan.headings)
        expectHeadingReflight(problem, plan, what + " default");
    else
        expectStraightLegRetiming(problem, plan, what + " default");
    if (level.headings)
        expectHeadingReflight(problem, level, what + " LevelSet");
    else
        expectStraightLegRetiming(problem, level, what + " LevelSet");
}
} // namespace

// (4) The jet at V = 0.2 and 0.15 (the jet's core is several times faster): the default pipeline within 1.5 % of the
// level set at its default resolution.
TEST(StrongCurrents, JetAtSpeedPoint2DefaultMatchesTheLevelSet)
{
    expectJetNearLevelSet(0.2);
}

TEST(StrongCurrents, JetAtSpeedPoint15DefaultMatchesTheLevelSet)
{
    expectJetNearLevelSet(0.15);
}

// (4) At V = 0.1 the default pipeline still returns a route, and it flies.
TEST(StrongCurrents, JetAtSpeedPoint1DefaultReturnsARoute)
{
    const MissionProblem slow(jetAt(0.1));
    const PlannedPath plan = planRoute(slow, 0.0);
    std::printf("jet V 0.10: default (%s, switched from '%s') solved %d, %.6f in %.2f s %s\n", plan.planner.c_str(),
                plan.switchedFrom.c_str(), plan.solved ? 1 : 0, plan.travelTime,
                plan.planningSeconds + plan.postprocessSeconds, plan.reason.c_str());
    ASSERT_TRUE(plan.solved) << plan.reason;
    if (plan.headings)
        expectHeadingReflight(slow, plan, "jet V 0.1 default");
    else
        expectStraightLegRetiming(slow, plan, "jet V 0.1 default");
}

// (6) The execution simulator, flying the returned route in its own forecast (truth = forecast) with the route's own
// headings (strategy planned_headings, added to the default strategies for a heading route), reaches the goal within
// a radius of 1e-5 at the reported arrival, within 1e-5 of the travel time: the pilot's plan is what the glider does.
// On the jet at V = 0.2 (the default switches to Isochrone) and on the time-dependent double gyre at V = 0.15.
TEST(StrongCurrents, ExecutionSimulatorFliesTheHeadingRouteToTheGoalAtTheReportedTime)
{
    MissionSpec jet = jetAt(0.2);
    const MissionSpec gyre = parseMission(R"(name: gyre
current: {type: double_gyre, parameters: {amplitude: 0.3, length: 1, epsilon: 0.25, omega: 0.6283185307179586}}
region: {x_min: 0, x_max: 2, y_min: 0, y_max: 1}
start: {x: 0.3, y: 0.3}
goal: {x: 1.6, y: 0.7}
departure: {time: 0}
vehicle: {speed: 0.15}
)",
                                          "gyre.yaml");
    for (MissionSpec m : {jet, gyre})
    {
        m.execution.enabled = true;
        m.execution.radius = 1e-5;
        m.execution.surfacingInterval = 0.25;
        m.execution.replanEvery = 100000; // the replan strategy plans once, at the start
        const MissionProblem problem(m);
        const MissionResult r = runMission(problem);
        ASSERT_TRUE(r.plan.solved) << m.name << ": " << r.plan.reason;
        ASSERT_TRUE(r.plan.headingRoute()) << m.name;
        EXPECT_EQ(r.plan.switchedFrom, "ZA*TVE") << m.name;
        ASSERT_TRUE(r.execution.has_value());
        const ExecutionResult &e = *r.execution;
        ASSERT_FALSE(e.strategies.empty());
        ASSERT_EQ(e.strategies.front(), ControlStrategy::PlannedHeadings) << m.name;
        const FlownTrack &f = e.runs[0].flown[0];
        EXPECT_TRUE(f.reached) << m.name << ": closest " << f.finalDistance;
        EXPECT_FALSE(f.grounded) << m.name << ": " << f.groundedWhy;
        const double reported = r.plan.departure + r.plan.travelTime;
        EXPECT_NEAR(f.arrivalTime, reported, 1e-5 * r.plan.travelTime) << m.name;
        EXPECT_LE(f.arrivalTime, reported + 1e-9) << m.name; // the radius is entered before the route's end
        // the other strategies steer toward waypoints with a crab angle: in this current they do not arrive in time
        std::printf("%s: travel time %.6f, planned_headings arrives %.6f after departure\n", m.name.c_str(),
                    r.plan.travelTime, f.arrivalTime - r.plan.departure);
    }
}

// Closed-form checks of the two strong-current test flows: the time-dependent double gyre
// ([ShaddenLCS]) and the Rankine vortex ([LollaLevelSet]'s benchmark), and the closed-form travel times in the
// vortex that the planners' tests use as independent references.
//
// Travel times in the Rankine vortex without background stream (u = v = 0), glider speed V through the water
// (any V > 0, also V much smaller than vmax), heading free at every instant. Polar coordinates (r, theta) about the
// centre, theta counter-clockwise from +x; w(r) = vmax r / R (r <= R), vmax R / r (r > R).
//  (1) The current is purely azimuthal, so the radial ground speed is the radial part of the glider's own velocity:
//      |dr/dt| <= V along every route, and any route from radius r0 to radius r1 takes at least |r1 - r0| / V.
//  (2) Heading radially (out or in) attains |dr/dt| = V; the current turns the glider at dtheta/dt = w(r) / r, so
//      dtheta/dr = w(r) / (V r) and the route is the spiral
//          theta(r1) - theta(r0) = vmax (b - a) / (V R)            for a core stretch a..b (r <= R),
//                                = (vmax R / V) (1/a - 1/b)        outside the core,
//      summed over the stretches (for an inward route a > b, the turn is the same magnitude, counter-clockwise).
//      Hence: the time-optimal trip from (r0, theta0) to the spiral's end point (r1, theta(r1)) takes exactly
//      T* = |r1 - r0| / V (lower bound (1) attained), and any other point at radius r1 takes strictly longer
//      (equality in (1) forces the radial heading almost everywhere, hence that spiral).
//  (3) From the centre, the first heading chooses theta0 freely, so every point at distance d is reached at best in
//      T* = d / V, whatever vmax: the earliest-arrival front at time t is the circle of radius V t (the kind of
//      analytic answer [LollaLevelSet] checks its Rankine-vortex benchmark against). The optimal route ends at angle
//      theta0 + (vmax / V)(d / R) for d <= R and theta0 + (vmax / V)(2 - R / d) for d > R, so the first heading is
//      theta_goal minus that turn.
//  (4) Upper bounds (flown routes, not optimal in general): two points at the same radius r, the second at the
//      counter-clockwise angle dtheta from the first, are joined in r dtheta / (w(r) + V) by the circle flown with
//      the heading tangent (counter-clockwise) at every instant (ground speed w(r) + V along the circle, no radial
//      component); any two points at radii r0, r1 in (r0 + r1) / V by (2) into the centre and (3) out of it.
// Only (2) and (3) are optimality claims; a planner flying held headings (piecewise constant) is slower than T* by
// its discretisation and must converge to T* as its segments shrink.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/DoubleGyre.h"
#include "ompl_glider/current/RankineVortex.h"

using namespace ompl_glider;

namespace
{
/// Same bits (so also the sign of a zero).
bool sameBits(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// The double gyre of [ShaddenLCS] in its own variables on [0, 2] x [0, 1], written here independently of
/// DoubleGyre: u = -pi A sin(pi f) cos(pi y), v = pi A cos(pi f) sin(pi y) df/dx.
Velocity shaddenGyre(double A, double eps, double omega, double x, double y, double t)
{
    const double a = eps * std::sin(omega * t), b = 1.0 - 2.0 * eps * std::sin(omega * t);
    const double f = a * x * x + b * x, fx = 2.0 * a * x + b;
    return {-M_PI * A * std::sin(M_PI * f) * std::cos(M_PI * y),
            M_PI * A * std::cos(M_PI * f) * std::sin(M_PI * y) * fx};
}

/// Separatrix X_s(s) in [0, 2]: f(X_s) = 1, i.e. s X^2 + (1 - 2s) X - 1 = 0 (discriminant 1 + 4 s^2); the root
/// written without cancellation, also for s = 0 and tiny s.
double separatrix(double s)
{
    return 2.0 / ((1.0 - 2.0 * s) + std::sqrt(1.0 + 4.0 * s * s));
}

/// RK4 of dp/dt = c(p, t) + V h(p) with a continuously steered unit heading h, over [0, T]: steps of T / steps,
/// shorter near @p centre (at most 1 % of the distance to it over V, at least 1e-9), where a radial heading law is
/// singular.
Point2 flyContinuous(const CurrentField &field, Point2 p, double V, double T, int steps,
                     const std::function<Velocity(Point2)> &heading, Point2 centre = {NAN, NAN})
{
    auto f = [&](Point2 q, double t) {
        const Velocity c = field.velocity(q.x, q.y, 0.0, t);
        const Velocity h = heading(q);
        return Velocity{c.u + V * h.u, c.v + V * h.v};
    };
    double t = 0.0;
    while (t < T)
    {
        double dt = T / steps;
        if (std::isfinite(centre.x))
            dt = std::min(dt, std::max(1e-9, 0.01 * std::hypot(p.x - centre.x, p.y - centre.y) / V));
        dt = std::min(dt, T - t);
        const Velocity k1 = f(p, t);
        const Velocity k2 = f({p.x + 0.5 * dt * k1.u, p.y + 0.5 * dt * k1.v}, t + 0.5 * dt);
        const Velocity k3 = f({p.x + 0.5 * dt * k2.u, p.y + 0.5 * dt * k2.v}, t + 0.5 * dt);
        const Velocity k4 = f({p.x + dt * k3.u, p.y + dt * k3.v}, t + dt);
        p.x += dt / 6.0 * (k1.u + 2.0 * k2.u + 2.0 * k3.u + k4.u);
        p.y += dt / 6.0 * (k1.v + 2.0 * k2.v + 2.0 * k3.v + k4.v);
        t += dt;
    }
    return p;
}

/// Turn of the radial spiral (2) from radius a to radius b (either order), counter-clockwise, in radians.
double spiralTurn(double vmax, double R, double V, double a, double b)
{
    auto F = [&](double r) { // antiderivative of w(r) / (V r) in r, continuous at R
        return r <= R ? vmax * r / (V * R) : vmax / V * (2.0 - R / r);
    };
    return std::abs(F(b) - F(a));
}

double wrapAngle(double a)
{
    return std::remainder(a, 2.0 * M_PI);
}
} // namespace

// ---------------------------------------------------------------- double gyre

TEST(DoubleGyre, SteadyCaseIsTheHistoricFormulaBitForBit)
{
    // the expressions of the steady field before the time dependence was added
    const double A = 0.1, L = 1.3, w = M_PI / L;
    for (const DoubleGyre &g : {DoubleGyre(A, L), DoubleGyre(A, L, 0.0, 0.7), DoubleGyre(A, L, 0.25, 0.0)})
    {
        EXPECT_EQ(g.name(), "double gyre");
        EXPECT_TRUE(g.steady());
        EXPECT_TRUE(sameBits(g.maxSpeed({}), M_PI * std::abs(A) / L));
        for (double x : {0.0, 0.05, 0.41, 1.3, 1.77, 2.6})
            for (double y : {0.0, 0.2, 0.65, 1.1})
                for (double t : {0.0, 2.5, 7.5})
                {
                    const Velocity c = g.velocity(x, y, 0, t);
                    EXPECT_TRUE(sameBits(c.u, -A * w * std::sin(w * x) * std::cos(w * y)));
                    EXPECT_TRUE(sameBits(c.v, A * w * std::cos(w * x) * std::sin(w * y)));
                    const double a = A * w * w;
                    const double sx = std::sin(w * x), cx = std::cos(w * x), sy = std::sin(w * y), cy = std::cos(w * y);
                    const Jacobian J = g.jacobian(x, y, 0, t);
                    EXPECT_TRUE(sameBits(J.ux, -a * cx * cy));
                    EXPECT_TRUE(sameBits(J.uy, a * sx * sy));
                    EXPECT_TRUE(sameBits(J.vx, -a * sx * sy));
                    EXPECT_TRUE(sameBits(J.vy, a * cx * cy));
                    EXPECT_TRUE(
                        sameBits(*g.streamFunction(x, y, 0, t), A * std::sin(M_PI * x / L) * std::sin(M_PI * y / L)));
                }
    }
}

TEST(DoubleGyre, TimeDependentFieldIsShaddensScaledByLength)
{
    const double A = 0.1, eps = 0.25, omega = 2 * M_PI / 10, L = 2.5;
    const DoubleGyre g(A, L, eps, omega);
    EXPECT_EQ(g.name(), "time-dependent double gyre");
    EXPECT_FALSE(g.steady());
    for (double X : {0.1, 0.5, 0.93, 1.2, 1.8})
        for (double Y : {0.15, 0.5, 0.8})
            for (double t : {0.0, 1.3, 4.0, 8.8})
            {
                // x = L X, y = L Y; velocities scale as 1/L (psi keeps its amplitude A)
                const Velocity ref = shaddenGyre(A, eps, omega, X, Y, t);
                const Velocity c = g.velocity(L * X, L * Y, 0, t);
                EXPECT_NEAR(c.u, ref.u / L, 1e-14);
                EXPECT_NEAR(c.v, ref.v / L, 1e-14);
            }
}

TEST(DoubleGyre, SeparatrixOscillatesWhereFIsOne)
{
    const double A = 0.1, eps = 0.25, omega = 2 * M_PI / 10, L = 1.0, w = M_PI / L;
    const DoubleGyre g(A, L, eps, omega);
    for (double t : {0.0, 1.0, 2.5, 5.0, 7.5, 9.0})
    {
        const double s = eps * std::sin(omega * t);
        const double xs = L * separatrix(s);
        const double fx = 2.0 * s * xs / L + 1.0 - 2.0 * s;
        for (double y : {0.1, 0.3, 0.5, 0.9})
        {
            // on the separatrix f = 1: no flow across it (u = 0), v = -A w sin(w y) f_X
            const Velocity c = g.velocity(xs, y, 0, t);
            EXPECT_NEAR(c.u, 0.0, 1e-15) << "t " << t;
            EXPECT_NEAR(c.v, -A * w * std::sin(w * y) * fx, 1e-15);
            // at the steady separatrix x = L: f = 1 - s, so u = -A w sin(pi s) cos(w y) (zero only when s = 0)
            const Velocity m = g.velocity(L, y, 0, t);
            EXPECT_NEAR(m.u, -A * w * std::sin(M_PI * s) * std::cos(w * y), 1e-15);
            // the walls x = 0 and x = 2L stay closed (f = 0 and 2 there)
            EXPECT_NEAR(g.velocity(0.0, y, 0, t).u, 0.0, 1e-15);
            EXPECT_NEAR(g.velocity(2 * L, y, 0, t).u, 0.0, 1e-15);
        }
    }
    // for eps = 1/4 the separatrix swings between L (3 - sqrt 5) = 0.764 L (s = -eps) and L (sqrt 5 - 1) = 1.236 L
    // (s = eps); X_s(s) = 1 + s + O(s^3)
    EXPECT_NEAR(separatrix(eps), std::sqrt(5.0) - 1.0, 1e-15);
    EXPECT_NEAR(separatrix(-eps), 3.0 - std::sqrt(5.0), 1e-15);
    EXPECT_NEAR(separatrix(0.01), 1.01, 1e-5);
    // the point x = L (1 + eps/2), mid-depth, lies between the extremes: in the left gyre (psi > 0 for A > 0) at
    // t = T/4 (s = eps), in the right one (psi < 0) at t = 3T/4
    const double T = 2 * M_PI / omega;
    // (f = 0.8789 and 1.3711 there: psi = A sin(pi f) = 0.0371 and -0.0917)
    EXPECT_GT(*g.streamFunction(L * (1 + eps / 2), 0.5 * L, 0, T / 4), 0.03);
    EXPECT_LT(*g.streamFunction(L * (1 + eps / 2), 0.5 * L, 0, 3 * T / 4), -0.09);
}

TEST(DoubleGyre, PeriodicInTimeAndMirroredAfterHalfAPeriod)
{
    const double L = 1.7, omega = 0.9, T = 2 * M_PI / omega;
    const DoubleGyre g(0.2, L, 0.3, omega);
    for (double x : {0.2, 0.9, 1.7, 2.9})
        for (double y : {0.3, 1.1})
            for (double t : {0.0, 0.4, 3.3})
            {
                const Velocity c = g.velocity(x, y, 0, t);
                const Velocity p = g.velocity(x, y, 0, t + T), p3 = g.velocity(x, y, 0, t - 3 * T);
                EXPECT_NEAR(p.u, c.u, 1e-13);
                EXPECT_NEAR(p.v, c.v, 1e-13);
                EXPECT_NEAR(p3.u, c.u, 1e-13);
                EXPECT_NEAR(p3.v, c.v, 1e-13);
                // s -> -s after half a period, and f(2 - X, -s) = 2 - f(X, s): psi(2L - x, y, t + T/2) =
                // -psi(x, y, t), so u(2L - x, y, t + T/2) = -u(x, y, t) and v(2L - x, y, t + T/2) = v(x, y, t)
                const Velocity h = g.velocity(2 * L - x, y, 0, t + T / 2);
                EXPECT_NEAR(h.u, -c.u, 1e-13);
                EXPECT_NEAR(h.v, c.v, 1e-13);
                EXPECT_NEAR(*g.streamFunction(2 * L - x, y, 0, t + T / 2), -*g.streamFunction(x, y, 0, t), 1e-13);
            }
    // and the field does change within a period
    EXPECT_GT(std::abs(g.velocity(0.3, 0.5, 0, T / 4).v - g.velocity(0.3, 0.5, 0, 3 * T / 4).v), 0.05);
}

TEST(DoubleGyre, SpeedBoundIsReachedAndUnboundedRegionsAreInfinite)
{
    const double A = 0.1, eps = 0.25, omega = 2 * M_PI / 10, L = 1.0;
    const DoubleGyre g(A, L, eps, omega);
    const double bound = g.maxSpeed({0.0, 2.0 * L, 0.0, L});
    EXPECT_NEAR(bound, M_PI * A / L * (1 + 2 * eps), 1e-12);
    // reached at x = 0, y = L/2 when s = -eps (t = 7.5): the flow along the wall, pi A / L (1 + 2 eps)
    const Velocity c = g.velocity(0.0, 0.5 * L, 0, 7.5);
    EXPECT_NEAR(std::hypot(c.u, c.v), bound, 1e-12);
    EXPECT_LE(std::hypot(c.u, c.v), bound);
    // a region reaching farther from x = L has a larger f_X, so a larger bound; unbounded: infinite
    EXPECT_NEAR(g.maxSpeed({-1.0, 2.0, 0.0, 1.0}), M_PI * A / L * (1 + 4 * eps), 1e-12);
    EXPECT_TRUE(std::isinf(g.maxSpeed({})));
    // the wider bound holds on a dense sample of its region, and is needed there (more than the [0, 2L] bound)
    const double wide = g.maxSpeed({-1.0, 2.0, 0.0, 1.0});
    double maxSeen = 0.0;
    for (int i = 0; i <= 120; ++i)
        for (int j = 0; j <= 40; ++j)
            for (int k = 0; k <= 40; ++k)
            {
                const Velocity v = g.velocity(-1.0 + 3.0 * i / 120, 1.0 * j / 40, 0, 10.0 * k / 40);
                maxSeen = std::max(maxSeen, std::hypot(v.u, v.v));
            }
    EXPECT_LE(maxSeen, wide);
    EXPECT_GT(maxSeen, 1.1 * bound);
}

TEST(DoubleGyre, RegistryTakesEpsilonAndOmega)
{
    const auto f = makeAnalyticField("double_gyre", {{"epsilon", 0.25}, {"omega", 2 * M_PI / 10}});
    const DoubleGyre g(0.1, 1.0, 0.25, 2 * M_PI / 10);
    for (double t : {0.0, 2.5, 6.0})
    {
        EXPECT_EQ(f->velocity(0.4, 0.3, 0, t).u, g.velocity(0.4, 0.3, 0, t).u);
        EXPECT_EQ(f->velocity(0.4, 0.3, 0, t).v, g.velocity(0.4, 0.3, 0, t).v);
    }
    EXPECT_EQ(f->name(), "time-dependent double gyre");
    EXPECT_EQ(makeAnalyticField("double_gyre")->name(), "double gyre");
}

// ---------------------------------------------------------------- Rankine vortex

TEST(RankineVortex, SpeedProfileIsSolidBodyInsideAndOneOverROutside)
{
    RankineVortexParams p;
    p.x0 = 1.5;
    p.y0 = -2.0;
    p.radius = 0.8;
    p.vmax = 1.25;
    const RankineVortex vtx(p);
    for (double r : {0.0, 0.1, 0.4, 0.8, 1.0, 1.6, 4.0, 40.0})
    {
        const double expected = r <= p.radius ? p.vmax * r / p.radius : p.vmax * p.radius / r;
        EXPECT_NEAR(vtx.azimuthalSpeed(r), expected, 1e-15);
        for (double th : {0.0, 0.7, 2.0, 3.9, 5.5})
        {
            const double ex = std::cos(th), ey = std::sin(th);
            const Velocity c = vtx.velocity(p.x0 + r * ex, p.y0 + r * ey, 0, 0);
            EXPECT_NEAR(std::hypot(c.u, c.v), expected, 1e-14) << "r " << r;
            EXPECT_NEAR(c.u * ex + c.v * ey, 0.0, 1e-14);       // no radial component
            EXPECT_NEAR(-c.u * ey + c.v * ex, expected, 1e-14); // counter-clockwise
        }
    }
    EXPECT_EQ(vtx.name(), "rankine vortex");
    EXPECT_TRUE(vtx.divergenceFree());
    // steady
    EXPECT_EQ(vtx.velocity(2.0, -1.0, 0, 0).u, vtx.velocity(2.0, -1.0, 0, 123.0).u);
}

TEST(RankineVortex, ContinuousAtTheCoreRadiusWithTheVorticityJump)
{
    const RankineVortex vtx; // R = 1, vmax = 1 at the origin
    for (double th : {0.3, 1.9, 4.4})
    {
        const double ex = std::cos(th), ey = std::sin(th);
        const Velocity in = vtx.velocity((1 - 1e-9) * ex, (1 - 1e-9) * ey, 0, 0);
        const Velocity out = vtx.velocity((1 + 1e-9) * ex, (1 + 1e-9) * ey, 0, 0);
        EXPECT_NEAR(in.u, out.u, 3e-9);
        EXPECT_NEAR(in.v, out.v, 3e-9);
        EXPECT_NEAR(std::hypot(in.u, in.v), 1.0, 2e-9);
        EXPECT_NEAR(*vtx.streamFunction((1 - 1e-9) * ex, (1 - 1e-9) * ey, 0, 0),
                    *vtx.streamFunction((1 + 1e-9) * ex, (1 + 1e-9) * ey, 0, 0), 3e-9);
        EXPECT_NEAR(*vtx.streamFunction(ex, ey, 0, 0), 0.5, 1e-15);
        // vorticity v_x - u_y: 2 vmax / R in the core, 0 outside (irrotational)
        const Jacobian Ji = vtx.jacobian(0.5 * ex, 0.5 * ey, 0, 0), Jo = vtx.jacobian(2 * ex, 2 * ey, 0, 0);
        EXPECT_NEAR(Ji.vx - Ji.uy, 2.0, 1e-15);
        EXPECT_NEAR(Jo.vx - Jo.uy, 0.0, 1e-15);
        EXPECT_NEAR(Jo.ux + Jo.vy, 0.0, 1e-15);
    }
}

TEST(RankineVortex, ClockwiseForNegativeVmaxAndDriftAdds)
{
    RankineVortexParams p;
    p.vmax = -2.0;
    p.u = 0.3;
    p.v = -0.1;
    const RankineVortex vtx(p);
    // at (2, 0), outside the core: azimuthal -2 * 1 / 2 = -1 along +y, i.e. (0, -1), plus the stream
    const Velocity c = vtx.velocity(2.0, 0.0, 0, 0);
    EXPECT_NEAR(c.u, 0.3, 1e-15);
    EXPECT_NEAR(c.v, -1.1, 1e-15);
    // at the centre only the stream
    const Velocity o = vtx.velocity(0.0, 0.0, 0, 0);
    EXPECT_EQ(o.u, 0.3);
    EXPECT_EQ(o.v, -0.1);
    // the stream function of the uniform part: psi = v x - u y (plus the vortex's, which depends on r only)
    EXPECT_NEAR(*vtx.streamFunction(0.0, 0.5, 0, 0) - *vtx.streamFunction(0.0, -0.5, 0, 0), -0.3, 1e-15);
}

TEST(RankineVortex, SpeedBoundIsTheExactMaximumOverTheRegion)
{
    RankineVortexParams p;
    p.vmax = 2.0;
    p.radius = 0.5;
    p.u = 0.3;
    p.v = 0.4;
    const RankineVortex vtx(p);
    const double tol = 1e-11;                                    // the bound's rounding margin
    EXPECT_NEAR(vtx.maxSpeed({}), 2.5, tol);                     // the plane: |vmax| + |(u, v)|
    EXPECT_NEAR(vtx.maxSpeed({-1.0, 1.0, -1.0, 1.0}), 2.5, tol); // holds the core circle
    EXPECT_NEAR(vtx.maxSpeed({-0.1, 0.1, -0.1, 0.1}), 2.0 * std::hypot(0.1, 0.1) / 0.5 + 0.5, tol); // in the core
    EXPECT_NEAR(vtx.maxSpeed({3.0, 4.0, -4.0, 4.0}), 2.0 * 0.5 / 3.0 + 0.5, tol); // outside: nearest point (3, 0)
    EXPECT_NEAR(vtx.maxSpeed({3.0, 4.0, 4.0, 5.0}), 2.0 * 0.5 / 5.0 + 0.5, tol);  // nearest corner (3, 4)
    // and never below the speed at the nearest point
    const Velocity corner = vtx.velocity(3.0, 4.0, 0, 0);
    const Velocity cornerVortex{corner.u - 0.3, corner.v - 0.4};
    EXPECT_LE(std::hypot(cornerVortex.u, cornerVortex.v) + 0.5, vtx.maxSpeed({3.0, 4.0, 4.0, 5.0}));
    EXPECT_THROW(RankineVortex(RankineVortexParams{0.0, 0.0, 0.0, 1.0, 0.0, 0.0}), Error);
    EXPECT_THROW(RankineVortex(RankineVortexParams{0.0, 0.0, -1.0, 1.0, 0.0, 0.0}), Error);
    EXPECT_THROW(RankineVortex(RankineVortexParams{0.0, NAN, 1.0, 1.0, 0.0, 0.0}), Error);
}

TEST(RankineVortex, RegistryParametersAndDefaults)
{
    const auto f = makeAnalyticField(
        "rankine_vortex", {{"x0", 1.0}, {"y0", 2.0}, {"radius", 0.5}, {"vmax", 3.0}, {"u", 0.1}, {"v", 0.2}});
    // at (1, 3): r = 1 = 2 R, azimuthal 3 * 0.5 / 1 = 1.5 along -x, plus the stream
    const Velocity c = f->velocity(1.0, 3.0, 0, 0);
    EXPECT_NEAR(c.u, 0.1 - 1.5, 1e-15);
    EXPECT_NEAR(c.v, 0.2, 1e-15);
    const auto d = makeAnalyticField("rankine_vortex"); // unit vortex at the origin in still water
    EXPECT_NEAR(d->velocity(1.0, 0.0, 0, 0).v, 1.0, 1e-15);
    EXPECT_NEAR(d->velocity(0.0, 2.0, 0, 0).u, -0.5, 1e-15);
    EXPECT_THROW(makeAnalyticField("rankine_vortex", {{"radius", 0.0}}), Error);
}

// ---------------------------------------------------------------- closed-form travel times in the vortex

TEST(RankineVortexTravel, FromTheCentreRadialHeadingReachesDistanceDInDOverV)
{
    // (3): V = 0.2 against vmax = 1 (the current five times the glider), several distances and first headings
    const RankineVortex vtx;
    const double V = 0.2, R = 1.0, vmax = 1.0;
    for (double d : {0.6, 1.0, 3.0})
        for (double th0 : {0.0, 2.0})
        {
            const double T = d / V;
            auto radial = [th0](Point2 q) {
                const double r = std::hypot(q.x, q.y);
                return r > 0.0 ? Velocity{q.x / r, q.y / r} : Velocity{std::cos(th0), std::sin(th0)};
            };
            const Point2 end = flyContinuous(vtx, {0.0, 0.0}, V, T, 20000, radial, {0.0, 0.0});
            EXPECT_NEAR(std::hypot(end.x, end.y), d, 1e-7);
            const double turn = d <= R ? vmax / V * d / R : vmax / V * (2.0 - R / d);
            EXPECT_NEAR(wrapAngle(std::atan2(end.y, end.x) - (th0 + turn)), 0.0, 1e-7) << "d " << d;
            EXPECT_NEAR(turn, spiralTurn(vmax, R, V, 0.0, d), 1e-12);
        }
    // d = 3: the route turns (1/0.2)(2 - 1/3) = 8.3333 rad counter-clockwise on its way out
    EXPECT_NEAR(spiralTurn(1.0, 1.0, 0.2, 0.0, 3.0), 25.0 / 3.0, 1e-12);
}

TEST(RankineVortexTravel, RadialSpiralBetweenTwoRadiiTakesTheRadialDistanceOverV)
{
    // (2): start (x0 + 2, y0), goal at radius 4 on the spiral: T* = 10, turn 5 (1/2 - 1/4) = 1.25 rad; and inward
    // from radius 3 through the core edge to radius 0.5: T* = 12.5, turn 5 (1 - 1/3) + 5 (1 - 0.5) = 5.8333 rad
    RankineVortexParams p;
    p.x0 = 10.0;
    p.y0 = -5.0;
    const RankineVortex vtx(p);
    const double V = 0.2;
    struct Trip
    {
        double r0, r1, th0, turn;
    };
    for (const Trip &c : {Trip{2.0, 4.0, 0.0, 1.25}, Trip{3.0, 0.5, 1.0, 5.0 * (1.0 - 1.0 / 3.0) + 2.5}})
    {
        EXPECT_NEAR(spiralTurn(1.0, 1.0, V, c.r0, c.r1), c.turn, 1e-12);
        const double sign = c.r1 > c.r0 ? 1.0 : -1.0;
        auto radial = [&](Point2 q) {
            const double dx = q.x - p.x0, dy = q.y - p.y0, r = std::hypot(dx, dy);
            return Velocity{sign * dx / r, sign * dy / r};
        };
        const Point2 start{p.x0 + c.r0 * std::cos(c.th0), p.y0 + c.r0 * std::sin(c.th0)};
        const Point2 end = flyContinuous(vtx, start, V, std::abs(c.r1 - c.r0) / V, 20000, radial);
        const double ex = p.x0 + c.r1 * std::cos(c.th0 + c.turn), ey = p.y0 + c.r1 * std::sin(c.th0 + c.turn);
        EXPECT_NEAR(end.x, ex, 1e-7);
        EXPECT_NEAR(end.y, ey, 1e-7);
    }
    // the first trip's goal, for planner tests with the vortex at the origin: (4 cos 1.25, 4 sin 1.25)
    EXPECT_NEAR(4.0 * std::cos(1.25), 1.2612894, 1e-7);
    EXPECT_NEAR(4.0 * std::sin(1.25), 3.7959385, 1e-7);
}

TEST(RankineVortexTravel, NoHeadingGainsRadiusFasterThanV)
{
    // the lower bound (1): the current has no radial part, so dr/dt = V (h . e_r) <= V for every heading h
    const RankineVortex vtx;
    const double V = 0.2;
    for (double r : {0.3, 1.0, 2.5})
        for (double th : {0.1, 2.2, 4.0})
            for (double heading = 0.0; heading < 2 * M_PI; heading += 0.25)
            {
                const double ex = std::cos(th), ey = std::sin(th);
                const Velocity c = vtx.velocity(r * ex, r * ey, 0, 0);
                const double radial = (c.u + V * std::cos(heading)) * ex + (c.v + V * std::sin(heading)) * ey;
                EXPECT_LE(radial, V + 1e-15);
            }
}

TEST(RankineVortexTravel, TangentHeadingFliesTheCircleAtCurrentPlusV)
{
    // (4): from (2, 0) to (-2, 0) counter-clockwise along r = 2: ground speed 1/2 + 0.2, time 2 pi / 0.7 = 8.976
    const RankineVortex vtx;
    const double V = 0.2, r = 2.0, T = r * M_PI / (vtx.azimuthalSpeed(r) + V);
    EXPECT_NEAR(T, 2.0 * M_PI / 0.7, 1e-12);
    auto tangent = [](Point2 q) {
        const double rr = std::hypot(q.x, q.y);
        return Velocity{-q.y / rr, q.x / rr};
    };
    const Point2 end = flyContinuous(vtx, {r, 0.0}, V, T, 20000, tangent);
    EXPECT_NEAR(end.x, -2.0, 1e-7);
    EXPECT_NEAR(end.y, 0.0, 1e-7);
}

#pragma once
// An independent reference for "the default is the best route there is": a sweep of extremals of Zermelo's heading
// law from the start, integrated by a fixed-step RK4 of its own with the current's Jacobian by central differences
// (nothing of the library's planners, references or integrators: only the current field's velocity is read).
// Every extremal that passes through the goal without leaving the box is a flyable route (its heading schedule), so
// the fastest one bounds the optimum from above; a default answer slower than it by more than a tolerance is not the
// best route.
//
// Equations ([EichhornRAS] Eq. 2, Eq. 10): x' = u + V cos th, y' = v + V sin th,
// th' = -u_y cos^2 th + (u_x - v_y) cos th sin th + v_x sin^2 th (th from +x, counter-clockwise).

#include <algorithm>
#include <cmath>
#include <functional>
#include <future>
#include <limits>
#include <thread>
#include <vector>

namespace extremal_sweep
{
/// The current (u, v) at (x, y, t).
using Velocity2 = std::function<void(double x, double y, double t, double &u, double &v)>;

struct Setup
{
    Velocity2 current;
    double speed{0.5};
    double xMin{0}, xMax{0}, yMin{0}, yMax{0}; ///< an extremal that leaves the box ends there
    double maxTime{0.0};                       ///< longest extremal followed
    int headings{360};                         ///< initial headings swept over [0, 2 pi)
    int steps{2000};                           ///< RK4 steps over maxTime
    int zoom{0}; ///< finer windows about the nearest miss where the sweep finds no extremal through the goal
};

/// The fastest extremal found through the goal.
struct Best
{
    bool found{false};
    double time{std::numeric_limits<double>::infinity()};
    double heading{0.0}; ///< initial heading (radians from +x)
    int throughGoal{0};  ///< extremals found through the goal
};

namespace detail
{
struct S
{
    double x, y, th;
};

inline S rhs(const Setup &s, double t, const S &p)
{
    double u, v;
    s.current(p.x, p.y, t, u, v);
    const double e = 1e-6;
    double uxp, vxp, uxm, vxm, uyp, vyp, uym, vym;
    s.current(p.x + e, p.y, t, uxp, vxp);
    s.current(p.x - e, p.y, t, uxm, vxm);
    s.current(p.x, p.y + e, t, uyp, vyp);
    s.current(p.x, p.y - e, t, uym, vym);
    const double ux = (uxp - uxm) / (2 * e), vx = (vxp - vxm) / (2 * e);
    const double uy = (uyp - uym) / (2 * e), vy = (vyp - vym) / (2 * e);
    const double c = std::cos(p.th), sn = std::sin(p.th);
    return {u + s.speed * c, v + s.speed * sn, -uy * c * c + (ux - vy) * c * sn + vx * sn * sn};
}

inline S rk4(const Setup &s, double t, const S &p, double h)
{
    const S k1 = rhs(s, t, p);
    const S k2 = rhs(s, t + h / 2, {p.x + h / 2 * k1.x, p.y + h / 2 * k1.y, p.th + h / 2 * k1.th});
    const S k3 = rhs(s, t + h / 2, {p.x + h / 2 * k2.x, p.y + h / 2 * k2.y, p.th + h / 2 * k2.th});
    const S k4 = rhs(s, t + h, {p.x + h * k3.x, p.y + h * k3.y, p.th + h * k3.th});
    return {p.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x), p.y + h / 6 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y),
            p.th + h / 6 * (k1.th + 2 * k2.th + 2 * k3.th + k4.th)};
}

/// A closest approach of an extremal to the goal: its time since departure and signed miss (side of the track).
struct Pass
{
    double t, miss;
};

/// The closest approaches of the extremal with initial heading th0 (located inside a step by bisection on the
/// derivative of the distance, each trial point one RK4 step from the step's start).
inline std::vector<Pass> shoot(const Setup &s, double x0, double y0, double t0, double th0, double gx, double gy,
                               double until = std::numeric_limits<double>::infinity())
{
    std::vector<Pass> out;
    const double h = s.maxTime / s.steps;
    S p{x0, y0, th0};
    const auto approach = [&](double t, const S &q) {
        const S d = rhs(s, t, q);
        return (q.x - gx) * d.x + (q.y - gy) * d.y;
    };
    double a0 = approach(t0, p);
    for (int k = 0; k < s.steps && k * h <= until; ++k)
    {
        const double t = t0 + k * h;
        const S n = rk4(s, t, p, h);
        if (!(n.x >= s.xMin && n.x <= s.xMax && n.y >= s.yMin && n.y <= s.yMax) || !std::isfinite(n.th))
            break;
        const double a1 = approach(t + h, n);
        if (a0 < 0 && a1 >= 0)
        {
            double lo = 0, hi = h;
            for (int it = 0; it < 60; ++it)
            {
                const double mid = 0.5 * (lo + hi);
                (approach(t + mid, rk4(s, t, p, mid)) < 0 ? lo : hi) = mid;
            }
            const S q = rk4(s, t, p, hi);
            const S d = rhs(s, t + hi, q);
            const double sp = std::hypot(d.x, d.y);
            out.push_back({k * h + hi, sp > 0 ? (d.x * (gy - q.y) - d.y * (gx - q.x)) / sp : 0.0});
        }
        p = n;
        a0 = a1;
    }
    return out;
}

inline const Pass *nearest(const std::vector<Pass> &v, double t)
{
    const Pass *b = nullptr;
    for (const Pass &p : v)
        if (!b || std::abs(p.t - t) < std::abs(b->t - t))
            b = &p;
    return b;
}
/// The fastest extremal through the goal among the headings from + j (span / n), j = 0..n (the whole circle, its
/// last heading next to its first, when span is 2 pi): sign changes of the miss between neighbouring headings, each
/// refined by bisection on the heading until the miss is below 1e-7 of the trip (else not counted). Also the heading
/// whose pass came nearest the goal.
inline Best window(const Setup &s, double x0, double y0, double t0, double gx, double gy, double from, double span,
                   double &nearestHeading, double &nearestMiss)
{
    const bool circle = span >= 2 * M_PI;
    const int n = s.headings, count = circle ? n : n + 1;
    const double dth = span / n;
    std::vector<std::vector<Pass>> shots(count);
    const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::future<void>> jobs;
    for (unsigned w = 0; w < workers; ++w)
        jobs.push_back(std::async(std::launch::async, [&, w] {
            for (int j = static_cast<int>(w); j < count; j += static_cast<int>(workers))
                shots[j] = shoot(s, x0, y0, t0, from + j * dth, gx, gy);
        }));
    for (auto &j : jobs)
        j.get();
    nearestMiss = std::numeric_limits<double>::infinity();
    for (int j = 0; j < count; ++j)
        for (const Pass &e : shots[j])
            if (std::abs(e.miss) < nearestMiss)
            {
                nearestMiss = std::abs(e.miss);
                nearestHeading = from + j * dth;
            }
    const double D = std::hypot(gx - x0, gy - y0);
    Best best;
    for (int j = 0; j + (circle ? 0 : 1) < count; ++j)
        for (const Pass &e : shots[j])
        {
            const Pass *f = nearest(shots[(j + 1) % count], e.t);
            if (!f || (e.miss < 0) == (f->miss < 0) || std::abs(e.miss) + std::abs(f->miss) > 0.5 * D)
                continue;
            if (best.found && std::min(e.t, f->t) > 1.2 * best.time)
                continue;
            double a = from + j * dth, fa = e.miss, b = from + (j + 1) * dth;
            double tRef = std::min(e.t, f->t), miss = std::abs(fa);
            Pass at = e;
            for (int it = 0; it < 60 && miss > 1e-7 * D; ++it)
            {
                const double m = 0.5 * (a + b);
                const std::vector<Pass> passes = shoot(s, x0, y0, t0, m, gx, gy, 1.2 * tRef + 10 * s.maxTime / s.steps);
                const Pass *q = nearest(passes, tRef);
                if (!q)
                    break;
                at = *q;
                tRef = q->t;
                miss = std::abs(q->miss);
                if ((q->miss < 0) == (fa < 0))
                {
                    a = m;
                    fa = q->miss;
                }
                else
                    b = m;
            }
            if (!(miss <= 1e-7 * D))
                continue;
            ++best.throughGoal;
            if (at.t < best.time)
            {
                best.found = true;
                best.time = at.t;
                best.heading = 0.5 * (a + b);
            }
        }
    return best;
}
} // namespace detail

/// The fastest extremal from (x0, y0) at t0 through (gx, gy) within the setup's time and box: a sweep of the whole
/// circle; where it finds none, Setup::zoom windows of the same number of headings, each a tenth as wide as the last
/// (the first ten sweep spacings), about the heading whose pass came nearest the goal (in strong currents the
/// extremals through a far goal can lie within a fraction of the sweep's spacing).
inline Best fastest(const Setup &s, double x0, double y0, double t0, double gx, double gy)
{
    double heading = 0.0, miss = 0.0;
    Best best = detail::window(s, x0, y0, t0, gx, gy, 0.0, 2 * M_PI, heading, miss);
    double width = 10.0 * 2 * M_PI / s.headings;
    for (int level = 0; level < s.zoom && !best.found && std::isfinite(miss); ++level, width /= 10.0)
        best = detail::window(s, x0, y0, t0, gx, gy, heading - 0.5 * width, width, heading, miss);
    return best;
}
} // namespace extremal_sweep

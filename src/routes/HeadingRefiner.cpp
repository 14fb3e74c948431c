// Refinement of heading routes by direct shooting (see HeadingRefiner.h).
#include "ompl_glider/routes/HeadingRefiner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <nlopt.hpp>

#include "ompl_glider/ThreadPool.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

/// The shooting problem: variables are the free segments' headings (radians) and T / T0.
struct Shooting
{
    const GliderContext *ctx;
    HeadingRoute base; // resampled route; its frozen segments keep their bearings
    unsigned firstFree{0};
    double T0{1.0};
    Point2 goal;
    double scale{1.0}; // length scale of the constraint (the start-goal distance)
    DiveSettings dive;
    unsigned flights{0};
    ThreadPool *pool{nullptr};

    HeadingRoute routeOf(const double *x, unsigned n) const
    {
        HeadingRoute r = base;
        const double T = x[n - 1] * T0;
        for (std::size_t i = 0; i < r.segments.size(); ++i)
        {
            r.segments[i].duration = T / static_cast<double>(r.segments.size());
            if (i >= firstFree)
                r.segments[i].bearing = x[i - firstFree] * kDegPerRad;
        }
        return r;
    }
    /// The optimiser's flights take 16 RK4 steps per segment whatever T is: a fixed step would make a flight whose
    /// T grows toward the time window's end (up to (tEnd - departure) / T0 times T0) cost that many times more.
    DiveSettings diveOf(const double *x, unsigned n) const
    {
        DiveSettings d = dive;
        d.step = x[n - 1] * T0 / (16.0 * static_cast<double>(base.segments.size()));
        return d;
    }
    /// Segment ends of the flight without goal radius (pure dynamics: the constraints must be smooth).
    std::vector<TimedPoint> endsOf(const double *x, unsigned n)
    {
        ++flights;
        return flyHeadingRoute(routeOf(x, n), *ctx->field, nullptr, diveOf(x, n), false).ends;
    }

    /// The flights at x and at x + h e_j (forward differences), kept for the constraints at the same x.
    std::vector<double> cachedX;
    std::vector<TimedPoint> ends;
    std::vector<std::vector<TimedPoint>> perturbed;
    std::vector<double> steps;
    bool withGradient{false};
    void evaluate(const double *x, unsigned n, bool gradient)
    {
        if (cachedX.size() == n && std::equal(cachedX.begin(), cachedX.end(), x) && (withGradient || !gradient))
            return;
        cachedX.assign(x, x + n);
        withGradient = gradient;
        ends = endsOf(x, n);
        perturbed.assign(gradient ? n : 0, {});
        steps.assign(n, 0.0);
        if (!gradient)
            return;
        // the forward differences' flights are independent: flown in parallel
        pool->parallelFor(n, [&](std::size_t j) {
            std::vector<double> xp(x, x + n);
            steps[j] = 1e-7 * std::max(1.0, std::abs(x[j]));
            xp[j] = x[j] + steps[j];
            perturbed[j] =
                flyHeadingRoute(routeOf(xp.data(), n), *ctx->field, nullptr, diveOf(xp.data(), n), false).ends;
        });
        flights += n;
    }
    /// Region bounds shrunk by a margin: the segment ends must stay inside (the refinement's region constraint).
    double xLo{0}, xHi{0}, yLo{0}, yHi{0};
};

double objective(unsigned n, const double *x, double *grad, void *)
{
    if (grad)
    {
        std::fill(grad, grad + n, 0.0);
        grad[n - 1] = 1.0;
    }
    return x[n - 1];
}

void endConstraint(unsigned m, double *result, unsigned n, const double *x, double *grad, void *data)
{
    Shooting &s = *static_cast<Shooting *>(data);
    s.evaluate(x, n, grad != nullptr);
    const TimedPoint &e = s.ends.back();
    result[0] = (e.x - s.goal.x) / s.scale;
    if (m > 1)
        result[1] = (e.y - s.goal.y) / s.scale;
    for (unsigned j = 0; grad && j < n; ++j)
    {
        const TimedPoint &ep = s.perturbed[j].back();
        grad[j] = (ep.x - e.x) / s.scale / s.steps[j];
        grad[n + j] = (ep.y - e.y) / s.scale / s.steps[j];
    }
}

/// Every segment end inside the shrunk region: 4 constraints per end (x >= xLo, x <= xHi, y >= yLo, y <= yHi).
void regionConstraint(unsigned m, double *result, unsigned n, const double *x, double *grad, void *data)
{
    Shooting &s = *static_cast<Shooting *>(data);
    s.evaluate(x, n, grad != nullptr);
    const std::size_t points = m / 4;
    for (std::size_t k = 0; k < points; ++k)
    {
        const std::size_t idx = std::min(k + 1, s.ends.size() - 1);
        const TimedPoint &e = s.ends[idx];
        const double v[4] = {s.xLo - e.x, e.x - s.xHi, s.yLo - e.y, e.y - s.yHi};
        for (int c = 0; c < 4; ++c)
            result[4 * k + c] = v[c] / s.scale;
        for (unsigned j = 0; grad && j < n; ++j)
        {
            const std::vector<TimedPoint> &pj = s.perturbed[j];
            const TimedPoint &ep = pj[std::min(idx, pj.size() - 1)];
            const double dx = (ep.x - e.x) / s.scale / s.steps[j], dy = (ep.y - e.y) / s.scale / s.steps[j];
            grad[(4 * k + 0) * n + j] = -dx;
            grad[(4 * k + 1) * n + j] = dx;
            grad[(4 * k + 2) * n + j] = -dy;
            grad[(4 * k + 3) * n + j] = dy;
        }
    }
}

/// Newton on the last segment's bearing and duration so that the flight at @p step ends at the goal (the SLSQP
/// flights use a coarser step; this closes the remaining gap at the step the route is checked at).
HeadingRoute polish(HeadingRoute r, Point2 goal, const GliderContext &ctx, double depth, double step, unsigned &flights)
{
    DiveSettings d;
    d.speed = ctx.speed();
    d.depth = depth;
    d.step = step;
    const auto endOf = [&](const HeadingRoute &q) {
        ++flights;
        const HeadingFlight f = flyHeadingRoute(q, *ctx.field, nullptr, d, false);
        return Point2{f.ends.back().x, f.ends.back().y};
    };
    HeadingSegment &last = r.segments.back();
    for (int it = 0; it < 8; ++it)
    {
        const Point2 e = endOf(r);
        const double fx = e.x - goal.x, fy = e.y - goal.y;
        if (std::hypot(fx, fy) < 1e-12 * std::max(1.0, std::hypot(goal.x, goal.y)))
            break;
        const double hb = 1e-6, hd = 1e-7 * std::max(last.duration, 1e-9);
        HeadingRoute q = r;
        q.segments.back().bearing += hb;
        const Point2 eb = endOf(q);
        q = r;
        q.segments.back().duration += hd;
        const Point2 ed = endOf(q);
        const double a = (eb.x - e.x) / hb, b = (ed.x - e.x) / hd, c = (eb.y - e.y) / hb, dd = (ed.y - e.y) / hd;
        const double det = a * dd - b * c;
        if (!(std::abs(det) > 0.0) || !std::isfinite(det))
            break;
        last.bearing -= (dd * fx - b * fy) / det;
        last.duration = std::max(1e-9 * r.duration(), last.duration - (-c * fx + a * fy) / det);
    }
    return r;
}

bool inRegion(const Region &r, const TimedPoint &p)
{
    return p.x >= r.xMin && p.x <= r.xMax && p.y >= r.yMin && p.y <= r.yMax;
}
} // namespace

double headingCheckStep(double duration, const GliderContext &ctx)
{
    // a step no longer than the time to cross 1/150 of the region at V + max|c| either: long routes through the
    // flow's features (a gyre circled for weeks) are integrated as finely as short ones
    const Region &r = ctx.region;
    const double cross = std::max(r.xMax - r.xMin, r.yMax - r.yMin) / 150.0 / (ctx.speed() + ctx.maxCurrent());
    const double step = std::max(duration, 1e-12) / 2000.0;
    return std::isfinite(cross) && cross > 0.0 ? std::min(step, cross) : step;
}

HeadingRoute resampleHeadingRoute(const HeadingRoute &initial, unsigned n, double duration)
{
    HeadingRoute r;
    r.start = initial.start;
    r.departure = initial.departure;
    n = std::max(1u, n);
    const double d = duration / n;
    for (unsigned i = 0; i < n; ++i)
    {
        // the initial route's bearing at the middle of the new segment (its last one beyond its end)
        const double tm = (i + 0.5) * d;
        double acc = 0.0, bearing = initial.segments.empty() ? 0.0 : initial.segments.back().bearing;
        for (const HeadingSegment &s : initial.segments)
        {
            if (tm < acc + s.duration)
            {
                bearing = s.bearing;
                break;
            }
            acc += s.duration;
        }
        r.segments.push_back({bearing, d});
    }
    return r;
}

HeadingFlight verifyHeadingRoute(const HeadingRoute &route, const GliderContext &ctx, Point2 goal,
                                 const HeadingRefineSettings &settings, std::string *why)
{
    DiveSettings dive;
    dive.speed = ctx.speed();
    dive.depth = settings.depth;
    dive.step = settings.step > 0.0 ? settings.step
                : route.step > 0.0  ? route.step
                                    : headingCheckStep(route.duration(), ctx);
    // the whole route is flown (it ends at the goal); its end must lie within the radius
    HeadingFlight f = flyHeadingRoute(route, *ctx.field, ctx.environment.get(), dive, true);
    const TimedPoint &end = f.ends.back();
    const double miss = std::hypot(end.x - goal.x, end.y - goal.y);
    f.closestDistance = miss;
    f.closestTime = end.t;
    std::string w;
    if (f.grounded)
        w = f.why;
    else if (!(miss <= settings.radius))
        w = "the flight ends " + std::to_string(miss) + " from the goal (goal radius " +
            std::to_string(settings.radius) + ")";
    else if (end.t > settings.tEnd)
        w = "the arrival is after the end of the time window";
    else
        for (const TimedPoint &p : f.track)
            if (!inRegion(ctx.region, p))
            {
                w = "the track leaves the planning region at (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                    ")";
                break;
            }
    f.reached = w.empty();
    f.arrivalTime = f.reached ? end.t : std::numeric_limits<double>::quiet_NaN();
    if (!w.empty() && why)
        *why = w;
    return f;
}

RefinedHeadings refineHeadingRoute(const HeadingRoute &initial, Point2 goal, const GliderContext &ctx,
                                   const HeadingRefineSettings &settings)
{
    RefinedHeadings out;
    const double T0 = initial.duration();
    if (!(T0 > 0.0) || initial.segments.empty())
    {
        out.why = "empty initial route";
        return out;
    }
    const unsigned N = std::max(2u, settings.segments);
    Shooting s;
    s.ctx = &ctx;
    s.base = resampleHeadingRoute(initial, N, T0);
    s.T0 = T0;
    s.goal = goal;
    s.scale = std::max(std::hypot(goal.x - initial.start.x, goal.y - initial.start.y), 1e-9);
    s.dive.speed = ctx.speed();
    s.dive.depth = settings.depth;
    ThreadPool pool(settings.threads);
    s.pool = &pool;
    const Region &reg = ctx.region;
    const double margin = 1e-3 * std::max(reg.xMax - reg.xMin, reg.yMax - reg.yMin);
    s.xLo = reg.xMin + margin;
    s.xHi = reg.xMax - margin;
    s.yLo = reg.yMin + margin;
    s.yHi = reg.yMax - margin;
    HeadingRefineSettings verify = settings;

    // all segments free, then only the last 3, then the last one: the first valid result wins
    for (unsigned freeCount : {N, std::min(N, 3u), 1u})
    {
        s.firstFree = N - freeCount;
        s.cachedX.clear();
        const unsigned n = freeCount + 1;
        std::vector<double> x(n), lo(n), hi(n);
        for (unsigned i = 0; i < freeCount; ++i)
        {
            // headings measured in radians, unwrapped around the initial bearing
            x[i] = s.base.segments[s.firstFree + i].bearing / kDegPerRad;
            lo[i] = x[i] - 2.0 * kPi;
            hi[i] = x[i] + 2.0 * kPi;
        }
        x[n - 1] = 1.0;
        lo[n - 1] = 0.2;
        hi[n - 1] = std::isfinite(settings.tEnd) ? std::max(1.0, (settings.tEnd - initial.departure) / T0) : 5.0;
        nlopt::opt opt(nlopt::LD_SLSQP, n);
        opt.set_lower_bounds(lo);
        opt.set_upper_bounds(hi);
        opt.set_min_objective(objective, nullptr);
        opt.add_equality_mconstraint(endConstraint, &s, std::vector<double>(2, 1e-9));
        if (std::isfinite(s.xLo) && std::isfinite(s.xHi) && std::isfinite(s.yLo) && std::isfinite(s.yHi))
            opt.add_inequality_mconstraint(regionConstraint, &s, std::vector<double>(4 * N, 0.0));
        // the end point is closed on the goal by polish() below: the optimiser only has to find the headings
        opt.set_xtol_rel(1e-8);
        opt.set_ftol_rel(1e-9);
        opt.set_maxeval(static_cast<int>(settings.maxEvaluations));
        double f = 0.0;
        try
        {
            opt.optimize(x, f);
        }
        catch (const std::exception &)
        {
            // roundoff or a failed line search: judge the point reached below
        }
        HeadingRoute r = s.routeOf(x.data(), n);
        verify.step = settings.step > 0.0 ? settings.step : headingCheckStep(r.duration(), ctx);
        r = polish(std::move(r), goal, ctx, settings.depth, verify.step, s.flights);
        r.step = verify.step;
        std::string why;
        HeadingFlight flight = verifyHeadingRoute(r, ctx, goal, verify, &why);
        if (flight.reached)
        {
            out.ok = true;
            out.route = r;
            out.flight = std::move(flight);
            out.flights = s.flights;
            return out;
        }
        out.why = why;
    }
    out.flights = s.flights;
    return out;
}
} // namespace ompl_glider

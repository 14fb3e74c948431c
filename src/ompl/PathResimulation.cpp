#include "ompl_glider/ompl/PathResimulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

/// Empty when (x, y, t) is a valid point of the context, else why not.
std::string pointProblem(const GliderContext &ctx, double x, double y, double t)
{
    // The checks first, the message only on failure: this runs at every hold step and departure sample.
    const Region &r = ctx.region;
    const bool inRegion = x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax;
    const bool inWindow = inRegion && t >= r.tMin && t <= r.tMax;
    const bool wet = inWindow && ctx.field->inWater(x, y, ctx.travel->params().depth);
    if (wet && (!ctx.environment || ctx.environment->pointFree(x, y, t)))
        return {};
    std::ostringstream os;
    if (!inRegion)
        os << "(" << x << ", " << y << ") outside the region";
    else if (!inWindow)
        os << "time " << t << " outside the window [" << r.tMin << ", " << r.tMax << "]";
    else if (!wet)
        os << "(" << x << ", " << y << ") not in water";
    else
        os << "(" << x << ", " << y << ") at time " << t
           << " in a forbidden region: " << ctx.environment->whyBlocked(x, y, t);
    return os.str();
}

/// True when the glider can hold at (x, y) at time t (|c| < V, in water, free).
bool holdable(const GliderContext &ctx, double x, double y, double t)
{
    if (!pointProblem(ctx, x, y, t).empty())
        return false;
    const Velocity c = ctx.field->velocity(x, y, ctx.travel->params().depth, t);
    const double V = ctx.speed();
    return c.u * c.u + c.v * c.v < V * V;
}
} // namespace

namespace
{
/// Every leg as fast as possible from the arrival at its first waypoint.
PathResimulation flyDirect(const GliderContext &ctx, const std::vector<std::array<double, 2>> &wp, double t0)
{
    PathResimulation r;
    r.departureTime = t0;
    r.arrivalTime = t0;
    r.times.assign(wp.size(), kInf);
    r.times[0] = t0;
    auto fail = [&r](int leg, const std::string &why) {
        if (r.valid)
        {
            r.valid = false;
            r.firstBadLeg = leg;
            r.reason = why;
        }
    };
    std::string why = pointProblem(ctx, wp[0][0], wp[0][1], t0);
    if (!why.empty())
        fail(wp.size() > 1 ? 0 : -1, "start: " + why);
    double t = t0;
    for (std::size_t i = 0; i + 1 < wp.size(); ++i)
    {
        const auto &a = wp[i];
        const auto &b = wp[i + 1];
        const int leg = static_cast<int>(i);
        const double tt = ctx.travel->travelTime(a[0], a[1], b[0], b[1], t);
        if (!std::isfinite(tt))
        {
            r.finite = false;
            fail(leg, "leg " + std::to_string(i) + " is infeasible (travel time +inf departing at " +
                          std::to_string(t) + ")");
            t = kInf;
            break;
        }
        const double t2 = t + tt;
        r.times[i + 1] = t2;
        why = pointProblem(ctx, b[0], b[1], t2);
        if (!why.empty())
            fail(leg, "leg " + std::to_string(i) + " ends at " + why);
        else if (ctx.environment && !ctx.environment->legFree(a[0], a[1], t, b[0], b[1], t2))
            fail(leg, "leg " + std::to_string(i) + " crosses a forbidden region at the flown times");
        t = t2;
    }
    r.arrivalTime = t;
    r.travelTime = t - t0;
    return r;
}

struct HoldInterval
{
    double a, b; // reachable times [a, b] at a waypoint
};

void merge(std::vector<HoldInterval> &v)
{
    std::sort(v.begin(), v.end(), [](const HoldInterval &p, const HoldInterval &q) { return p.a < q.a; });
    std::vector<HoldInterval> out;
    for (const HoldInterval &iv : v)
    {
        if (!out.empty() && iv.a <= out.back().b)
            out.back().b = std::max(out.back().b, iv.b);
        else
            out.push_back(iv);
    }
    v.swap(out);
}

/// Extends each interval by holding at (x, y) on a grid of step while |c| < V there.
void hold(const GliderContext &ctx, double x, double y, double step, std::vector<HoldInterval> &v)
{
    for (HoldInterval &iv : v)
    {
        if (!holdable(ctx, x, y, iv.b))
            continue;
        while (iv.b + step <= ctx.region.tMax && holdable(ctx, x, y, iv.b + step))
            iv.b += step;
    }
    merge(v);
}

/// Earliest arrival over all paces between the roots and holds at waypoints.
PathResimulation flyWaiting(const GliderContext &ctx, const std::vector<std::array<double, 2>> &wp, double t0,
                            double step)
{
    PathResimulation r;
    r.waited = true;
    r.departureTime = t0;
    r.times.assign(wp.size(), kInf);
    r.times[0] = t0;
    std::vector<HoldInterval> reach{{t0, t0}};
    hold(ctx, wp[0][0], wp[0][1], step, reach);
    for (std::size_t i = 0; i + 1 < wp.size(); ++i)
    {
        const auto &a = wp[i];
        const auto &b = wp[i + 1];
        std::vector<HoldInterval> next;
        for (const HoldInterval &iv : reach)
        {
            for (double td = iv.a;; td = std::min(iv.b, td + step))
            {
                const ArrivalWindow w = ctx.travel->arrivalWindow(a[0], a[1], b[0], b[1], td);
                const double arr = td + w.earliest;
                if (std::isfinite(w.earliest) && arr <= ctx.region.tMax && pointProblem(ctx, b[0], b[1], arr).empty() &&
                    (!ctx.environment || ctx.environment->legFree(a[0], a[1], td, b[0], b[1], arr)))
                    next.push_back({arr, std::max(arr, std::min(ctx.region.tMax, td + w.latest))});
                if (td >= iv.b)
                    break;
            }
        }
        merge(next);
        if (next.empty())
        {
            r.finite = false;
            r.valid = false;
            r.firstBadLeg = static_cast<int>(i);
            r.reason = "leg " + std::to_string(i) + ": waypoint " + std::to_string(i + 1) +
                       " cannot be reached in the time window, whatever the pace or waiting";
            r.arrivalTime = r.travelTime = kInf;
            return r;
        }
        hold(ctx, b[0], b[1], step, next);
        r.times[i + 1] = next.front().a;
        reach.swap(next);
    }
    r.arrivalTime = r.times.back();
    r.travelTime = r.arrivalTime - t0;
    return r;
}
} // namespace

PathResimulation resimulatePath(const GliderContext &ctx, const std::vector<std::array<double, 2>> &wp, double t0,
                                const ResimulationOptions &opt)
{
    if (wp.empty())
    {
        PathResimulation r;
        r.departureTime = r.arrivalTime = t0;
        return r;
    }
    PathResimulation direct = flyDirect(ctx, wp, t0);
    if (direct.valid || !opt.allowWaiting || !pointProblem(ctx, wp[0][0], wp[0][1], t0).empty())
        return direct;
    const double span = ctx.region.tMax - ctx.region.tMin;
    const double step = opt.holdStep > 0.0 ? opt.holdStep : (std::isfinite(span) && span > 0 ? span / 512.0 : 1.0);
    return flyWaiting(ctx, wp, t0, step);
}

PathResimulation resimulatePath(const GliderContext &ctx, const ompl::geometric::PathGeometric &path, double t0,
                                const ResimulationOptions &options)
{
    std::vector<std::array<double, 2>> wp;
    wp.reserve(path.getStateCount());
    for (std::size_t i = 0; i < path.getStateCount(); ++i)
    {
        const auto *st = path.getState(i)->as<TimeSE2StateSpace::StateType>();
        wp.push_back({st->getX(), st->getY()});
    }
    return resimulatePath(ctx, wp, t0, options);
}
} // namespace ompl_glider

/// @file CurveLegs.cpp
/// @brief legsAlongCurve() (CurveLegs.h): a curve through the plane flown as straight legs.

#include "ompl_glider/routes/CurveLegs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "../io/NumberText.h"
#include "ompl_glider/routes/PathSmoother.h"

namespace ompl_glider
{
namespace
{
double segmentDistance(const TimedPoint &p, const TimedPoint &a, const TimedPoint &b)
{
    const double ex = b.x - a.x, ey = b.y - a.y, l2 = ex * ex + ey * ey;
    double s = l2 > 0.0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / l2 : 0.0;
    s = std::clamp(s, 0.0, 1.0);
    return std::hypot(p.x - a.x - s * ex, p.y - a.y - s * ey);
}

/// |c| < V at (x, y) over [t1, t2], sampled at 64 times at least.
bool holdable(const GliderContext &ctx, double x, double y, double t1, double t2)
{
    const double V = ctx.speed(), z = ctx.travel->params().depth;
    const int n = 64;
    for (int k = 0; k <= n; ++k)
    {
        const Velocity c = ctx.field->velocity(x, y, z, t1 + (t2 - t1) * k / n);
        if (!(std::hypot(c.u, c.v) < V))
            return false;
    }
    return true;
}

/// The farthest index j > a (at most 512 on, no hold in between) such that every point between a and j is within
/// @p tolerance of the chord from path[a] to path[j]; a + 1 at least.
std::size_t farthestChord(const std::vector<TimedPoint> &path, std::size_t a, double tolerance)
{
    const auto same = [&](std::size_t i, std::size_t j) { return path[i].x == path[j].x && path[i].y == path[j].y; };
    const std::size_t n = path.size();
    std::size_t best = a + 1;
    for (std::size_t j = a + 2; j < n && j - a <= 512 && !same(j - 1, j); ++j)
    {
        bool ok = true;
        for (std::size_t k = a + 1; k < j && ok; ++k)
            ok = segmentDistance(path[k], path[a], path[j]) <= tolerance;
        if (!ok)
            break;
        best = j;
    }
    return best;
}

/// Why the leg from path[a] (departing at @p t) to the next point cannot be flown (for legsAlongCurve()'s why).
std::string infeasibleLegReason(const GliderContext &ctx, const std::vector<TimedPoint> &path, std::size_t a, double t)
{
    const std::string env = ctx.environment ? ctx.environment->whyLegBlocked(path[a].x, path[a].y, t, path[a + 1].x,
                                                                             path[a + 1].y, t + 1e-9)
                                            : std::string();
    return "leg from (" + text::number(path[a].x) + ", " + text::number(path[a].y) + ") at time " + text::number(t) +
           " (level set " + text::number(path[a].t) + ") to the next point is infeasible" +
           (env.empty() ? "" : ": " + env);
}

} // namespace

std::vector<TimedPoint> legsAlongCurve(const GliderContext &ctx, const std::vector<TimedPoint> &path, double tolerance,
                                       std::string *why)
{
    std::vector<TimedPoint> out;
    if (path.size() < 2)
        return out;
    const auto same = [&](std::size_t i, std::size_t j) { return path[i].x == path[j].x && path[i].y == path[j].y; };
    double t = path.front().t;
    out.push_back({path.front().x, path.front().y, t});
    std::size_t a = 0;
    const std::size_t n = path.size();
    bool heldHere = false;
    while (a + 1 < n)
    {
        if (same(a, a + 1))
        {
            // The backtracked path holds here: hold until its time if the glider can.
            if (path[a + 1].t > t && holdable(ctx, path[a].x, path[a].y, t, path[a + 1].t))
            {
                t = path[a + 1].t;
                out.push_back({path[a].x, path[a].y, t});
            }
            ++a;
            continue;
        }
        const std::size_t best = farthestChord(path, a, tolerance);
        double tt = std::numeric_limits<double>::infinity();
        std::size_t j = best;
        for (; j > a; --j)
        {
            tt = legTravelTime(ctx, path[a].x, path[a].y, path[j].x, path[j].y, t);
            if (std::isfinite(tt))
                break;
        }
        if (!std::isfinite(tt))
        {
            // Blocked now: the level set waited here (a lane not yet open). Its time steps straddle the opening, so
            // hold until the first departure (on a fine time grid, up to a few of its steps past its own time) at
            // which the next leg is free, where the glider can hold.
            j = a + 1;
            // a quarter of the backtracking's mean step (a hold pair's span would be far too coarse)
            const double step = std::max((path.back().t - path.front().t) / static_cast<double>(n), 1e-9) / 4.0;
            const double from = std::max(t, path[a].t);
            bool found = false;
            for (int m = 0; m <= 64 && !found && !heldHere; ++m)
            {
                const double dep = from + m * step;
                if (dep > t && !holdable(ctx, path[a].x, path[a].y, t, dep))
                    break;
                tt = legTravelTime(ctx, path[a].x, path[a].y, path[j].x, path[j].y, dep);
                if (std::isfinite(tt))
                {
                    if (dep > t)
                        out.push_back({path[a].x, path[a].y, dep});
                    t = dep;
                    found = true;
                }
            }
            if (!found)
            {
                if (why)
                    *why = infeasibleLegReason(ctx, path, a, t);
                return {};
            }
            heldHere = true;
        }
        else
            heldHere = false;
        double arrive = t + tt;
        if (path[j].t > arrive)
        {
            // The level set reaches this point later than the straight legs at full speed: keep its schedule by
            // flying the leg slower, within the leg's arrival window (the motion validator's pace), where that keeps
            // the leg free (e.g. arriving at a lane as it opens when the current is too strong to hold).
            const ArrivalWindow w = ctx.travel->arrivalWindow(path[a].x, path[a].y, path[j].x, path[j].y, t);
            const double slow = std::min(path[j].t, t + w.latest * (1.0 - 1e-9));
            if (slow > arrive && slow <= ctx.region.tMax &&
                (!ctx.environment || ctx.environment->legFree(path[a].x, path[a].y, t, path[j].x, path[j].y, slow)))
                arrive = slow;
        }
        t = arrive;
        out.push_back({path[j].x, path[j].y, t});
        a = j;
    }
    return out;
}
} // namespace ompl_glider

// A timed path followed by held headings, piece by piece (see HeadingTracker.h).
#include "ompl_glider/routes/HeadingTracker.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <ompl/util/Console.h>

namespace ompl_glider
{
namespace
{
/// One held heading from (x, y, t) to the target (solveHeldHeading() with the planner's RK4 flights).
double flyTo(const GliderContext &ctx, const DiveSettings &dive, const TimedPoint &from, Point2 target, double &bearing,
             double &duration)
{
    const auto endOf = [&](double b, double d) {
        HeadingRoute r;
        r.start = {from.x, from.y};
        r.departure = from.t;
        r.segments.push_back({b, d});
        const HeadingFlight f = flyHeadingRoute(r, *ctx.field, nullptr, dive, false);
        return Point2{f.ends.back().x - target.x, f.ends.back().y - target.y};
    };
    const double scale = std::max(std::hypot(target.x - from.x, target.y - from.y), 1e-12);
    return solveHeldHeading(endOf, 1e-12 * std::max(scale, 1.0), bearing, duration);
}
/// The planned duration of a piece to a path point reached at @p tq (at least a tiny positive one).
double duration0(const TimedPoint &at, double tq, double total)
{
    return std::max(tq - at.t, 1e-6 * std::max(total, 1e-9));
}

/// The steering estimate of a piece: the bearing of the velocity through the water that covers it on schedule.
double bearing0(const GliderContext &ctx, const HeadingRefineSettings &settings, const TimedPoint &at, Point2 q,
                double tq)
{
    const double duration = std::max(tq - at.t, 1e-12);
    const Velocity c =
        ctx.field->velocity(0.5 * (at.x + q.x), 0.5 * (at.y + q.y), settings.depth, at.t + 0.5 * duration);
    return bearingOf((q.x - at.x) / duration - c.u, (q.y - at.y) / duration - c.v);
}
} // namespace

double solveHeldHeading(const std::function<Point2(double, double)> &miss, double tolerance, double &bearing,
                        double &duration)
{
    Point2 F = miss(bearing, duration);
    double m = std::hypot(F.x, F.y);
    for (int it = 0; it < 30 && m > tolerance; ++it)
    {
        const double hb = 1e-6, hd = 1e-7 * std::max(duration, 1e-9);
        const Point2 Fb = miss(bearing + hb, duration), Fd = miss(bearing, duration + hd);
        const double a = (Fb.x - F.x) / hb, b = (Fd.x - F.x) / hd, c = (Fb.y - F.y) / hb, d = (Fd.y - F.y) / hd;
        const double det = a * d - b * c;
        if (!std::isfinite(det) || det == 0.0)
            break;
        const double db = -(d * F.x - b * F.y) / det, dd = -(-c * F.x + a * F.y) / det;
        double lambda = 1.0;
        bool improved = false;
        for (int k = 0; k < 12; ++k, lambda *= 0.5)
        {
            const double nb = bearing + lambda * db, nd = duration + lambda * dd;
            if (!(nd > 0.0))
                continue;
            const Point2 G = miss(nb, nd);
            const double mg = std::hypot(G.x, G.y);
            if (mg < m)
            {
                bearing = nb;
                duration = nd;
                F = G;
                m = mg;
                improved = true;
                break;
            }
        }
        if (!improved)
            break;
    }
    return m;
}

RefinedHeadings trackPathWithHeadings(const std::vector<TimedPoint> &path, Point2 goal, const GliderContext &ctx,
                                      const HeadingRefineSettings &settings, double spacing,
                                      const std::vector<double> *flownBearings)
{
    RefinedHeadings out;
    if (path.size() < 2)
    {
        out.why = "the path has fewer than two points";
        return out;
    }
    const double total = path.back().t - path.front().t;
    DiveSettings dive;
    dive.speed = ctx.speed();
    dive.depth = settings.depth;
    dive.step = settings.step > 0.0 ? settings.step : headingCheckStep(total, ctx);
    HeadingRoute route;
    route.start = {path.front().x, path.front().y};
    route.departure = path.front().t;
    route.step = dive.step;
    TimedPoint at = path.front();
    std::size_t from = 0;
    const double tolerance = std::max(settings.radius, 1e-12) * 1e-3;
    unsigned shotPieces = 0, pieceFlights = 0;
    while (from + 1 < path.size())
    {
        // the next target: the first point at least spacing along the path (the last point is the goal itself)
        std::size_t to = from + 1;
        double along = std::hypot(path[to].x - path[from].x, path[to].y - path[from].y);
        while (to + 1 < path.size() && along < spacing)
        {
            along += std::hypot(path[to + 1].x - path[to].x, path[to + 1].y - path[to].y);
            ++to;
        }
        bool flown = false;
        // a piece no single heading flies is split: the target moves back toward the piece's start
        for (std::size_t target = to; target > from && !flown; target = from + (target - from) / 2)
        {
            const Point2 q = target + 1 == path.size() ? goal : Point2{path[target].x, path[target].y};
            double duration = duration0(at, path[target].t, total);
            double bearing = flownBearings && target == from + 1 && target < flownBearings->size()
                                 ? (*flownBearings)[target]
                                 : bearing0(ctx, settings, at, q, path[target].t);
            if (flyTo(ctx, dive, at, q, bearing, duration) <= tolerance)
            {
                route.segments.push_back({bearing, duration});
                at = {q.x, q.y, at.t + duration};
                from = target;
                flown = true;
            }
            if (target == from + 1)
            {
                // no path point between: several held headings, shot to the point in least time
                HeadingRoute piece;
                piece.start = {at.x, at.y};
                piece.departure = at.t;
                piece.segments.push_back(
                    {bearing0(ctx, settings, at, q, path[target].t), duration0(at, path[target].t, total)});
                HeadingRefineSettings sub = settings;
                sub.segments = 16;
                sub.radius = tolerance;
                sub.step = dive.step;
                const RefinedHeadings r = refineHeadingRoute(piece, q, ctx, sub);
                ++shotPieces;
                pieceFlights += r.flights;
                if (r.ok)
                {
                    route.segments.insert(route.segments.end(), r.route.segments.begin(), r.route.segments.end());
                    at = {q.x, q.y, r.flight.ends.back().t};
                    from = target;
                    flown = true;
                }
                break;
            }
        }
        if (!flown)
        {
            OMPL_DEBUG("tracking: %u pieces shot (%u flights)", shotPieces, pieceFlights);
            out.why = "no held heading flies from (" + std::to_string(at.x) + ", " + std::to_string(at.y) +
                      ") at t = " + std::to_string(at.t) + " to the path's next point";
            out.route = std::move(route);
            out.stoppedAt = at;
            return out;
        }
    }
    OMPL_DEBUG("tracking: %zu path points, %u pieces shot (%u flights)", path.size(), shotPieces, pieceFlights);
    std::string why;
    HeadingRefineSettings verify = settings;
    verify.step = dive.step;
    HeadingFlight flight = verifyHeadingRoute(route, ctx, goal, verify, &why);
    if (!flight.reached)
    {
        out.why = "the followed path fails its check: " + why;
        return out;
    }
    out.ok = true;
    out.route = std::move(route);
    out.flight = std::move(flight);
    return out;
}
bool reaimOnReflight(HeadingRoute &route, Point2 goal, const CurrentField &field, const Environment *forbidden,
                     const ReflightSettings &settings, double radius, HeadingReflight &flight)
{
    if (route.segments.empty() || !(radius > 0.0))
        return false;
    ReflightSettings s = settings;
    s.radius = 0.0; // every segment flown to its end: the last one must end on the goal
    TimedPoint from{route.start.x, route.start.y, route.departure};
    HeadingRoute prefix = route;
    prefix.segments.pop_back();
    if (!prefix.segments.empty())
    {
        const HeadingReflight f = reflyHeadingRoute(prefix, field, forbidden, s);
        if (!f.ok || f.grounded)
            return false;
        from = f.end;
    }
    HeadingSegment last = route.segments.back();
    const auto miss = [&](double bearing, double duration) {
        HeadingRoute one;
        one.start = {from.x, from.y};
        one.departure = from.t;
        one.segments.push_back({bearing, duration});
        const HeadingReflight f = reflyHeadingRoute(one, field, forbidden, s);
        return Point2{f.end.x - goal.x, f.end.y - goal.y};
    };
    if (!(solveHeldHeading(miss, 1e-3 * radius, last.bearing, last.duration) <= 1e-3 * radius))
        return false;
    HeadingRoute aimed = route;
    aimed.segments.back() = last;
    HeadingReflight f = reflyHeadingRoute(aimed, field, forbidden, s);
    if (!f.ok || f.grounded || !(std::hypot(f.end.x - goal.x, f.end.y - goal.y) <= radius))
        return false;
    route = std::move(aimed);
    flight = std::move(f);
    return true;
}
} // namespace ompl_glider

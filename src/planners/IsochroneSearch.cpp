// The isochrone search and the closing of its routes on the goal (see IsochroneSearch.h).
#include "ompl_glider/planners/IsochroneSearch.h"

#include <algorithm>
#include <cmath>

#include <ompl/util/Console.h>

#include "ompl_glider/routes/HeadingTracker.h"

namespace ompl_glider
{
namespace
{
/// Front points at most (about 50 bytes each): beyond, the search gives up (the level set decides then).
constexpr std::size_t kMaxPoints = 4000000;

/// A flight of one step from a front point with one heading.
struct Flight
{
    std::size_t cell;
    double x, y, t;
    long parent;
    double bearing;
    double centreDistance; ///< to the cell's centre (the kept point of a cell is the one nearest it)
};

/// The square grid of cells over the region, and which cells a front has reached.
struct CellGrid
{
    double x0, y0, h;
    std::size_t nx, ny;
    std::vector<long> reached;  ///< the step at which a front last held the cell (-1: never)
    std::vector<long> occupied; ///< the step whose new front holds the cell (-1: none)

    CellGrid(const Region &r, double cell)
        : x0(r.xMin), y0(r.yMin), h(cell), nx(static_cast<std::size_t>(std::ceil((r.xMax - r.xMin) / cell)) + 1),
          ny(static_cast<std::size_t>(std::ceil((r.yMax - r.yMin) / cell)) + 1), reached(nx * ny, -1),
          occupied(nx * ny, -1)
    {
    }
    /// A cell a new point may take at @p step: never reached, or reached long enough ago that the reachable set,
    /// which cannot hold still where the current is stronger than the vehicle, may have left it and come back.
    bool open(std::size_t c, long step) const { return reached[c] < 0 || step - reached[c] > kReopenSteps; }
    static constexpr long kReopenSteps = 8;
    std::size_t cellOf(double x, double y) const
    {
        const auto i = static_cast<std::size_t>(std::clamp((x - x0) / h, 0.0, static_cast<double>(nx - 1)));
        const auto j = static_cast<std::size_t>(std::clamp((y - y0) / h, 0.0, static_cast<double>(ny - 1)));
        return j * nx + i;
    }
    double centreDistance(std::size_t c, double x, double y) const
    {
        const double cx = x0 + (static_cast<double>(c % nx) + 0.5) * h,
                     cy = y0 + (static_cast<double>(c / nx) + 0.5) * h;
        return std::hypot(x - cx, y - cy);
    }
};

/// The earliest arrival per cell: of the flights of a step, one new front point per open cell (the one nearest the
/// cell's centre; ties broken by parent and heading, so that the result does not depend on threads). Of those, the
/// points whose eight neighbouring cells all hold new points too are inside the front, not on it, and are dropped:
/// the front is the boundary of the set reached at this step (what the isochrone method keeps).
std::vector<long> keepOnePerCell(std::vector<std::vector<Flight>> &flown, CellGrid &grid,
                                 std::vector<FrontPoint> &points, long step)
{
    std::vector<Flight> all;
    for (auto &f : flown)
        all.insert(all.end(), f.begin(), f.end());
    std::sort(all.begin(), all.end(), [](const Flight &a, const Flight &b) {
        return a.cell != b.cell                       ? a.cell < b.cell
               : a.centreDistance != b.centreDistance ? a.centreDistance < b.centreDistance
               : a.parent != b.parent                 ? a.parent < b.parent
                                                      : a.bearing < b.bearing;
    });
    std::vector<const Flight *> kept;
    for (const Flight &f : all)
        if (grid.open(f.cell, step) && grid.occupied[f.cell] != step)
        {
            grid.occupied[f.cell] = step;
            kept.push_back(&f);
        }
    std::vector<long> front;
    for (const Flight *f : kept)
    {
        const long i = static_cast<long>(f->cell % grid.nx), j = static_cast<long>(f->cell / grid.nx);
        bool inside = true;
        for (long dj = -1; dj <= 1 && inside; ++dj)
            for (long di = -1; di <= 1 && inside; ++di)
            {
                const long a = i + di, b = j + dj;
                inside = a >= 0 && b >= 0 && a < static_cast<long>(grid.nx) && b < static_cast<long>(grid.ny) &&
                         grid.occupied[static_cast<std::size_t>(b) * grid.nx + static_cast<std::size_t>(a)] == step;
            }
        grid.reached[f->cell] = step;
        if (inside)
            continue;
        front.push_back(static_cast<long>(points.size()));
        points.push_back({f->x, f->y, f->t, f->parent, f->bearing});
    }
    return front;
}

} // namespace

IsochroneSetup makeIsochroneSetup(const GliderContext &ctx, Point2 goal, double tolerance, double cell, double dt,
                                  unsigned headings)
{
    const Region &r = ctx.region;
    IsochroneSetup s;
    s.ctx = &ctx;
    s.cell = cell > 0.0 ? cell : std::max(r.xMax - r.xMin, r.yMax - r.yMin) / 150.0;
    s.dt = dt > 0.0 ? dt : 2.5 * s.cell / ctx.speed();
    s.tEnd = std::min(r.tMax, ctx.field->timeEnd());
    s.rose.resize(headings);
    for (unsigned k = 0; k < headings; ++k)
        s.rose[k] = bearingVector(360.0 * k / headings);
    s.dive.speed = ctx.speed();
    s.dive.depth = ctx.travel->params().depth;
    s.dive.step = s.dt / 4.0;
    s.dive.radius = std::max(s.cell, tolerance);
    s.dive.goal = goal;
    return s;
}

IsochroneSearch searchIsochrones(const IsochroneSetup &S, TimedPoint from, ThreadPool &pool,
                                 const ompl::base::PlannerTerminationCondition &ptc)
{
    const Region &r = S.ctx->region;
    const auto inRegion = [&](double x, double y) { return x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax; };
    IsochroneSearch out;
    CellGrid grid(r, S.cell);
    std::vector<FrontPoint> &points = out.points;
    points.push_back({from.x, from.y, from.t, -1, 0.0});
    std::vector<long> front{0};
    grid.reached[grid.cellOf(from.x, from.y)] = 0;
    long step = 0;
    const auto K = static_cast<unsigned>(S.rose.size());
    while (!front.empty() && !ptc())
    {
        // every front point flies K headings for one step (in parallel, one list per chunk)
        const std::size_t chunks = std::min<std::size_t>(front.size(), 4 * pool.size());
        std::vector<std::vector<Flight>> flown(chunks);
        std::vector<GoalHit> hits(chunks);
        pool.parallelFor(chunks, [&](std::size_t c) {
            for (std::size_t q = c; q < front.size(); q += chunks)
            {
                const FrontPoint p = points[static_cast<std::size_t>(front[q])];
                const double tNext = std::min(p.t + S.dt, S.tEnd);
                if (!(tNext > p.t))
                    continue;
                for (unsigned k = 0; k < K; ++k)
                {
                    const double bearing = 360.0 * k / K;
                    const DiveEnd e = flyHeading(p.x, p.y, p.t, S.rose[k].x, S.rose[k].y, tNext, *S.ctx->field,
                                                 S.ctx->environment.get(), S.dive);
                    if (e.reached)
                    {
                        if (e.arrivalTime < hits[c].arrival)
                            hits[c] = {e.arrivalTime, front[q], bearing};
                        continue;
                    }
                    if (e.grounded || !inRegion(e.x, e.y))
                        continue;
                    const std::size_t cl = grid.cellOf(e.x, e.y);
                    if (grid.open(cl, step + 1))
                        flown[c].push_back({cl, e.x, e.y, e.t, front[q], bearing, grid.centreDistance(cl, e.x, e.y)});
                }
            }
        });
        for (const GoalHit &g : hits)
            if (g.arrival < out.hit.arrival)
                out.hit = g;
        if (std::isfinite(out.hit.arrival))
            return out;
        front = keepOnePerCell(flown, grid, points, ++step);
        if (points.size() > kMaxPoints)
        {
            out.why = "the isochrone search gave up after " + std::to_string(points.size()) +
                      " front points without meeting the goal";
            return out;
        }
        out.expanded += front.size();
    }
    out.timedOut = ptc();
    out.why = front.empty() ? "the isochrone front died out before the goal (walled in, or every heading leaves the "
                              "region or the water)"
                            : "the front did not reach the goal before the end of the time window";
    return out;
}

std::vector<TimedPoint> searchChain(const IsochroneSearch &search, Point2 goal, std::vector<double> &bearings)
{
    const std::vector<FrontPoint> &points = search.points;
    const GoalHit &hit = search.hit;
    std::vector<TimedPoint> back{{goal.x, goal.y, hit.arrival}};
    std::vector<double> into{hit.bearing};
    for (long k = hit.parent; k >= 0; k = points[static_cast<std::size_t>(k)].parent)
    {
        const FrontPoint &p = points[static_cast<std::size_t>(k)];
        back.push_back({p.x, p.y, p.t});
        into.push_back(p.bearing);
    }
    bearings.assign(into.rbegin(), into.rend());
    return std::vector<TimedPoint>(back.rbegin(), back.rend());
}

HeadingRoute searchRoute(const IsochroneSearch &search)
{
    const std::vector<FrontPoint> &points = search.points;
    const long i = search.hit.parent;
    const double lastBearing = search.hit.bearing;
    const double lastDuration = search.hit.arrival - points[static_cast<std::size_t>(i)].t;
    const Point2 start{points[0].x, points[0].y};
    const double t0 = points[0].t;
    HeadingRoute r;
    r.start = start;
    r.departure = t0;
    std::vector<HeadingSegment> back{{lastBearing, lastDuration}};
    for (long k = i; k > 0; k = points[static_cast<std::size_t>(k)].parent)
    {
        const FrontPoint &p = points[static_cast<std::size_t>(k)];
        back.push_back({p.bearing, p.t - points[static_cast<std::size_t>(p.parent)].t});
    }
    r.segments.assign(back.rbegin(), back.rend());
    return r;
}

RefinedHeadings followWithRestarts(const std::vector<TimedPoint> &path, const std::vector<double> *bearings,
                                   Point2 goal, const GliderContext &ctx, const HeadingRefineSettings &settings,
                                   double spacing, const IsochroneSetup &setup, ThreadPool &pool,
                                   const ompl::base::PlannerTerminationCondition &ptc, int restarts)
{
    RefinedHeadings followed = trackPathWithHeadings(path, goal, ctx, settings, spacing, bearings);
    if (followed.ok || !followed.stoppedAt)
        return followed;
    HeadingRoute joined;
    joined.start = {path.front().x, path.front().y};
    joined.departure = path.front().t;
    joined.step = settings.step;
    IsochroneSetup again = setup;
    std::vector<double> into;
    for (int restart = 0; !followed.ok && followed.stoppedAt && restart < restarts && !ptc(); ++restart)
    {
        joined.segments.insert(joined.segments.end(), followed.route.segments.begin(), followed.route.segments.end());
        again.dive.step *= 0.5;
        const TimedPoint at = *followed.stoppedAt;
        const IsochroneSearch next = searchIsochrones(again, at, pool, ptc);
        if (!std::isfinite(next.hit.arrival))
        {
            followed.why += "; a new search from there: " + next.why;
            followed.stoppedAt.reset();
            break;
        }
        OMPL_DEBUG("following stopped at t = %g; a new isochrone search from there meets the goal at %g", at.t,
                   next.hit.arrival);
        followed = trackPathWithHeadings(searchChain(next, goal, into), goal, ctx, settings, 0.0, &into);
        if (followed.ok)
        {
            joined.segments.insert(joined.segments.end(), followed.route.segments.begin(),
                                   followed.route.segments.end());
            followed.route = joined;
            followed.flight = verifyHeadingRoute(joined, ctx, goal, settings, &followed.why);
            followed.ok = followed.flight.reached;
            if (!followed.ok)
                followed.why = "the route joined after a new search fails its check: " + followed.why;
        }
    }
    if (!followed.ok)
        followed.route = HeadingRoute();
    return followed;
}
} // namespace ompl_glider

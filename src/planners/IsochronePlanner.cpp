// The isochrone heading planner (see IsochronePlanner.h).
#include "ompl_glider/planners/IsochronePlanner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/geometric/PathGeometric.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/execution/Dive.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/planners/HeadingRefiner.h"
#include "ompl_glider/planners/HeadingTracker.h"
#include "ompl_glider/planners/PathSmoother.h"

namespace ompl_glider
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
/// Front points at most (about 50 bytes each): beyond, the search gives up (the level set decides then).
constexpr std::size_t kMaxPoints = 4000000;

/// A point of a front: where a chain of held headings from the start is at the end of a step.
struct FrontPoint
{
    double x, y, t;
    long parent;     ///< index of the point it was flown from (-1: the start)
    double bearing;  ///< heading flown from the parent
};

/// A flight of one step from a front point with one heading.
struct Flight
{
    std::size_t cell;
    double x, y, t;
    long parent;
    double bearing;
    double centreDistance;  ///< to the cell's centre (the kept point of a cell is the one nearest it)
};

/// The first arrival found in a step.
struct GoalHit
{
    double arrival{kInf};
    long parent{-1};
    double bearing{0.0};
};

/// The square grid of cells over the region, and which cells a front has reached.
struct CellGrid
{
    double x0, y0, h;
    std::size_t nx, ny;
    std::vector<long> reached;   ///< the step at which a front last held the cell (-1: never)
    std::vector<long> occupied;  ///< the step whose new front holds the cell (-1: none)

    CellGrid(const Region &r, double cell)
        : x0(r.xMin), y0(r.yMin), h(cell),
          nx(static_cast<std::size_t>(std::ceil((r.xMax - r.xMin) / cell)) + 1),
          ny(static_cast<std::size_t>(std::ceil((r.yMax - r.yMin) / cell)) + 1), reached(nx * ny, -1), occupied(nx * ny, -1)
    {
    }
    /// A cell a new point may take at @p step: never reached, or reached long enough ago that the reachable set,
    /// which cannot hold still where the current is stronger than the vehicle, may have left it and come back.
    bool open(std::size_t c, long step) const
    {
        return reached[c] < 0 || step - reached[c] > kReopenSteps;
    }
    static constexpr long kReopenSteps = 8;
    std::size_t cellOf(double x, double y) const
    {
        const auto i = static_cast<std::size_t>(std::clamp((x - x0) / h, 0.0, static_cast<double>(nx - 1)));
        const auto j = static_cast<std::size_t>(std::clamp((y - y0) / h, 0.0, static_cast<double>(ny - 1)));
        return j * nx + i;
    }
    double centreDistance(std::size_t c, double x, double y) const
    {
        const double cx = x0 + (static_cast<double>(c % nx) + 0.5) * h, cy = y0 + (static_cast<double>(c / nx) + 0.5) * h;
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
        return a.cell != b.cell ? a.cell < b.cell :
               a.centreDistance != b.centreDistance ? a.centreDistance < b.centreDistance :
               a.parent != b.parent ? a.parent < b.parent : a.bearing < b.bearing;
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

/// The timed points of the search from the start to the goal hit: the front points back from the hit's parent, then
/// the goal at the hit's arrival; @p bearings gets the bearing flown into each (the start's is unused).
std::vector<TimedPoint> chainTo(const std::vector<FrontPoint> &points, const GoalHit &hit, Point2 goal,
                                std::vector<double> &bearings)
{
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

/// The headings flown from the start to front point @p i, then @p last for @p lastDuration.
HeadingRoute routeTo(const std::vector<FrontPoint> &points, long i, double lastBearing, double lastDuration,
                     Point2 start, double t0)
{
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
// The search's points followed by held headings, the last piece closed on the goal (always near the goal, so this
// closes wherever the search arrived), and the whole route shot in N segments: the faster valid one into `route`.
bool closeOnGoal(const std::vector<FrontPoint> &points, const GoalHit &hit, const HeadingRoute &coarse, Point2 goal,
                 const GliderContext &ctx, const HeadingRefineSettings &rs, HeadingRoute &route, std::string &why)
{
    std::vector<double> bearings;
    const std::vector<TimedPoint> chain = chainTo(points, hit, goal, bearings);
    const RefinedHeadings followed = trackPathWithHeadings(chain, goal, ctx, rs, 0.0, &bearings);
    const RefinedHeadings shot = refineHeadingRoute(coarse, goal, ctx, rs);
    if (!followed.ok && !shot.ok)
    {
        why = followed.why + "; " + shot.why;
        return false;
    }
    const bool useShot = shot.ok && (!followed.ok || shot.flight.arrivalTime <= followed.flight.arrivalTime);
    route = useShot ? shot.route : followed.route;
    OMPL_DEBUG("Isochrone: refinement: %u flights, %u segments, search %g -> shot %g, followed %g", shot.flights,
               rs.segments, coarse.duration(), shot.ok ? shot.route.duration() : kInf,
               followed.ok ? followed.route.duration() : kInf);
    return true;
}
}  // namespace

IsochronePlanner::IsochronePlanner(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx)
    : ompl::base::Planner(si, "Isochrone"), ctx_(std::move(ctx))
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("Isochrone: the problem context is null or has no field");
    specs_.approximateSolutions = false;
    specs_.optimizingPaths = true;
    specs_.multithreaded = true;
    declareParam<double>("resolution", this, &IsochronePlanner::setResolution, &IsochronePlanner::getResolution,
                         "0:0.001:1000000");
    declareParam<unsigned>("headings", this, &IsochronePlanner::setHeadings, &IsochronePlanner::getHeadings,
                           "8:1:720");
    declareParam<double>("time_step", this, &IsochronePlanner::setTimeStep, &IsochronePlanner::getTimeStep,
                         "0:0.001:1000000");
    declareParam<unsigned>("segments", this, &IsochronePlanner::setSegments, &IsochronePlanner::getSegments,
                           "0:1:1000");
    declareParam<bool>("shooting", this, &IsochronePlanner::setRefine, &IsochronePlanner::getRefine, "0,1");
    declareParam<unsigned>("threads", this, &IsochronePlanner::setThreads, &IsochronePlanner::getThreads, "0:1:64");
}

IsochronePlanner::~IsochronePlanner() = default;

void IsochronePlanner::setResolution(double h)
{
    if (!(h >= 0.0) || !std::isfinite(h))
        throw Error("Isochrone: resolution must be >= 0 (0: automatic), got " + std::to_string(h));
    resolution_ = h;
}
void IsochronePlanner::setHeadings(unsigned k)
{
    if (k < 8 || k > 720)
        throw Error("Isochrone: headings must be in 8..720, got " + std::to_string(k));
    headings_ = k;
}
void IsochronePlanner::setTimeStep(double dt)
{
    if (!(dt >= 0.0) || !std::isfinite(dt))
        throw Error("Isochrone: time_step must be >= 0 (0: automatic), got " + std::to_string(dt));
    timeStep_ = dt;
}
void IsochronePlanner::setSegments(unsigned n)
{
    if (n > 1000)
        throw Error("Isochrone: segments must be in 0..1000 (0: automatic), got " + std::to_string(n));
    segments_ = n;
}
void IsochronePlanner::setThreads(unsigned n)
{
    if (n > 64)
        throw Error("Isochrone: threads must be in 0..64 (0: all cores), got " + std::to_string(n));
    threads_ = n;
}

void IsochronePlanner::clear()
{
    Planner::clear();
    route_ = HeadingRoute();
    reason_.clear();
    expanded_ = 0;
    searchTime_ = kInf;
}

ompl::base::PlannerStatus IsochronePlanner::solve(const ompl::base::PlannerTerminationCondition &ptc)
{
    checkValidity();
    route_ = HeadingRoute();
    reason_.clear();
    expanded_ = 0;
    searchTime_ = kInf;
    ompl::base::PlannerStatus status;
    const std::optional<StartAndGoal> sg = startAndGoal(*pdef_, getName(), status);
    if (!sg)
        return status;
    const Region &r = ctx_->region;
    const auto inRegion = [&](double x, double y) { return x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax; };
    if (!inRegion(sg->sx, sg->sy))
        return ompl::base::PlannerStatus::INVALID_START;
    if (!inRegion(sg->goal.x, sg->goal.y))
        return ompl::base::PlannerStatus::INVALID_GOAL;
    const auto *goalRegion = pdef_->getGoal()->as<ompl::base::GoalRegion>();
    const Point2 start{sg->sx, sg->sy}, goal = sg->goal;
    const double t0 = sg->t0, V = ctx_->speed();
    const double tEnd = std::min(r.tMax, ctx_->field->timeEnd());
    const double cell = resolution_ > 0.0 ? resolution_ : std::max(r.xMax - r.xMin, r.yMax - r.yMin) / 150.0;
    const double dt = timeStep_ > 0.0 ? timeStep_ : 2.5 * cell / V;
    const double tolerance = std::max(goalRegion->getThreshold(), 1e-12 * std::hypot(goal.x - start.x, goal.y - start.y));

    DiveSettings dive;
    dive.speed = V;
    dive.depth = ctx_->travel->params().depth;
    dive.step = dt / 4.0;
    dive.radius = std::max(cell, tolerance);
    dive.goal = goal;
    CellGrid grid(r, cell);
    std::vector<FrontPoint> points{{start.x, start.y, t0, -1, 0.0}};
    std::vector<long> front{0};
    grid.reached[grid.cellOf(start.x, start.y)] = 0;
    long step = 0;
    ThreadPool pool(threads_);
    const unsigned K = headings_;
    // the K headings, once (not per front point and step)
    std::vector<Point2> rose(K);
    for (unsigned k = 0; k < K; ++k)
        rose[k] = bearingVector(360.0 * k / K);
    GoalHit hit;
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
                const double tNext = std::min(p.t + dt, tEnd);
                if (!(tNext > p.t))
                    continue;
                for (unsigned k = 0; k < K; ++k)
                {
                    const double bearing = 360.0 * k / K;
                    const Point2 h = rose[k];
                    const DiveEnd e = flyHeading(p.x, p.y, p.t, h.x, h.y, tNext, *ctx_->field,
                                                 ctx_->environment.get(), dive);
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
            if (g.arrival < hit.arrival)
                hit = g;
        if (std::isfinite(hit.arrival))
            break;
        front = keepOnePerCell(flown, grid, points, ++step);
        if (points.size() > kMaxPoints)
        {
            reason_ = "the isochrone search gave up after " + std::to_string(points.size()) +
                      " front points without meeting the goal";
            return ompl::base::PlannerStatus::ABORT;
        }
        expanded_ += front.size();
    }
    if (!std::isfinite(hit.arrival))
    {
        if (ptc())
            return ompl::base::PlannerStatus::TIMEOUT;
        reason_ = front.empty() ? "the isochrone front died out before the goal (walled in, or every heading leaves the "
                                  "region or the water)" :
                                  "the front did not reach the goal before the end of the time window";
        OMPL_INFORM("%s: %s (%zu points)", getName().c_str(), reason_.c_str(), points.size());
        return ompl::base::PlannerStatus::ABORT;
    }
    const FrontPoint &last = points[static_cast<std::size_t>(hit.parent)];
    HeadingRoute coarse = routeTo(points, hit.parent, hit.bearing, hit.arrival - last.t, start, t0);
    searchTime_ = hit.arrival - t0;

    HeadingRefineSettings rs;
    rs.segments = segments_ > 0 ? segments_ : static_cast<unsigned>(std::clamp<std::size_t>(coarse.segments.size(), 16, 32));
    rs.depth = dive.depth;
    rs.radius = tolerance;
    rs.tEnd = tEnd;
    rs.threads = threads_;
    if (refine_)
    {
        std::string why;
        if (!closeOnGoal(points, hit, coarse, goal, *ctx_, rs, route_, why))
        {
            reason_ = "the route could not be closed on the goal: " + why;
            OMPL_INFORM("%s: %s", getName().c_str(), reason_.c_str());
            return ompl::base::PlannerStatus::ABORT;
        }
    }
    else
    {
        route_ = coarse;
        route_.step = dive.step;
    }
    std::string why;
    const HeadingFlight flight = verifyHeadingRoute(route_, *ctx_, goal, rs, &why);
    if (!flight.reached && refine_)
    {
        reason_ = "the refined route fails its check: " + why;
        route_ = HeadingRoute();
        return ompl::base::PlannerStatus::ABORT;
    }
    auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
    waypointsToPath(flight.ends, *path);
    const double cost = flight.ends.back().t - t0;
    ompl::base::PlannerSolution sol(path);
    sol.setPlannerName(getName());
    if (pdef_->getOptimizationObjective())
        sol.setOptimized(pdef_->getOptimizationObjective(), ompl::base::Cost(cost), true);
    if (!flight.reached)
        sol.setApproximate(flight.closestDistance);
    pdef_->addSolutionPath(sol);
    return flight.reached ? ompl::base::PlannerStatus::EXACT_SOLUTION : ompl::base::PlannerStatus::APPROXIMATE_SOLUTION;
}
}  // namespace ompl_glider

/// @file LevelSet.cpp
/// @brief LevelSetSolver::solve() as a sequence of steps (FrontPropagation); the grid and forbidden set prepared by
/// the constructor in LevelSetGrid.cpp, distances and reinitialisation in LevelSetDistance.cpp, backtracking and the
/// Reachability queries in LevelSetBacktrack.cpp.

#include "ompl_glider/reachability/LevelSet.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "LevelSetFront.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/TimeWindowedZone.h"

namespace ompl_glider
{
namespace levelset_detail
{
double discArrival(double wx, double wy, double cx, double cy, double V, double tau)
{
    const double w2 = wx * wx + wy * wy;
    if (w2 == 0.0)
        return 0.0;
    // |w - c s|^2 - V^2 s^2 = a s^2 + b s + w2 <= 0
    const double a = cx * cx + cy * cy - V * V, b = -2.0 * (wx * cx + wy * cy);
    double first = kInf;
    if (std::abs(a) < 1e-300)
        first = b < 0.0 ? -w2 / b : kInf;
    else
    {
        const double disc = b * b - 4.0 * a * w2;
        if (disc < 0.0)
            return kInf;
        const double sq = std::sqrt(disc);
        const double r1 = (-b - sq) / (2.0 * a), r2 = (-b + sq) / (2.0 * a);
        for (double r : {std::min(r1, r2), std::max(r1, r2)})
            if (r > 0.0)
            {
                first = r;
                break;
            }
    }
    return first <= tau * (1.0 + 1e-12) ? std::min(first, tau) : kInf;
}

FrontPropagation::FrontPropagation(const SolverGrid &sg, const GliderContext &ctx, const LevelSetParams &params,
                                   FrontDirection direction)
    : sg_(sg), g_(sg.grid), params_(params), field_(*ctx.field), band_(sg.band), V_(ctx.speed()),
      z_(ctx.travel->params().depth), direction_(direction)
{
    const Grid &g = g_;
    out_.x0 = g.x0;
    out_.y0 = g.y0;
    out_.h = g.h;
    out_.nx = g.nx;
    out_.ny = g.ny;
    out_.arrival.assign(g.size(), kInf);
    const double cmax = std::max(ctx.maxCurrent(), 0.0);
    dt_ = sg_.cfl * g.h / (V_ + cmax);
    dt_ = std::min(dt_, kMaxDiscCells * g.h / V_);
    out_.stats.dt = dt_;
    out_.stats.nodes = g.size();
    obstacle_ = sg_.staticD;
    ds_ = dt_;
    r_ = V_ * ds_;
}

/// The forbidden set at time t (into obstacle_): the static part raised by the zones closed at t, the ice zones at
/// their drifted position and the nodes the other environments block.
void FrontPropagation::updateForbidden(double tFront)
{
    const double t = direction_.backward ? direction_.tRef - tFront : tFront; // absolute time
    const Grid &g = g_;
    const double band = band_;
    for (std::uint32_t n : dynamicNodes_)
        obstacle_[n] = sg_.staticD[n];
    dynamicNodes_.clear();
    const auto raise = [&](std::uint32_t n, double dIn) {
        const double d = closedBoundary(dIn, g.h);
        if (d > obstacle_[n])
        {
            if (obstacle_[n] == sg_.staticD[n])
                dynamicNodes_.push_back(n);
            obstacle_[n] = d;
        }
    };
    for (const SolverGrid::Zone &zn : sg_.zones)
        if (zn.zone->active(t))
            for (std::size_t k = 0; k < zn.d.nodes.size(); ++k)
                raise(zn.d.nodes[k], zn.d.d[k]);
    for (const IceZone *iz : sg_.ice)
    {
        const Point2 s = iz->displacement(t);
        const SparseDistance d = polygonDistance(g, iz->shape(), s.x, s.y, band, params_.clearance);
        for (std::size_t k = 0; k < d.nodes.size(); ++k)
            raise(d.nodes[k], d.d[k]);
    }
    if (!sg_.others.empty())
    {
        std::vector<char> blocked(g.size(), 0);
        bool any = false;
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i)
                for (const Environment *e : sg_.others)
                    if (!e->pointFree(g.x(i), g.y(j), t))
                        blocked[g.index(i, j)] = any = 1;
        if (any)
        {
            std::vector<double> d;
            maskDistance(g, blocked, band, d, params_.clearance);
            for (std::size_t n = 0; n < g.size(); ++n)
                if (d[n] > -band)
                    raise(static_cast<std::uint32_t>(n), d[n]);
        }
    }
}

void FrontPropagation::initialise(double sx, double sy, double t0, const std::optional<Point2> &goal)
{
    const Grid &g = g_;
    const double band = band_, V = V_;
    goal_ = goal;
    out_.t0 = t0;
    const double r0 = 4.0 * g.h; // 2 cells leave a dent in the front that persists; 3-6 agree
    dt0_ = r0 / V;
    const double dt0 = dt0_;
    const Velocity c0 = current(sx, sy, t0 + 0.5 * dt0);
    const double cxs = sx + dt0 * c0.u, cys = sy + dt0 * c0.v;
    phi_.resize(g.size());
    next_.resize(g.size());
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
        {
            const std::size_t n = g.index(i, j);
            phi_[n] = std::clamp(std::hypot(g.x(i) - cxs, g.y(j) - cys) - r0, -band, band);
            if (phi_[n] <= 0.0)
                out_.arrival[n] = t0 + std::min(discArrival(g.x(i) - sx, g.y(j) - sy, c0.u, c0.v, V, dt0), dt0);
        }
    t_ = t0 + dt0;
    updateForbidden(t_);
    for (std::size_t n = 0; n < g.size(); ++n)
        if (obstacle_[n] > phi_[n])
        {
            phi_[n] = obstacle_[n];
            if (phi_[n] > 0.0)
                out_.arrival[n] = kInf;
        }

    goalPhi_ = goal ? g.cubic(phi_, goal->x, goal->y, band) : band;
    if (goal && goalPhi_ <= 0.0)
    {
        out_.goalReached = true;
        out_.goalTime = t0 + std::min(discArrival(goal->x - sx, goal->y - sy, c0.u, c0.v, V, dt0), dt0);
    }

    tx_ = (g.nx + kTile - 1) / kTile;
    ty_ = (g.ny + kTile - 1) / kTile;
    bandInner_ = band * (1.0 - 1e-9);
    tileLive_.assign(static_cast<std::size_t>(tx_) * ty_, 0);
    for (std::size_t t = 0; t < tileLive_.size(); ++t)
        refreshLive(static_cast<std::uint32_t>(t));
    // A step moves a departure point at most ds (V + |c|) <= cfl h from its node (|c| <= the field's bound; a
    // quarter more kept for a bound that is not tight), and the cubic reads two nodes further; the step's midpoint
    // current is read half as far again, bilinear.
    const int moved = static_cast<int>(std::ceil(1.25 * sg_.cfl));
    reach_ = moved + 2;
    sample_ = std::min(reach_ + (moved + 1) / 2 + 1, kMaxSampleReach); // cfl <= 8: at most 18
    guardAll_ = moved + 1 > params_.band + 1e-9;
    update_.assign(g.size(), 0);
    cu_.assign(g.size(), 0.0);
    cv_.assign(g.size(), 0.0);
    sampled_.assign(g.size(), 0);
}

/// The times at which a time-windowed zone opens or closes, sorted: steps end there, so that a lane is not entered
/// part of a step before it opens.
std::vector<double> FrontPropagation::eventTimes() const
{
    std::vector<double> events;
    for (const SolverGrid::Zone &zn : direction_.backward ? std::vector<SolverGrid::Zone>{} : sg_.zones)
        for (const Interval &w : zn.zone->windows())
        {
            events.push_back(w.lo);
            events.push_back(w.hi);
        }
    std::sort(events.begin(), events.end());
    return events;
}

/// The next step's length: dt, shortened to end at the next of @p events.
double FrontPropagation::stepLength(const std::vector<double> &events) const
{
    const double t = t_;
    double ds = dt_;
    const auto ev = std::upper_bound(events.begin(), events.end(), t * (1 + 1e-12) + 1e-12);
    if (ev != events.end() && *ev < t + dt_)
        ds = *ev - t;
    return ds;
}

/// Every reinitEvery steps: phi becomes the signed distance to its zero level on the active tiles, the forbidden
/// set kept out again (the distance may cut its corners).
void FrontPropagation::reinitialiseIfDue(std::size_t step, ThreadPool &pool)
{
    if (!(sg_.reinitEvery > 0 && (step + 1) % sg_.reinitEvery == 0))
        return;
    const Grid &g = g_;
    reinitialise(g, phi_, activeTiles_, tx_, band_, reinitDist_, &pool);
    pool.parallelFor(activeTiles_.size(), [&](std::size_t k) {
        forTileNodes(activeTiles_[k], [&](int i, int j) {
            phi_[g.index(i, j)] = std::max(phi_[g.index(i, j)], obstacle_[g.index(i, j)]);
        });
        refreshLive(activeTiles_[k]);
    });
}

/// The goal's first arrival: when phi interpolated at the goal becomes <= 0 in the step ending at t1 (linear in
/// phi within the step).
void FrontPropagation::checkGoal(double t1)
{
    if (!goal_ || out_.goalReached)
        return;
    const double gp = g_.cubic(phi_, goal_->x, goal_->y, band_);
    if (gp <= 0.0)
    {
        const double at = goalPhi_ > 0.0 ? t_ + ds_ * goalPhi_ / (goalPhi_ - gp) : t1;
        if (at <= tEnd_) // the step past the end (propagate()) records no goal after it
        {
            out_.goalReached = true;
            out_.goalTime = at;
        }
    }
    goalPhi_ = gp;
}

void FrontPropagation::propagate(double tEnd, bool stopAtGoal, const std::function<bool()> &stop)
{
    ThreadPool pool(params_.threads);
    out_.stats.threads = pool.size();
    const std::vector<double> events = eventTimes();
    // Without a stop at the goal the front is followed one step past tEnd, so that the nodes on both sides of the
    // set reached by tEnd have their arrival (an isochrone at tEnd lies between them, not at the last one reached).
    tEnd_ = tEnd;
    const double tLast = stopAtGoal && goal_ ? tEnd : tEnd + dt_;
    const std::size_t maxSteps = static_cast<std::size_t>(std::ceil((tLast - t_) / dt_)) + 1 + 2 * events.size();
    for (std::size_t k = 0; k < maxSteps && t_ < tLast; ++k)
    {
        if (stop && stop())
            break;
        if (params_.maxNodeUpdates > 0 && updates_ >= params_.maxNodeUpdates)
        {
            out_.stats.budgetSpent = true;
            break;
        }
        ds_ = stepLength(events);
        r_ = V_ * ds_;
        const double t1 = t_ + ds_, tm = t_ + 0.5 * ds_;
        step(pool, t1, tm);
        reinitialiseIfDue(k, pool);
        ++out_.stats.steps;
        checkGoal(t1);
        t_ = t1;
        if (goal_ && out_.goalReached && stopAtGoal)
            break;
    }
    out_.stats.nodeUpdates = updates_;
}
} // namespace levelset_detail

std::vector<char> LevelSetSolver::corridor(double sx, double sy, double t0, double tEnd, Point2 goal,
                                           const std::function<bool()> &stop, std::uint64_t &work, double &tRef) const
{
    using levelset_detail::FrontPropagation;
    std::vector<char> keep;
    if (!params_.corridor || !impl_->zones.empty() || !impl_->ice.empty() || !impl_->others.empty())
        return keep;
    LevelSetParams cp = params_;
    cp.cellSize = levelset_detail::kCorridorCoarsening * params_.cellSize;
    cp.corridor = false;
    std::unique_ptr<LevelSetSolver> coarse;
    try
    {
        coarse = std::make_unique<LevelSetSolver>(ctx_, cp);
    }
    catch (const Error &)
    {
        return keep; // too few coarse cells across the region
    }
    // forward to the goal, then on to the end of the margin
    FrontPropagation ahead(*coarse->impl_, *ctx_, cp);
    ahead.initialise(sx, sy, t0, goal);
    ahead.propagate(tEnd, true, stop);
    const double margin =
        std::getenv("MARGIN") ? std::atof(std::getenv("MARGIN")) : levelset_detail::kCorridorMargin; // TEMP
    if (!ahead.result().goalReached || ahead.result().stats.budgetSpent)
    {
        work += ahead.result().stats.nodeUpdates;
        return keep;
    }
    tRef = t0 + (ahead.result().goalTime - t0) * (1.0 + margin);
    ahead.propagate(std::min(tRef, tEnd), false, stop);
    // backward from the goal at tRef: its arrival is how long before tRef a point must be left
    FrontPropagation behind(*coarse->impl_, *ctx_, cp, {true, tRef});
    behind.countWork(ahead.result().stats.nodeUpdates);
    behind.initialise(goal.x, goal.y, 0.0, std::nullopt);
    behind.propagate(tRef - t0, false, stop);
    work += behind.result().stats.nodeUpdates;
    // a point can be on a route that arrives by tRef when it is reached before it must be left
    const levelset_detail::Grid &g = impl_->grid;
    std::vector<char> in(g.size(), 0);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
        {
            const double a = ahead.result().arrivalAt(g.x(i), g.y(j)), b = behind.result().arrivalAt(g.x(i), g.y(j));
            in[g.index(i, j)] = a + b <= tRef;
        }
    // grown by a few cells, so that the corridor's edge, which the fine front reads as unreachable, stays off the
    // routes inside
    const int grow = levelset_detail::kCorridorGrowth;
    std::vector<char> rows(g.size(), 0);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0, last = -1000000; i < g.nx; ++i)
        {
            // last flagged column at or before i, then the next at or after i
            if (in[g.index(i, j)])
                last = i;
            rows[g.index(i, j)] = i - last <= grow;
        }
    for (int j = 0; j < g.ny; ++j)
        for (int i = g.nx - 1, next = 1000000; i >= 0; --i)
        {
            if (in[g.index(i, j)])
                next = i;
            rows[g.index(i, j)] = rows[g.index(i, j)] || next - i <= grow;
        }
    keep.assign(g.size(), 0);
    for (int i = 0; i < g.nx; ++i)
    {
        for (int j = 0, last = -1000000; j < g.ny; ++j)
        {
            if (rows[g.index(i, j)])
                last = j;
            keep[g.index(i, j)] = j - last <= grow;
        }
        for (int j = g.ny - 1, next = 1000000; j >= 0; --j)
        {
            if (rows[g.index(i, j)])
                next = j;
            keep[g.index(i, j)] = keep[g.index(i, j)] || next - j <= grow;
        }
    }
    return keep;
}

Reachability LevelSetSolver::solve(double sx, double sy, double t0, double tEnd, const std::optional<Point2> &goal,
                                   bool stopAtGoal, const std::function<bool()> &stop) const
{
    const auto wall0 = std::chrono::steady_clock::now();
    const CurrentField &field = *ctx_->field;
    const std::uint64_t cmc0 = field.callCount();
    if (!std::isfinite(sx) || !std::isfinite(sy) || !std::isfinite(t0) || !(tEnd >= t0))
        throw Error("LevelSet: start, departure time or end time not finite, or end before departure");

    auto front = std::make_unique<levelset_detail::FrontPropagation>(*impl_, *ctx_, params_);
    front->initialise(sx, sy, t0, goal);
    // a goal walled off from the start: proven before any step (a long window would step for minutes)
    const int reach = static_cast<int>(std::ceil(impl_->cfl)) + 3; // a step's reach and its cubic stencil
    const bool walledOff = goal && stopAtGoal && !front->result().goalReached && impl_->staticForbidden &&
                           !levelset_detail::waterConnects(*impl_, {sx, sy}, *goal, reach);
    if (!walledOff)
    {
        std::uint64_t work = 0;
        double tRef = kInf;
        std::vector<char> keep;
        if (goal && stopAtGoal && !front->result().goalReached)
            keep = corridor(sx, sy, t0, tEnd, *goal, stop, work, tRef);
        const bool restricted = !keep.empty();
        front->restrictTo(std::move(keep));
        front->countWork(work);
        front->propagate(tEnd, stopAtGoal, stop);
        // The corridor cut the route (the coarse fronts' error beyond the margin): the whole front again, its work
        // counted on top. The fine front is never slower than the coarse one within the corridor's margin.
        const Reachability &r = front->result();
        if (restricted && !(r.goalReached && r.goalTime <= tRef) && !r.stats.budgetSpent && !(stop && stop()))
        {
            const std::uint64_t spent = r.stats.nodeUpdates;
            front = std::make_unique<levelset_detail::FrontPropagation>(*impl_, *ctx_, params_);
            front->initialise(sx, sy, t0, goal);
            front->countWork(spent);
            front->propagate(tEnd, stopAtGoal, stop);
        }
    }
    Reachability out = std::move(front->result());
    out.goalWalledOff = walledOff;

    // Backtracking from the goal through the arrival field.
    if (goal && out.goalReached)
    {
        levelset_detail::BacktrackSetup bs;
        bs.field = &field;
        bs.environment = ctx_->environment.get();
        bs.speed = ctx_->speed();
        bs.depth = ctx_->travel->params().depth;
        bs.dt = front->dt();
        bs.dt0 = front->dt0();
        out.path = levelset_detail::backtrackPath(out, impl_->grid, Point2{sx, sy}, *goal, bs);
    }
    out.stats.currentCalls = field.callCount() - cmc0;
    out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return out;
}
} // namespace ompl_glider

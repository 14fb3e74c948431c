/// @file LevelSet.cpp
/// @brief LevelSetSolver::solve() as a sequence of steps (FrontPropagation); the grid and forbidden set prepared by
/// the constructor in LevelSetGrid.cpp, distances and reinitialisation in LevelSetDistance.cpp, backtracking and the
/// Reachability queries in LevelSetBacktrack.cpp.

#include "ompl_glider/reachability/LevelSet.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "LevelSetInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/TimeWindowedZone.h"

namespace ompl_glider
{
namespace
{
using levelset_detail::Grid;
using levelset_detail::kTile;
using levelset_detail::maskDistance;
using levelset_detail::polygonDistance;
using levelset_detail::reinitialise;
using levelset_detail::SolverGrid;
using levelset_detail::SparseDistance;

/// First time in (0, tau] at which w (the offset from the start) is in the disc of centre c tau' and radius V tau'
/// (a uniform current over the first instant); +inf when never.
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

/// One solve of the level-set equation (see LevelSetSolver): the front phi on the grid, the narrow band's tiles, the
/// forbidden set at the front's time and the result being filled. initialise() sets the first instant's disc;
/// propagate() then takes steps t -> t + ds, each: advect() the active tiles, applyForbidden() (and record the
/// first arrivals), reinitialiseIfDue(), checkGoal().
class FrontPropagation
{
public:
    FrontPropagation(const SolverGrid &sg, const GliderContext &ctx, const LevelSetParams &params);

    /// The initial front: the exact reachable disc after dt0 ([LollaLevelSet]: start from the first instant's
    /// disc), the forbidden set kept out of it, and the goal's arrival when the disc holds it.
    void initialise(double sx, double sy, double t0, const std::optional<Point2> &goal);
    /// Steps until @p tEnd, until the goal is reached when @p stopAtGoal, or until @p stop (if any) answers true.
    void propagate(double tEnd, bool stopAtGoal, const std::function<bool()> &stop);

    /// The result so far (arrival field, goal, work done); moved out by the caller at the end.
    Reachability &result() { return out_; }
    double dt() const { return dt_; }
    double dt0() const { return dt0_; }

private:
    void updateForbidden(double t);
    void findActive();
    double nodeValue(const std::vector<double> &f, double x, double y, double t1, double tm) const;
    std::vector<double> eventTimes() const;
    double stepLength(const std::vector<double> &events) const;
    void advect(ThreadPool &pool, double t1, double tm);
    void applyForbidden(double t1);
    void reinitialiseIfDue(std::size_t step);
    void checkGoal(double t1);

    /// Calls fn(i, j) for every node (i, j) of @p tile.
    template <typename Fn> void forTileNodes(std::uint32_t tile, Fn &&fn) const
    {
        const int a = static_cast<int>(tile % tx_), b = static_cast<int>(tile / tx_);
        for (int j = b * kTile; j < std::min(g_.ny, (b + 1) * kTile); ++j)
            for (int i = a * kTile; i < std::min(g_.nx, (a + 1) * kTile); ++i)
                fn(i, j);
    }

    const SolverGrid &sg_;
    const Grid &g_;
    const LevelSetParams &params_;
    const CurrentField &field_;
    const double band_, V_, z_;
    std::optional<Point2> goal_;
    Reachability out_;
    double dt_{0.0};  ///< the time step
    double dt0_{0.0}; ///< the initial disc's time
    double t_{0.0};   ///< the front's time

    // The forbidden set at time t_: static part, closed zones, drifted ice, other environments' masks.
    std::vector<double> obstacle_;
    std::vector<std::uint32_t> dynamicNodes_; ///< nodes whose obstacle value differs from the static one

    std::vector<double> phi_, next_; ///< the front now and after the step
    double goalPhi_{0.0};            ///< phi at the goal (interpolated) after the last step

    // Tiles of the narrow band.
    int tx_{0}, ty_{0};
    std::vector<char> tileLive_;
    std::vector<std::uint32_t> activeTiles_;
    double bandInner_{0.0};

    double ds_{0.0}; ///< this step's length (shortened to end at a zone's opening or closing)
    double r_{0.0};  ///< the departure disc's radius V ds
    std::uint64_t updates_{0};
    std::vector<double> reinitDist_;
};

FrontPropagation::FrontPropagation(const SolverGrid &sg, const GliderContext &ctx, const LevelSetParams &params)
    : sg_(sg), g_(sg.grid), params_(params), field_(*ctx.field), band_(sg.band), V_(ctx.speed()),
      z_(ctx.travel->params().depth)
{
    const Grid &g = g_;
    out_.x0 = g.x0;
    out_.y0 = g.y0;
    out_.h = g.h;
    out_.nx = g.nx;
    out_.ny = g.ny;
    out_.arrival.assign(g.size(), kInf);
    const double cmax = std::max(ctx.maxCurrent(), 0.0);
    dt_ = params_.cfl * g.h / (V_ + cmax);
    out_.stats.dt = dt_;
    out_.stats.nodes = g.size();
    obstacle_ = sg_.staticD;
    ds_ = dt_;
    r_ = V_ * ds_;
}

/// The forbidden set at time t (into obstacle_): the static part raised by the zones closed at t, the ice zones at
/// their drifted position and the nodes the other environments block.
void FrontPropagation::updateForbidden(double t)
{
    const Grid &g = g_;
    const double band = band_;
    for (std::uint32_t n : dynamicNodes_)
        obstacle_[n] = sg_.staticD[n];
    dynamicNodes_.clear();
    const auto raise = [&](std::uint32_t n, double d) {
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
    const Velocity c0 = field_.velocity(sx, sy, z_, t0 + 0.5 * dt0);
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
    tileLive_.assign(static_cast<std::size_t>(tx_) * ty_, 0);
    bandInner_ = band * (1.0 - 1e-9);
}

/// The active tiles (into activeTiles_): those holding an unclipped value of phi, and their neighbours (every tile
/// without the narrow band).
void FrontPropagation::findActive()
{
    const Grid &g = g_;
    const int tx = tx_, ty = ty_;
    std::fill(tileLive_.begin(), tileLive_.end(), 0);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
            if (std::abs(phi_[g.index(i, j)]) < bandInner_)
                tileLive_[static_cast<std::size_t>(j / kTile) * tx + i / kTile] = 1;
    activeTiles_.clear();
    for (int b = 0; b < ty; ++b)
        for (int a = 0; a < tx; ++a)
        {
            bool on = false;
            for (int bb = std::max(0, b - 1); bb <= std::min(ty - 1, b + 1) && !on; ++bb)
                for (int aa = std::max(0, a - 1); aa <= std::min(tx - 1, a + 1) && !on; ++aa)
                    on = tileLive_[static_cast<std::size_t>(bb) * tx + aa];
            if (on || !params_.narrowBand)
                activeTiles_.push_back(static_cast<std::uint32_t>(b * tx + a));
        }
}

/// One node's new value: the minimum of phi (@p f) over the departure disc of the node (x, y) for the step ending
/// at t1 (midpoint time tm) ([LollaLevelSet]; see the class comment of LevelSetSolver).
double FrontPropagation::nodeValue(const std::vector<double> &f, double x, double y, double t1, double tm) const
{
    const Grid &g = g_;
    const double band = band_, V = V_, ds = ds_, r = r_;
    const double dth = 0.25;
    const Velocity c1 = field_.velocity(x, y, z_, t1);
    // Heading guess: the normal of the front at the departure point without the vehicle's own motion; where
    // phi is flat there (the band's clipped edge) the node's own neighbours, else a scan of 8 headings.
    double gx, gy;
    g.gradient(f, x - ds * c1.u, y - ds * c1.v, gx, gy);
    double gn = std::hypot(gx, gy);
    double nx = 1.0, ny = 0.0;
    const bool known = gn >= 0.2; // phi stays close to a distance (|grad phi| ~ 1) near the front
    if (known)
    {
        nx = gx / gn;
        ny = gy / gn;
    }
    const Velocity cm = field_.velocity(x - 0.5 * ds * (c1.u + V * nx), y - 0.5 * ds * (c1.v + V * ny), z_, tm);
    const double qx = x - ds * cm.u, qy = y - ds * cm.v;
    const auto at = [&](double a) { return g.cubic(f, qx - r * std::cos(a), qy - r * std::sin(a), band); };
    // The disc's centre (u = 0: drifting, or holding where |c| < V) covers minima inside the disc (the start).
    const double centre = g.cubic(f, qx, qy, band);
    double a0 = std::atan2(ny, nx);
    if (params_.headingScan > 0)
    {
        double v = centre;
        for (int k = 0; k < params_.headingScan; ++k)
            v = std::min(v, at(2.0 * M_PI * k / params_.headingScan));
        return v;
    }
    if (!known)
    {
        double v = band;
        for (int k = 0; k < 8; ++k)
        {
            const double fk = at(k * M_PI / 4);
            if (fk < v)
            {
                v = fk;
                a0 = k * M_PI / 4;
            }
        }
        if (v >= band)
            return std::min(v, centre);
    }
    else
    {
        // The normal at the departure point itself.
        g.gradient(f, qx - r * nx, qy - r * ny, gx, gy);
        if (std::hypot(gx, gy) >= 0.2)
            a0 = std::atan2(gy, gx);
    }
    // Three headings and the parabola through them.
    const double f0 = at(a0), fm = at(a0 - dth), fp = at(a0 + dth);
    double v = std::min(std::min(f0, centre), std::min(fm, fp));
    const double curv = fm - 2.0 * f0 + fp;
    if (curv > 0.0)
    {
        const double off = 0.5 * dth * (fm - fp) / curv;
        if (std::abs(off) < dth)
            v = std::min(v, at(a0 + off));
    }
    return v;
}

/// The times at which a time-windowed zone opens or closes, sorted: steps end there, so that a lane is not entered
/// part of a step before it opens.
std::vector<double> FrontPropagation::eventTimes() const
{
    std::vector<double> events;
    for (const SolverGrid::Zone &zn : sg_.zones)
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

/// The step's advection: next_ = phi_ with every node of the active tiles replaced by its value at t1 (the tiles
/// shared by the pool's threads); the other tiles keep their (clipped) values.
void FrontPropagation::advect(ThreadPool &pool, double t1, double tm)
{
    const Grid &g = g_;
    const double band = band_;
    findActive();
    next_ = phi_;
    pool.parallelFor(activeTiles_.size(), [&](std::size_t k) {
        forTileNodes(activeTiles_[k], [&](int i, int j) {
            const double x = g.x(i), y = g.y(j);
            next_[g.index(i, j)] = std::clamp(nodeValue(phi_, x, y, t1, tm), -band, band);
        });
    });
    updates_ += static_cast<std::uint64_t>(activeTiles_.size()) * kTile * kTile;
}

/// Keeps the forbidden set at t1 out of the new front (phi = max(phi, d)) and records the first arrival of every
/// node the front reached in the step (linear in phi within the step); then the new front becomes phi_.
void FrontPropagation::applyForbidden(double t1)
{
    const Grid &g = g_;
    const double t = t_, ds = ds_;
    updateForbidden(t1);
    for (std::uint32_t tile : activeTiles_)
        forTileNodes(tile, [&](int i, int j) {
            const std::size_t n = g.index(i, j);
            double &v = next_[n];
            v = std::max(v, obstacle_[n]);
            if (v <= 0.0 && out_.arrival[n] == kInf)
            {
                const double p0 = phi_[n];
                out_.arrival[n] = p0 > 0.0 ? t + ds * p0 / (p0 - v) : t1;
            }
        });
    for (std::uint32_t n : dynamicNodes_) // a zone that closed outside the active tiles
        next_[n] = std::max(next_[n], obstacle_[n]);
    phi_.swap(next_);
}

/// Every reinitEvery steps: phi becomes the signed distance to its zero level on the active tiles, the forbidden
/// set kept out again (the distance may cut its corners).
void FrontPropagation::reinitialiseIfDue(std::size_t step)
{
    if (!(params_.reinitEvery > 0 && (step + 1) % params_.reinitEvery == 0))
        return;
    const Grid &g = g_;
    reinitialise(g, phi_, activeTiles_, tx_, band_, reinitDist_);
    for (std::uint32_t tile : activeTiles_)
        forTileNodes(
            tile, [&](int i, int j) { phi_[g.index(i, j)] = std::max(phi_[g.index(i, j)], obstacle_[g.index(i, j)]); });
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
        out_.goalReached = true;
        out_.goalTime = goalPhi_ > 0.0 ? t_ + ds_ * goalPhi_ / (goalPhi_ - gp) : t1;
    }
    goalPhi_ = gp;
}

void FrontPropagation::propagate(double tEnd, bool stopAtGoal, const std::function<bool()> &stop)
{
    ThreadPool pool(params_.threads);
    out_.stats.threads = pool.size();
    const std::vector<double> events = eventTimes();
    const std::size_t maxSteps = static_cast<std::size_t>(std::ceil((tEnd - t_) / dt_)) + 1 + 2 * events.size();
    for (std::size_t step = 0; step < maxSteps && t_ < tEnd; ++step)
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
        advect(pool, t1, tm);
        applyForbidden(t1);
        reinitialiseIfDue(step);
        ++out_.stats.steps;
        checkGoal(t1);
        t_ = t1;
        if (goal_ && out_.goalReached && stopAtGoal)
            break;
    }
    out_.stats.nodeUpdates = updates_;
}
} // namespace

Reachability LevelSetSolver::solve(double sx, double sy, double t0, double tEnd, const std::optional<Point2> &goal,
                                   bool stopAtGoal, const std::function<bool()> &stop) const
{
    const auto wall0 = std::chrono::steady_clock::now();
    const CurrentField &field = *ctx_->field;
    const std::uint64_t cmc0 = field.callCount();
    if (!std::isfinite(sx) || !std::isfinite(sy) || !std::isfinite(t0) || !(tEnd >= t0))
        throw Error("LevelSet: start, departure time or end time not finite, or end before departure");

    FrontPropagation front(*impl_, *ctx_, params_);
    front.initialise(sx, sy, t0, goal);
    // a goal walled off from the start: proven before any step (a long window would step for minutes)
    const int reach = static_cast<int>(std::ceil(params_.cfl)) + 3; // a step's reach and its cubic stencil
    const bool walledOff = goal && stopAtGoal && !front.result().goalReached && !impl_->staticD.empty() &&
                           !levelset_detail::waterConnects(*impl_, {sx, sy}, *goal, reach);
    if (!walledOff)
        front.propagate(tEnd, stopAtGoal, stop);
    Reachability out = std::move(front.result());
    out.goalWalledOff = walledOff;

    // Backtracking from the goal through the arrival field.
    if (goal && out.goalReached)
    {
        levelset_detail::BacktrackSetup bs;
        bs.field = &field;
        bs.environment = ctx_->environment.get();
        bs.speed = ctx_->speed();
        bs.depth = ctx_->travel->params().depth;
        bs.dt = front.dt();
        bs.dt0 = front.dt0();
        out.path = levelset_detail::backtrackPath(out, impl_->grid, Point2{sx, sy}, *goal, bs);
    }
    out.stats.currentCalls = field.callCount() - cmc0;
    out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return out;
}
} // namespace ompl_glider

/// @file TveSearchCore.cpp
/// @brief One search of TveSearch ([EichhornRAS] Table 2 with the switches of TveOptions): TveSearch::runCore(), and
/// the set-up and result steps of TveSearch::Core (TveSearchCore.h): start and goal checked, bounds and heuristic,
/// the path or the reason returned. The queue loop and the edges in TveSearchExpansion.cpp.

#include "TveSearchCore.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "ompl_glider/Exception.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
TveSearch::Core::Core(TveSearch &search, double startX, double startY, double departure, double goalX, double goalY,
                      const TveOptions &opts, const std::function<bool()> &stop)
    : SearchSetting(*search.ctx_, startX, startY, departure, goalX, goalY), ts(search), lattice(search.lattice_),
      options(opts), terminate(stop), cfc0(travel.costFunctionCalls()), cmc0(field.callCount())
{
}

TveResult TveSearch::runCore(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                             const std::function<bool()> &terminate)
{
    return Core(*this, sx, sy, t0, gx, gy, options, terminate).run();
}

TveResult TveSearch::Core::run()
{
    // Clear the previous run's labels (only the vertices it touched).
    ts.labels_.reset(lattice, Label{}); // labels only of the pages reached: memory grows with the search
    ts.reached_.clear();

    // Start and goal.
    s = lattice.setStart(sx, sy);
    g = lattice.setGoal(gx, gy);
    if (!validEndpoints())
        return finish();
    wet.reset(lattice, 0);

    // Arrival deadline of this search (TveOptions::deadline): arrivals after it are dropped.
    tEnd = std::isnan(options.deadline) ? ctx.region.tMax : std::min(ctx.region.tMax, options.deadline);
    setUpBounds();

    // A* heuristic ([EichhornRAS] Eq. 1), or max(Eq. 1, LatticeHeuristic).
    vmax = ctx.speed() + (options.heuristic ? ctx.maxCurrent() : 0.0);
    if (options.heuristic && !(vmax > 0.0 && std::isfinite(vmax)))
        throw Error("TveSearch: the A* heuristic needs a finite bound of the current speed over the region");

    ts.labels_.ref(s) = {t0, Lattice::kNone};
    ts.reached_.push_back(s);
    Q.push({t0 + h(s), t0, s});
    pruning = options.zermelo;

    // Holding (TveOptions::waiting): the environment's release times and the goal window.
    releases = env && options.waiting ? env->releaseTimes() : std::vector<double>{};
    holdStep = ctx.holdTimeStep();
    goalWindow = !ts.ignoreGoalWindow_ && (std::isfinite(ctx.arriveNotBefore) || std::isfinite(ctx.arriveNotAfter));
    ts.goalHoldUntil_ = -kInf;

    // Certification (TveOptions::certifyTolerance): pruned edges are deferred, not dropped (see search()).
    certify = pruning && options.certifyTolerance >= 0.0;
    vAll = ctx.speed() + ctx.maxCurrent();
    if (certify && !(vAll > 0.0 && std::isfinite(vAll)))
        throw Error("TveSearch: certification needs a finite bound of the current speed over the region");
    checkEvery = std::max(1u, options.checkEvery);

    if (terminated())
    {
        res.outcome = TveOutcome::Terminated;
        return finish();
    }
    return result(search());
}

/// The result with the counters of this search; releases the bounds' land test (it refers to this search's cache).
TveResult TveSearch::Core::finish()
{
    res.costFunctionCalls = travel.costFunctionCalls() - cfc0;
    res.currentModelCalls = field.callCount() - cmc0;
    res.heuristicSettled = bounds ? bounds->settled() : 0;
    if (ts.bounds_)
        ts.bounds_->releaseLandTest(); // it refers to this run's land cache
    return res;
}

/// Sets the outcome and its reason; false.
bool TveSearch::Core::invalid(TveOutcome outcome, std::string message)
{
    res.outcome = outcome;
    res.message = std::move(message);
    return false;
}

/// Whether the end point @p what ("start " or "goal ") at (x, y), vertex v, lies in the region and in water; else
/// sets the outcome @p bad with the reason.
bool TveSearch::Core::placed(const std::string &what, Lattice::VertexId v, double x, double y, TveOutcome bad)
{
    if (v == Lattice::kNone)
        return invalid(bad, what + formatPoint(x, y) + " lies outside the planning region");
    if (!field.inWater(x, y, z))
        return invalid(bad, what + formatPoint(x, y) + " is not in water (land or no current data)");
    return true;
}

/// Whether start, t0 and goal are valid; else sets InvalidStart or InvalidGoal with the reason.
bool TveSearch::Core::validEndpoints()
{
    if (!placed("start ", s, sx, sy, TveOutcome::InvalidStart))
        return false;
    if (!std::isfinite(t0) || !(t0 >= ctx.region.tMin && t0 <= ctx.region.tMax))
    {
        std::ostringstream os;
        os << "start time t0 = " << t0 << (std::isfinite(t0) ? " lies outside" : " is not finite; it must lie in")
           << " the planning window [" << ctx.region.tMin << ", " << ctx.region.tMax << "]";
        return invalid(TveOutcome::InvalidStart, os.str());
    }
    if (env && !env->pointFree(sx, sy, t0))
        return invalid(TveOutcome::InvalidStart,
                       "start " + formatPoint(sx, sy) + " is blocked at t0: " + env->whyBlocked(sx, sy, t0));
    if (!placed("goal ", g, gx, gy, TveOutcome::InvalidGoal))
        return false;
    if (env)
    {
        // A goal blocked at t0 and at the end of the window (t0 when the window is open-ended) is invalid.
        const double tLate = std::isfinite(ctx.region.tMax) ? ctx.region.tMax : t0;
        if (!env->pointFree(gx, gy, t0) && !env->pointFree(gx, gy, tLate))
            return invalid(TveOutcome::InvalidGoal,
                           "goal " + formatPoint(gx, gy) + " is blocked: " + env->whyBlocked(gx, gy, t0));
    }
    return true;
}

/// Lower bounds of edges and of the remaining time (TveOptions::tightBounds, LatticeHeuristic); sets bounds when they
/// are informative. (Without local bounds the table would hold [EichhornRAS] Eq. 1's bound everywhere: not built.)
void TveSearch::Core::setUpBounds()
{
    if (!(options.tightBounds && (options.heuristic || options.zermelo) && LatticeHeuristic::hasLocalBounds(field)))
        return;
    // (refineWindows runs two static searches over the whole lattice: only on lattices up to 2^18 vertices)
    const bool refine = !std::isnan(options.deadline) && std::isfinite(tEnd) && options.windowRounds > 0 &&
                        lattice.numVertices() <= (std::size_t{1} << 18);
    const unsigned f = options.boundCellFactor ? options.boundCellFactor : LatticeHeuristic::autoCellFactor(lattice);
    const double origin = 0.0; // slices [k, k + 1] of absolute time: shared by searches of any departure
    if (LatticeHeuristic::hasSlicedBounds(field) &&
        (!ts.boxCache_ || !ts.boxCache_->matches(&field, lattice, z, f, origin, 1.0)))
        ts.boxCache_ = CellBoxCache::shared(ctx.field, lattice, z, f, origin, 1.0);
    if (refine || ts.boundsRefined_ || !ts.bounds_ || ts.bounds_->tBegin() != t0 || ts.bounds_->tEnd() != tEnd ||
        ts.bounds_->cellFactor() != f)
        ts.bounds_ = std::make_unique<LatticeHeuristic>(lattice, field, ctx.speed(), z, t0, tEnd, f, ts.boxCache_.get(),
                                                        terminate);
    ts.bounds_->setStop(terminate);
    ts.boundsRefined_ = refine;
    const auto landTest = [this](Lattice::VertexId v) { return inWater(v); };
    if (refine)
        ts.bounds_->refineWindows(options.windowRounds, landTest);
    if (terminated())
    {
        ts.bounds_.reset(); // built in part: not kept for the next search (the search stops before it uses them)
        return;
    }
    ts.bounds_->reset(landTest);
    if (ts.bounds_->informative())
        bounds = ts.bounds_.get(); // else the bounds are Eq. 1's: the code below uses it directly
}

/// The result of the queue loop: the path to the goal (Exact), to the reached vertex closest to the goal
/// (Terminated), or none (Exhausted).
TveResult TveSearch::Core::result(Lattice::VertexId found)
{
    if (found != Lattice::kNone)
    {
        res.outcome = TveOutcome::Exact;
        if (options.waiting && goalWindow && dist(found) < ctx.arriveNotBefore)
            ts.goalHoldUntil_ = ctx.arriveNotBefore; // arrived early where the goal can be held: hold there
        res.waypoints = ts.pathTo(found);
        res.travelTime = res.waypoints.back().t - t0;
        return finish();
    }
    if (res.outcome == TveOutcome::Terminated)
    {
        // Path to the reached vertex closest to the goal (when it is closer than the start).
        Lattice::VertexId best = Lattice::kNone;
        double bestDist = std::hypot(sx - gx, sy - gy);
        for (Lattice::VertexId v : ts.reached_)
        {
            const double d = std::hypot(lattice.x(v) - gx, lattice.y(v) - gy);
            if (d < bestDist)
            {
                bestDist = d;
                best = v;
            }
        }
        if (best != Lattice::kNone)
            res.waypoints = ts.pathTo(best);
        return finish();
    }
    res.outcome = TveOutcome::Exhausted;
    return finish();
}

/// Land test of a vertex (cached in wet); false outside the corridor of coarse-to-fine (TveOptions::coarseFactor).
bool TveSearch::Core::inWater(Lattice::VertexId v)
{
    if (!ts.inCorridor(v))
        return false;
    unsigned char &w = wet.ref(v);
    if (w == 0)
        w = field.inWater(lattice.x(v), lattice.y(v), z) ? 1 : 2;
    return w == 1;
}

/// [EichhornRAS] Eq. 1: |x_v - x_g| / vmax.
double TveSearch::Core::hEuclid(Lattice::VertexId v) const
{
    return std::hypot(lattice.x(v) - gx, lattice.y(v) - gy) / vmax;
}

/// The queue's heuristic: 0 without A*, else the weight times max(Eq. 1, LatticeHeuristic) (Eq. 1 without bounds).
double TveSearch::Core::h(Lattice::VertexId v)
{
    if (!options.heuristic)
        return 0.0;
    return options.heuristicWeight * (bounds ? std::max(hEuclid(v), (*bounds)(v)) : hEuclid(v));
}

/// A lower bound of the travel time of the edge u -> v at any departure in the search's window.
double TveSearch::Core::edgeBound(Lattice::VertexId u, Lattice::VertexId v) const
{
    return bounds ? bounds->edgeLowerBound(u, v)
                  : std::hypot(lattice.x(v) - lattice.x(u), lattice.y(v) - lattice.y(u)) / vAll;
}

/// With bounds: whether the edge u -> v leaving at du can be skipped without a CFC because its lower bound cannot
/// improve v, or reach the goal by the deadline, or improve the goal found so far (any arrival at the goal through
/// it is >= d[u] + bound + h(v)).
bool TveSearch::Core::boundSkip(Lattice::VertexId u, double du, Lattice::VertexId v)
{
    const double lb = bounds->edgeLowerBound(u, v);
    if (!(du + lb < dist(v)) || du + lb > tEnd)
        return true;
    const double hb = (*bounds)(v); // unweighted: a true lower bound (>= Eq. 1's, LatticeHeuristic)
    return du + lb + hb > tEnd || (dist(g) < kInf && !(du + lb + hb < dist(g)));
}

bool TveSearch::Core::terminated() const
{
    return terminate && terminate();
}
} // namespace ompl_glider

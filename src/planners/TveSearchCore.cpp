/// @file TveSearchCore.cpp
/// @brief One search of TveSearch ([EichhornRAS] Table 2 with the switches of TveOptions): TveSearch::runCore() and
/// its steps (TveSearch::Core).

#include "TveSearch.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <sstream>
#include <utility>

#include "ompl_glider/Exception.h"
#include "SearchSetting.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

/// Angle difference wrapped to [-pi, pi].
double angleDiff(double a, double b)
{
    double d = std::fmod(a - b, 2.0 * kPi);
    if (d > kPi)
        d -= 2.0 * kPi;
    else if (d < -kPi)
        d += 2.0 * kPi;
    return d;
}

/// Queue entry: key (d or d + h), the d it was pushed with (stale-entry test), vertex.
struct QueueEntry
{
    double key;
    double d;
    Lattice::VertexId v;
    bool operator>(const QueueEntry &o) const
    {
        return key > o.key || (key == o.key && v > o.v);
    }
};
/// An edge (u, v) pruned by the Zermelo cone, kept for the certification phase (TveOptions::certifyTolerance).
struct DeferredEdge
{
    double key;  ///< d[u] + |uv| / (V + max|c|) + |v - goal| / (V + max|c|): a lower bound of any arrival via it
    double du;   ///< d[u] when it was pruned (stale when d[u] changed since)
    Lattice::VertexId u, v;
    bool operator>(const DeferredEdge &o) const
    {
        return key > o.key || (key == o.key && (u > o.u || (u == o.u && v > o.v)));
    }
};

/// The predicted course at a vertex and the half-width of the accepted range around it (Zermelo pruning); no
/// course: every successor is examined.
struct Cone
{
    std::optional<double> phiOpt;
    double halfWidth;
};
}  // namespace

/// @brief One search of runCore(): the state its steps share (start s, goal g, queue Q, deadline tEnd, ...; the
/// arrival d[v] through dist()) and the steps as member functions. Lives for one call of runCore(); the labels, the
/// reached vertices, the bounds and the edge cache stay in the TveSearch.
class TveSearch::Core : private SearchSetting
{
public:
    /// @brief A search of @p search from (startX, startY), departing at @p departure, to (goalX, goalY).
    Core(TveSearch &search, double startX, double startY, double departure, double goalX, double goalY,
         const TveOptions &opts, const std::function<bool()> &stop);
    /// @brief Checks start and goal, sets up the bounds and the queue, runs the queue loop and returns the result
    /// with the CFC and CMC of this search.
    TveResult run();

private:
    using Queue = std::priority_queue<QueueEntry, std::vector<QueueEntry>, std::greater<QueueEntry>>;
    using DeferredQueue = std::priority_queue<DeferredEdge, std::vector<DeferredEdge>, std::greater<DeferredEdge>>;

    // --- set-up and result
    TveResult finish();
    bool invalid(TveOutcome outcome, std::string message);
    bool placed(const std::string &what, Lattice::VertexId v, double x, double y, TveOutcome bad);
    bool validEndpoints();
    void setUpBounds();
    TveResult result(Lattice::VertexId found);
    // --- land, bounds and heuristic
    bool inWater(Lattice::VertexId v);
    double hEuclid(Lattice::VertexId v) const;
    double h(Lattice::VertexId v);
    double edgeBound(Lattice::VertexId u, Lattice::VertexId v) const;
    bool boundSkip(Lattice::VertexId u, double du, Lattice::VertexId v);
    bool terminated() const;
    // --- edges
    double edgeTime(Lattice::VertexId u, double ux, double uy, Lattice::VertexId v, double vx, double vy,
                    double dep);
    void label(Lattice::VertexId u, Lattice::VertexId v, double dv, double dep);
    bool canWait(double ux, double uy, double du, double tw) const;
    bool relax(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v);
    void holdBeforeGoal(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v, double vx,
                        double vy);
    void departAfterRelease(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v, double vx,
                            double vy);
    // --- the queue loop
    Lattice::VertexId search();
    void examineDeferred();
    bool restartUnpruned();
    Cone predictCone(Lattice::VertexId u, double ux, double uy, double du);
    void expand(Lattice::VertexId u);

    double dist(Lattice::VertexId v) const
    {
        return ts.dist(v);
    }
    Lattice::VertexId parent(Lattice::VertexId v) const
    {
        return ts.parent(v);
    }

    TveSearch &ts;
    Lattice &lattice;
    const TveOptions &options;
    const std::function<bool()> &terminate;
    const std::uint64_t cfc0;  ///< CFC before the search
    const std::uint64_t cmc0;  ///< CMC before the search
    TveResult res;
    LatticeHeuristic *bounds{nullptr};  ///< set by setUpBounds() when TveOptions::tightBounds applies
    Lattice::VertexId s{Lattice::kNone}, g{Lattice::kNone};
    VertexPages<unsigned char> wet;  ///< land cache: 0 unknown, 1 water, 2 land (only the pages looked at)
    double tEnd{0.0};                ///< arrival deadline of this search (TveOptions::deadline)
    double vmax{0.0};                ///< speed bound of [EichhornRAS] Eq. 1: V + max|c| with the heuristic, else V
    Queue Q;
    std::vector<Lattice::VertexId> prunedAt;  ///< vertices whose expansion pruned edges (for the fallback)
    bool pruning{false};
    std::vector<double> releases;  ///< the environment's release times (TveOptions::waiting)
    double holdStep{0.0};
    bool goalWindow{false};
    bool certify{false};  ///< TveOptions::certifyTolerance applies
    double vAll{0.0};     ///< V + max|c|: the edge bound without LatticeHeuristic
    DeferredQueue deferred;
    unsigned checkEvery{1};
};

TveSearch::Core::Core(TveSearch &search, double startX, double startY, double departure, double goalX, double goalY,
                      const TveOptions &opts, const std::function<bool()> &stop)
  : SearchSetting(*search.ctx_, startX, startY, departure, goalX, goalY)
  , ts(search)
  , lattice(search.lattice_)
  , options(opts)
  , terminate(stop)
  , cfc0(travel.costFunctionCalls())
  , cmc0(field.callCount())
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
    ts.labels_.reset(lattice, Label{});  // labels only of the pages reached: memory grows with the search
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
        ts.bounds_->releaseLandTest();  // it refers to this run's land cache
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
    const double origin = 0.0;  // slices [k, k + 1] of absolute time: shared by searches of any departure
    if (LatticeHeuristic::hasSlicedBounds(field) &&
        (!ts.boxCache_ || !ts.boxCache_->matches(&field, lattice, z, f, origin, 1.0)))
        ts.boxCache_ = CellBoxCache::shared(ctx.field, lattice, z, f, origin, 1.0);
    if (refine || ts.boundsRefined_ || !ts.bounds_ || ts.bounds_->tBegin() != t0 || ts.bounds_->tEnd() != tEnd ||
        ts.bounds_->cellFactor() != f)
        ts.bounds_ = std::make_unique<LatticeHeuristic>(lattice, field, ctx.speed(), z, t0, tEnd, f,
                                                        ts.boxCache_.get(), terminate);
    ts.bounds_->setStop(terminate);
    ts.boundsRefined_ = refine;
    const auto landTest = [this](Lattice::VertexId v) { return inWater(v); };
    if (refine)
        ts.bounds_->refineWindows(options.windowRounds, landTest);
    if (terminated())
    {
        ts.bounds_.reset();  // built in part: not kept for the next search (the search stops before it uses them)
        return;
    }
    ts.bounds_->reset(landTest);
    if (ts.bounds_->informative())
        bounds = ts.bounds_.get();  // else the bounds are Eq. 1's: the code below uses it directly
}

/// The result of the queue loop: the path to the goal (Exact), to the reached vertex closest to the goal
/// (Terminated), or none (Exhausted).
TveResult TveSearch::Core::result(Lattice::VertexId found)
{
    if (found != Lattice::kNone)
    {
        res.outcome = TveOutcome::Exact;
        if (options.waiting && goalWindow && dist(found) < ctx.arriveNotBefore)
            ts.goalHoldUntil_ = ctx.arriveNotBefore;  // arrived early where the goal can be held: hold there
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
    const double hb = (*bounds)(v);  // unweighted: a true lower bound (>= Eq. 1's, LatticeHeuristic)
    return du + lb + hb > tEnd || (dist(g) < kInf && !(du + lb + hb < dist(g)));
}

bool TveSearch::Core::terminated() const
{
    return terminate && terminate();
}

/// Travel time of the edge u -> v departing at dep (one CFC; from the edge cache of the phases when there is one).
double TveSearch::Core::edgeTime(Lattice::VertexId u, double ux, double uy, Lattice::VertexId v, double vx, double vy,
                                 double dep)
{
    if (!ts.edgeCache_)
        return travel.travelTime(ux, uy, vx, vy, dep);
    const auto [it, inserted] = ts.edgeCache_->try_emplace(EdgeKey{u, v, dep}, 0.0);
    if (inserted)
        it->second = travel.travelTime(ux, uy, vx, vy, dep);
    return it->second;
}

/// Improves v: arrival dv through u, departing from u at dep (-inf: on arrival); queued unless the goal cannot be
/// reached from v.
void TveSearch::Core::label(Lattice::VertexId u, Lattice::VertexId v, double dv, double dep)
{
    Label &lv = ts.labels_.ref(v);
    if (lv.d == kInf)
        ts.reached_.push_back(v);
    lv.d = dv;
    lv.pi = u;
    lv.dep = dep;
    const double hv = h(v);
    if (hv < kInf)  // +inf: the goal cannot be reached from v even with the optimistic bounds
        Q.push({dv + hv, dv, v});
}

/// Holding at u over [du, tw]: |c| < V there (a superset of the motion validator's samples) and u free.
bool TveSearch::Core::canWait(double ux, double uy, double du, double tw) const
{
    return ctx.canHold(ux, uy, du, tw, holdStep, 4) && (!env || env->legFree(ux, uy, du, ux, uy, tw));
}

/// Examines the edge u -> v leaving at du (one CFC): true when its travel time is finite; improves v when the arrival
/// is earlier than d[v], inside the window and free.
bool TveSearch::Core::relax(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v)
{
    if (!inWater(v))
        return false;
    const double vx = lattice.x(v), vy = lattice.y(v);
    if (bounds && boundSkip(u, du, v))
    {
        ++res.boundSkips;
        return true;
    }
    const double w = edgeTime(u, ux, uy, v, vx, vy, du);
    if (!std::isfinite(w))
        return false;
    const double dv = du + w;
    if (options.waiting && v == g && goalWindow)
    {
        // goal window: an arrival counts inside [arriveNotBefore, arriveNotAfter] (TveOptions::waiting)
        if (dv > ctx.arriveNotAfter)
            return true;
        if (dv < ctx.arriveNotBefore && !(ctx.canHold(gx, gy, dv, ctx.arriveNotBefore, holdStep, 4) &&
                                           (!env || env->legFree(gx, gy, dv, gx, gy, ctx.arriveNotBefore))))
        {
            holdBeforeGoal(u, ux, uy, du, v, vx, vy);
            return true;
        }
    }
    if (!(dv < dist(v)) || dv > tEnd)
        return true;  // no improvement, or later than the planning window
    if (env && (!env->pointFree(vx, vy, dv) || !env->legFree(ux, uy, du, vx, vy, dv)))
    {
        if (options.waiting && !releases.empty())
            departAfterRelease(u, ux, uy, du, v, vx, vy);
        return true;
    }
    label(u, v, dv, -kInf);
    return true;
}

/// The edge u -> v into the goal arrives before the goal window opens and the goal cannot be held: hold at u so that
/// the edge arrives at the window's begin (bisection on the departure; arrival non-decreasing in it, FIFO).
void TveSearch::Core::holdBeforeGoal(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v,
                                     double vx, double vy)
{
    const double B = ctx.arriveNotBefore;
    if (!(B < dist(v)) || B > tEnd)
        return;
    double lo = du, hi = B;
    double hiArr = hi + edgeTime(u, ux, uy, v, vx, vy, hi);
    if (!std::isfinite(hiArr))
        return;
    for (int it = 0; it < 50 && hiArr > B * (1.0 + 1e-12) + 1e-12; ++it)
    {
        const double mid = 0.5 * (lo + hi);
        const double a = mid + edgeTime(u, ux, uy, v, vx, vy, mid);
        if (std::isfinite(a) && a >= B)
        {
            hi = mid;
            hiArr = a;
        }
        else
            lo = mid;
    }
    if (!(hiArr < dist(v)) || hiArr > tEnd || hiArr > ctx.arriveNotAfter || !canWait(ux, uy, du, hi))
        return;
    if (env && (!env->pointFree(vx, vy, hiArr) || !env->legFree(ux, uy, hi, vx, vy, hiArr)))
        return;
    label(u, v, hiArr, hi);
}

/// The edge u -> v leaving at du is blocked by the environment: a waiting edge departing just after a release time
/// (the end of a blocking window), the first that frees the leg (later ones arrive no earlier where the field is
/// FIFO).
void TveSearch::Core::departAfterRelease(Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v,
                                         double vx, double vy)
{
    for (const double r : releases)
    {
        const double tw = r + 1e-9 * std::max(1.0, std::abs(r));
        if (tw <= du)
            continue;
        if (tw > tEnd || !(tw < dist(v)) || !canWait(ux, uy, du, tw))
            break;  // later departures cannot improve v, or the glider cannot hold that long
        const double ww = edgeTime(u, ux, uy, v, vx, vy, tw);
        if (!std::isfinite(ww))
            continue;
        const double dw = tw + ww;
        if (dw > tEnd || !(dw < dist(v)))
            break;
        if (env->pointFree(vx, vy, dw) && env->legFree(ux, uy, tw, vx, vy, dw))
        {
            if (v == g && goalWindow && dw > ctx.arriveNotAfter)
                break;
            label(u, v, dw, tw);
            break;
        }
    }
}

/// The queue loop ([EichhornRAS] Table 2): the goal vertex when it is extracted, kNone when the queue runs empty or
/// the termination callback fires (res.outcome Terminated).
///
/// Certification (TveOptions::certifyTolerance): pruned edges are deferred, not dropped, each with the lower
/// bound key = d[u] + (edge bound) + h(v) of the queue key v would get through it (h = the queue's heuristic, 0
/// without A*). A deferred edge is examined as soon as its key, inflated by (1 + tol) from t0, is not above the
/// queue's smallest key, i.e. in key order interleaved with the queue. With tol = 0 and a consistent heuristic
/// (and edge bounds consistent with it) every vertex is extracted with its final label, as in A* without
/// pruning: the search returns the fixpoint d(v) = min_u d(u) + w(u, v, d(u)) that TVE computes (unique for
/// positive edge times), only without the CFC of the deferred edges whose key exceeds the goal's arrival.
/// (The earlier rule examined deferred edges only after the goal's first extraction; a vertex could then be
/// improved after its successors had been labelled from its old arrival time, and the returned arrival could
/// differ from TVE's where the field is not FIFO, e.g. random pair 9 of bench_search, 16 % below TVE's.)
Lattice::VertexId TveSearch::Core::search()
{
    for (;;)
    {
        if (certify && !deferred.empty() &&
            (Q.empty() || t0 + (deferred.top().key - t0) * (1.0 + options.certifyTolerance) <= Q.top().key))
        {
            examineDeferred();
            continue;
        }
        if (Q.empty())
        {
            if (restartUnpruned())
                continue;
            return Lattice::kNone;
        }
        const QueueEntry e = Q.top();
        Q.pop();
        const Lattice::VertexId u = e.v;
        if (e.d != dist(u))
            continue;  // stale entry (u was improved after this push)
        if (u == g)
            return u;
        if (!options.reopen)
        {
            Label &lu = ts.labels_.ref(u);
            if (lu.expanded)
                continue;  // expanded once already (TveOptions::reopen)
            lu.expanded = true;
        }
        ++res.expansions;
        if (res.expansions % checkEvery == 0 && terminated())
        {
            res.outcome = TveOutcome::Terminated;
            return Lattice::kNone;
        }
        expand(u);
    }
}

/// Examines the deferred edge with the smallest key (certification).
void TveSearch::Core::examineDeferred()
{
    const DeferredEdge de = deferred.top();
    deferred.pop();
    // stale (u improved and re-expanded since), or cannot improve v even at the bound
    if (de.du != dist(de.u) || !(de.du + edgeBound(de.u, de.v) < dist(de.v)))
        return;
    ++res.reopenedEdges;
    relax(de.u, lattice.x(de.u), lattice.y(de.u), de.du, de.v);
}

/// The pruned search could not reach the goal: continue with the full neighbourhoods of the vertices whose expansion
/// pruned edges (TveOptions::unprunedFallback). False when there is nothing to continue with.
bool TveSearch::Core::restartUnpruned()
{
    if (!(pruning && options.unprunedFallback && !prunedAt.empty()))
        return false;
    pruning = false;
    res.fallbackUsed = true;
    for (Lattice::VertexId v : prunedAt)
    {
        ts.labels_.ref(v).expanded = false;  // expanded again, with every edge
        if (h(v) < kInf)
            Q.push({dist(v) + h(v), dist(v), v});
    }
    prunedAt.clear();
    return true;
}

/// Zermelo pruning at u ([EichhornRAS] Sec. 2.2.2): phi_opt predicted by CALC-OPTDIR from u's predecessor edge,
/// extrapolated and widened with the predicted turn (TveOptions); no course at the start, near the goal
/// (goalRadius), where the prediction fails or is unreliable, and without pruning.
Cone TveSearch::Core::predictCone(Lattice::VertexId u, double ux, double uy, double du)
{
    Cone cone{std::nullopt, options.deltaPhiMax};
    if (!pruning || u == s || parent(u) == Lattice::kNone ||
        (options.goalRadius > 0.0 && std::hypot(ux - gx, uy - gy) <= options.goalRadius))
        return cone;
    const Lattice::VertexId p = parent(u);
    cone.phiOpt = ts.calcOptimalCourse(lattice.x(p), lattice.y(p), dist(p), ux, uy, du, options.zermeloSteps);
    if (cone.phiOpt)
    {
        const double edge = std::atan2(uy - lattice.y(p), ux - lattice.x(p));
        const double turn = angleDiff(*cone.phiOpt, edge);
        *cone.phiOpt += options.courseExtrapolation * turn;
        cone.halfWidth = options.deltaPhiMax + options.turnWidening * std::abs(turn);
        if (std::abs(turn) > options.reliableTurn)
            cone.phiOpt.reset();  // unreliable prediction: examine every successor
    }
    return cone;
}

/// Expands u: examines its successors inside the Zermelo cone, defers (certification) or drops the others.
void TveSearch::Core::expand(Lattice::VertexId u)
{
    const double du = dist(u);
    const double ux = lattice.x(u), uy = lattice.y(u);
    const Cone cone = predictCone(u, ux, uy, du);
    bool prunedHere = false;
    bool feasibleInCone = false;  // some examined edge had a finite travel time
    // pass 0: the cone around phi_opt (everything without pruning); pass 1: the rest, only when the cone was a
    // dead end (options.deadEndFallback).
    for (int pass = 0; pass < 2; ++pass)
    {
        if (pass == 1 && (!prunedHere || feasibleInCone || !options.deadEndFallback))
            break;
        lattice.forEachSuccessor(u, [&](Lattice::VertexId v) {
            if (!(du < dist(v)))
                return;  // d[u] >= d[v]: the edge cannot improve v ([EichhornRAS] Table 1, difference 2)
            const double vx = lattice.x(v), vy = lattice.y(v);
            const bool inCone = !cone.phiOpt || (options.neverPruneGoal && v == g) ||
                                std::abs(angleDiff(*cone.phiOpt, std::atan2(vy - uy, vx - ux))) <= cone.halfWidth;
            if (pass == 0 && !inCone)
            {
                ++res.prunedEdges;
                prunedHere = true;
                if (certify)
                {
                    // a lower bound of the queue key v would get through u -> v
                    const double key = du + edgeBound(u, v) + h(v);
                    if (key < kInf)
                        deferred.push({key, du, u, v});
                }
                return;
            }
            if (pass == 1 && inCone)
                return;  // examined in pass 0
            if (relax(u, ux, uy, du, v))
                feasibleInCone = true;
        });
        if (pass == 1)
        {
            ++res.deadEnds;
            prunedHere = false;  // everything examined now
        }
    }
    if (prunedHere)
        prunedAt.push_back(u);
}
}  // namespace ompl_glider

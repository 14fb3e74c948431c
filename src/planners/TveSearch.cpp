#include "ompl_glider/planners/TveSearch.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <sstream>
#include <utility>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

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

const GliderContext &checkedContext(const std::shared_ptr<const GliderContext> &ctx)
{
    if (!ctx)
        throw Error("TveSearch: no GliderContext given");
    if (!ctx->field)
        throw Error("TveSearch: GliderContext.field is null");
    if (!ctx->travel)
        throw Error("TveSearch: GliderContext.travel is null");
    return *ctx;
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
}  // namespace

TveSearch::TveSearch(std::shared_ptr<const GliderContext> ctx, double gridSize, unsigned sectors)
  : ctx_(std::move(ctx))
  , lattice_(checkedContext(ctx_).region.xMin, ctx_->region.xMax, ctx_->region.yMin, ctx_->region.yMax, gridSize,
             sectors)
{
}

std::optional<double> TveSearch::calcOptimalCourse(double px, double py, double tp, double ux, double uy, double tu,
                                                   unsigned steps) const
{
    const CurrentField &f = *ctx_->field;
    const double V = ctx_->speed();
    const double z = ctx_->travel->params().depth;
    const double len = std::hypot(ux - px, uy - py);
    if (!(len > 0.0) || !std::isfinite(tp) || !std::isfinite(tu))
        return std::nullopt;
    const double ex = (ux - px) / len, ey = (uy - py) / len;
    double x = 0.5 * (px + ux), y = 0.5 * (py + uy), t = 0.5 * (tp + tu);
    Velocity c = f.velocity(x, y, z, t);
    const AlongTrackSpeeds r = alongTrackSpeeds(ex, ey, c, V);
    if (!r.feasible)
        return std::nullopt;
    // Heading through water that keeps the course along the edge: V (cos th, sin th) = s e - c.
    double th = std::atan2(r.fast * ey - c.v, r.fast * ex - c.u);

    // Zermelo's law ([EichhornRAS] Eq. 2) and the motion ([EichhornRAS] Eq. 10): (x, y, th)' = F(x, y, th, t).
    auto rhs = [&](const Velocity &cv, double px_, double py_, double th_, double t_, double &dx, double &dy,
                   double &dth) {
        const Jacobian J = f.jacobian(px_, py_, z, t_);
        const double ct = std::cos(th_), st = std::sin(th_);
        dx = cv.u + V * ct;
        dy = cv.v + V * st;
        dth = -J.uy * ct * ct + (J.ux - J.vy) * ct * st + J.vx * st * st;
    };
    const double T = tu - t;
    if (T > 0.0 && steps > 0)
    {
        const double h = T / static_cast<double>(steps);
        for (unsigned k = 0; k < steps; ++k)
        {
            if (k > 0)
                c = f.velocity(x, y, z, t);
            double k1x, k1y, k1t;
            rhs(c, x, y, th, t, k1x, k1y, k1t);
            const double xm = x + 0.5 * h * k1x, ym = y + 0.5 * h * k1y, thm = th + 0.5 * h * k1t;
            const Velocity cm = f.velocity(xm, ym, z, t + 0.5 * h);
            double k2x, k2y, k2t;
            rhs(cm, xm, ym, thm, t + 0.5 * h, k2x, k2y, k2t);
            x += h * k2x;
            y += h * k2y;
            th += h * k2t;
            t += h;
        }
        c = f.velocity(x, y, z, t);
    }
    const double gx = c.u + V * std::cos(th), gy = c.v + V * std::sin(th);
    if (!(std::hypot(gx, gy) > 1e-12 * V) || !std::isfinite(gx) || !std::isfinite(gy))
        return std::nullopt;
    return std::atan2(gy, gx);
}

TveResult TveSearch::run(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                         const std::function<bool()> &terminate)
{
    const bool coarseToFine =
        std::isnan(options.deadline) &&
        (options.coarseFactor > 1 ||
         (options.coarseFactor == 0 && options.heuristic && lattice_.numGridVertices() > (std::size_t{1} << 19)));
    auto search = [&] {
        return coarseToFine ? runCoarseToFine(sx, sy, t0, gx, gy, options, terminate)
                            : runPhases(sx, sy, t0, gx, gy, options, terminate);
    };
    TveResult r = search();
    const bool window = std::isfinite(ctx_->arriveNotBefore) || std::isfinite(ctx_->arriveNotAfter);
    if (r.outcome != TveOutcome::Exhausted || !window || !options.waiting || !options.goalWindowFallback)
        return r;
    // no path meets the goal window: the earliest arrival without it (TveOptions::goalWindowFallback)
    struct Scope
    {
        TveSearch &s;
        ~Scope()
        {
            s.ignoreGoalWindow_ = false;
        }
    } scope{*this};
    ignoreGoalWindow_ = true;
    TveResult f = search();
    f.costFunctionCalls += r.costFunctionCalls;
    f.currentModelCalls += r.currentModelCalls;
    f.expansions += r.expansions;
    f.goalWindowMissed = f.outcome == TveOutcome::Exact;
    return f;
}

namespace
{
/// Adds the counters of r to into (the searches of one run).
void addCounts(TveResult &into, const TveResult &r)
{
    into.costFunctionCalls += r.costFunctionCalls;
    into.currentModelCalls += r.currentModelCalls;
    into.expansions += r.expansions;
    into.prunedEdges += r.prunedEdges;
    into.reopenedEdges += r.reopenedEdges;
    into.boundSkips += r.boundSkips;
    into.heuristicSettled += r.heuristicSettled;
}
}  // namespace

TveResult TveSearch::runCoarseToFine(double sx, double sy, double t0, double gx, double gy,
                                     const TveOptions &options, const std::function<bool()> &terminate)
{
    const long f = options.coarseFactor > 1 ? static_cast<long>(options.coarseFactor) : 8;
    TveOptions single = options;
    single.coarseFactor = 1;

    // 1. The coarse search (same region, spacing f g; kept between runs).
    const double gc = lattice_.gridSize() * static_cast<double>(f);
    if (!coarse_ || coarse_->lattice_.gridSize() != gc || coarse_->lattice_.sectors() != lattice_.sectors())
        coarse_ = std::make_unique<TveSearch>(ctx_, gc, lattice_.sectors());
    coarse_->ignoreGoalWindow_ = ignoreGoalWindow_;
    const TveResult coarse = coarse_->runPhases(sx, sy, t0, gx, gy, single, terminate);
    if (coarse.outcome == TveOutcome::Terminated)
        return coarse;
    if (coarse.outcome != TveOutcome::Exact)
    {
        // no coarse path (a passage narrower than the coarse lattice resolves, or none at all): the full search
        TveResult r = runPhases(sx, sy, t0, gx, gy, single, terminate);
        addCounts(r, coarse);
        return r;
    }

    // 2. Chebyshev distance, in blocks of f x f cells, of every block from the blocks the coarse path crosses
    // (multi-source breadth-first search with 8 neighbours).
    const long NX = (lattice_.nx() + f - 1) / f, NY = (lattice_.ny() + f - 1) / f;
    const double bs = lattice_.gridSize() * static_cast<double>(f);
    std::vector<int> ring(static_cast<std::size_t>(NX * NY), -1);
    std::vector<long> frontier;
    auto mark = [&](double x, double y) {
        const long I = std::clamp(static_cast<long>(std::floor((x - lattice_.xMin()) / bs)), 0L, NX - 1);
        const long J = std::clamp(static_cast<long>(std::floor((y - lattice_.yMin()) / bs)), 0L, NY - 1);
        const long b = I + J * NX;
        if (ring[static_cast<std::size_t>(b)] < 0)
        {
            ring[static_cast<std::size_t>(b)] = 0;
            frontier.push_back(b);
        }
    };
    for (std::size_t k = 0; k < coarse.waypoints.size(); ++k)
    {
        const TimedPoint &a = coarse.waypoints[k];
        mark(a.x, a.y);
        if (k + 1 == coarse.waypoints.size())
            break;
        const TimedPoint &b = coarse.waypoints[k + 1];
        const int n = static_cast<int>(std::ceil(4.0 * std::hypot(b.x - a.x, b.y - a.y) / bs));
        for (int i = 1; i < n; ++i)
            mark(a.x + (b.x - a.x) * i / n, a.y + (b.y - a.y) * i / n);
    }
    int maxRing = 0;
    for (std::size_t head = 0; head < frontier.size(); ++head)
    {
        const long b = frontier[head], I = b % NX, J = b / NX;
        const int d = ring[static_cast<std::size_t>(b)];
        maxRing = std::max(maxRing, d);
        for (long dj = -1; dj <= 1; ++dj)
            for (long di = -1; di <= 1; ++di)
            {
                const long a = I + di, c = J + dj;
                if (a < 0 || c < 0 || a >= NX || c >= NY || ring[static_cast<std::size_t>(a + c * NX)] >= 0)
                    continue;
                ring[static_cast<std::size_t>(a + c * NX)] = d + 1;
                frontier.push_back(a + c * NX);
            }
    }

    // 3. Fine searches inside the corridor, doubled while the fine path enters its outermost ring (or none lies
    // inside). Travel times are shared between the rounds (same edge, same departure).
    struct Scope
    {
        TveSearch &s;
        bool ownsCache;
        ~Scope()
        {
            s.corridor_.clear();
            if (ownsCache)
                s.edgeCache_ = nullptr;
        }
    } scope{*this, edgeCache_ == nullptr};
    std::unordered_map<EdgeKey, double, EdgeKeyHash> cache;
    if (scope.ownsCache)
        edgeCache_ = &cache;
    corridorFactor_ = f;
    corridorNX_ = NX;
    TveResult total = coarse;
    total.waypoints.clear();
    unsigned rounds = 0;
    for (int w = std::max(1, static_cast<int>(options.corridorBlocks));; w = 2 * w)
    {
        const bool whole = w >= maxRing;
        corridor_.clear();
        if (!whole)
        {
            corridor_.resize(ring.size());
            for (std::size_t b = 0; b < ring.size(); ++b)
                corridor_[b] = ring[b] <= w ? 1 : 0;
        }
        TveResult r = runPhases(sx, sy, t0, gx, gy, single, terminate);
        addCounts(total, r);
        r.costFunctionCalls = total.costFunctionCalls;
        r.currentModelCalls = total.currentModelCalls;
        r.expansions = total.expansions;
        r.prunedEdges = total.prunedEdges;
        r.reopenedEdges = total.reopenedEdges;
        r.boundSkips = total.boundSkips;
        r.heuristicSettled = total.heuristicSettled;
        r.corridorRounds = ++rounds;
        r.corridorBlocks = static_cast<unsigned>(w);
        if (whole || r.outcome == TveOutcome::Terminated || r.outcome == TveOutcome::InvalidStart ||
            r.outcome == TveOutcome::InvalidGoal)
            return r;
        if (r.outcome == TveOutcome::Exact)
        {
            bool touches = false;
            for (const TimedPoint &p : r.waypoints)
            {
                const long i = std::lround((p.x - lattice_.xMin()) / lattice_.gridSize());
                const long j = std::lround((p.y - lattice_.yMin()) / lattice_.gridSize());
                if (i < 0 || j < 0 || i >= lattice_.nx() || j >= lattice_.ny())
                    continue;
                if (ring[static_cast<std::size_t>(i / f + (j / f) * NX)] >= w)
                    touches = true;
            }
            if (!touches)
                return r;
        }
    }
}

TveResult TveSearch::runPhases(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                               const std::function<bool()> &terminate)
{
    // (the phases pay off through LatticeHeuristic::refineWindows: only with local bounds, on lattices it refines)
    if (!(options.tightBounds && options.heuristic && options.greedyDeadline && std::isnan(options.deadline) &&
          options.heuristicWeight == 1.0 && options.windowRounds > 0 &&
          lattice_.numVertices() <= (std::size_t{1} << 18) && LatticeHeuristic::hasLocalBounds(*ctx_->field)))
        return runCore(sx, sy, t0, gx, gy, options, terminate);
    std::unordered_map<EdgeKey, double, EdgeKeyHash> cache;
    struct Scope
    {
        TveSearch &s;
        bool ownsCache;
        ~Scope()
        {
            if (ownsCache)
                s.edgeCache_ = nullptr;
        }
    } scope{*this, edgeCache_ == nullptr};
    if (scope.ownsCache)
        edgeCache_ = &cache;  // (coarse-to-fine shares its own between the corridor rounds)
    const auto add = addCounts;
    TveOptions greedy = options;
    greedy.greedyDeadline = false;
    greedy.zermelo = true;
    greedy.certifyTolerance = -1.0;
    greedy.heuristicWeight = options.greedyWeight;
    greedy.reopen = false;  // any arrival serves as the deadline; reopening could cost far more than it gains
    const TveResult first = runCore(sx, sy, t0, gx, gy, greedy, terminate);
    TveOptions second = options;
    second.greedyDeadline = false;
    if (first.outcome == TveOutcome::Exhausted)
    {
        // (without reopening, a greedy search that exhausts proves nothing where the field is not FIFO: the search
        // without deadline decides)
        TveResult full = runCore(sx, sy, t0, gx, gy, second, terminate);
        add(full, first);
        return full;
    }
    if (first.outcome != TveOutcome::Exact)
        return first;  // invalid start/goal, or terminated
    second.deadline = t0 + first.travelTime * (1.0 + 1e-12);
    TveResult r = runCore(sx, sy, t0, gx, gy, second, terminate);
    add(r, first);
    if (r.outcome == TveOutcome::Exhausted)
    {
        second.deadline = std::numeric_limits<double>::quiet_NaN();
        TveResult full = runCore(sx, sy, t0, gx, gy, second, terminate);
        add(full, r);
        return full;
    }
    return r;
}

TveResult TveSearch::runCore(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                             const std::function<bool()> &terminate)
{
    const GliderContext &ctx = *ctx_;
    const CurrentField &field = *ctx.field;
    const TravelTimeCalculator &travel = *ctx.travel;
    const Environment *env = ctx.environment.get();
    const double z = travel.params().depth;

    const std::uint64_t cfc0 = travel.costFunctionCalls();
    const std::uint64_t cmc0 = field.callCount();
    TveResult res;
    LatticeHeuristic *bounds = nullptr;  // set below when TveOptions::tightBounds applies
    auto finish = [&](TveResult &r) -> TveResult & {
        r.costFunctionCalls = travel.costFunctionCalls() - cfc0;
        r.currentModelCalls = field.callCount() - cmc0;
        r.heuristicSettled = bounds ? bounds->settled() : 0;
        if (bounds_)
            bounds_->releaseLandTest();  // it refers to this run's land cache
        return r;
    };

    // Clear the previous run's labels (only the vertices it touched).
    labels_.reset(lattice_, Label{});  // labels only of the pages reached: memory grows with the search
    reached_.clear();

    // Start and goal.
    const Lattice::VertexId s = lattice_.setStart(sx, sy);
    const Lattice::VertexId g = lattice_.setGoal(gx, gy);
    if (s == Lattice::kNone)
    {
        res.outcome = TveOutcome::InvalidStart;
        res.message = "start " + formatPoint(sx, sy) + " lies outside the planning region";
        return finish(res);
    }
    if (!field.inWater(sx, sy, z))
    {
        res.outcome = TveOutcome::InvalidStart;
        res.message = "start " + formatPoint(sx, sy) + " is not in water (land or no current data)";
        return finish(res);
    }
    if (!std::isfinite(t0) || !(t0 >= ctx.region.tMin && t0 <= ctx.region.tMax))
    {
        std::ostringstream os;
        os << "start time t0 = " << t0 << (std::isfinite(t0) ? " lies outside" : " is not finite; it must lie in")
           << " the planning window [" << ctx.region.tMin << ", " << ctx.region.tMax << "]";
        res.outcome = TveOutcome::InvalidStart;
        res.message = os.str();
        return finish(res);
    }
    if (env && !env->pointFree(sx, sy, t0))
    {
        res.outcome = TveOutcome::InvalidStart;
        res.message = "start " + formatPoint(sx, sy) + " is blocked at t0: " + env->whyBlocked(sx, sy, t0);
        return finish(res);
    }
    if (g == Lattice::kNone)
    {
        res.outcome = TveOutcome::InvalidGoal;
        res.message = "goal " + formatPoint(gx, gy) + " lies outside the planning region";
        return finish(res);
    }
    if (!field.inWater(gx, gy, z))
    {
        res.outcome = TveOutcome::InvalidGoal;
        res.message = "goal " + formatPoint(gx, gy) + " is not in water (land or no current data)";
        return finish(res);
    }
    if (env)
    {
        // A goal blocked at t0 and at the end of the window (t0 when the window is open-ended) is invalid.
        const double tLate = std::isfinite(ctx.region.tMax) ? ctx.region.tMax : t0;
        if (!env->pointFree(gx, gy, t0) && !env->pointFree(gx, gy, tLate))
        {
            res.outcome = TveOutcome::InvalidGoal;
            res.message = "goal " + formatPoint(gx, gy) + " is blocked: " + env->whyBlocked(gx, gy, t0);
            return finish(res);
        }
    }

    // Land cache: 0 unknown, 1 water, 2 land.
    VertexPages<unsigned char> wet;  // only the pages looked at
    wet.reset(lattice_, 0);
    auto inWater = [&](Lattice::VertexId v) {
        if (!inCorridor(v))
            return false;  // outside the corridor of coarse-to-fine (TveOptions::coarseFactor)
        unsigned char &w = wet.ref(v);
        if (w == 0)
            w = field.inWater(lattice_.x(v), lattice_.y(v), z) ? 1 : 2;
        return w == 1;
    };

    // Arrival deadline of this search (TveOptions::deadline): arrivals after it are dropped.
    const double tEnd = std::isnan(options.deadline) ? ctx.region.tMax : std::min(ctx.region.tMax, options.deadline);

    // Lower bounds of edges and of the remaining time (TveOptions::tightBounds, LatticeHeuristic).
    // (without local bounds the table would hold [EichhornRAS] Eq. 1's bound everywhere: not built)
    if (options.tightBounds && (options.heuristic || options.zermelo) && LatticeHeuristic::hasLocalBounds(field))
    {
        // (refineWindows runs two static searches over the whole lattice: only on lattices up to 2^18 vertices)
        const bool refine = !std::isnan(options.deadline) && std::isfinite(tEnd) && options.windowRounds > 0 &&
                            lattice_.numVertices() <= (std::size_t{1} << 18);
        const unsigned f =
            options.boundCellFactor ? options.boundCellFactor : LatticeHeuristic::autoCellFactor(lattice_);
        const double origin = 0.0;  // slices [k, k + 1] of absolute time: shared by searches of any departure
        if (LatticeHeuristic::hasSlicedBounds(field) &&
            (!boxCache_ || !boxCache_->matches(&field, lattice_, z, f, origin, 1.0)))
            boxCache_ = CellBoxCache::shared(ctx.field, lattice_, z, f, origin, 1.0);
        if (refine || boundsRefined_ || !bounds_ || bounds_->tBegin() != t0 || bounds_->tEnd() != tEnd ||
            bounds_->cellFactor() != f)
            bounds_ = std::make_unique<LatticeHeuristic>(lattice_, field, ctx.speed(), z, t0, tEnd, f,
                                                         boxCache_.get());
        boundsRefined_ = refine;
        if (refine)
            bounds_->refineWindows(options.windowRounds, inWater);
        bounds_->reset(inWater);
        if (bounds_->informative())
            bounds = bounds_.get();  // else the bounds are Eq. 1's: the code below uses it directly
    }

    // A* heuristic ([EichhornRAS] Eq. 1), or max(Eq. 1, LatticeHeuristic).
    const double vmax = ctx.speed() + (options.heuristic ? ctx.maxCurrent() : 0.0);
    auto hEuclid = [&](Lattice::VertexId v) -> double {
        return std::hypot(lattice_.x(v) - gx, lattice_.y(v) - gy) / vmax;
    };
    auto h = [&](Lattice::VertexId v) -> double {
        if (!options.heuristic)
            return 0.0;
        return options.heuristicWeight * (bounds ? std::max(hEuclid(v), (*bounds)(v)) : hEuclid(v));
    };
    if (options.heuristic && !(vmax > 0.0 && std::isfinite(vmax)))
        throw Error("TveSearch: the A* heuristic needs a finite bound of the current speed over the region");

    std::priority_queue<QueueEntry, std::vector<QueueEntry>, std::greater<QueueEntry>> Q;
    labels_.ref(s) = {t0, Lattice::kNone};
    reached_.push_back(s);
    Q.push({t0 + h(s), t0, s});
    std::vector<Lattice::VertexId> prunedAt;  // vertices whose expansion pruned edges (for the fallback)
    bool pruning = options.zermelo;

    // Holding (TveOptions::waiting): the environment's release times and the goal window.
    const std::vector<double> releases = env && options.waiting ? env->releaseTimes() : std::vector<double>{};
    const double holdStep = ctx.holdTimeStep();
    const bool goalWindow =
        !ignoreGoalWindow_ && (std::isfinite(ctx.arriveNotBefore) || std::isfinite(ctx.arriveNotAfter));
    goalHoldUntil_ = -kInf;

    // Examines the edge u -> v leaving at du (one CFC): true when its travel time is finite; improves v when the
    // arrival is earlier than d[v], inside the window and free.
    auto relax = [&](Lattice::VertexId u, double ux, double uy, double du, Lattice::VertexId v) -> bool {
        if (!inWater(v))
            return false;
        const double vx = lattice_.x(v), vy = lattice_.y(v);
        double hv = -1.0;  // h(v), when known
        if (bounds)
        {
            // No CFC for an edge whose lower bound cannot improve v, or reach the goal by the deadline, or improve
            // the goal found so far (any arrival at the goal through it is >= d[u] + bound + h(v)).
            const double lb = bounds->edgeLowerBound(u, v);
            if (!(du + lb < dist(v)) || du + lb > tEnd)
            {
                ++res.boundSkips;
                return true;
            }
            const double hb = (*bounds)(v);  // unweighted: a true lower bound (>= Eq. 1's, LatticeHeuristic)
            if (du + lb + hb > tEnd || (dist(g) < kInf && !(du + lb + hb < dist(g))))
            {
                ++res.boundSkips;
                return true;
            }
        }
        auto edgeTime = [&](double dep) {
            if (!edgeCache_)
                return travel.travelTime(ux, uy, vx, vy, dep);
            const auto [it, inserted] = edgeCache_->try_emplace(EdgeKey{u, v, dep}, 0.0);
            if (inserted)
                it->second = travel.travelTime(ux, uy, vx, vy, dep);
            return it->second;
        };
        auto label = [&](double dv, double dep) {
            Label &lv = labels_.ref(v);
            if (lv.d == kInf)
                reached_.push_back(v);
            lv.d = dv;
            lv.pi = u;
            lv.dep = dep;
            if (hv < 0.0)
                hv = h(v);
            if (hv < kInf)  // +inf: the goal cannot be reached from v even with the optimistic bounds
                Q.push({dv + hv, dv, v});
        };
        // holding at u over [du, tw]: |c| < V there (a superset of the motion validator's samples) and u free
        auto canWait = [&](double tw) {
            return ctx.canHold(ux, uy, du, tw, holdStep, 4) && (!env || env->legFree(ux, uy, du, ux, uy, tw));
        };
        const double w = edgeTime(du);
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
                // no hold at the goal: hold at u so that the edge arrives at the window's begin (bisection on the
                // departure; arrival non-decreasing in it, FIFO)
                const double B = ctx.arriveNotBefore;
                if (!(B < dist(v)) || B > tEnd)
                    return true;
                double lo = du, hi = B;
                double hiArr = hi + edgeTime(hi);
                if (!std::isfinite(hiArr))
                    return true;
                for (int it = 0; it < 50 && hiArr > B * (1.0 + 1e-12) + 1e-12; ++it)
                {
                    const double mid = 0.5 * (lo + hi);
                    const double a = mid + edgeTime(mid);
                    if (std::isfinite(a) && a >= B)
                    {
                        hi = mid;
                        hiArr = a;
                    }
                    else
                        lo = mid;
                }
                if (!(hiArr < dist(v)) || hiArr > tEnd || hiArr > ctx.arriveNotAfter || !canWait(hi))
                    return true;
                if (env && (!env->pointFree(vx, vy, hiArr) || !env->legFree(ux, uy, hi, vx, vy, hiArr)))
                    return true;
                label(hiArr, hi);
                return true;
            }
        }
        if (!(dv < dist(v)) || dv > tEnd)
            return true;  // no improvement, or later than the planning window
        if (env && (!env->pointFree(vx, vy, dv) || !env->legFree(ux, uy, du, vx, vy, dv)))
        {
            if (!options.waiting || releases.empty())
                return true;
            // waiting edge: depart just after a release time (the end of a blocking window), the first that frees
            // the leg (later ones arrive no earlier where the field is FIFO)
            for (const double r : releases)
            {
                const double tw = r + 1e-9 * std::max(1.0, std::abs(r));
                if (tw <= du)
                    continue;
                if (tw > tEnd || !(tw < dist(v)) || !canWait(tw))
                    break;  // later departures cannot improve v, or the glider cannot hold that long
                const double ww = edgeTime(tw);
                if (!std::isfinite(ww))
                    continue;
                const double dw = tw + ww;
                if (dw > tEnd || !(dw < dist(v)))
                    break;
                if (env->pointFree(vx, vy, dw) && env->legFree(ux, uy, tw, vx, vy, dw))
                {
                    if (v == g && goalWindow && dw > ctx.arriveNotAfter)
                        break;
                    label(dw, tw);
                    break;
                }
            }
            return true;
        }
        label(dv, -kInf);
        return true;
    };

    // Certification (TveOptions::certifyTolerance): pruned edges are deferred, not dropped, each with the lower
    // bound key = d[u] + (edge bound) + h(v) of the queue key v would get through it (h = the queue's heuristic, 0
    // without A*). A deferred edge is examined as soon as its key, inflated by (1 + tol) from t0, is not above the
    // queue's smallest key, i.e. in key order interleaved with the queue. With tol = 0 and a consistent heuristic
    // (and edge bounds consistent with it) every vertex is extracted with its final label, as in A* without
    // pruning: the search returns the fixpoint d(v) = min_u d(u) + w(u, v, d(u)) that TVE computes (unique for
    // positive edge times), only without the CFC of the deferred edges whose key exceeds the goal's arrival.
    // (The earlier rule examined deferred edges only after the goal's first extraction; a vertex could then be
    // improved after its successors had been labelled from its old arrival time, and the returned arrival could
    // differ from TVE's where the field is not FIFO, e.g. random pair 9 of bench_search, 16 % below TVE's.)
    const bool certify = pruning && options.certifyTolerance >= 0.0;
    const double vAll = ctx.speed() + ctx.maxCurrent();
    if (certify && !(vAll > 0.0 && std::isfinite(vAll)))
        throw Error("TveSearch: certification needs a finite bound of the current speed over the region");
    std::priority_queue<DeferredEdge, std::vector<DeferredEdge>, std::greater<DeferredEdge>> deferred;
    const unsigned checkEvery = std::max(1u, options.checkEvery);
    auto edgeBound = [&](Lattice::VertexId u, Lattice::VertexId v) {
        return bounds ? bounds->edgeLowerBound(u, v)
                      : std::hypot(lattice_.x(v) - lattice_.x(u), lattice_.y(v) - lattice_.y(u)) / vAll;
    };

    auto terminated = [&]() { return terminate && terminate(); };
    if (terminated())
    {
        res.outcome = TveOutcome::Terminated;
        return finish(res);
    }

    Lattice::VertexId found = Lattice::kNone;
    for (;;)
    {
        if (certify && !deferred.empty() &&
            (Q.empty() || t0 + (deferred.top().key - t0) * (1.0 + options.certifyTolerance) <= Q.top().key))
        {
            const DeferredEdge de = deferred.top();
            deferred.pop();
            // stale (u improved and re-expanded since), or cannot improve v even at the bound
            if (de.du != dist(de.u) || !(de.du + edgeBound(de.u, de.v) < dist(de.v)))
                continue;
            ++res.reopenedEdges;
            relax(de.u, lattice_.x(de.u), lattice_.y(de.u), de.du, de.v);
            continue;
        }
        if (Q.empty())
        {
            if (pruning && options.unprunedFallback && !prunedAt.empty())
            {
                // The pruned search could not reach the goal: continue with the full neighbourhoods.
                pruning = false;
                res.fallbackUsed = true;
                for (Lattice::VertexId v : prunedAt)
                {
                    labels_.ref(v).expanded = false;  // expanded again, with every edge
                    if (h(v) < kInf)
                        Q.push({dist(v) + h(v), dist(v), v});
                }
                prunedAt.clear();
                continue;
            }
            break;
        }
        const QueueEntry e = Q.top();
        Q.pop();
        const Lattice::VertexId u = e.v;
        if (e.d != dist(u))
            continue;  // stale entry (u was improved after this push)
        if (u == g)
        {
            found = u;
            break;
        }
        if (!options.reopen)
        {
            Label &lu = labels_.ref(u);
            if (lu.expanded)
                continue;  // expanded once already (TveOptions::reopen)
            lu.expanded = true;
        }
        ++res.expansions;
        if (res.expansions % checkEvery == 0 && terminated())
        {
            res.outcome = TveOutcome::Terminated;
            break;
        }
        const double du = dist(u);
        const double ux = lattice_.x(u), uy = lattice_.y(u);

        std::optional<double> phiOpt;
        double halfWidth = options.deltaPhiMax;
        if (pruning && u != s && parent(u) != Lattice::kNone &&
            !(options.goalRadius > 0.0 && std::hypot(ux - gx, uy - gy) <= options.goalRadius))
        {
            const Lattice::VertexId p = parent(u);
            phiOpt = calcOptimalCourse(lattice_.x(p), lattice_.y(p), dist(p), ux, uy, du, options.zermeloSteps);
            if (phiOpt)
            {
                const double edge = std::atan2(uy - lattice_.y(p), ux - lattice_.x(p));
                const double turn = angleDiff(*phiOpt, edge);
                *phiOpt += options.courseExtrapolation * turn;
                halfWidth = options.deltaPhiMax + options.turnWidening * std::abs(turn);
                if (std::abs(turn) > options.reliableTurn)
                    phiOpt.reset();  // unreliable prediction: examine every successor
            }
        }
        bool prunedHere = false;
        bool feasibleInCone = false;  // some examined edge had a finite travel time
        // pass 0: the cone around phi_opt (everything without pruning); pass 1: the rest, only when the cone was a
        // dead end (options.deadEndFallback).
        for (int pass = 0; pass < 2; ++pass)
        {
            if (pass == 1 && (!prunedHere || feasibleInCone || !options.deadEndFallback))
                break;
            lattice_.forEachSuccessor(u, [&](Lattice::VertexId v) {
                if (!(du < dist(v)))
                    return;  // d[u] >= d[v]: the edge cannot improve v ([EichhornRAS] Table 1, difference 2)
                const double vx = lattice_.x(v), vy = lattice_.y(v);
                const bool inCone = !phiOpt || (options.neverPruneGoal && v == g) ||
                                    std::abs(angleDiff(*phiOpt, std::atan2(vy - uy, vx - ux))) <= halfWidth;
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

    if (found != Lattice::kNone)
    {
        res.outcome = TveOutcome::Exact;
        if (options.waiting && goalWindow && dist(found) < ctx.arriveNotBefore)
            goalHoldUntil_ = ctx.arriveNotBefore;  // arrived early where the goal can be held: hold there
        res.waypoints = pathTo(found);
        res.travelTime = res.waypoints.back().t - t0;
        return finish(res);
    }
    if (res.outcome == TveOutcome::Terminated)
    {
        // Path to the reached vertex closest to the goal (when it is closer than the start).
        Lattice::VertexId best = Lattice::kNone;
        double bestDist = std::hypot(sx - gx, sy - gy);
        for (Lattice::VertexId v : reached_)
        {
            const double dist = std::hypot(lattice_.x(v) - gx, lattice_.y(v) - gy);
            if (dist < bestDist)
            {
                bestDist = dist;
                best = v;
            }
        }
        if (best != Lattice::kNone)
            res.waypoints = pathTo(best);
        return finish(res);
    }
    res.outcome = TveOutcome::Exhausted;
    return finish(res);
}

std::vector<TimedPoint> TveSearch::pathTo(Lattice::VertexId v) const
{
    std::vector<TimedPoint> out;
    if (v == lattice_.goal() && goalHoldUntil_ > dist(v))
        out.push_back({lattice_.x(v), lattice_.y(v), goalHoldUntil_});  // hold at the goal (goal window)
    for (Lattice::VertexId w = v; w != Lattice::kNone; w = parent(w))
    {
        out.push_back({lattice_.x(w), lattice_.y(w), dist(w)});
        const Label &lw = labels_.get(w);
        if (lw.pi != Lattice::kNone && lw.dep > dist(lw.pi))
            out.push_back({lattice_.x(lw.pi), lattice_.y(lw.pi), lw.dep});  // a hold
        if (out.size() > 2 * reached_.size() + 2)
            throw Error("TveSearch: predecessor cycle (internal error)");
    }
    std::reverse(out.begin(), out.end());
    return out;
}

std::vector<TveTreeVertex> TveSearch::tree() const
{
    std::vector<TveTreeVertex> out;
    out.reserve(reached_.size());
    for (Lattice::VertexId v : reached_)
        out.push_back({v, parent(v), lattice_.x(v), lattice_.y(v), dist(v)});
    return out;
}
}  // namespace ompl_glider

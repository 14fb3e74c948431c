/// @file TveSearch.cpp
/// @brief TveSearch's runs around its single search (TveSearchCore.cpp): the goal-window fallback (run()), the two
/// phases of greedyDeadline (runPhases()) and coarse-to-fine (runCoarseToFine()); CALC-OPTDIR (calcOptimalCourse());
/// the path and the tree of a search.

#include "TveSearch.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
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

/// The lattice over a checked context's region (the context is checked before any member reads it).
Lattice latticeOf(const GliderContext &ctx, double gridSize, unsigned sectors)
{
    return Lattice(ctx.region.xMin, ctx.region.xMax, ctx.region.yMin, ctx.region.yMax, gridSize, sectors);
}
} // namespace

TveSearch::TveSearch(std::shared_ptr<const GliderContext> ctx, double gridSize, unsigned sectors)
    : ctx_(std::move(ctx)), lattice_(latticeOf(checkedContext(ctx_), gridSize, sectors))
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
    const bool coarseToFine = std::isnan(options.deadline) &&
                              (options.coarseFactor > 1 || (options.coarseFactor == 0 && options.heuristic &&
                                                            lattice_.numGridVertices() > (std::size_t{1} << 19)));
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
        ~Scope() { s.ignoreGoalWindow_ = false; }
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

/// Sets the counters of into to those of r.
void copyCounts(TveResult &into, const TveResult &r)
{
    into.costFunctionCalls = r.costFunctionCalls;
    into.currentModelCalls = r.currentModelCalls;
    into.expansions = r.expansions;
    into.prunedEdges = r.prunedEdges;
    into.reopenedEdges = r.reopenedEdges;
    into.boundSkips = r.boundSkips;
    into.heuristicSettled = r.heuristicSettled;
}

/// Blocks of f x f lattice cells (coarse-to-fine, TveOptions::coarseFactor) with the Chebyshev distance of each, in
/// blocks, from the blocks a coarse path crosses.
struct BlockRings
{
    long f{1};             ///< cells per block side
    long nx{0}, ny{0};     ///< blocks per row and per column
    std::vector<int> ring; ///< distance per block (row-major)
    int maxRing{0};        ///< the largest distance
};

/// The blocks of @p lattice and their distance from @p path (multi-source breadth-first search with 8 neighbours;
/// the path's legs sampled at a quarter of a block).
BlockRings pathRings(const Lattice &lattice, long f, const std::vector<TimedPoint> &path)
{
    BlockRings br;
    br.f = f;
    br.nx = (lattice.nx() + f - 1) / f;
    br.ny = (lattice.ny() + f - 1) / f;
    const long NX = br.nx, NY = br.ny;
    const double bs = lattice.gridSize() * static_cast<double>(f);
    std::vector<int> &ring = br.ring;
    ring.assign(static_cast<std::size_t>(NX * NY), -1);
    std::vector<long> frontier;
    auto mark = [&](double x, double y) {
        const long I = std::clamp(static_cast<long>(std::floor((x - lattice.xMin()) / bs)), 0L, NX - 1);
        const long J = std::clamp(static_cast<long>(std::floor((y - lattice.yMin()) / bs)), 0L, NY - 1);
        const long b = I + J * NX;
        if (ring[static_cast<std::size_t>(b)] < 0)
        {
            ring[static_cast<std::size_t>(b)] = 0;
            frontier.push_back(b);
        }
    };
    for (std::size_t k = 0; k < path.size(); ++k)
    {
        const TimedPoint &a = path[k];
        mark(a.x, a.y);
        if (k + 1 == path.size())
            break;
        const TimedPoint &b = path[k + 1];
        const int n = static_cast<int>(std::ceil(4.0 * std::hypot(b.x - a.x, b.y - a.y) / bs));
        for (int i = 1; i < n; ++i)
            mark(a.x + (b.x - a.x) * i / n, a.y + (b.y - a.y) * i / n);
    }
    for (std::size_t head = 0; head < frontier.size(); ++head)
    {
        const long b = frontier[head], I = b % NX, J = b / NX;
        const int d = ring[static_cast<std::size_t>(b)];
        br.maxRing = std::max(br.maxRing, d);
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
    return br;
}

/// Whether a lattice vertex of @p path lies in a block at distance >= w (the outermost ring of a corridor of
/// half-width w).
bool entersRing(const Lattice &lattice, const BlockRings &br, int w, const std::vector<TimedPoint> &path)
{
    for (const TimedPoint &p : path)
    {
        const long i = std::lround((p.x - lattice.xMin()) / lattice.gridSize());
        const long j = std::lround((p.y - lattice.yMin()) / lattice.gridSize());
        if (i < 0 || j < 0 || i >= lattice.nx() || j >= lattice.ny())
            continue;
        if (br.ring[static_cast<std::size_t>(i / br.f + (j / br.f) * br.nx)] >= w)
            return true;
    }
    return false;
}
} // namespace

TveResult TveSearch::runCoarseToFine(double sx, double sy, double t0, double gx, double gy, const TveOptions &options,
                                     const std::function<bool()> &terminate)
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

    // 2. Chebyshev distance, in blocks of f x f cells, of every block from the blocks the coarse path crosses.
    const BlockRings rings = pathRings(lattice_, f, coarse.waypoints);

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
    corridorNX_ = rings.nx;
    TveResult total = coarse;
    total.waypoints.clear();
    unsigned rounds = 0;
    for (int w = std::max(1, static_cast<int>(options.corridorBlocks));; w = 2 * w)
    {
        const bool whole = w >= rings.maxRing;
        corridor_.clear();
        if (!whole)
        {
            corridor_.resize(rings.ring.size());
            for (std::size_t b = 0; b < rings.ring.size(); ++b)
                corridor_[b] = rings.ring[b] <= w ? 1 : 0;
        }
        TveResult r = runPhases(sx, sy, t0, gx, gy, single, terminate);
        addCounts(total, r);
        copyCounts(r, total);
        r.corridorRounds = ++rounds;
        r.corridorBlocks = static_cast<unsigned>(w);
        if (whole || r.outcome == TveOutcome::Terminated || r.outcome == TveOutcome::InvalidStart ||
            r.outcome == TveOutcome::InvalidGoal)
            return r;
        if (r.outcome == TveOutcome::Exact && !entersRing(lattice_, rings, w, r.waypoints))
            return r;
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
        edgeCache_ = &cache; // (coarse-to-fine shares its own between the corridor rounds)
    const auto add = addCounts;
    TveOptions greedy = options;
    greedy.greedyDeadline = false;
    greedy.zermelo = true;
    greedy.certifyTolerance = -1.0;
    greedy.heuristicWeight = options.greedyWeight;
    greedy.reopen = false; // any arrival serves as the deadline; reopening could cost far more than it gains
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
        return first; // invalid start/goal, or terminated
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

std::vector<TimedPoint> TveSearch::pathTo(Lattice::VertexId v) const
{
    std::vector<TimedPoint> out;
    if (v == lattice_.goal() && goalHoldUntil_ > dist(v))
        out.push_back({lattice_.x(v), lattice_.y(v), goalHoldUntil_}); // hold at the goal (goal window)
    for (Lattice::VertexId w = v; w != Lattice::kNone; w = parent(w))
    {
        out.push_back({lattice_.x(w), lattice_.y(w), dist(w)});
        const Label &lw = labels_.get(w);
        if (lw.pi != Lattice::kNone && lw.dep > dist(lw.pi))
            out.push_back({lattice_.x(lw.pi), lattice_.y(lw.pi), lw.dep}); // a hold
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
} // namespace ompl_glider

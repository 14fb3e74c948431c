#include "ompl_glider/routes/WaypointRefiner.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ompl_glider/Exception.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

/// Search state shared by the phases of one refinement.
struct Search
{
    const GliderContext &ctx;
    double t0;
    unsigned budget;
    double bumpFraction{0.0};
    const std::function<bool()> *terminate{nullptr};
    unsigned evaluations{0};
    unsigned accepted{0};

    bool exhausted() const { return evaluations >= budget || (terminate && *terminate && (*terminate)()); }

    double cost(const std::vector<TimedPoint> &wp)
    {
        ++evaluations;
        return arrivalTime(ctx, wp, t0);
    }

    /// Arrival times at waypoints k + 1 ... computed by the last costFrom() (scratch, reused between calls).
    std::vector<double> times{};

    /// Arrival at the goal when the path is flown from waypoint k, reached at time tk (the legs before k are
    /// unchanged, so their times are reused). Stores the arrival at each waypoint j > k in times[j] (up to the
    /// first infinite one).
    double costFrom(const std::vector<TimedPoint> &wp, std::size_t k, double tk)
    {
        ++evaluations;
        times.resize(wp.size());
        double t = tk;
        for (std::size_t j = k + 1; j < wp.size() && std::isfinite(t); ++j)
        {
            t += legTravelTime(ctx, wp[j - 1].x, wp[j - 1].y, wp[j].x, wp[j].y, t);
            times[j] = t;
        }
        return t;
    }

    bool inBounds(double x, double y) const
    {
        const Region &r = ctx.region;
        return x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax;
    }

    /// Moves waypoint i by (dx, dy) and its neighbours within radius (interior only) by the same vector scaled
    /// by 1 - |j - i| / (radius + 1); keeps the move iff the arrival gets strictly earlier. timed holds the
    /// arrival times of wp and is updated on acceptance.
    bool tryMove(std::vector<TimedPoint> &wp, std::vector<TimedPoint> &timed, double &best, std::size_t i,
                 std::size_t radius, double dx, double dy)
    {
        const std::size_t n = wp.size();
        const std::size_t lo = i > radius ? std::max<std::size_t>(1, i - radius) : 1;
        const std::size_t hi = std::min(n - 2, i + radius);
        const std::vector<TimedPoint> keep(wp.begin() + lo, wp.begin() + hi + 1);
        bool inside = true;
        for (std::size_t j = lo; j <= hi; ++j)
        {
            const double dist = j > i ? double(j - i) : double(i - j);
            const double w = 1.0 - dist / double(radius + 1);
            wp[j].x += w * dx;
            wp[j].y += w * dy;
            inside = inside && inBounds(wp[j].x, wp[j].y);
        }
        if (inside)
        {
            const double c = costFrom(wp, lo - 1, timed[lo - 1].t);
            if (c < best)
            {
                best = c;
                ++accepted;
                // c is finite, so costFrom timed every leg from lo on: reuse its times instead of flying the
                // legs again (the same operations, hence the same values, without their CFC).
                for (std::size_t j = lo; j < n; ++j)
                    timed[j].t = times[j];
                return true;
            }
        }
        std::copy(keep.begin(), keep.end(), wp.begin() + lo);
        return false;
    }

    /// Compass search on the interior waypoints; wp and best are updated in place.
    void pattern(std::vector<TimedPoint> &wp, double &best, double s0, double sMin)
    {
        const std::size_t n = wp.size();
        if (n < 3)
            return;
        std::vector<double> step(n, s0);
        const double sMax = 4.0 * s0;
        const std::size_t bumpRadius = bumpFraction > 0.0 ? static_cast<std::size_t>(bumpFraction * double(n)) : 0;
        std::vector<TimedPoint> timed = retimeWaypoints(ctx, wp, t0); // arrival times of the current path
        while (!exhausted())
        {
            bool active = false;
            for (std::size_t i = 1; i + 1 < n && !exhausted(); ++i)
            {
                if (step[i] < sMin)
                    continue;
                active = true;
                // Local frame: along the chord of the neighbours and across it.
                double tx = wp[i + 1].x - wp[i - 1].x, ty = wp[i + 1].y - wp[i - 1].y;
                const double tl = std::hypot(tx, ty);
                if (tl > 0.0)
                {
                    tx /= tl;
                    ty /= tl;
                }
                else
                {
                    tx = 1.0;
                    ty = 0.0;
                }
                const double dirs[4][2] = {{-ty, tx}, {ty, -tx}, {tx, ty}, {-tx, -ty}};
                bool improved = false;
                for (const auto &d : dirs)
                {
                    if (tryMove(wp, timed, best, i, 0, step[i] * d[0], step[i] * d[1]))
                    {
                        improved = true;
                        break;
                    }
                    if (exhausted())
                        break;
                }
                // A single waypoint cannot move a whole stretch of path without kinks: try a bump of the
                // neighbours too (weights falling linearly to zero at bumpRadius + 1 waypoints away).
                for (int sgn = 1; !improved && bumpRadius > 0 && sgn >= -1 && !exhausted(); sgn -= 2)
                    improved =
                        tryMove(wp, timed, best, i, bumpRadius, sgn * step[i] * dirs[0][0], sgn * step[i] * dirs[0][1]);
                step[i] = improved ? std::min(sMax, 2.0 * step[i]) : 0.5 * step[i];
            }
            if (!active)
                break;
        }
    }

    /// Drops interior waypoints whose removal does not make the arrival later.
    void dropRedundant(std::vector<TimedPoint> &wp, double &best)
    {
        for (std::size_t i = 1; i + 1 < wp.size() && !exhausted();)
        {
            std::vector<TimedPoint> cand = wp;
            cand.erase(cand.begin() + static_cast<std::ptrdiff_t>(i));
            const double c = cost(cand);
            if (c <= best)
            {
                best = c;
                wp = std::move(cand);
                ++accepted;
            }
            else
                ++i;
        }
    }
};

double meanLeg(const std::vector<TimedPoint> &wp)
{
    return wp.size() > 1 ? pathLength(wp) / static_cast<double>(wp.size() - 1) : 0.0;
}
} // namespace

WaypointRefiner::WaypointRefiner(std::shared_ptr<const GliderContext> ctx, RefinerParams params)
    : ctx_(std::move(ctx)), params_(params)
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("WaypointRefiner: the GliderContext must be non-null with a field and a travel-time calculator");
    if (params_.maxEvaluations == 0)
        throw Error("WaypointRefiner: maxEvaluations must be > 0");
    if (!std::isfinite(params_.initialStep) || !std::isfinite(params_.minStep))
        throw Error("WaypointRefiner: initialStep and minStep must be finite");
    if (!(params_.minRelativeGain >= 0.0))
        throw Error("WaypointRefiner: minRelativeGain must be >= 0");
}

RefinementResult WaypointRefiner::refine(const std::vector<TimedPoint> &input) const
{
    if (input.empty())
        return {};
    if (lastHoldEnd(input) > 0)
    {
        // a path that holds position: refine its hold-free pieces, keep the holds (improveAroundHolds())
        const std::uint64_t cfcH = ctx_->travel->costFunctionCalls();
        RefinementResult res;
        res.waypointsBefore = input.size();
        res.arrivalBefore = input.back().t;
        res.waypoints = improveAroundHolds(*ctx_, input, [&](const std::vector<TimedPoint> &piece) {
            RefinementResult r = refine(piece);
            res.evaluations += r.evaluations;
            res.acceptedMoves += r.acceptedMoves;
            return std::isfinite(r.arrivalAfter) && r.arrivalAfter <= piece.back().t ? r.waypoints : piece;
        });
        res.waypointsAfter = res.waypoints.size();
        res.arrivalAfter = res.waypoints.back().t;
        res.costFunctionCalls = ctx_->travel->costFunctionCalls() - cfcH;
        return res;
    }
    const double t0 = input.front().t; // the departure
    const GliderContext &ctx = *ctx_;
    const std::uint64_t cfc0 = ctx.travel->costFunctionCalls();
    RefinementResult res;
    res.waypointsBefore = input.size();
    std::vector<TimedPoint> wp = input;
    Search s{ctx, t0, params_.maxEvaluations, params_.bumpFraction, &params_.terminate};
    double best = s.cost(wp);
    res.arrivalBefore = best;
    if (wp.size() >= 2 && std::isfinite(best))
    {
        const double len = pathLength(wp);
        const double sMin = params_.minStep > 0.0 ? params_.minStep : 1e-4 * len;
        auto s0For = [&](const std::vector<TimedPoint> &w) {
            return params_.initialStep > 0.0 ? params_.initialStep : 0.25 * meanLeg(w);
        };
        s.dropRedundant(wp, best);
        s.pattern(wp, best, s0For(wp), sMin);
        for (unsigned round = 0; round < params_.insertionRounds && !s.exhausted(); ++round)
        {
            if (2 * wp.size() - 1 > params_.maxWaypoints)
                break;
            std::vector<TimedPoint> cand;
            const double splitAbove = params_.splitFraction * meanLeg(wp);
            for (std::size_t i = 0; i < wp.size(); ++i)
            {
                if (i > 0 && std::hypot(wp[i].x - wp[i - 1].x, wp[i].y - wp[i - 1].y) > splitAbove)
                    cand.push_back({0.5 * (wp[i - 1].x + wp[i].x), 0.5 * (wp[i - 1].y + wp[i].y), 0.0});
                cand.push_back(wp[i]);
            }
            if (cand.size() == wp.size())
                break;
            double cBest = s.cost(cand);
            if (!std::isfinite(cBest))
                break;
            s.pattern(cand, cBest, s0For(cand), sMin);
            if (cBest < best && best - cBest >= params_.minRelativeGain * (best - t0))
            {
                wp = std::move(cand);
                best = cBest;
                ++s.accepted;
            }
            else
                break; // gain too small for twice the waypoints: keep the shorter list
        }
        s.dropRedundant(wp, best);
    }
    res.waypoints = retimeWaypoints(ctx, wp, t0);
    res.waypointsAfter = res.waypoints.size();
    res.arrivalAfter = res.waypoints.back().t;
    if (!(res.arrivalAfter <= res.arrivalBefore)) // cannot happen with a deterministic travel-time code
    {
        res.waypoints = retimeWaypoints(ctx, input, t0);
        res.waypointsAfter = input.size();
        res.arrivalAfter = res.arrivalBefore;
    }
    res.evaluations = s.evaluations;
    res.acceptedMoves = s.accepted;
    res.costFunctionCalls = ctx.travel->costFunctionCalls() - cfc0;
    return res;
}

RefinementResult WaypointRefiner::refine(ompl::geometric::PathGeometric &path) const
{
    const std::vector<TimedPoint> in = waypointsFromPath(path);
    if (in.empty())
        return {};
    RefinementResult res = refine(in);
    if (std::isfinite(res.arrivalAfter) && res.arrivalAfter <= in.back().t)
        waypointsToPath(res.waypoints, path);
    else
    {
        res.waypoints = in;
        res.waypointsAfter = in.size();
        res.arrivalAfter = in.back().t;
    }
    return res;
}
} // namespace ompl_glider

#include "ompl_glider/routes/PathSmoother.h"

#include <cmath>
#include <limits>

#include <ompl/base/SpaceInformation.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

const TimeSE2StateSpace &timeSpace(const ompl::geometric::PathGeometric &path, const char *who)
{
    const auto *space = dynamic_cast<const TimeSE2StateSpace *>(path.getSpaceInformation()->getStateSpace().get());
    if (!space)
        throw Error(std::string(who) + ": the path's state space is not an ompl_glider::TimeSE2StateSpace");
    return *space;
}
} // namespace

double legTravelTime(const GliderContext &ctx, double x1, double y1, double x2, double y2, double tStart)
{
    const double tt = ctx.travel->travelTime(x1, y1, x2, y2, tStart);
    if (!std::isfinite(tt))
        return kInf;
    if (tStart + tt > ctx.region.tMax)
        return kInf;
    if (ctx.environment && !ctx.environment->legFree(x1, y1, tStart, x2, y2, tStart + tt))
        return kInf;
    return tt;
}

std::vector<TimedPoint> retimeWaypoints(const GliderContext &ctx, std::vector<TimedPoint> waypoints, double t0)
{
    if (waypoints.empty())
        return waypoints;
    waypoints[0].t = t0;
    for (std::size_t i = 1; i < waypoints.size(); ++i)
    {
        const double tPrev = waypoints[i - 1].t;
        waypoints[i].t = std::isfinite(tPrev) ? tPrev + legTravelTime(ctx, waypoints[i - 1].x, waypoints[i - 1].y,
                                                                      waypoints[i].x, waypoints[i].y, tPrev)
                                              : kInf;
    }
    return waypoints;
}

double arrivalTime(const GliderContext &ctx, const std::vector<TimedPoint> &waypoints, double t0)
{
    double t = t0;
    for (std::size_t i = 1; i < waypoints.size() && std::isfinite(t); ++i)
        t += legTravelTime(ctx, waypoints[i - 1].x, waypoints[i - 1].y, waypoints[i].x, waypoints[i].y, t);
    return t;
}

double pathLength(const std::vector<TimedPoint> &waypoints)
{
    double len = 0.0;
    for (std::size_t i = 1; i < waypoints.size(); ++i)
        len += std::hypot(waypoints[i].x - waypoints[i - 1].x, waypoints[i].y - waypoints[i - 1].y);
    return len;
}

std::vector<TimedPoint> waypointsFromPath(const ompl::geometric::PathGeometric &path)
{
    timeSpace(path, "waypointsFromPath");
    std::vector<TimedPoint> out;
    out.reserve(path.getStateCount());
    for (std::size_t i = 0; i < path.getStateCount(); ++i)
    {
        const auto *s = path.getState(i)->as<TimeSE2StateSpace::StateType>();
        out.push_back({s->getX(), s->getY(), s->getTime()});
    }
    return out;
}

std::size_t lastHoldEnd(const std::vector<TimedPoint> &w)
{
    for (std::size_t k = w.size(); k-- > 1;)
        if (w[k].x == w[k - 1].x && w[k].y == w[k - 1].y && w[k].t > w[k - 1].t)
            return k;
    return 0;
}

std::vector<TimedPoint> improveAroundHolds(
    const GliderContext &ctx, const std::vector<TimedPoint> &w,
    const std::function<std::vector<TimedPoint>(const std::vector<TimedPoint> &)> &improve)
{
    const std::size_t k = lastHoldEnd(w);
    if (k == 0)
        return improve(w);
    if (k + 1 < w.size())
    {
        // the piece after the last hold, departing at the hold's end
        std::vector<TimedPoint> out(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(k));
        const std::vector<TimedPoint> tail = improve({w.begin() + static_cast<std::ptrdiff_t>(k), w.end()});
        out.insert(out.end(), tail.begin(), tail.end());
        return out;
    }
    // the path ends with a hold: improve the part before it, then hold from its new arrival to the old end
    const std::vector<TimedPoint> head(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(k));
    std::vector<TimedPoint> better = improveAroundHolds(ctx, head, improve);
    const TimedPoint &end = w.back();
    const double arrival = better.back().t;
    if (!(arrival <= head.back().t) || !ctx.canHold(end.x, end.y, arrival, end.t, ctx.holdTimeStep(), 4) ||
        (ctx.environment && !ctx.environment->legFree(end.x, end.y, arrival, end.x, end.y, end.t)))
        return w;
    better.push_back(end);
    return better;
}

void waypointsToPath(const std::vector<TimedPoint> &waypoints, ompl::geometric::PathGeometric &path)
{
    const TimeSE2StateSpace &space = timeSpace(path, "waypointsToPath");
    const auto &si = path.getSpaceInformation();
    path.clear();
    ompl::base::State *st = si->allocState();
    auto *s = st->as<TimeSE2StateSpace::StateType>();
    for (std::size_t i = 0; i < waypoints.size(); ++i)
    {
        const std::size_t a = i == 0 ? 0 : i - 1, b = i == 0 ? std::min<std::size_t>(1, waypoints.size() - 1) : i;
        const double dx = waypoints[b].x - waypoints[a].x, dy = waypoints[b].y - waypoints[a].y;
        s->setXYT(waypoints[i].x, waypoints[i].y, waypoints[i].t);
        s->setYaw(dx == 0.0 && dy == 0.0 ? 0.0 : std::atan2(dy, dx));
        space.enforceBounds(st);
        // enforceBounds may only wrap the yaw: positions and times are kept as given.
        s->setXYT(waypoints[i].x, waypoints[i].y, waypoints[i].t);
        path.append(st);
    }
    si->freeState(st);
}

std::vector<TimedPoint> mergeKeepingSchedule(const GliderContext &ctx, const std::vector<TimedPoint> &timed)
{
    if (timed.size() <= 2)
        return timed;
    auto flyable = [&](const TimedPoint &a, const TimedPoint &b) {
        const double dur = b.t - a.t;
        if (!(dur > 0.0) || !std::isfinite(dur) || b.t > ctx.region.tMax)
            return false;
        if (a.x == b.x && a.y == b.y)
            return false; // a hold: keep it as it is
        const ArrivalWindow w = ctx.travel->arrivalWindow(a.x, a.y, b.x, b.y, a.t);
        if (!(std::isfinite(w.earliest) && w.earliest * (1.0 - 1e-9) <= dur && dur <= w.latest * (1.0 + 1e-9)))
            return false;
        return !ctx.environment || ctx.environment->legFree(a.x, a.y, a.t, b.x, b.y, b.t);
    };
    std::vector<TimedPoint> out{timed.front()};
    std::size_t i = 0;
    while (i + 1 < timed.size())
    {
        std::size_t j = timed.size() - 1;
        while (j > i + 1 && !flyable(timed[i], timed[j]))
            --j;
        out.push_back(timed[j]);
        i = j;
    }
    return out;
}

namespace
{
/// Arrival a is no later than b up to the relative rounding tolerance kSmoothingTieTolerance (exact ties, e.g.
/// collinear legs in a uniform current, differ by a few ulps between the merged leg and the legs it replaces).
bool noLater(double a, double b)
{
    return a <= b + kSmoothingTieTolerance * std::fabs(b);
}
} // namespace

PathSmoother::PathSmoother(std::shared_ptr<const GliderContext> ctx) : ctx_(std::move(ctx))
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("PathSmoother: the GliderContext must be non-null with a field and a travel-time calculator");
}

SmoothingResult PathSmoother::smooth(const std::vector<TimedPoint> &input) const
{
    if (input.empty())
        return {};
    if (lastHoldEnd(input) > 0)
    {
        // a path that holds position: smooth its hold-free pieces, keep the holds (improveAroundHolds())
        const std::uint64_t cfcH = ctx_->travel->costFunctionCalls();
        SmoothingResult res;
        res.waypointsBefore = input.size();
        res.arrivalBefore = input.back().t;
        res.waypoints = improveAroundHolds(*ctx_, input, [&](const std::vector<TimedPoint> &piece) {
            SmoothingResult r = smooth(piece);
            return std::isfinite(r.arrivalAfter) && r.arrivalAfter <= piece.back().t ? r.waypoints : piece;
        });
        res.waypointsAfter = res.waypoints.size();
        res.arrivalAfter = res.waypoints.back().t;
        res.passes = 1;
        res.costFunctionCalls = ctx_->travel->costFunctionCalls() - cfcH;
        return res;
    }
    const double t0 = input.front().t; // the departure
    const GliderContext &ctx = *ctx_;
    const std::uint64_t cfc0 = ctx.travel->costFunctionCalls();
    SmoothingResult res;
    res.waypointsBefore = input.size();
    std::vector<TimedPoint> wp = retimeWaypoints(ctx, input, t0);
    res.arrivalBefore = wp.back().t;
    double best = res.arrivalBefore; // arrival at the goal of the current candidate path (TT[end])
    if (wp.size() > 2 && std::isfinite(best))
    {
        auto leg = [&](const TimedPoint &a, const TimedPoint &b, double t) {
            return legTravelTime(ctx, a.x, a.y, b.x, b.y, t);
        };
        while (wp.size() > 2) // loop I
        {
            ++res.passes;
            const std::size_t n = wp.size();
            std::vector<TimedPoint> out{wp[0]};
            std::size_t iStart = 0;
            double t1 = wp[1].t - wp[0].t; // time from WP[i_start] to WP[i_path - 1] along the candidate path
            for (std::size_t iPath = 2; iPath < n; ++iPath) // loop II
            {
                const double tS = wp[iStart].t;
                const double t2 = leg(wp[iPath - 1], wp[iPath], tS + t1);
                const double tSum = leg(wp[iStart], wp[iPath], tS);                   // III
                bool merge = std::isfinite(tSum) && noLater(tS + tSum, tS + t1 + t2); // III, IV
                if (merge)
                {
                    // V: the rest of the path from the merged arrival must reach the goal no later.
                    double tEnd = tS + tSum;
                    for (std::size_t k = iPath + 1; k < n && std::isfinite(tEnd); ++k)
                        tEnd += leg(wp[k - 1], wp[k], tEnd);
                    if (noLater(tEnd, best))
                        best = std::min(best, tEnd); // the minimum: the tolerance never accumulates
                    else
                        merge = false;
                }
                if (merge)
                {
                    t1 = tSum;
                    wp[iPath].t = tS + tSum;
                }
                else
                {
                    wp[iPath - 1].t = tS + t1; // VI: keep WP[i_path - 1], merging restarts there
                    wp[iPath].t = tS + t1 + t2;
                    iStart = iPath - 1;
                    t1 = t2;
                    out.push_back(wp[iStart]);
                }
            }
            out.push_back(wp[n - 1]);
            out = retimeWaypoints(ctx, out, t0);
            const bool changed = out.size() != wp.size();
            // Guard (cannot trigger unless the travel-time code is non-deterministic): never accept a later path.
            if (!noLater(out.back().t, res.arrivalBefore))
                break;
            wp = std::move(out);
            if (!changed)
                break;
        }
    }
    res.waypoints = std::move(wp);
    res.waypointsAfter = res.waypoints.size();
    res.arrivalAfter = res.waypoints.back().t;
    res.costFunctionCalls = ctx.travel->costFunctionCalls() - cfc0;
    return res;
}

SmoothingResult PathSmoother::smooth(ompl::geometric::PathGeometric &path) const
{
    const std::vector<TimedPoint> in = waypointsFromPath(path);
    if (in.empty())
        return {};
    const std::uint64_t cfc0 = ctx_->travel->costFunctionCalls();
    SmoothingResult res = smooth(in);
    if (std::isfinite(res.arrivalAfter) && noLater(res.arrivalAfter, in.back().t))
    {
        waypointsToPath(res.waypoints, path);
        return res;
    }
    // The waypoints cannot be flown at full speed from the departure (the path waits or flies slow legs): merge
    // keeping the schedule, then try full speed on the fewer waypoints.
    const std::vector<TimedPoint> merged = mergeKeepingSchedule(*ctx_, in);
    SmoothingResult fast = smooth(merged); // merged.front() is in.front()
    if (std::isfinite(fast.arrivalAfter) && noLater(fast.arrivalAfter, in.back().t))
        res = fast;
    else
    {
        res.waypoints = merged;
        res.waypointsAfter = merged.size();
        res.arrivalAfter = in.back().t;
    }
    res.waypointsBefore = in.size();
    res.arrivalBefore = in.back().t;
    res.costFunctionCalls = ctx_->travel->costFunctionCalls() - cfc0;
    if (res.waypointsAfter != in.size() || res.arrivalAfter < in.back().t)
        waypointsToPath(res.waypoints, path);
    return res;
}
} // namespace ompl_glider

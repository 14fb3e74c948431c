// Flying a plan in a "truth" ocean: headings chosen at each surfacing, held while submerged (see Execution.h).
#include "ompl_glider/execution/Execution.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "ompl_glider/Exception.h"
#include "ompl_glider/execution/Dive.h"
#include "DiveOutcome.h"

namespace ompl_glider
{
std::string controlStrategyName(ControlStrategy s)
{
    switch (s)
    {
    case ControlStrategy::CurrentSensitive:
        return "current_sensitive";
    case ControlStrategy::CurrentBlind:
        return "current_blind";
    case ControlStrategy::Greedy:
        return "greedy";
    case ControlStrategy::Replan:
        return "replan";
    case ControlStrategy::PlannedHeadings:
        return "planned_headings";
    case ControlStrategy::Dac:
        return "dac";
    case ControlStrategy::ReplanObserved:
        return "replan_observed";
    }
    return "unknown";
}

const std::vector<ControlStrategy> &controlStrategies()
{
    static const std::vector<ControlStrategy> all{ControlStrategy::CurrentSensitive, ControlStrategy::CurrentBlind,
                                                  ControlStrategy::Greedy,           ControlStrategy::Replan,
                                                  ControlStrategy::PlannedHeadings,  ControlStrategy::Dac,
                                                  ControlStrategy::ReplanObserved};
    return all;
}

std::optional<ControlStrategy> parseControlStrategy(const std::string &name)
{
    for (ControlStrategy s : controlStrategies())
        if (controlStrategyName(s) == name)
            return s;
    return std::nullopt;
}

void crabHeading(double dx, double dy, Velocity c, double speed, double &hx, double &hy)
{
    // c = along * d + cross * n with n the left normal of d; the heading cancels the cross part
    const double nx = -dy, ny = dx;
    const double cross = c.u * nx + c.v * ny;
    if (std::abs(cross) >= speed)
    {
        hx = -std::copysign(1.0, cross) * nx;
        hy = -std::copysign(1.0, cross) * ny;
        return;
    }
    const double s = -cross / speed, a = std::sqrt(1.0 - s * s);
    hx = a * dx + s * nx;
    hy = a * dy + s * ny;
}

TimedPoint planAt(const std::vector<TimedPoint> &plan, double t)
{
    if (t <= plan.front().t)
        return plan.front();
    for (std::size_t k = 0; k + 1 < plan.size(); ++k)
        if (t <= plan[k + 1].t)
        {
            const TimedPoint &a = plan[k], &b = plan[k + 1];
            const double s = b.t > a.t ? (t - a.t) / (b.t - a.t) : 1.0;
            return {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), t};
        }
    return plan.back();
}

namespace
{
/// The end of the plan's segment active at time t (the first waypoint planned after t; the goal after the plan).
TimedPoint activeWaypoint(const std::vector<TimedPoint> &plan, double t)
{
    for (const TimedPoint &w : plan)
        if (w.t > t)
            return w;
    return plan.back();
}

/// The depth-averaged current of the dive flown over track[from..]: the truth's mean along it (trapezoids in time),
/// with noise, and the forecast's mean along the same points, tagged at the dive's middle.
DacObservation measureDive(const std::vector<TimedPoint> &track, std::size_t from, const CurrentField &truth,
                           const CurrentField &forecast, double depth, double noise, std::mt19937 &rng)
{
    DacObservation d;
    Velocity w, f;
    double span = 0.0;
    for (std::size_t i = from; i + 1 < track.size(); ++i)
    {
        const TimedPoint &a = track[i], &b = track[i + 1];
        const double dt = b.t - a.t;
        if (!(dt > 0.0))
            continue;
        const Velocity wa = truth.velocity(a.x, a.y, depth, a.t), wb = truth.velocity(b.x, b.y, depth, b.t);
        const Velocity fa = forecast.velocity(a.x, a.y, depth, a.t), fb = forecast.velocity(b.x, b.y, depth, b.t);
        w.u += 0.5 * dt * (wa.u + wb.u);
        w.v += 0.5 * dt * (wa.v + wb.v);
        f.u += 0.5 * dt * (fa.u + fb.u);
        f.v += 0.5 * dt * (fa.v + fb.v);
        span += dt;
    }
    const TimedPoint mid =
        planAt(std::vector<TimedPoint>(track.begin() + static_cast<std::ptrdiff_t>(from), track.end()),
               0.5 * (track[from].t + track.back().t));
    d.t = mid.t;
    d.at = {mid.x, mid.y};
    if (span > 0.0)
    {
        d.dac = {w.u / span, w.v / span};
        d.forecast = Velocity{f.u / span, f.v / span};
    }
    if (noise > 0.0)
    {
        std::normal_distribution<double> n(0.0, noise);
        d.dac.u += n(rng);
        d.dac.v += n(rng);
    }
    return d;
}
/// The heading of the dac strategy: at the active waypoint, seen from the fix, aimed off upstream by the drift
/// that the current c gives over the dive of duration dt: the unit vector along w - c dt (w the waypoint relative to
/// the fix), the heading that brings the dive's end nearest the waypoint if the current is c. Far from the waypoint it
/// is nearly the bearing to it (the drift of one dive is a small part of the way); near it, the whole correction.
void aimOffHeading(double wx, double wy, Velocity c, double dt, double &hx, double &hy)
{
    const double ax = wx - c.u * dt, ay = wy - c.v * dt, len = std::hypot(ax, ay);
    const double w = std::hypot(wx, wy);
    if (len > 0.0)
    {
        hx = ax / len;
        hy = ay / len;
    }
    else // the current alone carries the glider to the waypoint: head at it
    {
        hx = wx / w;
        hy = wy / w;
    }
}

/// The forecast corrected by @p measured with @p params (the default of ExecutionOptions::learn).
std::shared_ptr<const CurrentField> correctedForecast(const CurrentField &forecast,
                                                      const std::vector<DacObservation> &measured,
                                                      const CorrectionParams &params)
{
    const std::shared_ptr<const CurrentField> base(std::shared_ptr<const CurrentField>(), &forecast); // not owned
    if (measured.empty())
        return base;
    return std::make_shared<CorrectedField>(base, measured, params);
}

/// The forecast the DAC make, renewed at a surfacing that brought a new one (one solve shared by the steering and
/// the replanning).
class LearnedForecast
{
public:
    LearnedForecast(const CurrentField &forecast, const ExecutionOptions &o) : forecast_(forecast), o_(o) {}

    /// The forecast learned from @p measured (learned again only when a DAC was added since).
    const std::shared_ptr<const CurrentField> &of(const std::vector<DacObservation> &measured)
    {
        if (measured.size() != from_)
        {
            learned_ = o_.learn ? o_.learn(measured) : correctedForecast(forecast_, measured, o_.correction);
            from_ = measured.size();
        }
        return learned_;
    }

private:
    const CurrentField &forecast_;
    const ExecutionOptions &o_;
    std::shared_ptr<const CurrentField> learned_;
    std::size_t from_ = std::numeric_limits<std::size_t>::max();
};

/// Refuses a plan without a waypoint, a speed, surfacing interval or step not positive and finite, and a replanning
/// strategy without its replanner.
void checkFlight(const std::vector<TimedPoint> &plan, double speed, ControlStrategy strategy, const ExecutionOptions &o)
{
    if (plan.empty())
        throw Error("flyPlan: the plan has no waypoint");
    if (!(speed > 0.0) || !std::isfinite(speed))
        throw Error("flyPlan: the speed must be positive and finite");
    if (!(o.surfacingInterval > 0.0) || !std::isfinite(o.surfacingInterval) || !(o.step > 0.0) ||
        !std::isfinite(o.step))
        throw Error("flyPlan: the surfacing interval and the step must be positive and finite");
    if (strategy == ControlStrategy::Replan && (!o.replan || o.replanEvery == 0))
        throw Error("flyPlan: the replan strategy needs a replanner and replanEvery >= 1");
    if (strategy == ControlStrategy::ReplanObserved && (!o.replanObserved || o.replanEvery == 0))
        throw Error("flyPlan: the replan_observed strategy needs an observed replanner and replanEvery >= 1");
}

/// The planned heading at @p t: its segment's, until the segment's end (@p surface brought forward to it: then a
/// surfacing), the last one held after it.
Point2 plannedHeading(const HeadingRoute &headings, double t, double &surface)
{
    double segEnd = headings.departure;
    const HeadingSegment *seg = &headings.segments.back();
    for (const HeadingSegment &h : headings.segments)
    {
        segEnd += std::max(h.duration, 0.0);
        if (t < segEnd - 1e-12 * std::max(1.0, std::abs(segEnd)))
        {
            seg = &h;
            break;
        }
    }
    if (seg != &headings.segments.back() || t < segEnd)
        surface = std::min(surface, segEnd);
    return bearingVector(seg->bearing);
}

/// One dive's settings: the heading held at @p speed with the options' step and depth, toward @p goal within the
/// options' radius (none once @p reached).
DiveSettings diveSettings(double speed, const ExecutionOptions &o, const TimedPoint &goal, bool reached)
{
    DiveSettings ds;
    ds.speed = speed;
    ds.step = o.step;
    ds.depth = o.depth;
    ds.radius = reached ? 0.0 : o.radius;
    ds.goal.x = goal.x;
    ds.goal.y = goal.y;
    return ds;
}
} // namespace

FlownTrack flyPlan(const std::vector<TimedPoint> &plan, double speed, const CurrentField &forecast,
                   const CurrentField &truth, const Environment *forbidden, ControlStrategy strategy,
                   const ExecutionOptions &o)
{
    checkFlight(plan, speed, strategy, o);
    const bool measuring = strategy == ControlStrategy::Dac || strategy == ControlStrategy::ReplanObserved;
    std::mt19937 rng(o.dacSeed);
    FlownTrack r;
    if (measuring)
        r.measured = o.measuredBefore;     // the earlier legs' dives
    std::vector<TimedPoint> active = plan; // the plan flown now (replaced by each new plan)
    LearnedForecast learned(forecast, o);
    const auto learnedNow = [&]() -> const std::shared_ptr<const CurrentField> & { return learned.of(r.measured); };
    unsigned surfacings = 0;
    std::size_t nextRun = 0; // the first of o.replanAt not yet replanned at
    const TimedPoint &goal = plan.back();
    const double t0 = plan.front().t;
    r.plannedArrival = goal.t;
    const double end = std::isfinite(o.endTime) ? o.endTime : t0 + 2.0 * std::max(goal.t - t0, o.surfacingInterval);
    double x = plan.front().x, y = plan.front().y, t = t0;
    r.fixes.push_back({x, y, t});
    r.track.push_back({x, y, t});
    auto distance = [&](double px, double py) { return std::hypot(goal.x - px, goal.y - py); };
    auto reachedNow = [&](double px, double py) { return o.radius > 0.0 && distance(px, py) <= o.radius; };
    if (reachedNow(x, y))
    {
        r.reached = true;
        r.arrivalTime = t;
    }
    // the run's end is met by a dive ending within flyHeading()'s own tolerance of it (a dive's last step may stop a
    // rounding short of its surfacing): a fix there dives no more
    const double endTolerance = 1e-12 * std::max(1.0, std::abs(end));
    while (!r.reached && !r.grounded && t < end - endTolerance)
    {
        // at the surface: a new plan (replanning), then the heading for the next dive
        const bool replanning = strategy == ControlStrategy::Replan || strategy == ControlStrategy::ReplanObserved;
        bool due = replanning && surfacings++ % o.replanEvery == 0;
        for (; replanning && nextRun < o.replanAt.size() && o.replanAt[nextRun] <= t; ++nextRun)
            due = true; // a new forecast run since the last surfacing
        if (due)
        {
            std::vector<TimedPoint> fresh = strategy == ControlStrategy::Replan
                                                ? o.replan(x, y, t, active)
                                                : o.replanObserved(x, y, t, active, learnedNow());
            if (!fresh.empty())
            {
                fresh.back() = {goal.x, goal.y, fresh.back().t};
                active = std::move(fresh);
                ++r.replans;
            }
        }
        const TimedPoint target = strategy == ControlStrategy::Greedy ? goal : activeWaypoint(active, t);
        double dx = target.x - x, dy = target.y - y;
        const double len = std::hypot(dx, dy);
        double hx = 0.0, hy = 0.0;
        double surface = std::min(t + o.surfacingInterval, end);
        if (strategy == ControlStrategy::PlannedHeadings && o.headings && !o.headings->segments.empty())
        {
            const Point2 h = plannedHeading(*o.headings, t, surface);
            hx = h.x;
            hy = h.y;
        }
        else if (len > 0.0)
        {
            dx /= len;
            dy /= len;
            if (strategy == ControlStrategy::Dac && !r.measured.empty()) // the last dive's measured current
                aimOffHeading(target.x - x, target.y - y,
                              o.learnSteersDac ? learnedNow()->velocityOnce(x, y, o.depth, t) : r.measured.back().dac,
                              surface - t, hx, hy);
            else if (strategy == ControlStrategy::ReplanObserved)
                crabHeading(dx, dy, learnedNow()->velocityOnce(x, y, o.depth, t), speed, hx, hy);
            else if (strategy != ControlStrategy::CurrentBlind && strategy != ControlStrategy::Greedy)
                crabHeading(dx, dy, forecast.velocity(x, y, o.depth, t), speed, hx, hy);
            else
            {
                hx = dx;
                hy = dy;
            }
        }
        r.headings.push_back(std::atan2(hy, hx));
        // the dive: the heading held (the one integrator of a dive, Dive.h)
        const DiveSettings ds = diveSettings(speed, o, goal, r.reached);
        const std::size_t diveStart = r.track.size() - 1;
        const DiveEnd dive = flyHeading(x, y, t, hx, hy, surface, truth, forbidden, ds, &r.track);
        if (measuring && r.track.size() > diveStart + 1)
            r.measured.push_back(measureDive(r.track, diveStart, truth, forecast, o.depth, o.dacNoise, rng));
        const bool advanced = dive.t > t;
        x = dive.x;
        y = dive.y;
        t = dive.t;
        noteDiveOutcome(dive, r);
        r.fixes.push_back({x, y, t});
        if (!advanced) // a dive of no time: another would be the same (every surfacing is a fix kept in memory)
            break;
    }
    // the distance to the goal at the planned arrival time, on the flown track
    const TimedPoint at = planAt(r.track, std::min(r.plannedArrival, r.track.back().t));
    r.finalDistance = distance(at.x, at.y);
    const double flown = r.track.back().t - t0;
    r.madeGoodSpeed =
        flown > 0.0 ? std::hypot(r.track.back().x - plan.front().x, r.track.back().y - plan.front().y) / flown : 0.0;
    return r;
}
} // namespace ompl_glider

/// @file MissionLegs.cpp
/// @brief Missions of several legs (MissionLegs.h): the legs planned in turn on one clock, stays held, the whole route
/// assembled, and the free-order search (branch and bound over the via points' orders with planned leg times).

#include "ompl_glider/mission/MissionLegs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "../../io/NumberText.h"
#include "LegPlanner.h"
#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/routes/PathSmoother.h"

namespace ompl_glider
{
namespace
{
using planning_detail::LegPlanner;
using planning_detail::Stops;
using planning_detail::timeText;

/// Why the glider cannot hold at @p p over [t1, t2] (the motion validator's hold test: in water, within the forecast,
/// |c| < V at its samples; no forbidden region there then); empty when it can.
std::string whyNoStay(const MissionProblem &problem, Point2 p, double t1, double t2, double speed)
{
    const double end = problem.getField()->timeEnd();
    if (std::isfinite(end) && t2 > end)
        return "the stay would end at " + timeText(problem, t2) + ", after the forecast ends (" +
               timeText(problem, end) + ")";
    std::shared_ptr<GliderContext> ctx;
    makeSimpleSetup(problem.gliderProblem(t1, speed), &ctx);
    if (ctx->canHold(p.x, p.y, t1, t2, ctx->holdTimeStep()) &&
        (!ctx->environment || ctx->environment->legFree(p.x, p.y, t1, p.x, p.y, t2)))
        return "";
    // the figures: the fastest current met over the stay
    double fastest = 0.0, when = t1;
    const int samples = 256;
    for (int i = 0; i <= samples; ++i)
    {
        const double t = t1 + (t2 - t1) * i / samples;
        const Velocity c = problem.getField()->velocity(p.x, p.y, problem.getSpec().vehicle.depth, t);
        if (std::hypot(c.u, c.v) > fastest)
        {
            fastest = std::hypot(c.u, c.v);
            when = t;
        }
    }
    if (fastest >= speed)
    {
        const bool metres = problem.getSpec().current.isForecast();
        return "the current there reaches " + text::number(fastest, 4) + (metres ? " m/s" : "") + " at " +
               timeText(problem, when) + ", faster than the glider's " + text::number(speed, 4) +
               (metres ? " m/s" : "") + ": it cannot hold position for the stay (a virtual mooring needs |c| < V)";
    }
    return "a forbidden region covers the point during the stay";
}

/// A leg's bad input in the mission's terms: the leg's start or goal is a via point, its departure a time on the
/// mission's clock (only the first leg's is the pilot's).
BadInput legBadInput(const BadInput &badInput, int from, int to, std::size_t n, std::size_t leg)
{
    const auto via = [](int k) { return BadInput{BadInput::Input::ViaPoint, static_cast<std::size_t>(k)}; };
    switch (badInput.input)
    {
    case BadInput::Input::Start:
        return from < 0 ? badInput : via(from);
    case BadInput::Input::Goal:
        return to >= static_cast<int>(n) ? badInput : via(to);
    default: // a later leg's departure after the forecast: no path, not bad input
        return leg == 0 ? badInput : BadInput{};
    }
}

/// Appends @p add to @p to, leaving out a first point at the time of the last one there and within @p gap of it (a
/// heading route ends within its goal tolerance of the via point the next leg leaves from).
void append(std::vector<TimedPoint> &to, const std::vector<TimedPoint> &add, double gap = 0.0)
{
    for (std::size_t i = 0; i < add.size(); ++i)
    {
        if (i == 0 && !to.empty() && to.back().t == add[i].t &&
            std::hypot(to.back().x - add[i].x, to.back().y - add[i].y) <= gap)
            continue;
        to.push_back(add[i]);
    }
}

/// The route of @p legs whose last could not be planned, in @p r: no path, for that leg's cause and the setting it
/// names (the leg's words after its name), with every leg's planning work.
void noteUnsolvedLeg(const MissionProblem &problem, const std::vector<PlannedLeg> &legs, PlannedPath &r)
{
    const MissionSpec &m = problem.getSpec();
    const PlannedLeg &bad = legs.back();
    r.status = bad.plan.status == PlanStatus::ExactSolution ? PlanStatus::NoPath : bad.plan.status;
    r.plannerStatus = bad.plan.plannerStatus;
    // the leg's cause and figures, its words after the leg's name
    const std::string leg = "leg " + std::to_string(bad.index + 1) + ", " + bad.from + " to " + bad.to + ": ";
    NoPath why = bad.plan.noPath;
    why.leg = bad.index + 1;
    why.what = leg + why.what;
    if (bad.plan.badInput.input == BadInput::Input::DepartureTime && bad.index > 0)
        why.what =
            leg + "it would depart at " + timeText(problem, bad.plan.departure) + ", after the end of the forecast";
    r.setNoPath(std::move(why));
    r.badInput =
        legBadInput(bad.plan.badInput, bad.fromVia, bad.toVia < 0 ? static_cast<int>(m.waypoints.size()) : bad.toVia,
                    m.waypoints.size(), bad.index);
    for (const PlannedLeg &l : legs)
        planning_detail::addPlanningWork(r, l.plan);
}

/// The straight line of the mission, in @p r: each leg flown straight in turn from the previous straight leg's
/// arrival (its stay held), its length and travel time (infinite past the end of the forecast).
void noteStraightLine(const MissionProblem &problem, const std::vector<PlannedLeg> &legs, double departure,
                      PlannedPath &r)
{
    double t = departure;
    for (const PlannedLeg &l : legs)
    {
        r.straightLineLength += std::hypot(l.toPoint.x - l.fromPoint.x, l.toPoint.y - l.fromPoint.y);
        if (!std::isfinite(t))
            continue;
        const double end = problem.getField()->timeEnd();
        if (std::isfinite(end) && t >= end)
        {
            t = kInf;
            continue;
        }
        std::shared_ptr<GliderContext> ctx;
        makeSimpleSetup(problem.withLeg(l.fromPoint, l.toPoint, {}).gliderProblem(t, r.speed), &ctx);
        t += legTravelTime(*ctx, l.fromPoint.x, l.fromPoint.y, l.toPoint.x, l.toPoint.y, t) + l.stay;
    }
    r.straightLineTime = std::isfinite(t) ? t - departure - legs.back().stay : kInf;
}

/// The whole route of @p legs (all solved, or the first unsolved one last).
PlannedPath assemble(const MissionProblem &problem, std::vector<PlannedLeg> &legs, double departure)
{
    PlannedPath r;
    r.departure = departure;
    r.speed = legs.front().plan.speed;
    r.planner = legs.front().plan.planner;
    bool all = true, headings = true, anyHeadings = false, stays = false;
    for (const PlannedLeg &l : legs)
    {
        all = all && l.plan.solved;
        headings = headings && l.plan.headingRoute();
        anyHeadings = anyHeadings || l.plan.headingRoute();
        stays = stays || l.stay > 0.0;
    }
    const PlannedLeg &last = legs.back();
    if (!all)
    {
        noteUnsolvedLeg(problem, legs, r);
        return r;
    }
    r.solved = true;
    r.status = last.plan.status;
    r.plannerStatus = last.plan.plannerStatus;
    r.pathChecked = r.reflown = true;
    double rawTime = 0.0, smoothedTime = 0.0;
    for (PlannedLeg &l : legs)
    {
        const PlannedPath &p = l.plan;
        l.firstPoint = r.path.empty() ? 0 : r.path.size() - 1;
        if (!r.path.empty() && r.path.back().t != p.path.front().t)
            l.firstPoint = r.path.size(); // after a stay the leg starts with a hold's end
        const double gap = problem.goalTolerance() + 1e-9 * r.pathLength;
        append(r.path, p.path, gap);
        l.lastPoint = r.path.size() - 1;
        append(r.raw, p.raw, gap);
        append(r.smoothed, p.smoothed, gap);
        if (anyHeadings)
            append(r.track, p.headingRoute() ? p.track : p.path, gap);
        rawTime += p.rawTravelTime;
        smoothedTime += p.smoothedTravelTime;
        r.rawPathLength += p.rawPathLength;
        r.pathLength += p.pathLength;
        planning_detail::addPlanningWork(r, p);
        r.pathChecked = r.pathChecked && p.pathChecked;
        r.reflown = r.reflown && p.reflown;
        if (r.switchedFrom.empty() && !p.switchedFrom.empty())
        {
            r.switchedFrom = p.switchedFrom;
            r.switchReason = "leg " + std::to_string(l.index + 1) + ": " + p.switchReason;
            r.planner = p.planner;
        }
        if (!p.arrivalTiming.empty())
            r.arrivalTiming += (r.arrivalTiming.empty() ? "" : "; ") + std::string("leg ") +
                               std::to_string(l.index + 1) + ": " + p.arrivalTiming;
        if (l.stay > 0.0 && &l != &legs.back())
        {
            TimedPoint hold = r.path.back();
            hold.t += l.stay;
            r.path.push_back(hold); // the stay: a hold, flown as the motion validator's hold
            r.raw.push_back(hold);
            r.smoothed.push_back(hold);
            if (anyHeadings)
                r.track.push_back(hold);
        }
        rawTime += &l != &legs.back() ? l.stay : 0.0;
        smoothedTime += &l != &legs.back() ? l.stay : 0.0;
    }
    if (headings && !stays)
    {
        HeadingRoute h = *legs.front().plan.headings;
        for (std::size_t k = 1; k < legs.size(); ++k)
            for (const HeadingSegment &s : legs[k].plan.headings->segments)
                h.segments.push_back(s);
        r.headings = std::move(h);
    }
    r.travelTime = r.path.back().t - departure;
    r.rawTravelTime = rawTime;
    r.smoothedTravelTime = smoothedTime;
    r.reflownTravelTime = r.reflown ? r.travelTime : std::numeric_limits<double>::quiet_NaN();
    // straight legs end on their via point; a heading route where its re-flight ended
    r.reflownEndDistance = 0.0;
    for (const PlannedLeg &l : legs)
        if (l.plan.headingRoute() && std::isfinite(l.plan.reflownEndDistance))
            r.reflownEndDistance = std::max(r.reflownEndDistance, l.plan.reflownEndDistance);
    r.holdTime = planning_detail::holdTimeOf(r.path);
    noteStraightLine(problem, legs, departure, r);
    return r;
}

} // namespace

namespace planning_detail
{
const PlannedLeg &LegPlanner::leg(int from, int to, double t)
{
    const auto key = std::make_tuple(from, to, t);
    const auto it = cache_.find(key);
    if (it != cache_.end())
        return it->second;
    PlannedLeg l;
    l.from = stops_.name(from);
    l.to = stops_.name(to);
    l.fromVia = from;
    l.toVia = to >= static_cast<int>(stops_.n) ? -1 : to;
    l.fromPoint = stops_.point(from);
    l.toPoint = stops_.point(to);
    l.window = stops_.window(to);
    l.stay = stops_.stay(to);
    const MissionProblem legProblem = problem_.withLeg(l.fromPoint, l.toPoint, l.window);
    l.plan = planRoute(legProblem, t, options_);
    planning_detail::diagnoseNoPath(legProblem, t, l.plan);
    ++planned_;
    return cache_.emplace(key, std::move(l)).first->second;
}

std::string LegPlanner::stayProblem(const PlannedLeg &l) const
{
    if (!(l.stay > 0.0) || !l.plan.solved)
        return "";
    return whyNoStay(problem_, l.toPoint, l.arrival(), l.arrival() + l.stay, l.plan.speed);
}

/// The legs of @p order from @p departure, in turn, until the goal or the first leg without a route (or a stay that
/// cannot be held: that leg is kept, marked unsolved with the reason).
std::vector<PlannedLeg> flyOrder(LegPlanner &planner, const std::vector<std::size_t> &order, double departure)
{
    std::vector<PlannedLeg> legs;
    int from = -1;
    double t = departure;
    for (std::size_t k = 0; k <= order.size(); ++k)
    {
        const int to = k < order.size() ? static_cast<int>(order[k]) : static_cast<int>(planner.stops().n);
        PlannedLeg l = planner.leg(from, to, t);
        l.index = k;
        const std::string why = planner.stayProblem(l);
        if (!why.empty())
        {
            l.plan.solved = false;
            l.plan.status = PlanStatus::NoPath;
            l.plan.setNoPath(
                {NoPathCause::ArrivalWindow,
                 "stay at " + l.to + " for " + planner.stops().problem.getSpec().durationText(l.stay) + ": " + why});
        }
        legs.push_back(std::move(l));
        if (!legs.back().plan.solved)
            break;
        t = legs.back().arrival() + legs.back().stay;
        from = to;
    }
    return legs;
}

} // namespace planning_detail

OptimumReference missionOptimumReference(const MissionProblem &problem, const MissionResult &result)
{
    OptimumReference out;
    double t = result.plan.departure;
    for (const PlannedLeg &l : result.legs)
    {
        const MissionProblem leg = problem.withLeg(l.fromPoint, l.toPoint, {});
        const double bound = l.plan.solved ? 1.2 * l.plan.travelTime + std::max(0.0, l.departure() - t)
                                           : leg.horizon(t, result.plan.speed);
        const OptimumReference r = optimumReference(leg, t, result.plan.speed, bound);
        if (!r.found)
            return OptimumReference{};
        append(out.path, r.path);
        t += r.travelTime;
        if (l.window.set)
            t = std::max(t, l.window.begin);
        if (&l != &result.legs.back())
            t += l.stay;
    }
    out.found = true;
    out.travelTime = t - result.plan.departure;
    return out;
}

MissionPlan planMission(const MissionProblem &problem, double departure, const PlanOptions &options)
{
    const MissionSpec &m = problem.getSpec();
    MissionPlan out;
    if (m.waypoints.empty())
    {
        out.plan = planRoute(problem, departure, options);
        return out;
    }
    if (m.stints.set)
        throw Error(m.place("stints") + ": a mission with via points ('waypoints') is planned leg by leg; the stints "
                                        "section (one stint plan from start to goal) cannot be combined with it");
    planning_detail::LegPlanner planner(problem, options);
    if (m.order == VisitOrder::Free)
        out.orderSearch = planning_detail::searchFreeOrder(
            problem, planner, departure, std::isnan(options.speed) ? m.vehicle.speed : options.speed,
            options.timeLimit > 0.0 ? options.timeLimit : m.planner.timeLimit, out.legs, out.order);
    else
    {
        out.order.resize(m.waypoints.size());
        std::iota(out.order.begin(), out.order.end(), std::size_t{0});
        out.legs = flyOrder(planner, out.order, departure);
    }
    out.plan = assemble(problem, out.legs, departure);
    return out;
}
} // namespace ompl_glider

/// @file GotoWaypoints.cpp
/// @brief The route's goto list: which waypoints it names (gotoWaypointIndices(): the turns, and what keeps a
/// thinned list on the water, out of the forbidden regions and on time) and the notes a pilot reads beside them (the
/// heading held to reach a waypoint, a stay at a via point). The other route files: RouteFiles.cpp.
#include "ompl_glider/output/RouteFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "ompl_glider/Exception.h"
#include "../io/NumberText.h"
#include "../io/TextUtil.h"
#include "RouteCommon.h"

namespace ompl_glider
{
namespace
{
/// A held duration for the pilot: hours with physical time units ("2.50 h"), else the field's number.
std::string heldFor(const MissionResult &r, double t)
{
    if (!r.spec.physicalUnits().time)
        return text::number(t, 4);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.4f h", t * r.spec.timeUnitSeconds / 3600.0); // to a third of a second
    return buf;
}

/// The course from @p a to @p b in degrees clockwise from the planning frame's y axis.
double courseDeg(Point2 a, Point2 b)
{
    return std::atan2(b.x - a.x, b.y - a.y) * 180.0 / M_PI;
}

/// Distance from @p p to the segment @p a - @p b.
double offsetFrom(Point2 p, Point2 a, Point2 b)
{
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    const double s = l2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - s * dx, p.y - a.y - s * dy);
}

/// The leg from waypoint @p a to @p b keeps to water and out of the forbidden regions (nothing to check without
/// the problem).
bool legAllowed(const MissionResult &r, const MissionProblem *problem, std::size_t a, std::size_t b)
{
    if (!problem)
        return true;
    const MissionWaypoint &p = r.waypoints[a], &q = r.waypoints[b];
    if (!problem->getField()->segmentInWater(p.position.x, p.position.y, q.position.x, q.position.y,
                                             r.spec.vehicle.depth))
        return false;
    const auto &env = problem->getEnvironment();
    return !env || env->legFree(p.position.x, p.position.y, p.time, q.position.x, q.position.y, q.time);
}

/// The straight leg from waypoint @p a to @p b, flown as the glider flies a goto list's leg (the fastest straight
/// travel time, retimePath()), arrives when the planned waypoints do: within 0.1 % of their time or half a minute, so
/// that a thinned list still arrives when the summary says (nothing to check without the problem).
bool legKeepsTime(const MissionResult &r, const MissionProblem *problem, std::size_t a, std::size_t b)
{
    if (!problem)
        return true;
    const MissionWaypoint &p = r.waypoints[a], &q = r.waypoints[b];
    const std::vector<TimedPoint> flown =
        retimePath(*problem, problem->getField(), r.plan.speed,
                   {{p.position.x, p.position.y, p.time}, {q.position.x, q.position.y, q.time}});
    if (flown.size() != 2)
        return false;
    const double planned = q.time - p.time;
    const double tolerance = std::max(1e-3 * planned, 30.0 / r.spec.timeUnitSeconds);
    return std::abs((flown.back().t - flown.front().t) - planned) <= tolerance;
}
} // namespace

namespace
{
/// Waypoint @p i is a via point's arrival (the end of a leg other than the last).
bool isViaArrival(const MissionResult &r, std::size_t i)
{
    for (std::size_t k = 0; k + 1 < r.legs.size(); ++k)
        if (r.legs[k].lastPoint == i)
            return true;
    return false;
}

/// Waypoint @p i ends a segment of a leg flown as held headings (a mission whose legs mix both kinds).
bool inHeadingLeg(const MissionResult &r, std::size_t i)
{
    for (const PlannedLeg &l : r.legs)
        if (l.plan.headingRoute() && i > l.firstPoint && i <= l.lastPoint)
            return true;
    return false;
}
} // namespace

std::vector<std::size_t> gotoWaypointIndices(const MissionResult &r, const MissionProblem *problem)
{
    bool headings = false;
    for (const MissionWaypoint &w : r.waypoints)
        headings = headings || std::isfinite(w.heading);
    return gotoWaypointIndices(r, problem, headings ? uploadHolds(r, problem) : std::vector<HeldHeading>{});
}

std::vector<std::size_t> gotoWaypointIndices(const MissionResult &r, const MissionProblem *problem,
                                             const std::vector<HeldHeading> &holds)
{
    const std::size_t n = r.waypoints.size();
    std::vector<std::size_t> kept;
    if (n == 0)
        return kept;
    // the segment ends inside a merged hold are not listed: the glider holds on through them
    std::vector<bool> inside(n, false);
    for (const HeldHeading &h : holds)
        for (std::size_t k = h.from + 1; k < h.to && k < n; ++k)
            inside[k] = true;
    kept.push_back(0);
    const double turn = r.spec.outputs.gotoTurnDeg;
    const double tolerance = r.spec.outputs.gotoMaxOffset / r.spec.metresPerUnit();
    auto at = [&](std::size_t i) { return r.waypoints[i].position; };
    auto same = [&](std::size_t i, std::size_t j) { return at(i).x == at(j).x && at(i).y == at(j).y; };
    for (std::size_t i = 1; i + 1 < n; ++i)
    {
        const std::size_t k = kept.back();
        if (isViaArrival(r, i) && !same(i, k)) // stations
        {
            kept.push_back(i);
            continue;
        }
        if (inHeadingLeg(r, i) || r.plan.headingRoute()) // held headings: the ends of the holds
        {
            if (!inside[i])
                kept.push_back(i);
            continue;
        }
        if (!(turn > 0.0)) // every waypoint
        {
            kept.push_back(i);
            continue;
        }
        if (same(i, k) || same(i, i + 1)) // a hold: the same position again
            continue;
        bool drop = std::abs(std::remainder(courseDeg(at(i), at(i + 1)) - courseDeg(at(k), at(i)), 360.0)) <= turn;
        for (std::size_t j = k + 1; drop && j <= i; ++j)
            drop = offsetFrom(at(j), at(k), at(i + 1)) <= tolerance;
        if (!(drop && legAllowed(r, problem, k, i + 1) && legKeepsTime(r, problem, k, i + 1)))
            kept.push_back(i);
    }
    if (n > 1)
        kept.push_back(n - 1);
    return kept;
}

std::string headingNote(const MissionResult &r, const HeldHeading &h)
{
    char buf[128];
    std::snprintf(buf, sizeof buf, "to here: hold heading %05.1f deg true for %s", h.bearing,
                  heldFor(r, h.duration).c_str());
    return buf;
}

std::optional<StationStay> stayAt(const MissionResult &r, std::size_t i)
{
    for (std::size_t k = 0; k + 1 < r.legs.size(); ++k)
    {
        const PlannedLeg &l = r.legs[k];
        if (l.lastPoint != i || !(l.stay > 0.0) || i + 1 >= r.waypoints.size())
            continue;
        StationStay s;
        s.name = l.to;
        s.arrival = r.waypoints[i].time;
        s.duration = l.stay;
        s.leave = r.waypoints[i + 1].time; // the hold's end: the next waypoint, at the same place
        s.leaveIso = r.waypoints[i + 1].iso;
        s.radius = r.spec.outputs.gotoWptDist;
        if (l.toVia >= 0 && std::isfinite(r.spec.waypoints[l.toVia].radius))
            s.radius = r.spec.waypoints[l.toVia].radius * r.spec.metresPerUnit();
        return s;
    }
    return std::nullopt;
}

std::optional<StationStay> resumedStay(const MissionResult &r)
{
    const auto &o = r.spec.observations;
    if (!o || !o->resumed || o->resumed->dropped.empty() || r.waypoints.empty())
        return std::nullopt;
    const DroppedStation &d = o->resumed->dropped.back();
    if (!(d.stayLeft > 0.0))
        return std::nullopt;
    StationStay s;
    s.name = d.name;
    s.leave = r.waypoints.front().time; // the plan's departure: the stay's end
    s.leaveIso = r.waypoints.front().iso;
    s.arrival = r.spec.timeOf(o->resumed->fixIso); // held from the last fix on
    s.duration = std::max(0.0, s.leave - s.arrival);
    s.radius = d.radius;
    s.at = d.at;
    return s;
}

std::string stayNote(const MissionResult &r, const StationStay &s)
{
    char radius[32];
    std::snprintf(radius, sizeof radius, "%.0f m", std::max(1.0, std::round(s.radius)));
    return "stay at " + s.name + ": hold within " +
           (r.spec.physicalUnits().length ? std::string(radius) : text::number(s.radius / r.spec.metresPerUnit())) +
           " for " + heldFor(r, s.duration) + ", leave at " +
           (s.leaveIso.empty() ? text::number(s.leave, 10) : s.leaveIso);
}

GotoList gotoList(const MissionResult &r, const MissionProblem *problem)
{
    if (!route_detail::geographic(r))
        throw Error(r.spec.file + ": a goto list needs longitudes and latitudes (give a 'projection')");
    GotoList g;
    g.number = r.spec.outputs.gotoNumber;
    g.comment = r.spec.name;
    g.listWhenWptDist = r.spec.outputs.gotoWptDist;
    bool headings = false;
    for (const MissionWaypoint &w : r.waypoints)
        headings = headings || std::isfinite(w.heading);
    const std::vector<HeldHeading> holds = headings ? uploadHolds(r, problem) : std::vector<HeldHeading>{};
    const std::vector<std::size_t> listed = gotoWaypointIndices(r, problem, holds);
    if (const auto stay = resumedStay(r)) // a stay under way: held first, until the plan departs
    {
        g.waypoints.push_back(stay->at);
        g.notes.push_back(stayNote(r, *stay));
    }
    for (std::size_t i : listed)
    {
        if (i == 0 && !r.spec.outputs.gotoIncludeStart)
            continue;
        g.waypoints.push_back({r.waypoints[i].lonLat.lon, r.waypoints[i].lonLat.lat});
        // how the glider flies to this waypoint where it is not a straight leg: the heading to hold
        std::string note;
        for (const HeldHeading &h : holds)
            if (h.to == i)
                note = headingNote(r, h);
        if (note.empty() && r.plan.headingRoute())
            note = i == 0 ? "start" : "hold in place";
        if (const auto stay = stayAt(r, i))
            note += (note.empty() ? "" : "; then ") + stayNote(r, *stay);
        g.notes.resize(g.waypoints.size());
        g.notes.back() = note;
    }
    return g;
}
} // namespace ompl_glider

/// @file RouteFiles.cpp
/// @brief The route files: waypoints.csv, path.csv, path.geojson, isochrones.geojson, route.kml, stints.csv. The goto
/// list's waypoints and notes: GotoWaypoints.cpp.
#include "ompl_glider/output/RouteFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <nlohmann/json.hpp>

#include "JsonValues.h"
#include "RouteCommon.h"

#include "ompl_glider/Exception.h"
#include "../io/NumberText.h"
#include "../io/TextUtil.h"

namespace ompl_glider
{
namespace
{

using output_json::jnum;
using route_detail::geographic;

bool hasProfile(const MissionResult &r, std::size_t i)
{
    return r.diveProfiles && i > 0 && r.waypoints[i].profile >= 0;
}
} // namespace

std::string stopName(const MissionResult &r, std::size_t i)
{
    if (r.legs.empty())
        return "";
    if (i == 0)
        return "start";
    for (const PlannedLeg &l : r.legs)
    {
        if (i == l.lastPoint)
            return l.to;
        if (i == l.firstPoint && l.index > 0)
            return r.legs[l.index - 1].to; // the end of the stay at the previous leg's via point
    }
    return "";
}

std::string waypointsCsv(const MissionResult &r, const MissionProblem *problem)
{
    const std::vector<double> heading = trueHeadings(r, problem); // true bearings: the one written
    // a mission of several legs: the leg each waypoint belongs to and the via point it is (empty between them)
    const bool legs = !r.legs.empty();
    std::string s =
        std::string("index,x,y,lon,lat,time,time_s,time_iso,leg_time,profile,climb_to,dive_to,heading_true_deg,"
                    "segment_duration") +
        (legs ? ",leg,stop\n" : "\n");
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        const MissionWaypoint &w = r.waypoints[i];
        s += std::to_string(i) + "," + text::csvNumber(w.position.x) + "," + text::csvNumber(w.position.y) + ",";
        s += w.geographic ? text::csvNumber(w.lonLat.lon) + "," + text::csvNumber(w.lonLat.lat) : std::string(",");
        s += "," + text::csvNumber(w.time) + "," + text::csvNumber(w.time * r.spec.timeUnitSeconds) + "," + w.iso +
             "," + text::csvNumber(w.legTime) + ",";
        if (hasProfile(r, i))
            s += std::to_string(w.profile) + "," + text::csvNumber(w.dive.climbTo) + "," +
                 text::csvNumber(w.dive.diveTo);
        else
            s += ",,";
        // a heading route: the heading held from here and for how long (empty for straight legs)
        s += "," + (std::isfinite(heading[i]) ? text::csvNumber(heading[i]) : std::string()) + "," +
             (std::isfinite(w.headingDuration) ? text::csvNumber(w.headingDuration) : std::string());
        if (legs)
            s += "," + std::to_string(w.missionLeg) + "," + stopName(r, i);
        s += "\n";
    }
    return s;
}

std::string pathCsv(const MissionResult &r)
{
    const bool legs = !r.legs.empty();
    std::string s = legs ? "t,x,y,lon,lat,leg\n" : "t,x,y,lon,lat\n";
    for (const MissionWaypoint &w : r.waypoints)
    {
        s += text::csvNumber(w.time) + "," + text::csvNumber(w.position.x) + "," + text::csvNumber(w.position.y) + ",";
        s += w.geographic ? text::csvNumber(w.lonLat.lon) + "," + text::csvNumber(w.lonLat.lat) : std::string(",");
        s += legs ? "," + std::to_string(w.missionLeg) + "\n" : "\n";
    }
    return s;
}

std::vector<std::vector<LonLat>> splitAtAntimeridian(const std::vector<LonLat> &line)
{
    // Longitudes unwrapped along the line (each leg the shorter way round), cut where the line meets 180 + 360 k,
    // each piece shifted back by whole turns into -180..180 (its eastern or western edge at +-180 exactly).
    std::vector<std::vector<LonLat>> pieces;
    if (line.empty())
        return pieces;
    auto cell = [](double u) { return std::floor((u - 180.0) / 360.0); }; // [180 + 360 k, 540 + 360 k)
    std::vector<LonLat> piece{{normalizeLongitude(line[0].lon), line[0].lat}};
    auto close = [&]() {
        std::vector<LonLat> kept;
        for (const LonLat &p : piece)
            if (kept.empty() || p.lon != kept.back().lon || p.lat != kept.back().lat)
                kept.push_back(p);
        if (kept.size() >= 2)
        {
            double lo = kept[0].lon, hi = kept[0].lon;
            for (const LonLat &p : kept)
            {
                lo = std::min(lo, p.lon);
                hi = std::max(hi, p.lon);
            }
            const double shift = -360.0 * std::round(0.5 * (lo + hi) / 360.0);
            for (LonLat &p : kept)
                p.lon += shift;
            pieces.push_back(kept);
        }
    };
    for (std::size_t i = 1; i < line.size(); ++i)
    {
        const LonLat a = piece.back();
        const LonLat b{a.lon + std::remainder(line[i].lon - a.lon, 360.0), line[i].lat};
        if (cell(a.lon) != cell(b.lon))
        {
            const double c = 180.0 + 360.0 * std::max(cell(a.lon), cell(b.lon));
            const double lat = a.lat + (c - a.lon) / (b.lon - a.lon) * (b.lat - a.lat);
            piece.push_back({c, lat});
            close();
            piece = {{c, lat}};
        }
        piece.push_back(b);
    }
    close();
    return pieces;
}

std::string isochronesGeoJson(const MissionResult &r)
{
    // One feature per time: a MultiLineString of the reachable set's boundary, lon/lat where geographic.
    const bool geo = geographic(r);
    nlohmann::ordered_json features = nlohmann::ordered_json::array();
    if (r.isochrones)
        for (const Isochrone &c : r.isochrones->contours)
        {
            nlohmann::ordered_json lines = nlohmann::ordered_json::array();
            if (geo)
                for (const auto &line : c.lonLat)
                    for (const auto &part : splitAtAntimeridian(line))
                    {
                        nlohmann::ordered_json l = nlohmann::ordered_json::array();
                        for (const LonLat &p : part)
                            l.push_back(nlohmann::ordered_json::array({p.lon, p.lat}));
                        lines.push_back(l);
                    }
            else
                for (const auto &line : c.lines)
                {
                    nlohmann::ordered_json l = nlohmann::ordered_json::array();
                    for (const Point2 &p : line)
                        l.push_back(nlohmann::ordered_json::array({p.x, p.y}));
                    lines.push_back(l);
                }
            features.push_back(
                {{"type", "Feature"},
                 {"properties",
                  {{"time", jnum(c.time)},
                   {"time_s", jnum(c.time * r.spec.timeUnitSeconds)},
                   {"time_iso", c.iso.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.iso)},
                   {"since_departure", jnum(c.time - r.plan.departure)}}},
                 {"geometry", {{"type", "MultiLineString"}, {"coordinates", lines}}}});
        }
    nlohmann::ordered_json doc = {{"type", "FeatureCollection"},
                                  {"name", r.spec.name + " isochrones"},
                                  {"resolution", r.isochrones ? jnum(r.isochrones->resolution) : jnum(0.0)},
                                  {"features", features}};
    return output_json::utf8Dump(doc, 1) + "\n";
}

namespace
{
/// The route line of the GeoJSON: the waypoints for straight legs, the flown track of a heading route (planning
/// frame and, where geographic, lon/lat).
struct RouteLine
{
    std::vector<Point2> xy;
    std::vector<LonLat> lonLat;
};

RouteLine routeLine(const MissionResult &r, const MissionProblem *problem, bool geo)
{
    RouteLine l;
    if (r.plan.headingRoute() && r.plan.track.size() >= 2)
    {
        if (geo && !problem)
            throw Error("routeGeoJson: the track of a geographic heading route needs the problem to project it");
        for (const TimedPoint &p : r.plan.track)
        {
            l.xy.push_back({p.x, p.y});
            l.lonLat.push_back(geo ? problem->toGeographic({p.x, p.y}) : LonLat{});
        }
        return l;
    }
    for (const MissionWaypoint &w : r.waypoints)
    {
        l.xy.push_back(w.position);
        l.lonLat.push_back(w.lonLat);
    }
    return l;
}
} // namespace

std::string routeGeoJson(const MissionResult &r, const MissionProblem *problem)
{
    const bool geo = geographic(r);
    auto coord = [&](const MissionWaypoint &w) {
        return geo ? nlohmann::ordered_json::array({w.lonLat.lon, w.lonLat.lat})
                   : nlohmann::ordered_json::array({w.position.x, w.position.y});
    };
    nlohmann::ordered_json geometry;
    const RouteLine route = routeLine(r, problem, geo);
    const std::vector<std::vector<LonLat>> parts =
        geo ? splitAtAntimeridian(route.lonLat) : std::vector<std::vector<LonLat>>{}; // one piece unless it crosses
    if (parts.size() > 1)
    {
        // across the antimeridian: a MultiLineString split there (RFC 7946 sec. 3.1.9)
        nlohmann::ordered_json lines = nlohmann::ordered_json::array();
        for (const auto &part : parts)
        {
            nlohmann::ordered_json line = nlohmann::ordered_json::array();
            for (const LonLat &p : part)
                line.push_back(nlohmann::ordered_json::array({p.lon, p.lat}));
            lines.push_back(line);
        }
        geometry = {{"type", "MultiLineString"}, {"coordinates", lines}};
    }
    else
    {
        nlohmann::ordered_json line = nlohmann::ordered_json::array();
        for (std::size_t i = 0; i < route.xy.size(); ++i)
            line.push_back(geo ? nlohmann::ordered_json::array({route.lonLat[i].lon, route.lonLat[i].lat})
                               : nlohmann::ordered_json::array({route.xy[i].x, route.xy[i].y}));
        geometry = {{"type", "LineString"}, {"coordinates", line}};
    }
    nlohmann::ordered_json pathProps = {{"name", r.spec.name + " path"},
                                        {"departure", jnum(r.plan.departure)},
                                        {"travel_time", jnum(r.plan.travelTime)},
                                        {"path_length", jnum(r.plan.pathLength)}};
    if (r.plan.headingRoute())
    {
        // the line is the flown track of held headings, not straight legs between the waypoints
        pathProps["route_model"] = "headings";
        pathProps["segments"] = r.plan.headings->segments.size();
    }
    nlohmann::ordered_json features = nlohmann::ordered_json::array();
    features.push_back({{"type", "Feature"}, {"properties", pathProps}, {"geometry", geometry}});
    const std::vector<double> heading = trueHeadings(r, problem);
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        const MissionWaypoint &w = r.waypoints[i];
        nlohmann::ordered_json props = {
            {"index", i},
            {"time", jnum(w.time)},
            {"time_s", jnum(w.time * r.spec.timeUnitSeconds)},
            {"time_iso", w.iso.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(w.iso)},
            {"leg_time", jnum(w.legTime)}};
        if (hasProfile(r, i))
        {
            props["profile"] = w.profile;
            props["climb_to"] = jnum(w.dive.climbTo);
            props["dive_to"] = jnum(w.dive.diveTo);
        }
        if (r.plan.headingRoute() || std::isfinite(w.heading))
        {
            // the TRUE heading held from this waypoint (null at the last one; a mission's legs of held headings)
            props["heading_true_deg"] = jnum(heading[i]);
            props["segment_duration"] = jnum(w.headingDuration);
        }
        features.push_back(
            {{"type", "Feature"}, {"properties", props}, {"geometry", {{"type", "Point"}, {"coordinates", coord(w)}}}});
    }
    nlohmann::ordered_json doc = {{"type", "FeatureCollection"}, {"features", features}};
    if (!geo)
        doc["coordinates"] = "local";
    return output_json::utf8Dump(doc, 1) + "\n";
}

namespace
{
/// A KML coordinates list "lon,lat,0 lon,lat,0 ...".
std::string kmlCoordinates(const std::vector<LonLat> &line)
{
    std::string s;
    char buf[64];
    for (const LonLat &p : line)
    {
        std::snprintf(buf, sizeof buf, "%s%.12g,%.12g,0", s.empty() ? "" : " ", p.lon, p.lat);
        s += buf;
    }
    return s;
}

/// A line of lon/lat as KML geometry: a LineString, or a MultiGeometry of the pieces split at the antimeridian.
std::string kmlLines(const std::vector<std::vector<LonLat>> &pieces)
{
    std::string s = pieces.size() == 1 ? "" : "<MultiGeometry>";
    for (const auto &piece : pieces)
        s += "<LineString><tessellate>1</tessellate><coordinates>" + kmlCoordinates(piece) +
             "</coordinates></LineString>";
    return s + (pieces.size() == 1 ? "" : "</MultiGeometry>");
}

/// Whether the mission's dates are Gregorian ones (KML's TimeStamp is xsd:dateTime, which has no year 0): an epoch
/// from year 1 on, or a forecast on the standard or proleptic Gregorian calendar after 1582.
bool gregorianDates(const MissionResult &r, const std::string &iso)
{
    if (iso.empty())
        return false;
    if (!r.spec.fileCalendar)
        return iso.compare(0, 4, "0001") >= 0;
    const Calendar c = r.spec.fileCalendar->calendar;
    return (c == Calendar::Standard || c == Calendar::ProlepticGregorian) && iso.compare(0, 4, "1583") >= 0;
}
} // namespace

std::string routeKml(const MissionResult &r, const MissionProblem *problem)
{
    if (!geographic(r))
        throw Error(r.spec.file + ": route.kml needs longitudes and latitudes (give a 'projection')");
    std::string k = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<kml xmlns=\"http://www.opengis.net/kml/2.2\">\n"
                    "<Document>\n<name>" +
                    text::xmlEscaped(r.spec.name) +
                    "</name>\n"
                    "<Style id=\"route\"><LineStyle><color>ff0000ff</color><width>3</width></LineStyle></Style>\n"
                    "<Style id=\"isochrone\"><LineStyle><color>ff00aaff</color><width>1</width></LineStyle></Style>\n";
    const RouteLine route = routeLine(r, problem, true);
    const auto pieces = splitAtAntimeridian(route.lonLat);
    const MissionSpec::PhysicalUnits units = r.spec.physicalUnits();
    const std::string about =
        "travel time " +
        (units.time ? text::durationText(r.plan.travelTime * r.spec.timeUnitSeconds)
                    : text::number(r.plan.travelTime)) +
        ", path length " +
        (units.length ? text::number(r.plan.pathLength * r.spec.metresPerUnit() / 1000.0, 6) + " km"
                      : text::number(r.plan.pathLength));
    const bool stamped = !r.waypoints.empty() && gregorianDates(r, r.waypoints.front().iso);
    k += "<Placemark>\n<name>route</name>\n<description>" + text::xmlEscaped(about) +
         (r.plan.headingRoute() ? " (the flown track of held headings)" : "") +
         (!stamped && !r.waypoints.empty() && !r.waypoints.front().iso.empty()
              ? "; the waypoints' dates are in their descriptions, without KML time stamps (not Gregorian dates of "
                "years 1-9999: a climatology's or a model calendar's)"
              : "") +
         "</description>\n<styleUrl>#route</styleUrl>\n" + kmlLines(pieces) + "\n</Placemark>\n";
    // the waypoints first..last: a placemark each (a mission's stops by their names)
    const auto placemarks = [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i <= last && i < r.waypoints.size(); ++i)
        {
            const MissionWaypoint &w = r.waypoints[i];
            const std::string stop = stopName(r, i);
            const std::string name = !stop.empty()                 ? stop
                                     : i == 0                      ? "start"
                                     : i + 1 == r.waypoints.size() ? "goal"
                                                                   : "WP " + std::to_string(i);
            k += "<Placemark>\n<name>" + text::xmlEscaped(name) + "</name>\n";
            if (gregorianDates(r, w.iso))
                k += "<TimeStamp><when>" + w.iso + "</when></TimeStamp>\n";
            k += "<description>" +
                 text::xmlEscaped(w.iso.empty() ? "t = " + text::number(w.time, 10)
                                                : (i == 0 ? "departure " : "arrival ") + w.iso) +
                 "</description>\n<Point><coordinates>" + kmlCoordinates({w.lonLat}) +
                 "</coordinates></Point>\n"
                 "</Placemark>\n";
        }
    };
    if (r.legs.empty())
    {
        k += "<Folder>\n<name>waypoints</name>\n";
        placemarks(0, r.waypoints.size() - 1);
        k += "</Folder>\n";
    }
    // a mission of several legs: a folder per leg, its line and its waypoints
    for (const PlannedLeg &l : r.legs)
    {
        std::vector<LonLat> line;
        for (std::size_t i = l.firstPoint; i <= l.lastPoint && i < r.waypoints.size(); ++i)
            line.push_back(r.waypoints[i].lonLat);
        const double legTime = l.plan.travelTime;
        k += "<Folder>\n<name>" +
             text::xmlEscaped("leg " + std::to_string(l.index + 1) + ": " + l.from + " to " + l.to) +
             "</name>\n<Placemark>\n<name>" + text::xmlEscaped("leg " + std::to_string(l.index + 1)) +
             "</name>\n<description>" +
             text::xmlEscaped(
                 "travel time " +
                 (units.time ? text::durationText(legTime * r.spec.timeUnitSeconds) : text::number(legTime)) +
                 (l.stay > 0.0 ? ", then a stay at " + l.to : std::string())) +
             "</description>\n<styleUrl>#route</styleUrl>\n" + kmlLines(splitAtAntimeridian(line)) + "\n</Placemark>\n";
        placemarks(l.firstPoint, l.lastPoint);
        k += "</Folder>\n";
    }
    if (r.isochrones && !r.isochrones->contours.empty())
    {
        k += "<Folder>\n<name>isochrones</name>\n";
        for (const Isochrone &c : r.isochrones->contours)
        {
            std::vector<std::vector<LonLat>> lines;
            for (const auto &line : c.lonLat)
                for (const auto &part : splitAtAntimeridian(line))
                    lines.push_back(part);
            if (lines.empty())
                continue;
            k += "<Placemark>\n<name>" + text::xmlEscaped(c.iso.empty() ? "t = " + text::number(c.time, 10) : c.iso) +
                 "</name>\n<styleUrl>#isochrone</styleUrl>\n<MultiGeometry>";
            for (const auto &line : lines)
                k += kmlLines({line});
            k += "</MultiGeometry>\n</Placemark>\n";
        }
        k += "</Folder>\n";
    }
    return k + "</Document>\n</kml>\n";
}

namespace
{
/// One stints.csv row: stint @p k from @p a held at @p bearing (the plane's; @p trueDeg written) until @p b.
std::string stintRow(const MissionResult &r, const MissionProblem &problem, std::size_t k, const TimedPoint &a,
                     double bearing, double trueDeg, const TimedPoint &b)
{
    const Point2 h = bearingVector(bearing);
    const double dt = b.t - a.t;
    const double dx = b.x - a.x - r.plan.speed * dt * h.x, dy = b.y - a.y - r.plan.speed * dt * h.y;
    std::string s = std::to_string(k) + "," + text::csvNumber(a.t) + "," +
                    text::csvNumber(a.t * r.spec.timeUnitSeconds) + "," + problem.isoTime(a.t) + "," +
                    text::csvNumber(a.x) + "," + text::csvNumber(a.y) + ",";
    if (problem.isGeographic())
    {
        const LonLat g = problem.toGeographic({a.x, a.y});
        s += text::csvNumber(g.lon) + "," + text::csvNumber(g.lat);
    }
    else
        s += ",";
    s += "," + text::csvNumber(trueDeg) + "," + text::csvNumber(b.t) + "," + text::csvNumber(b.x) + "," +
         text::csvNumber(b.y) + "," + text::csvNumber(dx) + "," + text::csvNumber(dy) + "," +
         text::csvNumber(dt > 0.0 ? std::hypot(dx, dy) / dt : 0.0) + "\n";
    return s;
}
} // namespace

std::string stintsCsv(const MissionResult &r, const MissionProblem &problem)
{
    std::string s = "stint,time,time_s,time_iso,x,y,lon,lat,heading_true_deg,end_time,end_x,end_y,drift_x,drift_y,"
                    "drift_speed\n";
    if (!r.plan.stints)
    {
        // a heading route: its segments are the stints, from the waypoint where each is begun to the next one
        std::size_t k = 0;
        const std::vector<double> heading = r.plan.headingRoute() ? trueHeadings(r, &problem) : std::vector<double>{};
        if (r.plan.headingRoute())
            for (std::size_t i = 0; i + 1 < r.waypoints.size(); ++i)
                if (std::isfinite(r.waypoints[i].heading))
                {
                    const MissionWaypoint &a = r.waypoints[i], &b = r.waypoints[i + 1];
                    s += stintRow(r, problem, k++, {a.position.x, a.position.y, a.time}, a.heading, heading[i],
                                  {b.position.x, b.position.y, b.time});
                }
        return s;
    }
    const StintPlan &p = r.plan.stints->plan;
    for (std::size_t k = 0; k < p.bearings.size() && k + 1 < p.surfacings.size(); ++k)
        s += stintRow(
            r, problem, k, p.surfacings[k], p.bearings[k],
            trueBearingOfFlight(r, &problem, p.surfacings[k], p.surfacings[k + 1], p.bearings[k], r.plan.speed),
            p.surfacings[k + 1]);
    return s;
}
} // namespace ompl_glider

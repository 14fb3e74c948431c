#pragma once
/// @file RouteFiles.h
/// @brief The route as text files a pilot or a GIS loads: waypoints CSV, path CSV, GeoJSON, the Slocum goto list.

#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/SlocumGoto.h"

namespace ompl_glider
{
/// @brief Waypoints CSV, one line per waypoint (start first), header
/// `index,x,y,lon,lat,time,time_s,time_iso,leg_time,profile,climb_to,dive_to,heading_deg,segment_duration` (time in
/// field units, time_s in seconds = time * units.time_s; lon/lat in -180..180, empty without a projection; time_iso
/// empty without a calendar; the profile columns empty without dive profiles). For a heading route
/// (PlannedPath::headingRoute()) heading_deg is the heading held FROM the waypoint (degrees clockwise from north,
/// through the water) and segment_duration how long it is held, as flown (field time units); both are empty for
/// straight legs and at the last waypoint. Numbers with 10 significant digits.
std::string waypointsCsv(const MissionResult &result);
/// @brief The stop waypoint @p i of a mission of several legs is: "start", a via point's name (its arrival, and the
/// end of its stay), "goal"; empty between stops and for a mission of one leg.
std::string stopName(const MissionResult &result, std::size_t i);

/// @brief The final path as CSV with header `t,x,y,lon,lat` (t in field time units; lon/lat empty without a
/// projection).
std::string pathCsv(const MissionResult &result);

/// @brief A line of lon/lat positions (any longitude convention) as pieces that do not cross the antimeridian
/// (RFC 7946 sec. 3.1.9): each leg goes the shorter way round; a leg across 180 is cut there, at the latitude
/// interpolated linearly in lon/lat (how a GeoJSON reader draws the leg), the piece before ending at +-180 and the
/// one after starting at -+180. Longitudes out are in -180..180; one piece when the line does not cross;
/// consecutive repeated points are dropped, and pieces of fewer than two points.
std::vector<std::vector<LonLat>> splitAtAntimeridian(const std::vector<LonLat> &line);

/// @brief GeoJSON FeatureCollection: the path (properties: mission, departure, travel time, path length) and one
/// Point per waypoint (properties: index, time, time_s, time_iso, leg_time, dive profile). Coordinates are
/// [lon, lat] (RFC 7946, longitudes in -180..180) when the mission has a projection, else planning x/y (then the
/// collection carries "coordinates": "local"). The path is a LineString, or a MultiLineString split at the
/// antimeridian (splitAtAntimeridian()) when it crosses it.
/// A heading route (PlannedPath::headingRoute()): the line is the flown track (PlannedPath::track, every integration
/// step, so it passes through every segment end), the path carries "route_model": "headings" and "segments", and
/// every waypoint "heading_deg" and "segment_duration" (the heading held from it and for how long; null at the last).
/// The track of a geographic heading route is projected with @p problem.
/// @throws Error for a geographic heading route without @p problem.
std::string routeGeoJson(const MissionResult &result, const MissionProblem *problem = nullptr);

/// @brief isochrones.geojson: one Feature per isochrone time (MultiLineString, lon/lat where the problem is
/// geographic, else the planning frame) with properties time (the mission's unit), time_s, time_iso (null without
/// dates) and since_departure ([ThompsonICRA] Fig. 4).
std::string isochronesGeoJson(const MissionResult &result);

/// @brief "to here: hold heading 348.3 deg for 0.3172 h" where waypoint @p i is reached by a held heading (a heading
/// route, or a leg of a mission flown as held headings): the heading of the waypoint before and how long it is held;
/// empty where a straight leg reaches it.
std::string headingNote(const MissionResult &result, std::size_t i);

/// @brief A stay at a via point of a mission (a "virtual mooring"): where, from when, how long, until when.
struct StationStay
{
    std::string name;     ///< the via point
    double arrival{0.0};  ///< field time
    double duration{0.0}; ///< field time units
    double leave{0.0};    ///< the stay's end (field time)
    std::string leaveIso; ///< its date (empty without a calendar)
    double radius{0.0};   ///< metres: held within it (the via point's radius, else outputs.goto_wpt_dist)
};
/// @brief The stay that begins at waypoint @p i (a via point's arrival), if any.
std::optional<StationStay> stayAt(const MissionResult &result, std::size_t i);
/// @brief "stay at A: hold within 500 m for 6.0000 h, leave at 2026-03-16T02:41:12Z".
std::string stayNote(const MissionResult &result, const StationStay &stay);

/// @brief The Slocum goto list of the final path, thinned to gotoWaypointIndices() (without the start unless
/// outputs.goto_include_start), list_when_wpt_dist from outputs.goto_wpt_dist. A waypoint reached by a held heading
/// (a heading route's segment ends; the segment ends of a mission's legs flown as held headings) carries a note
/// (GotoList::notes, headingNote()) naming the heading held on the way to it and for how long; a via point with a
/// stay, the stay (stayNote()): hold there, how long, when to leave.
/// @throws Error when the waypoints have no geographic coordinates.
GotoList gotoList(const MissionResult &result, const MissionProblem *problem = nullptr);

/// @brief The waypoints (indices into MissionResult::waypoints) the goto list names: always the start and the goal;
/// of straight legs, a waypoint only where the course turns by more than outputs.goto_turn_deg, or where the
/// straight leg past it would stray more than outputs.goto_max_offset from a waypoint left out or (with @p problem)
/// leave the water or cross a forbidden region (the keep-off zone included); a repeated position (a hold) once.
/// Every waypoint of a heading route, and every waypoint when goto_turn_deg is 0.
std::vector<std::size_t> gotoWaypointIndices(const MissionResult &result, const MissionProblem *problem = nullptr);

/// @brief route.kml for Google Earth (KML 2.2; geographic missions): the route as a LineString of lon,lat (the
/// flown track of a heading route; split at the antimeridian), one Placemark per waypoint with its arrival date
/// (TimeStamp where the dates are Gregorian, and in the description), and a folder of isochrones when the result
/// has them. @throws Error when the mission has no lon/lat, or for a heading route without @p problem.
std::string routeKml(const MissionResult &result, const MissionProblem *problem = nullptr);
/// @brief stints.csv: the heading table of a stint plan ([IsernObstacles]), one row per surfacing: stint index,
/// time (field units, seconds, ISO 8601), position (x, y, lon, lat), heading through the water held until the next
/// surfacing (degrees clockwise from north), the next surfacing (time, x, y) and the expected drift over the stint
/// (displacement minus speed x time x heading: what the current does; drift_speed its mean speed). Empty rows when
/// the result has no stints. A heading route without stints writes its segments as the stints: one row per segment
/// flown, from the waypoint where it is begun to the next one (the last ends at the arrival).
std::string stintsCsv(const MissionResult &result, const MissionProblem &problem);

} // namespace ompl_glider

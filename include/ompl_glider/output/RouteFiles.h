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
/// `index,x,y,lon,lat,time,time_s,time_iso,leg_time,profile,climb_to,dive_to,heading_true_deg,segment_duration` (time
/// in field units, time_s in seconds = time * units.time_s; lon/lat in -180..180, empty without a projection;
/// time_iso empty without a calendar; the profile columns empty without dive profiles). Where a heading is held from
/// the waypoint (a heading route, a leg of held headings) heading_true_deg is that heading through the water as a
/// TRUE bearing (degrees clockwise from true north, trueHeadings(); the frame's +y without a projection) and
/// segment_duration how long it is held, as flown (field time units): every planned segment, not the uploads'
/// merged holds; both are empty for straight legs and at the last waypoint. Numbers with 10 significant digits.
/// @throws Error for a geographic mission with headings without @p problem.
std::string waypointsCsv(const MissionResult &result, const MissionProblem *problem = nullptr);
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
/// every waypoint "heading_true_deg" and "segment_duration" (the TRUE heading held from it, trueHeadings(), and for
/// how long; null at the last).
/// The track of a geographic heading route is projected with @p problem.
/// @throws Error for a geographic heading route without @p problem.
std::string routeGeoJson(const MissionResult &result, const MissionProblem *problem = nullptr);

/// @brief isochrones.geojson: one Feature per isochrone time (MultiLineString, lon/lat where the problem is
/// geographic, else the planning frame) with properties time (the mission's unit), time_s, time_iso (null without
/// dates) and since_departure ([ThompsonICRA] Fig. 4).
std::string isochronesGeoJson(const MissionResult &result);

/// @brief One heading the uploads tell the glider to hold: from waypoint `from` to waypoint `to` (indices into
/// MissionResult::waypoints; one planned segment, or several merged, uploadHolds()).
struct HeldHeading
{
    std::size_t from{0}, to{0};
    double bearing{0.0};  ///< TRUE bearing through the water, degrees clockwise from true north, [0, 360)
    double duration{0.0}; ///< how long it is held (field time units)
    double miss{0.0};     ///< metres: where its flight through the forecast ends from waypoint `to`
};

/// @brief The true bearing (degrees clockwise from true north at @p at, [0, 360)) of the planning frame's bearing
/// @p gridDeg (clockwise from +y, the projection's grid north) at @p at; the bearing itself without lon/lat.
/// @throws Error for a geographic mission without @p problem.
double trueBearing(const MissionResult &result, const MissionProblem *problem, Point2 at, double gridDeg);
/// @brief trueBearing() with the problem alone: the bearing itself where the problem has no lon/lat.
double trueBearing(const MissionProblem &problem, Point2 at, double gridDeg);
/// @brief The true bearing to write for a heading @p gridDeg held from @p from until @p to.t at @p speed: the true
/// heading whose flight through the forecast (held true: its direction in the plane turns with the meridians along
/// the way) ends nearest @p to (the planned segment's end), from trueBearing() at the start.
double trueBearingOfFlight(const MissionResult &result, const MissionProblem *problem, const TimedPoint &from,
                           const TimedPoint &to, double gridDeg, double speed);
/// @brief Per waypoint, the TRUE heading held from it (trueBearingOfFlight() of MissionWaypoint::heading to the next
/// waypoint), NaN where MissionWaypoint::heading is: what waypoints.csv, path.geojson, summary.json and Python write.
/// @throws Error for a geographic mission with headings without @p problem.
std::vector<double> trueHeadings(const MissionResult &result, const MissionProblem *problem);
/// @brief A stint plan's bearings as TRUE bearings, each the one whose flight ends at its next surfacing
/// (trueBearingOfFlight()); empty without stints. @throws Error for a geographic mission without @p problem.
std::vector<double> trueStintBearings(const MissionResult &result, const MissionProblem *problem);
/// @brief The held headings the uploads (goto list, targets file) write: each run of held headings of a leg as the
/// fewest holds whose flights through the forecast pass every planned segment end of their span (at its time)
/// within outputs.hold_tolerance metres (0: every segment), each with the true heading that ends nearest its span's
/// end (trueBearingOfFlight()), and (with @p problem) whose flown track keeps to water and out of the forbidden
/// regions; found from each hold's start by doubling the span, then halving. A single segment is always a hold.
/// @throws Error for a geographic mission with headings without @p problem.
std::vector<HeldHeading> uploadHolds(const MissionResult &result, const MissionProblem *problem);

/// @brief "to here: hold heading 348.3 deg true for 0.3172 h": the note of the waypoint a hold (uploadHolds()) ends
/// at: its true heading and how long it is held.
std::string headingNote(const MissionResult &result, const HeldHeading &hold);

/// @brief A stay at a via point of a mission (a "virtual mooring"): where, from when, how long, until when.
struct StationStay
{
    std::string name;     ///< the via point
    double arrival{0.0};  ///< field time
    double duration{0.0}; ///< field time units
    double leave{0.0};    ///< the stay's end (field time)
    std::string leaveIso; ///< its date (empty without a calendar)
    double radius{0.0};   ///< metres: held within it (the via point's radius, else outputs.goto_wpt_dist)
    LonLat at;            ///< the via point (set by resumedStay())
};
/// @brief The stay that begins at waypoint @p i (a via point's arrival), if any.
std::optional<StationStay> stayAt(const MissionResult &result, std::size_t i);
/// @brief A stay under way when the mission was resumed at the glider's last fix (MissionResume, DroppedStation::
/// stayLeft): the station, from the last fix until the plan's departure (the stay's end), its radius; none when the
/// mission was not resumed during a stay. The uploads begin with it (gotoList(), seagliderTargets()).
std::optional<StationStay> resumedStay(const MissionResult &result);
/// @brief "stay at A: hold within 500 m for 6.0000 h, leave at 2026-03-16T02:41:12Z".
std::string stayNote(const MissionResult &result, const StationStay &stay);

/// @brief The Slocum goto list of the final path, thinned to gotoWaypointIndices() (without the start unless
/// outputs.goto_include_start), list_when_wpt_dist from outputs.goto_wpt_dist. A waypoint reached by a held heading
/// (the end of a hold, uploadHolds()) carries a note (GotoList::notes, headingNote()) naming the TRUE heading held on
/// the way to it and for how long; a via point with a
/// stay, the stay (stayNote()): hold there, how long, when to leave. A mission resumed during a stay (resumedStay())
/// begins with the station and that stay's note: the glider holds there until the plan departs.
/// @throws Error when the waypoints have no geographic coordinates.
GotoList gotoList(const MissionResult &result, const MissionProblem *problem = nullptr);

/// @brief The waypoints (indices into MissionResult::waypoints) the goto list names: always the start and the goal;
/// of straight legs, a waypoint only where the course turns by more than outputs.goto_turn_deg, or where the
/// straight leg past it would stray more than outputs.goto_max_offset from a waypoint left out or (with @p problem)
/// leave the water or cross a forbidden region (the keep-off zone included); a repeated position (a hold) once.
/// Of held headings, the end of every hold (uploadHolds()); every waypoint when goto_turn_deg is 0.
std::vector<std::size_t> gotoWaypointIndices(const MissionResult &result, const MissionProblem *problem = nullptr);
/// @brief gotoWaypointIndices() with the holds already computed (uploadHolds()).
std::vector<std::size_t> gotoWaypointIndices(const MissionResult &result, const MissionProblem *problem,
                                             const std::vector<HeldHeading> &holds);

/// @brief route.kml for Google Earth (KML 2.2; geographic missions): the route as a LineString of lon,lat (the
/// flown track of a heading route; split at the antimeridian), one Placemark per waypoint with its arrival date
/// (TimeStamp where the dates are Gregorian, and in the description), and a folder of isochrones when the result
/// has them. @throws Error when the mission has no lon/lat, or for a heading route without @p problem.
std::string routeKml(const MissionResult &result, const MissionProblem *problem = nullptr);
/// @brief stints.csv: the heading table of a stint plan ([IsernObstacles]), one row per surfacing: stint index,
/// time (field units, seconds, ISO 8601), position (x, y, lon, lat), heading through the water held until the next
/// surfacing (heading_true_deg: degrees clockwise from TRUE north, trueBearingOfFlight()), the next surfacing (time, x,
/// y) and the expected drift over the stint (displacement minus speed x time x heading: what the current does;
/// drift_speed its mean speed). Empty rows when the result has no stints. A heading route without stints writes its
/// segments as the stints: one row per segment flown, from the waypoint where it is begun to the next one (the last
/// ends at the arrival).
std::string stintsCsv(const MissionResult &result, const MissionProblem &problem);

} // namespace ompl_glider

#pragma once
/// @file MissionOutputs.h
/// @brief What a mission writes for the pilot (SPEC.md 6, 003 Sec. IV): waypoints CSV, GeoJSON, the Slocum goto
/// list, a JSON summary, the speed-sweep table and the map.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ompl_glider/mission/MapRenderer.h"
#include "ompl_glider/mission/MissionRunner.h"
#include "ompl_glider/mission/SlocumGoto.h"

namespace ompl_glider
{
/// @brief Waypoints CSV, one line per waypoint (start first), header
/// `index,x,y,lon,lat,time,time_s,time_iso,leg_time,profile,climb_to,dive_to` (time in field units, time_s in
/// seconds = time * units.time_s; lon/lat empty without a projection,
/// time_iso empty without a calendar, the profile columns empty without dive profiles). Numbers with 10
/// significant digits.
std::string waypointsCsv(const MissionResult &result);

/// @brief GeoJSON FeatureCollection: one LineString of the path (properties: mission, departure, travel time,
/// path length) and one Point per waypoint (properties: index, time, time_s, time_iso, leg_time, dive profile).
/// Coordinates are [lon, lat] (RFC 7946) when the mission has a projection, else planning x/y (then the
/// collection carries "coordinates": "local").
std::string waypointsGeoJson(const MissionResult &result);

/// @brief JSON summary: mission, status, departure (+ISO), travel time (2-D and with dive profiles), path length,
/// straight-line travel time or "impassable", straight-line length, waypoints raw/smoothed, CFC, CMC, planning
/// wall time, the departure search (counts, times, supporting points) and the speed sweep.
std::string summaryJson(const MissionResult &result);

/// @brief The Slocum goto list of the final path (without the start unless outputs.goto_include_start).
/// @throws Error when the waypoints have no geographic coordinates.
GotoList gotoList(const MissionResult &result);

/// @brief The speed sweep as a text table (003 Table VI): speed, travel time, path length, straight-line travel
/// time ("impassable" when infinite) and length.
std::string speedSweepTable(const std::vector<SpeedSweepRow> &rows);

/// @brief The mission's map: current arrows at outputs.map_time (default: the departure), forbidden regions, lattice
/// and final paths with time ticks (hours or days after departure for physical units), start and goal.
MapRenderer missionMap(const MissionResult &result, const MissionProblem &problem);

/// @brief Writes the files listed in result.spec.outputs.files into result.spec.outputs.directory (created when
/// missing): <prefix>_waypoints.csv, <prefix>.geojson, goto_lNN.ma, <prefix>_summary.json, <prefix>_map.svg/.png.
/// @return the paths written. @throws Error when a file cannot be written.
std::vector<std::string> writeMissionOutputs(const MissionResult &result, const MissionProblem &problem);

/// @brief Human-readable report of a mission run for the terminal: departure (and the departure search's counts),
/// travel time (2-D and with dive profiles), path length, straight-line time or "impassable", waypoints
/// raw/smoothed, CFC/CMC, wall times, the waypoint table with the dive profile per leg, the speed sweep and the
/// files written.
void printMissionReport(std::ostream &out, const MissionResult &result);

/// @brief Options of runMissionFile() (the CLI's flags).
struct MissionCommandOptions
{
    std::optional<std::vector<double>> speeds;   ///< --speeds: speed sweep (overrides the mission's)
    std::optional<std::string> outputDirectory;  ///< --out: overrides outputs.directory
    bool progress{true};                         ///< progress lines on stderr
};

/// @brief What `glider_plan --mission FILE` does: loadMission(), runMission() (writing the outputs) and
/// printMissionReport() on @p out; a configuration or I/O error is printed on @p err.
/// @return 0 when a path was found, 1 when the mission has no path, 2 on a configuration or I/O error.
int runMissionFile(const std::string &path, const MissionCommandOptions &options, std::ostream &out,
                   std::ostream &err);

/// @brief Parses a speed list "0.25,0.30,0.35" (--speeds). @throws Error naming the bad item.
std::vector<double> parseSpeedList(const std::string &text);

/// @brief Writes @p text to @p path. @throws Error naming the path on failure.
void writeTextFile(const std::string &path, const std::string &text);
}  // namespace ompl_glider

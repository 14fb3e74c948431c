#pragma once
/// @file Report.h
/// @brief The run as text for a terminal.

#include <ostream>
#include <string>
#include <vector>

#include "ompl_glider/mission/Planning.h"

namespace ompl_glider
{
/// @brief The speed sweep as a text table ([EichhornOceans] Table VI): speed, travel time, path length, straight-line
/// travel time ("impassable" when infinite) and length.
std::string speedSweepTable(const std::vector<SpeedSweepRow> &rows);

/// @brief The correction the glider's DAC made to the forecast, for a pilot (the report's "Correction:" lines; empty
/// without observations): the DAC used (and rejected, by reason), what the glider measured against the forecast on
/// average (speed and direction, m/s and kn), and how far and how long after the dives the plan uses it (the
/// correction's length and time scales); an ensemble's closest members. The statisticians' figures are
/// summary.json's `observations`.
std::vector<std::string> correctionLines(const MissionResult &result);

/// @brief Human-readable report: mission, planner, status (and why there is no path), departure (and the departure
/// search), travel time (raw, smoothed, final; with dive profiles), path length, straight line, waypoints, CFC and
/// CMC, wall times, the optimal-control reference, the waypoint table and the speed sweep.
/// With @p problem, every bearing (held headings, stints' bearings) from true north where the mission has lon/lat, as
/// the pilot files write them (trueHeadings()); without it, from the planning frame's grid north, said so.
void printReport(std::ostream &out, const MissionResult &result, const MissionProblem *problem = nullptr);
} // namespace ompl_glider

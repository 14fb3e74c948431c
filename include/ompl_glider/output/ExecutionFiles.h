#pragma once
/// @file ExecutionFiles.h
/// @brief Files of a mission's execution: execution.csv (one row per run and strategy),
/// execution_tracks.csv (the surfacings of the mission's own run, per strategy) and the box plot of the measures
/// per strategy over the runs (execution.svg / .png, like [ThompsonICRA] Fig. 8).

#include <string>

#include "ompl_glider/mission/Planning.h"

namespace ompl_glider
{
/// @brief One row per run and strategy: endpoints, departure, planned arrival, final distance, arrival (within
/// the radius), reached, grounded, speed made good, replans. Runs without a plan get one row with the reason.
std::string executionCsv(const ExecutionResult &e, const MissionProblem &problem);

/// @brief The mission's own run: the plan's waypoints (strategy "plan") and, per strategy, every surfacing (GPS
/// fix) with the heading chosen there (degrees clockwise from north) and the end of the run.
std::string executionTracksCsv(const ExecutionResult &e, const MissionProblem &problem);

/// @brief Box plots per strategy (median, quartiles, whiskers to the extremes) of the distance to the goal at the
/// planned arrival and of the arrival delay, over every run flown; SVG when @p svg, else PNG.
void writeExecutionPlot(const std::string &path, const ExecutionResult &e, const MissionSpec &m, bool svg);
} // namespace ompl_glider

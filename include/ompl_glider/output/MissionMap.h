#pragma once
/// @file MissionMap.h
/// @brief The map of a run: the current at departure (or outputs.map_time), forbidden regions, the planner's,
/// smoothed and final paths with time ticks, the optimal-control reference when computed, start and goal.

#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/MapRenderer.h"

namespace ompl_glider
{
/// @brief Draws the map of @p result on @p problem (write it with MapRenderer::writeSvg / writePng). A problem with
/// lon/lat (a forecast, or a projection) gives a map in longitude/latitude with a graticule and a scale bar; the map
/// then refers to @p problem, which must outlive it.
MapRenderer missionMap(const MissionResult &result, const MissionProblem &problem);

/// @brief The model-difference map of an execution with a truth: RMS over the runs' time window of
/// |c_truth - c_forecast| shaded over the box, the plan, the regions. Requires result.execution.
MapRenderer modelDifferenceMap(const MissionResult &result, const MissionProblem &problem);
} // namespace ompl_glider

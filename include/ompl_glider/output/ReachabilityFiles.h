#pragma once
/// @file ReachabilityFiles.h
/// @brief The files of the output format "reachability" (mission/ReachProbability.h): reachability.nc, the
/// probability of reach per frame on the level set's grid (CF-1.8 NetCDF), and reachability.geojson, its contours
/// per frame and level.

#include <string>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

namespace ompl_glider
{
/// @brief reachability.geojson: one Feature per (frame, level), a MultiLineString of the p = level contour (lon/lat
/// where the problem is geographic, split at the antimeridian), properties time, time_iso, since_departure, level.
std::string reachabilityGeoJson(const MissionResult &r);

/// @brief Writes reachability.nc to @p path (NetCDF-4, CF-1.8): dimensions time, y, x (member with
/// reachability.member_arrival), probability(time, y, x), lon/lat(y, x) where the problem is geographic, the
/// members' weights and goal arrivals, the goal's quantiles. (Only with OMPL_GLIDER_WITH_NETCDF.)
/// @throws Error naming the file when NetCDF-C refuses a call, or when the result has no reachability.
void writeReachabilityNetCdf(const std::string &path, const MissionResult &r, const MissionProblem &problem);
} // namespace ompl_glider

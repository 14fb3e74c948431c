#pragma once
/// @file RouteCommon.h (internal to src/output, not installed)
/// @brief What the route files (RouteFiles.cpp) and the goto list (GotoWaypoints.cpp) share.

#include "ompl_glider/mission/Planning.h"

namespace ompl_glider
{
namespace route_detail
{
/// The waypoints have lon/lat (the mission has a projection).
inline bool geographic(const MissionResult &r)
{
    return !r.waypoints.empty() && r.waypoints.front().geographic;
}
} // namespace route_detail
} // namespace ompl_glider

#pragma once
/// @file CurveLegs.h
/// @brief A timed curve through the plane (the level set's backtracked path, an extremal of Zermelo's heading law)
/// turned into straight legs a glider flies, timed by the travel-time code.

#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief A curve (a backtracked level-set path, LevelSetSolver; an extremal's track) as waypoints a glider flies:
/// thinned to straight legs within @p tolerance of the curve and free of forbidden regions, timed by the travel-time
/// code from the first point's time; holds kept where the glider can hold. Empty when no timing is feasible (@p why,
/// if given, says where).
std::vector<TimedPoint> legsAlongCurve(const GliderContext &ctx, const std::vector<TimedPoint> &path, double tolerance,
                                       std::string *why = nullptr);
} // namespace ompl_glider

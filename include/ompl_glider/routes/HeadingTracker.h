#pragma once
/// @file HeadingTracker.h
/// @brief A timed path (the level set's backtracked optimal path) followed by held headings, piece by piece: from
/// where the glider is, one held heading and its duration (Newton on the two of them) take it exactly to the next
/// point of the path; a piece that no single heading can fly is split at the path's points between. Errors cannot
/// build up along the way (every piece ends on the path), so long trips through sensitive flows (where a route shot
/// whole from the start diverges) are followed as closely as the path is resolved. Then the route can be refined
/// (refineHeadingRoute()).

#include <functional>
#include <string>
#include <vector>

#include "ompl_glider/execution/Reflight.h"
#include "ompl_glider/routes/HeadingRefiner.h"

namespace ompl_glider
{
/// @brief Follows @p path (start first, its last point the goal) with held headings, targets at least @p spacing
/// apart along it (x/y units), flights at @p settings.step (0: headingCheckStep() of the path's duration). The
/// result is checked as every heading route is (verifyHeadingRoute(): land, forbidden regions, region, the end within
/// settings.radius of @p goal); ok false with why when a piece cannot be flown even split down to the path's points.
/// @p flownBearings (may be null): when the path was flown by held headings (a search's points), the bearing flown
/// into each point (index 0 unused): the first guess of a piece between neighbouring points.
/// @brief One held heading and its duration that end a flight on a target: Newton on (bearing, duration) with
/// forward differences, the step halved while it does not reduce the miss. @p miss(bearing, duration) is the end of
/// the flight minus the target; @p bearing and @p duration are the first guess and the result. Returns the miss left.
double solveHeldHeading(const std::function<Point2(double, double)> &miss, double tolerance, double &bearing,
                        double &duration);

RefinedHeadings trackPathWithHeadings(const std::vector<TimedPoint> &path, Point2 goal, const GliderContext &ctx,
                                      const HeadingRefineSettings &settings, double spacing,
                                      const std::vector<double> *flownBearings = nullptr);

/// @brief Re-aims the last segment of @p route on the accurate re-flight (reflyHeadingRoute() with @p settings): Newton
/// on its bearing and duration with accurate flights from where the re-flown route begins it, until that flight ends
/// within 1e-3 @p radius of @p goal. For long routes through sensitive flows, where the planner's fixed-step flights
/// and the accurate ones part by more than the goal's radius. True when the accurate flight of the re-aimed route
/// then ends within @p radius of the goal (route and @p flight hold the result; flight.ends are the segment ends);
/// false leaves @p route unchanged.
bool reaimOnReflight(HeadingRoute &route, Point2 goal, const CurrentField &field, const Environment *forbidden,
                     const ReflightSettings &settings, double radius, HeadingReflight &flight);
} // namespace ompl_glider

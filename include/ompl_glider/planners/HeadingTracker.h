#pragma once
/// @file HeadingTracker.h
/// @brief A timed path (the level set's backtracked optimal path) followed by held headings, piece by piece: from
/// where the glider is, one held heading and its duration (Newton on the two of them) take it exactly to the next
/// point of the path; a piece that no single heading can fly is split at the path's points between. Errors cannot
/// build up along the way (every piece ends on the path), so long trips through sensitive flows (where a route shot
/// whole from the start diverges) are followed as closely as the path is resolved. Then the route can be refined
/// (refineHeadingRoute()).

#include <string>
#include <vector>

#include "ompl_glider/planners/HeadingRefiner.h"

namespace ompl_glider
{
/// @brief Follows @p path (start first, its last point the goal) with held headings, targets at least @p spacing
/// apart along it (x/y units), flights at @p settings.step (0: headingCheckStep() of the path's duration). The
/// result is checked as every heading route is (verifyHeadingRoute(): land, forbidden regions, region, the end within
/// settings.radius of @p goal); ok false with why when a piece cannot be flown even split down to the path's points.
/// @p flownBearings (may be null): when the path was flown by held headings (a search's points), the bearing flown
/// into each point (index 0 unused): the first guess of a piece between neighbouring points.
RefinedHeadings trackPathWithHeadings(const std::vector<TimedPoint> &path, Point2 goal, const GliderContext &ctx,
                                      const HeadingRefineSettings &settings, double spacing,
                                      const std::vector<double> *flownBearings = nullptr);
}  // namespace ompl_glider

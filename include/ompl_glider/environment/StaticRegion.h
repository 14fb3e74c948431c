#pragma once
/// @file StaticRegion.h
/// @brief A polygon forbidden at all times: an island, land, a restricted area.

#include "ompl_glider/environment/ForbiddenRegion.h"
#include "ompl_glider/environment/Polygon.h"

namespace ompl_glider
{
/// @brief A polygon (with holes, any number of vertices) that is forbidden at all times.
///
/// Method: exact segment-polygon intersection of Polygon::segmentIntersects (closed polygon: touching a vertex or
/// running along an edge counts as meeting it). Tolerance: the orientation filter of Polygon (about 1e-15
/// relative), resolved towards "blocked". Times are ignored. Obstacle avoidance near coasts: [IsernObstacles] Sec. II.
class StaticRegion : public ForbiddenRegion
{
public:
    /// @param kind "island", "land" or "restricted area" (free text, used in messages)
    StaticRegion(std::string name, Polygon polygon, std::string kind = "island");

    bool pointFree(double x, double y, double t) const override;
    bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override;
    bool isStatic() const override { return true; }

    /// @brief The polygon.
    const Polygon &polygon() const { return polygon_; }

private:
    Polygon polygon_;
};
} // namespace ompl_glider

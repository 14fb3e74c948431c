#pragma once
/// @file KeepOffZone.h
/// @brief The band within a keep-off distance of land: forbidden at all times, so that routes keep their distance
/// from coasts (land cells of a forecast, coastline polygons, islands).

#include <limits>
#include <memory>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/environment/ForbiddenRegion.h"

namespace ompl_glider
{
namespace environment_detail
{
class SegmentIndex;
}

/// @brief Every point closer than a distance d to land's boundary, given as straight edges of the planning frame.
///
/// Method: exact point-segment and segment-segment distances to the edges (a bucket index finds those within d).
/// A point is free when its distance to every edge is >= d; a leg when the smallest distance between it and every
/// edge is >= d, so a free leg keeps d from land all along (no sampling). Land itself is not part of the zone (the
/// field's land mask and the land polygons forbid it); a leg that crosses land meets an edge and is refused here
/// too. Times are ignored. Tolerance: rounding of the distances (about 1e-15 relative). The one test the planners,
/// the motion validator and the re-flights ask through Environment.
class KeepOffZone : public ForbiddenRegion
{
public:
    /// @param edges land's boundary (planning frame)
    /// @param distance keep-off distance d >= 0 (planning units); 0 keeps the zone empty (distances only)
    KeepOffZone(std::vector<Segment2> edges, double distance, std::string name = "land");
    ~KeepOffZone() override;

    bool pointFree(double x, double y, double t) const override;
    bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override;
    std::string whyBlocked(double x, double y, double t) const override;
    bool isStatic() const override { return true; }

    /// @brief Metres per planning unit (> 0): whyBlocked() then gives the distances in m or km; 0 (the default):
    /// in planning units.
    void setMetresPerUnit(double metres) { metresPerUnit_ = metres; }
    /// @brief The keep-off distance.
    double distance() const { return d_; }
    /// @brief True when there is no land edge.
    bool empty() const;
    /// @brief Distance from (x, y) to land's boundary (+inf without edges).
    double distanceTo(double x, double y) const;
    /// @brief Smallest distance from the leg (x1, y1) -> (x2, y2) to land's boundary (0 when it meets an edge).
    double legDistance(double x1, double y1, double x2, double y2) const;

private:
    std::unique_ptr<environment_detail::SegmentIndex> index_;
    double d_{0.0};
    double metresPerUnit_{0.0};
};

/// @brief Closest approach to land of a route: the smallest legDistance() over its legs, and where.
struct LandApproach
{
    double distance{std::numeric_limits<double>::quiet_NaN()}; ///< NaN: no route or no land
    Point2 where;                                              ///< the route's point nearest to land
};
/// @brief The closest approach of the polyline @p route (TimedPoints, times ignored) to @p zone's land.
LandApproach closestApproach(const KeepOffZone &zone, const std::vector<TimedPoint> &route);
} // namespace ompl_glider

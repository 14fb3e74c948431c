#pragma once
/// @file TimeWindowedZone.h
/// @brief A polygon forbidden only during given time intervals (a closed shipping lane, an exercise area).

#include <vector>

#include "ompl_glider/environment/ForbiddenRegion.h"
#include "ompl_glider/environment/Polygon.h"

namespace ompl_glider
{
/// @brief A polygon forbidden during closed time windows [a_k, b_k] and free otherwise.
///
/// Method (exact for the Environment's time model, time linear in arc length along a leg): the parameters
/// s in [0, 1] at which the leg is inside the polygon come from Polygon::segmentInsideIntervals; they map to the
/// time intervals t1 + s (t2 - t1) during which the glider is inside; the leg is blocked iff one of them
/// intersects a window (closed intervals: touching counts). Tolerance: the orientation filter of Polygon plus
/// rounding of t1 + s (t2 - t1) (relative 1e-15 of the times); no sampling.
class TimeWindowedZone : public ForbiddenRegion
{
public:
    /// @param windows closed intervals [lo, hi] with lo <= hi, in the field's time unit; overlapping windows are merged
    /// @throws ompl_glider::Error for an empty list, a non-finite bound or lo > hi (naming the zone and window)
    TimeWindowedZone(std::string name, Polygon polygon, std::vector<Interval> windows, std::string kind = "closure");

    bool pointFree(double x, double y, double t) const override;
    bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override;

    /// @brief The ends of the windows (Environment::releaseTimes()).
    std::vector<double> releaseTimes() const override;

    /// @brief The time intervals during which the leg is inside the polygon (whatever the windows).
    std::vector<Interval> insideTimes(double x1, double y1, double t1, double x2, double y2, double t2) const;

    /// @brief True when t is in a window.
    bool active(double t) const;

    /// @brief The polygon.
    const Polygon &polygon() const { return polygon_; }
    /// @brief The (sorted, merged) windows.
    const std::vector<Interval> &windows() const { return windows_; }

private:
    Polygon polygon_;
    std::vector<Interval> windows_;
};
} // namespace ompl_glider

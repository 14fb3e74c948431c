#pragma once
/// @file SegmentIndex.h
/// @brief Internal to environment/ (not installed): straight segments of the plane in a bucket index, and the
/// smallest distance from a segment (a leg, or a point as a segment of length 0) to them. KeepOffZone and
/// ForbiddenCells use it.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
namespace environment_detail
{
/// Distance from point p to segment ab.
double pointSegmentDistance(Point2 p, Point2 a, Point2 b);
/// Smallest distance between segments pq and ab: 0 when they meet (touching included; exact orientation signs up to
/// rounding), else the least of the four end-to-segment distances.
double segmentDistance(Point2 p, Point2 q, Point2 a, Point2 b);

class SegmentIndex
{
public:
    SegmentIndex() = default;
    /// @param cellHint wanted bucket side (for example the distance most queries look within); 0: automatic
    explicit SegmentIndex(std::vector<Segment2> segments, double cellHint = 0.0);

    bool empty() const { return segments_.empty(); }
    const std::vector<Segment2> &segments() const { return segments_; }
    /// The smallest distance from segment pq to the segments that may lie within @p radius of it: exact when it is
    /// <= radius; a value > radius (or +inf) means no segment is within radius.
    double within(Point2 p, Point2 q, double radius) const;
    /// The exact smallest distance from segment pq to the segments (+inf when there are none).
    double distance(Point2 p, Point2 q) const;

private:
    std::vector<Segment2> segments_;
    std::vector<std::uint32_t> start_, ids_; // bucket b holds ids_[start_[b] .. start_[b + 1])
    double x0_{0}, y0_{0}, side_{1}, diag_{0};
    std::size_t nx_{1}, ny_{1};
    std::size_t column(double x) const;
    std::size_t row(double y) const;
};
} // namespace environment_detail
} // namespace ompl_glider

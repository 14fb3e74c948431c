#pragma once
/// @file Polygon.h
/// @brief A closed polygon with holes and a uniform-grid edge index: point and segment tests for forbidden regions.

#include <cstdint>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief A closed interval [lo, hi] (of a segment parameter or of time); lo == hi is a single point.
struct Interval
{
    double lo{0.0};
    double hi{0.0};
};

/// @brief A polygon with any number of holes, taken as a CLOSED set: its boundary (outer ring and hole rings)
/// belongs to it, so a segment that only touches a vertex or runs along an edge meets the polygon.
///
/// Method. Inside = odd number of ring crossings of the ray from the point towards +x (even-odd rule over all
/// rings, so holes are the rings nested inside the outer ring), with points on any ring counted as inside.
/// Segment tests intersect the segment with every candidate edge: the parameters where it meets the boundary
/// split it into pieces that are wholly inside or wholly outside, classified by their midpoints
/// (segmentInsideIntervals); segmentIntersects() only asks whether any edge is met, else whether the start is inside.
/// Candidate edges come from a uniform grid over the bounding box (about one edge per cell; each edge is listed in
/// the cells it passes through, grown by a 1e-9 relative pad), so a 10,000-vertex coastline costs a few dozen edge
/// tests per query.
///
/// Tolerance. Orientations are determinants evaluated in double precision; a determinant whose magnitude is
/// below 8 DBL_EPSILON (|t1| + |t2|) (the rounding bound of its two products, cf. Shewchuk's orient2d filter)
/// is taken as zero, i.e. collinear. Exactly collinear or touching configurations are therefore always detected,
/// and near-ties (a point within about 1e-15 relative distance of the boundary) resolve to "on the boundary":
/// the test is conservative (it may call such a point forbidden, never the reverse by more than rounding).
///
/// Thread-safe for const use. Invalid input (a ring with fewer than 3 distinct vertices, a non-finite
/// coordinate, zero area) throws ompl_glider::Error naming the polygon and ring.
/// @brief How a Polygon checks its rings.
enum class RingCheck
{
    strict,    ///< no two edges meet except consecutive edges of one ring at their shared vertex
    validated, ///< the caller has checked the rings (GEOS's validity in the coordinates given, which lets a hole
               ///< touch the outer ring or another hole at a point): only finite vertices and a positive area
};

class Polygon
{
public:
    /// @brief Build from the outer ring and optional holes. Rings may be closed (last == first) or open, in any
    /// orientation. Holes must lie inside the outer ring and not overlap each other (not checked).
    /// @param name used in error messages
    /// @param check RingCheck::strict (the default) refuses rings that cross or touch, naming the two edges
    explicit Polygon(std::vector<Point2> outer, std::vector<std::vector<Point2>> holes = {},
                     const std::string &name = "polygon", RingCheck check = RingCheck::strict);

    /// @brief An axis-aligned rectangle [xMin, xMax] x [yMin, yMax].
    static Polygon rectangle(double xMin, double yMin, double xMax, double yMax, const std::string &name = "rectangle");

    /// @brief A regular n-gon inscribed in the circle of centre (cx, cy) and radius r (first vertex at angle phase).
    static Polygon regular(double cx, double cy, double r, int n, double phase = 0.0,
                           const std::string &name = "polygon");

    /// @brief True when (x, y) is inside or on the boundary.
    bool contains(double x, double y) const;

    /// @brief True when the closed segment (ax, ay)-(bx, by) has at least one point in the polygon (touching counts).
    bool segmentIntersects(double ax, double ay, double bx, double by) const;

    /// @brief The parameters s in [0, 1] at which a + s (b - a) is in the polygon, as sorted disjoint closed
    /// intervals (a touch at a single vertex gives a degenerate interval [s, s]).
    std::vector<Interval> segmentInsideIntervals(double ax, double ay, double bx, double by) const;

    /// @brief Signed Euclidean distance from (x, y) to the polygon's boundary (outer ring and holes): positive
    /// inside, negative outside, 0 on it. Exact (minimum over every edge of the point-segment distance, sign by
    /// contains()); cost linear in the number of edges. Used by the level-set planner to keep its front out of the
    /// polygon ([LollaLevelSet]; obstacles enter as phi = max(phi, d)).
    double signedDistance(double x, double y) const;
    /// @brief Bounding box of the outer ring.
    const Box &bounds() const { return box_; }
    /// @brief Total number of vertices (outer ring and holes).
    std::size_t vertexCount() const { return edges_.size(); }
    /// @brief Number of holes.
    std::size_t holeCount() const { return holes_; }
    /// @brief Area (outer ring minus holes).
    double area() const { return area_; }
    /// @brief Every edge of the outer ring and the holes.
    std::vector<Segment2> edges() const
    {
        std::vector<Segment2> out;
        out.reserve(edges_.size());
        for (const Edge &e : edges_)
            out.push_back({{e.ax, e.ay}, {e.bx, e.by}});
        return out;
    }
    /// @brief The outer ring (open: last != first).
    const std::vector<Point2> &outer() const { return outer_; }

private:
    struct Edge
    {
        double ax, ay, bx, by;
    };
    void buildIndex();
    /// Calls f(cell) for every grid cell the segment (padded) may touch.
    template <typename F> void forEachCell(double ax, double ay, double bx, double by, F &&f) const;
    int column(double x) const;
    int row(double y) const;
    /// Candidate edges for the segment (sorted, unique).
    void segmentCandidates(double ax, double ay, double bx, double by, std::vector<std::uint32_t> &out) const;

    std::vector<Point2> outer_;
    std::vector<Edge> edges_;
    std::size_t holes_{0};
    double area_{0.0};
    Box box_;
    // uniform grid (CSR layout): cell (i, j) -> edges cellEdges_[cellStart_[c] .. cellStart_[c + 1])
    int nx_{1}, ny_{1};
    double cellW_{1.0}, cellH_{1.0}, pad_{0.0};
    std::vector<std::uint32_t> cellStart_;
    std::vector<std::uint32_t> cellEdges_;
};
} // namespace ompl_glider

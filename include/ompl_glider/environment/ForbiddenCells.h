#pragma once
/// @file ForbiddenCells.h
/// @brief A union of grid cells forbidden at all times (water shallower than a depth limit, from a bathymetry grid).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/environment/ForbiddenRegion.h"

namespace ompl_glider
{
namespace environment_detail
{
class SegmentIndex;
}

/// @brief The union of the forbidden cells of a grid of nx x ny nodes placed in the planning frame; each cell is the
/// quadrilateral of its four nodes with straight edges (closed: its boundary is forbidden too).
///
/// Method: a point is blocked when it lies in a forbidden cell (bucket index of the cells, crossing-number test); a
/// leg is free when its start is free and it meets no boundary edge of the union (edges between a forbidden cell and
/// a free one or the outside): exact, whatever the cell size. Outside the grid nothing is forbidden. Times are
/// ignored. Tolerance: rounding of the orientation tests, resolved towards "blocked".
class ForbiddenCells : public ForbiddenRegion
{
public:
    /// @param nodes node positions [j * nx + i] (non-finite nodes: their cells are left out)
    /// @param forbidden cell flags [j * (nx - 1) + i], 1 = forbidden
    /// @throws Error when the sizes do not fit
    ForbiddenCells(std::string name, std::string kind, std::size_t nx, std::size_t ny, std::vector<Point2> nodes,
                   const std::vector<std::uint8_t> &forbidden);
    ~ForbiddenCells() override;

    bool pointFree(double x, double y, double t) const override;
    bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override;
    bool isStatic() const override { return true; }
    /// @brief Number of forbidden cells.
    std::size_t cellCount() const { return cells_.size(); }
    /// @brief The boundary edges of the union.
    const std::vector<Segment2> &boundary() const;

private:
    std::size_t nx_;
    std::vector<Point2> nodes_;
    std::vector<std::uint32_t> cells_; // forbidden cell ids j * (nx - 1) + i
    std::unique_ptr<environment_detail::SegmentIndex> edges_;
    // cells in buckets
    std::vector<std::uint32_t> start_, ids_;
    double x0_{0}, y0_{0}, side_{1};
    std::size_t bnx_{1}, bny_{1};
    bool inCell(std::uint32_t c, double x, double y) const;
};
} // namespace ompl_glider

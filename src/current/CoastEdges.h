#pragma once
/// @file CoastEdges.h
/// @brief The boundary of the water of a gridded field, per depth layer, with a bucket index: the cell edges between
/// a water cell and a land cell, and the grid's outer edges next to a water cell. GriddedCurrentField uses it to
/// check a straight leg exactly (segmentInWater()). Internal; not installed.
///
/// Why this is exact: inside the grid, whether a point is in water changes only across an edge between a water
/// cell and a land cell, and at the grid's outer edge. Between two consecutive parameters at which a segment meets
/// such an edge it is therefore all in water or all on land, and one test at the middle of that piece decides it.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace ompl_glider
{
namespace detail
{
class CoastEdges
{
public:
    /// @brief Node position of node n = j * nx + i.
    using NodeXY = std::function<void(std::size_t n, double &x, double &y)>;

    CoastEdges() = default;

    /// @brief Builds the edges of every layer from the cell mask cellWater[(k * (ny - 1) + j) * (nx - 1) + i]
    /// (1 = water) of nz layers, on nx x ny nodes placed by @p node, the nodes lying in [x0, x1] x [y0, y1].
    void build(std::size_t nx, std::size_t ny, std::size_t nz, const std::vector<std::uint8_t> &cellWater,
               const NodeXY &node, double x0, double x1, double y0, double y1);

    /// @brief Appends to @p s the parameters in [0, 1] at which the segment (ax, ay) -> (bx, by) meets a boundary
    /// edge of layer @p k (both ends of an overlap for an edge along the segment).
    void meet(std::size_t k, double ax, double ay, double bx, double by, std::vector<double> &s) const;

    /// @brief Edges of layer k (for tests and memory accounting).
    std::size_t edgeCount(std::size_t k) const { return layers_[k].edges.size(); }
    /// @brief Bytes held.
    std::size_t memoryBytes() const;

private:
    struct Edge
    {
        double ax, ay, bx, by;
    };
    struct Layer
    {
        std::vector<Edge> edges;
        std::vector<std::uint32_t> start; ///< bucket b holds ids[start[b] .. start[b + 1])
        std::vector<std::uint32_t> ids;
    };
    std::vector<Layer> layers_;
    double x0_{0}, y0_{0}, inv_{1};
    std::size_t bnx_{1}, bny_{1};
};
} // namespace detail
} // namespace ompl_glider

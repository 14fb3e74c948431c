#pragma once
/// @file GriddedCurrentField.h
/// @brief A current field interpolated from gridded forecast data ([EichhornOceans] Sec. II.C, [EichhornRAS] Sec.
/// 3.4.2).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ompl_glider/current/BeyondForecast.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/Interpolation.h"

namespace ompl_glider
{
namespace detail
{
class CoastEdges;
}

/// @brief Interpolation schemes and policies of a gridded field.
struct GriddedFieldOptions
{
    Interp2D xy{Interp2D::Bilinear};               ///< horizontal scheme (first step of [EichhornOceans] Fig. 2)
    Interp1D depth{Interp1D::Linear};              ///< depth scheme (second step)
    Interp1D time{Interp1D::Linear};               ///< time scheme (third step)
    BeyondForecast beyond{BeyondForecast::Refuse}; ///< policy after the last forecast time
    std::string name{"gridded"};                   ///< returned by name()
};

/// @brief Gridded current data in the local Cartesian frame, ready for GriddedCurrentField.
///
/// Horizontal grid: either rectilinear (axes x and y, each strictly increasing) or curvilinear (nodeX/nodeY of
/// size ny*nx, index [j*nx + i], any quadrilateral mesh without folds). Velocities u (along x) and v (along y)
/// are stored at index [((t * nz + k) * ny + j) * nx + i]; water (optional) marks water nodes (1) and land /
/// fill nodes (0) at index [(k * ny + j) * nx + i].
struct GriddedData
{
    std::size_t nx{0};               ///< nodes along x (i)
    std::size_t ny{0};               ///< nodes along y (j)
    std::vector<double> x;           ///< rectilinear x axis (size nx), empty when curvilinear
    std::vector<double> y;           ///< rectilinear y axis (size ny), empty when curvilinear
    std::vector<double> nodeX;       ///< curvilinear node x (size ny*nx), empty when rectilinear
    std::vector<double> nodeY;       ///< curvilinear node y (size ny*nx), empty when rectilinear
    std::vector<double> depth{0.0};  ///< depth layers, positive down, strictly increasing (one layer: 2-D field)
    std::vector<double> time{0.0};   ///< forecast times, strictly increasing (one time: steady field)
    std::vector<float> u;            ///< velocity along x at the nodes
    std::vector<float> v;            ///< velocity along y at the nodes
    std::vector<std::uint8_t> water; ///< 1 = water, 0 = land/fill; empty means all water
};

/// @brief The ocean-current model of [EichhornOceans] Sec. II.C: horizontal interpolation on each depth layer and
/// forecast time, then 1-D interpolation in depth, then in time, each with its own scheme (GriddedFieldOptions).
///
/// - Rectilinear grids interpolate in x/y directly (non-uniform axes allowed). Curvilinear grids (and
///   geographic grids after projection) first locate the point: a bucket index gives a start cell, then a walk
///   over cells solving the inverse bilinear map of each quadrilateral by Newton's method gives fractional
///   indices (fi, fj); the schemes then run in index space, and the Jacobian is chained with the inverse of
///   d(x, y)/d(fi, fj) of the cell's bilinear map.
/// - Land: nodes marked land hold zero velocity (a no-slip coast), so velocity() never returns a fill value;
///   next to land it interpolates between the water values and these zeros. inWater() is false outside the
///   grid and in every cell (at the depth layers that carry weight) with a land corner: a coastal band up to
///   one cell wide is forbidden, which keeps planners off any cell whose interpolant touches land.
/// - Queries outside the grid, above the first / below the last layer, or before the first time are clamped
///   to the grid (no extrapolation). After the last time: BeyondForecast.
/// - Jacobian: analytic from the interpolants' derivative weights (piecewise: one-sided at cell edges); with
///   an Akima depth or time scheme (nonlinear in the data) by central differences with a step of 1e-4 of the
///   mean cell size.
/// - maxSpeed(): largest |c| of the stored nodes in the region's time window (plus the stencil margin; all
///   loaded depth layers, whatever the region's depth range; all nodes in x/y) times the
///   product of the schemes' overshoot factors (overshootFactor(): 1 for nearest/linear/bilinear, about 1.25
///   per cubic axis, about 1.6 for Akima, which is applied per component so the node bound is then
///   hypot(max|u|, max|v|)), or, when smaller, the data-dependent bound M + D (K_xy + K_z L_xy + K_t L_xy L_z)
///   with M the largest node speed, D the largest diameter of the node velocities within one interpolation
///   stencil box, L the stages' overshoot factors and K = (L - 1) / 2 (see maxSpeed() in GriddedBounds.cpp for the
///   argument): both are true upper bounds of what velocity() can return; the second is close to M for
///   smooth data even with cubic/Akima schemes on uneven axes.
class GriddedCurrentField : public CurrentField, public FieldGrid
{
public:
    /// @brief Validates the data (sizes, monotone axes, finite values at water nodes) and builds the locator.
    /// @throws Error naming the inconsistent piece.
    GriddedCurrentField(GriddedData data, GriddedFieldOptions options = {});

    double maxSpeed(const Region &region) const override;
    /// @brief Node minimum and maximum of u and v over the nodes whose interpolation stencils can serve the region
    /// (the forecast records bracketing the time window, all loaded depth layers): true bounds of velocity() when
    /// every scheme is a convex combination of nodes (nearest or bilinear horizontally; nearest or linear in depth
    /// and time). Rectilinear grids: the nodes of the cells the region overlaps (x, y clamped to the grid).
    /// Curvilinear grids (geographic forecasts after projection): the nodes of the blocks of 8 x 8 cells whose
    /// bounding boxes meet the region, when the region's centre lies in the grid and none of these blocks touches
    /// the grid's edge (then every point of the region lies in one of their cells, since a region reaching outside
    /// would cross the edge); else the nodes of the whole grid. False for cubic or Akima schemes (their overshoot
    /// would need the margin of maxSpeed()).
    bool velocityBounds(const Region &region, double &uMin, double &uMax, double &vMin, double &vMax) const override;
    bool hasVelocityBounds() const override;
    bool inWater(double x, double y, double z) const override;
    double timeBegin() const override;
    double timeEnd() const override;
    std::string name() const override { return options_.name; }
    const FieldGrid *grid() const override { return this; }
    const std::vector<double> &recordTimes() const override { return time_.nodes(); }
    bool covers(double x, double y) const override
    {
        double fi, fj;
        return locate(x, y, fi, fj);
    }

    /// @brief The options in use.
    const GriddedFieldOptions &options() const { return options_; }
    /// @brief True for a curvilinear (or projected geographic) grid.
    bool curvilinear() const { return curvilinear_; }
    /// @brief Grid sizes.
    std::size_t nx() const { return nx_; }
    std::size_t ny() const { return ny_; }
    std::size_t nz() const { return depth_.size(); }
    std::size_t nt() const { return time_.size(); }
    /// @brief Depth and time axes.
    const Axis &depthAxis() const { return depth_; }
    const Axis &timeAxis() const { return time_; }
    /// @brief Bounding box of the grid nodes in x/y (z and t: depth and time ranges).
    Region extent() const override;
    /// @brief Bytes held by the velocity arrays, mask and node positions.
    std::size_t memoryBytes() const;
    /// @brief The product of the schemes' overshoot factors used by maxSpeed().
    double overshoot() const { return overshoot_; }
    /// @brief True when the straight segment stays in water (inWater()) at depth z, decided exactly: the segment is
    /// cut where it meets the boundary of the water (edges between a water cell and a land cell, and the grid's
    /// outer edges, of the depth layers that carry weight at z), and each piece is tested once at its middle. A
    /// segment that clips a corner of a land cell is refused however small the clipped part (the only tolerance is
    /// 1e-12 relative, in the intersection tests). For environment/planner code that must keep whole legs off land
    /// (the travel-time code asks it once per leg).
    bool segmentInWater(double x1, double y1, double x2, double y2, double z) const override;
    /// @brief The edges between a water cell and a land cell (a cell is land at z when it is land in any depth
    /// layer that carries weight at z, as inWater() decides), straight between their nodes.
    std::vector<Segment2> landBoundary(double z) const override;
    /// @brief Smallest distance between neighbouring grid nodes (x/y units).
    double minCellSize() const override { return minCell_; }
    /// @brief Fractional grid indices (fi, fj) of (x, y); false when the point is outside the grid (the indices
    /// are then those of the nearest boundary point of the last cell visited).
    bool locate(double x, double y, double &fi, double &fj) const;

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    struct Sample
    {
        double u{0}, v{0}, ui{0}, uj{0}, vi{0}, vj{0};
    };
    struct Horizontal
    {
        Stencil sx, sy;
        double m[4]{1, 0, 0, 1}; ///< d(fi, fj)/d(x, y) for curvilinear grids: [dfi/dx, dfi/dy, dfj/dx, dfj/dy]
    };
    Horizontal horizontal(double x, double y, bool derivative) const;
    template <bool Deriv> Sample spatial(const Horizontal &h, std::size_t it, std::size_t iz) const;
    template <bool Deriv> Sample depthCombined(const Horizontal &h, std::size_t it, double z) const;
    template <bool Deriv> Sample full(double x, double y, double z, double t) const;
    double clampTime(double t) const;
    /// Depth layers k0..k1 that carry weight at depth z (both 0 for a single layer).
    void waterLayers(double z, std::size_t &k0, std::size_t &k1) const;
    bool cellInside(std::size_t ci, std::size_t cj, double px, double py, double &a, double &b) const;
    // construction (GriddedCurrentField.cpp), the locator (GriddedLocator.cpp), bounds (GriddedBounds.cpp)
    void storeVelocities(const GriddedData &d, const std::string &who);
    void computeMinCell(const std::string &who);
    void buildLocator();
    void computeStencilDiameters();

    GriddedFieldOptions options_;
    std::uint64_t id_{0}; // unique per instance (key of the per-thread locate hint)
    bool curvilinear_{false};
    std::size_t nx_{0}, ny_{0};
    Axis x_, y_; // rectilinear axes, or index axes 0..n-1 when curvilinear
    Axis depth_, time_;
    std::vector<double> nodeX_, nodeY_;
    std::vector<float> uv_;                                     // interleaved u, v
    std::vector<std::uint8_t> cellWater_;                       // [(k * (ny-1) + j) * (nx-1) + i]
    std::shared_ptr<const detail::CoastEdges> coast_;           // boundary of the water per layer (segmentInWater)
    std::vector<double> layerMaxSpeed_, layerMaxU_, layerMaxV_; // per (t, k)
    double overshoot_{1.0};
    double lamXY_{1.0}, lamZ_{1.0}, lamT_{1.0}; // overshoot factors of the three stages
    std::vector<double> boxDiameter_;           // per time index: largest diameter of a stencil box starting there
    double fdStep_{1e-6};
    double minCell_{1.0};
    // locator for curvilinear grids
    double bx0_{0}, by0_{0}, bInv_{1};
    std::size_t bnx_{0}, bny_{0};
    std::vector<std::int32_t> bucket_; // start cell (j * (nx-1) + i) or -1
    double xMin_{0}, xMax_{0}, yMin_{0}, yMax_{0};
    /// Curvilinear grids: blocks of kBlock x kBlock cells with the bounding box of their nodes, whether they touch
    /// the grid's edge, and the extremes of u and v over their nodes per forecast record (velocityBounds()); a
    /// bucket grid over the nodes' bounding box lists the blocks meeting each bucket.
    struct Blocks
    {
        static constexpr std::size_t kBlock = 8;
        std::size_t nbi{0}, nbj{0};
        std::vector<double> box;         // per block: xMin, xMax, yMin, yMax
        std::vector<unsigned char> edge; // per block: touches the grid's edge
        std::vector<float> ext;          // per (record, block): uMin, uMax, vMin, vMax
        std::vector<float> all;          // per record: extremes over every node
        double bx0{0}, by0{0}, bdx{1}, bdy{1};
        std::size_t bnx{1}, bny{1};
        std::vector<std::vector<std::uint32_t>> buckets;
    };
    Blocks blocks_;
    void buildBlocks();
    /// Widens e = {uMin, uMax, vMin, vMax} by the nodes of the curvilinear grid that can serve the region in the
    /// records t0..t1 (see velocityBounds()).
    void curvilinearExtremes(const Region &region, std::size_t t0, std::size_t t1, float *e) const;
};
} // namespace ompl_glider

#pragma once
/// @file CurrentField.h
/// @brief Interface of an ocean-current (or wind) field c(x, y, z, t).

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/ShardedCounter.h"

namespace ompl_glider
{
/// @brief Spatial Jacobian of the horizontal current (needed by Zermelo's navigation law, [EichhornRAS] Eq. 2).
struct Jacobian
{
    double ux{0.0}; ///< du/dx
    double uy{0.0}; ///< du/dy
    double vx{0.0}; ///< dv/dx
    double vy{0.0}; ///< dv/dy
};

/// @brief An axis-aligned region of space and a time window; used to bound the current speed.
struct Region
{
    double xMin{-std::numeric_limits<double>::infinity()};
    double xMax{std::numeric_limits<double>::infinity()};
    double yMin{-std::numeric_limits<double>::infinity()};
    double yMax{std::numeric_limits<double>::infinity()};
    double zMin{0.0}; ///< depth range (positive down)
    double zMax{0.0};
    double tMin{-std::numeric_limits<double>::infinity()};
    double tMax{std::numeric_limits<double>::infinity()};
};

/// @brief What a field given on a grid of nodes tells of its grid: what the pipeline asks of any gridded source (a
/// forecast file read by the NetCDF reader, or data built in memory), never its concrete type.
class FieldGrid
{
public:
    virtual ~FieldGrid() = default;
    /// @brief Bounding box of the nodes in x/y (z: the depth range, t: the time range).
    virtual Region extent() const = 0;
    /// @brief Smallest distance between neighbouring nodes (x/y units).
    virtual double minCellSize() const = 0;
    /// @brief The times of the records, ascending (one record: a steady field).
    virtual const std::vector<double> &recordTimes() const = 0;
    /// @brief True when (x, y) lies on the grid (within its outer edge), whether land or water there.
    virtual bool covers(double x, double y) const = 0;
};

/// @brief A horizontal current field c(x, y, z, t) in a local Cartesian frame.
///
/// Coordinates are metres and seconds for real forecasts, dimensionless for analytic test flows.
/// Every query through velocity() or jacobian() counts one current-model call (CMC, [EichhornRAS] Table 4);
/// the counter (ShardedCounter) is exact and cheap when several threads query the same field.
/// Implementations override evaluate() / evaluateJacobian() and must be thread-safe for const use.
class CurrentField
{
public:
    virtual ~CurrentField() = default;

    /// @brief Current at (x, y, depth z, time t). Counts one CMC.
    Velocity velocity(double x, double y, double z, double t) const
    {
        calls_.add();
        return evaluate(x, y, z, t);
    }

    /// @brief Spatial Jacobian at (x, y, z, t). Counts one CMC.
    Jacobian jacobian(double x, double y, double z, double t) const
    {
        calls_.add();
        return evaluateJacobian(x, y, z, t);
    }

    /// @brief The current at one point asked once (a glider's heading at a surfacing): velocity(), to the accuracy of
    /// the field's own sampling. A field that prepares for many queries (CorrectedField's sampled grid) answers it
    /// without preparing. Counts one CMC.
    virtual Velocity velocityOnce(double x, double y, double z, double t) const { return velocity(x, y, z, t); }

    /// @brief An upper bound of |c| over the region and time window (the A*TVE heuristic, [EichhornRAS] Eq. 1).
    virtual double maxSpeed(const Region &region) const = 0;

    /// @brief Local bounds of the current components over a region of space and time, where the field can give
    /// them cheaply without sampling itself (no CMC): true with every velocity() value over the region (x, y,
    /// the time window, any depth) inside [uMin, uMax] x [vMin, vMax]; false = no local bound (the caller falls
    /// back to maxSpeed()). Used by the lattice search's lower bounds (LatticeHeuristic).
    virtual bool velocityBounds(const Region & /*region*/, double & /*uMin*/, double & /*uMax*/, double & /*vMin*/,
                                double & /*vMax*/) const
    {
        return false;
    }
    /// @brief True when velocityBounds() gives local bounds (it would return true).
    virtual bool hasVelocityBounds() const { return false; }

    /// @brief Stream function psi with u = -dpsi/dy, v = dpsi/dx, where the field has one.
    virtual std::optional<double> streamFunction(double /*x*/, double /*y*/, double /*z*/, double /*t*/) const
    {
        return std::nullopt;
    }

    /// @brief True when the field should be divergence-free (u_x + v_y = 0).
    virtual bool divergenceFree() const { return false; }

    /// @brief False where the field has no water (land / fill cells of a forecast). Travel-time code treats such
    /// points as forbidden and never reads a current there. Does not count as a CMC.
    virtual bool inWater(double /*x*/, double /*y*/, double /*z*/) const { return true; }

    /// @brief True when the whole straight segment (x1, y1) -> (x2, y2) at depth z stays in water. The travel-time
    /// code asks this once per leg, so a leg never crosses land between its integration steps. The default checks
    /// the two ends (exact for fields whose inWater() is true everywhere); gridded fields override it.
    virtual bool segmentInWater(double x1, double y1, double x2, double y2, double z) const
    {
        return inWater(x1, y1, z) && inWater(x2, y2, z);
    }

    /// @brief The boundary between water and land at depth z, as straight edges of the plane: the edges between a
    /// cell inWater() refuses and one it accepts (not the field's outer edges). The distance to land of the
    /// keep-off zone (environment/KeepOffZone.h) and of the report is measured to these edges. Empty by default
    /// (fields without land).
    virtual std::vector<Segment2> landBoundary(double /*z*/) const { return {}; }

    /// @brief Earliest time at which the field is defined (-inf for analytic fields).
    virtual double timeBegin() const { return -std::numeric_limits<double>::infinity(); }
    /// @brief Latest time at which the field is defined (+inf for analytic fields or a "hold last" policy).
    /// Travel-time code treats a leg that would need the field after this time as infeasible.
    virtual double timeEnd() const { return std::numeric_limits<double>::infinity(); }

    /// @brief Short human-readable name ("meandering jet", "netcdf:file.nc", ...).
    virtual std::string name() const = 0;

    /// @brief The grid of nodes the field is given on; null for a field given by formulas (the default).
    virtual const FieldGrid *grid() const { return nullptr; }

    /// @brief Number of current-model calls (CMC) so far.
    std::uint64_t callCount() const { return calls_.load(); }
    /// @brief Reset the CMC counter to zero.
    void resetCallCount() const { calls_.reset(); }

protected:
    /// @brief The field itself: velocity at (x, y, z, t). Must not count calls.
    virtual Velocity evaluate(double x, double y, double z, double t) const = 0;
    /// @brief The field's spatial Jacobian at (x, y, z, t). Must not count calls.
    virtual Jacobian evaluateJacobian(double x, double y, double z, double t) const = 0;

private:
    mutable ShardedCounter calls_;
};
} // namespace ompl_glider

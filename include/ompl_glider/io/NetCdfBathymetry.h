#pragma once
/// @file NetCdfBathymetry.h
/// @brief Seafloor depth from a NetCDF grid, limiting the glider's dives ([EichhornOceans] Sec. III).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/io/Bathymetry.h"

namespace ompl_glider
{
/// @brief A 2-D seafloor-depth variable var(y, x) on 1-D axes (lat/lon in degrees, or x/y in planning units),
/// bilinearly interpolated. Depth is positive down; a variable with the attribute positive = "up" (elevation,
/// e.g. GEBCO) is negated. Fill values and depths <= 0 are land (depth 0). Outside the grid the nearest edge value
/// is used.
///
/// For geographic axes, queries in the planning frame are converted with @p toGeographic, which returns the
/// (lon, lat) of a planning-frame point (x, y) (for example MissionProblem::toGeographic) and the longitude shifted
/// by whole turns into the file's convention (0..360 or -180..180); without it the axes are taken as planning x/y.
class NetCdfBathymetry : public Bathymetry
{
public:
    /// @throws Error "NetCDF file '<path>': ..." naming the variable when the file, the variable or its axes cannot be
    /// read (every NetCDF-C call is checked), the variable is not 2-D, an axis is not a 1-D coordinate variable of
    /// its dimension or not strictly monotonic, or the axes are longitude/latitude without @p toGeographic.
    NetCdfBathymetry(const std::string &path, const std::string &variable,
                     std::function<LonLat(double x, double y)> toGeographic = {});

    double seafloorDepth(double x, double y) const override;

    /// @brief Depth at axis coordinates (a, b) = (lon, lat) or (x, y).
    double atAxes(double a, double b) const;
    /// @brief True when the axes are longitude/latitude.
    bool geographic() const
    {
        return geographic_;
    }

private:
    std::vector<double> ax_, ay_;  // ascending axes (x: lon or x, y: lat or y)
    std::vector<double> depth_;    // [j * nx + i]
    bool geographic_{false};
    std::function<LonLat(double, double)> toGeographic_;
};
}  // namespace ompl_glider

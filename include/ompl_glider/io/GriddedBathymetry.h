#pragma once
/// @file GriddedBathymetry.h
/// @brief Seafloor depth from a NetCDF grid, limiting the glider's dives ([EichhornOceans] Sec. III).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/io/Bathymetry.h"
#include "ompl_glider/io/DepthGrid.h"

namespace ompl_glider
{
/// @brief A 2-D seafloor-depth variable on 1-D axes (lat/lon in degrees, or x/y in planning units), read by
/// readDepthGrid() (its sign rule, dimension order and checks, the same as the depth limit's) and bilinearly
/// interpolated. Fill values and depths <= 0 are land (depth 0). Outside the grid the nearest edge value is used.
///
/// For geographic axes, queries in the planning frame are converted with @p toGeographic, which returns the
/// (lon, lat) of a planning-frame point (x, y) (for example MissionProblem::toGeographic) and the longitude shifted
/// by whole turns into the file's convention (0..360 or -180..180); without it the axes are taken as planning x/y.
class GriddedBathymetry : public Bathymetry
{
public:
    /// @param variable the depth variable; empty: found as readDepthGrid() finds it
    /// @param region the lon/lat box read of a geographic grid (default: the whole grid)
    /// @throws Error "NetCDF file '<path>': ..." naming the variable as readDepthGrid() does, or when the grid is on
    /// 2-D longitude/latitude, or on longitude/latitude without @p toGeographic.
    GriddedBathymetry(const std::string &path, const std::string &variable,
                      std::function<LonLat(double x, double y)> toGeographic = {},
                      const GeoBox &region = GeoBox::world());

    double seafloorDepth(double x, double y) const override;

    /// @brief Depth at axis coordinates (a, b) = (lon, lat) or (x, y).
    double atAxes(double a, double b) const;
    /// @brief True when the axes are longitude/latitude.
    bool geographic() const { return geographic_; }
    /// @brief The variable read, and how its sign was decided (DepthGrid::convention).
    const std::string &variable() const { return variable_; }
    const std::string &convention() const { return convention_; }

private:
    std::vector<double> ax_, ay_; // ascending axes (x: lon or x, y: lat or y)
    std::vector<double> depth_;   // [j * nx + i]
    bool geographic_{false};
    std::string variable_, convention_;
    std::function<LonLat(double, double)> toGeographic_;
};
} // namespace ompl_glider

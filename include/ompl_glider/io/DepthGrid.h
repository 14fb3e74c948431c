#pragma once
/// @file DepthGrid.h
/// @brief A seafloor-depth grid read from a NetCDF file for the depth limit: GEBCO/ETOPO-style files (1-D lon/lat
/// axes, elevation or depth) and a model's own bathymetry (ROMS `h` on 2-D lon_rho/lat_rho).

#include <cstddef>
#include <string>
#include <vector>

#include "ompl_glider/io/GeoBox.h"

namespace ompl_glider
{
/// @brief Nodes and seafloor depths of a bathymetry file, cut to a region.
struct DepthGrid
{
    std::size_t nx{0}, ny{0};  ///< nodes along i and j
    std::vector<double> a, b;  ///< node coordinates [j * nx + i]: lon/lat (degrees) when geographic, else x/y
    std::vector<double> depth; ///< seafloor depth, metres positive down (negative on land); NaN for fill values
    bool geographic{true};     ///< the coordinates are lon/lat
    bool rectilinear{false};   ///< on 1-D axes: a ascends along i (the same for every j), b along j
    std::string variable;      ///< the variable read
    std::string convention;    ///< how its sign was decided ("elevation, positive up (attribute positive)")
};

/// @brief Reads the depth variable @p variable (empty: the first 2-D variable whose standard_name or name says it is
/// a depth or an elevation: sea_floor_depth*, height_above_*, altitude; depth, h, bathymetry, elevation, z, topo,
/// rose) on 1-D axes (coordinate variables of its two dimensions) or 2-D lon/lat (its `coordinates` attribute, or
/// lon_rho/lat_rho). Its sign is decided by the attribute `positive`, else its standard_name, else its name, else
/// its long_name ("depth"/"bathymetry" down; "elevation", "height", "altitude", "relief" up); a variable none of
/// these settle is refused. Which of its two dimensions is longitude/x is told by the coordinate variables (units
/// degrees_east/north, standard_name, axis X/Y, then the names lon*/lat*, x/y), so (lat, lon) and (lon, lat) are
/// both read right; axes that do not say are refused, never guessed from their ranges. 1-D geographic axes are cut to
/// @p region (one node beyond each side; a global axis across its seam); 2-D grids are kept whole.
/// @throws Error "NetCDF file '<path>': ..." naming the variable when the file, the variable or its coordinates
/// cannot be read, none is found, its sign is ambiguous, its axis order cannot be told, an axis repeats a value, no
/// node lies in the region, or the region holds only fill values or only land (the message names the sign
/// convention it was read with and the attribute that states the other).
DepthGrid readDepthGrid(const std::string &path, const std::string &variable, const GeoBox &region);
} // namespace ompl_glider

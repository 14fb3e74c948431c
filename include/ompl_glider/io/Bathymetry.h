#pragma once
/// @file Bathymetry.h
/// @brief The seafloor a glider's dives must stay above: the interface the dive profiles read
/// (cost/DiveProfile.h) and the readers implement (io/GriddedBathymetry.h).

#include <functional>
#include <memory>
#include <string>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/io/GeoBox.h"

namespace ompl_glider
{
/// @brief Seafloor depth (positive down) at a horizontal position; +inf where there is no limit.
/// Implementations must be thread-safe for const use.
class Bathymetry
{
public:
    virtual ~Bathymetry() = default;
    /// @brief Depth of the seafloor at (x, y); <= 0 means land.
    virtual double seafloorDepth(double x, double y) const = 0;
};

/// @brief The seafloor of a gridded depth file (GEBCO/ETOPO-like, or a model's h: the NetCDF reader,
/// GriddedBathymetry), read over @p region; @p toGeographic turns planning-frame points into lon/lat (empty: the
/// file's axes are planning x/y). @throws Error naming the file and variable.
std::shared_ptr<const Bathymetry> readBathymetry(const std::string &path, const std::string &variable,
                                                 std::function<LonLat(double x, double y)> toGeographic,
                                                 const GeoBox &region);
} // namespace ompl_glider

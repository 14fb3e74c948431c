#pragma once
/// @file Bathymetry.h
/// @brief The seafloor a glider's dives must stay above: the interface the dive profiles read
/// (cost/DiveProfile.h) and the readers implement (io/NetCdfBathymetry.h).

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
}  // namespace ompl_glider

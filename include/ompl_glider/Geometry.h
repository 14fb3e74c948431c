#pragma once
/// @file Geometry.h
/// @brief The 2-D point of the planning frame and the geographic position, used by every layer.

namespace ompl_glider
{
/// @brief A point of the plane (planning frame: metres, or dimensionless for analytic flows).
struct Point2
{
    double x{0.0};  ///< east (planning frame)
    double y{0.0};  ///< north (planning frame)
};

/// @brief A geographic position in degrees.
struct LonLat
{
    double lon{0.0};  ///< longitude, degrees east
    double lat{0.0};  ///< latitude, degrees north
};
}  // namespace ompl_glider

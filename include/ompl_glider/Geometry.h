#pragma once
/// @file Geometry.h
/// @brief The 2-D point of the planning frame and the geographic position, used by every layer.

#include <cmath>

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

/// @brief A longitude in any convention (0..360, -180..180, or any whole number of turns off) as the one value
/// in [-180, 180) every output carries: 185 -> -175, 360 -> 0, 180 -> -180. Exact (std::remainder), so the same
/// position written in two conventions gives the same double. NaN and infinities give NaN.
inline double normalizeLongitude(double lon)
{
    double l = std::remainder(lon, 360.0);  // [-180, 180]
    if (l >= 180.0)
        l -= 360.0;
    return l;
}
}  // namespace ompl_glider

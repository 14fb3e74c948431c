#pragma once
/// @file Geometry.h
/// @brief The value types every layer shares: the 2-D point of the planning frame, the timed point of a path, the
/// axis-aligned box, the velocity and the geographic position.

#include <cmath>

namespace ompl_glider
{
/// @brief A point of the plane (planning frame: metres, or dimensionless for analytic flows).
struct Point2
{
    double x{0.0}; ///< east (planning frame)
    double y{0.0}; ///< north (planning frame)
};

/// @brief A position of the planning frame at a time: a waypoint of a path, a point of a flown or backtracked track.
struct TimedPoint
{
    double x{0.0}; ///< east (planning frame)
    double y{0.0}; ///< north (planning frame)
    double t{0.0}; ///< time at the point (the departure time at a path's start)
};

/// @brief An axis-aligned box of the planning frame.
struct Box
{
    double xMin{0.0};
    double xMax{0.0};
    double yMin{0.0};
    double yMax{0.0};
};

/// @brief A straight segment of the plane (an edge of land's boundary, a leg).
struct Segment2
{
    Point2 a; ///< one end
    Point2 b; ///< the other end
};

/// @brief A horizontal velocity (u eastward / along x, v northward / along y): a current, a wind or a glider's
/// velocity through the water, in the units of its field.
struct Velocity
{
    double u{0.0}; ///< x component
    double v{0.0}; ///< y component
};

/// @brief A geographic position in degrees.
struct LonLat
{
    double lon{0.0}; ///< longitude, degrees east
    double lat{0.0}; ///< latitude, degrees north
};

/// @brief A longitude in any convention (0..360, -180..180, or any whole number of turns off) as the one value
/// in [-180, 180) every output carries: 185 -> -175, 360 -> 0, 180 -> -180. Exact (std::remainder), so the same
/// position written in two conventions gives the same double. NaN and infinities give NaN.
inline double normalizeLongitude(double lon)
{
    double l = std::remainder(lon, 360.0); // [-180, 180]
    if (l >= 180.0)
        l -= 360.0;
    return l;
}
} // namespace ompl_glider

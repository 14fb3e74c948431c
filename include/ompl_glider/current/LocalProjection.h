#pragma once
/// @file LocalProjection.h
/// @brief Geographic (lon, lat) <-> local Cartesian (x east, y north, metres) about a reference point.

#include <memory>
#include <mutex>
#include <string>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief Azimuthal equidistant projection on the WGS84 ellipsoid about (lon0, lat0), through PROJ
/// ("+proj=aeqd +ellps=WGS84"); x points east and y north at the reference point, in metres.
///
/// The mapping itself is exact (forward then inverse returns the point to better than 1e-6 m; tested).
/// Planning in the plane instead of on the ellipsoid is the approximation: distances from the reference point
/// are exact geodesic distances, and a straight leg of the plane differs in length from the geodesic between
/// its ends by less than about d^2 / (6 R^2) relative, d = distance from the reference point, R = 6371 km:
/// 2.6e-4 (0.026 %) at 250 km, i.e. everywhere in a 500 km region centred on the reference point (the test
/// checks 5e-4). Velocities given eastward/northward are rotated into x/y with eastDirection()/northDirection()
/// at each grid node (the meridian convergence is up to 2-3 degrees 250 km off the reference meridian at mid
/// latitudes, a 4 % cross-component error if ignored).
///
/// Thread-safe: each call locks a mutex around the PROJ object (use for loading and output, not per current
/// query; gridded fields store projected node positions).
class LocalProjection
{
public:
    /// @brief Projection centred on (lon0, lat0) in degrees. @throws Error if PROJ cannot create it.
    LocalProjection(double lon0, double lat0);
    ~LocalProjection();
    LocalProjection(const LocalProjection &) = delete;
    LocalProjection &operator=(const LocalProjection &) = delete;

    /// @brief Reference longitude (degrees).
    double lon0() const { return lon0_; }
    /// @brief Reference latitude (degrees).
    double lat0() const { return lat0_; }

    /// @brief (lon, lat) in degrees -> (x, y) in metres. Longitude may be given in any convention (0..360,
    /// -180..180, whole turns off): it is normalised exactly (normalizeLongitude()) first, so one position written
    /// in two conventions gives the identical point. @throws Error if the point cannot be projected.
    Point2 forward(double lon, double lat) const;
    /// @brief (x, y) in metres -> (lon, lat) in degrees, lon in [-180, 180) whatever lon0 is (normalizeLongitude():
    /// the one place where planning-frame points become longitudes, so every output is in -180..180).
    /// @throws Error if the point cannot be inverted.
    LonLat inverse(double x, double y) const;

    /// @brief Unit vector (ex, ey) in the plane of the local eastward direction at (lon, lat).
    void eastDirection(double lon, double lat, double &ex, double &ey) const;
    /// @brief Unit vector (nx, ny) in the plane of the local northward direction at (lon, lat).
    void northDirection(double lon, double lat, double &nx, double &ny) const;

    /// @brief Geodesic distance in metres on WGS84 between two geographic points (for tests and reports).
    double geodesicDistance(double lon1, double lat1, double lon2, double lat2) const;

    /// @brief The PROJ definition string in use.
    std::string definition() const;

private:
    double lon0_, lat0_;
    struct Impl;
    std::unique_ptr<Impl> impl_;
    mutable std::mutex mutex_;
};
} // namespace ompl_glider

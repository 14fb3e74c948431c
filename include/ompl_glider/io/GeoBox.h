#pragma once
/// @file GeoBox.h
/// @brief Longitude/latitude boxes in geographic terms: a region given in either longitude convention (checked),
/// and the trip's region (the box of start and goal widened by a geodesic margin), across the antimeridian.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief Grid nodes beyond this |latitude| (degrees) are not loaded: a longitude/latitude grid degenerates at the
/// poles (its cells shrink to wedges and the east direction is undefined there). A trip's region stops here; a
/// start or goal beyond it is refused.
constexpr double kMaxGridLatitude = 89.9;

/// @brief The Earth's mean radius (IUGG), km: the sphere of margins and messages.
constexpr double kEarthRadiusKm = 6371.0088;
/// @brief Kilometres per degree of a great circle on that sphere (111.195 km).
constexpr double kKmPerDegree = kEarthRadiusKm * 3.14159265358979323846 / 180.0;

/// @brief A longitude/latitude box. lonMin is in [-180, 180); lonMax in [lonMin, lonMin + 360]: beyond 180 when
/// the box crosses the antimeridian (170..190 is 170E eastward to 170W). latMin <= latMax, both in [-90, 90].
struct GeoBox
{
    double lonMin{0.0}, lonMax{0.0};
    double latMin{0.0}, latMax{0.0};

    /// @brief Degrees of longitude covered (in [0, 360]).
    double width() const { return lonMax - lonMin; }
    /// @brief True when the position (longitude in any convention) lies in the box, edges included.
    bool contains(LonLat p) const;
    /// @brief The longitude shifted by whole turns to lie in [lonMin, lonMin + 360) (so in [lonMin, lonMax] when
    /// it is inside).
    double unwrap(double lon) const;
    /// @brief "lon A..B, lat C..D" (A in -180..180, B beyond 180 across the antimeridian).
    std::string text() const;
    /// @brief The whole globe: lon -180..180, lat -90..90.
    static GeoBox world() { return GeoBox{-180.0, 180.0, -90.0, 90.0}; }
};

/// @brief What is wrong with a region: the bound at fault (lon_min, lat_min, lon_max or lat_max) and why.
struct RegionFault
{
    std::string bound;
    std::string what;
};

/// @brief Checks a region given as lon_min, lat_min, lon_max, lat_max (the order of a GeoJSON bbox, RFC 7946
/// sec. 5) in either longitude convention: every value finite, longitudes within -180..360, latitudes within
/// -90..90, lat_min < lat_max, lon_max != lon_min. lon_max > lon_min is the box from lon_min east to lon_max (less
/// than 360 degrees wide); lon_max < lon_min crosses the antimeridian (or the 0/360 seam) as in RFC 7946 sec. 5.2:
/// 170..-170 and 350..10 are 20 degrees wide. @returns the first fault, nullopt when the region is good.
std::optional<RegionFault> regionFault(double lonMin, double latMin, double lonMax, double latMax);

/// @brief The checked region as a GeoBox (lonMin normalised into [-180, 180), lonMax = lonMin + width).
/// @throws Error "region: <bound> ..." when regionFault() finds a fault.
GeoBox geoBox(double lonMin, double latMin, double lonMax, double latMax);

/// @brief Great-circle distance in km on the sphere of radius 6371.0088 km (haversine; longitudes in any
/// convention). Within 0.5 % of the WGS84 geodesic: for margins and messages, not for travel times.
double greatCircleKm(LonLat a, LonLat b);

/// @brief The trip's region: the smallest box holding the points (their latitudes, and the shortest arc of
/// longitudes that holds them all, so a trip from 175E to 175W is 10 degrees wide across the antimeridian,
/// whatever convention the longitudes are written in), widened on every side by marginKm: marginKm /
/// kKmPerDegree degrees of latitude, then marginKm / (kKmPerDegree cos(phi)) degrees of longitude at phi, the
/// widened box's highest |latitude|. Latitudes stop at +-kMaxGridLatitude; when the longitudes would reach all
/// round (or phi is that close to a pole) the box is the whole circle of latitude centred on the trip. A single
/// point with no margin gives a box of zero size.
/// @throws Error when there is no point, a value is not finite, a |latitude| exceeds kMaxGridLatitude (the message
/// says so), or the margin is negative.
GeoBox tripBox(const std::vector<LonLat> &points, double marginKm);
/// @brief The lon/lat box of a planning-frame rectangle (a Region's x/y extent): its edges sampled (40 points each)
/// through @p toGeographic,
/// longitudes unwrapped about the centre's so that a rectangle across the antimeridian stays narrow (lonMax beyond
/// 180 then). For clipping and drawing, not for exact bounds (an edge may bow between samples).
GeoBox frameBounds(const Box &frame, const std::function<LonLat(Point2)> &toGeographic);
} // namespace ompl_glider

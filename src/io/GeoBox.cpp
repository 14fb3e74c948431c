// Longitude/latitude boxes: regions checked in either convention, the trip's region widened by a geodesic margin.
#include "ompl_glider/io/GeoBox.h"
#include "NumberText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ompl_glider/Exception.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

} // namespace

double GeoBox::unwrap(double lon) const
{
    double d = std::fmod(normalizeLongitude(lon) - lonMin, 360.0);
    if (d < 0.0)
        d += 360.0;
    return lonMin + d;
}

bool GeoBox::contains(LonLat p) const
{
    if (!(p.lat >= latMin && p.lat <= latMax))
        return false;
    return unwrap(p.lon) <= lonMax || width() >= 360.0;
}

std::string GeoBox::text() const
{
    return "lon " + text::number(lonMin) + ".." + text::number(lonMax) + ", lat " + text::number(latMin) + ".." +
           text::number(latMax);
}

std::optional<RegionFault> regionFault(double lonMin, double latMin, double lonMax, double latMax)
{
    const std::pair<const char *, double> values[] = {
        {"lon_min", lonMin}, {"lat_min", latMin}, {"lon_max", lonMax}, {"lat_max", latMax}};
    for (const auto &[bound, v] : values)
        if (!std::isfinite(v))
            return RegionFault{bound, "must be a finite number (got " + text::number(v) + ")"};
    for (const auto &[bound, v] : {values[0], values[2]})
        if (v < -180.0 || v > 360.0)
            return RegionFault{bound, text::number(v) + " is not a longitude in -180..180 or 0..360"};
    for (const auto &[bound, v] : {values[1], values[3]})
        if (v < -90.0 || v > 90.0)
            return RegionFault{bound, text::number(v) + " is not a latitude in -90..90"};
    if (!(latMax > latMin))
        return RegionFault{"lat_max", text::number(latMax) + " must be > lat_min " + text::number(latMin)};
    if (lonMax == lonMin)
        return RegionFault{"lon_max", text::number(lonMax) + " equals lon_min: the region has no width"};
    if (lonMax - lonMin >= 360.0)
        return RegionFault{"lon_max", "the region " + text::number(lonMin) + ".." + text::number(lonMax) + " is " +
                                          text::number(lonMax - lonMin) + " degrees wide; it must be less than 360"};
    if (lonMax < lonMin && lonMax - lonMin + 360.0 <= 0.0)
        return RegionFault{"lon_max", text::number(lonMax) + " lies a whole turn or more west of lon_min " +
                                          text::number(lonMin) +
                                          " (lon_max < lon_min means eastward across the antimeridian)"};
    return std::nullopt;
}

GeoBox geoBox(double lonMin, double latMin, double lonMax, double latMax)
{
    if (const auto f = regionFault(lonMin, latMin, lonMax, latMax))
        throw Error("region: " + f->bound + " " + f->what);
    GeoBox b;
    const double width = lonMax > lonMin ? lonMax - lonMin : lonMax - lonMin + 360.0;
    b.lonMin = normalizeLongitude(lonMin);
    b.lonMax = b.lonMin + width;
    b.latMin = latMin;
    b.latMax = latMax;
    return b;
}

double greatCircleKm(LonLat a, LonLat b)
{
    const double dLat = (b.lat - a.lat) * kRadPerDeg, dLon = normalizeLongitude(b.lon - a.lon) * kRadPerDeg;
    const double h = std::sin(dLat / 2) * std::sin(dLat / 2) + std::cos(a.lat * kRadPerDeg) *
                                                                   std::cos(b.lat * kRadPerDeg) * std::sin(dLon / 2) *
                                                                   std::sin(dLon / 2);
    return 2.0 * kEarthRadiusKm * std::asin(std::min(1.0, std::sqrt(h)));
}

GeoBox tripBox(const std::vector<LonLat> &points, double marginKm)
{
    if (points.empty())
        throw Error("tripBox: no points");
    if (!(marginKm >= 0.0) || !std::isfinite(marginKm))
        throw Error("tripBox: the margin must be finite and >= 0 km (got " + text::number(marginKm) + ")");
    std::vector<double> lons;
    GeoBox b;
    b.latMin = 90.0;
    b.latMax = -90.0;
    for (const LonLat &p : points)
    {
        if (!std::isfinite(p.lon) || !std::isfinite(p.lat) || std::abs(p.lat) > 90.0)
            throw Error("(" + text::number(p.lon) + ", " + text::number(p.lat) + ") is not a longitude/latitude");
        if (std::abs(p.lat) > kMaxGridLatitude)
            throw Error("latitude " + text::number(p.lat) + " is within " + text::number(90.0 - kMaxGridLatitude) +
                        " degrees of a pole, where a longitude/latitude grid degenerates (|lat| <= " +
                        text::number(kMaxGridLatitude) + " is planned)");
        lons.push_back(normalizeLongitude(p.lon));
        b.latMin = std::min(b.latMin, p.lat);
        b.latMax = std::max(b.latMax, p.lat);
    }
    // The shortest arc holding every longitude: the circle minus its largest gap between neighbours.
    std::sort(lons.begin(), lons.end());
    std::size_t after = 0; // the arc starts at lons[after]
    double gap = lons.front() + 360.0 - lons.back();
    for (std::size_t k = 1; k < lons.size(); ++k)
        if (lons[k] - lons[k - 1] > gap)
        {
            gap = lons[k] - lons[k - 1];
            after = k;
        }
    double lon0 = lons[after], width = 360.0 - gap;
    // Widen: latitudes first (stopping short of the poles), then longitudes at the widened box's highest |lat|.
    const double dLat = marginKm / kKmPerDegree;
    b.latMin = std::max(b.latMin - dLat, -kMaxGridLatitude);
    b.latMax = std::min(b.latMax + dLat, kMaxGridLatitude);
    const double phi = std::max(std::abs(b.latMin), std::abs(b.latMax));
    const double dLon = marginKm / (kKmPerDegree * std::cos(phi * kRadPerDeg));
    if (width + 2.0 * dLon >= 360.0 || !std::isfinite(dLon))
    {
        lon0 += 0.5 * width - 180.0; // the whole circle, centred on the trip
        width = 360.0;
    }
    else
    {
        lon0 -= dLon;
        width += 2.0 * dLon;
    }
    b.lonMin = normalizeLongitude(lon0);
    b.lonMax = b.lonMin + width;
    return b;
}
GeoBox frameBounds(const Box &r, const std::function<LonLat(Point2)> &toGeographic)
{
    const double lonC = toGeographic({0.5 * (r.xMin + r.xMax), 0.5 * (r.yMin + r.yMax)}).lon;
    double lon0 = 1e9, lon1 = -1e9, lat0 = 90.0, lat1 = -90.0;
    for (int k = 0; k <= 40; ++k)
    {
        const double s = k / 40.0, x = r.xMin + s * (r.xMax - r.xMin), y = r.yMin + s * (r.yMax - r.yMin);
        for (const Point2 p : {Point2{x, r.yMin}, Point2{x, r.yMax}, Point2{r.xMin, y}, Point2{r.xMax, y}})
        {
            const LonLat g = toGeographic(p);
            const double lon = lonC + std::remainder(g.lon - lonC, 360.0);
            lon0 = std::min(lon0, lon);
            lon1 = std::max(lon1, lon);
            lat0 = std::min(lat0, g.lat);
            lat1 = std::max(lat1, g.lat);
        }
    }
    GeoBox b;
    b.lonMin = normalizeLongitude(lon0);
    b.lonMax = b.lonMin + (lon1 - lon0);
    b.latMin = lat0;
    b.latMax = lat1;
    return b;
}

} // namespace ompl_glider

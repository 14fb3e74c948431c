// The `region` section: the box to plan in, x/y or lon/lat (either longitude convention).
#include "MissionReader.h"
#include "ompl_glider/io/GeoBox.h"

namespace ompl_glider::mission_loader
{
void readRegion(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "region";
    r.checkMap(n, f, {"x_min", "x_max", "y_min", "y_max", "lon_min", "lon_max", "lat_min", "lat_max"});
    RegionSpec &g = m.region;
    g.set = true;
    const bool xy = n["x_min"] || n["x_max"] || n["y_min"] || n["y_max"];
    const bool geo = n["lon_min"] || n["lon_max"] || n["lat_min"] || n["lat_max"];
    if (xy == geo)
        r.fail(n, f, "give either x_min, x_max, y_min, y_max or lon_min, lon_max, lat_min, lat_max");
    auto need = [&](const char *key) -> double {
        if (!n[key])
            r.fail(n, f + "." + key, "missing");
        return r.finite(n[key], f + "." + key);
    };
    g.geographic = geo;
    if (xy)
    {
        g.xy.xMin = need("x_min");
        g.xy.xMax = need("x_max");
        g.xy.yMin = need("y_min");
        g.xy.yMax = need("y_max");
        if (!(g.xy.xMax > g.xy.xMin))
            r.fail(n["x_max"], f + ".x_max", "must be > x_min");
        if (!(g.xy.yMax > g.xy.yMin))
            r.fail(n["y_max"], f + ".y_max", "must be > y_min");
    }
    else
    {
        if (!m.projection.set && !m.current.isForecast())
            r.fail(n, f, "lon/lat bounds need a 'projection' in the mission");
        const double lonMin = need("lon_min"), lonMax = need("lon_max");
        const double latMin = need("lat_min"), latMax = need("lat_max");
        // either convention; lon_max < lon_min crosses the antimeridian (RFC 7946 bbox), stored unwrapped
        if (const auto fault = regionFault(lonMin, latMin, lonMax, latMax))
            r.fail(n[fault->bound], f + "." + fault->bound, fault->what);
        g.lonLat = geoBox(lonMin, latMin, lonMax, latMax);
    }
}
} // namespace ompl_glider::mission_loader

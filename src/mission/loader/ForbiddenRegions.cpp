// Forbidden regions of a mission: static polygons, time-windowed zones and ice zones, inline or from a GeoJSON
// FeatureCollection ([IsernObstacles] Sec. II; ice: [EichhornIce]).
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "MissionReader.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/Exception.h"
#include "../../io/NumberText.h"

namespace ompl_glider
{
const char *regionKindName(RegionKind k)
{
    switch (k)
    {
    case RegionKind::Land:
        return "land";
    case RegionKind::RestrictedArea:
        return "restricted area";
    case RegionKind::Closure:
        return "closure";
    case RegionKind::Ice:
        return "ice";
    case RegionKind::Island:
        break;
    }
    return "island";
}

std::optional<RegionKind> parseRegionKind(const std::string &name)
{
    for (const RegionKind k :
         {RegionKind::Island, RegionKind::Land, RegionKind::RestrictedArea, RegionKind::Closure, RegionKind::Ice})
        if (name == regionKindName(k))
            return k;
    return std::nullopt;
}
} // namespace ompl_glider

namespace ompl_glider::mission_loader
{
namespace
{

// --- GeoJSON forbidden regions ---------------------------------------------------------------------------------

/// A GeoJSON `crs` member (GeoJSON 2008; RFC 7946 dropped it): only lon/lat (WGS 84) is taken; another one is
/// refused, since the mission reads the coordinates as lon/lat or as its own x/y.
void checkGeoJsonCrs(const Reader &g, const YAML::Node &doc)
{
    const YAML::Node crs = doc["crs"];
    if (!crs)
        return;
    std::string name;
    if (crs.IsMap() && crs["properties"] && crs["properties"].IsMap() && crs["properties"]["name"] &&
        crs["properties"]["name"].IsScalar())
        name = crs["properties"]["name"].Scalar();
    const bool lonLat = name.find("CRS84") != std::string::npos || name.find("4326") != std::string::npos;
    if (!lonLat)
        g.fail(crs, "crs",
               "the GeoJSON names the coordinate reference system '" + (name.empty() ? "?" : name) +
                   "'; forbidden regions are read as lon/lat (WGS 84) or as the mission's x/y "
                   "(geojson_coordinates: local): transform the file first (ogr2ogr -t_srs EPSG:4326 OUT IN), "
                   "or give it as forbidden.coastline, which is transformed");
}

/// Lon/lat of a geographic GeoJSON ring: a longitude outside -180..360 or a latitude outside -90..90 is not lon/lat
/// (web-mercator metres without a `crs` member, say).
void checkLonLat(const Reader &g, const YAML::Node &ring, const std::string &field, const std::string &feature,
                 const std::vector<std::pair<double, double>> &points)
{
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!(points[i].first >= -180.0 && points[i].first <= 360.0 && points[i].second >= -90.0 &&
              points[i].second <= 90.0))
            g.fail(ring[i], field + "[" + std::to_string(i) + "]",
                   "feature '" + feature + "': [" + text::number(points[i].first) + ", " +
                       text::number(points[i].second) +
                       "] is not lon/lat (longitude -180..360, latitude -90..90): projected coordinates (metres of "
                       "web-mercator?) need transforming to lon/lat, or geojson_coordinates: local for the "
                       "mission's x/y");
}

// (GeoJSON forbidden regions ---------------------------------------------------------------------------------

void readGeoJson(const Reader &r, const YAML::Node &where, MissionSpec &m)
{
    const std::string &path = m.forbidden.geojson;
    YAML::Node doc;
    try
    {
        doc = YAML::LoadFile(path);
    }
    catch (const YAML::BadFile &)
    {
        r.fail(where, "forbidden.geojson", "cannot open '" + path + "'");
    }
    catch (const YAML::ParserException &e)
    {
        throw Error(yamlErrorMessage(path, e, "not valid GeoJSON"));
    }
    const Reader g(path, r.dir());
    if (!doc.IsMap() || !doc["type"] || doc["type"].Scalar() != "FeatureCollection" || !doc["features"] ||
        !doc["features"].IsSequence())
        g.fail(doc, "type", "expected a GeoJSON FeatureCollection with a 'features' list");
    checkGeoJsonCrs(g, doc);
    const bool geo = m.forbidden.geojsonGeographic;
    if (geo && !m.projection.set && !m.current.isForecast())
        r.fail(where, "forbidden.geojson", "GeoJSON coordinates are lon/lat: give a 'projection' in the mission");
    const YAML::Node &features = doc["features"];
    for (std::size_t i = 0; i < features.size(); ++i)
    {
        const YAML::Node &ft = features[i];
        const std::string fld = "features[" + std::to_string(i) + "]";
        if (!ft.IsMap() || !ft["geometry"] || !ft["geometry"].IsMap() || !ft["geometry"]["type"])
            g.fail(ft, fld, "expected a Feature with a geometry");
        const YAML::Node &geom = ft["geometry"];
        const std::string type = geom["type"].Scalar();
        static const std::set<std::string> polygons = {"Polygon", "MultiPolygon"}; // the geometries of a region
        if (!polygons.count(type))
            g.fail(geom, fld + ".geometry.type",
                   "only Polygon and MultiPolygon are forbidden regions (got " + type + ")");
        YAML::Node props = ft["properties"];
        std::string name = "feature " + std::to_string(i), kind = regionKindName(RegionKind::Island);
        if (props && props.IsMap())
        {
            g.checkMap(props, fld + ".properties",
                       {"name", "kind", "windows", "max_submerged_time", "drift", "t_ref", "carried"});
            if (props["name"])
                name = g.text(props["name"], fld + ".properties.name");
            if (props["kind"])
                kind = g.oneOf(props["kind"], fld + ".properties.kind",
                               {"island", "land", "restricted area", "closure", "ice"});
            // a property of another kind would be ignored: refused, saying which kind it belongs to
            for (const auto &[key, owner] :
                 std::vector<std::pair<const char *, const char *>>{{"windows", "closure"},
                                                                    {"max_submerged_time", "ice"},
                                                                    {"drift", "ice"},
                                                                    {"t_ref", "ice"},
                                                                    {"carried", "ice"}})
                if (props[key] && kind != owner)
                    g.fail(props[key], fld + ".properties." + key,
                           std::string("belongs to a zone of kind '") + owner + "', but this feature's kind is '" +
                               kind + "'" + (props["kind"] ? "" : " (the default)") + ": give kind: " + owner +
                               " or leave " + key + " out");
        }
        std::vector<YAML::Node> polys;
        if (type == "Polygon")
            polys.push_back(geom["coordinates"]);
        else if (geom["coordinates"].IsSequence())
            for (std::size_t k = 0; k < geom["coordinates"].size(); ++k)
                polys.push_back(geom["coordinates"][k]);
        for (std::size_t k = 0; k < polys.size(); ++k)
        {
            const YAML::Node &rings = polys[k];
            const std::string pf =
                fld + ".geometry.coordinates" + (type == "Polygon" ? "" : "[" + std::to_string(k) + "]");
            if (!rings.IsSequence() || rings.size() < 1)
                g.fail(rings, pf, "expected a list of linear rings");
            PolygonSpec poly;
            poly.name = polys.size() > 1 ? name + " #" + std::to_string(k + 1) : name;
            poly.geographic = geo;
            poly.mark = {path, g.line(rings)};
            poly.points = g.ring(rings[0], pf + "[0]");
            for (std::size_t h = 1; h < rings.size(); ++h)
                poly.holes.push_back(g.ring(rings[h], pf + "[" + std::to_string(h) + "]"));
            if (geo)
                for (std::size_t h = 0; h < rings.size(); ++h)
                    checkLonLat(g, rings[h], pf + "[" + std::to_string(h) + "]", name,
                                h == 0 ? poly.points : poly.holes[h - 1]);
            const RegionKind parsed = *parseRegionKind(kind); // one of the names oneOf() took
            if (parsed == RegionKind::Closure)
            {
                TimeWindowSpec tw;
                tw.polygon = poly;
                if (!props["windows"] || !props["windows"].IsSequence())
                    g.fail(ft, fld + ".properties.windows", "a closure needs windows: [[from, to], ...]");
                for (std::size_t w = 0; w < props["windows"].size(); ++w)
                    tw.windows.push_back(
                        g.pair(props["windows"][w], fld + ".properties.windows[" + std::to_string(w) + "]"));
                m.forbidden.timeWindows.push_back(tw);
            }
            else if (parsed == RegionKind::Ice)
            {
                IceSpec ice;
                ice.polygon = poly;
                if (!props["max_submerged_time"])
                    g.fail(ft, fld + ".properties.max_submerged_time", "an ice zone needs max_submerged_time");
                ice.maxSubmergedTime =
                    g.nonNegative(props["max_submerged_time"], fld + ".properties.max_submerged_time");
                if (props["t_ref"])
                    ice.tRef = g.finite(props["t_ref"], fld + ".properties.t_ref");
                if (props["drift"])
                    std::tie(ice.vx, ice.vy) = g.pair(props["drift"], fld + ".properties.drift");
                if (props["carried"])
                    ice.carried = g.boolean(props["carried"], fld + ".properties.carried");
                m.forbidden.ice.push_back(ice);
            }
            else
                m.forbidden.obstacles.push_back({poly, parsed});
        }
    }
}

/// @brief Entry @p i of the list forbidden.<list> (@p entry): checks its keys against @p keys, reads its polygon
/// into @p polygon and names it "<unnamed> <i + 1>" when the entry gives no name.
/// @return The entry's path in messages, "forbidden.<list>[i]".
std::string readListedPolygon(const Reader &r, const YAML::Node &entry, const char *list, std::size_t i,
                              const std::set<std::string> &keys, const char *unnamed, PolygonSpec &polygon,
                              const MissionSpec &m)
{
    const std::string g = std::string("forbidden.") + list + "[" + std::to_string(i) + "]";
    r.checkMap(entry, g, keys);
    readPolygon(r, entry, g, polygon, m);
    if (polygon.name.empty())
        polygon.name = std::string(unnamed) + " " + std::to_string(i + 1);
    return g;
}

} // namespace

void readForbidden(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "forbidden";
    r.checkMap(n, f, {"obstacles", "time_windows", "ice", "geojson", "geojson_coordinates", "coastline"});
    auto list = [&](const char *key) -> YAML::Node {
        const YAML::Node &l = n[key];
        if (l && !l.IsSequence())
            r.fail(l, f + "." + key, "expected a list");
        return l;
    };
    if (const YAML::Node l = list("obstacles"))
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            ObstacleSpec o;
            const std::string g = readListedPolygon(
                r, l[i], "obstacles", i, {"name", "kind", "points", "lonlat", "holes"}, "obstacle", o.polygon, m);
            if (l[i]["kind"])
                o.kind = *parseRegionKind(r.oneOf(l[i]["kind"], g + ".kind", {"island", "land", "restricted area"}));
            m.forbidden.obstacles.push_back(o);
        }
    if (const YAML::Node l = list("time_windows"))
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            TimeWindowSpec tw;
            const std::string g = readListedPolygon(
                r, l[i], "time_windows", i, {"name", "points", "lonlat", "holes", "windows"}, "closure", tw.polygon, m);
            const YAML::Node &w = l[i]["windows"];
            if (!w || !w.IsSequence() || w.size() == 0)
                r.fail(w ? w : l[i], g + ".windows", "expected a list of [from, to] time intervals");
            for (std::size_t k = 0; k < w.size(); ++k)
            {
                const std::string wf = g + ".windows[" + std::to_string(k) + "]";
                if (!w[k].IsSequence() || w[k].size() != 2)
                    r.fail(w[k], wf, "expected [from, to]");
                const double a = r.time(w[k][0], wf + "[0]", m), b = r.time(w[k][1], wf + "[1]", m);
                if (!(b >= a))
                    r.fail(w[k], wf, "'to' must not be before 'from'");
                tw.windows.push_back({a, b});
            }
            m.forbidden.timeWindows.push_back(tw);
        }
    if (const YAML::Node l = list("ice"))
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            IceSpec ice;
            const std::string g = readListedPolygon(
                r, l[i], "ice", i,
                {"name", "points", "lonlat", "holes", "t_ref", "drift", "carried", "max_submerged_time"}, "ice",
                ice.polygon, m);
            if (!l[i]["max_submerged_time"])
                r.fail(l[i], g + ".max_submerged_time", "missing: the longest continuous stay under the ice");
            ice.maxSubmergedTime = r.nonNegative(l[i]["max_submerged_time"], g + ".max_submerged_time");
            if (l[i]["t_ref"])
                ice.tRef = r.time(l[i]["t_ref"], g + ".t_ref", m);
            if (l[i]["drift"] && l[i]["carried"])
                r.fail(l[i], g, "give either drift [vx, vy] or carried: true");
            if (l[i]["drift"])
                std::tie(ice.vx, ice.vy) = r.pair(l[i]["drift"], g + ".drift");
            if (l[i]["carried"])
                ice.carried = r.boolean(l[i]["carried"], g + ".carried");
            m.forbidden.ice.push_back(ice);
        }
    if (n["geojson_coordinates"])
        m.forbidden.geojsonGeographic =
            r.oneOf(n["geojson_coordinates"], f + ".geojson_coordinates", {"geographic", "local"}) == "geographic";
    if (n["geojson"])
    {
        m.forbidden.geojson = joinPath(r.dir(), r.text(n["geojson"], f + ".geojson"));
        readGeoJson(r, n["geojson"], m);
    }
    if (n["coastline"])
    {
        // read when the problem is built, clipped to the trip's box (MissionProblem::buildRegions())
        m.forbidden.coastline = joinPath(r.dir(), r.text(n["coastline"], f + ".coastline"));
        m.forbidden.coastlineMark = {r.file(), r.line(n["coastline"])};
        if (!fileExists(m.forbidden.coastline))
            r.fail(n["coastline"], f + ".coastline", "cannot open '" + m.forbidden.coastline + "'");
    }
}
} // namespace ompl_glider::mission_loader

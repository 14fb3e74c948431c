// Safety margins of a mission (MissionSpec::safety): the keep-off zone from land and the shallow water of the depth
// limit, both forbidden regions of the one environment (see MissionProblem.h).
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "../../io/NumberText.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/environment/ForbiddenCells.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/KeepOffZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/io/Coastline.h"
#include "ompl_glider/io/DepthGrid.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/SettingRanges.h"

namespace ompl_glider
{
namespace
{
/// "m.yaml:12: field 'safety.min_depth': " or "--min-depth: ".
std::string at(const MissionSpec &m, const std::string &field)
{
    const auto it = m.marks.find(field);
    if (it != m.marks.end() && it->second.namesItself())
        return it->second.file + ": ";
    return m.place(field) + ": ";
}
} // namespace

#if OMPL_GLIDER_WITH_NETCDF
GeoBox MissionProblem::bathymetryRegion() const
{
    GeoBox region = GeoBox::world();
    if (isGeographic())
    {
        const GeoBox gb =
            frameBounds(Box{box_.xMin, box_.xMax, box_.yMin, box_.yMax}, [this](Point2 p) { return toGeographic(p); });
        const double pad = 0.05 * std::max(gb.lonMax - gb.lonMin, gb.latMax - gb.latMin);
        region = {gb.lonMin - pad, gb.lonMax + pad, std::max(-90.0, gb.latMin - pad), std::min(90.0, gb.latMax + pad)};
    }
    return region;
}
#endif

std::shared_ptr<const ForbiddenCells> MissionProblem::shallowWater()
{
    const MissionSpec &m = spec_;
    const bool limit = m.marks.count("safety.min_depth") > 0 || !m.safety.bathymetry.empty();
    if (!limit)
        return nullptr;
    const std::string field = m.safety.bathymetry.empty() ? "safety.min_depth" : "safety.bathymetry";
    std::string file = m.safety.bathymetry;
    if (file.empty())
    {
        if (forecastFiles_.empty())
            throw Error(at(m, field) + "a depth limit needs a bathymetry file (" + m.term("safety.bathymetry") + ")");
        file = forecastFiles_.front(); // the model's own bathymetry (ROMS h)
    }
#if OMPL_GLIDER_WITH_NETCDF
    const GeoBox region = bathymetryRegion();
    const bool geo = isGeographic();
    DepthGrid g;
    try
    {
        g = readDepthGrid(file, m.safety.bathymetryVariable, region);
        if (g.geographic && !geo)
            throw Error("the bathymetry is on longitude/latitude: the mission needs a projection");
    }
    catch (const Error &e)
    {
        throw Error(at(m, field) + e.what());
    }
    std::vector<Point2> nodes(g.a.size());
    for (std::size_t n = 0; n < nodes.size(); ++n)
        nodes[n] = g.geographic ? (std::abs(g.b[n]) <= 89.9 ? toLocal({g.a[n], g.b[n]}) : Point2{NAN, NAN})
                                : Point2{g.a[n], g.b[n]};
    // a cell is too shallow when any corner is (or has no value): the depth limit holds on the whole cell
    const std::size_t cx = g.nx - 1, cy = g.ny - 1;
    std::vector<std::uint8_t> bad(cx * cy, 0);
    std::size_t count = 0;
    auto shallow = [&](std::size_t n) { return !(g.depth[n] >= m.safety.minDepth); };
    for (std::size_t j = 0; j < cy; ++j)
        for (std::size_t i = 0; i < cx; ++i)
            if (shallow(j * g.nx + i) || shallow(j * g.nx + i + 1) || shallow((j + 1) * g.nx + i) ||
                shallow((j + 1) * g.nx + i + 1))
            {
                bad[j * cx + i] = 1;
                ++count;
            }
    const std::string name = "depth < " + text::number(m.safety.minDepth) + " m";
    auto cells = std::make_shared<ForbiddenCells>(name, "shallow water", g.nx, g.ny, std::move(nodes), bad);
    safetyNote_ = "depth limit " + text::number(m.safety.minDepth) + " m from '" + file + "' variable '" + g.variable +
                  "' (" + g.convention + "): " + std::to_string(count) + " of " + std::to_string(cx * cy) +
                  " cells too shallow";
    return cells;
#else
    (void)file;
    throw Error(at(m, field) + "this build of ompl_glider has no NetCDF support");
#endif
}

void MissionProblem::addSafety(ForbiddenRegions &regions)
{
    const MissionSpec &m = spec_;
    // (a program may set them without the loader or the overrides: their declared ranges, SettingRanges.h)
    for (const auto &[field, value] : {std::pair<const char *, double>{"safety.keep_off", m.safety.keepOff},
                                       std::pair<const char *, double>{"safety.min_depth", m.safety.minDepth}})
        try
        {
            checkSetting(field, value, text::number(value));
        }
        catch (const Error &e)
        {
            throw Error(at(m, field) + e.what());
        }
    // land's boundary: the field's land cells, the land polygons (coastline, islands, land obstacles)
    std::vector<Segment2> edges = field_->landBoundary(m.vehicle.depth);
    for (const auto &r : regions.regions())
        if (const auto *s = dynamic_cast<const StaticRegion *>(r.get()))
            if (s->kind() == regionKindName(RegionKind::Land) || s->kind() == regionKindName(RegionKind::Island))
            {
                const std::vector<Segment2> e = s->polygon().edges();
                edges.insert(edges.end(), e.begin(), e.end());
            }
    if (!edges.empty())
    {
        auto zone = std::make_shared<KeepOffZone>(std::move(edges), m.safety.keepOff);
        if (m.physicalUnits().length)
            zone->setMetresPerUnit(m.metresPerUnit()); // the pilot's units in its messages
        land_ = zone;
        if (m.safety.keepOff > 0.0)
            regions.add(land_);
    }
    if (auto shallow = shallowWater())
        regions.add(shallow);
}
void MissionProblem::checkGeoJsonNearBox() const
{
    const MissionSpec &m = spec_;
    if (m.forbidden.geojson.empty())
        return;
    std::vector<const PolygonSpec *> given;
    for (const auto &o : m.forbidden.obstacles)
        given.push_back(&o.polygon);
    for (const auto &t : m.forbidden.timeWindows)
        given.push_back(&t.polygon);
    for (const auto &i : m.forbidden.ice)
        given.push_back(&i.polygon);
    const double near = std::max(box_.xMax - box_.xMin, box_.yMax - box_.yMin);
    double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300; // the file's extent as given
    int n = 0;
    for (const PolygonSpec *p : given)
    {
        if (p->mark.file != m.forbidden.geojson)
            continue;
        ++n;
        for (const auto &[a, b] : p->points)
        {
            a0 = std::min(a0, a), a1 = std::max(a1, a), b0 = std::min(b0, b), b1 = std::max(b1, b);
        }
        if (p->geographic && std::abs(p->points.front().second) >= 89.9)
            continue; // (no projection at a pole)
        for (const Point2 &q : ring(p->points, p->geographic, p->name))
            if (q.x >= box_.xMin - near && q.x <= box_.xMax + near && q.y >= box_.yMin - near &&
                q.y <= box_.yMax + near)
                return;
    }
    if (n == 0)
        return;
    const bool geo = m.forbidden.geojsonGeographic;
    throw Error(m.place("forbidden.geojson") + ": '" + m.forbidden.geojson + "': none of its " + std::to_string(n) +
                " forbidden regions lies in or near the planning region; they lie within " + (geo ? "lon " : "x ") +
                text::number(a0) + ".." + text::number(a1) + (geo ? ", lat " : ", y ") + text::number(b0) + ".." +
                text::number(b1) + (geo ? " (lon and lat swapped? another region?)" : ""));
}

std::vector<LandPolygon> MissionProblem::readCoastline(const std::string &at)
{
    // the coastline's land polygons that meet the box (with a margin of a tenth of its size)
    const MissionSpec &m = spec_;
    const GeoBox gb =
        frameBounds(Box{box_.xMin, box_.xMax, box_.yMin, box_.yMax}, [this](Point2 p) { return toGeographic(p); });
    const double lon0 = gb.lonMin, lon1 = gb.lonMax, lat0 = gb.latMin, lat1 = gb.latMax;
    const double pad = 0.1 * std::max(lon1 - lon0, lat1 - lat0);
    std::vector<LandPolygon> land;
    try
    {
        // the box in -180..180; across the antimeridian, its two sides
        const double a = lon0 - pad, b = lon1 + pad, s = std::max(-90.0, lat0 - pad), n = std::min(90.0, lat1 + pad);
        std::vector<std::pair<double, double>> spans;
        if (b - a >= 360.0)
            spans = {{-180.0, 180.0}};
        else if (a < -180.0)
            spans = {{a + 360.0, 180.0}, {-180.0, b}};
        else if (b > 180.0)
            spans = {{a, 180.0}, {-180.0, b - 360.0}};
        else
            spans = {{a, b}};
        std::vector<std::string> repairs;
        CoastlineCount count;
        std::set<std::string> usedFeatures; // a feature across the antimeridian meets both spans: counted once
        for (const auto &[w, e] : spans)
        {
            count = {};
            for (LandPolygon &p : readLandPolygons(m.forbidden.coastline, GeoBox{w, e, s, n}, &repairs, &count))
                land.push_back(std::move(p));
            usedFeatures.insert(count.usedFeatures.begin(), count.usedFeatures.end());
        }
        const int used = static_cast<int>(usedFeatures.size());
        // none used: open water in a larger file, or a file nowhere near the trip (lon and lat swapped, another
        // region): the latter is refused, with where the file's features lie
        const double near = std::max(lon1 - lon0, lat1 - lat0);
        auto nearBox = [&](double shift) {
            return count.lonMax + shift >= lon0 - near && count.lonMin + shift <= lon1 + near &&
                   count.latMax >= lat0 - near && count.latMin <= lat1 + near;
        };
        if (count.features > 0 && used == 0 && !nearBox(0.0) && !nearBox(360.0) && !nearBox(-360.0))
            throw Error("coastline file '" + m.forbidden.coastline + "': none of its " +
                        std::to_string(count.features) + " features lies in or near the trip's box (" + gb.text() +
                        "); they lie within lon " + text::number(count.lonMin) + ".." + text::number(count.lonMax) +
                        ", lat " + text::number(count.latMin) + ".." + text::number(count.latMax) +
                        " (lon and lat swapped? another region?)");
        coastlineNote_ = std::to_string(land.size()) + " land polygons from " + std::to_string(used) + " of " +
                         std::to_string(count.features) + " features of '" + m.forbidden.coastline + "'";
        for (const std::string &r : repairs)
            coastlineNote_ += "; " + r;
    }
    catch (const Error &e)
    {
        throw Error(at + e.what());
    }
    return land;
}
} // namespace ompl_glider

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

std::shared_ptr<const ForbiddenCells> MissionProblem::shallowWater(const ProblemInputs &in)
{
    if (!in.depthGrid)
        return nullptr;
    const MissionSpec &m = spec_;
    const DepthGrid &g = *in.depthGrid;
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
    safetyNote_ = "depth limit " + text::number(m.safety.minDepth) + " m from '" + in.depthGridFile + "' variable '" +
                  g.variable + "' (" + g.convention + "): " + std::to_string(count) + " of " + std::to_string(cx * cy) +
                  " cells too shallow";
    return cells;
}

void MissionProblem::addSafety(ForbiddenRegions &regions, const ProblemInputs &in)
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
            throw Error(m.place(field) + ": " + e.what());
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
    if (auto shallow = shallowWater(in))
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
    const double near = std::max(frame_.box.xMax - frame_.box.xMin, frame_.box.yMax - frame_.box.yMin);
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
            if (q.x >= frame_.box.xMin - near && q.x <= frame_.box.xMax + near && q.y >= frame_.box.yMin - near &&
                q.y <= frame_.box.yMax + near)
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

} // namespace ompl_glider

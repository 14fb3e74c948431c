// The mission's land and forbidden regions (MissionProblem.h): its polygons, the coastline's land polygons as read
// (ProblemInputs), closures and ice, each checked as given and placed in the planning frame (the keep-off zone and
// the depth limit: Safety.cpp).
#include "ompl_glider/mission/MissionProblem.h"
#include "../../io/NumberText.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/environment/Polygon.h"
#include "ompl_glider/io/Coastline.h"
#include "ompl_glider/io/GeoBox.h"

namespace ompl_glider
{
std::vector<Point2> MissionProblem::ring(const std::vector<std::pair<double, double>> &pts, bool geographic,
                                         const std::string &what) const
{
    std::vector<Point2> out;
    for (const auto &[a, b] : pts)
    {
        PointSpec p;
        p.geographic = geographic;
        p.xy.x = p.lonLat.lon = a;
        p.xy.y = p.lonLat.lat = b;
        out.push_back(localPoint(p, what));
    }
    return out;
}

Polygon MissionProblem::placedPolygon(const PolygonSpec &p, RegionKind kind)
{
    // the polygon as given, checked: every polygon GEOS calls valid (a hole may touch its outer ring at a point)
    auto given = [](const std::vector<std::pair<double, double>> &r) {
        std::vector<Point2> out;
        for (const auto &[a, b] : r)
            out.push_back({a, b});
        return out;
    };
    std::vector<std::vector<Point2>> holes;
    for (const auto &h : p.holes)
        holes.push_back(given(h));
    const std::string fault = polygonFault(given(p.points), holes);
    if (!fault.empty())
        throw Error("an invalid polygon: " + fault + (p.geographic ? " (lon lat)" : " (x y as given)"));
    holes.clear();
    for (const auto &h : p.holes)
        holes.push_back(ring(h, p.geographic, p.name));
    std::vector<Point2> outer = ring(p.points, p.geographic, p.name);
    polygons_.push_back({p.name, kind, outer, false, {}});
    return Polygon(outer, holes, p.name, RingCheck::validated);
}

void MissionProblem::addCoastline(ForbiddenRegions &regions, const ProblemInputs &in)
{
    const MissionSpec &m = spec_;
    const SourceMark &mk = m.forbidden.coastlineMark;
    const std::string at = mk.namesItself() ? mk.file + ": " : sourcePlace(m, mk);
    const std::vector<LandPolygon> &land = in.coastline;
    for (std::size_t k = 0; k < land.size(); ++k)
    {
        PolygonSpec p;
        p.name = land[k].name;
        p.geographic = true;
        p.mark = m.forbidden.coastlineMark;
        for (const LonLat &g : land[k].outer)
            p.points.emplace_back(g.lon, g.lat);
        for (const auto &h : land[k].holes)
        {
            p.holes.emplace_back();
            for (const LonLat &g : h)
                p.holes.back().emplace_back(g.lon, g.lat);
        }
        try
        {
            regions.add(std::make_shared<StaticRegion>(p.name, placedPolygon(p, RegionKind::Land),
                                                       regionKindName(RegionKind::Land)));
            polygons_.back().coastline = true;
        }
        catch (const Error &e)
        {
            // named by the coastline file and the feature
            throw Error(at + "coastline file '" + m.forbidden.coastline + "', feature '" + p.name + "': " + e.what());
        }
    }
}

void MissionProblem::buildRegions(const ProblemInputs &in)
{
    const MissionSpec &m = spec_;
    // a mission's polygon: its faults named by its place in the mission
    auto polygon = [&](const PolygonSpec &p, RegionKind kind) {
        try
        {
            return placedPolygon(p, kind);
        }
        catch (const Error &e)
        {
            throw Error(sourcePlace(m, p.mark) + "forbidden region '" + p.name + "': " + e.what());
        }
    };
    auto regions = std::make_shared<ForbiddenRegions>();
    for (const auto &o : m.forbidden.obstacles)
        regions->add(
            std::make_shared<StaticRegion>(o.polygon.name, polygon(o.polygon, o.kind), regionKindName(o.kind)));
    if (!m.forbidden.coastline.empty())
        addCoastline(*regions, in); // the coastline's land polygons that meet the box (as read: ProblemInputs)
    for (const auto &t : m.forbidden.timeWindows)
    {
        std::vector<Interval> w;
        for (const auto &p : t.windows)
            w.push_back({p.first, p.second});
        try
        {
            regions->add(
                std::make_shared<TimeWindowedZone>(t.polygon.name, polygon(t.polygon, RegionKind::Closure), w));
            polygons_.back().windows = t.windows;
        }
        catch (const Error &e)
        {
            throw Error(sourcePlace(m, t.polygon.mark) + e.what());
        }
    }
    for (const auto &i : m.forbidden.ice)
    {
        Polygon shape = polygon(i.polygon, RegionKind::Ice);
        try
        {
            if (i.carried)
            {
                // Advected over the mission's time span: from the earliest departure (or t_ref) to the latest
                // departure plus five straight-line crossings of the box at the vehicle speed, within the field's time.
                const Point2 ref = shape.outer().front();
                const double diag = std::hypot(frame_.box.xMax - frame_.box.xMin, frame_.box.yMax - frame_.box.yMin);
                const double firstDep = m.departure.window ? m.departure.begin : m.departure.time;
                const double lastDep = m.departure.window ? m.departure.end : m.departure.time;
                double t0 = std::min(i.tRef, firstDep), t1 = std::max(i.tRef, lastDep + 5.0 * diag / m.vehicle.speed);
                t0 = std::max(t0, field_->timeBegin());
                t1 = std::min(t1, field_->timeEnd());
                regions->add(std::make_shared<IceZone>(i.polygon.name, shape, i.tRef, *field_, ref, t0,
                                                       std::max(t1, t0), i.maxSubmergedTime));
            }
            else
                regions->add(std::make_shared<IceZone>(i.polygon.name, shape, i.tRef, i.vx, i.vy, i.maxSubmergedTime));
        }
        catch (const Error &e)
        {
            throw Error(sourcePlace(m, i.polygon.mark) + e.what());
        }
    }
    checkGeoJsonNearBox();
    addSafety(*regions, in);
    if (regions->size() > 0)
        environment_ = regions;
}

} // namespace ompl_glider

// A start or goal on a forecast's land: the nearest water, named in the refusal or taken as the endpoint
// (safety.snap_to_water, --snap-to-water); and what reading the forecast decided that a pilot should know
// (forecastNotes()).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../io/NumberText.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/mission/MissionProblem.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/current/NetCdfCurrents.h"
#endif

namespace ompl_glider
{
std::optional<Point2> nearestWater(const CurrentField &field, Point2 p, double z, double step)
{
    // the closest points of land's boundary, nearest first; just beyond each (away from p, or across the edge)
    std::vector<std::pair<double, std::pair<Point2, Point2>>> near;  // distance, (closest point, edge normal)
    for (const Segment2 &e : field.landBoundary(z))
    {
        const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y, len2 = dx * dx + dy * dy;
        if (!(len2 > 0.0))
            continue;
        const double s = std::clamp(((p.x - e.a.x) * dx + (p.y - e.a.y) * dy) / len2, 0.0, 1.0);
        const Point2 q{e.a.x + s * dx, e.a.y + s * dy};
        const double len = std::sqrt(len2);
        near.push_back({std::hypot(q.x - p.x, q.y - p.y), {q, Point2{-dy / len, dx / len}}});
    }
    std::sort(near.begin(), near.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
    if (near.size() > 256)
        near.resize(256);
    for (const auto &[d, qn] : near)
    {
        const auto &[q, n] = qn;
        std::vector<Point2> dirs{n, Point2{-n.x, -n.y}};
        if (d > 0.0)
            dirs.insert(dirs.begin(), Point2{(q.x - p.x) / d, (q.y - p.y) / d});
        for (const double f : {1.0, 3.0})
            for (const Point2 &u : dirs)
            {
                const Point2 w{q.x + f * step * u.x, q.y + f * step * u.y};
                if (field.inWater(w.x, w.y, z))
                    return w;
            }
    }
    return std::nullopt;
}

void MissionProblem::snapEndpoints()
{
    const auto grid = std::dynamic_pointer_cast<const GriddedCurrentField>(members_.empty() ? field_ : members_.front());
    if (!grid)
        return;
    const MissionSpec &m = spec_;
    const double z = m.vehicle.depth;
    auto text = [&](Point2 p) {
        if (!isGeographic())
            return "x,y " + text::number(p.x) + "," + text::number(p.y);
        const LonLat g = toGeographic(p);
        return "lon,lat " + text::number(g.lon, 8) + "," + text::number(g.lat, 8);
    };
    for (const auto &[name, p] : {std::pair<const char *, Point2 *>{"start", &start_}, {"goal", &goal_}})
    {
        double fi, fj;
        if (!grid->locate(p->x, p->y, fi, fj) || grid->inWater(p->x, p->y, z))
            continue;  // (outside the grid: the planning box's check names it)
        const std::optional<Point2> w = nearestWater(*grid, *p, z, 0.01 * grid->minCellSize());
        if (!w)
            throw Error(m.place(name) + ": " + text(*p) + " is on land in the forecast at depth " + text::number(z) +
                        " m, and the forecast has no water there");
        const double d = std::hypot(w->x - p->x, w->y - p->y);
        const std::string away = isGeographic() ? text::number(d / 1000.0, 4) + " km" : text::number(d, 6);
        if (!m.safety.snapToWater)
            throw Error(m.place(name) + ": " + text(*p) + " is on land in the forecast at depth " + text::number(z) +
                        " m; the nearest water is " + text(*w) + ", " + away +
                        " away: give that, or --snap-to-water (safety.snap_to_water: true) to use it");
        endpointNotes_.push_back(std::string(name) + " " + text(*p) + " is on land: moved to the nearest water " +
                                 text(*w) + " (" + away + " away; safety.snap_to_water)");
        *p = *w;
    }
}

#if OMPL_GLIDER_WITH_NETCDF
std::vector<std::string> forecastNotes(const NetCdfCurrents &nc)
{
    std::vector<std::string> notes;
    if (nc.gridAngle.rfind("variable ", 0) == 0)
        notes.push_back("grid angle from the " + nc.gridAngle + " (velocities along the grid turned to east/north)");
    else if (!nc.gridAngle.empty())
        notes.push_back("grid angle " + nc.gridAngle + " (the file has no angle variable and its velocities do not "
                        "say they are eastward/northward)");
    return notes;
}
#endif
}  // namespace ompl_glider

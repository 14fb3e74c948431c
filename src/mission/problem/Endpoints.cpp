// A start or goal on a forecast's land: the nearest water, named in the refusal or taken as the endpoint
// (safety.snap_to_water, --snap-to-water).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../../io/NumberText.h"
#include "ompl_glider/current/BeyondForecast.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/SettingRanges.h"

namespace ompl_glider
{
std::optional<Point2> nearestWater(const CurrentField &field, Point2 p, double z, double step)
{
    // the closest points of land's boundary, nearest first; just beyond each (away from p, or across the edge)
    struct Near
    {
        double d;
        Point2 q, n, t; // closest point, edge normal, unit vector from q into the edge (zero at its middle)
    };
    std::vector<Near> near;
    for (const Segment2 &e : field.landBoundary(z))
    {
        const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y, len2 = dx * dx + dy * dy;
        if (!(len2 > 0.0))
            continue;
        const double s = std::clamp(((p.x - e.a.x) * dx + (p.y - e.a.y) * dy) / len2, 0.0, 1.0);
        const Point2 q{e.a.x + s * dx, e.a.y + s * dy};
        const double len = std::sqrt(len2), in = s < 0.5 ? 1.0 : -1.0;
        near.push_back(
            {std::hypot(q.x - p.x, q.y - p.y), q, Point2{-dy / len, dx / len}, Point2{in * dx / len, in * dy / len}});
    }
    std::sort(near.begin(), near.end(), [](const Near &a, const Near &b) { return a.d < b.d; });
    if (near.size() > 256)
        near.resize(256);
    for (const Near &c : near)
    {
        const Point2 q = c.q, n = c.n, t = c.t;
        // across the edge (away from p, or either side), also inwards along it (q may be a corner of the grid)
        std::vector<Point2> dirs{n, Point2{-n.x, -n.y}, Point2{n.x + t.x, n.y + t.y}, Point2{t.x - n.x, t.y - n.y}};
        if (c.d > 0.0)
        {
            const Point2 a{(q.x - p.x) / c.d, (q.y - p.y) / c.d};
            dirs.insert(dirs.begin(), {a, Point2{a.x + t.x, a.y + t.y}});
        }
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
    const CurrentField &field = *(members_.empty() ? field_ : members_.front());
    const FieldGrid *grid = field.grid();
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
    std::vector<std::pair<std::string, Point2 *>> points{{"start", &start_}, {"goal", &goal_}};
    for (std::size_t i = 0; i < via_.size(); ++i)
        points.emplace_back("waypoints[" + std::to_string(i) + "]", &via_[i]);
    for (const auto &[name, p] : points)
    {
        if (!grid->covers(p->x, p->y) || field.inWater(p->x, p->y, z))
            continue; // (outside the grid: the planning box's check names it)
        const std::optional<Point2> w = nearestWater(field, *p, z, 0.01 * grid->minCellSize());
        if (!w)
            throw Error(m.place(name) + ": " + text(*p) + " is on land in the forecast at depth " + text::number(z) +
                        " m, and the forecast has no water there");
        const double d = std::hypot(w->x - p->x, w->y - p->y);
        const std::string away = isGeographic() ? text::number(d / 1000.0, 4) + " km" : text::number(d, 6);
        if (!m.safety.snapToWater)
            throw Error(m.place(name) + ": " + text(*p) + " is on land in the forecast at depth " + text::number(z) +
                        " m; the nearest water is " + text(*w) + ", " + away + " away: give that, or " +
                        m.term("safety.snap_to_water: true") + " to use it");
        endpointNotes_.push_back(name + " " + text(*p) + " is on land: moved to the nearest water " + text(*w) + " (" +
                                 away + " away; safety.snap_to_water)");
        *p = *w;
    }
}

MissionProblem MissionProblem::withMember(std::size_t member) const
{
    MissionProblem p(*this);
    p.field_ = members_.empty() ? weighedMembers_.at(member) : members_.at(member);
    p.members_.clear();
    p.weighedMembers_.clear();
    return p;
}

MissionProblem MissionProblem::withLeg(Point2 start, Point2 goal, const GoalWindowSpec &window) const
{
    MissionProblem p(*this);
    p.start_ = start;
    p.goal_ = goal;
    p.spec_.goalWindow = window;
    p.spec_.waypoints.clear();
    p.via_.clear();
    // the spec's ends are the leg's (x/y in the file's units, or lon/lat), as a one-leg mission between them has
    for (const auto &[spec, q] : {std::pair<PointSpec *, Point2>{&p.spec_.start, start}, {&p.spec_.goal, goal}})
        if (spec->geographic)
            spec->lonLat = toGeographic(q);
        else
            spec->xy = {q.x / frame_.xyScale, q.y / frame_.xyScale};
    if (gridSizeAutomatic_ && std::hypot(goal.x - start.x, goal.y - start.y) > 0.0)
        p.spec_.planner.gridSize = p.automaticGridSize(start, goal); // the leg's own, as a one-leg mission's
    return p;
}

double MissionProblem::automaticGridSize(Point2 a, Point2 b) const
{
    const FieldGrid *grid = (members_.empty() ? field_ : members_.front())->grid();
    const double d = std::hypot(b.x - a.x, b.y - a.y);
    double g = grid ? defaultForecastGridSize(grid->minCellSize(), d) : defaultAnalyticGridSize(spec_, d);
    // a leg of a few tens of metres in a box of a hundred kilometres: a spacing whose lattice the box can hold (its
    // start and goal then share a lattice cell and its direct edge), two significant digits, rounded up
    const double area = (frame_.box.xMax - frame_.box.xMin) * (frame_.box.yMax - frame_.box.yMin);
    const double finest = std::sqrt(area / kAutomaticLatticeVertices);
    if (std::isfinite(finest) && finest > g)
    {
        const double scale = std::pow(10.0, std::floor(std::log10(finest)) - 1.0);
        g = std::ceil(finest / scale) * scale;
    }
    return g;
}

MissionProblem MissionProblem::withField(std::shared_ptr<const CurrentField> field) const
{
    MissionProblem p(*this);
    p.field_ = std::move(field);
    p.members_.clear();
    p.runs_.reset(); // planned on that field alone, not on the forecast's runs
    return p;
}

MissionProblem MissionProblem::withEndpoints(Point2 start, Point2 goal) const
{
    MissionProblem p(*this);
    p.start_ = start;
    if (goal.x != goal_.x || goal.y != goal_.y)
        p.spec_.goalWindow = {}; // the window belongs to the mission's goal
    p.goal_ = goal;
    return p;
}

void MissionProblem::checkViaPoints() const
{
    const MissionSpec &m = spec_;
    const double span = field_->timeEnd() - field_->timeBegin();
    for (std::size_t i = 0; i < via_.size(); ++i)
    {
        const ViaPointSpec &v = m.waypoints[i];
        const std::string field = "waypoints[" + std::to_string(i) + "]";
        const std::string named = " (via point '" + v.name + "')";
        // land's keep-off band, shallow water, an island or a restricted area: the leg could never end there
        if (environment_ && environment_->isStatic())
            if (const std::string why = environment_->whyBlocked(via_[i].x, via_[i].y, m.departure.time); !why.empty())
                throw Error(m.place(field) + named + ": the point is " + why);
        if (std::isfinite(span) && v.stay > span)
            throw Error(m.place(field + ".stay") + named + ": a stay of " + m.durationText(v.stay) +
                        " is longer than the whole forecast");
        if (!std::isnan(v.radius)) // (a program may set it without the loader: its declared range)
            try
            {
                checkSetting("waypoints[].radius", v.radius, text::number(v.radius));
            }
            catch (const Error &err)
            {
                throw Error(m.place(field + ".radius") + named + ": " + err.what());
            }
    }
}

Point2 MissionProblem::localPoint(const PointSpec &p, const std::string &what) const
{
    if (!p.geographic)
        return {p.xy.x * frame_.xyScale, p.xy.y * frame_.xyScale};
    if (!frame_.projection)
        throw Error(spec_.place(what) + ": lon/lat given but the forecast has no geographic coordinates");
    return toLocal(p.lonLat);
}

} // namespace ompl_glider

/// @file NoPathDiagnosis.cpp
/// @brief What blocks a route that no planner found, in the pilot's terms (diagnoseNoPath()): start or goal cut off
/// from the other's water (by the forecast's land at its resolution, or by forbidden regions, coastlines and the
/// keep-off distance), a forecast too short to arrive in, a current faster than the glider. Each finding comes with
/// the advice that can help, and replaces the generic advice of the planner's own reason.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>

#include "PlanningInternal.h"
#include "ompl_glider/current/CurrentField.h"
#include "../../io/NumberText.h"

namespace ompl_glider
{
namespace planning_detail
{
namespace
{
/// A lattice of sample points over the planning box, 4-connected where the leg between two neighbours is in water
/// (and, with @p env, free of the static forbidden regions); start and goal joined to the points near them.
struct WaterGraph
{
    std::size_t nx{0}, ny{0};
    double x0{0.0}, y0{0.0}, h{1.0};
    std::vector<std::uint8_t> open; ///< the point is in water (and free)

    Point2 at(std::size_t i, std::size_t j) const
    {
        return {x0 + h * static_cast<double>(i), y0 + h * static_cast<double>(j)};
    }
};

bool legOpen(const CurrentField &field, const Environment *env, double z, double t, Point2 a, Point2 b)
{
    return field.segmentInWater(a.x, a.y, b.x, b.y, z) && (!env || env->legFree(a.x, a.y, t, b.x, b.y, t));
}

/// The points reached from @p from through open legs (marks in @p seen), and the number of them.
std::size_t flood(const WaterGraph &g, const CurrentField &field, const Environment *env, double z, double t,
                  Point2 from, std::vector<std::uint8_t> &seen)
{
    seen.assign(g.nx * g.ny, 0);
    std::deque<std::size_t> queue;
    // the points within two spacings of the point, joined by an open leg
    const long ci = std::lround((from.x - g.x0) / g.h), cj = std::lround((from.y - g.y0) / g.h);
    for (long j = cj - 2; j <= cj + 2; ++j)
        for (long i = ci - 2; i <= ci + 2; ++i)
        {
            if (i < 0 || j < 0 || i >= static_cast<long>(g.nx) || j >= static_cast<long>(g.ny))
                continue;
            const std::size_t n = static_cast<std::size_t>(j) * g.nx + static_cast<std::size_t>(i);
            if (g.open[n] && !seen[n] &&
                legOpen(field, env, z, t, from, g.at(static_cast<std::size_t>(i), static_cast<std::size_t>(j))))
            {
                seen[n] = 1;
                queue.push_back(n);
            }
        }
    std::size_t count = 0;
    while (!queue.empty())
    {
        const std::size_t n = queue.front();
        queue.pop_front();
        ++count;
        const std::size_t i = n % g.nx, j = n / g.nx;
        const long di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
        for (int k = 0; k < 4; ++k)
        {
            const long a = static_cast<long>(i) + di[k], b = static_cast<long>(j) + dj[k];
            if (a < 0 || b < 0 || a >= static_cast<long>(g.nx) || b >= static_cast<long>(g.ny))
                continue;
            const std::size_t m = static_cast<std::size_t>(b) * g.nx + static_cast<std::size_t>(a);
            if (g.open[m] && !seen[m] &&
                legOpen(field, env, z, t, g.at(i, j), g.at(static_cast<std::size_t>(a), static_cast<std::size_t>(b))))
            {
                seen[m] = 1;
                queue.push_back(m);
            }
        }
    }
    return count;
}

/// Whether the goal's neighbourhood is reached from the start on @p g; the sizes of both components.
struct Connection
{
    bool connected{true};
    std::size_t startPoints{0}, goalPoints{0};
};

Connection connection(const WaterGraph &g, const CurrentField &field, const Environment *env, double z, double t,
                      Point2 s, Point2 goal)
{
    Connection c;
    std::vector<std::uint8_t> fromStart, fromGoal;
    c.startPoints = flood(g, field, env, z, t, s, fromStart);
    c.goalPoints = flood(g, field, env, z, t, goal, fromGoal);
    if (legOpen(field, env, z, t, s, goal))
        return c;
    for (std::size_t n = 0; n < fromStart.size(); ++n)
        if (fromStart[n] && fromGoal[n])
            return c;
    c.connected = false;
    return c;
}

WaterGraph waterGraph(const MissionProblem &problem, const Environment *env, double z, double t, double h)
{
    const Region &box = problem.getBox();
    WaterGraph g;
    g.h = h;
    g.x0 = box.xMin;
    g.y0 = box.yMin;
    g.nx = static_cast<std::size_t>(std::floor((box.xMax - box.xMin) / h)) + 1;
    g.ny = static_cast<std::size_t>(std::floor((box.yMax - box.yMin) / h)) + 1;
    g.open.assign(g.nx * g.ny, 0);
    const CurrentField &field = *problem.getField();
    for (std::size_t j = 0; j < g.ny; ++j)
        for (std::size_t i = 0; i < g.nx; ++i)
        {
            const Point2 p = g.at(i, j);
            g.open[j * g.nx + i] = field.inWater(p.x, p.y, z) && (!env || env->pointFree(p.x, p.y, t));
        }
    return g;
}

/// A length for the pilot: km with physical units, else the field's number.
std::string lengthText(const MissionSpec &m, double d)
{
    return m.physicalUnits().length ? text::number(d * m.metresPerUnit() / 1000.0, 4) + " km" : text::number(d, 6);
}

/// A duration for the pilot: days and hours with the seconds beside them, else the field's number.
std::string durationOf(const MissionSpec &m, double t)
{
    return m.physicalUnits().time ? text::durationText(t * m.timeUnitSeconds) : text::number(t, 6) + " time units";
}

} // namespace

std::string enclosure(const MissionProblem &problem, double t0, bool *byModelLand)
{
    if (byModelLand)
        *byModelLand = false;
    const MissionSpec &m = problem.getSpec();
    const Region &box = problem.getBox();
    const CurrentField &field = *problem.getField();
    const FieldGrid *gridded = field.grid();
    const double side = std::max(box.xMax - box.xMin, box.yMax - box.yMin);
    double h = side / 250.0;
    if (gridded)
        h = std::min(h, 0.5 * gridded->minCellSize());
    h = std::max(h, std::sqrt((box.xMax - box.xMin) * (box.yMax - box.yMin) / 250000.0)); // at most 250000 points
    if (!(h > 0.0) || !std::isfinite(h))
        return "";
    const double z = m.vehicle.depth;
    const Environment *env =
        problem.getEnvironment() && problem.getEnvironment()->isStatic() ? problem.getEnvironment().get() : nullptr;
    const Point2 s = problem.getStart(), g = problem.getGoal();
    // the forecast's own land first: a passage closed at the model's resolution
    const Connection water = connection(waterGraph(problem, nullptr, z, t0, h), field, nullptr, z, t0, s, g);
    // sampled coarser than half a model cell (a huge region), a narrow passage may be missed: no verdict then
    if (!water.connected && gridded && h > 0.5 * gridded->minCellSize() * (1.0 + 1e-9))
        return "";
    if (byModelLand)
        *byModelLand = !water.connected;
    Connection c = water;
    if (water.connected && env)
        c = connection(waterGraph(problem, env, z, t0, h), field, env, z, t0, s, g);
    if (c.connected)
        return "";
    const bool startSide = c.startPoints <= c.goalPoints;
    const double area = static_cast<double>(startSide ? c.startPoints : c.goalPoints) * h * h;
    std::string what =
        std::string(startSide ? "the start" : "the goal") + " is enclosed: the water around it (" +
        (m.physicalUnits().length ? text::number(area * std::pow(m.metresPerUnit() / 1000.0, 2), 3) + " km2"
                                  : text::number(area, 3) + " square units") +
        ") does not reach " + (startSide ? "the goal" : "the start") + "'s";
    if (!water.connected)
        what += gridded ? ", closed by the forecast's land at its resolution (cells of " +
                              lengthText(m, gridded->minCellSize()) +
                              ": a passage narrower than a model cell is closed); a forecast on a finer grid, or " +
                              "other start and goal points, may help"
                        : ", closed by the current field's land; choose other start and goal points";
    else
        what += ", closed by forbidden regions, coastline polygons or the keep-off distance" +
                std::string(m.safety.keepOff > 0.0 ? " (keep-off " + lengthText(m, m.safety.keepOff) + ")" : "") +
                "; a smaller keep-off distance or other start and goal points may help";
    return what;
}

void diagnoseNoPath(const MissionProblem &problem, double tDep, PlannedPath &r)
{
    // a search stopped by its time limit is not diagnosed: more time is the advice
    const NoPathCause cause = r.noPath.cause;
    // nor an ensemble's: its reason says that no member is reached, and comes first
    if (r.solved || r.badInput.any() || cause == NoPathCause::TimeLimit || cause == NoPathCause::Approximate ||
        cause == NoPathCause::NotRobust)
        return;
    const MissionSpec &m = problem.getSpec();
    const GliderProblem gp = problem.gliderProblem(tDep, r.speed > 0.0 ? r.speed : m.vehicle.speed);
    const double speed = gp.travel.speed;
    std::vector<std::string> findings;
    const std::string enclosed = enclosure(problem, tDep);
    if (!enclosed.empty())
        findings.push_back(enclosed);
    Region window = problem.getBox();
    window.zMin = window.zMax = m.vehicle.depth;
    window.tMin = tDep;
    window.tMax = tDep + gp.horizon;
    const double cMax = problem.getField()->maxSpeed(window);
    const Point2 s = problem.getStart(), g = problem.getGoal();
    const double distance = std::hypot(g.x - s.x, g.y - s.y);
    const double fieldEnd = problem.getField()->timeEnd();
    const bool forecastBound =
        std::isfinite(fieldEnd) && gp.t0 + gp.horizon >= fieldEnd - 1e-9 * std::max(1.0, std::abs(fieldEnd));
    if (enclosed.empty() && forecastBound)
    {
        const std::string end = problem.isoTime(fieldEnd);
        std::string f = "the forecast ends " + (end.empty() ? "" : "at " + end + ", ") + durationOf(m, gp.horizon) +
                        " after the departure";
        if (distance / (speed + cMax) > gp.horizon)
            f += ", sooner than the glider can cover the " + lengthText(m, distance) +
                 " to the goal even with the "
                 "strongest current behind it (at least " +
                 durationOf(m, distance / (speed + cMax)) + ")";
        else
            f += ", before the glider reaches the goal";
        findings.push_back(f + ": plan on its last field past its end (" + m.term("current.horizon: hold_last") +
                           "), depart earlier, or use a forecast that runs longer");
    }
    // the current is named where time is not what is short: the glider would cross still water twice over
    if (enclosed.empty() && cMax > speed && gp.horizon >= 2.0 * distance / speed)
    {
        const double ms = m.metresPerUnit() / m.timeUnitSeconds, kn = 3600.0 / 1852.0;
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "the current reaches up to %.2f m/s (%.1f kn) on the way, faster than the glider's V = %.2f m/s "
                      "(%.1f kn): it carries the glider off faster than it makes way; a faster vehicle (%s) or "
                      "another departure may help",
                      cMax * ms, cMax * ms * kn, speed * ms, speed * ms * kn, m.term("vehicle.speed").c_str());
        findings.push_back(m.physicalUnits().length && m.physicalUnits().time
                               ? std::string(buf)
                               : "the current reaches up to " + text::number(cMax, 4) + " against the glider's V = " +
                                     text::number(speed, 4) + ": a faster vehicle or another departure may help");
    }
    if (findings.empty())
        return;
    std::string why;
    for (const std::string &f : findings)
        why += (why.empty() ? "" : "; ") + f;
    // the planner's generic advice gives way to the findings, and so does the bound where they name it
    NoPath n = r.noPath;
    n.what = why + " (" + n.what + (!enclosed.empty() || forecastBound ? std::string() : n.boundText) + ")";
    n.advice.clear();
    n.boundText.clear();
    r.setNoPath(std::move(n));
}
} // namespace planning_detail
} // namespace ompl_glider

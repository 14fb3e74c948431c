#include "ompl_glider/output/MissionMap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../io/NumberText.h"
#include "ompl_glider/Config.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif

namespace ompl_glider
{
namespace
{
std::string fmt(double v)
{
    return text::number(v, 4);
}

MapPolygon mapPolygon(const MissionPolygon &p)
{
    MapPolygon mp;
    mp.label = p.name;
    if (p.coastline)
    {
        // a coastline's polygons (often hundreds): one legend entry, no labels on the map
        mp.label.clear();
        mp.legend = "land (coastline)";
    }
    for (const Point2 &q : p.points)
        mp.vertices.push_back({q.x, q.y});
    if (p.kind == RegionKind::Closure)
    {
        mp.hatched = true;
        mp.fill = {0.9, 0.6, 0.1, 0.35};
        mp.stroke = {0.7, 0.4, 0.0, 1.0};
    }
    else if (p.kind == RegionKind::Ice)
    {
        mp.fill = {0.85, 0.93, 1.0, 0.75};
        mp.stroke = {0.3, 0.5, 0.8, 1.0};
        mp.label += " (ice at t_ref)";
    }
    return mp;
}

/// The time ticks' unit a pilot reads when the mission has physical time units: hours, or days for a trip of more
/// than 4 days (seconds); 0: field time.
double tickSeconds(const MissionResult &r)
{
    if (!r.spec.physicalUnits().time)
        return 0.0;
    return r.plan.travelTime * r.spec.timeUnitSeconds > 4 * 86400.0 ? 86400.0 : 3600.0;
}

/// The paths' times as the ticks read them: tickSeconds() after the departure (field time without a unit).
void toTickTimes(const MissionResult &r, std::vector<std::vector<TimedPoint> *> paths)
{
    const double unit = tickSeconds(r);
    if (unit > 0.0)
        for (auto *v : paths)
            for (auto &w : *v)
                w.t = (w.t - r.plan.departure) * r.spec.timeUnitSeconds / unit;
}

/// A duration for the pilot: "3.2 days (76.8 h)" or "5.4 h" with physical time units (short: "3.20 d"), else the
/// field's number.
std::string duration(const MissionResult &r, double t, bool shortForm = false)
{
    if (!r.spec.physicalUnits().time || !std::isfinite(t))
        return fmt(t);
    const double h = t * r.spec.timeUnitSeconds / 3600.0;
    char buf[64];
    if (h >= 48.0 && shortForm)
        std::snprintf(buf, sizeof buf, "%.2f d", h / 24.0);
    else if (h >= 48.0)
        std::snprintf(buf, sizeof buf, "%.2f days (%.1f h)", h / 24.0, h);
    else
        std::snprintf(buf, sizeof buf, "%.2f h", h);
    return buf;
}

/// A length: km when the frame is in metres, else the field's number.
std::string length(const MissionResult &r, double d)
{
    if (!r.spec.physicalUnits().length)
        return fmt(d);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.1f km", d * r.spec.metresPerUnit() / 1000.0);
    return buf;
}

void addPaths(MapRenderer &map, const MissionResult &r)
{
    const PlannedPath &p = r.plan;
    std::vector<TimedPoint> raw = p.raw, smoothed = p.smoothed, fin = p.path, track = p.track;
    toTickTimes(r, {&raw, &smoothed, &fin, &track});
    const bool smoothedDiffers = p.smoothed.size() != p.raw.size() || p.smoothedTravelTime < p.rawTravelTime;
    const bool finalDiffers = p.path.size() != p.smoothed.size() || p.travelTime < p.smoothedTravelTime;
    MapPath rawPath = MapRenderer::rawPathStyle(
        p.planner + " path: " + std::to_string(p.raw.size()) + " wp, T=" + duration(r, p.rawTravelTime, true), raw);
    rawPath.timeTicks = !smoothedDiffers && !finalDiffers;
    map.addPath(rawPath);
    if (smoothedDiffers)
    {
        MapPath s = MapRenderer::smoothedPathStyle("smoothed: " + std::to_string(p.smoothed.size()) +
                                                       " wp, T=" + duration(r, p.smoothedTravelTime, true),
                                                   smoothed);
        s.timeTicks = !finalDiffers;
        map.addPath(s);
    }
    if (finalDiffers)
        map.addPath(MapRenderer::refinedPathStyle(
            "refined: " + std::to_string(p.path.size()) + " wp, T=" + duration(r, p.travelTime, true), fin));
    if (p.track.size() > 1)
    {
        // a mission whose legs mix straight legs and held headings: the flown track over the waypoints
        MapPath t = MapRenderer::refinedPathStyle("flown track (legs of held headings drift)", track);
        t.waypointMarkers = false;
        t.width = 1.5;
        map.addPath(t);
    }
}
/// A heading route: the flown track of held headings (time ticks), the segment ends marked.
void addHeadingRoute(MapRenderer &map, const MissionResult &r)
{
    const PlannedPath &p = r.plan;
    std::vector<TimedPoint> track = p.track, ends = p.path;
    toTickTimes(r, {&track, &ends});
    const std::string label = p.planner + ": " + std::to_string(p.headings->segments.size()) +
                              " held headings, T=" + duration(r, p.travelTime, true);
    MapPath t = MapRenderer::refinedPathStyle(label, track);
    t.waypointMarkers = false; // the track has a point per integration step
    map.addPath(t);
    MapPath marks = MapRenderer::rawPathStyle("segment ends (heading changes)", ends);
    marks.width = 0.6;
    map.addPath(marks);
}

/// The map's frame: lon/lat when the problem has them (the map then refers to the problem: draw it while the
/// problem lives), speeds in m/s for forecasts.
MapOptions mapFrame(const MissionProblem &problem)
{
    const MissionSpec &m = problem.getSpec();
    const bool netcdf = m.current.isForecast();
    MapOptions mo;
    if (problem.isGeographic())
    {
        mo.toGeographic = [&problem](Point2 p) { return problem.toGeographic(p); };
        mo.toLocal = [&problem](LonLat g) { return problem.toLocal(g); };
        mo.metresPerUnit = m.metresPerUnit();
    }
    mo.speedInMetresPerSecond = netcdf;
    mo.fieldWord = problem.fieldWord();
    mo.timeText = [&problem](double t) {
        const std::string iso = problem.isoTime(t);
        return iso.empty() ? "t=" + fmt(t) : iso;
    };
    return mo;
}

/// RMS over a time window of |truth - forecast| as the "speed" (u) of a steady field, for the difference map.
class RmsDifferenceField : public CurrentField
{
public:
    RmsDifferenceField(std::shared_ptr<const CurrentField> a, std::shared_ptr<const CurrentField> b, double t0,
                       double t1)
        : a_(std::move(a)), b_(std::move(b)), t0_(t0), t1_(t1)
    {
    }
    double maxSpeed(const Region &region) const override { return a_->maxSpeed(region) + b_->maxSpeed(region); }
    bool inWater(double x, double y, double z) const override { return a_->inWater(x, y, z) && b_->inWater(x, y, z); }
    std::string name() const override { return "RMS |truth - forecast|"; }

protected:
    Velocity evaluate(double x, double y, double z, double) const override
    {
        const double d = rmsDifference(*a_, *b_, x, y, z, t0_, t1_);
        return {std::isnan(d) ? 0.0 : d, 0.0};
    }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }

private:
    std::shared_ptr<const CurrentField> a_, b_;
    double t0_, t1_;
};
} // namespace

namespace
{
/// The glider's history with observations: its past surfacing fixes (a grey line with circles; the positions a source
/// gives only for its DAC, the middle of a dive, are not fixes) and the DAC it measured (purple arrows from where each
/// was measured, at the current arrows' scale, MapVectors).
void addGliderHistory(MapRenderer &map, const MissionProblem &problem)
{
#if OMPL_GLIDER_WITH_NETCDF
    const auto &o = problem.observations();
    if (!o || !problem.isGeographic())
        return;
    const MissionSpec &m = problem.getSpec();
    bool dacOnly = false;
    const std::vector<GliderFix> fixes = surfacingFixes(*o, &dacOnly);
    MapPath track;
    track.label = "glider: " + std::to_string(fixes.size()) +
                  (dacOnly             ? " past positions (of its DAC)"
                   : fixes.size() == 1 ? " past fix"
                                       : " past fixes");
    for (const GliderFix &f : fixes)
    {
        const Point2 q = problem.toLocal(f.at);
        track.waypoints.push_back({q.x, q.y, 0.0});
    }
    track.colour = {0.22, 0.28, 0.31, 0.95};
    track.width = 1.2;
    map.addPath(track);
    // the DAC in the field's velocity unit (m/s for a forecast), east and north turned into the frame there
    const double seconds = m.current.isForecast() ? 1.0 : m.hasTimeUnit() ? m.timeUnitSeconds : 0.0;
    const double perMs = seconds > 0.0 && m.physicalUnits().length ? seconds / m.metresPerUnit() : 1.0;
    MapVectors dac;
    dac.label = "glider: " + std::to_string(o->dac.size()) + " measured DAC";
    for (const DacRecord &d : o->dac)
    {
        const Point2 q = problem.toLocal(d.at);
        const Point2 e = problem.toLocal({d.at.lon + 0.01, d.at.lat}), n = problem.toLocal({d.at.lon, d.at.lat + 0.01});
        const double el = std::hypot(e.x - q.x, e.y - q.y), nl = std::hypot(n.x - q.x, n.y - q.y);
        dac.at.push_back(q);
        dac.velocity.push_back({perMs * (d.u * (e.x - q.x) / el + d.v * (n.x - q.x) / nl),
                                perMs * (d.u * (e.y - q.y) / el + d.v * (n.y - q.y) / nl)});
    }
    map.addVectors(dac);
#else
    (void)map;
    (void)problem;
#endif
}
} // namespace

MapRenderer modelDifferenceMap(const MissionResult &r, const MissionProblem &problem)
{
    const MissionSpec &m = r.spec;
    const ExecutionResult &e = *r.execution;
    MapOptions mo = mapFrame(problem);
    mo.arrows = false;
    const bool netcdf = m.current.isForecast();
    mo.shadingLabel = netcdf ? "RMS |truth - forecast| (m/s)" : "RMS |truth - forecast|";
    mo.title = m.name + " - truth against forecast, RMS over " + duration(r, e.differenceEnd - e.differenceBegin);
    MapRenderer map(problem.getBox(), mo);
    const double tEnd = std::max(
        e.differenceBegin, std::min({e.differenceEnd, problem.getField()->timeEnd(), problem.getTruth()->timeEnd()}));
    map.setField(std::make_shared<RmsDifferenceField>(problem.getTruth(), problem.getField(), e.differenceBegin, tEnd),
                 e.differenceBegin, m.vehicle.depth);
    for (const MissionPolygon &p : problem.getPolygons())
        map.addPolygon(mapPolygon(p));
    if (r.plan.solved)
    {
        MapPath plan = MapRenderer::refinedPathStyle("plan", r.plan.track.size() > 1 ? r.plan.track : r.plan.path);
        plan.waypointMarkers = !r.plan.headingRoute(); // a heading route's track: a point per integration step
        map.addPath(plan);
    }
    const Point2 s = problem.getStart(), g = problem.getGoal();
    map.setStartGoal(s.x, s.y, g.x, g.y);
    map.addNote("truth: " + e.truth);
    map.addNote("forecast: " + problem.getField()->name());
    map.addNote("RMS over the box " + fmt(e.rmsDifference) + (netcdf ? " m/s" : "") + ", largest at a point " +
                fmt(e.maxPointRmsDifference) + (netcdf ? " m/s" : ""));
    return map;
}

namespace
{
/// The probability of reach at its last frame (the horizon) as a colour fill of p (MapGridFill) and, with it and
/// lighter and thinner half way there, the contour of each level, one legend entry per level and frame, and a note with
/// the goal's probability and median arrival
/// ([SubramaniStochastic]).
void addReachContours(MapRenderer &map, const MissionResult &r)
{
    if (!r.reachability || r.reachability->contours.empty())
        return;
    const ReachProbability &p = *r.reachability;
    const double last = p.times.back();
    if (!p.probability.empty() && p.probability.back().size() == static_cast<std::size_t>(p.nx) * p.ny && p.h > 0.0)
    {
        // p at the horizon as a colour fill under the contours
        MapGridFill fill;
        fill.label = "probability of reach by +" + duration(r, last - p.departure, true);
        fill.x0 = p.x0;
        fill.y0 = p.y0;
        fill.h = p.h;
        fill.nx = p.nx;
        fill.ny = p.ny;
        fill.values = p.probability.back();
        map.setGridFill(std::move(fill));
    }
    std::vector<double> shown{last};
    if (p.times.size() >= 3)
        shown.insert(shown.begin(), p.times[(p.times.size() - 1) / 2]);
    for (const double t : shown)
        for (std::size_t l = 0; l < p.levels.size(); ++l)
        {
            const double f = p.levels.size() > 1 ? static_cast<double>(l) / (p.levels.size() - 1) : 1.0;
            const bool early = t != last;
            bool labelled = false;
            for (const ReachContour &c : p.contours)
            {
                if (c.time != t || c.level != p.levels[l])
                    continue;
                for (const auto &line : c.lines)
                {
                    MapPath path;
                    if (!labelled)
                        path.label = "p = " + fmt(100.0 * c.level) + " % by +" + duration(r, t - p.departure, true);
                    labelled = true;
                    for (const Point2 &q : line)
                        path.waypoints.push_back({q.x, q.y, t});
                    path.colour = {0.95 - 0.25 * f, 0.55 - 0.45 * f, 0.05, early ? 0.55 : 0.95};
                    path.width = early ? 1.2 : 2.0;
                    path.dashed = l + 1 < p.levels.size();
                    path.waypointMarkers = false;
                    map.addPath(path);
                }
            }
        }
    std::string q;
    for (const ReachQuantile &rq : p.quantiles)
        if (rq.q == 0.5)
            q = rq.reached ? ", median arrival +" + duration(r, rq.travelTime, true) : ", median not by the horizon";
    map.addNote("probability of reach over " + std::to_string(p.members) + (p.members == 1 ? " member" : " members") +
                ": the goal by +" + duration(r, last - p.departure, true) + " with p = " + fmt(p.goalProbability) + q);
}

/// What the glider flies as stints: the stint track, and the surfacings as markers.
void addStints(MapRenderer &map, const MissionResult &r)
{
    if (!r.plan.solved || !r.plan.stints)
        return;
    const StintOutcome &st = *r.plan.stints;
    char label[200];
    std::snprintf(label, sizeof label, "%s: %zu stints, %s left%s", st.converted ? "as stints" : r.plan.planner.c_str(),
                  st.plan.bearings.size(), length(r, st.plan.remainingDistance).c_str(),
                  st.plan.grounded ? " (on land)" : "");
    map.addPath(MapRenderer::stintTrackStyle(label, st.plan.track, st.converted ? 2 : 0));
    MapPath fixes = MapRenderer::rawPathStyle("surfacings", st.plan.surfacings);
    fixes.width = 0.6;
    map.addPath(fixes);
}

/// The optimal control's extremal through the goal, dashed, where one was found.
void addOptimum(MapRenderer &map, const MissionResult &r)
{
    if (!r.optimum || !r.optimum->found)
        return;
    MapPath opt;
    opt.label = "optimal control: T=" + fmt(r.optimum->travelTime);
    opt.waypoints = r.optimum->path;
    opt.colour = {0.10, 0.35, 0.95, 1.0};
    opt.width = 1.6;
    opt.dashed = true;
    opt.waypointMarkers = false;
    map.addPath(opt);
}

/// The reachable-set contours ([ThompsonICRA] Fig. 4), light to dark with time, one legend entry.
void addIsochrones(MapRenderer &map, const MissionResult &r)
{
    if (!r.isochrones || r.isochrones->contours.empty())
        return;
    const auto &cs = r.isochrones->contours;
    bool labelled = false;
    for (std::size_t k = 0; k < cs.size(); ++k)
    {
        const double f = cs.size() > 1 ? static_cast<double>(k) / (cs.size() - 1) : 1.0;
        for (const auto &line : cs[k].lines)
        {
            MapPath iso;
            if (!labelled)
            {
                iso.label = "reachable by +" + duration(r, cs.front().time - r.plan.departure, true) + " ... +" +
                            duration(r, cs.back().time - r.plan.departure, true);
                labelled = true;
            }
            for (const Point2 &p : line)
                iso.waypoints.push_back({p.x, p.y, cs[k].time});
            iso.colour = {0.55 - 0.35 * f, 0.25, 0.75 - 0.25 * f, 0.85};
            iso.width = 1.2;
            iso.waypointMarkers = false;
            map.addPath(iso);
        }
    }
}

/// The mission's own run flown in the truth, one dashed track per strategy, surfacings marked.
void addFlownTracks(MapRenderer &map, const MissionResult &r)
{
    if (!r.execution || !r.execution->runs.front().planned)
        return;
    const ExecutionResult &e = *r.execution;
    const Rgba colours[4] = {
        {0.05, 0.35, 0.85, 0.9}, {0.10, 0.60, 0.20, 0.9}, {0.95, 0.50, 0.05, 0.9}, {0.55, 0.20, 0.70, 0.9}};
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const FlownTrack &f = e.runs.front().flown[k];
        MapPath flown;
        std::string name = controlStrategyName(e.strategies[k]);
        if (name.rfind("current_", 0) == 0)
            name = name.substr(8);
        flown.label = name + ": " +
                      (f.reached ? duration(r, f.arrivalTime - r.plan.departure, true)
                                 : std::string(f.grounded ? "grounded" : "not there")) +
                      ", off " + length(r, f.finalDistance);
        flown.waypoints = f.fixes;
        flown.colour = colours[k % 4];
        flown.width = 1.4;
        flown.dashed = true;
        flown.waypointMarkers = false;
        map.addPath(flown);
    }
    map.addNote("dashed: the plan flown in the truth (" + e.truth + "), surfacing every " +
                duration(r, e.surfacingInterval) + "; arrival, distance off the goal at the planned arrival");
}

/// A mission's via points: their radius, name and arrival (a date where the field has dates).
void addViaStations(MapRenderer &map, const MissionResult &r, const MissionProblem &problem)
{
    const MissionSpec &m = r.spec;
    for (std::size_t i = 0; i < problem.getViaPoints().size(); ++i)
    {
        const ViaPointSpec &v = m.waypoints[i];
        std::string label = v.name;
        for (const PlannedLeg &l : r.legs)
            if (l.toVia == static_cast<int>(i) && l.plan.solved)
            {
                const std::string iso = problem.isoTime(l.arrival());
                label += " " + (iso.empty() ? "t=" + fmt(l.arrival()) : iso.substr(0, 16) + "Z") +
                         (l.stay > 0.0 ? " (stay " + duration(r, l.stay) + ")" : "");
            }
        map.addStation(problem.getViaPoints()[i], v.radius, label);
    }
}

/// The notes under the map: the departure, the travel time and path length (or why there is no path), and the time
/// the field is shown at (@p tMap).
void addNotes(MapRenderer &map, const MissionResult &r, const MissionProblem &problem, double tMap)
{
    const MissionSpec &m = r.spec;
    // the departure as a date when the field has dates (also without a path)
    const std::string iso = problem.isoTime(r.plan.departure);
    map.addNote("departure " + (iso.empty() ? fmt(r.plan.departure) : iso));
    if (r.plan.solved)
    {
        map.addNote("travel time " + duration(r, r.plan.travelTime) + ", path length " + length(r, r.plan.pathLength));
        if (const auto &e = r.plan.ensemble; e && e->arrivalProbability < 1.0) // the route, not the reach map
        {
            const std::size_t n = e->memberTravelTimes.size();
            const auto arriving = static_cast<std::size_t>(std::llround(e->arrivalProbability * double(n)));
            map.addNote("the route arrives in " + std::to_string(arriving) + " of " + std::to_string(n) +
                        " members (p = " + fmt(e->arrivalProbability) + "): none arrives in every member");
        }
        map.addNote("straight line: " + (std::isfinite(r.plan.straightLineTime)
                                             ? "T=" + duration(r, r.plan.straightLineTime)
                                             : std::string("impassable")));
    }
    else
        map.addNote("no path: " + r.plan.reason);
    map.addNote(std::isnan(m.outputs.mapTime)
                    ? "field shown at departure"
                    : "field shown at " + (problem.isoTime(tMap).empty() ? "t = " + fmt(tMap) : problem.isoTime(tMap)));
}
} // namespace

MapRenderer missionMap(const MissionResult &r, const MissionProblem &problem)
{
    const MissionSpec &m = r.spec;
    MapOptions mo = mapFrame(problem);
    const bool netcdf = m.current.isForecast();
    const std::string depIso = problem.isoTime(r.plan.departure);
    mo.title = m.name + " - " + r.plan.planner + ", V = " + fmt(r.plan.speed) + (netcdf ? " m/s" : "") +
               (depIso.empty() ? "" : ", departing " + depIso) + (r.plan.solved ? "" : " (no path)");
    if (const double unit = tickSeconds(r); unit > 0.0)
    {
        mo.tickUnit = unit == 86400.0 ? "d" : "h";
        mo.tickNote = std::string("ticks: ") + (unit == 86400.0 ? "days" : "hours") + " after the departure";
    }
    MapRenderer map(problem.getBox(), mo);
    const double tMap = std::isnan(m.outputs.mapTime) ? r.plan.departure : m.outputs.mapTime;
    map.setField(problem.getField(), tMap, m.vehicle.depth);
    for (const MissionPolygon &p : problem.getPolygons())
        map.addPolygon(mapPolygon(p));
    if (r.plan.solved && r.plan.headingRoute())
        addHeadingRoute(map, r);
    else if (r.plan.solved && !(r.plan.stints && !r.plan.stints->converted))
        addPaths(map, r);
    addStints(map, r);
    addOptimum(map, r);
    addIsochrones(map, r);
    addReachContours(map, r);
    addFlownTracks(map, r);
    addGliderHistory(map, problem);
    const Point2 s = problem.getStart(), g = problem.getGoal();
    map.setStartGoal(s.x, s.y, g.x, g.y);
    addViaStations(map, r, problem);
    addNotes(map, r, problem, tMap);
    return map;
}
} // namespace ompl_glider

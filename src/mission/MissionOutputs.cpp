#include "ompl_glider/mission/MissionOutputs.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MapRenderer.h"

namespace ompl_glider
{
namespace
{
std::string num(double v)
{
    if (!std::isfinite(v))
        return "null";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string csvNum(double v)
{
    if (std::isnan(v))
        return "";
    if (std::isinf(v))
        return v > 0 ? "inf" : "-inf";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string quote(const std::string &s)
{
    std::string o = "\"";
    for (char c : s)
    {
        switch (c)
        {
            case '"':
                o += "\\\"";
                break;
            case '\\':
                o += "\\\\";
                break;
            case '\n':
                o += "\\n";
                break;
            case '\t':
                o += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20)
                {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    o += buf;
                }
                else
                    o += c;
        }
    }
    return o + "\"";
}

/// A time as JSON: a number, or "impassable" when infinite.
std::string timeOrImpassable(double t)
{
    return std::isfinite(t) ? num(t) : "\"impassable\"";
}

bool geographic(const MissionResult &r)
{
    return !r.waypoints.empty() && r.waypoints.front().geographic;
}
}  // namespace

std::string waypointsCsv(const MissionResult &r)
{
    std::ostringstream s;
    s << "index,x,y,lon,lat,time,time_s,time_iso,leg_time,profile,climb_to,dive_to\n";
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        const MissionWaypoint &w = r.waypoints[i];
        s << i << "," << csvNum(w.x) << "," << csvNum(w.y) << ",";
        if (w.geographic)
            s << csvNum(w.lon) << "," << csvNum(w.lat);
        else
            s << ",";
        s << "," << csvNum(w.time) << "," << csvNum(w.time * r.spec.timeUnitSeconds) << "," << w.iso << ","
          << csvNum(w.legTime) << ",";
        if (r.diveProfiles && i > 0 && w.profile >= 0)
            s << w.profile << "," << csvNum(w.dive.climbTo) << "," << csvNum(w.dive.diveTo);
        else
            s << ",,";
        s << "\n";
    }
    return s.str();
}

std::string waypointsGeoJson(const MissionResult &r)
{
    const bool geo = geographic(r);
    auto coord = [&](const MissionWaypoint &w) {
        return "[" + num(geo ? w.lon : w.x) + ", " + num(geo ? w.lat : w.y) + "]";
    };
    std::ostringstream s;
    s << "{\"type\": \"FeatureCollection\",\n";
    if (!geo)
        s << " \"coordinates\": \"local\",\n";
    s << " \"features\": [\n";
    s << "  {\"type\": \"Feature\", \"properties\": {\"name\": " << quote(r.spec.name + " path")
      << ", \"departure\": " << num(r.plan.departure) << ", \"travel_time\": " << num(r.plan.travelTime)
      << ", \"path_length\": " << num(r.plan.pathLength) << "},\n   \"geometry\": {\"type\": \"LineString\", "
      << "\"coordinates\": [";
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
        s << (i ? ", " : "") << coord(r.waypoints[i]);
    s << "]}}";
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        const MissionWaypoint &w = r.waypoints[i];
        s << ",\n  {\"type\": \"Feature\", \"properties\": {\"index\": " << i << ", \"time\": " << num(w.time)
          << ", \"time_s\": " << num(w.time * r.spec.timeUnitSeconds)
          << ", \"time_iso\": " << (w.iso.empty() ? "null" : quote(w.iso)) << ", \"leg_time\": " << num(w.legTime);
        if (r.diveProfiles && i > 0 && w.profile >= 0)
            s << ", \"profile\": " << w.profile << ", \"climb_to\": " << num(w.dive.climbTo)
              << ", \"dive_to\": " << num(w.dive.diveTo);
        s << "},\n   \"geometry\": {\"type\": \"Point\", \"coordinates\": " << coord(w) << "}}";
    }
    s << "\n]}\n";
    return s.str();
}

std::string summaryJson(const MissionResult &r)
{
    const PlannedPath &p = r.plan;
    std::ostringstream s;
    s << "{\n";
    s << " \"mission\": " << quote(r.spec.name) << ",\n";
    s << " \"file\": " << quote(r.spec.file) << ",\n";
    s << " \"current\": " << quote(r.spec.current.type) << ",\n";
    s << " \"planner\": " << quote(r.spec.planner.name) << ",\n";
    s << " \"grid_size\": " << num(r.spec.planner.gridSize) << ",\n";
    s << " \"sectors\": " << r.spec.planner.sectors << ",\n";
    s << " \"status\": " << quote(p.status) << ",\n";
    s << " \"solved\": " << (p.solved ? "true" : "false") << ",\n";
    s << " \"speed\": " << num(p.speed) << ",\n";
    s << " \"departure\": " << num(p.departure) << ",\n";
    const std::string depIso = r.waypoints.empty() ? "" : r.waypoints.front().iso;
    s << " \"departure_iso\": " << (depIso.empty() ? "null" : quote(depIso)) << ",\n";
    s << " \"arrival_iso\": " << (r.waypoints.empty() || r.waypoints.back().iso.empty() ? "null" : quote(r.waypoints.back().iso))
      << ",\n";
    s << " \"time_unit_s\": " << num(r.spec.timeUnitSeconds) << ",\n";
    s << " \"length_unit_m\": " << num(r.spec.lengthUnitMetres) << ",\n";
    s << " \"travel_time\": " << num(p.travelTime) << ",\n";
    s << " \"travel_time_raw\": " << num(p.rawTravelTime) << ",\n";
    if (r.diveProfiles)
        s << " \"travel_time_dive_profiles\": " << timeOrImpassable(r.diveTravelTime) << ",\n";
    s << " \"path_length\": " << num(p.pathLength) << ",\n";
    s << " \"path_length_raw\": " << num(p.rawPathLength) << ",\n";
    s << " \"straight_line_travel_time\": " << timeOrImpassable(p.straightLineTime) << ",\n";
    s << " \"straight_line_length\": " << num(p.straightLineLength) << ",\n";
    s << " \"waypoints_raw\": " << p.raw.size() << ",\n";
    s << " \"waypoints_smoothed\": " << p.smoothedWaypoints << ",\n";
    s << " \"waypoints_final\": " << p.path.size() << ",\n";
    s << " \"cfc\": " << p.costFunctionCalls << ",\n";
    s << " \"cmc\": " << p.currentModelCalls << ",\n";
    s << " \"expansions\": " << p.expansions << ",\n";
    s << " \"planning_wall_time_s\": " << num(p.wallSeconds) << ",\n";
    // The keys of glider_plan's summary (issue 3), so every mode of the CLI writes them.
    s << " \"feasible\": " << (p.solved ? "true" : "false") << ",\n";
    s << " \"cost_function_calls\": " << p.costFunctionCalls << ",\n";
    s << " \"current_model_calls\": " << p.currentModelCalls << ",\n";
    s << " \"planning_time_s\": " << num(p.wallSeconds) << ",\n";
    s << " \"total_wall_time_s\": " << num(r.wallSeconds);
    if (r.diveProfiles)
    {
        s << ",\n \"dive_profiles\": [";
        for (std::size_t i = 0; i < r.profileSet.size(); ++i)
            s << (i ? ", " : "") << "{\"climb_to\": " << num(r.profileSet[i].climbTo)
              << ", \"dive_to\": " << num(r.profileSet[i].diveTo) << "}";
        s << "],\n \"selection\": " << quote(toString(r.spec.dive.params.selection));
    }
    if (r.departureSearch)
    {
        const DepartureSearchResult &d = *r.departureSearch;
        s << ",\n \"departure_search\": {\"found\": " << (d.found ? "true" : "false")
          << ", \"departure\": " << num(d.departure) << ", \"travel_time\": " << num(d.travelTime)
          << ", \"window_begin\": " << num(r.spec.departure.begin) << ", \"window_end\": " << num(d.windowEnd)
          << ", \"bracket\": [" << num(d.bracketLo) << ", " << num(d.bracketHi) << "]"
          << ", \"fine_searches\": " << d.fineEvaluations << ", \"coarse_searches\": " << d.coarseEvaluations
          << ", \"wall_time_s\": " << num(d.wallSeconds) << ",\n   \"supporting_points\": [";
        for (std::size_t i = 0; i < d.supportingPoints.size(); ++i)
            s << (i ? ", " : "") << "[" << num(d.supportingPoints[i].tDep) << ", "
              << timeOrImpassable(d.supportingPoints[i].travelTime) << "]";
        s << "],\n   \"refinements\": [";
        for (std::size_t i = 0; i < d.refinements.size(); ++i)
            s << (i ? ", " : "") << "[" << num(d.refinements[i].tDep) << ", "
              << timeOrImpassable(d.refinements[i].travelTime) << "]";
        s << "]}";
    }
    if (!r.speedSweep.empty())
    {
        s << ",\n \"speed_sweep\": [";
        for (std::size_t i = 0; i < r.speedSweep.size(); ++i)
        {
            const SpeedSweepRow &w = r.speedSweep[i];
            s << (i ? ",\n   " : "") << "{\"speed\": " << num(w.speed) << ", \"travel_time\": "
              << timeOrImpassable(w.travelTime) << ", \"path_length\": " << num(w.pathLength)
              << ", \"straight_line_travel_time\": " << timeOrImpassable(w.straightLineTime)
              << ", \"straight_line_length\": " << num(w.straightLineLength) << "}";
        }
        s << "]";
    }
    s << "\n}\n";
    return s.str();
}

GotoList gotoList(const MissionResult &r)
{
    if (!geographic(r))
        throw Error(r.spec.file + ": a goto list needs longitudes and latitudes (give a 'projection')");
    GotoList g;
    g.number = r.spec.outputs.gotoNumber;
    g.comment = r.spec.name;
    for (std::size_t i = r.spec.outputs.gotoIncludeStart ? 0 : 1; i < r.waypoints.size(); ++i)
        g.waypoints.push_back({r.waypoints[i].lon, r.waypoints[i].lat});
    return g;
}

std::string speedSweepTable(const std::vector<SpeedSweepRow> &rows)
{
    std::ostringstream s;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%8s %14s %12s %18s %14s\n", "speed", "travel time", "path length",
                  "straight-line time", "straight length");
    s << buf;
    for (const auto &r : rows)
    {
        const std::string tt = r.solved ? csvNum(r.travelTime) : "no path";
        const std::string st = std::isfinite(r.straightLineTime) ? csvNum(r.straightLineTime) : "impassable";
        std::snprintf(buf, sizeof buf, "%8.4g %14s %12.6g %18s %14.6g\n", r.speed, tt.c_str(), r.pathLength,
                      st.c_str(), r.straightLineLength);
        s << buf;
    }
    return s.str();
}

void printMissionReport(std::ostream &out, const MissionResult &r)
{
    const PlannedPath &p = r.plan;
    char buf[256];
    auto line = [&](const char *fmt, auto... args) {
        std::snprintf(buf, sizeof buf, fmt, args...);
        out << buf;
    };
    out << "mission " << r.spec.name << " (" << r.spec.file << "), current " << r.spec.current.type << ", planner "
        << r.spec.planner.name << "\n";
    if (r.departureSearch)
    {
        const DepartureSearchResult &d = *r.departureSearch;
        line("departure search over [%g, %g]: %zu fine + %zu coarse searches in %.3f s, best departure %s\n",
             r.spec.departure.begin, d.windowEnd, d.fineEvaluations, d.coarseEvaluations, d.wallSeconds,
             d.found ? csvNum(d.departure).c_str() : "none");
    }
    const std::string dep = r.waypoints.empty() ? "" : r.waypoints.front().iso;
    line("status: %s\n", p.status.c_str());
    line("departure %s%s%s%s\n", csvNum(p.departure).c_str(), dep.empty() ? "" : " (", dep.c_str(),
         dep.empty() ? "" : ")");
    if (!p.solved)
        return;
    line("travel time %s (lattice path %s)", csvNum(p.travelTime).c_str(), csvNum(p.rawTravelTime).c_str());
    if (r.diveProfiles)
        line(", with dive profiles %s",
             std::isfinite(r.diveTravelTime) ? csvNum(r.diveTravelTime).c_str() : "impassable");
    out << "\n";
    line("path length %s (lattice path %s); straight line %s, travel time %s\n", csvNum(p.pathLength).c_str(),
         csvNum(p.rawPathLength).c_str(), csvNum(p.straightLineLength).c_str(),
         std::isfinite(p.straightLineTime) ? csvNum(p.straightLineTime).c_str() : "impassable");
    line("waypoints raw %zu, smoothed %zu, final %zu; CFC %llu, CMC %llu; planning %.3f s, total %.3f s\n",
         p.raw.size(), p.smoothedWaypoints, p.path.size(), static_cast<unsigned long long>(p.costFunctionCalls),
         static_cast<unsigned long long>(p.currentModelCalls), p.wallSeconds, r.wallSeconds);
    line("%4s %12s %12s %11s %10s %14s %22s %16s\n", "#", "x", "y", "lon", "lat", "arrival", "arrival (UTC)",
         "dive profile");
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        const MissionWaypoint &w = r.waypoints[i];
        std::string prof;
        if (r.diveProfiles && i > 0 && w.profile >= 0)
            prof = csvNum(w.dive.climbTo) + "-" + csvNum(w.dive.diveTo);
        line("%4zu %12.6g %12.6g %11s %10s %14s %22s %16s\n", i, w.x, w.y,
             w.geographic ? csvNum(w.lon).substr(0, 11).c_str() : "", w.geographic ? csvNum(w.lat).substr(0, 10).c_str() : "",
             csvNum(w.time).c_str(), w.iso.c_str(), prof.c_str());
    }
    if (!r.speedSweep.empty())
        out << "speed sweep (003 Table VI):\n" << speedSweepTable(r.speedSweep);
    for (const auto &f : r.files)
        out << "wrote " << f << "\n";
}

int runMissionFile(const std::string &path, const MissionCommandOptions &options, std::ostream &out,
                   std::ostream &err)
{
    try
    {
        const MissionSpec spec = loadMission(path);
        RunOptions o;
        o.progress = options.progress;
        o.speeds = options.speeds;
        o.outputDirectory = options.outputDirectory;
        const MissionResult r = runMission(spec, o);
        printMissionReport(out, r);
        return r.plan.solved ? 0 : 1;
    }
    catch (const Error &e)
    {
        err << "error: " << e.what() << "\n";
        return 2;
    }
}

std::vector<double> parseSpeedList(const std::string &text)
{
    std::vector<double> v;
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
    {
        std::size_t pos = 0;
        double x = 0;
        try
        {
            x = std::stod(item, &pos);
        }
        catch (const std::exception &)
        {
            pos = 0;
        }
        while (pos < item.size() && std::isspace(static_cast<unsigned char>(item[pos])))
            ++pos;
        if (item.empty() || pos != item.size() || !(x > 0) || !std::isfinite(x))
            throw Error("--speeds: '" + item + "' is not a speed > 0 (expected e.g. 0.25,0.30,0.35)");
        v.push_back(x);
    }
    if (v.empty())
        throw Error("--speeds: empty list (expected e.g. 0.25,0.30,0.35)");
    return v;
}

void writeTextFile(const std::string &path, const std::string &text)
{
    std::ofstream out(path);
    if (!out || !(out << text) || !(out.flush()))
        throw Error("cannot write '" + path + "'");
}

MapRenderer missionMap(const MissionResult &r, const MissionProblem &problem)
{
    const OutputSpec &o = r.spec.outputs;
    Region box = problem.box();
    MapOptions mo;
    mo.title = r.spec.name + (r.plan.solved ? "" : " (no path)");
    // (No MapOptions::timeUnit: it would also label the field time, which stays in field units.)
    MapRenderer map(box, mo);
    const double tMap = std::isnan(o.mapTime) ? r.plan.departure : o.mapTime;
    map.setField(problem.field(), tMap, r.spec.vehicle.depth);
    for (const MissionPolygon &p : problem.polygons())
    {
        MapPolygon mp;
        mp.label = p.name;
        mp.vertices = p.points;
        if (p.kind == "closure")
        {
            mp.hatched = true;
            mp.fill = {0.9, 0.6, 0.1, 0.35};
            mp.stroke = {0.7, 0.4, 0.0, 1.0};
        }
        else if (p.kind == "ice")
        {
            mp.fill = {0.85, 0.93, 1.0, 0.75};
            mp.stroke = {0.3, 0.5, 0.8, 1.0};
            mp.label += " (ice at t_ref)";
        }
        map.addPolygon(mp);
    }
    if (r.plan.solved)
    {
        // Time ticks a pilot reads: hours or days after departure when the mission has physical time units.
        std::vector<TimedWaypoint> raw = r.plan.raw, fin = r.plan.path;
        const bool physical = r.spec.current.type == "netcdf" || r.spec.timeUnitSeconds != 1.0;
        if (physical)
        {
            const double tripSeconds = r.plan.travelTime * r.spec.timeUnitSeconds;
            const double unit = tripSeconds > 4 * 86400.0 ? 86400.0 : 3600.0;
            for (auto *v : {&raw, &fin})
                for (auto &w : *v)
                    w.t = (w.t - r.plan.departure) * r.spec.timeUnitSeconds / unit;
            map.addNote(std::string("ticks: ") + (unit == 86400.0 ? "days" : "hours") + " after departure");
        }
        map.addPath(MapRenderer::rawPathStyle("lattice path", raw));
        MapPath smooth = MapRenderer::smoothedPathStyle(
            r.spec.planner.smoothing ? "smoothed path" : "final path", fin);
        smooth.timeTicks = true;
        map.addPath(smooth);
        map.addNote("departure " + csvNum(r.plan.departure) +
                    (r.waypoints.empty() || r.waypoints.front().iso.empty() ? "" : " (" + r.waypoints.front().iso + ")"));
        map.addNote("travel time " + csvNum(r.plan.travelTime) + ", straight line " +
                    (std::isfinite(r.plan.straightLineTime) ? csvNum(r.plan.straightLineTime) : "impassable"));
    }
    map.setStartGoal(problem.startX(), problem.startY(), problem.goalX(), problem.goalY());
    return map;
}

std::vector<std::string> writeMissionOutputs(const MissionResult &r, const MissionProblem &problem)
{
    const OutputSpec &o = r.spec.outputs;
    std::vector<std::string> written;
    std::error_code ec;
    std::filesystem::create_directories(o.directory.empty() ? "." : o.directory, ec);
    if (ec)
        throw Error("cannot create the output directory '" + o.directory + "': " + ec.message());
    const std::string base = (o.directory.empty() ? "." : o.directory) + "/";
    for (const std::string &kind : o.files)
    {
        if (kind == "csv" && r.plan.solved)
        {
            writeTextFile(base + o.prefix + "_waypoints.csv", waypointsCsv(r));
            written.push_back(base + o.prefix + "_waypoints.csv");
        }
        else if (kind == "geojson" && r.plan.solved)
        {
            writeTextFile(base + o.prefix + ".geojson", waypointsGeoJson(r));
            written.push_back(base + o.prefix + ".geojson");
        }
        else if (kind == "goto" && r.plan.solved)
        {
            const std::string path = base + gotoFileName(o.gotoNumber);
            writeGotoFile(path, gotoList(r));
            written.push_back(path);
        }
        else if (kind == "summary")
        {
            writeTextFile(base + o.prefix + "_summary.json", summaryJson(r));
            written.push_back(base + o.prefix + "_summary.json");
        }
        else if (kind == "map")
        {
            const MapRenderer map = missionMap(r, problem);
            map.writeSvg(base + o.prefix + "_map.svg");
            map.writePng(base + o.prefix + "_map.png");
            written.push_back(base + o.prefix + "_map.svg");
            written.push_back(base + o.prefix + "_map.png");
        }
    }
    return written;
}
}  // namespace ompl_glider

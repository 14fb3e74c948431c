/// @file Fleet.cpp
/// @brief A fleet of gliders (Fleet.h): one mission per glider through runMission(), in threads or spread over the
/// processes of a job.

#include "ompl_glider/mission/Fleet.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>

#include "ompl_glider/Exception.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/ThreadPool.h"

namespace ompl_glider
{
namespace
{
FleetRow rowOf(const MissionSpec &spec, const MissionProblem &problem, const MissionResult &r)
{
    FleetRow row;
    row.name = spec.name;
    row.solved = r.plan.solved;
    row.status = r.plan.status;
    row.reason = r.plan.reason;
    if (!r.plan.solved && r.plan.badInput.any())
        row.badInput = spec.place(r.plan.badInput.field());
    row.departure = r.plan.departure;
    row.departureIso = problem.isoTime(row.departure);
    if (r.plan.solved)
    {
        row.travelTime = r.plan.travelTime;
        row.pathLength = r.plan.pathLength;
        row.arrival = r.waypoints.empty() ? row.departure + row.travelTime : r.waypoints.back().time;
        row.arrivalIso = problem.isoTime(row.arrival);
    }
    return row;
}

std::string pack(const FleetGlider &g)
{
    ByteWriter w;
    const FleetRow &r = g.row;
    for (const std::string *s : {&r.name, &r.reason, &r.badInput, &r.departureIso, &r.arrivalIso, &g.kept})
        w.put(*s);
    w.put(r.status);
    w.put(r.solved);
    for (const double v : {r.departure, r.travelTime, r.pathLength, r.arrival})
        w.put(v);
    return w.take();
}

FleetGlider unpack(const std::string &bytes)
{
    FleetGlider g;
    FleetRow &r = g.row;
    ByteReader in(bytes);
    for (std::string *s : {&r.name, &r.reason, &r.badInput, &r.departureIso, &r.arrivalIso, &g.kept})
        in.get(*s);
    in.get(r.status);
    in.get(r.solved);
    for (double *v : {&r.departure, &r.travelTime, &r.pathLength, &r.arrival})
        in.get(*v);
    return g;
}
} // namespace

namespace
{
/// The mission without its fleet and the fleet entries' marks: what every glider's mission starts from (made once
/// per fleet, so that a glider's mission costs the same whatever the fleet's size).
MissionSpec fleetBase(const MissionSpec &mission)
{
    MissionSpec m = mission; // once per fleet
    m.fleet.clear();
    for (auto it = m.marks.lower_bound("fleet["); it != m.marks.end() && it->first.rfind("fleet[", 0) == 0;)
        it = m.marks.erase(it);
    return m;
}

/// Glider @p i's mission from the fleet's base (fleetBase()) and the whole mission (its entry and marks).
MissionSpec gliderMission(const MissionSpec &base, const MissionSpec &mission, std::size_t i)
{
    const FleetGliderSpec &g = mission.fleet.at(i);
    MissionSpec m = base;
    m.name = g.name;
    m.start = g.start;
    m.goal = g.goal;
    if (g.speed)
        m.vehicle.speed = *g.speed;
    if (g.departure)
    {
        m.departure.time = *g.departure;
        m.departure.window = false;
    }
    if (!g.waypoints.empty())
    {
        // its own via points (a glider without any flies the mission's, if the mission lists some)
        m.waypoints = g.waypoints;
        m.order = VisitOrder::Given;
        for (auto it = m.marks.lower_bound("waypoints"); it != m.marks.end() && it->first.rfind("waypoints", 0) == 0;)
            it = m.marks.erase(it);
        const std::string own = "fleet[" + std::to_string(i) + "].waypoints";
        for (auto it = mission.marks.lower_bound(own); it != mission.marks.end() && it->first.rfind(own, 0) == 0; ++it)
            m.marks[it->first.substr(own.size() - std::string("waypoints").size())] = it->second;
    }
    if (g.order)
        m.order = *g.order;
    m.outputs.directory = (std::filesystem::path(mission.outputs.directory) / g.name).string();
    // the glider's values were given in its fleet entry: messages name those lines
    const std::string entry = "fleet[" + std::to_string(i) + "].";
    const std::pair<std::string, std::vector<std::string>> renamed[] = {{"start", {"", ".x", ".y", ".lon", ".lat"}},
                                                                        {"goal", {"", ".x", ".y", ".lon", ".lat"}},
                                                                        {"speed", {""}},
                                                                        {"departure", {""}}};
    for (const auto &[from, parts] : renamed)
    {
        const std::string to = from == "speed" ? "vehicle.speed" : from == "departure" ? "departure.time" : from;
        if (!mission.marks.count(entry + from) &&
            mission.marks.lower_bound(entry + from + ".") == mission.marks.lower_bound(entry + from + "/"))
            continue; // not given by the glider: the mission's value and place
        for (const std::string &part : parts)
        {
            m.marks.erase(to + part);
            const auto it = mission.marks.find(entry + from + part);
            if (it != mission.marks.end())
                m.marks[to + part] = it->second;
        }
    }
    return m;
}
} // namespace

MissionSpec fleetGliderMission(const MissionSpec &mission, std::size_t i)
{
    return gliderMission(fleetBase(mission), mission, i);
}

std::vector<FleetGlider> runFleet(const MissionSpec &mission, const RunOptions &options, const FleetKeep &keep)
{
    const std::size_t n = mission.fleet.size();
    RunOptions each = options;
    each.progress = {}; // one line per glider instead of each glider's own
    const MissionSpec base = fleetBase(mission);
    std::mutex loading;
    const auto plan = [&](std::size_t i) {
        const MissionSpec spec = gliderMission(base, mission, i);
        try
        {
            // the problems are built one at a time: they read the forecast, bathymetry and coastline files, and the
            // NetCDF and GDAL libraries are not thread-safe; the plans then run in parallel
            std::unique_lock<std::mutex> lock(loading);
            const MissionProblem problem(spec);
            lock.unlock();
            const MissionResult result = runMission(problem, each);
            FleetGlider g;
            g.row = rowOf(spec, problem, result);
            if (keep && g.row.badInput.empty())
                g.kept = keep(result, problem);
            return g;
        }
        catch (const Error &e)
        {
            throw Error("glider '" + spec.name + "': " + e.what());
        }
    };
    const auto report = [&](std::size_t done) {
        if (!options.progress)
            return;
        char line[96];
        std::snprintf(line, sizeof line, "fleet: %zu/%zu gliders planned", done, n);
        options.progress(line, done == n);
    };
    std::vector<FleetGlider> out(n);
    if (TaskSpreader *spread = activeTaskSpreader())
    {
        const std::vector<std::string> bytes = spread->run(
            "fleet glider", n, [&](std::size_t i) { return pack(plan(i)); },
            [&](std::size_t done, std::size_t) { report(done); });
        for (std::size_t i = 0; i < n; ++i)
            out[i] = unpack(bytes[i]);
        return out;
    }
    std::mutex m;
    std::size_t done = 0;
    ThreadPool pool(0);
    pool.parallelFor(n, [&](std::size_t i) {
        out[i] = plan(i);
        const std::lock_guard<std::mutex> lock(m);
        report(++done);
    });
    return out;
}
} // namespace ompl_glider

/// @file OverridableFields.cpp
/// @brief overridableFields() (Overrides.h): the fields a flag or a keyword can change, as texts, and which were given.

#include <charconv>
#include <cmath>

#include "ompl_glider/mission/Overrides.h"
#include "ompl_glider/mission/OutputFormats.h"

namespace ompl_glider
{
std::vector<std::pair<std::string, std::string>> overridableFields(const MissionSpec &m)
{
    // the shortest text that reads back as the same double: equal texts are equal values, and 0.6 stays "0.6"
    const auto num = [](double v) {
        char buf[32];
        const auto r = std::to_chars(buf, buf + sizeof buf, v);
        return std::string(buf, r.ptr);
    };
    const auto point = [&](const PointSpec &p) {
        return p.geographic ? num(p.lonLat.lon) + "," + num(p.lonLat.lat) : num(p.xy.x) + "," + num(p.xy.y);
    };
    std::string parameters, files;
    for (const auto &[name, value] : m.planner.parameters)
        parameters += (parameters.empty() ? "" : ",") + name + "=" + value;
    for (const OutputFormatId id : m.outputs.files)
        for (const OutputFormat &f : outputFormats())
            if (f.id == id)
                files += (files.empty() ? "" : ",") + f.name;
    std::string via;
    for (const ViaPointSpec &v : m.waypoints)
        via += (via.empty() ? "" : ";") + v.name + "@" + point(v.position) +
               (std::isnan(v.radius) ? "" : ",radius=" + num(v.radius)) + (v.stay > 0.0 ? ",stay=" + num(v.stay) : "") +
               (v.arrive.set ? ",arrive=" + num(v.arrive.begin) + ".." + num(v.arrive.end) : "");
    std::string region = "unset";
    if (m.region.set)
        region = m.region.geographic ? num(m.region.lonLat.lonMin) + "," + num(m.region.lonLat.latMin) + "," +
                                           num(m.region.lonLat.lonMax) + "," + num(m.region.lonLat.latMax)
                                     : num(m.region.xy.xMin) + "," + num(m.region.xy.yMin) + "," +
                                           num(m.region.xy.xMax) + "," + num(m.region.xy.yMax);
    std::vector<std::pair<std::string, std::string>> fields = {
        {"planner.name", m.planner.name},
        {"planner.parameters", parameters},
        {"planner.grid_size", num(m.planner.gridSize)},
        {"planner.sectors", std::to_string(m.planner.sectors)},
        {"planner.time_limit", num(m.planner.timeLimit)},
        {"planner.horizon", num(m.planner.horizon)},
        {"planner.goal_tolerance", num(m.planner.goalTolerance)},
        {"planner.smoothing", m.planner.smoothing ? "true" : "false"},
        {"planner.refinement", m.planner.refinement ? "true" : "false"},
        {"planner.global_check", m.planner.globalCheck ? "true" : "false"},
        {"vehicle.speed", num(m.vehicle.speed)},
        {"departure.time", num(m.departure.time)},
        {"departure.window", m.departure.window ? "true" : "false"},
        {"start", point(m.start)},
        {"goal", point(m.goal)},
        {"region", region},
        {"goal.window", m.goalWindow.set ? num(m.goalWindow.begin) + "," + num(m.goalWindow.end) : "unset"},
        {"waypoints", via},
        {"order", visitOrderName(m.order)},
        {"observations", m.observations && m.observations->hasFiles() ? m.observations->path : std::string("unset")},
        {"forbidden.coastline", m.forbidden.coastline},
        {"outputs.directory", m.outputs.directory},
        {"outputs.files", files},
        {"outputs.isochrone_interval", num(m.outputs.isochroneInterval)},
        {"reachability.horizon", num(m.reachability.horizon)},
        {"reachability.interval", num(m.reachability.interval)},
        {"reachability.resolution", num(m.reachability.resolution)},
        {"outputs.goto_turn_deg", num(m.outputs.gotoTurnDeg)},
        {"outputs.hold_tolerance", num(m.outputs.holdTolerance)}};
    // which of these the file, a flag or a keyword gave (a field, or a value inside it: start.x, outputs.files[0])
    std::string marked;
    for (const auto &[name, value] : fields)
    {
        const auto it = m.marks.lower_bound(name);
        const bool given = it != m.marks.end() && (it->first == name || it->first.rfind(name + ".", 0) == 0 ||
                                                   it->first.rfind(name + "[", 0) == 0);
        const bool parameters = name == "planner.parameters" && !m.planner.parameterMarks.empty();
        if (given || parameters)
            marked += (marked.empty() ? "" : ",") + name;
    }
    fields.emplace_back("given", marked);
    return fields;
}
} // namespace ompl_glider

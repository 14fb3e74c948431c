// The `outputs` section: the directory, the formats written and their settings.
#include <set>

#include "MissionReader.h"
#include "ompl_glider/mission/OutputFormats.h"

namespace ompl_glider::mission_loader
{
void readOutputs(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "outputs";
    r.checkMap(n, f,
               {"directory", "files", "goto_number", "goto_include_start", "goto_turn_deg", "goto_max_offset",
                "goto_wpt_dist", "hold_tolerance", "prefix", "map_time", "isochrone_interval"});
    OutputSpec &o = m.outputs;
    if (n["directory"])
        o.directory = joinPath(r.dir(), r.text(n["directory"], f + ".directory"));
    if (n["files"])
    {
        const YAML::Node &l = n["files"];
        if (!l.IsSequence())
            r.fail(l, f + ".files", "expected a list such as [csv, geojson, goto, summary, map]");
        o.files.clear();
        std::set<std::string> formats;
        for (const OutputFormat &format : outputFormats())
            formats.insert(format.name);
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            const std::string kind = r.oneOf(l[i], f + ".files[" + std::to_string(i) + "]", formats);
            const OutputFormatId id = *outputFormatByName(kind);
            if (id == OutputFormatId::Goto && !m.projection.set && !m.current.isForecast())
                r.fail(l[i], f + ".files[" + std::to_string(i) + "]",
                       "a goto list needs longitudes and latitudes: give a 'projection' in the mission");
            o.files.push_back(id);
        }
    }
    if (n["goto_number"])
        o.gotoNumber = static_cast<int>(r.integer(n["goto_number"], f + ".goto_number", 0, 99));
    if (n["goto_include_start"])
        o.gotoIncludeStart = r.boolean(n["goto_include_start"], f + ".goto_include_start");
    if (n["goto_turn_deg"])
        o.gotoTurnDeg = r.setting(n["goto_turn_deg"], f + ".goto_turn_deg", m);
    if (n["goto_max_offset"] && !((o.gotoMaxOffset = r.number(n["goto_max_offset"], f + ".goto_max_offset")) >= 0.0))
        r.fail(n["goto_max_offset"], f + ".goto_max_offset", "expected a distance in metres >= 0");
    if (n["goto_wpt_dist"] && !((o.gotoWptDist = r.number(n["goto_wpt_dist"], f + ".goto_wpt_dist")) > 0.0))
        r.fail(n["goto_wpt_dist"], f + ".goto_wpt_dist", "expected a distance in metres > 0");
    if (n["hold_tolerance"])
        o.holdTolerance = r.setting(n["hold_tolerance"], f + ".hold_tolerance", m);
    if (n["prefix"])
    {
        o.prefix = r.text(n["prefix"], f + ".prefix");
        if (o.prefix.empty() || o.prefix.find_first_of("/\\") != std::string::npos || o.prefix == "." ||
            o.prefix == ".." || o.prefix.find_first_of(std::string("\0:*?\"<>|", 8)) != std::string::npos)
            r.fail(n["prefix"], f + ".prefix",
                   "expected a plain file-name part (letters, digits, '_', '-', '.'; no '/' or '..'), got '" +
                       o.prefix + "'");
    }
    if (n["map_time"])
        o.mapTime = r.time(n["map_time"], f + ".map_time", m);
    if (n["isochrone_interval"])
        o.isochroneInterval = r.setting(n["isochrone_interval"], f + ".isochrone_interval", m);
}
} // namespace ompl_glider::mission_loader

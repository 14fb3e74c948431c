// The outputs of a fleet (FleetFiles.h): each glider's files rendered where it was planned, then written with
// fleet.csv and the fleet's summary.json in one transaction.
#include "ompl_glider/Config.h"
#include "ompl_glider/output/MapHtml.h"
#include "ompl_glider/output/FleetFiles.h"

#include <cerrno>
#include <cmath>
#include <csignal>
#include <mutex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "../io/NumberText.h"
#include "JsonValues.h"
#include "OutputDirectory.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/io/TempFolder.h"
#include "ompl_glider/output/SummaryJson.h"

namespace ompl_glider
{
namespace fs = std::filesystem;

namespace
{
using json = nlohmann::ordered_json;
using output_json::jnum;
using output_json::jtext;

std::string csvText(const std::string &s)
{
    if (s.find_first_of(",\"\n") == std::string::npos)
        return s;
    std::string q = "\"";
    for (const char c : s)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

/// A glider's rendered files: (name, bytes) pairs.
std::vector<std::pair<std::string, std::string>> keptFiles(const std::string &kept)
{
    std::vector<std::string> names, bytes;
    ByteReader in(kept);
    in.get(names);
    in.get(bytes);
    std::vector<std::pair<std::string, std::string>> out;
    for (std::size_t i = 0; i < names.size() && i < bytes.size(); ++i)
        out.emplace_back(names[i], bytes[i]);
    return out;
}

/// The rendering directories ("ompl_glider-fleet-PID-XXXXXX" in the temporary directory) that a process no longer
/// running left (a signal or a kill while it rendered a glider's files), once per process.
void removeStaleRenderDirectories()
{
    static std::once_flag once;
    std::call_once(once, [] {
        std::error_code ec;
        const std::string head = "ompl_glider-fleet-";
        fs::path tmp;
        try
        {
            tmp = temporaryFolder();
        }
        catch (const Error &)
        {
            return; // said by renderOutputFiles()
        }
        for (const fs::directory_entry &e : fs::directory_iterator(tmp, ec))
        {
            const std::string name = e.path().filename().string();
            if (name.compare(0, head.size(), head) != 0)
                continue;
            const long pid = std::strtol(name.c_str() + head.size(), nullptr, 10);
            if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
                fs::remove_all(e.path(), ec);
        }
    });
}

std::string fleetSummaryJson(const MissionSpec &m, const std::vector<FleetGlider> &gliders,
                             const std::vector<std::string> &files, double wallSeconds)
{
    json fleet = json::array();
    std::size_t solved = 0;
    for (const FleetGlider &g : gliders)
    {
        const FleetRow &r = g.row;
        solved += r.solved ? 1 : 0;
        fleet.push_back({{"name", r.name},
                         {"directory", r.name},
                         {"solved", r.solved},
                         {"status", statusText(r.status)},
                         {"reason", jtext(r.reason)},
                         {"travel_time", jnum(r.travelTime)},
                         {"path_length", jnum(r.pathLength)},
                         {"departure", jnum(r.departure)},
                         {"departure_iso", jtext(r.departureIso)},
                         {"arrival_time", jnum(r.arrival)},
                         {"arrival_iso", jtext(r.arrivalIso)}});
    }
    json j;
    j["schema"] = kSummarySchema;
    j["mission"] = m.name;
    j["mission_file"] = m.file;
    j["gliders"] = gliders.size();
    j["gliders_with_route"] = solved;
    j["fleet"] = fleet;
    j["wall_time_s"] = jnum(wallSeconds);
    j["processes"] = taskProcesses();
    j["files"] = files;
    return output_json::utf8Dump(j, 2) + "\n";
}
} // namespace

std::string renderOutputFiles(const MissionResult &result, const MissionProblem &problem)
{
    removeStaleRenderDirectories();
    const fs::path tmp = temporaryFolder();
    std::string pattern = (tmp / ("ompl_glider-fleet-" + std::to_string(::getpid()) + "-XXXXXX")).string();
    if (!::mkdtemp(&pattern[0]))
        throw Error("cannot create a temporary directory in '" + tmp.string() + "' for a glider's files (" +
                    std::strerror(errno) + "): set TMPDIR to a writable folder");
    const fs::path dir(pattern);
    std::vector<std::string> names, bytes;
    try
    {
        for (const OutputFile &f : outputFiles(result, problem))
        {
            const fs::path p = dir / f.name;
            f.write(p.string());
            std::ifstream in(p, std::ios::binary);
            std::ostringstream s;
            s << in.rdbuf();
            if (!in)
                throw Error("cannot read back '" + p.string() + "'");
            names.push_back(f.name);
            bytes.push_back(s.str());
            fs::remove(p);
        }
    }
    catch (...)
    {
        std::error_code ec;
        fs::remove_all(dir, ec);
        throw;
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
    ByteWriter w;
    w.put(names);
    w.put(bytes);
    return w.take();
}

std::string fleetCsv(const std::vector<FleetGlider> &gliders)
{
    std::string out = "name,status,travel_time,path_length,departure,arrival_time,departure_iso,arrival_iso,reason\n";
    for (const FleetGlider &g : gliders)
    {
        const FleetRow &r = g.row;
        out += csvText(r.name) + "," + csvText(statusText(r.status)) + "," + text::csvNumber(r.travelTime) + "," +
               text::csvNumber(r.pathLength) + "," + text::csvNumber(r.departure) + "," + text::csvNumber(r.arrival) +
               "," + r.departureIso + "," + r.arrivalIso + "," + csvText(r.reason) + "\n";
    }
    return out;
}

std::vector<OutputFile> fleetOutputFiles(const MissionSpec &mission, const std::vector<FleetGlider> &gliders,
                                         double wallSeconds)
{
    std::vector<OutputFile> files;
    for (const FleetGlider &g : gliders)
        for (auto &[name, bytes] : keptFiles(g.kept))
            files.push_back({g.row.name + "/" + name,
                             [bytes = bytes](const std::string &p) { output_detail::writeFileChecked(p, bytes); }});
    const std::string csv = fleetCsv(gliders);
    files.push_back({"fleet.csv", [csv](const std::string &p) { output_detail::writeFileChecked(p, csv); }});
#if OMPL_GLIDER_WITH_MAP
    // every glider's route on one interactive map (the first glider's frame, land and currents)
    std::vector<std::string> maps;
    for (const FleetGlider &g : gliders)
        for (auto &[name, bytes] : keptFiles(g.kept))
            if (name == "map.html")
                if (std::string data = mapHtmlDataOf(bytes); !data.empty())
                    maps.push_back(std::move(data));
    if (!maps.empty())
    {
        const std::string page = mapHtmlPage(maps, mission.name + " (fleet of " + std::to_string(gliders.size()) + ")");
        files.push_back({"map.html", [page](const std::string &p) { output_detail::writeFileChecked(p, page); }});
    }
#endif
    std::vector<std::string> names = {"summary.json"};
    for (const OutputFile &f : files)
        names.push_back(f.name);
    const std::string summary = fleetSummaryJson(mission, gliders, names, wallSeconds);
    files.insert(files.begin(), OutputFile{"summary.json", [summary](const std::string &p) {
                                               output_detail::writeFileChecked(p, summary);
                                           }});
    return files;
}

void printFleetTable(std::ostream &out, const MissionSpec &mission, const std::vector<FleetGlider> &gliders)
{
    const MissionSpec::PhysicalUnits units = mission.physicalUnits();
    std::size_t width = 6;
    for (const FleetGlider &g : gliders)
        width = std::max(width, g.row.name.size());
    char line[512];
    std::snprintf(line, sizeof line, "%-*s  %-8s  %14s  %14s  %s\n", static_cast<int>(width), "glider", "status",
                  units.time ? "travel time h" : "travel time", units.length ? "path km" : "path length", "arrival");
    out << "Fleet: " << mission.name << ", " << gliders.size() << " gliders\n" << line;
    for (const FleetGlider &g : gliders)
    {
        const FleetRow &r = g.row;
        const double hours = r.travelTime * mission.timeUnitSeconds / 3600.0;
        const double km = r.pathLength * mission.metresPerUnit() / 1000.0;
        const std::string arrival = !r.solved ? "-" : !r.arrivalIso.empty() ? r.arrivalIso : text::number(r.arrival, 6);
        std::snprintf(line, sizeof line, "%-*s  %-8s  %14s  %14s  %s%s\n", static_cast<int>(width), r.name.c_str(),
                      r.solved ? "route" : "no path",
                      r.solved ? text::number(units.time ? hours : r.travelTime, 6).c_str() : "-",
                      r.solved ? text::number(units.length ? km : r.pathLength, 6).c_str() : "-", arrival.c_str(),
                      r.solved ? "" : ("  (" + r.reason + ")").c_str());
        out << line;
    }
}
} // namespace ompl_glider

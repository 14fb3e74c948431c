// loadMission(): YAML mission files, validated field by field ([EichhornOceans] Sec. IV mission contents). The
// sections are read in loader/ (MissionReader.h).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../../io/NumberText.h"
#include "MissionReader.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/Config.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif
#include "ompl_glider/registry/PlannerRegistry.h"

namespace ompl_glider
{
namespace
{
using namespace mission_loader;

/// name, units, epoch and projection.
void readHeader(const Reader &r, const YAML::Node &root, MissionSpec &m)
{
    if (root["name"])
        m.name = r.text(root["name"], "name");
    if (root["units"])
    {
        r.checkMap(root["units"], "units", {"length_m", "time_s"});
        if (root["units"]["length_m"])
            m.lengthUnitMetres = r.positive(root["units"]["length_m"], "units.length_m");
        if (root["units"]["time_s"])
            m.timeUnitSeconds = r.positive(root["units"]["time_s"], "units.time_s");
    }
    if (root["epoch"])
    {
        try
        {
            m.epoch = parseIsoTime(r.text(root["epoch"], "epoch"));
        }
        catch (const Error &e)
        {
            r.fail(root["epoch"], "epoch", e.what());
        }
    }
    if (root["projection"])
    {
        const YAML::Node &p = root["projection"];
        r.checkMap(p, "projection", {"lon0", "lat0"});
        if (!p["lon0"] || !p["lat0"])
            r.fail(p, "projection", "lon0 and lat0 (the reference point) are required");
        m.projection.set = true;
        m.projection.lon0 = r.finite(p["lon0"], "projection.lon0");
        m.projection.lat0 = r.finite(p["lat0"], "projection.lat0");
        if (std::abs(m.projection.lat0) >= 90)
            r.fail(p["lat0"], "projection.lat0", "must be within (-90, 90)");
    }
}

/// vehicle and travel_time (the travel-time integrator's tolerances).
void readVehicleAndTravel(const Reader &r, const YAML::Node &root, MissionSpec &m)
{
    if (root["vehicle"])
    {
        const YAML::Node &v = root["vehicle"];
        r.checkMap(v, "vehicle", {"speed", "depth"});
        if (v["speed"])
            m.vehicle.speed = r.setting(v["speed"], "vehicle.speed", m);
        if (v["depth"])
            m.vehicle.depth = r.nonNegative(v["depth"], "vehicle.depth");
    }
    if (root["travel_time"])
    {
        const YAML::Node &t = root["travel_time"];
        r.checkMap(t, "travel_time", {"h", "h_min", "h_max", "eps", "tau"});
        if (t["h"])
            m.travel.h = r.positive(t["h"], "travel_time.h");
        if (t["h_min"])
            m.travel.hMin = r.positive(t["h_min"], "travel_time.h_min");
        if (t["h_max"])
            m.travel.hMax = r.positive(t["h_max"], "travel_time.h_max");
        if (t["eps"])
            m.travel.eps = r.positive(t["eps"], "travel_time.eps");
        if (t["tau"])
            m.travel.tau = r.positive(t["tau"], "travel_time.tau");
    }
    // eps is absolute in the field's time unit: 1 s for forecasts in seconds, unless given.
    if (m.current.isForecast() && !(root["travel_time"] && root["travel_time"]["eps"]))
        m.travel.eps = 1.0;
    try
    {
        TravelTimeParams check = m.travel;
        if (!(check.hMin > 0.0) || !(check.hMax >= check.hMin) || !(check.h >= check.hMin) || check.hMax > 1.0 ||
            !(check.tau > 0.0 && check.tau <= 1.0))
            throw Error("need 0 < h_min <= h, h_min <= h_max <= 1 and 0 < tau <= 1");
    }
    catch (const Error &e)
    {
        r.fail(root["travel_time"] ? root["travel_time"] : root, "travel_time", e.what());
    }
}

/// The speed sweep, then the cross-field checks that can be made without building the field.
void readSpeedsAndCheck(const Reader &r, const YAML::Node &root, MissionSpec &m)
{
    if (root["speeds"])
    {
        const YAML::Node &s = root["speeds"];
        if (!s.IsSequence() || s.size() == 0)
            r.fail(s, "speeds", "expected a list of vehicle speeds, e.g. [0.25, 0.30, 0.35]");
        for (std::size_t i = 0; i < s.size(); ++i)
            m.speeds.push_back(r.positive(s[i], "speeds[" + std::to_string(i) + "]"));
    }
    if (m.region.set && !m.region.geographic)
    {
        for (const auto *p : {&m.start, &m.goal})
            if (!p->geographic && (p->xy.x < m.region.xy.xMin || p->xy.x > m.region.xy.xMax ||
                                   p->xy.y < m.region.xy.yMin || p->xy.y > m.region.xy.yMax))
            {
                const char *key = p == &m.start ? "start" : "goal";
                r.fail(root[key], key, "lies outside the region");
            }
    }
}

MissionSpec readMission(const YAML::Node &root, const Reader &r)
{
    MissionSpec m;
    m.file = r.file();
    m.directory = r.dir();
    if (!root.IsDefined() || root.IsNull())
        throw Error(r.file() + ": the mission file is empty");
    r.checkMap(root, "", {"name",      "units",  "epoch",     "projection", "current",      "region",
                          "start",     "goal",   "departure", "vehicle",    "travel_time",  "dive_profile",
                          "forbidden", "safety", "planner",   "stints",     "outputs",      "speeds",
                          "execution", "fleet",  "waypoints", "order",      "observations", "reachability"});
    readHeader(r, root, m);
    if (!root["current"])
        r.fail(root, "current", "missing: the current source (type: meandering_jet | uniform | ... | netcdf)");
    readCurrent(r, root["current"], m, root["departure"]);
    if (m.current.isForecast() && root["units"])
        r.fail(root["units"], "units", "a gridded forecast is planned in metres and seconds: remove 'units'");
    // A dated forecast defines the time origin; a steady file without dates takes the mission's epoch as the date
    // of field time 0 (ISO times in the mission and the outputs).
    if (m.current.isForecast() && root["epoch"] && (m.fileCalendar || !m.current.steady))
        r.fail(root["epoch"], "epoch",
               m.fileCalendar ? "the forecast defines the time origin (its first time): remove 'epoch'"
                              : "the forecast has undated times (field time is the file's): remove 'epoch' "
                                "(only a steady file without dates takes one)");
    if (root["region"])
        readRegion(r, root["region"], m);
    else if (!m.current.isForecast())
        r.fail(root, "region", "missing: an analytic current needs the planning region");
    for (const char *key : {"start", "goal"})
    {
        if (!root[key] && root["fleet"])
            continue; // a fleet's gliders give theirs
        if (!root[key] && root["observations"] && std::string(key) == "start" &&
            !(root["observations"].IsMap() && !root["observations"]["file"]))
            continue; // the glider's last fix
        if (!root[key])
            r.fail(root, key, "missing");
        readPoint(r, root[key], key, std::string(key) == "start" ? m.start : m.goal, m);
    }
    if (root["departure"])
        readDeparture(r, root["departure"], m);
    if (root["observations"])
    {
        readObservations(r, root["observations"], m);
        if (!root["start"] && !root["fleet"] && m.observations->hasFiles())
        {
#if OMPL_GLIDER_WITH_NETCDF
            try
            {
                startAtLastFix(m, SourceMark{r.file(), r.line(root["observations"])},
                               static_cast<bool>(root["departure"]));
            }
            catch (const Error &e)
            {
                r.fail(root["observations"], "observations", e.what());
            }
#else
            r.fail(root["observations"], "observations", "this build reads no glider files (no NetCDF)");
#endif
        }
    }
    if (root["fleet"])
    {
        readFleet(r, root["fleet"], m);
        if (!root["start"])
            m.start = m.fleet.front().start;
        if (!root["goal"])
            m.goal = m.fleet.front().goal;
    }
    if (root["goal"] && root["goal"]["window"])
        readGoalWindow(r, root["goal"]["window"], m);
    if (root["waypoints"])
        readViaPoints(r, root["waypoints"], "waypoints", m.waypoints, m);
    if (root["order"])
        m.order = readVisitOrder(r, root["order"], "order", m.waypoints.size());
    readVehicleAndTravel(r, root, m);
    if (root["dive_profile"])
        readDive(r, root["dive_profile"], m);
    if (root["forbidden"])
        readForbidden(r, root["forbidden"], m);
    if (root["safety"])
        readSafety(r, root["safety"], m);
    if (root["planner"])
        readPlanner(r, root["planner"], m);
    if (root["stints"])
        readStints(r, root["stints"], m);
    const PlannerEntry *planner = findPlanner(m.planner.name);
    const bool stintPlanner = planner && planner->stints();
    if (stintPlanner && !m.stints.set)
        r.fail(root["planner"]["name"], "planner.name",
               "planner '" + m.planner.name +
                   "' flies constant-bearing stints: give a 'stints' section (duration, mission_duration)");
    if (stintPlanner && m.departure.window && m.stints.objective == StintObjective::RemainingDistance)
        r.fail(root["departure"]["window"], "departure.window",
               "the departure window is searched for the earliest arrival; the stint planner '" + m.planner.name +
                   "' with the remaining_distance objective has none: give departure.time, or stints.objective: "
                   "earliest_arrival with a radius");
    if (stintPlanner && m.goalWindow.set)
        r.fail(root["goal"]["window"], "goal.window",
               "the stint planner '" + m.planner.name +
                   "' flies fixed stints and cannot time its arrival: remove the window or use another planner");
    if (root["outputs"])
        readOutputs(r, root["outputs"], m);
    else
        m.outputs.directory = joinPath(r.dir(), ".");
    if ((!root["outputs"] || !root["outputs"]["files"]) && !m.projection.set && !m.current.isForecast())
        m.outputs.files = {OutputFormatId::Csv, OutputFormatId::GeoJson,
                           OutputFormatId::Summary}; // no lon/lat: no goto list by default
    readSpeedsAndCheck(r, root, m);
    if (root["reachability"])
        readReachability(r, root["reachability"], m);
    if (root["execution"])
        readExecution(r, root["execution"], m);
    m.marks = r.marks();
    return m;
}
} // namespace

double MissionSpec::timeOf(const std::string &text) const
{
    {
        // a number in field units (the whole text)
        std::size_t used = 0;
        double v = 0.0;
        bool number = false;
        try
        {
            v = std::stod(text, &used);
            number = used == text.size() && used > 0;
        }
        catch (const std::exception &)
        {
        }
        if (number)
        {
            if (!std::isfinite(v))
                throw Error("expected a finite time, got '" + text + "'");
            return v;
        }
    }
    if (fileCalendar)
        return secondsSinceCalendarEpoch(text, fileCalendar->calendar) - fileCalendar->originSeconds;
    if (!epoch)
        throw Error("expected a number (an ISO 8601 date needs 'epoch' at the top of the mission), got '" + text + "'");
    return (parseIsoTime(text) - *epoch) / timeUnitSeconds;
}

std::string SettingWords::operator()(const std::string &setting) const
{
    const auto it = words.find(setting);
    return it == words.end() ? setting : setting + ", " + it->second;
}

std::string SettingWords::givenName(const std::string &setting) const
{
    if (const auto it = given.find(setting); it != given.end())
        return it->second;
    const auto it = words.find(setting);
    return it == words.end() ? setting : it->second;
}

std::string MissionSpec::term(const std::string &setting) const
{
    return words ? (*words)(setting) : setting;
}

std::string MissionSpec::place(const std::string &field) const
{
    auto it = marks.find(field);
    if (it == marks.end()) // a point or a block: the first value given inside it ("start" -> "start.x")
    {
        it = marks.lower_bound(field + ".");
        if (it != marks.end() && it->first.rfind(field + ".", 0) != 0)
            it = marks.end();
    }
    // a list a flag or a keyword gave whole ("waypoints" by --via): an item of it is placed by the list's mark
    const std::size_t item = field.find('[');
    if (it == marks.end() && item != std::string::npos)
    {
        const auto whole = marks.find(field.substr(0, item));
        if (whole != marks.end() && whole->second.line == 0)
            it = whole;
    }
    // a command-line flag or a keyword of the Python module names itself, as its front end gave it
    if (it != marks.end() && it->second.namesItself())
        return it->second.file + (item != std::string::npos ? " (" + field + ")" : "");
    if (it != marks.end() && it->second.line > 0)
        return it->second.file + ":" + std::to_string(it->second.line) + ": field '" + field + "'";
    return file + ": field '" + field + "'";
}

namespace
{
/// Offset of the first byte of @p s that does not begin or continue a well-formed UTF-8 sequence (overlong forms,
/// surrogates and values beyond U+10FFFF included); s.size() when it is all UTF-8.
std::size_t firstBadUtf8(const std::string &s)
{
    std::size_t k = 0;
    while (k < s.size())
    {
        const auto c = static_cast<unsigned char>(s[k]);
        const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
        if (n == 0 || k + n > s.size() || c == 0xC0 || c == 0xC1 || c > 0xF4)
            return k;
        unsigned code = n == 1 ? c : c & (0xFFu >> (n + 1));
        for (std::size_t i = 1; i < n; ++i)
        {
            const auto d = static_cast<unsigned char>(s[k + i]);
            if ((d >> 6) != 0x2)
                return k;
            code = (code << 6) | (d & 0x3Fu);
        }
        if ((n == 3 && (code < 0x800 || (code >= 0xD800 && code <= 0xDFFF))) ||
            (n == 4 && (code < 0x10000 || code > 0x10FFFF)))
            return k;
        k += n;
    }
    return k;
}
} // namespace

MissionSpec parseMission(const std::string &yamlText, const std::string &file, const std::string &directory)
{
    // every name and text ends up in outputs (JSON, SVG, CSV): the file must be UTF-8
    if (const std::size_t bad = firstBadUtf8(yamlText); bad < yamlText.size())
    {
        const std::size_t lineStart = yamlText.rfind('\n', bad == 0 ? 0 : bad - 1);
        const std::size_t col = bad - (lineStart == std::string::npos || bad == 0 ? 0 : lineStart + 1) + 1;
        char byte[8];
        std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(yamlText[bad]));
        throw Error(file + ":" +
                    std::to_string(
                        std::count(yamlText.begin(), yamlText.begin() + static_cast<std::ptrdiff_t>(bad), '\n') + 1) +
                    ": the text is not UTF-8 (byte " + byte + " at column " + std::to_string(col) +
                    "); save the mission file as UTF-8");
    }
    // A second document is found by its "---" line after content (yaml-cpp 0.7's LoadAll() can loop without end on
    // malformed text; Load() reads the first document only)
    int line = 0;
    bool content = false;
    std::istringstream lines(yamlText);
    std::string text;
    for (int n = 1; line == 0 && std::getline(lines, text); ++n)
    {
        const bool marker =
            text.rfind("---", 0) == 0 && (text.size() == 3 || std::isspace(static_cast<unsigned char>(text[3])));
        if (marker && content)
            line = n;
        content = content || marker ||
                  (!text.empty() && text[0] != '#' && text.find_first_not_of(" \t\r") != std::string::npos);
    }
    YAML::Node document;
    try
    {
        document = YAML::Load(yamlText);
    }
    catch (const YAML::ParserException &e)
    {
        throw Error(yamlErrorMessage(file, e, "YAML syntax error"));
    }
    if (line > 0)
        throw Error(file + ":" + std::to_string(line) +
                    ": a second YAML document: a mission file holds one document (remove the '---' line and what "
                    "follows it, or split the file)");
    return readMission(document, Reader(file, directory));
}

MissionSpec loadMission(const std::string &path)
{
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw Error("cannot read mission file '" + path + "': it is a directory, not a YAML mission file");
    // a device, a pipe or a huge file is no mission: /dev/zero or a FIFO would be read without end
    const auto status = std::filesystem::status(path, ec);
    if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw Error("cannot read mission file '" + path +
                    "': it is not a regular file (a device, a pipe or a "
                    "socket); give a YAML mission file");
    constexpr std::uintmax_t kMaxMissionBytes = 16u << 20;
    if (const std::uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxMissionBytes)
        throw Error("cannot read mission file '" + path + "': it holds " + std::to_string(size) +
                    " bytes, more than the " + std::to_string(kMaxMissionBytes >> 20) +
                    " MiB a mission file may have (is it the right file?)");
    std::ifstream in(path);
    if (!in)
        throw Error("cannot read mission file '" + path + "'");
    std::ostringstream s;
    s << in.rdbuf();
    const auto slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash);
    return parseMission(s.str(), path, dir);
}

MissionSpec defaultGulfStreamMission()
{
    MissionSpec m;
    m.file = "<built-in>";
    m.name = "gulf_stream";
    m.current.type = "meandering_jet";
    m.region.set = true;
    m.region.xy = {0, 10, -4, 4};
    // South of the jet to north of it.
    m.start.xy = {1.0, -3.0};
    m.goal.xy = {8.0, 3.0};
    m.vehicle.speed = 0.5;
    m.planner.horizon = 60.0;
    m.planner.goalTolerance = 1e-3;
    m.outputs.files = {OutputFormatId::Summary, OutputFormatId::Path, OutputFormatId::Csv, OutputFormatId::GeoJson,
                       OutputFormatId::Map};
    return m;
}

double defaultForecastGridSize(double minCellSize, double distance)
{
    double g = 0.5 * minCellSize;
    if (distance > 0.0)
        g = std::clamp(g, distance / 200.0, distance / 25.0);
    if (!(g > 0.0) || !std::isfinite(g))
        throw Error("cannot choose a grid size (cell size " + text::number(minCellSize) + ", start-goal distance " +
                    text::number(distance) + "): give planner.grid_size");
    const double scale = std::pow(10.0, std::floor(std::log10(g)) - 1.0); // two significant digits
    return std::round(g / scale) * scale;
}

double defaultAnalyticGridSize(const MissionSpec &m, double distance)
{
    const MissionSpec b = defaultGulfStreamMission();
    const bool builtInTrip = m.current.type == b.current.type && !m.start.geographic && !m.goal.geographic &&
                             m.start.xy.x == b.start.xy.x && m.start.xy.y == b.start.xy.y &&
                             m.goal.xy.x == b.goal.xy.x && m.goal.xy.y == b.goal.xy.y;
    return builtInTrip ? 0.4 : defaultForecastGridSize(2.0 * 0.4, distance); // half of 0.8: the forecasts' rule
}
} // namespace ompl_glider

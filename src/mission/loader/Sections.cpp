// Readers of the mission's sections: current (with the forecast's calendar), region, departure, dive profile,
// planner and outputs ([EichhornOceans] Sec. IV mission contents).
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <set>

#include "MissionReader.h"
#include "ompl_glider/ompl/Sectors.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/execution/Execution.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/OutputFormats.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/io/FileList.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/io/UnitConversion.h"
#endif

namespace ompl_glider::mission_loader
{
namespace
{
constexpr double kMaxSupportingPoints = 10000.0;  ///< departure-window samples, each a whole search
/// Time origin of a gridded forecast (its first time, as its source loads it): ISO dates of the mission are field
/// times in the file's calendar, and the outputs get calendar dates. The time axis is found by the source's own
/// detection (GriddedSource::timeAxis(): variables.time, else the source's rules).
void readFileCalendar(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const CurrentFieldKind &kind = *findCurrentFieldKind(m.current.type);
    ForecastRequest o;
    o.files = m.current.forecastFiles();
    for (const char *role : {"time", "u"})
        if (m.current.variables.count(role))
            o.variables[role] = m.current.variables.at(role);
    o.timeUnits = m.current.timeUnits;
    o.steadyRecord = m.current.steadyRecord;
    o.optionNames = forecastFieldNames("current");
    const std::string timeName = o.variable("time"), uName = o.variable("u");
    ForecastTimeAxis axis;
    try
    {
        axis = kind.source->timeAxis(o);
    }
    catch (const Error &e)
    {
        // on the setting the source names as at fault (Error::field()) when the mission gave it, else on the file
        const std::string what = e.what(), &field = e.field();
        if (n["time_units"] && field == "current.time_units")
            r.fail(n["time_units"], field, what);
        if (n["steady_record"] && field == "current.steady_record")
            r.fail(n["steady_record"], field, what);
        if (!timeName.empty() && field == "current.variables.time")
            r.fail(n["variables"]["time"], field, what);
        if (!uName.empty() && field == "current.variables.u")
            r.fail(n["variables"]["u"], field, what);
        r.fail(n["file"], "current.file", what);
    }
    m.current.steady = axis.steady;
    if (!axis.found || !axis.dated)
        return;  // a steady field without dates, or raw times of a Cartesian file: no calendar
    MissionSpec::FileCalendar fc;
    fc.calendar = axis.calendar;
    fc.originSeconds = axis.originSeconds;
    m.fileCalendar = fc;
    m.epoch = fc.originSeconds - secondsSinceCalendarEpoch(DateTime{}, axis.calendar);
}

/// current.velocity_units (checked with UDUNITS-2 now: it does not depend on the file), current.time_units
/// (checked against the file's calendar by readFileCalendar) and current.steady_record.
void readUnitsAndRecord(const Reader &r, const YAML::Node &n, const std::string &f, CurrentSpec &c)
{
    if (n["velocity_units"])
    {
        c.velocityUnits = r.text(n["velocity_units"], f + ".velocity_units");
#if OMPL_GLIDER_WITH_NETCDF
        try
        {
            (void)velocityToMetresPerSecond(c.velocityUnits);
        }
        catch (const Error &e)
        {
            r.fail(n["velocity_units"], f + ".velocity_units", e.what());
        }
#endif
    }
    if (n["time_units"])
    {
        c.timeUnits = r.text(n["time_units"], f + ".time_units");
        std::string lower = c.timeUnits;
        for (char &ch : lower)
            ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        if (lower.find(" since ") == std::string::npos)
            r.fail(n["time_units"], f + ".time_units",
                   "expected '<seconds|minutes|hours|days> since <date>', got '" + c.timeUnits + "'");
    }
    if (n["steady_record"])
        c.steadyRecord =
            static_cast<std::size_t>(r.integer(n["steady_record"], f + ".steady_record", 0, 1000000000L));
}

/// @brief The optional key `threads` of @p n (path @p f + ".threads" in messages): an integer 0 .. 1024 into
/// @p threads when given (0: all cores); @p threads keeps its value otherwise.
void readThreads(const Reader &r, const YAML::Node &n, const std::string &f, unsigned &threads)
{
    if (n["threads"])
        threads = static_cast<unsigned>(r.integer(n["threads"], f + ".threads", 0, 1024));
}
}  // namespace

namespace
{
/// current.file: a path or a glob pattern, or a list of them (a forecast in several files), relative to the
/// mission file; every file must exist. An OPeNDAP URL (io/RemoteSource.h) is taken as it is.
void readForecastFiles(const Reader &r, const YAML::Node &n, const std::string &f, CurrentSpec &c)
{
    const auto resolved = [&](const std::string &item) {
        return isRemoteSource(item) || item.rfind("ZARR:", 0) == 0 ? item : joinPath(r.dir(), item);
    };
    std::vector<std::string> items;
    if (n.IsSequence())
    {
        if (n.size() == 0)
            r.fail(n, f, "an empty list: expected forecast files or glob patterns");
        for (std::size_t k = 0; k < n.size(); ++k)
            items.push_back(resolved(r.text(n[k], f)));
    }
    else
        items.push_back(resolved(r.text(n, f)));
    std::vector<std::string> files = items;
    try
    {
        files = expandForecastFiles(items);
    }
    catch (const Error &e)
    {
        r.fail(n, f, e.what());
    }
    for (const std::string &file : files)
        if (!isRemoteSource(file) && !fileExists(file))
            r.fail(n, f, "cannot open '" + file + "'");
    c.file = files.front();
    if (files.size() > 1)
        c.files = files;
}
}  // namespace

void readCurrent(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    if (isDrawnEnsemble(n))
        return readDrawnEnsemble(r, n, m);  // members drawn from one source (DrawnEnsemble.cpp)
    if (n.IsMap() && n["ensemble"])
    {
        // members of one kind (analytic flows, or forecasts on one calendar); the first sets names and dates
        r.checkMap(n, "current", {"ensemble"});
        const YAML::Node &l = n["ensemble"];
        if (!l.IsSequence() || l.size() < 2)
            r.fail(l, "current.ensemble", "expected a list of 2 or more current sources (type: ..., as in 'current')");
        std::vector<CurrentSpec> members;
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            const std::string f = "current.ensemble[" + std::to_string(i) + "]";
            CurrentSpec c;
            readCurrentSource(r, l[i], f, c);
            c.mark = {r.file(), r.line(l[i])};
            if (i > 0 && (c.isForecast()) != (members.front().isForecast()))
                r.fail(l[i]["type"], f + ".type",
                       "every member must be of one kind: all forecasts read from files or all analytic flows (the "
                       "first is " +
                           members.front().type + ")");
            members.push_back(c);
        }
        m.current = members.front();
        m.current.mark = {r.file(), r.line(n)};
        m.current.members = members;
        if (m.current.isForecast())
            readFileCalendar(r, l[0], m);
        return;
    }
    readCurrentSource(r, n, "current", m.current);
    if (m.current.isForecast())
        readFileCalendar(r, n, m);
}

void readCurrentSource(const Reader &r, const YAML::Node &n, const std::string &f, CurrentSpec &c,
                       const std::set<std::string> &extraKeys)
{
    std::set<std::string> keys{"type", "parameters", "file", "variables", "interpolation", "horizon",
                               "velocity_units", "time_units", "steady_record", "zero_velocity_land", "depth_average"};
    keys.insert(extraKeys.begin(), extraKeys.end());
    r.checkMap(n, f, keys);
    c.mark = {r.file(), r.line(n)};
    const std::vector<std::string> names = currentFieldKindNames();  // with the aliases ("netcdf": gridded)
    const std::set<std::string> kinds(names.begin(), names.end());
    if (!n["type"])
        r.fail(n, f + ".type", "missing (" + currentFieldKindList() + ")");
    c.type = r.oneOf(n["type"], f + ".type", kinds);
    const CurrentFieldKind &kind = *findCurrentFieldKind(c.type);
    if (n["parameters"])
    {
        std::set<std::string> names;
        for (const auto &[key, value] : kind.parameters)  // (the set checkMap() takes; hasParameter() decides alike)
            names.insert(key);
        r.checkMap(n["parameters"], f + ".parameters", names);
        for (auto it = n["parameters"].begin(); it != n["parameters"].end(); ++it)
        {
            const std::string key = it->first.Scalar();
            c.parameters[key] = r.finite(it->second, f + ".parameters." + key);
        }
    }
    if (c.type == "double_gyre" && c.parameters.count("length") && !(c.parameters["length"] > 0))
        r.fail(n["parameters"]["length"], f + ".parameters.length", "expected a number > 0");
    if (c.type == "rankine_vortex" && c.parameters.count("radius") && !(c.parameters["radius"] > 0))
        r.fail(n["parameters"]["radius"], f + ".parameters.radius", "expected a number > 0 (the core radius)");
    const bool gridded = kind.gridded();
    for (const char *key : {"file", "variables", "interpolation", "horizon", "velocity_units", "time_units",
                            "steady_record", "zero_velocity_land", "depth_average"})
        if (n[key] && !gridded)
            r.fail(n[key], f + "." + key, "only for type " + griddedKindList(" or ") + " (a forecast read from files)");
    if (!gridded)
        return;
    if (!n["file"])
        r.fail(n, f + ".file", "missing: the forecast's file (type " + c.type + ")");
    readForecastFiles(r, n["file"], f + ".file", c);
    if (n["variables"])
    {
        r.checkMap(n["variables"], f + ".variables", {"u", "v", "x", "y", "lon", "lat", "depth", "time", "mask", "angle"});
        for (auto it = n["variables"].begin(); it != n["variables"].end(); ++it)
            c.variables[it->first.Scalar()] = r.text(it->second, f + ".variables." + it->first.Scalar());
    }
    if (n["interpolation"])
    {
        const YAML::Node &i = n["interpolation"];
        r.checkMap(i, f + ".interpolation", {"xy", "depth", "time"});
        if (i["xy"])
            c.xyInterpolation = parseInterp2D(r.oneOf(i["xy"], f + ".interpolation.xy", {"nearest", "bilinear", "bicubic"}));
        if (i["depth"])
            c.depthInterpolation =
                parseInterp1D(r.oneOf(i["depth"], f + ".interpolation.depth", {"nearest", "linear", "cubic", "akima"}));
        if (i["time"])
            c.timeInterpolation =
                parseInterp1D(r.oneOf(i["time"], f + ".interpolation.time", {"nearest", "linear", "cubic", "akima"}));
    }
    if (n["horizon"])
        c.horizonPolicy = parseBeyondForecast(r.oneOf(n["horizon"], f + ".horizon", {"refuse", "hold_last"}));
    if (n["zero_velocity_land"])
        c.zeroVelocityLand = r.boolean(n["zero_velocity_land"], f + ".zero_velocity_land");
    if (n["depth_average"])
    {
        const auto [top, bottom] = r.pair(n["depth_average"], f + ".depth_average");
        if (!(top >= 0.0 && top <= bottom && bottom <= 12000.0))
            r.fail(n["depth_average"], f + ".depth_average",
                   "expected [top, bottom] in metres, positive down, 0 <= top <= bottom <= 12000");
        c.depthAverage = std::make_pair(top, bottom);
    }
    readUnitsAndRecord(r, n, f, c);
}

void readRegion(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "region";
    r.checkMap(n, f, {"x_min", "x_max", "y_min", "y_max", "lon_min", "lon_max", "lat_min", "lat_max"});
    RegionSpec &g = m.region;
    g.set = true;
    const bool xy = n["x_min"] || n["x_max"] || n["y_min"] || n["y_max"];
    const bool geo = n["lon_min"] || n["lon_max"] || n["lat_min"] || n["lat_max"];
    if (xy == geo)
        r.fail(n, f, "give either x_min, x_max, y_min, y_max or lon_min, lon_max, lat_min, lat_max");
    auto need = [&](const char *key) -> double {
        if (!n[key])
            r.fail(n, f + "." + key, "missing");
        return r.finite(n[key], f + "." + key);
    };
    g.geographic = geo;
    if (xy)
    {
        g.xy.xMin = need("x_min");
        g.xy.xMax = need("x_max");
        g.xy.yMin = need("y_min");
        g.xy.yMax = need("y_max");
        if (!(g.xy.xMax > g.xy.xMin))
            r.fail(n["x_max"], f + ".x_max", "must be > x_min");
        if (!(g.xy.yMax > g.xy.yMin))
            r.fail(n["y_max"], f + ".y_max", "must be > y_min");
    }
    else
    {
        if (!m.projection.set && !m.current.isForecast())
            r.fail(n, f, "lon/lat bounds need a 'projection' in the mission");
        const double lonMin = need("lon_min"), lonMax = need("lon_max");
        const double latMin = need("lat_min"), latMax = need("lat_max");
        // either convention; lon_max < lon_min crosses the antimeridian (RFC 7946 bbox), stored unwrapped
        if (const auto fault = regionFault(lonMin, latMin, lonMax, latMax))
            r.fail(n[fault->bound], f + "." + fault->bound, fault->what);
        g.lonLat = geoBox(lonMin, latMin, lonMax, latMax);
    }
}

void readDeparture(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "departure";
    r.checkMap(n, f, {"time", "window"});
    DepartureSpec &d = m.departure;
    if (n["time"] && n["window"])
        r.fail(n, f, "give either a departure time or a departure window, not both");
    if (n["time"])
        d.time = r.time(n["time"], f + ".time", m);
    if (!n["window"])
        return;
    const YAML::Node &w = n["window"];
    const std::string g = f + ".window";
    r.checkMap(w, g, {"begin", "end", "spacing", "tolerance", "coarse_grid_size", "coarse_sectors", "threads"});
    if (!w["begin"] || !w["end"])
        r.fail(w, g, "begin and end are required");
    d.window = true;
    d.begin = r.time(w["begin"], g + ".begin", m);
    d.end = r.time(w["end"], g + ".end", m);
    if (!(d.end >= d.begin))
        r.fail(w["end"], g + ".end", "must not be before begin");
    d.time = d.begin;
    if (w["spacing"])
        d.spacing = r.positive(w["spacing"], g + ".spacing");
    // every supporting point is a whole search: refuse a sample set that could never finish
    const double points = std::floor((d.end - d.begin) / d.spacing) + 1.0;
    if (points > kMaxSupportingPoints)
        r.fail(w["spacing"] ? w["spacing"] : w, g + ".spacing",
               "gives " + std::to_string(static_cast<long long>(std::min(points, 1e18))) +
                   " supporting points (one search each; at most " +
                   std::to_string(static_cast<long>(kMaxSupportingPoints)) + "): use a larger spacing");
    if (w["tolerance"])
        d.tolerance = r.positive(w["tolerance"], g + ".tolerance");
    if (w["coarse_grid_size"])
        d.coarseGridSize = r.positive(w["coarse_grid_size"], g + ".coarse_grid_size");
    if (w["coarse_sectors"])
        d.coarseSectors = static_cast<int>(r.integer(w["coarse_sectors"], g + ".coarse_sectors", kMinSectors, kMaxSectors));
    readThreads(r, w, g, d.threads);
}

void readGoalWindow(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string g = "goal.window";
    r.checkMap(n, g, {"begin", "end"});
    if (!n["begin"] || !n["end"])
        r.fail(n, g, std::string("begin and end are required (missing ") + (n["begin"] ? "end" : "begin") + ")");
    GoalWindowSpec &w = m.goalWindow;
    w.set = true;
    w.begin = r.time(n["begin"], g + ".begin", m);
    w.end = r.time(n["end"], g + ".end", m);
    if (!(w.end >= w.begin))
        r.fail(n["end"], g + ".end", "must not be before begin");
    // (a window out of reach of the departure and the planning horizon is refused by runMission())
}

void readDive(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "dive_profile";
    r.checkMap(n, f,
               {"z_min", "z_max", "climb_to_max", "min_range", "climb_to_levels", "dive_to_levels", "step",
                "selection", "max_time_factor", "max_time", "clearance", "threads", "bathymetry"});
    DiveSpec &d = m.dive;
    d.enabled = true;
    DiveProfileParams &p = d.params;
    for (const char *key : {"z_min", "z_max"})
        if (!n[key])
            r.fail(n, f + "." + key, "missing");
    p.zMin = r.nonNegative(n["z_min"], f + ".z_min");
    p.zMax = r.positive(n["z_max"], f + ".z_max");
    p.climbToMax = n["climb_to_max"] ? r.nonNegative(n["climb_to_max"], f + ".climb_to_max") : p.zMin;
    p.minRange = n["min_range"] ? r.nonNegative(n["min_range"], f + ".min_range") : 0.0;
    if (n["climb_to_levels"])
        p.climbToLevels = static_cast<int>(r.integer(n["climb_to_levels"], f + ".climb_to_levels", 1, 100));
    if (n["dive_to_levels"])
        p.diveToLevels = static_cast<int>(r.integer(n["dive_to_levels"], f + ".dive_to_levels", 1, 100));
    if (n["step"])
        p.step = r.positive(n["step"], f + ".step");
    if (n["selection"])
        p.selection = diveProfileSelectionFromString(
            r.oneOf(n["selection"], f + ".selection", {"fastest", "deepest_under_limit"}));
    if (n["max_time_factor"])
        p.maxTimeFactor = r.finite(n["max_time_factor"], f + ".max_time_factor");
    if (n["max_time"])
        p.maxTime = r.positive(n["max_time"], f + ".max_time");
    if (n["clearance"])
        p.clearance = r.nonNegative(n["clearance"], f + ".clearance");
    readThreads(r, n, f, d.threads);
    try
    {
        makeDiveProfiles(p);
    }
    catch (const Error &e)
    {
        r.fail(n, f, e.what());
    }
    if (n["bathymetry"])
    {
        const YAML::Node &b = n["bathymetry"];
        const std::string g = f + ".bathymetry";
        r.checkMap(b, g, {"type", "depth", "file", "variable"});
        if (!b["type"])
            r.fail(b, g + ".type", "missing (constant or netcdf)");
        d.bathymetryType = r.oneOf(b["type"], g + ".type", {"constant", "netcdf"});
        if (d.bathymetryType == "constant")
        {
            if (!b["depth"])
                r.fail(b, g + ".depth", "missing: the seafloor depth");
            d.bathymetryDepth = r.positive(b["depth"], g + ".depth");
        }
        else
        {
            if (!b["file"])
                r.fail(b, g + ".file", "missing: the NetCDF file with the seafloor depth");
            d.bathymetryFile = joinPath(r.dir(), r.text(b["file"], g + ".file"));
            if (!fileExists(d.bathymetryFile))
                r.fail(b["file"], g + ".file", "cannot open '" + d.bathymetryFile + "'");
            if (b["variable"])
                d.bathymetryVariable = r.text(b["variable"], g + ".variable");
        }
    }
}

void readPlanner(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "planner";
    r.checkMap(n, f,
               {"name", "grid_size", "sectors", "smoothing", "refinement", "time_limit", "horizon", "goal_tolerance",
                "parameters", "objective", "quantile", "global_check"});
    PlannerSpec &p = m.planner;
    if (n["objective"])
    {
        p.objective = parseEnsembleObjective(r.oneOf(n["objective"], f + ".objective", {"expected", "worst", "quantile"}));
        if (m.current.members.empty())
            r.fail(n["objective"], f + ".objective",
                   "an objective over members needs an ensemble current (current: {ensemble: [...]})");
    }
    if (n["quantile"])
    {
        p.quantile = r.number(n["quantile"], f + ".quantile");
        if (!(p.quantile > 0.0 && p.quantile <= 1.0))
            r.fail(n["quantile"], f + ".quantile", "expected a number in (0, 1]");
        if (p.objective != EnsembleObjective::Quantile)
            r.fail(n["quantile"], f + ".quantile", "only with objective: quantile");
    }
    if (n["name"])
    {
        const std::string name = r.text(n["name"], f + ".name");
        const PlannerEntry *entry = findPlanner(name);
        if (!entry)
            r.fail(n["name"], f + ".name",
                   "unknown planner '" + name + "' (expected one of " + plannerNameList() + ")");
        p.name = entry->name;
    }
    if (n["grid_size"])
        p.gridSize = r.positive(n["grid_size"], f + ".grid_size");
    if (n["sectors"])
        p.sectors = static_cast<int>(r.integer(n["sectors"], f + ".sectors", kMinSectors, kMaxSectors));
    if (n["smoothing"])
        p.smoothing = r.boolean(n["smoothing"], f + ".smoothing");
    if (n["refinement"])
        p.refinement = r.boolean(n["refinement"], f + ".refinement");
    if (n["global_check"])
        p.globalCheck = r.boolean(n["global_check"], f + ".global_check");
    if (n["time_limit"])
    {
        p.timeLimit = r.nonNegative(n["time_limit"], f + ".time_limit");
        if (p.timeLimit > kMaxTimeLimit)
            r.fail(n["time_limit"], f + ".time_limit", "at most 1e6 s (11.6 days), got " + n["time_limit"].Scalar());
    }
    if (n["horizon"])
        p.horizon = r.positive(n["horizon"], f + ".horizon");
    if (n["goal_tolerance"])
        p.goalTolerance = r.nonNegative(n["goal_tolerance"], f + ".goal_tolerance");
    if (n["parameters"])
    {
        // Names and values are checked against the planner's declared parameters before planning (Planning.cpp).
        const YAML::Node &params = n["parameters"];
        if (!params.IsMap())
            r.fail(params, f + ".parameters", "expected a map of planner parameter names to values");
        for (auto it = params.begin(); it != params.end(); ++it)
        {
            const std::string key = it->first.Scalar();
            const std::string field = f + ".parameters." + key;
            if (!it->second.IsScalar())
                r.fail(it->second, field, "expected a value (number or boolean)");
            if (p.parameters.count(key))
                r.fail(it->first, field, "given twice");
            p.parameters[key] = it->second.Scalar();
            p.parameterMarks[key] = {r.file(), r.line(it->first)};
        }
    }
}

void readStints(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "stints";
    r.checkMap(n, f, {"duration", "mission_duration", "bearing_step", "objective", "radius", "step"});
    StintSpec &s = m.stints;
    s.set = true;
    for (const char *key : {"duration", "mission_duration"})
        if (!n[key])
            r.fail(n, f + "." + key,
                   std::string("missing: the ") +
                       (std::string(key) == "duration" ? "time between two surfacings" : "length of the mission") +
                       " in the mission's time unit");
    s.duration = r.positive(n["duration"], f + ".duration");
    s.missionDuration = r.positive(n["mission_duration"], f + ".mission_duration");
    if (s.missionDuration / s.duration > 100000.0)
        r.fail(n["mission_duration"], f + ".mission_duration",
               "gives more than 100000 stints of stints.duration: use longer stints or a shorter mission");
    if (n["bearing_step"])
    {
        s.bearingStep = r.positive(n["bearing_step"], f + ".bearing_step");
        if (s.bearingStep > 180.0)
            r.fail(n["bearing_step"], f + ".bearing_step", "expected degrees in (0, 180], got " +
                                                               n["bearing_step"].Scalar());
    }
    if (n["objective"])
        s.objective =
            parseStintObjective(r.oneOf(n["objective"], f + ".objective", {"remaining_distance", "earliest_arrival"}));
    if (n["radius"])
        s.radius = r.nonNegative(n["radius"], f + ".radius");
    if (s.objective == StintObjective::EarliestArrival && !(s.radius > 0.0))
        r.fail(n["radius"] ? n["radius"] : n["objective"], f + ".radius",
               "the earliest_arrival objective needs a goal radius > 0");
    if (n["step"])
    {
        s.step = r.positive(n["step"], f + ".step");
        if (s.duration / s.step > 1e6)
            r.fail(n["step"], f + ".step", "gives more than 10^6 integration steps per stint");
    }
}

namespace
{
/// A duration: a number in field units, or a text "<number> s|min|h|d" converted with units.time_s.
double duration(const Reader &r, const YAML::Node &n, const std::string &f, const MissionSpec &m)
{
    if (!n.IsScalar())
        r.fail(n, f, "expected a duration: a number in the mission's time unit, or e.g. '1 h', '30 min', '2 d'");
    r.mark(n, f);
    try
    {
        return parseDuration(n.Scalar(), m.timeUnitSeconds, m.hasTimeUnit());
    }
    catch (const Error &e)
    {
        r.fail(n, f, e.what());
    }
}
}  // namespace

void readOutputs(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "outputs";
    r.checkMap(n, f,
               {"directory", "files", "goto_number", "goto_include_start", "goto_turn_deg", "goto_max_offset",
                "goto_wpt_dist", "prefix", "map_time", "isochrone_interval"});
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
    if (n["goto_turn_deg"] && !((o.gotoTurnDeg = r.number(n["goto_turn_deg"], f + ".goto_turn_deg")) >= 0.0 &&
                                o.gotoTurnDeg <= 180.0))
        r.fail(n["goto_turn_deg"], f + ".goto_turn_deg", "expected degrees in 0..180 (0: every waypoint)");
    if (n["goto_max_offset"] && !((o.gotoMaxOffset = r.number(n["goto_max_offset"], f + ".goto_max_offset")) >= 0.0))
        r.fail(n["goto_max_offset"], f + ".goto_max_offset", "expected a distance in metres >= 0");
    if (n["goto_wpt_dist"] && !((o.gotoWptDist = r.number(n["goto_wpt_dist"], f + ".goto_wpt_dist")) > 0.0))
        r.fail(n["goto_wpt_dist"], f + ".goto_wpt_dist", "expected a distance in metres > 0");
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
    {
        o.isochroneInterval = duration(r, n["isochrone_interval"], f + ".isochrone_interval", m);
        if (!(o.isochroneInterval > 0.0))
            r.fail(n["isochrone_interval"], f + ".isochrone_interval", "must be > 0");
    }
}
}  // namespace ompl_glider::mission_loader

namespace ompl_glider::mission_loader
{
namespace
{
}  // namespace

void readExecution(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "execution";
    r.checkMap(n, f,
               {"truth", "surfacing_interval", "strategies", "radius", "replan_every", "duration", "batch", "dac_noise"});
    ExecutionSpec &e = m.execution;
    e.enabled = true;
    e.mark = {r.file(), r.line(n)};
    if (n["truth"])
    {
        const YAML::Node &t = n["truth"];
        if (t.IsScalar() && t.Scalar() == "forecast")
            e.truth.reset();
        else
        {
            if (!t.IsMap())
                r.fail(t, f + ".truth", "expected 'forecast' or a current source (type: ..., as in 'current')");
            CurrentSpec c;
            readCurrentSource(r, t, f + ".truth", c);
            c.mark = {r.file(), r.line(t)};
            const bool gridded = c.isForecast(), forecastGridded = m.current.isForecast();
            if (gridded != forecastGridded)
                r.fail(t["type"], f + ".truth.type",
                       forecastGridded ? "the forecast is a NetCDF file: the truth must be one too (same frame)"
                                       : "the forecast is an analytic flow: the truth must be one too (same units)");
            e.truth = c;
        }
    }
    if (n["surfacing_interval"])
        e.surfacingInterval = duration(r, n["surfacing_interval"], f + ".surfacing_interval", m);
    if (n["duration"])
        e.duration = duration(r, n["duration"], f + ".duration", m);
    if (n["strategies"])
    {
        const YAML::Node &l = n["strategies"];
        std::set<std::string> names;
        for (ControlStrategy s : controlStrategies())
            names.insert(controlStrategyName(s));
        if (!l.IsSequence() || l.size() == 0)
            r.fail(l, f + ".strategies", "expected a list such as [current_sensitive, current_blind, greedy, replan]");
        e.strategies.clear();
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            const std::string field = f + ".strategies[" + std::to_string(i) + "]";
            const std::string s = r.oneOf(l[i], field, names);
            if (std::find(e.strategies.begin(), e.strategies.end(), s) != e.strategies.end())
                r.fail(l[i], field, "'" + s + "' is listed twice");
            e.strategies.push_back(s);
        }
    }
    if (n["radius"])
        e.radius = r.positive(n["radius"], f + ".radius");
    if (n["replan_every"])
        e.replanEvery = static_cast<unsigned>(r.integer(n["replan_every"], f + ".replan_every", 1, 100000));
    if (n["dac_noise"])
    {
        e.dacNoise = r.nonNegative(n["dac_noise"], f + ".dac_noise");
        if (std::find(e.strategies.begin(), e.strategies.end(), "dac") == e.strategies.end() &&
            std::find(e.strategies.begin(), e.strategies.end(), "replan_observed") == e.strategies.end())
            r.fail(n["dac_noise"], f + ".dac_noise",
                   "no strategy measures a DAC, so the noise on it would change nothing: add dac or replan_observed "
                   "to execution.strategies, or leave dac_noise out");
    }
    if (n["batch"])
    {
        const YAML::Node &b = n["batch"];
        r.checkMap(b, f + ".batch", {"pairs", "seed", "min_distance", "threads"});
        if (b["pairs"])
            e.pairs = static_cast<unsigned>(r.integer(b["pairs"], f + ".batch.pairs", 0, 100000));
        if (b["seed"])
            e.seed = static_cast<unsigned>(r.integer(b["seed"], f + ".batch.seed", 0, 4294967295L));
        if (b["min_distance"])
            e.minDistance = r.positive(b["min_distance"], f + ".batch.min_distance");
        readThreads(r, b, f + ".batch", e.threads);
    }
}
}  // namespace ompl_glider::mission_loader

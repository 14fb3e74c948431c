// The `current` section: the source of the currents (a kind of the registry and its parameters, or forecast
// files with their variables, units and calendar) and an ensemble of them ([EichhornOceans] Sec. IV).
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "MissionReader.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/ForecastRuns.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "../../core/Numbers.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/io/UnitConversion.h"
#endif

namespace ompl_glider::mission_loader
{
namespace
{
/// The departure date of @p departure (its `time` as a date text) in seconds from the epoch of @p calendar; NaN when
/// there is none (a number, a window, not given, or not a date: the departure's own reading reports it).
double departureDate(const YAML::Node &departure, Calendar calendar)
{
    if (!departure.IsDefined() || !departure.IsMap() || !departure["time"] || !departure["time"].IsScalar())
        return std::numeric_limits<double>::quiet_NaN();
    try
    {
        return secondsSinceCalendarEpoch(departure["time"].Scalar(), calendar);
    }
    catch (const Error &)
    {
        return std::numeric_limits<double>::quiet_NaN();
    }
}

/// The time axis of the run that starts the mission's clock: the newest run available at the departure date
/// (@p departure, @p delay: its reference time plus the delay at or before it; ties: the later first time), else the
/// earliest run. Each run's axis must be dated, not steady, and on one calendar. The runs as forecastRunSources() finds
/// them: a file of several runs (a THREDDS FMRC) is each of its runs, a run in several files one run.
/// @throws Error naming the run at fault.
ForecastTimeAxis clockRun(const CurrentFieldKind &kind, const ForecastRequest &o, const std::vector<std::string> &runs,
                          const YAML::Node &departure, double delay)
{
    ForecastTimeAxis first, chosen;
    double chosenReference = -kInf;
    bool found = false;
    bool any = false;
    for (const RunSource &s : forecastRunSources(*kind.source, o, runs))
    {
        const ForecastTimeAxis &axis = s.axis;
        const std::string name = "forecast run '" + s.files.front() + "'" +
                                 (s.runIndex || s.files.size() > 1 ? " (" + axis.referenceFrom + ")" : "");
        if (!axis.found || axis.steady || !axis.dated)
            throw Error(name + ": " +
                        (axis.dated ? std::string("one time only; a run is a forecast over time")
                                    : std::string("its time axis has no dates ('<unit> since <date>'): a run's "
                                                  "reference time and availability are dates")));
        if (any && axis.calendar != first.calendar)
            throw Error(name + ": its calendar (" + calendarName(axis.calendar) + ") differs from the first run's (" +
                        calendarName(first.calendar) + ")");
        if (!any || axis.originSeconds < first.originSeconds)
            first = axis;
        const double at = departureDate(departure, axis.calendar);
        const double reference = std::isfinite(axis.referenceSeconds) ? axis.referenceSeconds : axis.originSeconds;
        if (reference + delay <= at && (!found || reference > chosenReference ||
                                        (reference == chosenReference && axis.originSeconds > chosen.originSeconds)))
        {
            chosen = axis;
            chosenReference = reference;
            found = true;
        }
        any = true;
    }
    return found ? chosen : first;
}

/// Time origin of a gridded forecast (its first time, as its source loads it): ISO dates of the mission are field
/// times in the file's calendar, and the outputs get calendar dates. The time axis is found by the source's own
/// detection (GriddedSource::timeAxis(): variables.time, else the source's rules).
void readFileCalendar(const Reader &r, const YAML::Node &n, MissionSpec &m, const YAML::Node &departure = YAML::Node())
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
        axis = m.current.runs.empty() ? kind.source->timeAxis(o)
                                      : clockRun(kind, o, m.current.runs, departure, m.current.runDelay);
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
        r.fail(n["file"] ? n["file"] : n["runs"], n["file"] ? "current.file" : "current.runs", what);
    }
    if (m.current.runs.empty() && axis.runs.size() > 1)
        r.fail(n["file"], "current.file",
               "'" + m.current.file + "' holds " + std::to_string(axis.runs.size()) +
                   " forecast runs (a forecast model run collection, a THREDDS FMRC: the velocities on a run "
                   "dimension, time '" +
                   axis.variable +
                   "' 2-D): give it as 'runs:' in place of 'file:', and the plan is made on the newest run "
                   "available at the departure");
    m.current.steady = axis.steady;
    if (!axis.found || !axis.dated)
        return; // a steady field without dates, or raw times of a Cartesian file: no calendar
    MissionSpec::FileCalendar fc;
    fc.calendar = axis.calendar;
    fc.originSeconds = axis.originSeconds;
    m.fileCalendar = fc;
    m.epoch = fc.originSeconds - secondsSinceCalendarEpoch(DateTime{}, axis.calendar);
}

/// current.runs (read with the files by readCurrentSource()) and current.run_delay: only for a gridded forecast.
void readRuns(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    if (!n.IsMap())
        return;
    for (const char *key : {"runs", "run_delay"})
        if (n[key] && !m.current.isForecast())
            r.fail(n[key], std::string("current.") + key,
                   "only for type " + griddedKindList(" or ") + " (forecast runs read from files)");
    if (!n["run_delay"])
        return;
    if (!n["runs"])
        r.fail(n["run_delay"], "current.run_delay", "given without 'runs': the delay is that of forecast runs");
    m.current.runDelay = duration(r, n["run_delay"], "current.run_delay", m);
    if (!(m.current.runDelay >= 0.0))
        r.fail(n["run_delay"], "current.run_delay", "expected a duration >= 0, such as '12 h'");
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
    if (n["max_speed"])
    {
        try
        {
            c.maxSpeed = parseSpeed(r.text(n["max_speed"], f + ".max_speed"));
        }
        catch (const Error &e)
        {
            r.fail(n["max_speed"], f + ".max_speed", e.what());
        }
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
        c.steadyRecord = static_cast<std::size_t>(r.integer(n["steady_record"], f + ".steady_record", 0, 1000000000L));
}

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
} // namespace

void readCurrent(const Reader &r, const YAML::Node &n, MissionSpec &m, const YAML::Node &departure)
{
    if (isDrawnEnsemble(n))
        return readDrawnEnsemble(r, n, m); // members drawn from one source (DrawnEnsemble.cpp)
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
    readCurrentSource(r, n, "current", m.current, {"runs", "run_delay"});
    readRuns(r, n, m);
    if (m.current.isForecast())
        readFileCalendar(r, n, m, departure);
}

void readCurrentSource(const Reader &r, const YAML::Node &n, const std::string &f, CurrentSpec &c,
                       const std::set<std::string> &extraKeys)
{
    std::set<std::string> keys{"type",          "parameters",     "file",       "variables",     "interpolation",
                               "horizon",       "velocity_units", "time_units", "steady_record", "zero_velocity_land",
                               "depth_average", "max_speed"};
    keys.insert(extraKeys.begin(), extraKeys.end());
    r.checkMap(n, f, keys);
    c.mark = {r.file(), r.line(n)};
    const std::vector<std::string> names = currentFieldKindNames(); // with the aliases ("netcdf": gridded)
    const std::set<std::string> kinds(names.begin(), names.end());
    if (!n["type"])
        r.fail(n, f + ".type", "missing (" + currentFieldKindList() + ")");
    c.type = r.oneOf(n["type"], f + ".type", kinds);
    const CurrentFieldKind &kind = *findCurrentFieldKind(c.type);
    if (n["parameters"])
    {
        std::set<std::string> names;
        for (const auto &[key, value] : kind.parameters) // (the set checkMap() takes; hasParameter() decides alike)
            names.insert(key);
        r.checkMap(n["parameters"], f + ".parameters", names);
        for (auto it = n["parameters"].begin(); it != n["parameters"].end(); ++it)
        {
            const std::string key = it->first.Scalar();
            c.parameters[key] = r.finite(it->second, f + ".parameters." + key);
        }
    }
    // the analytic flows' parameters that must be positive: (flow, parameter, what is expected)
    static const std::array<std::array<const char *, 3>, 2> positive = {
        {{"double_gyre", "length", "expected a number > 0"},
         {"rankine_vortex", "radius", "expected a number > 0 (the core radius)"}}};
    for (const auto &[type, key, expected] : positive)
        if (c.type == type && c.parameters.count(key) && !(c.parameters[key] > 0))
            r.fail(n["parameters"][key], f + ".parameters." + key, expected);
    const bool gridded = kind.gridded();
    for (const char *key : {"file", "variables", "interpolation", "horizon", "velocity_units", "time_units",
                            "steady_record", "zero_velocity_land", "depth_average", "max_speed"})
        if (n[key] && !gridded)
            r.fail(n[key], f + "." + key, "only for type " + griddedKindList(" or ") + " (a forecast read from files)");
    if (!gridded)
        return;
    if (n["runs"]) // forecast runs in place of one forecast (readRuns())
    {
        if (n["file"])
            r.fail(n["file"], f + ".file",
                   "both 'file' and 'runs' given: give the forecast's files as 'file', or its runs (each file one "
                   "run) as 'runs'");
        readForecastFiles(r, n["runs"], f + ".runs", c);
        c.runs = c.forecastFiles();
        c.files.clear();
    }
    else if (!n["file"])
        r.fail(n, f + ".file", "missing: the forecast's file (type " + c.type + ")");
    else
        readForecastFiles(r, n["file"], f + ".file", c);
    if (n["variables"])
    {
        r.checkMap(n["variables"], f + ".variables",
                   {"u", "v", "x", "y", "lon", "lat", "depth", "time", "mask", "angle"});
        for (auto it = n["variables"].begin(); it != n["variables"].end(); ++it)
            c.variables[it->first.Scalar()] = r.text(it->second, f + ".variables." + it->first.Scalar());
    }
    if (n["interpolation"])
    {
        const YAML::Node &i = n["interpolation"];
        r.checkMap(i, f + ".interpolation", {"xy", "depth", "time"});
        if (i["xy"])
            c.xyInterpolation =
                parseInterp2D(r.oneOf(i["xy"], f + ".interpolation.xy", {"nearest", "bilinear", "bicubic"}));
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
} // namespace ompl_glider::mission_loader

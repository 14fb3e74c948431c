#include "ompl_glider/mission/ForecastMission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/ForecastRuns.h"
#include "ompl_glider/current/ForecastSource.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Observations.h"
#include "ompl_glider/mission/SettingRanges.h"
#include "../../io/NumberText.h"

namespace ompl_glider
{
namespace
{
/// A plain number (seconds after the first forecast time), not a date.
bool isNumber(const std::string &text)
{
    char *end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    return !text.empty() && end && *end == '\0' && std::isfinite(v);
}

std::string pointText(double a, double b)
{
    char buf[80];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g", a, b);
    return buf;
}

/// The region as given, in GeoJSON bbox order: "x_min,y_min,x_max,y_max" (lon_min,lat_min,lon_max,lat_max).
std::string regionText(const Box &r)
{
    return text::number(r.xMin) + "," + text::number(r.yMin) + "," + text::number(r.xMax) + "," + text::number(r.yMax);
}
/// How the caller names a value it gave for @p field ("--start", "plan(): keyword 'start'"), else the field.
std::string named(const ForecastInput &q, const std::string &field)
{
    return q.words ? q.words->givenName(field) : field;
}

/// The setting @p setting with the caller's word for it (SettingWords), else as a mission file names it.
std::string term(const ForecastInput &q, const std::string &setting)
{
    return q.words ? (*q.words)(setting) : setting;
}

/// Start and goal, each with the caller's name for it.
std::vector<std::pair<std::string, Point2>> endpoints(const ForecastInput &q)
{
    return {{named(q, "start"), q.start}, {named(q, "goal"), q.goal}};
}

/// Where the caller gave @p field.
SourceMark markOf(const ForecastInput &q, const std::string &field)
{
    return SourceMark{named(q, field), 0, q.words ? q.words->origin : Origin::Program};
}

/// The mission's request to its source, its settings named as the caller names them.
ForecastRequest callerRequest(const MissionSpec &m, const ForecastInput &q)
{
    ForecastRequest o = forecastRequest(m);
    for (auto &[option, field] : forecastFieldNames("current"))
        o.optionNames[option] = named(q, field);
    o.optionNames[ForecastOption::Departure] = named(q, "departure.time");
    o.optionNames[ForecastOption::MaxDepth] = named(q, "vehicle.depth");
    o.optionNames[ForecastOption::Region] = named(q, "region");
    return o;
}

/// The mission's gridded source.
const GriddedSource &sourceOf(const MissionSpec &m)
{
    return *findCurrentFieldKind(m.current.type)->source;
}

/// A departure or region fault (by the setting the source names, Error::field()) prefixed with what gave it.
std::string callerMessage(const Error &e, const ForecastInput &q, const ForecastRequest &o)
{
    const std::string what = e.what();
    if (e.field().empty())
        return what;
    if (!q.departure.empty() && e.field() == o.optionName(ForecastOption::Departure, ""))
        return named(q, "departure.time") + " " + q.departure + ": " + what;
    if (e.field() == o.optionName(ForecastOption::Region, ""))
    {
        const std::string given = q.region ? named(q, "region") + " " + regionText(*q.region)
                                           : named(q, "start") + " " + pointText(q.start.x, q.start.y) + " / " +
                                                 named(q, "goal") + " " + pointText(q.goal.x, q.goal.y);
        return given + ": not on the grid: " + what;
    }
    return what;
}

/// The forecast's files (file or files, each an existing regular file, or a folder: a Zarr store).
/// @throws Error when both or a missing file are given.
std::vector<std::string> forecastFiles(const ForecastInput &q)
{
    namespace fs = std::filesystem;
    if (!q.current.file.empty() && !q.current.files.empty())
        throw Error("ForecastInput: both current.file and current.files given; give one of them");
    if (!q.current.runs.empty() && (!q.current.file.empty() || !q.current.files.empty()))
        throw Error("ForecastInput: both current.runs and the forecast's files given; give one of them");
    const std::vector<std::string> files = q.current.runs.empty() ? q.current.forecastFiles() : q.current.runs;
    std::error_code ec;
    for (const std::string &p : files)
        if (!isRemoteSource(p) && !isMemoryDataset(p) && !fs::is_regular_file(p, ec) && !fs::is_directory(p, ec))
            throw Error(named(q, "current.file") + ": cannot open '" + p + "' (no such file)");
    return files;
}

/// The mission's current, start, goal and depth as the caller gives them (the current section as a mission file's
/// `current: type netcdf`); @p file names the forecast in messages.
MissionSpec forecastSpec(const ForecastInput &q, const std::vector<std::string> &files, const std::string &file)
{
    namespace fs = std::filesystem;
    MissionSpec m;
    m.file = withoutCredentials(file); // names the forecast in messages and outputs: never a URL's password
    m.directory = ".";
    m.name = fs::path(withoutCredentials(files.front())).stem().string();
    m.current = q.current;
    // the source the caller names (a registered gridded kind), else the gridded reader's (by its canonical name)
    const CurrentFieldKind *kind = findCurrentFieldKind(q.current.type);
    if (!kind || !kind->gridded())
        m.current.type = "gridded";
    m.current.file = files.front();
    m.current.files = files.size() > 1 ? files : std::vector<std::string>{};
    m.current.mark = SourceMark{file, 0};

    m.words = q.words;
    m.marks["start"] = markOf(q, "start");
    m.marks["goal"] = markOf(q, "goal");
    m.start.xy = q.start;
    m.start.lonLat = {q.start.x, q.start.y};
    m.goal.xy = q.goal;
    m.goal.lonLat = {q.goal.x, q.goal.y};
    m.vehicle.depth = q.depth;
    if (q.depth > 0.0)
        m.marks["vehicle.depth"] = markOf(q, "vehicle.depth");
    return m;
}

/// A run of forecast runs: its files (several for a run in several files), its index in a file of several runs (a
/// THREDDS FMRC), when it is available.
struct RunAt
{
    std::vector<std::string> files;
    std::optional<std::size_t> runIndex;
    double available{0.0};
};

/// Forecast runs (ForecastInput::current.runs): the run planned on, the newest available at the departure (its
/// reference time + current.runDelay at or before it), whose file (and run in a file of several) the mission is then
/// made of, as of that run alone (its first time the mission's field time 0); without a departure, the first run's
/// availability becomes the departure (@p departure is set to it). @throws Error for a departure that is no date,
/// or before any run.
RunAt runAtDeparture(const MissionSpec &m, const ForecastInput &q, std::string &departure)
{
    if (!departure.empty() && isNumber(departure))
        throw Error(named(q, "departure.time") + " " + departure +
                    ": with forecast runs the departure is a date (ISO 8601), not a time after one run's start");
    using Run = RunAt;
    std::vector<Run> runs;
    Calendar calendar = Calendar::Standard;
    const ForecastRequest o = callerRequest(m, q);
    std::vector<RunSource> sources;
    try
    {
        sources = forecastRunSources(sourceOf(m), o, m.current.runs);
    }
    catch (const Error &e)
    {
        throw Error(callerMessage(e, q, o), e.field());
    }
    for (const RunSource &s : sources) // (a file of several runs each of them, a run in several files one)
    {
        if (!s.axis.dated || s.axis.steady)
            throw Error(named(q, "current.runs") + ": forecast run '" + s.files.front() +
                        (s.runIndex || s.files.size() > 1 ? "' (" + s.axis.referenceFrom + ")" : "'") +
                        " has no dated time axis of several times: a run's reference time and availability are "
                        "dates");
        calendar = s.axis.calendar;
        runs.push_back({s.files, s.runIndex, s.axis.referenceSeconds + m.current.runDelay});
    }
    const auto first = std::min_element(runs.begin(), runs.end(),
                                        [](const Run &a, const Run &b) { return a.available < b.available; });
    if (departure.empty())
        departure = formatCalendarTime(first->available, calendar);
    double t = 0.0;
    try
    {
        t = secondsSinceCalendarEpoch(departure, calendar);
    }
    catch (const Error &e)
    {
        throw Error(named(q, "departure.time") + " " + departure + ": " + e.what());
    }
    const Run *newest = nullptr;
    for (const Run &r : runs)
        if (r.available <= t && (!newest || r.available >= newest->available))
            newest = &r;
    if (!newest)
        throw Error(named(q, "current.runs") + ": no run is available at the departure " + departure +
                    ": the first, '" + first->files.front() + "', is available from " +
                    formatCalendarTime(first->available, calendar) + " (its reference time + the run delay)");
    return *newest;
}

/// Longitude/latitude or x/y: the reader's own detection, before any region is cut.
bool forecastIsGeographic(const std::vector<std::string> &list, const MissionSpec &m, const ForecastInput &q)
{
    bool geographic = true;
    ForecastRequest o = callerRequest(m, q);
    try
    {
        o.files = list;
        geographic = sourceOf(m).geographic(o);
    }
    catch (const Error &e)
    {
        throw Error(callerMessage(e, q, o), e.field());
    }
    return geographic;
}

/// Start and goal of a geographic file: longitudes in -180..180 or 0..360, latitudes in -90..90.
void checkLonLat(const ForecastInput &q)
{
    for (const auto &[name, p] : endpoints(q))
    {
        if (p.x < -180.0 || p.x > 360.0)
            throw Error(name + " " + pointText(p.x, p.y) + ": longitude " + text::number(p.x) +
                        " is not in -180..180 or 0..360");
        if (std::abs(p.y) > 90.0)
            throw Error(name + " " + pointText(p.x, p.y) + ": latitude " + text::number(p.y) + " is not in -90..90");
    }
}

/// The region of --region (when given) in the mission, checked (regionFault() for a geographic file, the order of
/// the bounds for a Cartesian one) and with start and goal in it.
void setRegion(MissionSpec &m, const ForecastInput &q, bool geographic)
{
    if (!q.region)
        return;
    const Box &r = *q.region;
    m.marks["region"] = markOf(q, "region");
    m.region.set = true;
    m.region.geographic = geographic;
    if (geographic)
    {
        if (const auto fault = regionFault(r.xMin, r.yMin, r.xMax, r.yMax))
            throw Error(named(q, "region") + " " + regionText(r) + ": " + fault->bound + " " + fault->what);
        const GeoBox box = geoBox(r.xMin, r.yMin, r.xMax, r.yMax);
        m.region.lonLat = box;
        for (const auto &[name, p] : endpoints(q))
            if (!box.contains({p.x, p.y}))
                throw Error(name + " " + pointText(p.x, p.y) + " (lon,lat) lies outside " + named(q, "region") + " " +
                            regionText(r) + " (" + box.text() + ")");
    }
    else
    {
        if (!(r.xMax > r.xMin) || !(r.yMax > r.yMin) || !std::isfinite(r.xMax - r.xMin) ||
            !std::isfinite(r.yMax - r.yMin))
            throw Error(named(q, "region") + " " + regionText(r) +
                        ": a Cartesian file's region is x_min,y_min,x_max,y_max with x_max > x_min and "
                        "y_max > y_min");
        m.region.xy = r;
        for (const auto &[name, p] : endpoints(q))
            if (!(p.x >= r.xMin && p.x <= r.xMax && p.y >= r.yMin && p.y <= r.yMax))
                throw Error(name + " " + pointText(p.x, p.y) + " (x,y) lies outside " + named(q, "region") + " " +
                            regionText(r));
    }
}

/// Loads the trip's region as the mission will (forecastRequest()) to check the request and convert the departure;
/// @p epoch is set to the date of field time 0 of a steady file without dates when the departure is a date.
LoadedForecast loadForecast(const std::vector<std::string> &list, const MissionSpec &m, const ForecastInput &q,
                            std::optional<double> &epoch)
{
    ForecastRequest o = callerRequest(m, q);
    o.files = list;
    o.departure = q.departure;
    const GriddedSource &source = sourceOf(m);
    LoadedForecast nc;
    try
    {
        // start and goal within the file's coordinates, before its data are read (the files' grids agree)
        const ForecastExtent e = source.extent(o);
        for (const auto &[name, p] : endpoints(q))
            if (!e.contains(p.x, p.y))
                throw Error(name + " " + pointText(p.x, p.y) + " (" + (e.geographic ? "lon,lat" : "x,y") +
                            ") lies outside the grid of '" + list.front() + "' (" + e.text() +
                            (e.geographic ? ")" : "; start and goal are in the file's own x/y units)"));
        if (!q.departure.empty() && !isNumber(q.departure))
        {
            const ForecastTimeAxis axis = source.timeAxis(o);
            if (axis.steady && !axis.dated)
            {
                try
                {
                    epoch = parseIsoTime(q.departure);
                }
                catch (const Error &e)
                {
                    throw Error(named(q, "departure.time") + " " + q.departure + ": " + e.what());
                }
                o.departure.clear(); // departs at field time 0, which is that date
            }
        }
        nc = source.load(o);
    }
    catch (const Error &e)
    {
        throw Error(callerMessage(e, q, o), e.field());
    }
    return nc;
}

/// The depth lies within the forecast's layers, and start and goal lie on its grid and in water.
void checkEndpoints(const LoadedForecast &nc, const ForecastInput &q, const std::string &file, bool geographic)
{
    const char *coords = geographic ? "lon,lat" : "x,y";
    const CurrentField &g = *nc.field;
    const FieldGrid *grid = g.grid();
    if (!grid)
        throw Error("'" + file + "': its source gave a field without a grid");
    // (Above the first layer is the surface layer's value, as forecasts put their first layer just below it.)
    const Region extent = grid->extent();
    if (extent.zMax > extent.zMin && q.depth > extent.zMax)
        throw Error(named(q, "vehicle.depth") + " " + text::number(q.depth) + " m lies below the deepest layer of '" +
                    file + "' (" + text::number(extent.zMax) + " m)");
    const Point2 start = nc.toLocal({q.start.x, q.start.y});
    const Point2 goal = nc.toLocal({q.goal.x, q.goal.y});
    using Endpoint = std::tuple<std::string, double, double, double, double>;
    for (const auto &[name, a, b, x, y] : {Endpoint{named(q, "start"), q.start.x, q.start.y, start.x, start.y},
                                           Endpoint{named(q, "goal"), q.goal.x, q.goal.y, goal.x, goal.y}})
    {
        if (!std::isfinite(x) || !std::isfinite(y) || !grid->covers(x, y))
        {
            // the loaded nodes' own bounds, in the file's coordinates (longitudes from west to east)
            throw Error(name + " " + pointText(a, b) + " (" + coords + ") lies outside the grid of '" + file + "' (" +
                        (geographic ? "lon " : "x ") + text::number(nc.lonMin) + ".." + text::number(nc.lonMax) +
                        (geographic ? ", lat " : ", y ") + text::number(nc.latMin) + ".." + text::number(nc.latMax) +
                        ")");
        }
        if (!g.inWater(x, y, q.depth) && !q.snapToWater)
        {
            // what makes land in this forecast (a cell with a land corner is land)
            std::string why;
            for (const std::string &cause : nc.landCauses)
                why += (why.empty() ? "" : ", ") + cause;
            const std::string at = q.current.depthAverage
                                       ? "in the depth average over " + text::number(q.current.depthAverage->first) +
                                             ".." + text::number(q.current.depthAverage->second) +
                                             " m (land where any depth in it is land or below the sea floor)"
                                       : "at depth " + text::number(q.depth) + " m";
            std::string nearest;
            if (const std::optional<Point2> w = nearestWater(g, {x, y}, q.depth, 0.01 * grid->minCellSize()))
            {
                const LonLat ll = nc.toGeographic(*w);
                const double d = std::hypot(w->x - x, w->y - y);
                nearest = "; the nearest water is " + text::number(ll.lon, 8) + "," + text::number(ll.lat, 8) + " (" +
                          coords + "), " + (geographic ? text::number(d / 1000.0, 4) + " km" : text::number(d, 6)) +
                          " away (" + term(q, "safety.snap_to_water: true") + " uses it)";
            }
            throw Error(name + " " + pointText(a, b) + " (" + coords + ") is on land in '" + file + "' " + at +
                        (why.empty() ? "" : "; the forecast's land is where it has " + why) + nearest);
        }
    }
}

/// The departure lies within the forecast and leaves time to travel (a steady field takes any departure).
void checkDeparture(const LoadedForecast &nc, const ForecastInput &q)
{
    const double tDep = nc.departureTime;
    // a steady field (no time dimension, a single record, --steady-record) is the same at every time
    if (!nc.steady && (tDep < nc.forecastBegin || tDep > nc.forecastEnd))
        throw Error(named(q, "departure.time") + " " + q.departure + " is outside the forecast (" +
                    nc.isoTime(nc.forecastBegin) + " to " + nc.isoTime(nc.forecastEnd) + ")");
    if (!nc.steady && tDep >= nc.forecastEnd && q.current.horizonPolicy == BeyondForecast::Refuse)
        throw Error(named(q, "departure.time") + " " + (q.departure.empty() ? std::string("(default)") : q.departure) +
                    " is the last forecast time: no time is left to travel (use an earlier departure or " +
                    term(q, "current.horizon: hold_last") + ")");
}

/// The forecast's calendar, the departure, the vehicle and the outputs (every format) of the mission.
void finishSpec(MissionSpec &m, const LoadedForecast &nc, const std::optional<double> &epoch, const ForecastInput &q)
{
    if (nc.dated)
    {
        MissionSpec::FileCalendar fc;
        fc.calendar = nc.calendar;
        fc.originSeconds = nc.originSeconds;
        m.fileCalendar = fc;
        m.epoch = fc.originSeconds - secondsSinceCalendarEpoch(DateTime{}, fc.calendar);
    }
    else if (epoch)
        m.epoch = *epoch;
    m.current.steady = nc.steady;
    m.safety.snapToWater = q.snapToWater;
    m.departure.time = nc.departureTime;
    m.vehicle.speed = q.speed;
    m.vehicle.depth = q.depth;
    if (q.depth > 0.0)
        m.marks["vehicle.depth"] = markOf(q, "vehicle.depth");
    m.travel.eps = 1.0; // one second per integration step on trips of hours to days (as the example mission)
    m.outputs.files = {OutputFormatId::Summary, OutputFormatId::Path, OutputFormatId::Csv,
                       OutputFormatId::GeoJson, OutputFormatId::Goto, OutputFormatId::Map};
    m.outputs.directory.clear();
    m.outputs.gotoNumber = 10;
}

/// @p q with the start (and, where none is given, the departure) at the last fix of its observations, and the words
/// that name them so.
ForecastInput atLastFix(const ForecastInput &q, std::shared_ptr<const GliderObservations> &read)
{
    ForecastInput at = q;
    const std::string source = named(q, "observations");
    std::optional<GliderFix> fix;
    try
    {
        read = readObservationsAt(q.observations, q.observationsCache);
        fix = read->lastFix;
        if (!fix)
            throw Error("they report no position to start from");
    }
    catch (const Error &e)
    {
        throw Error(source + " " + q.observations + ": " + e.what());
    }
    at.start = {fix->at.lon, fix->at.lat};
    auto words = std::make_shared<SettingWords>(q.words ? *q.words : SettingWords{{}, {}, Origin::Program});
    words->given["start"] = "the last fix of " + source;
    if (q.departure.empty())
    {
        at.departure = formatIsoTime(fix->time);
        words->given["departure.time"] = "the last fix's time (" + source + ")";
    }
    at.words = words;
    return at;
}

/// The rest of forecastMission() once the forecast's files are known (@p m's current): its grid, region, departure
/// and calendar read from them; @p q the caller's input with the departure settled.
MissionSpec finishForecastMission(const ForecastInput &input, const ForecastInput &q, MissionSpec &m,
                                  const std::string &file, const std::shared_ptr<const GliderObservations> &read)
{
    const std::vector<std::string> list = m.current.forecastFiles();
    const bool geographic = forecastIsGeographic(list, m, q);
    m.start.geographic = m.goal.geographic = geographic;
    if (geographic)
        checkLonLat(q);
    setRegion(m, q, geographic);
    std::optional<double> epoch; // the date of field time 0 of a steady file without dates
    const LoadedForecast nc = loadForecast(list, m, q, epoch);
    checkEndpoints(nc, q, file, geographic);
    checkDeparture(nc, q);
    finishSpec(m, nc, epoch, q);
    if (input.startAtLastFix) // a first guess until the mission resumes at the fix
    {
        markLastFixGuess(m, SourceMark{named(input, "observations"), 0}, input.departure.empty());
        ObservationsSpec o = m.observations.value_or(ObservationsSpec{});
        o.path = input.observations;
        o.cache = input.observationsCache;
        keepObservations(o, read); // the mission's inputs take them from here
        m.observations = o;
    }
    return m;
}
} // namespace

MissionSpec forecastMission(const ForecastInput &input)
{
    std::shared_ptr<const GliderObservations> read; // the observations read for the last fix: read once
    const ForecastInput q = input.startAtLastFix ? atLastFix(input, read) : input;
    const std::vector<std::string> files = forecastFiles(q);
    // in messages: the file, or the files of a forecast in several
    std::string file = files.front();
    for (std::size_t k = 1; k < files.size(); ++k)
        file += "," + files[k];
    try
    {
        checkSetting("vehicle.speed", q.speed, text::number(q.speed));
    }
    catch (const Error &e)
    {
        throw Error(named(q, "vehicle.speed") + ": " + e.what() + " (m/s)");
    }
    if (!(q.depth >= 0.0))
        throw Error(named(q, "vehicle.depth") + " must be >= 0 (metres, positive down)");

    MissionSpec m = forecastSpec(q, files, file);
    ForecastInput given = q; // with runs, the departure (the first run's availability when none is given)
    if (!q.current.runs.empty())
    {
        const RunAt run = runAtDeparture(m, q, given.departure);
        m.current.file = run.files.front();
        m.current.runIndex = run.runIndex;
        m.current.files.clear();
        if (run.files.size() > 1) // a run in several files
            m.current.files = run.files;
        file = m.current.file; // messages name the run planned on
        m.file = withoutCredentials(file);
    }
    return finishForecastMission(input, given, m, file, read);
}

} // namespace ompl_glider

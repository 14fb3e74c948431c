// Missions for the Python module: the MissionSpec of each way in (built-in, mission file, mission text, NetCDF
// forecast) and the keyword arguments of plan() applied to it as the command line applies its flags.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <type_traits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "Bindings.h"
#include "KeywordValues.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/mission/Fleet.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Overrides.h"
#include "ompl_glider/registry/PlannerRegistry.h"

namespace py = pybind11;
using namespace ompl_glider;

namespace ompl_glider_py
{
namespace
{
using Pair = std::pair<double, double>;
using Quad = std::tuple<double, double, double, double>;

std::shared_ptr<const SettingWords> keywordWords();

/// One item of the `via` keyword: a pair (x, y) / (lon, lat), or a dict {at: pair, name, radius, stay,
/// arrive: (begin, end)}; a radius and a stay as a number in the mission's unit or a text with its unit.
ViaPointSpec viaPoint(const py::handle item, const std::string &at, const MissionSpec &m)
{
    ViaPointSpec p;
    if (py::isinstance<py::dict>(item))
    {
        const py::dict d = py::reinterpret_borrow<py::dict>(item);
        static const std::set<std::string> keys = {"at", "name", "radius", "stay", "arrive"};
        for (const auto &key : d)
        {
            const std::string name = key.first.cast<std::string>();
            if (!keys.count(name))
                throw Error("plan(): keyword 'via': " + at + ": unknown key '" + name +
                            "' (at, name, radius, stay, arrive)");
        }
        if (!d.contains("at"))
            throw Error("plan(): keyword 'via': " + at + ": 'at' (x, y) or (lon, lat) is required");
        const Pair xy = value<Pair>(d["at"], at + ".at", "a pair (x, y) or (lon, lat) of numbers");
        p.position.xy = {xy.first, xy.second};
        if (d.contains("name"))
            p.name = value<std::string>(d["name"], at + ".name", "a text");
        // a radius and a stay as a mission file gives them: a number in the mission's unit, or a text with
        // its unit ("500 m", "6 h")
        if (d.contains("radius") && py::isinstance<py::str>(d["radius"]))
            try
            {
                p.radius = parseLength(d["radius"].cast<std::string>(), m.metresPerUnit(), m.physicalUnits().length);
            }
            catch (const Error &e)
            {
                throw Error("plan(): keyword 'via': " + at + ".radius: " + e.what());
            }
        else if (d.contains("radius"))
            p.radius = value<double>(d["radius"], at + ".radius",
                                     "a number (the mission's length unit) or a length (\"500 m\")");
        if (d.contains("stay") && py::isinstance<py::str>(d["stay"]))
            try
            {
                p.stay = parseDuration(d["stay"].cast<std::string>(), m.timeUnitSeconds, m.hasTimeUnit());
            }
            catch (const Error &e)
            {
                throw Error("plan(): keyword 'via': " + at + ".stay: " + e.what());
            }
        else if (d.contains("stay"))
            p.stay =
                value<double>(d["stay"], at + ".stay", "a number (the mission's time unit) or a duration (\"6 h\")");
        if (d.contains("arrive"))
        {
            const auto [b, e] =
                value<std::pair<py::object, py::object>>(d["arrive"], at + ".arrive", "a pair (begin, end) of times");
            try
            {
                p.arrive = {true, m.timeOf(py::str(b).cast<std::string>()), m.timeOf(py::str(e).cast<std::string>())};
            }
            catch (const Error &e)
            {
                throw Error("plan(): keyword 'via': " + at + ".arrive: " + e.what());
            }
        }
    }
    else
    {
        const Pair xy = value<Pair>(item, at, "a pair (x, y) or (lon, lat) of numbers, or a dict");
        p.position.xy = {xy.first, xy.second};
    }
    return p;
}

/// The forecast of a gridded path (a file, or a comma-separated list of files and glob patterns) with the
/// command line's options, as `--currents FILE --start ... --goal ...` builds it (forecastMission()), read by the
/// gridded source @p kind names (Field.kind: gridded, its alias netcdf, or a registered one).
MissionSpec forecast(const std::string &files, std::optional<Pair> start, Pair goal, const std::string &departure,
                     std::optional<double> speed, double depth, std::optional<Quad> region,
                     const std::map<std::string, std::string> &variables, const std::string &xy,
                     const std::string &depthScheme, const std::string &timeScheme, const std::string &horizon,
                     const std::string &velocityUnits, const std::string &timeUnits,
                     std::optional<std::size_t> steadyRecord, bool zeroVelocityLand, std::optional<Pair> depthAverage,
                     bool snapToWater, const std::string &observations, const std::string &kind,
                     const std::string &observationsCache, const std::string &maxSpeed, bool runs,
                     const std::string &runDelay)
{
    ForecastInput in;
    in.current.type = kind; // a gridded kind of the registry (or its alias), kept as named; another: netcdf
    in.snapToWater = snapToWater;
    in.words = keywordWords();
    const std::vector<std::string> list = forecastFileList(files);
    if (runs)
        in.current.runs = list; // each file one run
    else if (list.size() == 1)
        in.current.file = list.front();
    else
        in.current.files = list;
    if (!runDelay.empty())
    {
        try
        {
            in.current.runDelay = parseDuration(runDelay, 1.0, true);
        }
        catch (const Error &e)
        {
            throw Error("Field.netcdf(): keyword 'run_delay': " + std::string(e.what()));
        }
        if (!(in.current.runDelay >= 0.0))
            throw Error("Field.netcdf(): keyword 'run_delay': expected a duration >= 0, such as '12 h'");
    }
    in.current.variables = variables;
    in.current.xyInterpolation = parseInterp2D(xy);
    in.current.depthInterpolation = parseInterp1D(depthScheme);
    in.current.timeInterpolation = parseInterp1D(timeScheme);
    in.current.horizonPolicy = parseBeyondForecast(horizon);
    in.current.velocityUnits = velocityUnits;
    if (!maxSpeed.empty())
    {
        try
        {
            in.current.maxSpeed = parseSpeed(maxSpeed);
        }
        catch (const Error &e)
        {
            throw Error("Field.netcdf(): keyword 'max_speed': " + std::string(e.what()));
        }
    }
    in.current.timeUnits = timeUnits;
    in.current.steadyRecord = steadyRecord;
    in.current.zeroVelocityLand = zeroVelocityLand;
    in.current.depthAverage = depthAverage;
    // without a start: the glider's last fix (and its time without a departure), read by the mission
    in.startAtLastFix = !start;
    in.observations = observations;
    in.observationsCache = observationsCache;
    if (start)
        in.start = {start->first, start->second};
    in.goal = {goal.first, goal.second};
    in.departure = departure;
    if (speed) // else ForecastInput's
    {
        checkFinite("speed", *speed, true);
        in.speed = *speed;
    }
    in.depth = depth;
    if (region)
    {
        const auto [a, b, c, d] = *region;
        in.region = Box{a, c, b, d}; // (lon_min, lat_min, lon_max, lat_max) as --region
    }
    MissionSpec out; // the forecast's description is read here (a URL: fetched, stopped by Ctrl-C)
    runStoppable([&] { out = forecastMission(in); });
    return out;
}

/// A polygon of the `forbidden` keyword: a dict with "points" and optional "name", "kind", "lonlat", "windows"
/// (a time-windowed zone), "t_ref", "drift", "carried", "max_submerged_time" (an ice zone).
void addForbidden(MissionSpec &m, const py::dict &item, std::size_t index)
{
    const std::string where = "plan(): keyword 'forbidden' [" + std::to_string(index) + "]";
    PolygonSpec poly;
    const std::string kw = "forbidden[" + std::to_string(index) + "]";
    poly.name = item.contains("name") ? value<std::string>(item["name"], kw + ".name", "a text")
                                      : "region " + std::to_string(index + 1);
    poly.geographic =
        item.contains("lonlat") ? value<bool>(item["lonlat"], kw + ".lonlat", "True or False") : m.start.geographic;
    if (!item.contains("points"))
        throw Error(where + ": expected 'points', a list of (x, y) or (lon, lat) pairs");
    poly.points = value<std::vector<Pair>>(item["points"], kw + ".points", "a list of (x, y) or (lon, lat) pairs");
    if (poly.points.size() < 3)
        throw Error(where + ": a polygon needs at least 3 points, got " + std::to_string(poly.points.size()));
    for (const Pair &p : poly.points)
        if (!std::isfinite(p.first) || !std::isfinite(p.second))
            throw Error(where + ": every point must be finite");
    poly.mark = keyword("forbidden");
    if (item.contains("windows"))
    {
        TimeWindowSpec w{poly,
                         value<std::vector<Pair>>(item["windows"], kw + ".windows", "a list of (begin, end) pairs")};
        for (const Pair &p : w.windows)
            if (!(p.second >= p.first))
                throw Error(where + ": a window's end must not be before its begin");
        m.forbidden.timeWindows.push_back(std::move(w));
    }
    else if (item.contains("max_submerged_time"))
    {
        IceSpec ice;
        ice.polygon = poly;
        ice.maxSubmergedTime = value<double>(item["max_submerged_time"], kw + ".max_submerged_time", "a number");
        checkFinite("forbidden.max_submerged_time", ice.maxSubmergedTime, false);
        ice.tRef = item.contains("t_ref") ? value<double>(item["t_ref"], kw + ".t_ref", "a number") : 0.0;
        if (item.contains("drift"))
            std::tie(ice.vx, ice.vy) = value<Pair>(item["drift"], kw + ".drift", "a pair (vx, vy) of numbers");
        ice.carried = item.contains("carried") && value<bool>(item["carried"], kw + ".carried", "True or False");
        m.forbidden.ice.push_back(std::move(ice));
    }
    else
    {
        ObstacleSpec o;
        o.polygon = poly;
        if (item.contains("kind"))
        {
            const std::string kind = value<std::string>(item["kind"], kw + ".kind", "a text");
            const std::optional<RegionKind> k = parseRegionKind(kind);
            if (!k || *k == RegionKind::Closure || *k == RegionKind::Ice)
                throw Error(where + ": kind must be island, land or restricted area, got '" + kind + "'");
            o.kind = *k;
        }
        m.forbidden.obstacles.push_back(std::move(o));
    }
}

/// The current of an analytic flow by its registry name, its parameters checked against the registry.
void setAnalytic(MissionSpec &m, const std::string &type, const std::map<std::string, double> &parameters)
{
    const CurrentFieldKind *kind = findCurrentFieldKind(type);
    std::string names;
    for (const CurrentFieldKind &k : currentFieldKinds())
        if (!k.gridded())
            names += (names.empty() ? "" : ", ") + k.name;
    if (!kind || kind->gridded())
        throw Error("analytic field: unknown flow '" + type + "' (expected one of " + names + ")");
    for (const auto &[name, value] : parameters)
    {
        if (!hasParameter(*kind, name))
            throw Error("analytic field '" + type + "': unknown parameter '" + name + "' (expected " +
                        parameterNameList(*kind) + ")");
        checkFinite(name, value, false);
    }
    if (m.current.isForecast())
        throw Error("analytic field: the mission plans on a NetCDF forecast");
    m.current.type = type;
    m.current.parameters = parameters;
    m.current.members.clear();
    m.marks["current"] = keyword("field");
}

/// How the Python module names the mission's settings in messages (MissionSpec::term()): its keywords.
std::shared_ptr<const SettingWords> keywordWords()
{
    static const auto words = std::make_shared<const SettingWords>(
        SettingWords{{{"planner.name", "planner="},
                      {"planner.grid_size", "grid_size="},
                      {"planner.sectors", "sectors="},
                      {"planner.time_limit", "time_limit="},
                      {"planner.horizon", "horizon="},
                      {"vehicle.speed", "speed="},
                      {"vehicle.depth", "Field.netcdf(depth=)"},
                      {"departure.time", "departure="},
                      {"start", "start="},
                      {"observations", "observations="},
                      {"observations.cache", "observations_cache="},
                      {"goal", "goal="},
                      {"region", "region="},
                      {"current.file", "Field.netcdf()"},
                      {"current.horizon: hold_last", "Field.netcdf(horizon='hold')"},
                      {"current.zero_velocity_land: false", "zero_velocity_land=False"},
                      {"current.depth_average", "depth_average="},
                      {"current.variables.angle", "variables={'angle': ...}"},
                      {"current.variables.angle: none", "variables={'angle': 'none'}"},
                      {"current.variables.mask", "variables={'mask': ...}"},
                      {"forbidden.coastline", "coastline="},
                      {"safety.keep_off", "keep_off="},
                      {"observations.length_scale", "correction_length="},
                      {"observations.time_scale", "correction_time="},
                      {"observations.error_ratio", "error_ratio="},
                      {"observations.learn", "learn="},
                      {"safety.min_depth", "min_depth="},
                      {"safety.bathymetry", "bathymetry="},
                      {"safety.bathymetry_variable", "bathymetry_variable="},
                      {"safety.snap_to_water: true", "snap_to_water=True"},
                      {"execution.truth", "truth="},
                      {"execution.surfacing_interval", "surfacing_interval="},
                      {"execution.strategies", "strategies="},
                      {"execution.radius", "radius="}},
                     // a value given: by its keyword (of plan(), or of Field.netcdf() for the forecast's reading)
                     {{"start", "plan(): keyword 'start'"},
                      {"observations", "plan(): keyword 'observations'"},
                      {"goal", "plan(): keyword 'goal'"},
                      {"region", "plan(): keyword 'region'"},
                      {"departure.time", "plan(): keyword 'departure'"},
                      {"vehicle.speed", "plan(): keyword 'speed'"},
                      {"vehicle.depth", "Field.netcdf(): keyword 'depth'"},
                      {"current.file", "Field.netcdf(): path"},
                      {"current.variables.u", "Field.netcdf(): keyword 'variables' (u)"},
                      {"current.variables.v", "Field.netcdf(): keyword 'variables' (v)"},
                      {"current.variables.lon", "Field.netcdf(): keyword 'variables' (lon)"},
                      {"current.variables.lat", "Field.netcdf(): keyword 'variables' (lat)"},
                      {"current.variables.depth", "Field.netcdf(): keyword 'variables' (depth)"},
                      {"current.variables.time", "Field.netcdf(): keyword 'variables' (time)"},
                      {"current.velocity_units", "Field.netcdf(): keyword 'velocity_units'"},
                      {"current.max_speed", "Field.netcdf(): keyword 'max_speed'"},
                      {"current.time_units", "Field.netcdf(): keyword 'time_units'"},
                      {"current.steady_record", "Field.netcdf(): keyword 'steady_record'"},
                      {"current.zero_velocity_land", "Field.netcdf(): keyword 'zero_velocity_land'"}},
                     Origin::Keyword});
    return words;
}

/// The keywords of plan() with a unit (isochrone_interval, surfacing_interval, keep_off, min_depth), the other
/// safety keywords (bathymetry, bathymetry_variable, snap_to_water) and the execution keywords: truth ("forecast",
/// forecast files, or {parameter: number} of the analytic flow), surfacing_interval (with the quantities), strategies
/// (a list of names), radius, execution_pairs, execution_seed.
template <class Get, class Text>
void applySafetyAndExecutionKeywords(const Get &get, const Text &text, MissionOverrides &o)
{
    // a number in the mission's unit, or a text with its unit ("6 h", "2 km"): as the command line reads it
    const auto quantity = [&](const char *name, const char *expected) {
        const py::object v = *get(name);
        if (py::isinstance<py::str>(v))
            return Given<std::string>{v.cast<std::string>(), text(name)};
        char digits[40]; // 17 digits: the same double back
        std::snprintf(digits, sizeof digits, "%.17g", value<double>(v, name, expected));
        return Given<std::string>{digits, text(name)};
    };
    for (const auto &[name, target, expected] :
         {std::make_tuple("isochrone_interval", &o.isochroneInterval, "a number or a duration ('6 h')"),
          std::make_tuple("surfacing_interval", &o.surfacingInterval, "a number or a duration ('1 h')"),
          std::make_tuple("keep_off", &o.keepOff, "a number or a length ('2 km')"),
          std::make_tuple("hold_tolerance", &o.holdTolerance, "a number of metres or a length ('500 m')"),
          std::make_tuple("min_depth", &o.minDepth, "a number of metres or a length ('50 m')"),
          std::make_tuple("correction_length", &o.correctionLength, "a number or a length ('20 km')"),
          std::make_tuple("correction_time", &o.correctionTime, "a number or a duration ('1 d')"),
          std::make_tuple("reach_horizon", &o.reachHorizon, "a number or a duration ('10 d')"),
          std::make_tuple("reach_interval", &o.reachInterval, "a number or a duration ('1 d')"),
          std::make_tuple("reach_resolution", &o.reachResolution, "a number or a length ('2 km')")})
        if (get(name))
            *target = quantity(name, expected);
    for (const auto &[name, target] :
         {std::make_pair("bathymetry", &o.bathymetry), std::make_pair("bathymetry_variable", &o.bathymetryVariable)})
        if (auto v = get(name))
            *target = Given<std::string>{value<std::string>(*v, name, "a text"), text(name)};
    if (auto v = get("snap_to_water"))
        o.snapToWater = Given<bool>{value<bool>(*v, "snap_to_water", "True or False"), text("snap_to_water")};
    if (auto v = get("error_ratio"))
        o.errorRatio = Given<double>{value<double>(*v, "error_ratio", "a number > 0"), text("error_ratio")};
    if (auto v = get("learn"))
        o.learn = Given<bool>{value<bool>(*v, "learn", "True or False"), text("learn")};
    if (auto v = get("truth"))
    {
        std::string truth;
        if (py::isinstance<py::dict>(*v))
            for (const auto &[name, x] : value<std::map<std::string, double>>(*v, "truth", "a dict of numbers"))
            {
                char digits[40];
                std::snprintf(digits, sizeof digits, "%.17g", x);
                truth += (truth.empty() ? "" : ",") + name + "=" + digits;
            }
        else if (py::isinstance<py::list>(*v) || py::isinstance<py::tuple>(*v))
            for (const std::string &file : value<std::vector<std::string>>(*v, "truth", "a list of file names"))
                truth += (truth.empty() ? "" : ",") + file;
        else
            truth = value<std::string>(*v, "truth", "'forecast', forecast files or a dict of the flow's parameters");
        o.truth = Given<std::string>{truth, text("truth")};
    }
    if (auto v = get("strategies"))
        o.strategies = Given<std::vector<std::string>>{
            value<std::vector<std::string>>(*v, "strategies", "a list of strategy names"), text("strategies")};
    if (auto v = get("radius"))
        o.radius = Given<double>{value<double>(*v, "radius", "a number"), text("radius")};
    if (auto v = get("across_runs"))
        o.acrossRuns =
            Given<std::string>{value<std::string>(*v, "across_runs", "'carry' or 'reset'"), text("across_runs")};
    for (const auto &[name, target] :
         {std::make_pair("execution_pairs", &o.executionPairs), std::make_pair("execution_seed", &o.executionSeed)})
        if (auto v = get(name))
            *target = Given<long long>{value<long long>(*v, name, "an integer"), text(name)};
}

/// The keyword arguments plan() takes.
const std::set<std::string> &planKeywords()
{
    static const std::set<std::string> known = {
        // the planner
        "planner", "planner_params", "grid_size", "sectors", "time_limit", "smoothing", "refinement", "speed",
        "horizon", "goal_tolerance", "global_check", "isochrones", "isochrone_interval", "analytic",
        // the route
        "departure", "start", "goal", "region", "arrive_between", "via", "order", "goto_turn", "hold_tolerance",
        // land, depth and the observations
        "forbidden", "coastline", "keep_off", "min_depth", "bathymetry", "bathymetry_variable", "snap_to_water",
        "observations", "observations_cache", "correction_length", "correction_time", "error_ratio", "learn",
        // the execution and the reachability
        "truth", "surfacing_interval", "strategies", "radius", "execution_pairs", "execution_seed", "across_runs",
        "reachability", "reach_horizon", "reach_interval", "reach_resolution"};
    return known;
}

/// The keywords of plan() that place the route: departure, start, goal, region, arrive_between and via (each via
/// point read against the mission @p m's units).
template <class Get, class Text>
void applyRouteKeywords(const Get &get, const Text &text, const MissionSpec &m, MissionOverrides &o)
{
    if (auto v = get("departure"))
    {
        if (const std::string why = badNumber(*v); !why.empty() || py::str(*v).cast<std::string>().empty())
            throw Error("plan(): keyword 'departure': expected a number or an ISO 8601 date, got " + describe(*v) +
                        (why.empty() ? std::string() : " (" + why + ")"));
        o.departure = Given<std::string>{py::str(*v).cast<std::string>(), text("departure")};
    }
    for (const auto &[name, target] : {std::make_pair("start", &o.start), std::make_pair("goal", &o.goal)})
        if (auto v = get(name))
        {
            const Pair p = value<Pair>(*v, name, "a pair (x, y) or (lon, lat) of numbers");
            *target = Given<Point2>{{p.first, p.second}, text(name)};
        }
    if (auto v = get("region"))
    {
        const auto [a, b, c, d] = value<Quad>(*v, "region", "four numbers (x_min, y_min, x_max, y_max)");
        o.region = Given<std::array<double, 4>>{{a, b, c, d}, text("region")};
    }
    if (auto v = get("arrive_between"))
    {
        const auto [begin, end] =
            value<std::pair<py::object, py::object>>(*v, "arrive_between", "a pair (begin, end) of times");
        o.arrivalWindow = Given<std::pair<std::string, std::string>>{
            {py::str(begin).cast<std::string>(), py::str(end).cast<std::string>()}, text("arrive_between")};
    }
    if (auto v = get("via"))
    {
        // each via point a pair (x, y) / (lon, lat), or a dict {at: pair, name, radius, stay, arrive: (begin, end)}
        std::vector<ViaPointSpec> via;
        std::size_t k = 0;
        for (const py::handle item : value<py::list>(*v, "via", "a list of via points"))
        {
            const std::string at = "via[" + std::to_string(k++) + "]";
            via.push_back(viaPoint(item, at, m));
        }
        o.via = Given<std::vector<ViaPointSpec>>{via, text("via")};
    }
}

/// The keyword arguments of plan(), applied as glider_plan applies its flags (applySettings()).
MissionSpec withKeywords(MissionSpec m, const py::kwargs &kw)
{
    auto get = [&kw](const char *name) -> std::optional<py::object> {
        if (kw.contains(name) && !kw[name].is_none())
            return py::reinterpret_borrow<py::object>(kw[name]);
        return std::nullopt;
    };
    for (const auto &item : kw)
        if (const std::string name = item.first.cast<std::string>(); !planKeywords().count(name))
            throw Error("plan(): unknown keyword '" + name + "'");
    if (auto v = get("analytic"))
    {
        const auto [type, params] =
            value<std::pair<std::string, std::map<std::string, double>>>(*v, "field", "(name, {parameter: number})");
        setAnalytic(m, type, params);
    }
    // the keywords the command line shares as flags: the library's typed overrides, each named by its keyword
    MissionOverrides o;
    o.origin = Origin::Keyword;
    o.words = keywordWords();
    auto text = [](const std::string &name) { return "plan(): keyword '" + name + "'"; };
    if (auto v = get("planner"))
        o.planner = Given<std::string>{value<std::string>(*v, "planner", "a planner name"), text("planner")};
    if (auto v = get("planner_params"))
        o.plannerParameters = Given<std::map<std::string, std::string>>{
            value<std::map<std::string, std::string>>(*v, "planner_params", "a dict of parameter names to values"),
            text("planner_params")};
    for (const auto &[name, target] :
         {std::make_pair("grid_size", &o.gridSize), std::make_pair("time_limit", &o.timeLimit),
          std::make_pair("horizon", &o.horizon), std::make_pair("goal_tolerance", &o.goalTolerance),
          std::make_pair("speed", &o.speed), std::make_pair("goto_turn", &o.gotoTurn)})
        if (auto v = get(name))
            *target = Given<double>{value<double>(*v, name, "a number"), text(name)};
    if (auto v = get("sectors"))
        o.sectors = Given<int>{value<int>(*v, "sectors", "an integer 1..5"), text("sectors")};
    for (const auto &[name, target] :
         {std::make_pair("smoothing", &o.smoothing), std::make_pair("refinement", &o.refinement),
          std::make_pair("global_check", &o.globalCheck), std::make_pair("isochrones", &o.isochrones),
          std::make_pair("reachability", &o.reachability)})
        if (auto v = get(name))
            *target = Given<bool>{value<bool>(*v, name, "True or False"), text(name)};
    applyRouteKeywords(get, text, m, o);
    if (auto v = get("order"))
        o.order = Given<std::string>{value<std::string>(*v, "order", "'given' or 'free'"), text("order")};
    if (auto v = get("observations"))
        o.observations = Given<std::string>{value<std::string>(*v, "observations", "a file, a folder, a glob or a URL"),
                                            text("observations")};
    if (auto v = get("observations_cache"))
        o.observationsCache =
            Given<std::string>{value<std::string>(*v, "observations_cache", "a folder"), text("observations_cache")};
    if (auto v = get("coastline"))
        o.coastline = Given<std::string>{value<std::string>(*v, "coastline", "a file name"), text("coastline")};
    applySafetyAndExecutionKeywords(get, text, o);
    applyOverrides(o, m);
    if (auto v = get("forbidden"))
    {
        std::size_t k = 0;
        for (const py::handle item : value<py::list>(*v, "forbidden", "a list of polygons"))
            addForbidden(m, value<py::dict>(item, "forbidden", "a polygon as a dict with points"), k++);
    }
    return m;
}
} // namespace

void bindMission(py::module_ &m)
{
    py::class_<MissionSpec>(m, "Mission", "A mission (MissionSpec): what plan() plans.")
        .def_readonly("name", &MissionSpec::name)
        .def_property_readonly("planner", [](const MissionSpec &s) { return s.planner.name; })
        .def_property_readonly("speed", [](const MissionSpec &s) { return s.vehicle.speed; })
        .def_property_readonly("is_forecast", [](const MissionSpec &s) { return s.current.isForecast(); })
        .def_property_readonly("geographic", [](const MissionSpec &s) { return s.start.geographic; })
        .def("with_keywords", &withKeywords, "The mission with plan()'s keyword arguments applied.")
        .def("fields", &overridableFields,
             "The fields plan()'s keywords (and glider_plan's flags) can change, as text, and the fields given: "
             "overridableFields(), as glider_plan --show-mission prints them.")
        .def_property_readonly("fleet_size", [](const MissionSpec &s) { return s.fleet.size(); })
        .def("fleet_glider", &fleetGliderMission, py::arg("i"),
             "The mission of glider i of the fleet (fleetGliderMission(): as glider_plan plans it).");
    m.def("builtin_mission", &defaultGulfStreamMission, "The built-in Gulf Stream mission (as glider_plan).");
    // (read with the GIL released: a mission's forecast files are asked for their time axis)
    m.def("load_mission", &loadMission, py::arg("path"), py::call_guard<py::gil_scoped_release>(),
          "A YAML mission file (examples/MISSION_FORMAT.md).");
    m.def("parse_mission", &parseMission, py::arg("text"), py::arg("file") = "<mission>", py::arg("directory") = ".",
          py::call_guard<py::gil_scoped_release>(), "A mission from YAML (or JSON) text.");
    m.def("forecast_mission", &forecast, py::arg("files"), py::arg("start"), py::arg("goal"), py::arg("departure") = "",
          py::arg("speed") = py::none(), py::arg("depth") = 0.0, py::arg("region") = py::none(),
          py::arg("variables") = std::map<std::string, std::string>{}, py::arg("xy_interpolation") = "bilinear",
          py::arg("depth_interpolation") = "linear", py::arg("time_interpolation") = "linear",
          py::arg("horizon") = "refuse", py::arg("velocity_units") = "", py::arg("time_units") = "",
          py::arg("steady_record") = py::none(), py::arg("zero_velocity_land") = true,
          py::arg("depth_average") = py::none(), py::arg("snap_to_water") = false, py::arg("observations") = "",
          py::arg("kind") = "netcdf", py::arg("observations_cache") = "", py::arg("max_speed") = "",
          py::arg("runs") = false, py::arg("run_delay") = "",
          "The mission of a gridded forecast, as glider_plan --currents builds it (start None: at the last fix of "
          "`observations`, and its time without a departure, marked so until the mission resumes there; speed None: "
          "the forecast mission's default), read by the gridded source `kind` "
          "names (gridded, its alias netcdf, or a registered gridded kind), which the mission keeps as named.");
    m.def("is_gridded_kind", &isGriddedKind, py::arg("kind"),
          "True when the registry reads the current kind `kind` (a name or an alias) from files through a gridded "
          "source (CurrentFieldRegistry.h: isGriddedKind()).");
    m.def("planner_names", []() {
        std::vector<std::string> names;
        for (const PlannerEntry &e : plannerRegistry())
            names.push_back(e.name);
        return names;
    });
    m.def("analytic_fields", []() {
        std::map<std::string, std::map<std::string, double>> out;
        for (const CurrentFieldKind &k : currentFieldKinds())
            if (!k.gridded())
                out[k.name] = std::map<std::string, double>(k.parameters.begin(), k.parameters.end());
        return out;
    });
}
} // namespace ompl_glider_py

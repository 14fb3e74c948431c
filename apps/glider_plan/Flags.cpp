// glider_plan's command line: flags, their checks, and the MissionSpec of the built-in and --currents modes.
#include "Flags.h"
#include "ompl_glider/planners/Sectors.h"

#include <cstdio>
#include <algorithm>
#include <cctype>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/GeoBox.h"
#include "ompl_glider/current/NetCdfCurrents.h"
#include "ompl_glider/current/UnitConversion.h"
#include "ompl_glider/execution/Execution.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/registry/PlannerRegistry.h"

namespace glider_plan
{
using namespace ompl_glider;

namespace
{
/// The whole of @p text as a finite number, or nullopt.
std::optional<double> finiteNumber(const std::string &text)
{
    std::size_t used = 0;
    double v = 0.0;
    try
    {
        v = std::stod(text, &used);
    }
    catch (const std::exception &)
    {
        return std::nullopt;
    }
    if (used == 0 || used != text.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

double number(const std::string &flag, const std::string &text)
{
    const auto v = finiteNumber(text);
    if (!v)
        throw UsageError{flag + " expects a finite number, got '" + text + "'"};
    return *v;
}

Point2 pair(const std::string &flag, const std::string &text)
{
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos)
        throw UsageError{flag + " expects two numbers separated by a comma (x,y or lon,lat), got '" + text + "'"};
    return {number(flag, text.substr(0, comma)), number(flag, text.substr(comma + 1))};
}

/// The comma-separated items of a flag's value, empty ones included ("a,,b" -> a, "", b).
std::vector<std::string> commaItems(const std::string &text)
{
    std::vector<std::string> items;
    std::size_t at = 0;
    while (at <= text.size())
    {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        items.push_back(text.substr(at, comma - at));
        at = comma + 1;
    }
    return items;
}

/// Four numbers separated by commas (--region), in GeoJSON bbox order: x_min,y_min,x_max,y_max (for a geographic
/// file lon_min,lat_min,lon_max,lat_max), as given (ForecastMission checks them).
Box quad(const std::string &flag, const std::string &text)
{
    std::array<double, 4> v{};
    std::size_t at = 0;
    for (std::size_t k = 0; k < 4; ++k)
    {
        const std::size_t comma = k < 3 ? text.find(',', at) : text.size();
        if (comma == std::string::npos || (k == 3 && text.find(',', at) != std::string::npos))
            throw UsageError{flag + " expects four numbers lon_min,lat_min,lon_max,lat_max separated by commas " +
                             "(write " + flag + "=-60,30,-40,45 when the first is negative), got '" + text + "'"};
        v[k] = number(flag, text.substr(at, comma - at));
        at = comma + 1;
    }
    return {v[0], v[2], v[1], v[3]};
}

/// A finite number > 0, not denormal (CLI11's PositiveNumber lets "nan" and "inf" through; 1e-310 overflows
/// every division).
const CLI::Validator kPositiveFinite(
    [](std::string &text) {
        const auto v = finiteNumber(text);
        return v && *v > 0.0 && std::isnormal(*v)
                   ? std::string()
                   : "expected a finite number > 0 (at least 2.2e-308), got '" + text + "'";
    },
    "POSITIVE");

const std::vector<std::string> kSchemes2D = {"nearest", "bilinear", "bicubic"};
const std::vector<std::string> kSchemes1D = {"nearest", "linear", "cubic", "akima"};

/// The execution flags (--truth, --surfacing-interval, --strategies, --radius, --execution-pairs/-seed).
void applyExecution(const Flags &f, MissionSpec &m)
{
    ExecutionSpec &e = m.execution;
    if (f.truth.empty() && f.surfacingInterval.empty() && f.strategies.empty() && !f.radius && !f.executionPairs &&
        !f.executionSeed)
        return;  // a mission file's execution section stays as it is
    e.enabled = true;
    e.mark = SourceMark{"--truth", 0};
    if (!f.truth.empty() && f.truth != "forecast")
    {
        CurrentSpec t = m.current;
        t.mark = SourceMark{"--truth", 0};
        if (m.current.isForecast())
        {
            // another forecast file (or list / glob) read with the forecast's variable names and options
            std::vector<std::string> files;
            try
            {
                files = ompl_glider::forecastFileList(f.truth);
            }
            catch (const ompl_glider::Error &err)
            {
                throw UsageError{"--truth " + f.truth + ": " + err.what()};
            }
            t.file = files.front();
            t.files = files.size() > 1 ? files : std::vector<std::string>{};
        }
        else
        {
            // the built-in flow with other parameters: NAME=VALUE,... (e.g. B0=1.3,c=0.14)
            const CurrentFieldKind *kind = findCurrentFieldKind(m.current.type);
            for (const std::string &item : commaItems(f.truth))
            {
                const std::size_t eq = item.find('=');
                bool known = false;
                if (eq != std::string::npos && kind)
                    for (const auto &[name, value] : kind->parameters)
                        known = known || name == item.substr(0, eq);
                if (!known)
                {
                    std::string names;
                    if (kind)
                        for (const auto &[name, value] : kind->parameters)
                            names += (names.empty() ? "" : ", ") + name;
                    throw UsageError{"--truth: expected 'forecast' or NAME=VALUE,... with the " + m.current.type +
                                     "'s parameters (" + names + "), got '" + item + "'"};
                }
                t.parameters[item.substr(0, eq)] = number("--truth", item.substr(eq + 1));
            }
        }
        e.truth = t;
    }
    if (!f.surfacingInterval.empty())
    {
        try
        {
            e.surfacingInterval =
                parseDuration(f.surfacingInterval, m.timeUnitSeconds, m.hasTimeUnit());
        }
        catch (const ompl_glider::Error &err)
        {
            throw UsageError{std::string("--surfacing-interval: ") + err.what()};
        }
        m.marks["execution.surfacing_interval"] = SourceMark{"--surfacing-interval", 0};
    }
    if (!f.strategies.empty())
    {
        e.strategies.clear();
        for (const std::string &name : commaItems(f.strategies))
        {
            if (!parseControlStrategy(name))
                throw UsageError{"--strategies: unknown strategy '" + name +
                                 "' (expected a comma-separated list of current_sensitive, current_blind, greedy, "
                                 "replan)"};
            if (std::find(e.strategies.begin(), e.strategies.end(), name) != e.strategies.end())
                throw UsageError{"--strategies: '" + name + "' is listed twice"};
            e.strategies.push_back(name);
        }
    }
    if (f.radius)
        e.radius = *f.radius;
    if (f.executionPairs)
        e.pairs = *f.executionPairs;
    if (f.executionSeed)
        e.seed = *f.executionSeed;
}

/// --arrive-between t1,t2: the goal's arrival window, each time read as the mission reads its departure (a number
/// in field units, or a date with the forecast's calendar or the mission's epoch).
void applyArrivalWindow(const Flags &f, MissionSpec &m)
{
    if (f.arriveBetween.empty())
        return;
    const std::vector<std::string> items = commaItems(f.arriveBetween);
    if (items.size() != 2 || items[0].empty() || items[1].empty())
        throw UsageError{"--arrive-between expects two times separated by a comma, begin,end (numbers in the "
                         "mission's time unit, or ISO 8601 dates with --currents), got '" + f.arriveBetween + "'"};
    double t[2];
    for (int k = 0; k < 2; ++k)
    {
        try
        {
            t[k] = m.timeOf(items[k]);
        }
        catch (const ompl_glider::Error &e)
        {
            throw UsageError{std::string("--arrive-between: ") + (k == 0 ? "begin" : "end") + ": " + e.what()};
        }
    }
    if (!(t[1] >= t[0]))
        throw UsageError{"--arrive-between: the end (" + items[1] + ") must not be before the begin (" + items[0] +
                         ")"};
    if (const PlannerEntry *planner = findPlanner(m.planner.name); planner && planner->stints())
        throw UsageError{"--arrive-between: the stint planner '" + m.planner.name +
                         "' flies fixed stints and cannot time its arrival"};
    m.goalWindow = {true, t[0], t[1]};
    for (const char *key : {"goal.window", "goal.window.begin", "goal.window.end"})
        m.marks[key] = SourceMark{"--arrive-between", 0};
}

/// The settings common to every mode: a flag given replaces the mission's field (of the built-in mission, the
/// --currents forecast's or the mission file's).
void applySettings(const Flags &f, MissionSpec &m)
{
    // checks after loading name the flag that gave the value (MissionSpec::place)
    const std::pair<bool, const char *> given[] = {{!f.planner.empty(), "planner.name=--planner"},
                                                   {f.gridSize.has_value(), "planner.grid_size=--grid-size"},
                                                   {f.sectors.has_value(), "planner.sectors=--sectors"},
                                                   {f.timeLimit.has_value(), "planner.time_limit=--time-limit"},
                                                   {f.speed.has_value(), "vehicle.speed=--speed"},
                                                   {!f.departure.empty(), "departure.time=--departure"},
                                                   {!f.start.empty(), "start=--start"},
                                                   {!f.goal.empty(), "goal=--goal"},
                                                   {!f.region.empty(), "region=--region"}};
    for (const auto &[set, pair] : given)
        if (set)
        {
            const std::string text = pair;
            const std::size_t eq = text.find('=');
            m.marks[text.substr(0, eq)] = SourceMark{text.substr(eq + 1), 0};
        }
    if (!f.planner.empty())
        m.planner.name = findPlanner(f.planner)->name;
    if (f.gridSize)
        m.planner.gridSize = *f.gridSize;
    if (f.sectors)
        m.planner.sectors = *f.sectors;
    if (f.timeLimit)
        m.planner.timeLimit = *f.timeLimit;
    if (f.noSmooth)
        m.planner.smoothing = false;
    if (f.noRefine)
        m.planner.refinement = false;
    if (f.noGlobalCheck)
        m.planner.globalCheck = false;
    if (f.speed)
        m.vehicle.speed = m.travel.speed = *f.speed;
    if (!f.out.empty() || f.mission.empty())  // a mission file keeps its outputs.directory unless --out is given
        m.outputs.directory = f.out;
    applyExecution(f, m);
    applyArrivalWindow(f, m);
    if (!f.coastline.empty())
    {
        m.forbidden.coastline = f.coastline;
        m.forbidden.coastlineMark = SourceMark{"--coastline", 0};
    }
}
}  // namespace

void applyOutputFlags(const Flags &f, MissionSpec &m)
{
    if (!f.isochroneInterval.empty())
    {
        try
        {
            m.outputs.isochroneInterval = parseDuration(f.isochroneInterval, m.timeUnitSeconds, m.hasTimeUnit());
        }
        catch (const ompl_glider::Error &err)
        {
            throw UsageError{std::string("--isochrone-interval: ") + err.what()};
        }
        if (!(m.outputs.isochroneInterval > 0.0))
            throw UsageError{"--isochrone-interval: must be > 0, got '" + f.isochroneInterval + "'"};
        m.marks["outputs.isochrone_interval"] = SourceMark{"--isochrone-interval", 0};
    }
    if (f.gotoTurn)
    {
        if (!(*f.gotoTurn >= 0.0 && *f.gotoTurn <= 180.0))
        {
            char got[32];
            std::snprintf(got, sizeof got, "%.10g", *f.gotoTurn);
            throw UsageError{std::string("--goto-turn: expected degrees in 0..180 (0: every waypoint), got ") + got};
        }
        m.outputs.gotoTurnDeg = *f.gotoTurn;
    }
    if ((f.isochrones || !f.isochroneInterval.empty()) &&
        !m.outputs.wants(OutputFormatId::Isochrones))
        m.outputs.files.push_back(OutputFormatId::Isochrones);
}

void applySafetyFlags(const Flags &f, MissionSpec &m)
{
    auto length = [](const char *flag, const std::string &text, double metresPerUnit, bool known) {
        try
        {
            return parseLength(text, metresPerUnit, known);
        }
        catch (const ompl_glider::Error &err)
        {
            throw UsageError{std::string(flag) + ": " + err.what()};
        }
    };
    if (!f.keepOff.empty())
    {
        m.safety.keepOff = length("--keep-off", f.keepOff, m.metresPerUnit(), m.physicalUnits().length);
        m.marks["safety.keep_off"] = SourceMark{"--keep-off", 0};
    }
    if (!f.minDepth.empty())
    {
        m.safety.minDepth = length("--min-depth", f.minDepth, 1.0, true);
        m.marks["safety.min_depth"] = SourceMark{"--min-depth", 0};
    }
    if (!f.bathymetry.empty())
    {
        m.safety.bathymetry = f.bathymetry;
        m.marks["safety.bathymetry"] = SourceMark{"--bathymetry", 0};
    }
    m.safety.bathymetryVariable = f.bathymetryVariable;
    if (f.snapToWater)
    {
        m.safety.snapToWater = true;
        m.marks["safety.snap_to_water"] = SourceMark{"--snap-to-water", 0};
    }
    if (!f.bathymetryVariable.empty() && f.bathymetry.empty() && !m.current.isForecast())
        throw UsageError{"--bathymetry-variable needs --bathymetry FILE"};
    if (!f.minDepth.empty() && f.bathymetry.empty() && !m.current.isForecast())
        throw UsageError{"--min-depth needs --bathymetry FILE (a NetCDF file of seafloor depth or elevation)"};
}

std::vector<double> speedList(const std::string &text)
{
    std::vector<double> v;
    for (const std::string &item : commaItems(text))
    {
        const double x = number("--speeds", item);
        if (!(x > 0.0))
            throw UsageError{"--speeds: every speed must be > 0, got " + item};
        v.push_back(x);
    }
    return v;
}

void defineFlags(CLI::App &app, Flags &f)
{
    auto *built = "Route and planner";
    app.add_option("--start", f.start, "start x,y (built-in default 1,-3); lon,lat with --currents (write "
                                       "--start=-52.7,47.9 for a negative first value)")
        ->group(built);
    app.add_option("--goal", f.goal, "goal x,y (built-in default 8,3); lon,lat with --currents")->group(built);
    app.add_option("--departure", f.departure,
                   "departure: a time (built-in, default 0); with --currents an ISO 8601 date "
                   "(2026-03-15T06:00:00Z) or seconds after the first forecast time (default: the first)")
        ->group(built);
    app.add_option("--arrive-between", f.arriveBetween,
                   "arrive at the goal within begin,end (built-in: times; --currents: ISO 8601 dates or seconds after "
                   "the first forecast time): arrive early and hold at the goal where the current allows, else time "
                   "the arrival (a hold or a slower leg earlier on the path)")
        ->group(built);
    app.add_option("--speed", f.speed, "speed through water (built-in 0.5; --currents m/s, default 0.3)")
        ->check(kPositiveFinite)
        ->group(built);
    app.add_option("--speeds", f.speeds, "speed sweep, e.g. 0.25,0.30,0.35: travel time and path length per speed")
        ->group(built);
    app.add_option("--planner", f.planner, "planner: " + plannerNameList(" | ") + " (default ZA*TVE)")
        ->check([](const std::string &name) {
            return findPlanner(name) ? std::string() : "unknown planner '" + name + "' (" + plannerNameList() + ")";
        })
        ->group(built);
    app.add_option("--grid-size", f.gridSize,
                   "lattice spacing (analytic flows: 0.4, kept within 1/200..1/25 of the start-goal distance; the "
                   "built-in trip 0.4; --currents metres, default half the smallest grid cell, within the same "
                   "bounds)")
        ->check(kPositiveFinite)
        ->group(built);
    app.add_option("--sectors", f.sectors, "lattice connectivity 1..5 (default 3)")
        ->check(CLI::Range(kMinSectors, kMaxSectors))
        ->group(built);
    app.add_option("--time-limit", f.timeLimit,
                   "planner time limit in seconds, at most 1e6 (default: none for the lattice planners, 10 s for the "
                   "sampling planners, which use all of it)")
        ->check(CLI::Range(1e-3, 1e6))
        ->group(built);
    app.add_flag("--no-smooth", f.noSmooth, "skip path smoothing")->group(built);
    app.add_flag("--no-refine", f.noRefine, "skip waypoint refinement")->group(built);
    app.add_flag("--no-global-check", f.noGlobalCheck,
                 "skip the global check of the route class (extremals shot from the start after a lattice planner)")
        ->group(built);
    app.add_flag("--optimum", f.optimum,
                 "also solve Zermelo's optimal-control problem by shooting (extremals that stay in the region's water "
                 "and out of forbidden regions) and compare")
        ->group(built);
    auto *io = "Input and output";
    app.add_option("--mission", f.mission, "run a YAML mission file (examples/MISSION_FORMAT.md); the other flags "
                                           "(not --currents and its options) override its fields")
        ->group(io);
    app.add_option("--currents", f.currents,
                   "plan on the u/v currents of a NetCDF forecast: a file, or several read as one forecast (a "
                   "comma-separated list of files and glob patterns, e.g. 'hycom_202603*.nc'; ordered by their "
                   "dates, the later file wins where two overlap)")
        ->group(io);
    app.add_option("--out", f.out,
                   "write summary.json and the route files (waypoints.csv, path.csv, path.geojson, goto_l10.ma, "
                   "map.svg, map.png) into this directory; with --mission it replaces outputs.directory")
        ->group(io);
    app.add_option("--coastline", f.coastline,
                   "land polygons from a GIS file (GeoJSON, Shapefile, KML, GeoPackage; read with GDAL/OGR), "
                   "forbidden to the glider and drawn on the map")
        ->check(CLI::ExistingFile)
        ->group(io);
    auto *safe = "Safety margins";
    app.add_option("--keep-off", f.keepOff,
                   "keep this far from land (land cells, --coastline polygons, islands): e.g. '2km', '500m', or a "
                   "number in planning units; the closest approach to land is reported")
        ->group(safe);
    app.add_option("--bathymetry", f.bathymetry,
                   "NetCDF seafloor depth or elevation (GEBCO/ETOPO-style lon/lat grid, or a model's h on lon_rho/"
                   "lat_rho); with --min-depth, shallower water is forbidden")
        ->check(CLI::ExistingFile)
        ->group(safe);
    app.add_option("--bathymetry-variable", f.bathymetryVariable,
                   "the depth variable of --bathymetry (default: detected from standard_name and name)")
        ->group(safe);
    app.add_option("--min-depth", f.minDepth,
                   "forbid water shallower than this, e.g. '50m' (needs --bathymetry, or a forecast file with h)")
        ->group(safe);
    app.add_flag("--snap-to-water", f.snapToWater,
                 "a start or goal on the forecast's land is moved to the nearest water (the report says where); "
                 "without it such a start or goal is refused, naming the nearest water")
        ->group(safe);
    app.add_flag("--verbose", f.verbose, "show OMPL's log messages")->group(io);
    app.add_flag("--isochrones", f.isochrones,
                 "also write isochrones.geojson: where the glider can be by times after the departure (level-set "
                 "reachable set), drawn on the map too")
        ->group(io);
    app.add_option("--goto-turn", f.gotoTurn,
                   "the goto list names a waypoint where the course turns by more than this many degrees, or where "
                   "leaving it out strays from the route or crosses land (default 10; 0: every waypoint)")
        ->group(io);
    app.add_option("--isochrone-interval", f.isochroneInterval,
                   "time between isochrones: a number in the mission's time unit, or e.g. '12 h' (default: eight up "
                   "to the arrival); implies --isochrones")
        ->group(io);
    auto *ex = "Execution in another ocean (any of these flies the plan; with --mission they override its execution "
               "section)";
    app.add_option("--truth", f.truth,
                   "the ocean the plan is flown in: 'forecast' (the planning field itself), with --currents another "
                   "NetCDF file (list or glob; same variable names), for the built-in flow its parameters changed, "
                   "e.g. B0=1.3,c=0.14")
        ->group(ex);
    app.add_option("--surfacing-interval", f.surfacingInterval,
                   "time between surfacings: a number in the mission's time unit, or e.g. '1 h', '30 min' (default "
                   "1 h; without a time unit a twentieth of the planned trip)")
        ->group(ex);
    app.add_option("--strategies", f.strategies,
                   "control strategies compared, e.g. current_sensitive,current_blind,greedy,replan (default: all)")
        ->group(ex);
    app.add_option("--radius", f.radius,
                   "the goal counts as reached within this distance (mission length unit; default 1 % of the "
                   "start-goal distance)")
        ->check(kPositiveFinite)
        ->group(ex);
    app.add_option("--execution-pairs", f.executionPairs,
                   "also fly this many random start/goal pairs of the region (a batch: box plot execution.png)")
        ->check(CLI::Range(0u, 100000u))
        ->group(ex);
    app.add_option("--execution-seed", f.executionSeed, "seed of the random pairs (default 1)")->group(ex);
    auto *nc = "NetCDF forecast (with --currents)";
    ForecastInput &fc = f.forecast;
    for (const char *role : {"u", "v", "lon", "lat", "depth", "time"})
        app.add_option_function<std::string>(
               std::string("--") + role + "-var", [&fc, role](const std::string &v) { fc.current.variables[role] = v; },
               std::string("name of the ") + role + " variable (found automatically when not given)")
            ->group(nc);
    app.add_option_function<std::string>(
           "--mask-var", [&fc](const std::string &v) { fc.current.variables["mask"] = v; },
           "land/sea mask variable (found automatically: flag_meanings, mask_rho, tmask, lsm, KMT...; 'none' for "
           "no mask)")
        ->group(nc);
    app.add_option_function<std::string>(
           "--angle-var", [&fc](const std::string &v) { fc.current.variables["angle"] = v; },
           "grid angle variable (radians or degrees, grid i direction to east) of velocities given along a rotated "
           "grid (found automatically: 'angle' on the velocities' grid, as ROMS and POP write it; 'none' for "
           "none)")
        ->group(nc);
    app.add_flag_function(
           "--no-zero-land", [&fc](std::int64_t) { fc.current.zeroVelocityLand = false; },
           "do not take nodes whose u and v are exactly 0 in every record of the trip for land (on by default: models "
           "such as POP store land as zero velocity)")
        ->group(nc);
    app.add_option_function<std::string>(
           "--xy-interp", [&fc](const std::string &v) { fc.current.xyInterpolation = parseInterp2D(v); },
           "nearest | bilinear (default) | bicubic")
        ->check(CLI::IsMember(kSchemes2D))
        ->group(nc);
    app.add_option_function<std::string>(
           "--time-interp", [&fc](const std::string &v) { fc.current.timeInterpolation = parseInterp1D(v); },
           "nearest | linear (default) | cubic | akima")
        ->check(CLI::IsMember(kSchemes1D))
        ->group(nc);
    app.add_option_function<std::string>(
           "--depth-interp", [&fc](const std::string &v) { fc.current.depthInterpolation = parseInterp1D(v); },
           "nearest | linear (default) | cubic | akima")
        ->check(CLI::IsMember(kSchemes1D))
        ->group(nc);
    app.add_option_function<std::string>(
           "--beyond", [&fc](const std::string &v) { fc.current.horizonPolicy = parseBeyondForecast(v); },
           "past the last forecast time: refuse (default) | hold (hold the last field)")
        ->check(CLI::IsMember({"refuse", "hold"}))
        ->group(nc);
    app.add_option("--region", f.region,
                   "region to load and plan in: lon_min,lat_min,lon_max,lat_max in either convention (-180..180 "
                   "or 0..360; lon_max < lon_min crosses the antimeridian, as a GeoJSON bbox), x_min,y_min,x_max,"
                   "y_max for a Cartesian file; write --region=-60,30,-40,45 for a negative first value (default: "
                   "the box of start and goal widened by half their distance, at least 25 km)")
        ->group(nc);
    app.add_option_function<std::string>(
           "--depth-average",
           [&fc](const std::string &v) {
               const Point2 p = pair("--depth-average", v);
               if (!(p.x >= 0.0 && p.x <= p.y && p.y <= 12000.0))
                   throw UsageError{"--depth-average expects top,bottom in metres with 0 <= top <= bottom <= 12000, "
                                    "got '" + v + "'"};
               fc.current.depthAverage = std::make_pair(p.x, p.y);
           },
           "plan on the current averaged over the glider's working depth, top,bottom in metres (e.g. 0,200)")
        ->group(nc);
    app.add_option("--depth", f.depth, "depth in metres, positive down, at which the current is read (default 0)")
        ->check(CLI::Range(0.0, 12000.0))
        ->group(nc);
    app.add_option("--velocity-units", fc.current.velocityUnits,
                   "units of u and v in place of the file's (any velocity UDUNITS-2 reads: \"m/s\", \"cm s-1\", "
                   "\"knots\", \"km/h\")")
        ->check(CLI::Validator(
            [](std::string &units) {
                try
                {
                    (void)velocityToMetresPerSecond(units);
                    return std::string();
                }
                catch (const Error &e)
                {
                    return std::string(e.what());
                }
            },
            "UNITS"))
        ->group(nc);
    app.add_option("--time-units", fc.current.timeUnits,
                   "units of the time variable in place of the file's, e.g. \"days since 2026-01-15\" (for a time "
                   "axis in \"month\", \"hours\" or without units)")
        ->check(CLI::Validator(
            [](std::string &units) {
                std::string lower = units;
                for (char &c : lower)
                    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
                return lower.find(" since ") != std::string::npos
                           ? std::string()
                           : "expected '<seconds|minutes|hours|days> since <date>', got '" + units + "'";
            },
            ""))
        ->group(nc);
    app.add_option_function<std::size_t>(
           "--steady-record", [&fc](std::size_t k) { fc.current.steadyRecord = k; },
           "plan on this time record only (0 the first), as a steady field")
        ->check(CLI::Range(std::size_t(0), std::size_t(1000000000)))
        ->group(nc);
    app.footer("Exit status: 0 path found, 1 no path (the reason is printed), 2 bad arguments or input (a message "
               "says what and where; nothing is written).");
}

/// Flags that --mission does not take: the forecast and its reading options are the mission's current section.
/// Every other flag overrides the mission file's field (missionFileOf()).
void checkCombinations(const CLI::App &app, const Flags &f)
{
    if (!f.mission.empty())
    {
        for (const CLI::Option *o : app.get_options())
        {
            const std::string name = o->get_name();
            if (o->count() > 0 && name != "--region" &&
                (name == "--currents" || o->get_group() == "NetCDF forecast (with --currents)"))
                throw UsageError{name + " cannot be combined with --mission: the mission file's current section "
                                        "names the forecast and how to read it (examples/MISSION_FORMAT.md)"};
        }
        return;
    }
    if (f.currents.empty())
        for (const CLI::Option *o : app.get_options())
            if (o->count() > 0 && o->get_group() == "NetCDF forecast (with --currents)")
                throw UsageError{o->get_name() + " needs --currents FILE"};
    if (!f.currents.empty() && (f.start.empty() || f.goal.empty()))
        throw UsageError{"--currents needs --start and --goal (lon,lat for a geographic file, x,y for a Cartesian "
                         "one)"};
}

void parseFlags(CLI::App &app, const Flags &f, int argc, const char *const *argv)
{
    app.parse(argc, argv);
    checkCombinations(app, f);
}

MissionSpec builtInMission(const Flags &f)
{
    MissionSpec m = defaultGulfStreamMission();
    if (!f.start.empty())
    {
        const Point2 p = pair("--start", f.start);
        m.start.xy = p;
    }
    if (!f.goal.empty())
    {
        const Point2 p = pair("--goal", f.goal);
        m.goal.xy = p;
    }
    if (!f.departure.empty())
        m.departure.time = number("--departure", f.departure);
    applySettings(f, m);
    return m;
}

MissionSpec missionFileOf(const Flags &f)
{
    MissionSpec m = loadMission(f.mission);
    for (auto [flag, text, point] : {std::make_tuple("--start", &f.start, &m.start),
                                     std::make_tuple("--goal", &f.goal, &m.goal)})
        if (!text->empty())
        {
            const Point2 p = pair(flag, *text);  // in the mission's terms: lon,lat where it gives lon/lat
            if (point->geographic)
                point->lonLat = {p.x, p.y};
            else
                point->xy = p;
        }
    if (!f.departure.empty())
    {
        try
        {
            m.departure.time = m.timeOf(f.departure);
        }
        catch (const ompl_glider::Error &e)
        {
            throw UsageError{std::string("--departure: ") + e.what()};
        }
        m.departure.window = false;  // one departure in place of the file's window
    }
    if (!f.region.empty())
    {
        const Box b = quad("--region", f.region);
        m.region.set = true;
        m.region.geographic = m.start.geographic;
        if (m.region.geographic)
            m.region.lonLat = geoBox(b.xMin, b.yMin, b.xMax, b.yMax);
        else if (!(b.xMax > b.xMin && b.yMax > b.yMin))
            throw UsageError{"--region expects x_min,y_min,x_max,y_max with x_max > x_min and y_max > y_min, got '" +
                             f.region + "'"};
        else
            m.region.xy = b;
    }
    if (!f.planner.empty() && findPlanner(f.planner)->name != m.planner.name)
    {
        m.planner.parameters.clear();  // the file's parameters are the other planner's
        m.planner.parameterMarks.clear();
    }
    applySettings(f, m);
    return m;
}

MissionSpec forecastMissionOf(Flags f)
{
    // one file, or several read as one forecast: a comma-separated list of files and glob patterns
    std::vector<std::string> files;
    try
    {
        files = ompl_glider::forecastFileList(f.currents);
    }
    catch (const ompl_glider::Error &e)
    {
        throw UsageError{"--currents " + f.currents + ": " + e.what()};
    }
    if (files.size() == 1)
        f.forecast.current.file = files.front();
    else
        f.forecast.current.files = files;
    f.forecast.start = pair("--start", f.start);
    f.forecast.goal = pair("--goal", f.goal);
    f.forecast.departure = f.departure;
    if (!f.region.empty())
        f.forecast.region = quad("--region", f.region);
    if (f.speed)
        f.forecast.speed = *f.speed;
    if (f.depth)
        f.forecast.depth = *f.depth;
    f.forecast.snapToWater = f.snapToWater;
    MissionSpec m = forecastMission(f.forecast);
    applySettings(f, m);
    return m;
}
}  // namespace glider_plan

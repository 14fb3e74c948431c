// glider_plan's command line: the flags and their checks (the missions they describe: FlagMissions.cpp).
#include "Flags.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "FlagText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/io/UnitConversion.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/registry/PlannerRegistry.h"

namespace glider_plan
{
using namespace ompl_glider;

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

namespace
{
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

/// The strategies an execution flies when none are listed (ExecutionSpec's): "current_sensitive,current_blind,...".
std::string defaultStrategies()
{
    std::string out;
    for (const std::string &s : ompl_glider::ExecutionSpec().strategies)
        out += (out.empty() ? "" : ",") + s;
    return out;
}

const std::vector<std::string> kSchemes2D = {"nearest", "bilinear", "bicubic"};
const std::vector<std::string> kSchemes1D = {"nearest", "linear", "cubic", "akima"};

/// The flags of the route and the planner.
void defineRouteFlags(CLI::App &app, Flags &f)
{
    auto *built = "Route and planner";
    app.add_option("--start", f.start,
                   "start x,y (built-in default 1,-3); lon,lat with --currents (write "
                   "--start=-52.7,47.9 for a negative first value)")
        ->group(built);
    app.add_option("--goal", f.goal, "goal x,y (built-in default 8,3); lon,lat with --currents")->group(built);
    app.add_option("--departure", f.departure,
                   "departure: a time (built-in, default 0); with --currents an ISO 8601 date "
                   "(2026-03-15T06:00:00Z) or seconds after the first forecast time (default: the first)")
        ->group(built);
    app.add_option("--via", f.via,
                   "via points between start and goal, 'x,y;x,y' (lon,lat with --currents or a geographic mission): "
                   "a mission of several legs, planned in turn on one clock (names WP1, WP2, ...; radii, windows and "
                   "stays in a mission file's waypoints list)")
        ->group(built);
    app.add_option("--order", f.order,
                   "given (default): visit the via points as listed; free: the fastest order of up to 8 via points "
                   "(branch and bound over the orders with the planned leg times)")
        ->group(built);
    app.add_option("--observations", f.observations,
                   "the glider's depth-averaged currents: IOOS glider profile NetCDF files, Slocum dba files or the "
                   "Slocum's binary files (sbd, tbd, dbd, ebd; compressed scd, tcd, dcd, ecd; their cache files "
                   "beside them or in cache/ beside them) (a file, folder or glob pattern), a CSV time,lon,lat,u,v, or "
                   "an ERDDAP tabledap URL (.csvp, .csv or "
                   ".ncCF of time,latitude,longitude,profile_id,time_uv,lat_uv,lon_uv,u,v,u_qc,v_qc); the forecast is "
                   "corrected by them (optimal interpolation) and, "
                   "without --start, the plan starts at the last fix (and at its time without --departure)")
        ->group(built);
    app.add_option("--observations-cache", f.observationsCache,
                   "the folder of a Slocum's cache files (<sensor_list_crc>.cac: the sensor lists its binary files "
                   "leave out), searched before the files' own folder and a cache/ folder beside them")
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
    // the range is checked once, in the library's overrides (Overrides.h), for the flag and Python's keyword alike
    app.add_option("--sectors", f.sectors, "lattice connectivity 1..5 (default 3)")->group(built);
    app.add_option("--time-limit", f.timeLimit,
                   "planner time limit in seconds, 0..1e6 (default and 0: none for the lattice planners, 10 s for the "
                   "sampling planners, which use all of it)")
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
}

/// The flags of input and output.
void defineIoFlags(CLI::App &app, Flags &f)
{
    auto *io = "Input and output";
    app.add_option("--mission", f.mission,
                   "run a YAML mission file (examples/MISSION_FORMAT.md); the other flags "
                   "(not --currents and its options) override its fields")
        ->group(io);
    app.add_option("--currents", f.currents,
                   "plan on the u/v currents of a forecast: a NetCDF file, or several read as one forecast (a "
                   "comma-separated list of files and glob patterns, e.g. 'hycom_202603*.nc'; ordered by their "
                   "dates, the later file wins where two overlap); a Zarr store (a folder, or a URL ending .zarr: "
                   "Copernicus Marine) or GRIB2 files (RTOFS, weather models' winds); an http(s):// URL is otherwise "
                   "an OPeNDAP dataset (HYCOM, THREDDS servers); only the trip's region, levels and records are read")
        ->group(io);
    app.add_option("--cache", f.cache,
                   "keep what is fetched from URLs in this folder (an OPeNDAP dataset's values as a NetCDF file, a "
                   "Zarr store's metadata and chunks as a folder, a GRIB file whole), so that a later plan over the "
                   "same window reads no network (remove a file or folder to fetch a newer forecast)")
        ->group(io);
    app.add_option("--request-timeout", f.requestTimeout,
                   "time limit of every request to a server (OPeNDAP, Zarr, GRIB over HTTP), seconds (default 60)")
        ->check(CLI::PositiveNumber)
        ->group(io);
    app.add_option("--retries", f.retries,
                   "further attempts after a request to an OPeNDAP server fails for the network or the server, 1 s, "
                   "2 s, ... apart (0..10, default 2)")
        ->check(CLI::Range(0, 10))
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
    app.add_flag("--verbose", f.verbose, "show OMPL's log messages")->group(io);
    app.add_flag("--show-observations", f.showObservations,
                 "print the fixes and DAC the planner reads from --observations (a table: time, lon, lat; u, v, the "
                 "dive's segment and depths), then exit without planning")
        ->group(io);
    app.add_flag("--show-mission", f.showMission,
                 "print the mission's fields that flags can change (planner, grid, speed, start, goal, departure, "
                 "region, ...) as the flags leave them, and the fields given, then exit without planning")
        ->group(io);
    app.add_flag("--isochrones", f.isochrones,
                 "also write isochrones.geojson: where the glider can be by times after the departure (level-set "
                 "reachable set), drawn on the map too")
        ->group(io);
    app.add_option("--goto-turn", f.gotoTurn,
                   "the goto list names a waypoint where the course turns by more than this many degrees, or where "
                   "leaving it out strays from the route or crosses land (default 10; 0: every waypoint)")
        ->group(io);
    app.add_option("--hold-tolerance", f.holdTolerance,
                   "the goto list and the targets file write a run of held headings as the fewest holds whose flight "
                   "passes every planned segment end within this distance: metres, or e.g. '0.5 km' (default 300; "
                   "0: every segment)")
        ->group(io);
    app.add_option("--isochrone-interval", f.isochroneInterval,
                   "time between isochrones: a number in the mission's time unit, or e.g. '12 h' (default: eight up "
                   "to the arrival); implies --isochrones")
        ->group(io);
    app.add_flag("--reachability", f.reachability,
                 "also write reachability.nc and reachability.geojson: the probability of reach by each time over "
                 "the ensemble's members (one level-set front per member; a single current is an ensemble of one), "
                 "the goal's arrival quantiles in summary.json, its contours on the maps")
        ->group(io);
    app.add_option("--reach-horizon", f.reachHorizon,
                   "how long after the departure the probability of reach runs: a number in the mission's time unit, "
                   "or e.g. '10 d' (default: 1.5 times the planned travel time); implies --reachability")
        ->group(io);
    app.add_option("--reach-interval", f.reachInterval,
                   "time between two frames of the probability of reach (default: the horizon / 10); implies "
                   "--reachability")
        ->group(io);
}

/// The flags of safety margins.
void defineSafetyFlags(CLI::App &app, Flags &f)
{
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
}

/// The flags of execution in another ocean.
void defineExecutionFlags(CLI::App &app, Flags &f)
{
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
    app.add_option(
           "--strategies", f.strategies,
           "control strategies compared, of current_sensitive, current_blind, greedy, replan, planned_headings (the "
           "plan's own held headings), dac (steer with the last dive's measured DAC) and replan_observed (replan on "
           "the forecast corrected by the DAC measured so far) (default: " +
               defaultStrategies() + ", and planned_headings first where the plan has held headings)")
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
    app.add_option("--across-runs", f.acrossRuns,
                   "with forecast runs: the DAC replan_observed learned before a new run, 'carry' (kept, compared with "
                   "the new run again; default) or 'reset' (dropped)")
        ->group(ex);
}

/// The flags of a forecast given as runs (with --currents): --runs, --run-delay.
void defineRunFlags(CLI::App &app, Flags &f)
{
    auto *nc = "Forecast files (with --currents)";
    ForecastInput &fc = f.forecast;
    CLI::Option *runs =
        app.add_flag("--runs", f.runs,
                     "the files of --currents are a forecast's runs, each file one run (reference time from CF "
                     "forecast_reference_time, else its first time): the plan is made on the newest run available at "
                     "the departure (default: when the first becomes available), and an execution replans as runs come")
            ->group(nc);
    app.add_option_function<std::string>(
           "--run-delay",
           [&fc](const std::string &v) {
               try
               {
                   fc.current.runDelay = parseDuration(v, 1.0, true);
               }
               catch (const Error &e)
               {
                   throw UsageError{"--run-delay " + v + ": " + e.what()};
               }
               if (!(fc.current.runDelay >= 0.0))
                   throw UsageError{"--run-delay " + v + ": expected a duration >= 0, such as '12 h'"};
           },
           "with --runs: how long after its reference time a run becomes available (default 12 h)")
        ->needs(runs)
        ->group(nc);
}

/// The flags of reading a forecast (with --currents): NetCDF, OPeNDAP, Zarr, GRIB.
void defineForecastFlags(CLI::App &app, Flags &f)
{
    auto *nc = "Forecast files (with --currents)";
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
                                    "got '" +
                                    v + "'"};
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
    app.add_option_function<std::string>(
           "--max-current-speed",
           [&fc](const std::string &v) {
               try
               {
                   fc.current.maxSpeed = parseSpeed(v);
               }
               catch (const Error &e)
               {
                   throw UsageError{"--max-current-speed: " + std::string(e.what())};
               }
           },
           "the fastest current believed in the forecast: m/s, or e.g. '600 m/s', '1000 kn' (default 300 m/s, where "
           "a few nodes continuous with the flow around them may be faster: beside a vortex's core)")
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
}

} // namespace

void defineFlags(CLI::App &app, Flags &f)
{
    defineRouteFlags(app, f);
    defineIoFlags(app, f);
    defineSafetyFlags(app, f);
    defineExecutionFlags(app, f);
    defineForecastFlags(app, f);
    defineRunFlags(app, f);
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
                (name == "--currents" || o->get_group() == "Forecast files (with --currents)"))
                throw UsageError{name + " cannot be combined with --mission: the mission file's current section "
                                        "names the forecast and how to read it (examples/MISSION_FORMAT.md)"};
        }
        return;
    }
    if (f.currents.empty())
        for (const CLI::Option *o : app.get_options())
            if (o->count() > 0 && o->get_group() == "Forecast files (with --currents)")
                throw UsageError{o->get_name() + " needs --currents FILE"};
    if (!f.currents.empty() && ((f.start.empty() && f.observations.empty()) || f.goal.empty()))
        throw UsageError{"--currents needs --start (or --observations: the last fix) and --goal (lon,lat for a "
                         "geographic file, x,y for a Cartesian one)"};
}

void parseFlags(CLI::App &app, const Flags &f, int argc, const char *const *argv)
{
    app.parse(argc, argv);
    checkCombinations(app, f);
    // how OPeNDAP URLs are fetched, set before any NetCDF access (NetCDF-C reads its time limit once)
    ompl_glider::RemoteAccess access;
    access.cacheDir = f.cache;
    if (f.requestTimeout)
        access.requestTimeout = *f.requestTimeout;
    if (f.retries)
        access.retries = *f.retries;
    try
    {
        ompl_glider::setRemoteAccess(access);
        ompl_glider::prepareRemoteAccess();
    }
    catch (const ompl_glider::Error &e)
    {
        throw UsageError{std::string("--request-timeout/--retries: ") + e.what()};
    }
}

} // namespace glider_plan

// glider_plan's flags applied to a mission: the overrides Python's keywords share (MissionOverrides, applied by the
// library's applyOverrides(): planner, place and time, via points, outputs, safety, execution), and the missions of
// the built-in, --mission and --currents modes.
#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "Flags.h"
#include "FlagText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/Overrides.h"

namespace glider_plan
{
using namespace ompl_glider;

namespace
{
/// A library refusal of a flag's value as the command line's (exit 2, with the hint to --help).
void applyOrRefuse(const MissionOverrides &o, MissionSpec &m)
{
    try
    {
        applyOverrides(o, m);
    }
    catch (const Error &e)
    {
        throw UsageError{e.what()};
    }
}

/// The flags of every mode applied to @p m: the overrides Python shares. @p placed: the
/// start, goal, departure and region already made the mission (--currents: forecastMission()); they are marked.
void applyFlags(const Flags &f, MissionSpec &m, bool placed)
{
    MissionOverrides o = overridesOf(f);
    if (placed)
    {
        for (const auto &[given, field, flag] :
             {std::make_tuple(!f.start.empty(), "start", "--start"), std::make_tuple(!f.goal.empty(), "goal", "--goal"),
              std::make_tuple(!f.departure.empty(), "departure.time", "--departure"),
              std::make_tuple(!f.region.empty(), "region", "--region")})
            if (given)
                m.marks[field] = SourceMark{flag, 0, Origin::Flag};
        o.start.reset();
        o.goal.reset();
        o.departure.reset();
        o.region.reset();
    }
    applyOrRefuse(o, m);
}
} // namespace

std::shared_ptr<const ompl_glider::SettingWords> flagWords()
{
    static const auto words =
        std::make_shared<const SettingWords>(SettingWords{{{"planner.name", "--planner"},
                                                           {"planner.grid_size", "--grid-size"},
                                                           {"planner.sectors", "--sectors"},
                                                           {"planner.time_limit", "--time-limit"},
                                                           {"vehicle.speed", "--speed"},
                                                           {"vehicle.depth", "--depth"},
                                                           {"departure.time", "--departure"},
                                                           {"start", "--start"},
                                                           {"observations", "--observations"},
                                                           {"observations.cache", "--observations-cache"},
                                                           {"goal", "--goal"},
                                                           {"region", "--region"},
                                                           {"current.file", "--currents"},
                                                           {"current.runs", "--currents ... --runs"},
                                                           {"current.horizon: hold_last", "--beyond hold"},
                                                           {"current.zero_velocity_land: false", "--no-zero-land"},
                                                           {"current.depth_average", "--depth-average"},
                                                           {"current.variables.angle", "--angle-var"},
                                                           {"current.variables.angle: none", "--angle-var none"},
                                                           {"current.variables.mask", "--mask-var"},
                                                           {"current.variables.u", "--u-var"},
                                                           {"current.variables.v", "--v-var"},
                                                           {"current.variables.lon", "--lon-var"},
                                                           {"current.variables.lat", "--lat-var"},
                                                           {"current.variables.depth", "--depth-var"},
                                                           {"current.variables.time", "--time-var"},
                                                           {"current.velocity_units", "--velocity-units"},
                                                           {"current.max_speed", "--max-current-speed"},
                                                           {"current.time_units", "--time-units"},
                                                           {"current.steady_record", "--steady-record"},
                                                           {"current.zero_velocity_land", "--no-zero-land"},
                                                           {"forbidden.coastline", "--coastline"},
                                                           {"safety.keep_off", "--keep-off"},
                                                           {"safety.min_depth", "--min-depth"},
                                                           {"safety.bathymetry", "--bathymetry"},
                                                           {"safety.bathymetry_variable", "--bathymetry-variable"},
                                                           {"safety.snap_to_water: true", "--snap-to-water"},
                                                           {"execution.truth", "--truth"},
                                                           {"execution.surfacing_interval", "--surfacing-interval"},
                                                           {"execution.strategies", "--strategies"},
                                                           {"execution.radius", "--radius"},
                                                           {"execution.across_runs", "--across-runs"}},
                                                          {},
                                                          Origin::Flag});
    return words;
}

MissionOverrides overridesOf(const Flags &f)
{
    MissionOverrides o;
    o.origin = Origin::Flag;
    o.words = flagWords();
    if (!f.planner.empty())
        o.planner = Given<std::string>{f.planner, "--planner"};
    if (f.gridSize)
        o.gridSize = Given<double>{*f.gridSize, "--grid-size"};
    if (f.sectors)
        o.sectors = Given<int>{*f.sectors, "--sectors"};
    if (f.timeLimit)
        o.timeLimit = Given<double>{*f.timeLimit, "--time-limit"};
    if (f.noSmooth)
        o.smoothing = Given<bool>{false, "--no-smooth"};
    if (f.noRefine)
        o.refinement = Given<bool>{false, "--no-refine"};
    if (f.noGlobalCheck)
        o.globalCheck = Given<bool>{false, "--no-global-check"};
    if (f.speed)
        o.speed = Given<double>{*f.speed, "--speed"};
    if (!f.departure.empty())
        o.departure = Given<std::string>{f.departure, "--departure"};
    if (!f.start.empty()) // lon,lat where the mission gives lon/lat
        o.start = Given<Point2>{pair("--start", f.start), "--start"};
    if (!f.goal.empty())
        o.goal = Given<Point2>{pair("--goal", f.goal), "--goal"};
    if (!f.region.empty())
    {
        const Box b = quad("--region", f.region);
        o.region = Given<std::array<double, 4>>{{b.xMin, b.yMin, b.xMax, b.yMax}, "--region"};
    }
    if (!f.out.empty() || f.mission.empty()) // a mission file keeps its outputs.directory unless --out is given
        o.outDirectory = Given<std::string>{f.out, "--out"};
    if (!f.arriveBetween.empty())
    {
        const std::vector<std::string> items = commaItems(f.arriveBetween);
        if (items.size() != 2 || items[0].empty() || items[1].empty())
            throw UsageError{"--arrive-between expects two times separated by a comma, begin,end (numbers in the "
                             "mission's time unit, or ISO 8601 dates with --currents), got '" +
                             f.arriveBetween + "'"};
        o.arrivalWindow = Given<std::pair<std::string, std::string>>{{items[0], items[1]}, "--arrive-between"};
    }
    if (!f.via.empty())
    {
        std::vector<ViaPointSpec> via;
        std::size_t from = 0;
        while (from <= f.via.size())
        {
            const std::size_t end = std::min(f.via.find(';', from), f.via.size());
            ViaPointSpec v;
            v.position.xy = pair("--via", f.via.substr(from, end - from)); // lon,lat where the mission gives lon/lat
            via.push_back(v);
            from = end + 1;
        }
        o.via = Given<std::vector<ViaPointSpec>>{via, "--via"};
    }
    if (!f.order.empty())
        o.order = Given<std::string>{f.order, "--order"};
    if (!f.observations.empty())
        o.observations = Given<std::string>{f.observations, "--observations"};
    if (!f.observationsCache.empty())
        o.observationsCache = Given<std::string>{f.observationsCache, "--observations-cache"};
    if (!f.coastline.empty())
        o.coastline = Given<std::string>{f.coastline, "--coastline"};
    if (f.isochrones)
        o.isochrones = Given<bool>{true, "--isochrones"};
    if (!f.isochroneInterval.empty())
        o.isochroneInterval = Given<std::string>{f.isochroneInterval, "--isochrone-interval"};
    if (f.reachability)
        o.reachability = Given<bool>{true, "--reachability"};
    if (!f.reachHorizon.empty())
        o.reachHorizon = Given<std::string>{f.reachHorizon, "--reach-horizon"};
    if (!f.reachInterval.empty())
        o.reachInterval = Given<std::string>{f.reachInterval, "--reach-interval"};
    if (f.gotoTurn)
        o.gotoTurn = Given<double>{*f.gotoTurn, "--goto-turn"};
    if (!f.holdTolerance.empty())
        o.holdTolerance = Given<std::string>{f.holdTolerance, "--hold-tolerance"};
    // safety
    for (const auto &[text, target, flag] :
         {std::make_tuple(&f.keepOff, &o.keepOff, "--keep-off"),
          std::make_tuple(&f.minDepth, &o.minDepth, "--min-depth"),
          std::make_tuple(&f.bathymetry, &o.bathymetry, "--bathymetry"),
          std::make_tuple(&f.bathymetryVariable, &o.bathymetryVariable, "--bathymetry-variable")})
        if (!text->empty())
            *target = Given<std::string>{*text, flag};
    if (f.snapToWater)
        o.snapToWater = Given<bool>{true, "--snap-to-water"};
    // execution in another ocean
    if (!f.truth.empty())
        o.truth = Given<std::string>{f.truth, "--truth"};
    if (!f.surfacingInterval.empty())
        o.surfacingInterval = Given<std::string>{f.surfacingInterval, "--surfacing-interval"};
    if (!f.strategies.empty())
        o.strategies = Given<std::vector<std::string>>{commaItems(f.strategies), "--strategies"};
    if (f.radius)
        o.radius = Given<double>{*f.radius, "--radius"};
    if (!f.acrossRuns.empty())
        o.acrossRuns = Given<std::string>{f.acrossRuns, "--across-runs"};
    if (f.executionPairs)
        o.executionPairs = Given<long long>{*f.executionPairs, "--execution-pairs"};
    if (f.executionSeed)
        o.executionSeed = Given<long long>{*f.executionSeed, "--execution-seed"};
    return o;
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

MissionSpec builtInMission(const Flags &f)
{
    MissionSpec m = defaultGulfStreamMission();
    applyFlags(f, m, false);
    return m;
}

MissionSpec missionFileOf(const Flags &f)
{
    MissionSpec m = loadMission(f.mission);
    applyFlags(f, m, false);
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
    if (f.runs)
        f.forecast.current.runs = files; // each file one run
    else if (files.size() == 1)
        f.forecast.current.file = files.front();
    else
        f.forecast.current.files = files;
    // without --start: the glider's last fix (and its time without --departure), read by the mission
    f.forecast.startAtLastFix = f.start.empty();
    f.forecast.observations = f.observations;
    f.forecast.observationsCache = f.observationsCache;
    if (!f.forecast.startAtLastFix)
        f.forecast.start = pair("--start", f.start);
    f.forecast.goal = pair("--goal", f.goal);
    f.forecast.departure = f.departure;
    if (!f.region.empty())
        f.forecast.region = quad("--region", f.region);
    // the speed, as every other planning setting, is the flags' (applyFlags(): checked once, marked "--speed")
    if (f.depth)
        f.forecast.depth = *f.depth;
    f.forecast.snapToWater = f.snapToWater;
    f.forecast.words = flagWords();
    MissionSpec m = forecastMission(f.forecast);
    applyFlags(f, m, true);
    return m;
}
} // namespace glider_plan

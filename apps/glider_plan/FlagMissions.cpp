// glider_plan's flags applied to a mission: the overrides Python's keywords share (MissionOverrides, applied by the
// library's applyOverrides()), the command line's own execution and safety flags, and the missions of the built-in,
// --mission and --currents modes.
#include <algorithm>
#include <cstdio>
#include <array>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "Flags.h"
#include "FlagText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/execution/Execution.h"
#include "ompl_glider/io/GliderObservations.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/Overrides.h"

namespace glider_plan
{
using namespace ompl_glider;

namespace
{
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

/// The flags of every mode applied to @p m: the overrides Python shares, then the execution flags. @p placed: the
/// start, goal, departure and region already made the mission (--currents: forecastMission()); they are marked.
void applyFlags(const Flags &f, MissionSpec &m, bool placed)
{
    MissionOverrides o = overridesOf(f);
    if (placed)
    {
        for (const auto &[given, field, flag] : {std::make_tuple(!f.start.empty(), "start", "--start"),
                                                 std::make_tuple(!f.goal.empty(), "goal", "--goal"),
                                                 std::make_tuple(!f.departure.empty(), "departure.time", "--departure"),
                                                 std::make_tuple(!f.region.empty(), "region", "--region")})
            if (given)
                m.marks[field] = SourceMark{flag, 0};
        o.start.reset();
        o.goal.reset();
        o.departure.reset();
        o.region.reset();
    }
    applyOrRefuse(o, m);
    applyExecution(f, m);
}
}  // namespace

MissionOverrides overridesOf(const Flags &f)
{
    MissionOverrides o;
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
    if (!f.start.empty())
        o.start = Given<Point2>{pair("--start", f.start), "--start"};  // lon,lat where the mission gives lon/lat
    if (!f.goal.empty())
        o.goal = Given<Point2>{pair("--goal", f.goal), "--goal"};
    if (!f.region.empty())
    {
        const Box b = quad("--region", f.region);
        o.region = Given<std::array<double, 4>>{{b.xMin, b.yMin, b.xMax, b.yMax}, "--region"};
    }
    if (!f.out.empty() || f.mission.empty())  // a mission file keeps its outputs.directory unless --out is given
        o.outDirectory = Given<std::string>{f.out, "--out"};
    if (!f.arriveBetween.empty())
    {
        const std::vector<std::string> items = commaItems(f.arriveBetween);
        if (items.size() != 2 || items[0].empty() || items[1].empty())
            throw UsageError{"--arrive-between expects two times separated by a comma, begin,end (numbers in the "
                             "mission's time unit, or ISO 8601 dates with --currents), got '" + f.arriveBetween + "'"};
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
            v.position.xy = pair("--via", f.via.substr(from, end - from));  // lon,lat where the mission gives lon/lat
            via.push_back(v);
            from = end + 1;
        }
        o.via = Given<std::vector<ViaPointSpec>>{via, "--via"};
    }
    if (!f.order.empty())
        o.order = Given<std::string>{f.order, "--order"};
    if (!f.observations.empty())
        o.observations = Given<std::string>{f.observations, "--observations"};
    if (!f.coastline.empty())
        o.coastline = Given<std::string>{f.coastline, "--coastline"};
    if (f.isochrones)
        o.isochrones = Given<bool>{true, "--isochrones"};
    if (!f.isochroneInterval.empty())
        o.isochroneInterval = Given<std::string>{f.isochroneInterval, "--isochrone-interval"};
    if (f.gotoTurn)
        o.gotoTurn = Given<double>{*f.gotoTurn, "--goto-turn"};
    return o;
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
    if (files.size() == 1)
        f.forecast.current.file = files.front();
    else
        f.forecast.current.files = files;
    const bool fromFix = f.start.empty(), departureFromFix = fromFix && f.departure.empty();
    if (fromFix)
    {
        // the glider's last fix (and its time without --departure): --observations
        try
        {
            const ompl_glider::GliderObservations o = ompl_glider::readGliderObservations(f.observations);
            if (!o.lastFix)
                throw ompl_glider::Error("they report no position to start from");
            char start[64];
            std::snprintf(start, sizeof start, "%.17g,%.17g", o.lastFix->at.lon, o.lastFix->at.lat);
            f.start = start;
            if (f.departure.empty())
                f.departure = ompl_glider::formatIsoTime(o.lastFix->time);
        }
        catch (const ompl_glider::Error &e)
        {
            throw UsageError{"--observations " + f.observations + ": " + e.what()};
        }
    }
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
    applyFlags(f, m, true);
    if (fromFix)
        m.marks["start"] = SourceMark{"--observations", 0};  // the last fix
    if (departureFromFix)
        m.marks["departure.time"] = SourceMark{"--observations", 0};
    return m;
}
}  // namespace glider_plan

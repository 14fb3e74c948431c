/// @file Overrides.cpp
/// @brief applyOverrides() (Overrides.h): the one place where a flag or a keyword changes a mission.

#include "ompl_glider/mission/Overrides.h"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <set>

#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/execution/Execution.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/SettingRanges.h"
#include "ompl_glider/registry/PlannerRegistry.h"

namespace ompl_glider
{
namespace
{
void applyCorrectionSettings(const MissionOverrides &o, MissionSpec &m);

/// @p v, refused naming its source unless it is finite.
double finite(const Given<double> &v)
{
    if (!std::isfinite(v.value))
        throw Error(v.source + ": expected a finite number, got " + text::number(v.value));
    return v.value;
}

/// @p v checked against the declared range of @p field (SettingRanges.h), refused naming its source.
template <class T> T setting(const Given<T> &v, const char *field)
{
    try
    {
        checkSetting(field, static_cast<double>(v.value), text::number(static_cast<double>(v.value)));
    }
    catch (const Error &e)
    {
        throw Error(v.source + ": " + e.what());
    }
    return v.value;
}

/// @p v (a number, or a length or duration with its unit) read as @p field of @p m and checked, refused naming its
/// source.
double settingOf(const Given<std::string> &v, const char *field, const MissionSpec &m)
{
    try
    {
        return settingFromText(field, v.value, m);
    }
    catch (const Error &e)
    {
        throw Error(v.source + ": " + e.what());
    }
}

void mark(MissionSpec &m, const char *field, const std::string &source, Origin origin)
{
    m.marks[field] = SourceMark{source, 0, origin};
}

/// A time read as the mission reads its departure, refused naming @p source.
double timeOf(const MissionSpec &m, const std::string &text, const std::string &source)
{
    try
    {
        return m.timeOf(text);
    }
    catch (const Error &e)
    {
        throw Error(source + ": " + e.what());
    }
}

void applyPlanner(const MissionOverrides &o, MissionSpec &m)
{
    if (o.planner)
    {
        const PlannerEntry *entry = findPlanner(o.planner->value);
        if (!entry)
            throw Error(o.planner->source + ": unknown planner '" + o.planner->value + "' (expected one of " +
                        plannerNameList() + ")");
        if (entry->name != m.planner.name)
        {
            m.planner.parameters.clear(); // the mission's parameters are the other planner's
            m.planner.parameterMarks.clear();
        }
        m.planner.name = entry->name;
        mark(m, "planner.name", o.planner->source, o.origin);
    }
    if (o.plannerParameters)
        for (const auto &[name, value] : o.plannerParameters->value)
        {
            m.planner.parameters[name] = value;
            m.planner.parameterMarks[name] = SourceMark{o.plannerParameters->source, 0, o.origin};
        }
    if (o.sectors)
    {
        m.planner.sectors = setting(*o.sectors, "planner.sectors");
        mark(m, "planner.sectors", o.sectors->source, o.origin);
    }
    const std::pair<const std::optional<Given<double>> *, std::pair<double *, const char *>> numbers[] = {
        {&o.gridSize, {&m.planner.gridSize, "planner.grid_size"}},
        {&o.timeLimit, {&m.planner.timeLimit, "planner.time_limit"}},
        {&o.horizon, {&m.planner.horizon, "planner.horizon"}},
        {&o.goalTolerance, {&m.planner.goalTolerance, "planner.goal_tolerance"}}};
    for (const auto &[given, target] : numbers)
        if (*given)
        {
            *target.first = setting(**given, target.second);
            mark(m, target.second, (*given)->source, o.origin);
        }
    if (o.smoothing)
        m.planner.smoothing = o.smoothing->value;
    if (o.refinement)
        m.planner.refinement = o.refinement->value;
    if (o.globalCheck)
        m.planner.globalCheck = o.globalCheck->value;
}

void applyPoint(const std::optional<Given<Point2>> &p, PointSpec &point, const char *field, MissionSpec &m,
                Origin origin)
{
    if (!p)
        return;
    for (const double v : {p->value.x, p->value.y})
        finite(Given<double>{v, p->source});
    if (point.geographic)
        point.lonLat = {p->value.x, p->value.y};
    else
        point.xy = p->value;
    mark(m, field, p->source, origin);
}

void applyWhereAndWhen(const MissionOverrides &o, MissionSpec &m)
{
    if (o.speed)
    {
        m.vehicle.speed = setting(*o.speed, "vehicle.speed");
        mark(m, "vehicle.speed", o.speed->source, o.origin);
    }
    if (o.departure)
    {
        // the mission's own departure, the deployment's (not the last fix's first guess): a resumed mission judges
        // the glider's fixes from then on, whatever departure the plan is made for
        const auto given = m.marks.find("departure.time");
        if (std::isnan(m.departure.replaced) && (given == m.marks.end() || given->second.origin == Origin::File))
            m.departure.replaced = m.departure.window ? m.departure.begin : m.departure.time;
        m.departure.time = timeOf(m, o.departure->value, o.departure->source);
        m.departure.window = false; // one departure in place of a window
        mark(m, "departure.time", o.departure->source, o.origin);
    }
    applyPoint(o.start, m.start, "start", m, o.origin);
    applyPoint(o.goal, m.goal, "goal", m, o.origin);
    if (o.region)
    {
        const auto [a, b, c, d] = o.region->value;
        for (const double v : o.region->value)
            finite(Given<double>{v, o.region->source});
        m.region.set = true;
        m.region.geographic = m.start.geographic;
        if (m.region.geographic)
            try
            {
                m.region.lonLat = geoBox(a, b, c, d);
            }
            catch (const Error &e)
            {
                throw Error(o.region->source + ": " + e.what());
            }
        else if (!(c > a && d > b))
            throw Error(o.region->source +
                        " expects x_min,y_min,x_max,y_max with x_max > x_min and y_max > y_min, "
                        "got " +
                        text::number(a) + "," + text::number(b) + "," + text::number(c) + "," + text::number(d));
        else
            m.region.xy = Box{a, c, b, d};
        mark(m, "region", o.region->source, o.origin);
    }
    if (o.arrivalWindow)
    {
        const std::string &source = o.arrivalWindow->source;
        const double begin = timeOf(m, o.arrivalWindow->value.first, source + ": begin");
        const double end = timeOf(m, o.arrivalWindow->value.second, source + ": end");
        if (!(end >= begin))
            throw Error(source + ": the end (" + o.arrivalWindow->value.second + ") must not be before the begin (" +
                        o.arrivalWindow->value.first + ")");
        if (const PlannerEntry *planner = findPlanner(m.planner.name); planner && planner->stints())
            throw Error(source + ": the stint planner '" + m.planner.name +
                        "' flies fixed stints and cannot time its arrival");
        m.goalWindow = {true, begin, end};
        for (const char *key : {"goal.window", "goal.window.begin", "goal.window.end"})
            mark(m, key, source, o.origin);
    }
}

void applyVia(const MissionOverrides &o, MissionSpec &m)
{
    if (o.via)
    {
        const std::string &source = o.via->source;
        std::vector<ViaPointSpec> via = o.via->value;
        std::set<std::string> names{"start", "goal"};
        for (std::size_t i = 0; i < via.size(); ++i)
        {
            ViaPointSpec &v = via[i];
            const std::string at = source + ": via point " + std::to_string(i + 1);
            for (const double c : {v.position.xy.x, v.position.xy.y})
                finite(Given<double>{c, at});
            if (m.start.geographic)
            {
                v.position.geographic = true;
                v.position.lonLat = {v.position.xy.x, v.position.xy.y};
                if (std::abs(v.position.lonLat.lat) > 90.0 || v.position.lonLat.lon < -180.0 ||
                    v.position.lonLat.lon > 360.0)
                    throw Error(at + ": lon,lat " + text::number(v.position.lonLat.lon) + "," +
                                text::number(v.position.lonLat.lat) +
                                " is not a position (longitude -180..180 or 0..360, latitude -90..90)");
            }
            if (v.name.empty())
                v.name = "WP" + std::to_string(i + 1);
            if (!plainViaPointName(v.name))
                throw Error(at + ": '" + v.name +
                            "' is not a plain name (a letter, then letters, digits, '_' or '-'; "
                            "at most 16 characters)");
            if (const std::string key = viaPointKey(v.name); !names.insert(key).second)
                throw Error(at + ": the name '" + v.name + "' is used twice" +
                            (key == "start" || key == "goal" ? " (it names the mission's " + key + ")" : "") +
                            " (names are compared without case)");
            if (!std::isnan(v.radius))
                setting(Given<double>{v.radius, at + ": the radius"}, "waypoints[].radius");
            setting(Given<double>{v.stay, at + ": the stay"}, "waypoints[].stay");
            if (v.arrive.set && !(v.arrive.end >= v.arrive.begin))
                throw Error(at + ": the arrival window ends before it begins");
        }
        for (auto it = m.marks.lower_bound("waypoints"); it != m.marks.end() && it->first.rfind("waypoints", 0) == 0;)
            it = m.marks.erase(it);
        m.waypoints = std::move(via);
        mark(m, "waypoints", source, o.origin);
    }
    if (o.order)
    {
        try
        {
            m.order = parseVisitOrder(o.order->value);
        }
        catch (const Error &e)
        {
            throw Error(o.order->source + ": " + e.what());
        }
        mark(m, "order", o.order->source, o.origin);
    }
    if (o.observations)
    {
        if (o.observations->value.empty()) // not "no observations": a caller that has none gives none
            throw Error(o.observations->source + ": expected a file, a folder, a glob or a URL, got an empty text");
        ObservationsSpec spec = m.observations.value_or(ObservationsSpec{});
        spec.path = o.observations->value;
        spec.mark = SourceMark{o.observations->source, 0, o.origin};
        m.observations = spec;
        mark(m, "observations", o.observations->source, o.origin);
    }
    if (o.observationsCache)
    {
        if (!m.observations || !m.observations->hasFiles())
            throw Error(o.observationsCache->source + ": a cache folder for the glider's files, but no observations "
                                                      "are given (the glider's files)");
        m.observations->cache = o.observationsCache->value;
        mark(m, "observations.cache", o.observationsCache->source, o.origin);
    }
    applyCorrectionSettings(o, m);
    if (m.order == VisitOrder::Free && m.waypoints.size() > kMaxFreeOrderViaPoints)
        throw Error((o.order ? o.order->source
                     : o.via ? o.via->source
                             : m.place("order")) +
                    ": free order over " + std::to_string(m.waypoints.size()) + " via points: at most " +
                    std::to_string(kMaxFreeOrderViaPoints) + " (the search is exponential in their number)");
}

void applyOutputs(const MissionOverrides &o, MissionSpec &m)
{
    if (o.coastline)
    {
        if (o.coastline->value.empty())
            throw Error(o.coastline->source + ": expected a file name, got an empty text");
        m.forbidden.coastline = o.coastline->value;
        m.forbidden.coastlineMark = SourceMark{o.coastline->source, 0, o.origin};
    }
    if (o.outDirectory)
        m.outputs.directory = o.outDirectory->value;
    if (o.isochroneInterval)
    {
        m.outputs.isochroneInterval = settingOf(*o.isochroneInterval, "outputs.isochrone_interval", m);
        mark(m, "outputs.isochrone_interval", o.isochroneInterval->source, o.origin);
    }
    if (o.gotoTurn)
        m.outputs.gotoTurnDeg = setting(*o.gotoTurn, "outputs.goto_turn_deg");
    if (o.holdTolerance)
    {
        m.outputs.holdTolerance = settingOf(*o.holdTolerance, "outputs.hold_tolerance", m);
        mark(m, "outputs.hold_tolerance", o.holdTolerance->source, o.origin);
    }
    if (((o.isochrones && o.isochrones->value) || o.isochroneInterval) && !m.outputs.wants(OutputFormatId::Isochrones))
        m.outputs.files.push_back(OutputFormatId::Isochrones);
    const std::pair<const std::optional<Given<std::string>> *, std::pair<const char *, double *>> reach[] = {
        {&o.reachHorizon, {"reachability.horizon", &m.reachability.horizon}},
        {&o.reachInterval, {"reachability.interval", &m.reachability.interval}},
        {&o.reachResolution, {"reachability.resolution", &m.reachability.resolution}}};
    for (const auto &[given, field] : reach)
        if (*given)
        {
            *field.second = settingOf(**given, field.first, m);
            mark(m, field.first, (*given)->source, o.origin);
        }
    if (((o.reachability && o.reachability->value) || o.reachHorizon || o.reachInterval || o.reachResolution) &&
        !m.outputs.wants(OutputFormatId::Reachability))
        m.outputs.files.push_back(OutputFormatId::Reachability);
}
/// The correction's settings given by a front end (MissionOverrides::correctionLength, ...), each refused naming its
/// source; they need the observations section (made empty, the correction's settings alone, when there is none).
void applyCorrectionSettings(const MissionOverrides &o, MissionSpec &m)
{
    if (!o.correctionLength && !o.correctionTime && !o.errorRatio && !o.learn)
        return;
    ObservationsSpec spec = m.observations.value_or(ObservationsSpec{});
    if (o.correctionLength)
    {
        spec.lengthScale = settingOf(*o.correctionLength, "observations.length_scale", m);
        mark(m, "observations.length_scale", o.correctionLength->source, o.origin);
    }
    if (o.correctionTime)
    {
        spec.timeScale = settingOf(*o.correctionTime, "observations.time_scale", m);
        mark(m, "observations.time_scale", o.correctionTime->source, o.origin);
    }
    if (o.errorRatio)
    {
        spec.errorRatio = setting(*o.errorRatio, "observations.error_ratio");
        mark(m, "observations.error_ratio", o.errorRatio->source, o.origin);
    }
    if (o.learn)
    {
        spec.learn = o.learn->value;
        mark(m, "observations.learn", o.learn->source, o.origin);
    }
    m.observations = spec;
}

void applySafety(const MissionOverrides &o, MissionSpec &m)
{
    SafetySpec &s = m.safety;
    if (o.keepOff)
    {
        s.keepOff = settingOf(*o.keepOff, "safety.keep_off", m);
        mark(m, "safety.keep_off", o.keepOff->source, o.origin);
    }
    if (o.minDepth)
    {
        s.minDepth = settingOf(*o.minDepth, "safety.min_depth", m);
        mark(m, "safety.min_depth", o.minDepth->source, o.origin);
    }
    if (o.bathymetry)
    {
        if (o.bathymetry->value.empty())
            throw Error(o.bathymetry->source + ": expected a file name, got an empty text");
        s.bathymetry = o.bathymetry->value;
        mark(m, "safety.bathymetry", o.bathymetry->source, o.origin);
    }
    if (o.bathymetryVariable)
    {
        s.bathymetryVariable = o.bathymetryVariable->value;
        mark(m, "safety.bathymetry_variable", o.bathymetryVariable->source, o.origin);
    }
    if (o.snapToWater)
    {
        s.snapToWater = o.snapToWater->value;
        mark(m, "safety.snap_to_water", o.snapToWater->source, o.origin);
    }
    // a depth limit reads the bathymetry file, or a forecast's own seafloor depth
    const bool seafloor = !s.bathymetry.empty() || m.current.isForecast();
    const std::string file = o.words ? (*o.words)("safety.bathymetry") : "safety.bathymetry";
    if (o.bathymetryVariable && !seafloor)
        throw Error(o.bathymetryVariable->source + ": the bathymetry variable needs a bathymetry file (" + file + ")");
    if (o.minDepth && s.minDepth > 0.0 && !seafloor)
        throw Error(o.minDepth->source +
                    ": a depth limit needs a bathymetry file, a NetCDF file of seafloor depth or "
                    "elevation (" +
                    file + ")");
}

/// The truth of an execution: another forecast (the forecast's variables and options), or the analytic flow with
/// other parameters.
CurrentSpec truthOf(const Given<std::string> &t, const MissionSpec &m, Origin origin)
{
    CurrentSpec c = m.current;
    c.runs.clear(); // the truth is one ocean, not runs
    c.runIndex.reset();
    c.mark = SourceMark{t.source, 0, origin};
    if (m.current.isForecast())
    {
        std::vector<std::string> files;
        try
        {
            files = forecastFileList(t.value);
        }
        catch (const Error &e)
        {
            throw Error(t.source + ": " + e.what());
        }
        c.file = files.front();
        c.files = files.size() > 1 ? files : std::vector<std::string>{};
        return c;
    }
    const CurrentFieldKind *kind = findCurrentFieldKind(m.current.type);
    const std::string names = kind ? parameterNameList(*kind) : std::string();
    std::size_t from = 0;
    while (from <= t.value.size())
    {
        const std::size_t end = std::min(t.value.find(',', from), t.value.size());
        const std::string item = t.value.substr(from, end - from);
        from = end + 1;
        const std::size_t eq = item.find('=');
        const std::string name = eq == std::string::npos ? item : item.substr(0, eq);
        if (eq == std::string::npos || !kind || !hasParameter(*kind, name))
            throw Error(t.source + ": expected 'forecast' or NAME=VALUE,... with the " + m.current.type +
                        "'s parameters (" + names + "), got '" + item + "'");
        const std::string number = item.substr(eq + 1);
        double value = 0.0;
        const char *first = number.data(), *last = number.data() + number.size();
        const auto r = std::from_chars(first, last, value);
        if (number.empty() || r.ec != std::errc() || r.ptr != last || !std::isfinite(value))
            throw Error(t.source + ": " + name + ": expected a finite number, got '" + number + "'");
        c.parameters[name] = value;
    }
    return c;
}

void applyExecution(const MissionOverrides &o, MissionSpec &m)
{
    if (!o.truth && !o.surfacingInterval && !o.strategies && !o.radius && !o.executionPairs && !o.executionSeed &&
        !o.acrossRuns)
        return; // the mission's execution section stays as it is
    ExecutionSpec &e = m.execution;
    const std::string &first = (o.truth               ? o.truth->source
                                : o.surfacingInterval ? o.surfacingInterval->source
                                : o.strategies        ? o.strategies->source
                                : o.radius            ? o.radius->source
                                : o.executionPairs    ? o.executionPairs->source
                                : o.executionSeed     ? o.executionSeed->source
                                                      : o.acrossRuns->source);
    e.enabled = true;
    e.mark = SourceMark{first, 0, o.origin};
    if (o.truth && o.truth->value != kTruthIsForecast)
        e.truth = truthOf(*o.truth, m, o.origin);
    else if (o.truth)
        e.truth.reset();
    if (o.surfacingInterval)
    {
        e.surfacingInterval = settingOf(*o.surfacingInterval, "execution.surfacing_interval", m);
        mark(m, "execution.surfacing_interval", o.surfacingInterval->source, o.origin);
    }
    if (o.strategies)
    {
        std::string known;
        for (const ControlStrategy s : controlStrategies())
            known += (known.empty() ? "" : ", ") + std::string(controlStrategyName(s));
        std::vector<std::string> names;
        for (const std::string &name : o.strategies->value)
        {
            if (!parseControlStrategy(name))
                throw Error(o.strategies->source + ": unknown strategy '" + name + "' (expected " + known + ")");
            if (std::find(names.begin(), names.end(), name) != names.end())
                throw Error(o.strategies->source + ": '" + name + "' is listed twice");
            names.push_back(name);
        }
        if (names.empty())
            throw Error(o.strategies->source + ": expected at least one strategy (" + known + ")");
        // the mission's noise on the DAC needs a strategy that measures them (as the mission file's check)
        const auto measures = [&names](const char *s) {
            return std::find(names.begin(), names.end(), s) != names.end();
        };
        if (e.dacNoise > 0.0 && !measures("dac") && !measures("replan_observed"))
            throw Error(o.strategies->source + ": no strategy listed measures a DAC, yet " +
                        m.place("execution.dac_noise") + " adds noise to them (" + text::number(e.dacNoise) +
                        "), which would change nothing: add dac or replan_observed, or leave dac_noise out");
        e.strategies = names;
        mark(m, "execution.strategies", o.strategies->source, o.origin);
    }
    if (o.radius)
    {
        e.radius = setting(*o.radius, "execution.radius");
        mark(m, "execution.radius", o.radius->source, o.origin);
    }
    if (o.executionPairs)
        e.pairs = static_cast<unsigned>(setting(*o.executionPairs, "execution.batch.pairs"));
    if (o.executionSeed)
        e.seed = static_cast<unsigned>(setting(*o.executionSeed, "execution.batch.seed"));
    if (o.acrossRuns)
    {
        if (m.current.runs.empty())
            throw Error(o.acrossRuns->source + ": given without forecast runs (" + m.term("current.runs") +
                        "): there is no new run to carry the learning across");
        try
        {
            e.acrossRuns = parseAcrossRuns(o.acrossRuns->value);
        }
        catch (const Error &x)
        {
            throw Error(o.acrossRuns->source + ": " + x.what());
        }
        mark(m, "execution.across_runs", o.acrossRuns->source, o.origin);
    }
}
} // namespace

void applyOverrides(const MissionOverrides &o, MissionSpec &m)
{
    MissionSpec changed = m; // all or nothing
    applyPlanner(o, changed);
    applyWhereAndWhen(o, changed);
    applyVia(o, changed);
    applyOutputs(o, changed);
    applySafety(o, changed);
    applyExecution(o, changed);
    if (o.words)
        changed.words = o.words;
    m = std::move(changed);
}
} // namespace ompl_glider

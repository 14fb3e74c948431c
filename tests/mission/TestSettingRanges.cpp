// The declared ranges of the mission's settings (mission/SettingRanges.h), read row by row: each bound is tried in a
// mission file and as a front end's override, and both ways in must accept the values inside and refuse the values
// outside in the same words, naming the place (file:line and field, or the flag). A row that one way in does not
// read, or reads with another range, fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Overrides.h"
#include "ompl_glider/mission/SettingRanges.h"

using namespace ompl_glider;

namespace
{
const std::string kRangesBase = R"(name: t
current:
  type: uniform
  parameters: {u: 0.1, v: 0.0}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
)";

std::string shortest(double v)
{
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

/// The mission file's text that gives @p field the value @p v (YAML flow maps for the dotted parts).
std::string missionWith(const std::string &field, const std::string &v, const std::string &bathymetry)
{
    if (field == "waypoints[].radius" || field == "waypoints[].stay")
        return kRangesBase + "waypoints:\n  - {name: A, x: 5, y: 1, " + field.substr(12) + ": " + v + "}\n";
    if (field == "safety.min_depth")
        return kRangesBase + "safety: {bathymetry: " + bathymetry + ", min_depth: " + v + "}\n";
    if (field == "execution.batch.pairs" || field == "execution.batch.seed")
        return kRangesBase + "execution: {batch: {" + field.substr(16) + ": " + v + "}}\n";
    const std::size_t dot = field.find('.');
    const std::string section = field.substr(0, dot), key = field.substr(dot + 1);
    if (section == "vehicle")
        return kRangesBase + "vehicle: {" + key + ": " + v + "}\n";
    return kRangesBase + section + ": {" + key + ": " + v + "}\n";
}

/// What the mission file gave the field (to check that a value inside the range is the value kept).
double valueOf(const std::string &field, const MissionSpec &m)
{
    const std::map<std::string, std::function<double(const MissionSpec &)>> read = {
        {"vehicle.speed", [](const MissionSpec &s) { return s.vehicle.speed; }},
        {"planner.grid_size", [](const MissionSpec &s) { return s.planner.gridSize; }},
        {"planner.sectors", [](const MissionSpec &s) { return double(s.planner.sectors); }},
        {"planner.time_limit", [](const MissionSpec &s) { return s.planner.timeLimit; }},
        {"planner.horizon", [](const MissionSpec &s) { return s.planner.horizon; }},
        {"planner.goal_tolerance", [](const MissionSpec &s) { return s.planner.goalTolerance; }},
        {"waypoints[].radius", [](const MissionSpec &s) { return s.waypoints.at(0).radius; }},
        {"waypoints[].stay", [](const MissionSpec &s) { return s.waypoints.at(0).stay; }},
        {"observations.length_scale", [](const MissionSpec &s) { return s.observations->lengthScale; }},
        {"observations.time_scale", [](const MissionSpec &s) { return s.observations->timeScale; }},
        {"observations.error_ratio", [](const MissionSpec &s) { return s.observations->errorRatio; }},
        {"safety.keep_off", [](const MissionSpec &s) { return s.safety.keepOff; }},
        {"safety.min_depth", [](const MissionSpec &s) { return s.safety.minDepth; }},
        {"outputs.goto_turn_deg", [](const MissionSpec &s) { return s.outputs.gotoTurnDeg; }},
        {"outputs.hold_tolerance", [](const MissionSpec &s) { return s.outputs.holdTolerance; }},
        {"outputs.isochrone_interval", [](const MissionSpec &s) { return s.outputs.isochroneInterval; }},
        {"reachability.horizon", [](const MissionSpec &s) { return s.reachability.horizon; }},
        {"reachability.interval", [](const MissionSpec &s) { return s.reachability.interval; }},
        {"reachability.resolution", [](const MissionSpec &s) { return s.reachability.resolution; }},
        {"execution.surfacing_interval", [](const MissionSpec &s) { return s.execution.surfacingInterval; }},
        {"execution.radius", [](const MissionSpec &s) { return s.execution.radius; }},
        {"execution.batch.pairs", [](const MissionSpec &s) { return double(s.execution.pairs); }},
        {"execution.batch.seed", [](const MissionSpec &s) { return double(s.execution.seed); }},
    };
    const auto it = read.find(field);
    if (it == read.end())
        throw std::logic_error("the test does not know where the mission keeps " + field);
    return it->second(m);
}

/// The front end's override of @p field with the value @p v, named "--x" in messages.
MissionOverrides overrideOf(const std::string &field, double v)
{
    MissionOverrides o;
    const std::string src = "--x", text = shortest(v);
    if (field == "vehicle.speed")
        o.speed = Given<double>{v, src};
    else if (field == "planner.grid_size")
        o.gridSize = Given<double>{v, src};
    else if (field == "planner.sectors")
        o.sectors = Given<int>{static_cast<int>(v), src};
    else if (field == "planner.time_limit")
        o.timeLimit = Given<double>{v, src};
    else if (field == "planner.horizon")
        o.horizon = Given<double>{v, src};
    else if (field == "planner.goal_tolerance")
        o.goalTolerance = Given<double>{v, src};
    else if (field == "waypoints[].radius" || field == "waypoints[].stay")
    {
        ViaPointSpec p;
        p.name = "A";
        p.position.xy = {5.0, 1.0};
        (field == "waypoints[].radius" ? p.radius : p.stay) = v;
        o.via = Given<std::vector<ViaPointSpec>>{{p}, src};
    }
    else if (field == "observations.length_scale")
        o.correctionLength = Given<std::string>{text, src};
    else if (field == "observations.time_scale")
        o.correctionTime = Given<std::string>{text, src};
    else if (field == "observations.error_ratio")
        o.errorRatio = Given<double>{v, src};
    else if (field == "safety.keep_off")
        o.keepOff = Given<std::string>{text, src};
    else if (field == "safety.min_depth")
        o.minDepth = Given<std::string>{text, src};
    else if (field == "outputs.goto_turn_deg")
        o.gotoTurn = Given<double>{v, src};
    else if (field == "outputs.hold_tolerance")
        o.holdTolerance = Given<std::string>{text, src};
    else if (field == "outputs.isochrone_interval")
        o.isochroneInterval = Given<std::string>{text, src};
    else if (field == "reachability.horizon")
        o.reachHorizon = Given<std::string>{text, src};
    else if (field == "reachability.interval")
        o.reachInterval = Given<std::string>{text, src};
    else if (field == "reachability.resolution")
        o.reachResolution = Given<std::string>{text, src};
    else if (field == "execution.surfacing_interval")
        o.surfacingInterval = Given<std::string>{text, src};
    else if (field == "execution.radius")
        o.radius = Given<double>{v, src};
    else if (field == "execution.batch.pairs")
        o.executionPairs = Given<long long>{static_cast<long long>(v), src};
    else if (field == "execution.batch.seed")
        o.executionSeed = Given<long long>{static_cast<long long>(v), src};
    else
        throw std::logic_error("the test does not know the override of " + field);
    return o;
}

/// Values inside and outside @p s's range.
void valuesOf(const SettingRange &s, std::vector<double> &inside, std::vector<double> &outside)
{
    const bool bounded = std::isfinite(s.high);
    inside = {s.lowIncluded ? s.low : s.low + 1.0, bounded ? s.high : s.low + 1000.0};
    outside = {s.lowIncluded ? s.low - 1.0 : s.low, s.low - 1.0};
    if (bounded)
        outside.push_back(s.high + 1.0);
    if (s.value == SettingValue::Integer)
        outside.push_back(s.low + 0.5);
}

std::string errorOfFile(const std::string &text)
{
    try
    {
        parseMission(text, "m.yaml");
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

std::string errorOfOverride(const MissionOverrides &o, MissionSpec m)
{
    try
    {
        applyOverrides(o, m);
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

std::string bathymetryFile()
{
    // the loader checks only that the file exists; the depth limit is read from it when the problem is built
    const std::string path = ::testing::TempDir() + "ranges_bathymetry.nc";
    std::ofstream(path) << "";
    return path;
}
} // namespace

TEST(SettingRanges, EveryRowIsFoundByItsFieldAndSaysItsRange)
{
    ASSERT_GE(settingRanges().size(), 15u);
    for (const SettingRange &s : settingRanges())
    {
        EXPECT_EQ(&settingRange(s.field), &s) << s.field;
        EXPECT_FALSE(rangeWords(s).empty());
    }
    EXPECT_EQ(settingRange("waypoints[12].radius").field, "waypoints[].radius");
    EXPECT_THROW(settingRange("planner.no_such_setting"), std::logic_error);
    EXPECT_EQ(rangeWords(settingRange("safety.keep_off")), ">= 0");
    EXPECT_EQ(rangeWords(settingRange("vehicle.speed")), "> 0");
    EXPECT_EQ(rangeWords(settingRange("outputs.goto_turn_deg")), "in 0..180");
}

TEST(SettingRanges, AMissionFileTakesTheValuesInsideAndRefusesTheOthersAtTheirLine)
{
    const std::string bathymetry = bathymetryFile();
    for (const SettingRange &s : settingRanges())
    {
        std::vector<double> inside, outside;
        valuesOf(s, inside, outside);
        for (const double v : inside)
        {
            const std::string text = missionWith(s.field, shortest(v), bathymetry);
            MissionSpec m;
            ASSERT_NO_THROW(m = parseMission(text, "m.yaml")) << s.field << " = " << v << ": " << errorOfFile(text);
            EXPECT_EQ(valueOf(s.field, m), v) << s.field;
        }
        for (const double v : outside)
        {
            const std::string text = missionWith(s.field, shortest(v), bathymetry);
            const std::string e = errorOfFile(text);
            ASSERT_FALSE(e.empty()) << s.field << " = " << v << " was taken";
            const int line = static_cast<int>(std::count(text.begin(), text.end(), '\n')); // the last line
            EXPECT_NE(e.find("m.yaml:" + std::to_string(line)), std::string::npos) << e;
            const std::string key = s.field.substr(s.field.rfind('.') + 1);
            EXPECT_NE(e.find(key), std::string::npos) << e;
        }
    }
}

TEST(SettingRanges, AnOverrideTakesAndRefusesTheSameValuesInTheSameWords)
{
    const std::string bathymetry = bathymetryFile();
    for (const SettingRange &s : settingRanges())
    {
        std::vector<double> inside, outside;
        valuesOf(s, inside, outside);
        MissionSpec base = parseMission(kRangesBase, "m.yaml");
        if (s.field == "safety.min_depth")
            base.safety.bathymetry = bathymetry;
        for (const double v : inside)
        {
            MissionSpec m = base;
            const std::string e = errorOfOverride(overrideOf(s.field, v), m);
            EXPECT_EQ(e, "") << s.field << " = " << v;
        }
        for (const double v : outside)
        {
            if (s.value == SettingValue::Integer && v != std::floor(v))
                continue; // an override's integer cannot hold it: its type refuses it before any check
            const std::string e = errorOfOverride(overrideOf(s.field, v), base);
            ASSERT_FALSE(e.empty()) << s.field << " = " << v << " was taken";
            EXPECT_EQ(e.rfind("--x", 0), 0u) << e;
            // the file says the same after its place (the value as written may differ: a text or a number)
            const std::string file = errorOfFile(missionWith(s.field, shortest(v), bathymetry));
            const std::size_t from = std::min(e.find("expected "), e.find("at most "));
            ASSERT_NE(from, std::string::npos) << e;
            const std::string head = e.substr(from, e.find(", got", from) - from);
            EXPECT_NE(file.find(head), std::string::npos) << "override: " << e << "\nfile: " << file;
        }
    }
}

TEST(SettingRanges, ALengthTakesAnyLengthUnitAndRefusesOthersNamingThem)
{
    // the mission's length unit is 1 km: each length is read in metres through its unit (UDUNITS-2), then in km
    const std::string base = kRangesBase + "units: {length_m: 1000, time_s: 3600}\n";
    for (const auto &[given, metres] : std::vector<std::pair<std::string, double>>{{"500 cm", 5.0},
                                                                                   {"20 mi", 20 * 1609.344},
                                                                                   {"65000 ft", 65000 * 0.3048},
                                                                                   {"2 km", 2000.0},
                                                                                   {"3 nmi", 3 * 1852.0},
                                                                                   {"1500m", 1500.0}})
    {
        const MissionSpec m = parseMission(base + "observations: {length_scale: " + given + "}\n", "m.yaml");
        ASSERT_TRUE(m.observations) << given;
        EXPECT_NEAR(m.observations->lengthScale, metres / 1000.0, 1e-12 * metres) << given;
        EXPECT_NEAR(settingFromText("safety.keep_off", given, m), metres / 1000.0, 1e-12 * metres) << given;
        EXPECT_NEAR(settingFromText("execution.radius", given, m), metres / 1000.0, 1e-12 * metres) << given;
    }
    for (const auto &[given, phrase] :
         std::vector<std::pair<std::string, std::string>>{{"3 h", "expected a length >= 0"},
                                                          {"20 furlongs per fortnight", "expected a length >= 0"},
                                                          {"20 quux", "expected a length >= 0"}})
        try
        {
            (void)parseMission(base + "observations: {length_scale: " + given + "}\n", "m.yaml");
            ADD_FAILURE() << given << " accepted as a length";
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find("m.yaml:9: field 'observations.length_scale': " + phrase),
                      std::string::npos)
                << e.what();
        }
}

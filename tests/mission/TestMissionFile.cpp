// Tests of mission files: the examples load, every error names the file, the field and the line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionSpec.h"

using namespace ompl_glider;

namespace
{
const std::string kMissionExamples = std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/";

const std::string kBase = R"(name: t
current:
  type: uniform
  parameters: {u: 0.1, v: 0.0}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
)";

/// The error message of parsing @p text, or "" when it parses.
std::string missionFileErrorOf(const std::string &text)
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

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << "message: " << (msg)
} // namespace

TEST(Time, IsoDatesRoundTripWithOffsets)
{
    EXPECT_DOUBLE_EQ(parseIsoTime("1970-01-01T00:00:00Z"), 0.0);
    EXPECT_DOUBLE_EQ(parseIsoTime("2026-06-01T00:00:00Z"), 1780272000.0);
    EXPECT_DOUBLE_EQ(parseIsoTime("2026-06-01T02:30:00+02:30"), 1780272000.0);
    EXPECT_DOUBLE_EQ(parseIsoTime("2024-02-29"), 1709164800.0);
    EXPECT_EQ(formatIsoTime(1780272000.0 + 86400 * 16 + 3661.4), "2026-06-17T01:01:01Z");
    EXPECT_EQ(formatIsoTime(parseIsoTime("1899-12-31T23:59:59Z")), "1899-12-31T23:59:59Z");
    EXPECT_THROW(parseIsoTime("2023-02-29"), Error);
    EXPECT_THROW(parseIsoTime("yesterday"), Error);
}

TEST(MissionFile, ExamplesLoad)
{
    const MissionSpec g = loadMission(kMissionExamples + "gulf_stream_window.yaml");
    EXPECT_EQ(g.current.type, "meandering_jet");
    EXPECT_DOUBLE_EQ(g.current.parameters.at("omega"), 0.4);
    EXPECT_TRUE(g.departure.window);
    EXPECT_DOUBLE_EQ(g.departure.begin, 5.0); // an ISO date, 5 days after the epoch
    EXPECT_DOUBLE_EQ(g.departure.end, 21.0);
    EXPECT_DOUBLE_EQ(g.departure.spacing, 1.0);
    EXPECT_DOUBLE_EQ(g.lengthUnitMetres, 50000.0);
    EXPECT_DOUBLE_EQ(g.timeUnitSeconds, 86400.0);
    ASSERT_TRUE(g.epoch.has_value());
    EXPECT_DOUBLE_EQ(*g.epoch, 1780272000.0);
    EXPECT_EQ(g.outputs.gotoNumber, 11);
    EXPECT_EQ(g.speeds, (std::vector<double>{0.4, 0.5, 0.6}));
    EXPECT_DOUBLE_EQ(g.vehicle.speed, 0.5);

    const MissionSpec i = loadMission(kMissionExamples + "islands_ice.yaml");
    ASSERT_EQ(i.forbidden.obstacles.size(), 2u);
    EXPECT_EQ(i.forbidden.obstacles[0].polygon.name, "North Island");
    EXPECT_EQ(i.forbidden.obstacles[0].polygon.points.size(), 5u);
    ASSERT_EQ(i.forbidden.timeWindows.size(), 1u);
    EXPECT_EQ(i.forbidden.timeWindows[0].windows[0], std::make_pair(0.0, 14.0));
    ASSERT_EQ(i.forbidden.ice.size(), 1u);
    EXPECT_DOUBLE_EQ(i.forbidden.ice[0].vx, 0.05);
    EXPECT_DOUBLE_EQ(i.forbidden.ice[0].maxSubmergedTime, 0.5);
    EXPECT_TRUE(i.dive.enabled);
    EXPECT_EQ(makeDiveProfiles(i.dive.params).size(), 5u); // (5,105) (5,152.5) (5,200) (30,152.5) (30,200)

    const MissionSpec l = loadMission(kMissionExamples + "labrador_forecast.yaml");
    EXPECT_EQ(l.current.type, "netcdf");
    EXPECT_EQ(l.current.file, kMissionExamples + "labrador_forecast.nc");
    EXPECT_EQ(l.current.xyInterpolation, Interp2D::Bicubic);
    EXPECT_EQ(l.current.timeInterpolation, Interp1D::Akima);
    ASSERT_TRUE(l.fileCalendar.has_value());
    EXPECT_DOUBLE_EQ(l.departure.begin, 0.0);       // the file's first time
    EXPECT_DOUBLE_EQ(l.departure.end, 2 * 86400.0); // ISO date in the file's calendar
    ASSERT_TRUE(l.epoch.has_value());
    EXPECT_DOUBLE_EQ(*l.epoch, parseIsoTime("2026-03-15T00:00:00Z"));
    EXPECT_TRUE(l.start.geographic);
    EXPECT_DOUBLE_EQ(l.start.lonLat.lon, -52.7);
    EXPECT_EQ(l.dive.bathymetry, DiveSpec::Bathymetry::Constant);
    EXPECT_DOUBLE_EQ(l.dive.bathymetryDepth, 180.0);
    EXPECT_DOUBLE_EQ(l.travel.eps, 1.0);
}

TEST(MissionFile, MinimalMissionAndDefaults)
{
    const MissionSpec m = parseMission(kBase, "m.yaml");
    EXPECT_EQ(m.name, "t");
    EXPECT_EQ(m.planner.name, "ZA*TVE"); // the canonical name of the registry
    EXPECT_FALSE(m.departure.window);
    EXPECT_FALSE(m.dive.enabled);
    EXPECT_EQ(m.outputs.files, (std::vector<OutputFormatId>{OutputFormatId::Csv, OutputFormatId::GeoJson,
                                                            OutputFormatId::Summary})); // no projection: no goto
}

TEST(MissionFile, UnknownFieldsAreRejectedWithTheirLine)
{
    std::string msg = missionFileErrorOf(kBase + "vehicel:\n  speed: 0.3\n");
    EXPECT_HAS(msg, "m.yaml:8:");
    EXPECT_HAS(msg, "unknown field 'vehicel'");
    msg = missionFileErrorOf(kBase + "planner:\n  name: zastartve\n  grid_sise: 0.2\n");
    EXPECT_HAS(msg, "m.yaml:10:");
    EXPECT_HAS(msg, "unknown field 'planner.grid_sise'");
    EXPECT_HAS(msg, "grid_size"); // the allowed names are listed
    msg = missionFileErrorOf(kBase + "departure:\n  window: {begin: 0, end: 5, spacin: 1}\n");
    EXPECT_HAS(msg, "m.yaml:9:");
    EXPECT_HAS(msg, "departure.window.spacin");
    msg = missionFileErrorOf(kBase + "vehicle:\n  speed: 0.3\n  speed: 0.4\n");
    EXPECT_HAS(msg, "m.yaml:10:");
    EXPECT_HAS(msg, "'vehicle.speed' is given twice");
    msg = missionFileErrorOf(std::string(kBase).replace(kBase.find("{u: 0.1"), 1, "{w: 1, "));
    EXPECT_HAS(msg, "m.yaml:4:");
    EXPECT_HAS(msg, "current.parameters.w");
}

TEST(MissionFile, WrongTypesAndValuesNameTheFieldAndLine)
{
    std::string msg = missionFileErrorOf(kBase + "vehicle:\n  speed: fast\n");
    EXPECT_HAS(msg, "m.yaml:9:");
    EXPECT_HAS(msg, "field 'vehicle.speed'");
    EXPECT_HAS(msg, "expected a number");
    msg = missionFileErrorOf(kBase + "vehicle:\n  speed: -0.3\n");
    EXPECT_HAS(msg, "m.yaml:9:");
    EXPECT_HAS(msg, "> 0");
    msg = missionFileErrorOf(kBase + "planner: {sectors: 9}\n");
    EXPECT_HAS(msg, "m.yaml:8:");
    EXPECT_HAS(msg, "planner.sectors");
    EXPECT_HAS(msg, "1..5");
    msg = missionFileErrorOf(kBase + "planner: {name: dijkstra}\n");
    EXPECT_HAS(msg, "planner.name");
    EXPECT_HAS(msg, "ZA*TVE");
    msg = missionFileErrorOf(kBase + "outputs: {files: [csv, kml]}\n");
    EXPECT_HAS(msg, "outputs.files[1]");
    msg = missionFileErrorOf(kBase + "outputs: {files: [goto]}\n");
    EXPECT_HAS(msg, "projection");
    msg = missionFileErrorOf(kBase + "dive_profile: {z_min: 10, z_max: 5}\n");
    EXPECT_HAS(msg, "m.yaml:8:");
    EXPECT_HAS(msg, "dive_profile");
    EXPECT_HAS(msg, "z_max");
    msg = missionFileErrorOf(kBase + "departure: {time: \"2026-01-01T00:00:00Z\"}\n");
    EXPECT_HAS(msg, "departure.time");
    EXPECT_HAS(msg, "epoch");
    msg = missionFileErrorOf(kBase + "departure:\n  window: {begin: 5, end: 1}\n");
    EXPECT_HAS(msg, "m.yaml:9:");
    EXPECT_HAS(msg, "departure.window.end");
    msg = missionFileErrorOf(kBase + "forbidden:\n  obstacles:\n    - name: A\n      points: [[1, 1], [2, 1]]\n");
    EXPECT_HAS(msg, "m.yaml:11:");
    EXPECT_HAS(msg, "forbidden.obstacles[0].points");
    msg = missionFileErrorOf(kBase + "forbidden:\n  ice:\n    - points: [[1, 1], [2, 1], [2, 2]]\n");
    EXPECT_HAS(msg, "forbidden.ice[0].max_submerged_time");
    msg = missionFileErrorOf(kBase + "planner: {goal_tolerance: .inf}\n");
    EXPECT_HAS(msg, "m.yaml:8:");
    EXPECT_HAS(msg, "planner.goal_tolerance");
    EXPECT_HAS(msg, "finite");
}

TEST(MissionFile, MissingRequiredFieldsAndSyntaxErrors)
{
    std::string msg = missionFileErrorOf("current: {type: uniform}\nregion: {x_min: 0, x_max: 1, y_min: 0, y_max: 1}\n"
                                         "goal: {x: 1, y: 1}\n");
    EXPECT_HAS(msg, "field 'start'");
    EXPECT_HAS(msg, "missing");
    msg = missionFileErrorOf("current: {type: uniform}\nstart: {x: 0, y: 0}\ngoal: {x: 1, y: 1}\n");
    EXPECT_HAS(msg, "field 'region'");
    msg = missionFileErrorOf("current: {type: uniform}\nregion: {x_min: 0, x_max: 1, y_min: 0, y_max: 1}\n"
                             "start: {lon: -50, lat: 40}\ngoal: {x: 1, y: 1}\n");
    EXPECT_HAS(msg, "m.yaml:3:");
    EXPECT_HAS(msg, "projection");
    msg = missionFileErrorOf(kBase + "goal: {x: 1\n");
    EXPECT_HAS(msg, "YAML syntax error");
    msg = missionFileErrorOf(std::string(kBase).replace(kBase.find("x: 9"), 4, "x: 19"));
    EXPECT_HAS(msg, "m.yaml:7:");
    EXPECT_HAS(msg, "outside the region");
    EXPECT_THROW(loadMission("/nonexistent/mission.yaml"), Error);
    msg =
        missionFileErrorOf("current: {type: netcdf, file: /nonexistent.nc}\nstart: {x: 0, y: 0}\ngoal: {x: 1, y: 1}\n");
    EXPECT_HAS(msg, "current.file");
    EXPECT_HAS(msg, "/nonexistent.nc");
}

TEST(MissionFile, GeographicRegionsInEitherConvention)
{
    // an analytic flow with a projection: lon/lat regions are stored from lon_min in -180..180 eastward
    const std::string geo = "current: {type: uniform}\nprojection: {lon0: 180, lat0: 0}\n"
                            "start: {lon: 175, lat: 0}\ngoal: {lon: 185, lat: 1}\n";
    auto region = [&](const std::string &r) { return parseMission(geo + "region: " + r + "\n", "m.yaml").region; };
    for (const char *r : {"{lon_min: 170, lon_max: -170, lat_min: -5, lat_max: 5}", // RFC 7946 bbox across 180
                          "{lon_min: 170, lon_max: 190, lat_min: -5, lat_max: 5}"}) // unwrapped
    {
        const RegionSpec g = region(r);
        EXPECT_TRUE(g.geographic);
        EXPECT_EQ(g.lonLat.lonMin, 170.0) << r;
        EXPECT_EQ(g.lonLat.lonMax, 190.0) << r;
    }
    const RegionSpec g = region("{lon_min: 350, lon_max: 10, lat_min: -5, lat_max: 5}"); // 0..360 across 0
    EXPECT_EQ(g.lonLat.lonMin, -10.0);
    EXPECT_EQ(g.lonLat.lonMax, 10.0);
    // bad bounds name the bound and its line
    std::string msg =
        missionFileErrorOf(geo + "region:\n  lon_min: 170\n  lon_max: -170\n  lat_min: -5\n  lat_max: 95\n");
    EXPECT_HAS(msg, "m.yaml:9:");
    EXPECT_HAS(msg, "field 'region.lat_max'");
    EXPECT_HAS(msg, "95");
    msg = missionFileErrorOf(geo + "region: {lon_min: -190, lon_max: -170, lat_min: -5, lat_max: 5}\n");
    EXPECT_HAS(msg, "field 'region.lon_min'");
    EXPECT_HAS(msg, "-180..180 or 0..360");
    msg = missionFileErrorOf(geo + "region: {lon_min: -180, lon_max: 180, lat_min: -5, lat_max: 5}\n");
    EXPECT_HAS(msg, "field 'region.lon_max'");
    EXPECT_HAS(msg, "less than 360");
    msg = missionFileErrorOf(geo + "region: {lon_min: 10, lon_max: 10, lat_min: -5, lat_max: 5}\n");
    EXPECT_HAS(msg, "field 'region.lon_max'");
    msg = missionFileErrorOf(geo + "region: {lon_min: 10, lon_max: 20, lat_min: 5, lat_max: -5}\n");
    EXPECT_HAS(msg, "field 'region.lat_max'");
    // start and goal longitudes in either convention, nothing else
    msg = missionFileErrorOf("current: {type: uniform}\nprojection: {lon0: 180, lat0: 0}\n"
                             "start: {lon: 400, lat: 0}\ngoal: {lon: 185, lat: 1}\n"
                             "region: {lon_min: 170, lon_max: -170, lat_min: -5, lat_max: 5}\n");
    EXPECT_HAS(msg, "m.yaml:3:");
    EXPECT_HAS(msg, "field 'start.lon'");
}

TEST(MissionFile, GeoJsonForbiddenRegions)
{
    const std::string dir = ::testing::TempDir();
    {
        std::ofstream f(dir + "mission_regions.geojson");
        f << R"({"type": "FeatureCollection", "features": [
 {"type": "Feature", "properties": {"name": "Rock", "kind": "island"},
  "geometry": {"type": "Polygon", "coordinates": [[[2, 1], [3, 1], [3, 2], [2, 2], [2, 1]]]}},
 {"type": "Feature", "properties": {"name": "Lane", "kind": "closure", "windows": [[0, 5], [10, 12]]},
  "geometry": {"type": "MultiPolygon", "coordinates": [[[[5, -1], [6, -1], [6, 1]]], [[[7, -1], [8, -1], [8, 1]]]]}},
 {"type": "Feature", "properties": {"name": "Floe", "kind": "ice", "max_submerged_time": 2, "drift": [0.1, 0]},
  "geometry": {"type": "Polygon", "coordinates": [[[1, 2], [2, 2], [2, 3]]]}}
]})";
    }
    const std::string mission =
        kBase + "forbidden:\n  geojson: mission_regions.geojson\n  geojson_coordinates: local\n";
    const MissionSpec m = parseMission(mission, "m.yaml", dir);
    ASSERT_EQ(m.forbidden.obstacles.size(), 1u);
    EXPECT_EQ(m.forbidden.obstacles[0].polygon.name, "Rock");
    EXPECT_EQ(m.forbidden.obstacles[0].polygon.points.size(), 5u);
    EXPECT_FALSE(m.forbidden.obstacles[0].polygon.geographic);
    ASSERT_EQ(m.forbidden.timeWindows.size(), 2u);
    EXPECT_EQ(m.forbidden.timeWindows[1].polygon.name, "Lane #2");
    EXPECT_EQ(m.forbidden.timeWindows[0].windows.size(), 2u);
    ASSERT_EQ(m.forbidden.ice.size(), 1u);
    EXPECT_DOUBLE_EQ(m.forbidden.ice[0].maxSubmergedTime, 2.0);
    // Geographic (default) coordinates need a projection.
    EXPECT_HAS(missionFileErrorOf(kBase + "forbidden:\n  geojson: " + dir + "mission_regions.geojson\n"), "projection");
    {
        std::ofstream f(dir + "mission_bad.geojson");
        f << "{\"type\": \"FeatureCollection\", \"features\": [\n {\"type\": \"Feature\", \"properties\": "
             "{\"nmae\": \"x\"},\n  \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],[1,1]]]}}]}\n";
    }
    const std::string msg = missionFileErrorOf(kBase + "forbidden:\n  geojson: " + dir +
                                               "mission_bad.geojson\n  geojson_coordinates: local\n");
    EXPECT_HAS(msg, "mission_bad.geojson:2:");
    EXPECT_HAS(msg, "features[0].properties.nmae");
}

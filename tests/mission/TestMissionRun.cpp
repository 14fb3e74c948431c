// Tests of runMission() and the pilot outputs: closed-form travel times in a uniform current, round trips of the
// CSV / GeoJSON / goto / summary files, dive profiles, forbidden regions, departure window, NetCDF forecast.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <sstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionOutputs.h"
#include "ompl_glider/mission/MissionRunner.h"
#include "ompl_glider/mission/MissionSpec.h"

using namespace ompl_glider;

namespace
{
const std::string kExamples = std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/";

MissionSpec uniformMission(bool projection)
{
    std::string text = R"(name: uniform
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
vehicle: {speed: 0.5}
planner: {grid_size: 0.5, sectors: 3}
dive_profile: {z_min: 0, z_max: 100, climb_to_max: 20, min_range: 50, climb_to_levels: 2, dive_to_levels: 2, step: 0.25}
)";
    if (projection)
        text += "units: {length_m: 10000, time_s: 3600}\nepoch: \"2026-01-01T00:00:00Z\"\n"
                "projection: {lon0: -60.0, lat0: 45.0}\noutputs: {files: [csv, geojson, goto, summary], goto_number: 3}\n";
    else
        text += "outputs: {files: [csv, geojson, summary]}\n";
    MissionSpec m = parseMission(text, "uniform.yaml");
    m.outputs.directory = ::testing::TempDir() + (projection ? "mission_geo" : "mission_local");
    return m;
}

std::string readFile(const std::string &path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::vector<std::string>> parseCsv(const std::string &text)
{
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line))
    {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream ls(line);
        while (std::getline(ls, cell, ','))
            cells.push_back(cell);
        if (!line.empty() && line.back() == ',')
            cells.push_back("");
        rows.push_back(cells);
    }
    return rows;
}
}  // namespace

TEST(MissionRun, UniformCurrentClosedFormAndOutputsRoundTrip)
{
    const MissionSpec spec = uniformMission(false);
    const MissionResult r = runMission(spec);
    ASSERT_TRUE(r.plan.solved) << r.plan.status;
    // Along x with the current: 8 / (0.5 + 0.1), straight line included.
    EXPECT_NEAR(r.plan.travelTime, 8.0 / 0.6, 1e-9);
    EXPECT_NEAR(r.plan.straightLineTime, 8.0 / 0.6, 1e-9);
    EXPECT_NEAR(r.plan.pathLength, 8.0, 1e-12);
    EXPECT_LE(r.plan.path.size(), r.plan.raw.size());
    for (const auto &w : r.plan.path)
        EXPECT_DOUBLE_EQ(w.y, 0.0);  // the straight line is optimal
    // Dive profiles in a depth-uniform current: exactly the 2-D travel time.
    EXPECT_TRUE(r.diveProfiles);
    EXPECT_NEAR(r.diveTravelTime, r.plan.travelTime, 1e-9);
    ASSERT_EQ(r.waypoints.size(), r.plan.path.size());
    for (std::size_t i = 1; i < r.waypoints.size(); ++i)
        EXPECT_EQ(r.waypoints[i].profile, 0);  // all profiles tie: the first is kept
    EXPECT_FALSE(r.waypoints[0].geographic);

    // CSV round trip.
    ASSERT_EQ(r.files.size(), 3u);
    const auto rows = parseCsv(readFile(spec.outputs.directory + "/mission_waypoints.csv"));
    ASSERT_EQ(rows.size(), r.waypoints.size() + 1);
    EXPECT_EQ(rows[0][0], "index");
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        EXPECT_NEAR(std::stod(rows[i + 1][1]), r.waypoints[i].x, 1e-9);
        EXPECT_NEAR(std::stod(rows[i + 1][2]), r.waypoints[i].y, 1e-9);
        EXPECT_EQ(rows[i + 1][3], "");  // no lon/lat without a projection
        EXPECT_NEAR(std::stod(rows[i + 1][5]), r.waypoints[i].time, 1e-8);
        EXPECT_NEAR(std::stod(rows[i + 1][6]), r.waypoints[i].time, 1e-8);  // time unit 1 s
    }
    EXPECT_EQ(rows[0][6], "time_s");
    EXPECT_EQ(rows[2][9], "0");
    EXPECT_EQ(rows[2][10], "0");
    EXPECT_EQ(rows[2][11], "50");

    // GeoJSON (parsed as YAML, a superset of JSON): local coordinates.
    const YAML::Node g = YAML::LoadFile(spec.outputs.directory + "/mission.geojson");
    EXPECT_EQ(g["type"].as<std::string>(), "FeatureCollection");
    EXPECT_EQ(g["coordinates"].as<std::string>(), "local");
    const std::size_t n = r.waypoints.size();
    ASSERT_EQ(g["features"].size(), n + 1);
    const YAML::Node line = g["features"][0]["geometry"];
    EXPECT_EQ(line["type"].as<std::string>(), "LineString");
    ASSERT_EQ(line["coordinates"].size(), n);
    for (std::size_t i = 0; i < n; ++i)
    {
        EXPECT_NEAR(line["coordinates"][i][0].as<double>(), r.waypoints[i].x, 1e-9);
        EXPECT_NEAR(line["coordinates"][i][1].as<double>(), r.waypoints[i].y, 1e-9);
        const YAML::Node pt = g["features"][i + 1];
        EXPECT_EQ(pt["geometry"]["type"].as<std::string>(), "Point");
        EXPECT_EQ(pt["properties"]["index"].as<std::size_t>(), i);
        EXPECT_NEAR(pt["properties"]["time"].as<double>(), r.waypoints[i].time, 1e-8);
    }
    EXPECT_NEAR(g["features"][n]["properties"]["time"].as<double>(), 8.0 / 0.6, 1e-8);

    // Summary.
    const YAML::Node s = YAML::LoadFile(spec.outputs.directory + "/mission_summary.json");
    EXPECT_TRUE(s["solved"].as<bool>());
    EXPECT_NEAR(s["travel_time"].as<double>(), 8.0 / 0.6, 1e-8);
    EXPECT_NEAR(s["straight_line_travel_time"].as<double>(), 8.0 / 0.6, 1e-8);
    EXPECT_EQ(s["waypoints_final"].as<std::size_t>(), n);
    EXPECT_EQ(s["waypoints_smoothed"].as<std::size_t>(), r.plan.smoothedWaypoints);
    EXPECT_LE(r.plan.smoothedWaypoints, r.plan.raw.size());
    EXPECT_EQ(s["waypoints_raw"].as<std::size_t>(), r.plan.raw.size());
    EXPECT_GT(s["cfc"].as<long>(), 0);
    EXPECT_GT(s["cmc"].as<long>(), 0);
    EXPECT_GE(s["planning_wall_time_s"].as<double>(), 0.0);
    EXPECT_EQ(s["dive_profiles"].size(), 3u);

    // The overload on a problem built beforehand gives the same plan and applies the output-directory override to
    // the result (no files here).
    const MissionProblem problem(spec);
    RunOptions quiet;
    quiet.writeOutputs = false;
    quiet.outputDirectory = spec.outputs.directory + "_other";
    const MissionResult r2 = runMission(problem, quiet);
    ASSERT_TRUE(r2.plan.solved) << r2.plan.status;
    EXPECT_EQ(r2.plan.travelTime, r.plan.travelTime);
    ASSERT_EQ(r2.waypoints.size(), r.waypoints.size());
    for (std::size_t i = 0; i < n; ++i)
    {
        EXPECT_EQ(r2.waypoints[i].x, r.waypoints[i].x);
        EXPECT_EQ(r2.waypoints[i].time, r.waypoints[i].time);
    }
    EXPECT_EQ(r2.spec.name, spec.name);
    EXPECT_EQ(r2.spec.outputs.directory, spec.outputs.directory + "_other");
    EXPECT_TRUE(r2.files.empty());
}

TEST(MissionRun, GeographicOutputsGotoAndIsoTimes)
{
    const MissionSpec spec = uniformMission(true);
    const MissionResult r = runMission(spec);
    ASSERT_TRUE(r.plan.solved);
    ASSERT_TRUE(r.waypoints[0].geographic);
    EXPECT_NEAR(r.waypoints[0].lon, -60.0 + 10000.0 / (111320.0 * std::cos(45.0 * M_PI / 180.0)) * 1.0, 2e-3);
    EXPECT_NEAR(r.waypoints[0].lat, 45.0, 1e-3);
    EXPECT_EQ(r.waypoints[0].iso, "2026-01-01T00:00:00Z");
    // 13.333... hours later.
    EXPECT_EQ(r.waypoints.back().iso, "2026-01-01T13:20:00Z");
    const GotoList back = readGotoFile(spec.outputs.directory + "/goto_l03.ma");
    EXPECT_EQ(back.number, 3);
    ASSERT_EQ(back.waypoints.size(), r.waypoints.size() - 1);  // the start is where the glider already is
    for (std::size_t i = 0; i < back.waypoints.size(); ++i)
    {
        EXPECT_LE(std::abs(back.waypoints[i].lon - r.waypoints[i + 1].lon) * 60, 0.5e-4 + 1e-9);
        EXPECT_LE(std::abs(back.waypoints[i].lat - r.waypoints[i + 1].lat) * 60, 0.5e-4 + 1e-9);
    }
    const YAML::Node g = YAML::LoadFile(spec.outputs.directory + "/mission.geojson");
    EXPECT_FALSE(g["coordinates"]);  // RFC 7946 lon/lat
    const YAML::Node c = g["features"][0]["geometry"]["coordinates"];
    EXPECT_NEAR(c[0][0].as<double>(), r.waypoints[0].lon, 1e-8);
    EXPECT_NEAR(c[0][1].as<double>(), r.waypoints[0].lat, 1e-8);
    EXPECT_EQ(g["features"][r.waypoints.size()]["properties"]["time_iso"].as<std::string>(), "2026-01-01T13:20:00Z");
    EXPECT_NEAR(g["features"][r.waypoints.size()]["properties"]["time_s"].as<double>(), 8.0 / 0.6 * 3600.0, 1e-5);
    // Frame conversions are inverse to each other.
    const MissionProblem problem(spec);
    double x, y;
    problem.toLocal(r.waypoints.back().lon, r.waypoints.back().lat, x, y);
    EXPECT_NEAR(x, 9.0, 1e-9);
    EXPECT_NEAR(y, 0.0, 1e-9);
}

TEST(MissionRun, SpeedSweepClosedForm)
{
    const MissionProblem problem(uniformMission(false));
    const auto rows = speedSweep(problem, 0.0, {0.25, 0.3, 0.35});
    ASSERT_EQ(rows.size(), 3u);
    for (const auto &row : rows)
    {
        EXPECT_TRUE(row.solved);
        EXPECT_NEAR(row.travelTime, 8.0 / (row.speed + 0.1), 1e-9);
        EXPECT_NEAR(row.pathLength, 8.0, 1e-12);
        EXPECT_NEAR(row.straightLineTime, 8.0 / (row.speed + 0.1), 1e-9);
    }
    const std::string table = speedSweepTable(rows);
    EXPECT_NE(table.find("0.25"), std::string::npos);
    EXPECT_NE(table.find("22.85714286"), std::string::npos);  // 8 / 0.35
}

TEST(MissionRun, GulfStreamStraightLineImpassableAndJetFasterThanStill)
{
    MissionSpec spec = defaultGulfStreamMission();
    RunOptions o;
    o.writeOutputs = false;
    const MissionResult r = runMission(spec, o);
    ASSERT_TRUE(r.plan.solved);
    EXPECT_TRUE(std::isinf(r.plan.straightLineTime));
    EXPECT_NE(summaryJson(r).find("\"straight_line_travel_time\": \"impassable\""), std::string::npos);
    EXPECT_LE(r.plan.travelTime, r.plan.rawTravelTime + 1e-12);  // smoothing never arrives later
    EXPECT_LE(r.plan.path.size(), r.plan.raw.size());
    // No path can beat the distance at V + max|c|.
    EXPECT_GE(r.plan.travelTime, std::hypot(spec.goal.x - spec.start.x, spec.goal.y - spec.start.y) / (0.5 + 1.01));
}

TEST(MissionRun, IslandsAndIceAreAvoided)
{
    MissionSpec spec = loadMission(kExamples + "islands_ice.yaml");
    RunOptions o;
    o.writeOutputs = false;
    const MissionResult r = runMission(spec, o);
    ASSERT_TRUE(r.plan.solved) << r.plan.status;
    const MissionProblem problem(spec);
    ASSERT_TRUE(problem.environment());
    const auto &p = r.plan.path;
    for (std::size_t i = 1; i < p.size(); ++i)
        EXPECT_TRUE(problem.environment()->legFree(p[i - 1].x, p[i - 1].y, p[i - 1].t, p[i].x, p[i].y, p[i].t)) << i;
    // The straight line crosses North Island.
    EXPECT_FALSE(problem.environment()->legFree(0.6, -3.2, 0.0, 9.2, 2.8, 20.0));
    EXPECT_EQ(problem.polygons().size(), 4u);
    ASSERT_EQ(r.waypoints.size(), p.size());
    for (std::size_t i = 1; i < r.waypoints.size(); ++i)
        EXPECT_GE(r.waypoints[i].profile, 0);
}

TEST(MissionRun, StartOnAnIslandIsAnOutcomeNotAnException)
{
    MissionSpec spec = loadMission(kExamples + "islands_ice.yaml");
    spec.start.x = 4.5;
    spec.start.y = -0.8;  // inside North Island
    spec.dive.enabled = false;
    RunOptions o;
    o.writeOutputs = false;
    const MissionResult r = runMission(spec, o);
    EXPECT_FALSE(r.plan.solved);
    EXPECT_NE(r.plan.status.find("invalid start"), std::string::npos) << r.plan.status;
    EXPECT_NE(summaryJson(r).find("\"solved\": false"), std::string::npos);
}

TEST(MissionRun, DepartureWindowPicksTheBestSearchedDeparture)
{
    MissionSpec spec = defaultGulfStreamMission();
    spec.departure.window = true;
    spec.departure.begin = 4.0;
    spec.departure.end = 20.0;
    spec.departure.spacing = 1.0;
    spec.departure.tolerance = 0.01;
    spec.departure.threads = 2;
    RunOptions o;
    o.writeOutputs = false;
    const MissionResult r = runMission(spec, o);
    ASSERT_TRUE(r.departureSearch && r.departureSearch->found);
    const DepartureSearchResult &d = *r.departureSearch;
    EXPECT_DOUBLE_EQ(r.plan.departure, d.departure);
    EXPECT_GE(d.departure, 4.0);
    EXPECT_LE(d.departure, 20.0);
    EXPECT_EQ(d.supportingPoints.size(), 17u);
    for (const auto &s : d.supportingPoints)
        EXPECT_GE(s.travelTime, d.travelTime);
    for (const auto &s : d.refinements)
        EXPECT_GE(s.travelTime, d.travelTime);
    // The plan at the chosen departure reproduces the searched travel time (same lattice), then smoothing.
    EXPECT_NEAR(r.plan.rawTravelTime, d.travelTime, 1e-9);
}

TEST(MissionRun, NetCdfForecastMission)
{
    MissionSpec spec = loadMission(kExamples + "labrador_forecast.yaml");
    spec.departure.window = false;
    spec.departure.time = 6 * 3600.0;
    spec.outputs.directory = ::testing::TempDir() + "mission_labrador";
    spec.outputs.files = {"csv", "goto", "summary"};
    const MissionResult r = runMission(spec);
    ASSERT_TRUE(r.plan.solved) << r.plan.status;
    ASSERT_TRUE(r.waypoints.front().geographic);
    EXPECT_NEAR(r.waypoints.front().lon, -52.7, 1e-9);
    EXPECT_NEAR(r.waypoints.front().lat, 47.9, 1e-9);
    EXPECT_NEAR(r.waypoints.back().lon, -51.5, 1e-9);
    EXPECT_NEAR(r.waypoints.back().lat, 48.45, 1e-9);
    EXPECT_EQ(r.waypoints.front().iso, "2026-03-15T06:00:00Z");
    EXPECT_TRUE(std::isfinite(r.diveTravelTime));
    // The trip fits in the 5-day forecast.
    EXPECT_LE(r.waypoints.back().time, 5 * 86400.0);
    const GotoList g = readGotoFile(spec.outputs.directory + "/goto_l13.ma");
    EXPECT_NEAR(g.waypoints.back().lon, -51.5, 1e-9);
    EXPECT_NEAR(g.waypoints.back().lat, 48.45, 1e-9);
}

TEST(MissionRun, MeanderingJetDepartureAgainstBruteForce)
{
    // 000 Sec. 5 on full lattice searches: one flow period (2 pi / 0.4 = 15.7) of departures; the scheme must come
    // within 1 % of a brute-force sweep at spacing 0.05 with at most a fifth of its searches. (A coarser lattice than
    // the benchmark's, to keep the test short; bench_departure runs the 0.4 lattice at spacing 0.02.)
    MissionSpec spec = defaultGulfStreamMission();
    spec.start = {false, 0.5, -3.0};  // bench_departure's default problem
    spec.goal = {false, 9.5, 3.0};
    spec.planner.gridSize = 0.8;
    spec.planner.sectors = 2;
    const MissionProblem problem(spec);
    std::atomic<std::size_t> calls{0};
    const TravelTimeOfDeparture search = problem.departureFunction();
    const TravelTimeOfDeparture f = [&](double t) {
        ++calls;
        return search(t);
    };
    DepartureSearchParams p;
    p.windowBegin = 5.0;
    p.windowEnd = 21.0;
    p.spacing = 0.05;
    const DepartureSearchResult brute = bruteForceDepartureTime(f, p);
    const std::size_t bruteCalls = calls.exchange(0);
    ASSERT_TRUE(brute.found);
    EXPECT_EQ(bruteCalls, 321u);
    p.spacing = 1.0;
    p.tolerance = 1e-3;
    const DepartureSearchResult opt = optimalDepartureTime(f, p);
    ASSERT_TRUE(opt.found);
    EXPECT_EQ(calls.load(), opt.fineEvaluations);
    EXPECT_LE(opt.fineEvaluations * 5, bruteCalls);
    EXPECT_LE(opt.travelTime, 1.01 * brute.travelTime);
    // Interior minimum: not at the window's ends.
    EXPECT_GT(brute.departure, 6.0);
    EXPECT_LT(brute.departure, 20.0);
}

TEST(MissionRun, CarriedIceZone)
{
    MissionSpec spec = loadMission(kExamples + "islands_ice.yaml");
    spec.forbidden.ice[0].carried = true;  // drifts with the jet instead of a constant velocity
    RunOptions o;
    o.writeOutputs = false;
    const MissionResult r = runMission(spec, o);
    ASSERT_TRUE(r.plan.solved) << r.plan.status;
    const MissionProblem problem(spec);
    const auto &p = r.plan.path;
    for (std::size_t i = 1; i < p.size(); ++i)
        EXPECT_TRUE(problem.environment()->legFree(p[i - 1].x, p[i - 1].y, p[i - 1].t, p[i].x, p[i].y, p[i].t)) << i;
}

TEST(MissionRun, ExampleMissionsRunEndToEnd)
{
    for (const char *name : {"gulf_stream_window", "islands_ice", "labrador_forecast"})
    {
        MissionSpec spec = loadMission(kExamples + name + ".yaml");
        RunOptions o;
        o.outputDirectory = ::testing::TempDir() + "mission_example_" + name;
        const MissionResult r = runMission(spec, o);
        EXPECT_TRUE(r.plan.solved) << name << ": " << r.plan.status;
        EXPECT_EQ(r.files.size(), 6u) << name;  // csv, geojson, goto, summary, map svg + png
        for (const auto &f : r.files)
            EXPECT_TRUE(std::ifstream(f).good()) << f;
        // The goto list is the path after the start, as flown.
        const GotoList g = readGotoFile(o.outputDirectory.value() + "/" + gotoFileName(spec.outputs.gotoNumber));
        ASSERT_EQ(g.waypoints.size() + 1, r.waypoints.size()) << name;
        EXPECT_LE(std::abs(g.waypoints.back().lat - r.waypoints.back().lat) * 60, 0.5e-4 + 1e-9);
        if (spec.departure.window)
        {
            ASSERT_TRUE(r.departureSearch);
            EXPECT_GE(r.plan.departure, spec.departure.begin);
            EXPECT_LE(r.plan.departure, spec.departure.end);
        }
    }
}

TEST(MissionRun, CommandEntryPointAndSpeedList)
{
    EXPECT_EQ(parseSpeedList("0.25,0.30, 0.35"), (std::vector<double>{0.25, 0.30, 0.35}));
    EXPECT_THROW(parseSpeedList("0.25,fast"), Error);
    EXPECT_THROW(parseSpeedList("0.25,-1"), Error);
    EXPECT_THROW(parseSpeedList(""), Error);
    // A bad mission: exit code 2 and the message names the file, line and field.
    const std::string path = ::testing::TempDir() + "mission_bad.yaml";
    {
        std::ofstream f(path);
        f << "current: {type: uniform}\nregion: {x_min: 0, x_max: 1, y_min: 0, y_max: 1}\nstart: {x: 0, y: 0}\n"
             "goal: {x: 1, y: 1}\nplanner: {gird_size: 0.1}\n";
    }
    std::ostringstream out, err;
    MissionCommandOptions o;
    o.progress = false;
    EXPECT_EQ(runMissionFile(path, o, out, err), 2);
    EXPECT_NE(err.str().find(path + ":5:"), std::string::npos) << err.str();
    EXPECT_NE(err.str().find("planner.gird_size"), std::string::npos) << err.str();
    // A good one: exit code 0, the report and the speed sweep.
    o.speeds = std::vector<double>{0.4, 0.5};
    o.outputDirectory = ::testing::TempDir() + "mission_cmd";
    std::ostringstream out2, err2;
    EXPECT_EQ(runMissionFile(kExamples + "islands_ice.yaml", o, out2, err2), 0) << err2.str();
    EXPECT_NE(out2.str().find("speed sweep"), std::string::npos);
    EXPECT_NE(out2.str().find("straight line"), std::string::npos);
    EXPECT_NE(out2.str().find("goto_l12.ma"), std::string::npos);
}

// A fleet (mission `fleet`): read with the places of its entries, each glider planned by the one pipeline (the same
// result as its own mission run alone), spread through a TaskSpreader like the threads, and written as one folder
// per glider beside fleet.csv and summary.json, all or nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "ompl_glider/Exception.h"
#include "ReverseSpreader.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/mission/Fleet.h"
#include "ompl_glider/output/FleetFiles.h"
#include "ompl_glider/output/RouteFiles.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
const std::string kFleet = R"(name: f
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
departure: {time: 1}
fleet:
  - {name: east, start: {x: 1, y: 0}, goal: {x: 9, y: 0}}
  - name: west
    start: {x: 9, y: 1}
    goal: {x: 1, y: 1}
    speed: 0.3
  - {name: late, start: {x: 1, y: -2}, goal: {x: 9, y: -2}, departure: 4}
outputs: {directory: out, files: [csv, summary]}
)";

std::string fleetErrorOf(const std::string &text)
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

using test::ReverseSpreader;

std::string read(const fs::path &p)
{
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
} // namespace

TEST(Fleet, ReadWithEachGlidersOwnValuesAndPlaces)
{
    const MissionSpec m = parseMission(kFleet, "m.yaml", "/tmp/fl");
    ASSERT_EQ(m.fleet.size(), 3u);
    EXPECT_EQ(m.start.xy.x, 1.0) << "without a top-level start the first glider's";
    const MissionSpec west = fleetGliderMission(m, 1);
    EXPECT_TRUE(west.fleet.empty());
    EXPECT_EQ(west.name, "west");
    EXPECT_EQ(west.start.xy.x, 9.0);
    EXPECT_EQ(west.goal.xy.y, 1.0);
    EXPECT_EQ(west.vehicle.speed, 0.3);
    EXPECT_EQ(west.departure.time, 1.0);
    EXPECT_EQ(west.outputs.directory, "/tmp/fl/out/west");
    EXPECT_EQ(west.place("start"), "m.yaml:10: field 'start'");
    EXPECT_EQ(west.place("vehicle.speed"), "m.yaml:12: field 'vehicle.speed'");
    const MissionSpec late = fleetGliderMission(m, 2);
    EXPECT_EQ(late.departure.time, 4.0);
    EXPECT_EQ(late.vehicle.speed, 0.5);
    EXPECT_EQ(late.place("departure.time"), "m.yaml:13: field 'departure.time'");
    // the fleet's mission itself is not one plan: runMission() refuses it, naming the field
    const MissionProblem problem(m);
    try
    {
        runMission(problem);
        ADD_FAILURE() << "a fleet planned as one mission";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("m.yaml:8: field 'fleet': a fleet is planned glider by glider"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Fleet, BadEntriesNameTheirLine)
{
    const std::string head = kFleet.substr(0, kFleet.find("fleet:"));
    EXPECT_NE(fleetErrorOf(head + "fleet:\n  - {name: a, start: {x: 1, y: 0}}\n")
                  .find("m.yaml:8: field 'fleet[0].goal': missing"),
              std::string::npos);
    EXPECT_NE(fleetErrorOf(head + "fleet:\n  - {name: a, start: {x: 1, y: 0}, goal: {x: 2, y: 0}}\n"
                                  "  - {name: a, start: {x: 1, y: 1}, goal: {x: 2, y: 1}}\n")
                  .find("m.yaml:9: field 'fleet[1].name': 'a' names another glider"),
              std::string::npos);
    EXPECT_NE(fleetErrorOf(head + "fleet:\n  - {name: ../x, start: {x: 1, y: 0}, goal: {x: 2, y: 0}}\n")
                  .find("field 'fleet[0].name': '../x' is not a folder name"),
              std::string::npos);
    EXPECT_NE(fleetErrorOf(head + "fleet:\n  - {name: a, start: {x: 11, y: 0}, goal: {x: 2, y: 0}}\n")
                  .find("m.yaml:8: field 'fleet[0].start': lies outside the region"),
              std::string::npos);
    EXPECT_NE(fleetErrorOf(head + "fleet: []\n").find("field 'fleet': expected a list of gliders"), std::string::npos);
    EXPECT_NE(fleetErrorOf(head + "fleet:\n  - {name: a, start: {x: 1, y: 0}, goal: {x: 2, y: 0}, colour: red}\n")
                  .find("colour"),
              std::string::npos);
}

TEST(Fleet, AGlidersMissionDoesNotGrowWithTheFleet)
{
    // a glider's mission holds no fleet list and no marks of other entries, so planning a fleet of n gliders costs n
    // times one glider (its mission was once a copy of the whole fleet: quadratic in n)
    const std::string head = kFleet.substr(0, kFleet.find("fleet:"));
    auto fleetOf = [&](std::size_t n) {
        std::string text = head + "fleet:\n";
        for (std::size_t i = 0; i < n; ++i)
            text += "  - {name: g" + std::to_string(i) +
                    ", start: {x: 1, y: 0}, goal: {x: 9, y: " + std::to_string(i % 3) + "}, speed: 0.4}\n";
        return parseMission(text, "m.yaml");
    };
    const MissionSpec small = fleetOf(3), large = fleetOf(3000);
    const MissionSpec a = fleetGliderMission(small, 2), b = fleetGliderMission(large, 2);
    EXPECT_TRUE(a.fleet.empty());
    EXPECT_TRUE(b.fleet.empty());
    EXPECT_EQ(a.marks.size(), b.marks.size());
    for (const auto &[key, mark] : b.marks)
        EXPECT_NE(key.rfind("fleet[", 0), 0u) << key;
    // the glider's own values keep their lines: fleet[2] is on line 10 of either file
    EXPECT_EQ(b.place("vehicle.speed"), "m.yaml:10: field 'vehicle.speed'");
    EXPECT_EQ(b.vehicle.speed, 0.4);
    // beyond the limit the fleet is refused before any plan, naming the field
    std::string huge = head + "fleet:\n";
    for (std::size_t i = 0; i <= 50000; ++i)
        huge += "  - {name: g" + std::to_string(i) + ", start: {x: 1, y: 0}, goal: {x: 9, y: 0}}\n";
    EXPECT_NE(fleetErrorOf(huge).find("field 'fleet': a fleet of 50001 gliders, more than the limit of 50000"),
              std::string::npos);
}

TEST(Fleet, EachGliderIsItsOwnMissionThroughThePipeline)
{
    const MissionSpec m = parseMission(kFleet, "m.yaml", "/tmp/fl");
    const auto keep = [](const MissionResult &r, const MissionProblem &) { return waypointsCsv(r); };
    const std::vector<FleetGlider> threads = runFleet(m, {}, keep);
    ASSERT_EQ(threads.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
    {
        const MissionSpec spec = fleetGliderMission(m, i);
        const MissionProblem problem(spec);
        const MissionResult alone = runMission(problem);
        ASSERT_TRUE(alone.plan.solved) << i;
        EXPECT_TRUE(threads[i].row.solved);
        EXPECT_EQ(threads[i].row.name, spec.name);
        EXPECT_EQ(threads[i].row.travelTime, alone.plan.travelTime) << i;
        EXPECT_EQ(threads[i].row.pathLength, alone.plan.pathLength) << i;
        EXPECT_EQ(threads[i].row.arrival, alone.waypoints.back().time) << i;
        EXPECT_EQ(threads[i].kept, waypointsCsv(alone)) << i;
    }
    // against the current at 0.3 the west glider is slower than the east one at 0.5 with it
    EXPECT_GT(threads[1].row.travelTime, 2.0 * threads[0].row.travelTime);
    EXPECT_EQ(threads[2].row.departure, 4.0);
    // spread over "two processes", only bytes coming back: the same rows and files
    auto spread = std::make_shared<ReverseSpreader>();
    setTaskSpreader(spread);
    const std::vector<FleetGlider> two = runFleet(m, {}, keep);
    setTaskSpreader(nullptr);
    EXPECT_EQ(spread->runs, std::vector<std::string>{"fleet glider x3"});
    for (std::size_t i = 0; i < 3; ++i)
    {
        EXPECT_EQ(two[i].row.travelTime, threads[i].row.travelTime);
        EXPECT_EQ(two[i].row.arrival, threads[i].row.arrival);
        EXPECT_EQ(two[i].kept, threads[i].kept);
    }
}

TEST(Fleet, BadInputOfOneGliderNamesItsEntry)
{
    std::string text = kFleet;
    text.replace(text.find("planner:"), 0,
                 "forbidden:\n  obstacles:\n    - {name: rock, kind: island, points: [[0.5, -2.5], [1.5, -2.5], "
                 "[1.5, -1.5], [0.5, -1.5]]}\n");
    const MissionSpec m = parseMission(text, "m.yaml", "/tmp/fl");
    const std::vector<FleetGlider> g = runFleet(m, {});
    EXPECT_TRUE(g[0].row.badInput.empty());
    EXPECT_TRUE(g[0].row.solved);
    EXPECT_FALSE(g[2].row.solved);
    EXPECT_EQ(g[2].row.badInput, "m.yaml:16: field 'start'") << g[2].row.reason;
}

TEST(Fleet, OneFolderPerGliderAllOrNothing)
{
    const fs::path dir = fs::temp_directory_path() / ("fleet_test_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    MissionSpec m = parseMission(kFleet, "m.yaml", dir.string());
    const std::vector<FleetGlider> g = runFleet(m, {}, renderOutputFiles);
    writeOutputFiles(m.outputs.directory, fleetOutputFiles(m, g, 1.0));
    const fs::path out = dir / "out";
    for (const char *name : {"east", "west", "late"})
    {
        EXPECT_TRUE(fs::is_regular_file(out / name / "waypoints.csv")) << name;
        const auto s = nlohmann::json::parse(read(out / name / "summary.json"));
        EXPECT_EQ(s["mission"], name);
    }
    const std::string csv = read(out / "fleet.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
    EXPECT_EQ(csv.rfind("name,status,travel_time,path_length", 0), 0u);
    const auto top = nlohmann::json::parse(read(out / "summary.json"));
    ASSERT_EQ(top["fleet"].size(), 3u);
    EXPECT_EQ(top["fleet"][1]["name"], "west");
    EXPECT_EQ(top["fleet"][1]["travel_time"].get<double>(), g[1].row.travelTime);
    EXPECT_EQ(top["gliders_with_route"], 3);
    // a second run with two gliders replaces the folder: no stale glider left
    m.fleet.pop_back();
    const std::vector<FleetGlider> g2 = runFleet(m, {}, renderOutputFiles);
    writeOutputFiles(m.outputs.directory, fleetOutputFiles(m, g2, 1.0));
    EXPECT_FALSE(fs::exists(out / "late"));
    EXPECT_TRUE(fs::is_regular_file(out / "west" / "summary.json"));
    // a file where a glider's folder goes: refused, nothing replaced
    fs::remove_all(out / "west");
    std::ofstream(out / "west") << "not a folder";
    std::ofstream(out / "mine.txt") << "the user's";
    EXPECT_THROW(writeOutputFiles(m.outputs.directory, fleetOutputFiles(m, g2, 1.0)), Error);
    EXPECT_EQ(read(out / "west"), "not a folder");
    EXPECT_TRUE(fs::is_regular_file(out / "east" / "summary.json"));
    // file by file into a folder holding the user's files: the gliders' folders are made
    fs::remove(out / "west");
    writeOutputFiles(m.outputs.directory, fleetOutputFiles(m, g2, 1.0));
    EXPECT_TRUE(fs::is_regular_file(out / "west" / "waypoints.csv"));
    EXPECT_EQ(read(out / "mine.txt"), "the user's");
    fs::remove_all(dir);
}

// The stint planners through the one pipeline: mission files with a `stints` section, summary.json's
// remaining_distance and bearings, stints.csv, errors naming file:line and field, and lattice paths flown as stints
// on the jet problems of test_planner_vs_optimum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SummaryJson.h"

using namespace ompl_glider;

namespace
{
/// The jet with one length unit of 10 km and one time unit of 12500 s: V = 0.5 is 0.4 m/s, 8 h stints are 2.304
/// time units, 4 days 27.648. An island lies across the straight line.
std::string stintMission(const std::string &planner, const std::string &extra = "")
{
    return R"(name: stints
units: {length_m: 10000, time_s: 12500}
current: {type: meandering_jet}
region: {x_min: 0, x_max: 30, y_min: -6, y_max: 6}
start: {x: 1, y: -3}
goal: {x: 22, y: 2}
vehicle: {speed: 0.5}
forbidden:
  obstacles:
    - name: Isle
      points: [[8, -2], [10, -2], [10, 0.5], [8, 0.5]]
planner:
  name: )" +
           planner + R"(
stints:
  duration: 2.304
  mission_duration: 27.648
  bearing_step: 20
)" + extra;
}
} // namespace

TEST(StintMissions, EveryStintPlannerFliesTheMissionThroughThePipeline)
{
    std::map<std::string, double> remaining;
    for (const std::string name : {"direct", "cts_astar", "optim", "init_optim"})
    {
        const MissionProblem problem(parseMission(stintMission(name), "s.yaml"));
        const MissionResult r = runMission(problem);
        ASSERT_TRUE(r.plan.solved) << name << ": " << r.plan.reason;
        ASSERT_TRUE(r.plan.stints.has_value());
        const StintOutcome &s = *r.plan.stints;
        EXPECT_FALSE(s.converted);
        const Point2 g = problem.getGoal();
        const TimedPoint &last = s.plan.surfacings.back();
        EXPECT_NEAR(s.plan.remainingDistance, std::hypot(g.x - last.x, g.y - last.y), 1e-12);
        if (!s.plan.grounded)
        {
            EXPECT_EQ(s.plan.bearings.size(), 12u) << name; // 4 days of 8 h stints
            EXPECT_NEAR(last.t, 27.648, 1e-9);
        }
        EXPECT_EQ(r.plan.path.size(), s.plan.surfacings.size());
        remaining[name] = s.plan.cost;
        // summary.json: remaining_distance and one bearing per stint, in degrees in [0, 360)
        const nlohmann::json j = nlohmann::json::parse(summaryJson(r, problem, {"summary.json"}));
        EXPECT_DOUBLE_EQ(j["remaining_distance"].get<double>(), s.plan.remainingDistance);
        ASSERT_EQ(j["bearings"].size(), s.plan.bearings.size());
        for (const auto &b : j["bearings"])
        {
            EXPECT_GE(b.get<double>(), 0.0);
            EXPECT_LT(b.get<double>(), 360.0);
        }
        // stints.csv: a header and one row per stint
        const std::string csv = stintsCsv(r, problem);
        EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), s.plan.bearings.size() + 1);
    }
    // direct to goal meets the island; the optimisers do not do worse than their start
    EXPECT_LE(remaining["optim"], remaining["direct"]);
    EXPECT_LE(remaining["init_optim"], remaining["cts_astar"]);
}

TEST(StintMissions, AStintPlannerNeedsTheStintsSection)
{
    const std::string yaml = R"(name: s
current: {type: meandering_jet}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: -3}
goal: {x: 8, y: 3}
planner:
  name: init_optim
)";
    try
    {
        parseMission(yaml, "s.yaml");
        FAIL() << "accepted a stint planner without stints";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("s.yaml:7: field 'planner.name'"), std::string::npos) << e.what();
    }
    for (const auto &[extra, field] : std::vector<std::pair<std::string, std::string>>{
             {"stints: {duration: 0, mission_duration: 3}", "stints.duration"},
             {"stints: {duration: 1, mission_duration: -3}", "stints.mission_duration"},
             {"stints: {mission_duration: 3}", "stints.duration"},
             {"stints: {duration: 1, mission_duration: 3, bearing_step: 270}", "stints.bearing_step"},
             {"stints: {duration: 1, mission_duration: 3, objective: fastest}", "stints.objective"},
             {"stints: {duration: 1, mission_duration: 3, objective: earliest_arrival}", "stints.radius"},
             {"stints: {duration: 1, mission_duration: 3, heading: 4}", "stints.heading"}})
    {
        try
        {
            parseMission(yaml + extra + "\n", "s.yaml");
            FAIL() << "accepted " << extra;
        }
        catch (const Error &e)
        {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind("s.yaml:8: ", 0), 0u) << what;
            EXPECT_NE(what.find("'" + field + "'"), std::string::npos) << what;
        }
    }
}

TEST(StintMissions, LatticePathsFlownAsOneHourStintsLoseUnderTwoPercent)
{
    // the unstarred jet problems of test_planner_vs_optimum; 1 h = 3600 / 12500 time units (V = 0.5 is 0.4 m/s
    // with 10 km per length unit)
    const double hour = 3600.0 / 12500.0;
    for (const auto &[sx, sy, gx, gy] :
         {std::array<double, 4>{1.0, -3.0, 8.0, 3.0}, std::array<double, 4>{1.0, 3.0, 9.0, -2.5},
          std::array<double, 4>{2.0, -3.5, 7.0, 3.5}, std::array<double, 4>{0.5, -2.0, 9.5, 2.0},
          std::array<double, 4>{2.0, 3.5, 8.0, -3.5}, std::array<double, 4>{0.5, 3.0, 5.0, -3.0}})
    {
        MissionSpec m = defaultGulfStreamMission();
        m.start.xy = {sx, sy};
        m.goal.xy = {gx, gy};
        m.stints.set = true;
        m.stints.duration = hour;
        m.stints.missionDuration = 40.0;
        const MissionProblem problem(m);
        const PlannedPath p = planRoute(problem, 0.0);
        ASSERT_TRUE(p.solved);
        ASSERT_TRUE(p.stints.has_value());
        const StintOutcome &s = *p.stints;
        EXPECT_TRUE(s.converted);
        ASSERT_TRUE(s.plan.reached) << sx << "," << sy;
        EXPECT_FALSE(s.plan.grounded);
        EXPECT_NEAR(s.pathTravelTime, p.travelTime, 1e-12);
        EXPECT_LT(s.loss, 0.02) << sx << "," << sy << " -> " << gx << "," << gy;
        // nor beat the optimal-control optimum by more than the goal radius (1e-4 of the distance) and the
        // tolerances of the shooting allow
        const OptimumReference opt = optimumReference(problem, 0.0, 0.5, 1.2 * p.travelTime);
        ASSERT_TRUE(opt.found);
        EXPECT_GT(s.stintTravelTime, opt.travelTime * (1.0 - 1e-3));
        std::printf("(%.1f, %.1f) -> (%.1f, %.1f): path %.4f, 1 h stints %.4f (%zu), loss %+.2f %%, optimum %.4f\n", sx,
                    sy, gx, gy, p.travelTime, s.stintTravelTime, s.plan.bearings.size(), 100.0 * s.loss,
                    opt.travelTime);
    }
}

TEST(StintMissions, TheExampleWritesItsHeadingTableSummaryAndMap)
{
    MissionSpec spec = loadMission(std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/stints_jet.yaml");
    const std::string dir = ::testing::TempDir() + "/stints_example";
    spec.outputs.directory = dir;
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved);
    ASSERT_TRUE(r.plan.stints.has_value());
    const std::vector<std::string> written = writeOutputs(r, problem);
    auto read = [&](const std::string &name) {
        std::ifstream in(dir + "/" + name);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    const std::string csv = read("stints.csv");
    EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')),
              r.plan.stints->plan.bearings.size() + 1);
    EXPECT_NE(csv.find("2026-04-01T08:00:00Z"), std::string::npos); // the second surfacing, 8 h after the epoch
    const nlohmann::json j = nlohmann::json::parse(read("summary.json"));
    EXPECT_DOUBLE_EQ(j["remaining_distance"].get<double>(), r.plan.stints->plan.remainingDistance);
    EXPECT_EQ(j["bearings"].size(), 12u);
    EXPECT_FALSE(read("map.png").empty());
    // without a stints section there is no heading table, even when asked for
    MissionSpec plain = defaultGulfStreamMission();
    plain.outputs.files = {OutputFormatId::Summary, OutputFormatId::Stints};
    const MissionProblem pp(plain);
    const MissionResult pr = runMission(pp);
    for (const OutputFile &f : outputFiles(pr, pp))
        EXPECT_NE(f.name, "stints.csv");
}

// Why a flown run does not count as reached, said in the execution's outputs: a station reached after its window
// (also when the run ended inside the goal's radius); nothing for a run reached; the report's table says its distance
// is the one at the planned arrival, execution.csv's header too.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/ExecutionFiles.h"
#include "ompl_glider/output/Report.h"

using namespace ompl_glider;

namespace
{
/// The uniform stations mission (1 km / 1 h units): the forecast's current u = 0.1, the truth's @p truthU; B's window
/// [5, 14] h; flown by greedy and current_blind.
MissionSpec reasonsMission(double truthU, bool stations)
{
    std::string yaml = R"(name: reasons
units: {length_m: 1000, time_s: 3600}
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 14, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
)";
    if (stations)
        yaml += R"(waypoints:
  - {name: A, x: 4, y: 0, radius: 0.1, stay: 2}
  - {name: B, x: 7, y: 0, radius: 0.1, arrive: {begin: 5, end: 14}}
)";
    yaml += R"(goal: {x: 12, y: 0}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
execution:
  truth: {type: uniform, parameters: {u: )" +
            std::to_string(truthU) + R"(, v: 0.0}}
  surfacing_interval: 15 min
  strategies: [greedy, current_blind]
  radius: 0.2
)";
    return parseMission(yaml, "m.yaml");
}
} // namespace

TEST(ExecutionReasons, AStationReachedAfterItsWindowIsSaidAlsoWhenTheRunEndedInTheGoalsRadius)
{
    // in the truth (u = -0.1) the glider makes 0.4 over ground: A's radius at 2.9 / 0.4 = 7.25 h, a stay of 2 h, B's
    // at 9.25 + 7.25 = 16.5 h, after B's window closed at 14 h; then on to the goal, inside its radius by 28.75 h
    const MissionProblem problem(reasonsMission(-0.1, true));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const ExecutionResult &e = *r.execution;
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const FlownTrack &f = e.runs[0].flown[k];
        EXPECT_FALSE(f.reached);
        EXPECT_EQ(f.windowsMissed, 1u);
        EXPECT_NEAR(f.arrivalTime, 16.5 + (12.0 - 0.2 - 6.9) / 0.4, 0.3); // inside the goal's radius
        EXPECT_NE(f.notReachedWhy.find("station B reached t = 16."), std::string::npos) << f.notReachedWhy;
        EXPECT_NE(f.notReachedWhy.find("after its window closed at t = 14"), std::string::npos) << f.notReachedWhy;
        EXPECT_NE(f.notReachedWhy.find("the run ended inside the goal's radius"), std::string::npos) << f.notReachedWhy;
    }
    std::ostringstream report;
    printReport(report, r);
    EXPECT_NE(report.str().find("at planned arr."), std::string::npos) << report.str();
    EXPECT_NE(report.str().find("not reached       greedy: station B reached"), std::string::npos) << report.str();
    const std::string csv = executionCsv(e, problem);
    const std::string header = csv.substr(0, csv.find('\n'));
    EXPECT_NE(header.find(",distance_at_planned_arrival,"), std::string::npos) << header;
    EXPECT_NE(header.find(",why_not_reached,"), std::string::npos) << header;
    EXPECT_NE(csv.find(",station B reached t = 16."), std::string::npos) << csv;
}

TEST(ExecutionReasons, ARunReachedSaysNothing)
{
    const MissionResult same = runMission(MissionProblem(reasonsMission(0.1, false)));
    ASSERT_TRUE(same.execution.has_value());
    for (const FlownTrack &f : same.execution->runs[0].flown)
    {
        EXPECT_TRUE(f.reached);
        EXPECT_EQ(f.notReachedWhy, "");
    }
}

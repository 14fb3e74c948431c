// The oracle of an execution: each run's pair planned on the truth and flown in it with the truth as its forecast,
// and every strategy's arrival over the oracle's (ExecutionResult::oracle, StrategySpread::overOracle): the closed
// form in a uniform truth, the same as the pair flown where the truth is the forecast, the spread of the listed
// ratios, and nothing where the truth is the forecast.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/ExecutionFiles.h"
#include "ompl_glider/output/Report.h"
#include "ompl_glider/output/SummaryJson.h"

using namespace ompl_glider;

namespace
{
// Forecast u = 0.1, truth u = 0.3 along the route from (1, 0) to (9, 0), departing at 2: no cross current, so the
// oracle and every strategy head +x and make good V + 0.3 = 0.8.
const std::string kUniform = R"(name: uniform
units: {length_m: 1000, time_s: 3600}
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
departure: {time: 2}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
)";

/// The q-quantile of @p v by linear interpolation between order statistics, written out again here.
double quantile(std::vector<double> v, double q)
{
    std::sort(v.begin(), v.end());
    const double pos = q * static_cast<double>(v.size() - 1);
    const std::size_t lo = static_cast<std::size_t>(pos), hi = std::min(lo + 1, v.size() - 1);
    return v[lo] * (1.0 - (pos - static_cast<double>(lo))) + v[hi] * (pos - static_cast<double>(lo));
}
} // namespace

// The oracle reaches the radius R = 0.2 at 2 + (8 - R) / 0.8 (to the integration's accuracy); every strategy flies
// the same straight line at the same speed, so each arrives over the oracle's in a ratio of 1.
TEST(ExecutionOracle, UniformTruthOracleInClosedFormAndRatioOne)
{
    const MissionSpec spec = parseMission(kUniform + R"(execution:
  truth: {type: uniform, parameters: {u: 0.3, v: 0.0}}
  surfacing_interval: 15 min
  strategies: [current_sensitive, current_blind, greedy]
  radius: 0.2
)",
                                          "m.yaml");
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_TRUE(r.execution.has_value());
    const ExecutionResult &e = *r.execution;
    ASSERT_TRUE(e.oracle);
    const ExecutionRun &run = e.runs.at(0);
    EXPECT_EQ(run.departure, 2.0);
    EXPECT_NEAR(run.oracleArrival, 2.0 + 7.8 / 0.8, 1e-6);
    EXPECT_NEAR(r.plan.travelTime, 8.0 / 0.6, 1e-3); // the forecast's plan: slower than the truth carries it
    EXPECT_GT(run.oracleSeconds, 0.0);
    EXPECT_EQ(e.oracleSeconds, run.oracleSeconds);
    ASSERT_EQ(e.spread.size(), 3u);
    for (const StrategySpread &s : e.spread)
    {
        ASSERT_EQ(s.overOracle.count, 1u) << s.strategy;
        EXPECT_NEAR(s.overOracle.median, 1.0, 1e-6) << s.strategy;
        EXPECT_NEAR(s.overOracle.q3, 1.0, 1e-6) << s.strategy;
    }
    // the outputs: summary.json, execution.csv's column, the report's table
    const nlohmann::json j = nlohmann::json::parse(summaryJson(r, problem, {}));
    const nlohmann::json &x = j.at("execution");
    EXPECT_NEAR(x.at("oracle").at("arrival_time").get<double>(), 2.0 + 7.8 / 0.8, 1e-6);
    EXPECT_EQ(x.at("oracle").at("runs_reached"), 1);
    EXPECT_EQ(x.at("greedy").at("batch").at("over_oracle").at("count"), 1);
    EXPECT_NEAR(x.at("greedy").at("batch").at("over_oracle").at("median").get<double>(), 1.0, 1e-6);
    const std::string csv = executionCsv(e, problem);
    const std::string header = csv.substr(0, csv.find('\n'));
    EXPECT_EQ(header.substr(header.rfind(',') + 1), "oracle_arrival");
    const std::string row = csv.substr(header.size() + 1, csv.find('\n', header.size() + 1) - header.size() - 1);
    EXPECT_NEAR(std::stod(row.substr(row.rfind(',') + 1)), 2.0 + 7.8 / 0.8, 1e-6);
    EXPECT_EQ(std::count(row.begin(), row.end(), ','), std::count(header.begin(), header.end(), ','));
    std::ostringstream report;
    printReport(report, r);
    // the last column's heading on the table's two heading lines: "over oracle", then "median / q3 (runs)"
    EXPECT_NE(report.str().find("  over oracle\n"), std::string::npos) << report.str();
    EXPECT_NE(report.str().find("  median / q3 (runs)\n"), std::string::npos) << report.str();
    EXPECT_NE(report.str().find("1.000 / 1.000 (1)"), std::string::npos) << report.str();
}

// The truth is the forecast: there is no oracle to compute, and no field says there is.
TEST(ExecutionOracle, NoneWhereTheTruthIsTheForecast)
{
    const MissionSpec spec =
        parseMission(kUniform + "execution: {strategies: [current_sensitive], radius: 0.2}\n", "m.yaml");
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.execution.has_value());
    const ExecutionResult &e = *r.execution;
    EXPECT_FALSE(e.oracle);
    EXPECT_TRUE(std::isnan(e.runs[0].oracleArrival));
    EXPECT_EQ(e.oracleSeconds, 0.0);
    EXPECT_EQ(e.spread[0].overOracle.count, 0u);
    const nlohmann::json j = nlohmann::json::parse(summaryJson(r, problem, {}));
    EXPECT_TRUE(j.at("execution").at("oracle").is_null());
    EXPECT_TRUE(j.at("execution").at("current_sensitive").at("batch").at("over_oracle").is_null());
    const std::string csv = executionCsv(e, problem);
    EXPECT_EQ(csv.substr(csv.size() - 2), ",\n"); // the column is there, empty
    std::ostringstream report;
    printReport(report, r);
    EXPECT_EQ(report.str().find("oracle"), std::string::npos) << report.str();
}

// A mission of several legs: the oracle flies the stations in turn as the strategies do. In the truth's 0.3 along
// the axis, B's window opening at 15 holds every flight there; the last leg from B's radius (x = 6.9) to the
// goal's (x = 11.8) then takes 4.9 / 0.8.
TEST(ExecutionOracle, StationsInTurnOracleInClosedForm)
{
    const MissionSpec spec = parseMission(R"(name: legs
units: {length_m: 1000, time_s: 3600}
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 14, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
waypoints:
  - {name: A, x: 4, y: 0, radius: 0.1, stay: 2}
  - {name: B, x: 7, y: 0, radius: 0.1, arrive: {begin: 15, end: 40}}
goal: {x: 12, y: 0}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
execution:
  truth: {type: uniform, parameters: {u: 0.3, v: 0.0}}
  surfacing_interval: 15 min
  strategies: [greedy]
  radius: 0.2
)",
                                          "m.yaml");
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const ExecutionResult &e = *r.execution;
    ASSERT_TRUE(e.oracle);
    EXPECT_NEAR(e.runs[0].oracleArrival, 15.0 + (12.0 - 6.9 - 0.2) / 0.8, 1e-3);
    // greedy heads for each station at full speed: the oracle's time (a ratio of 1)
    ASSERT_EQ(e.spread[0].overOracle.count, 1u);
    EXPECT_NEAR(e.spread[0].overOracle.median, 1.0, 1e-3 / 21.0);
}

// On the jet with a batch: each run's oracle arrival is the arrival of the same pair planned and flown by
// current_sensitive where the truth is the forecast (to the bit), and each strategy's median and q3 are those of the
// ratios listed from the runs.
TEST(ExecutionOracle, JetBatchOracleIsThePairFlownInTheTruthAndSpreadOfTheRatios)
{
    MissionSpec spec = defaultGulfStreamMission();
    spec.planner.globalCheck = false; // quicker; the same for the runs and the oracle
    spec.execution.enabled = true;
    spec.execution.surfacingInterval = 0.25;
    spec.execution.strategies = {"current_sensitive", "current_blind", "greedy"};
    spec.execution.truth = spec.current;
    spec.execution.truth->parameters["B0"] = 1.38;
    spec.execution.truth->parameters["c"] = 0.138;
    spec.execution.radius = 0.1;
    spec.execution.pairs = 6;
    spec.execution.seed = 3;
    spec.execution.minDistance = 3.0;
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    const ExecutionResult &e = *r.execution;
    ASSERT_TRUE(e.oracle);
    ASSERT_EQ(e.runs.size(), 7u);

    // the truth as the forecast and as the truth: the same pairs (every point of an analytic flow is water)
    MissionSpec onTruth = spec;
    onTruth.current = *spec.execution.truth;
    onTruth.execution.truth.reset();
    onTruth.execution.strategies = {"current_sensitive"};
    const MissionProblem twin(onTruth);
    const MissionResult t = runMission(twin);
    ASSERT_EQ(t.execution->runs.size(), 7u);
    std::size_t oracleReached = 0;
    for (std::size_t i = 0; i < 7; ++i)
    {
        const ExecutionRun &a = e.runs[i], &b = t.execution->runs[i];
        ASSERT_EQ(a.start.x, b.start.x);
        ASSERT_EQ(a.goal.y, b.goal.y);
        const double twinArrival = b.planned && b.flown[0].reached ? b.flown[0].arrivalTime : std::nan("");
        if (std::isnan(twinArrival))
            EXPECT_TRUE(std::isnan(a.oracleArrival)) << "run " << i;
        else
            EXPECT_EQ(a.oracleArrival, twinArrival) << "run " << i;
        oracleReached += std::isfinite(a.oracleArrival) ? 1 : 0;
    }
    EXPECT_GE(oracleReached, 4u);                // the truth flown with the truth as its forecast reaches most goals
    EXPECT_GE(e.spread[0].overOracle.count, 3u); // enough ratios for the quartiles to interpolate

    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        std::vector<double> ratios;
        for (const ExecutionRun &run : e.runs)
            if (run.planned && run.flown[k].reached && std::isfinite(run.oracleArrival))
                ratios.push_back((run.flown[k].arrivalTime - run.departure) / (run.oracleArrival - run.departure));
        const MeasureSpread &s = e.spread[k].overOracle;
        ASSERT_EQ(s.count, ratios.size()) << e.spread[k].strategy;
        if (ratios.empty())
            continue;
        EXPECT_DOUBLE_EQ(s.median, quantile(ratios, 0.5)) << e.spread[k].strategy;
        EXPECT_DOUBLE_EQ(s.q3, quantile(ratios, 0.75)) << e.spread[k].strategy;
        for (double x : ratios)
            EXPECT_GT(x, 0.5) << e.spread[k].strategy; // no flight arrives in half the oracle's time
    }
}

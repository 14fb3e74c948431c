// A mission's execution in another ocean through the one pipeline: the `execution` section, the truth
// on the forecast's frame and dates, runMission() flying the plan with each strategy, the batch, the output files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../current/MultiFileForecast.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/ShiftedTimeField.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
// Uniform current along +x, goal straight downstream: every strategy flies the x axis, in closed form.
const std::string kUniformExecution = R"(name: uniform
units: {length_m: 1000, time_s: 3600}
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
vehicle: {speed: 0.5}
planner: {name: zastartve, grid_size: 0.5}
)";

std::string executionMessageOf(const std::string &yaml)
{
    try
    {
        parseMission(yaml, "m.yaml");
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

const FlownTrack &flown(const ExecutionResult &e, std::size_t run, ControlStrategy s)
{
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
        if (e.strategies[k] == s)
            return e.runs.at(run).flown.at(k);
    throw std::runtime_error("strategy not flown");
}
} // namespace

TEST(MissionExecution, SectionIsReadWithUnitsAndDefaults)
{
    const MissionSpec m = parseMission(kUniformExecution + R"(execution:
  truth: {type: uniform, parameters: {u: 0.2, v: 0.0}}
  surfacing_interval: 30 min
  strategies: [greedy, current_sensitive]
  radius: 0.25
  replan_every: 3
  batch: {pairs: 4, seed: 7, min_distance: 2, threads: 2}
)",
                                       "m.yaml");
    const ExecutionSpec &e = m.execution;
    ASSERT_TRUE(e.enabled);
    ASSERT_TRUE(e.truth.has_value());
    EXPECT_EQ(e.truth->type, "uniform");
    EXPECT_DOUBLE_EQ(e.truth->parameters.at("u"), 0.2);
    EXPECT_DOUBLE_EQ(e.surfacingInterval, 0.5); // 30 min in hours (time_s 3600)
    EXPECT_EQ(e.strategies, (std::vector<std::string>{"greedy", "current_sensitive"}));
    EXPECT_DOUBLE_EQ(e.radius, 0.25);
    EXPECT_EQ(e.replanEvery, 3u);
    EXPECT_EQ(e.pairs, 4u);
    EXPECT_EQ(e.seed, 7u);
    EXPECT_DOUBLE_EQ(e.minDistance, 2.0);
    EXPECT_EQ(e.threads, 2u);

    const MissionSpec d = parseMission(kUniformExecution + "execution: {truth: forecast}\n", "m.yaml");
    EXPECT_TRUE(d.execution.enabled);
    EXPECT_FALSE(d.execution.truth.has_value());
    EXPECT_EQ(d.execution.strategies.size(), 4u);
    EXPECT_TRUE(std::isnan(d.execution.surfacingInterval)); // one hour, resolved when flying
    EXPECT_FALSE(parseMission(kUniformExecution, "m.yaml").execution.enabled);
}

TEST(MissionExecution, BadSectionsNameFileLineAndField)
{
    const std::string noUnits = R"(name: nounits
current: {type: uniform, parameters: {u: 0.1, v: 0.0}}
region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}
start: {x: 1, y: 0}
goal: {x: 9, y: 0}
)";
    struct Case
    {
        std::string yaml, phrase;
    };
    const Case cases[] = {
        {kUniformExecution + "execution: {surfacing: 1}\n", "m.yaml:9: unknown field 'execution.surfacing'"},
        {kUniformExecution + "execution: {strategies: [current_sensitive, zigzag]}\n",
         "m.yaml:9: field 'execution.strategies[1]'"},
        {kUniformExecution + "execution: {strategies: [greedy, greedy]}\n", "listed twice"},
        {kUniformExecution + "execution: {strategies: []}\n", "field 'execution.strategies'"},
        {kUniformExecution + "execution: {surfacing_interval: -1}\n", "field 'execution.surfacing_interval'"},
        {kUniformExecution + "execution: {surfacing_interval: 1 fortnight}\n", "field 'execution.surfacing_interval'"},
        {kUniformExecution + "execution: {surfacing_interval: nan}\n", "field 'execution.surfacing_interval'"},
        {noUnits + "execution: {surfacing_interval: 1 h}\n", "needs the mission's time unit"},
        {kUniformExecution + "execution: {radius: 0}\n", "field 'execution.radius'"},
        {kUniformExecution + "execution: {replan_every: 0}\n", "field 'execution.replan_every'"},
        {kUniformExecution + "execution: {truth: {type: netcdf, file: x.nc}}\n", "field 'execution.truth"},
        {kUniformExecution + "execution: {truth: {type: vortex}}\n", "field 'execution.truth.type'"},
        {kUniformExecution + "execution: {truth: {type: uniform, parameters: {w: 1}}}\n",
         "field 'execution.truth.parameters.w'"},
        {kUniformExecution + "execution: {truth: nowcast}\n", "field 'execution.truth'"},
        {kUniformExecution + "execution: {batch: {pairs: -3}}\n", "field 'execution.batch.pairs'"},
        {kUniformExecution + "execution: {batch: {size: 3}}\n", "field 'execution.batch.size'"},
    };
    for (const Case &c : cases)
    {
        const std::string msg = executionMessageOf(c.yaml);
        EXPECT_NE(msg.find(c.phrase), std::string::npos) << c.yaml << "\n-> " << msg;
    }
}

TEST(MissionExecution, ShiftedTimeFieldReadsTheInnerFieldAtTheShiftedTime)
{
    const auto jet = makeAnalyticField("meandering_jet", {});
    const ShiftedTimeField s(jet, 2.5);
    for (double t : {0.0, 1.0, 7.3})
    {
        const Velocity a = s.velocity(3.0, 0.5, 0.0, t), b = jet->velocity(3.0, 0.5, 0.0, t + 2.5);
        EXPECT_EQ(a.u, b.u);
        EXPECT_EQ(a.v, b.v);
        const Velocity c = jet->velocity(3.0, 0.5, 0.0, t);
        EXPECT_NE(a.u, c.u); // the jet is time-dependent: the shift matters
    }
    EXPECT_THROW(ShiftedTimeField(jet, std::nan("")), Error);
    EXPECT_THROW(ShiftedTimeField(nullptr, 1.0), Error);
}

// Forecast u = 0.1, truth u = 0.3 along the route: the glider makes good V + 0.3 instead of V + 0.1 with every
// strategy (no cross current: every heading is +x), so it reaches the radius R at (d - R) / (V + 0.3), before the
// planned arrival d / (V + 0.1); the run ends there, within R of the goal.
TEST(MissionExecution, UniformTruthArrivesAtTheClosedFormTime)
{
    const MissionSpec spec = parseMission(kUniformExecution + R"(execution:
  truth: {type: uniform, parameters: {u: 0.3, v: 0.0}}
  surfacing_interval: 15 min
  strategies: [current_sensitive, current_blind, greedy, replan]
  radius: 0.2
)",
                                          "m.yaml");
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved);
    ASSERT_TRUE(r.execution.has_value());
    const ExecutionResult &e = *r.execution;
    ASSERT_EQ(e.runs.size(), 1u);
    EXPECT_NEAR(e.surfacingInterval, 0.25, 1e-15);
    EXPECT_NEAR(r.plan.travelTime, 8.0 / 0.6, 1e-3); // the plan: 8 units at V + 0.1
    ASSERT_EQ(e.strategies.size(), 4u);              // a plan of straight legs: only the listed strategies
    for (ControlStrategy s : e.strategies)           // the four the mission lists
    {
        const FlownTrack &f = flown(e, 0, s);
        EXPECT_TRUE(f.reached) << controlStrategyName(s);
        EXPECT_FALSE(f.grounded);
        // the run ends on reaching the radius: (8 - 0.2) / 0.8 after departure, to the integration's accuracy
        EXPECT_NEAR(f.arrivalTime, r.plan.departure + 7.8 / 0.8, 1e-6) << controlStrategyName(s);
        EXPECT_LE(f.finalDistance, 0.2 + 1e-9);
        // at the fixes the glider is on the x axis
        for (const TimedPoint &w : f.fixes)
            EXPECT_NEAR(w.y, 0.0, 1e-6);
    }
}

// truth = forecast: the flown plan arrives where and when it was planned (the simulator and the plan agree).
TEST(MissionExecution, TruthEqualToTheForecastFliesThePlanOnTheJet)
{
    MissionSpec spec = defaultGulfStreamMission();
    spec.execution.enabled = true;
    spec.execution.surfacingInterval = 1.0 / 24.0;
    spec.execution.strategies = {"current_sensitive"};
    spec.execution.radius = 0.05;
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved);
    const FlownTrack &f = flown(*r.execution, 0, ControlStrategy::CurrentSensitive);
    EXPECT_TRUE(f.reached);
    EXPECT_LT(std::abs(f.arrivalTime - f.plannedArrival), 0.01 * r.plan.travelTime);
    EXPECT_LT(f.finalDistance, 0.05);
    EXPECT_EQ(r.execution->truth, "forecast");
}

// A batch: deterministic for a seed (pairs and results), the same with one thread as with two, pairs at least
// min_distance apart, and the spread counts every run.
TEST(MissionExecution, BatchIsDeterministicAndParallelRunsAgree)
{
    MissionSpec spec = defaultGulfStreamMission();
    spec.execution.enabled = true;
    spec.execution.surfacingInterval = 0.25;
    spec.execution.strategies = {"current_sensitive", "greedy"};
    spec.execution.truth = spec.current;
    spec.execution.truth->parameters["B0"] = 1.38;
    spec.execution.pairs = 5;
    spec.execution.seed = 3;
    spec.execution.minDistance = 3.0;
    spec.execution.threads = 2;
    const MissionProblem two(spec);
    spec.execution.threads = 1;
    const MissionProblem one(spec);
    const MissionResult a = runMission(two), b = runMission(one);
    ASSERT_EQ(a.execution->runs.size(), 6u);
    ASSERT_EQ(b.execution->runs.size(), 6u);
    EXPECT_EQ(a.execution->threads, 2u);
    EXPECT_EQ(b.execution->threads, 1u);
    for (std::size_t i = 0; i < 6; ++i)
    {
        const ExecutionRun &x = a.execution->runs[i], &y = b.execution->runs[i];
        EXPECT_EQ(x.start.x, y.start.x);
        EXPECT_EQ(x.goal.y, y.goal.y);
        if (i > 0)
        {
            EXPECT_GE(std::hypot(x.goal.x - x.start.x, x.goal.y - x.start.y), 3.0);
        }
        ASSERT_EQ(x.planned, y.planned);
        for (std::size_t k = 0; k < x.flown.size(); ++k)
        {
            EXPECT_EQ(x.flown[k].finalDistance, y.flown[k].finalDistance);
            EXPECT_EQ(x.flown[k].reached, y.flown[k].reached);
        }
    }
    std::size_t planned = 0;
    for (const ExecutionRun &run : a.execution->runs)
        planned += run.planned ? 1 : 0;
    for (const StrategySpread &s : a.execution->spread)
    {
        EXPECT_EQ(s.runs, planned);
        EXPECT_EQ(s.finalDistance.count, planned);
        EXPECT_LE(s.finalDistance.q1, s.finalDistance.median);
        EXPECT_LE(s.finalDistance.median, s.finalDistance.q3);
    }
    // the truth differs: the flown tracks are not the planned ones
    EXPECT_EQ(a.execution->truth, "meandering jet");
}

TEST(MissionExecution, MeasureSpreadQuartiles)
{
    const MeasureSpread s = measureSpread({4.0, 1.0, 3.0, 2.0, 5.0, std::nan(""), INFINITY});
    EXPECT_EQ(s.count, 5u);
    EXPECT_DOUBLE_EQ(s.min, 1.0);
    EXPECT_DOUBLE_EQ(s.q1, 2.0);
    EXPECT_DOUBLE_EQ(s.median, 3.0);
    EXPECT_DOUBLE_EQ(s.q3, 4.0);
    EXPECT_DOUBLE_EQ(s.max, 5.0);
    EXPECT_DOUBLE_EQ(s.mean, 3.0);
    EXPECT_DOUBLE_EQ(measureSpread({1.0, 2.0}).median, 1.5);
    EXPECT_EQ(measureSpread({}).count, 0u);
}

// The output layer: execution.csv has a row per run and strategy, execution_tracks.csv the fixes, summary.json an
// object per strategy with the measures the issue names.
TEST(MissionExecution, OutputFilesAndSummarySection)
{
    TempDir dir;
    MissionSpec spec = parseMission(kUniformExecution + R"(execution:
  truth: {type: uniform, parameters: {u: 0.3, v: 0.0}}
  surfacing_interval: 1 h
  strategies: [current_sensitive, greedy]
  batch: {pairs: 2, seed: 1, min_distance: 3}
)",
                                    "m.yaml");
    spec.outputs.directory = dir.file("out");
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    const std::vector<std::string> written = writeOutputs(r, problem);
    auto read = [&](const std::string &name) {
        std::ifstream in(dir.file("out/" + name));
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    const std::string csv = read("execution.csv");
    std::size_t rows = 0;
    for (char c : csv)
        rows += c == '\n' ? 1 : 0;
    EXPECT_EQ(rows, 1u + 3u * 2u); // header + 3 runs x 2 strategies
    EXPECT_NE(read("execution_tracks.csv").find("current_sensitive,0,"), std::string::npos);
    const auto j = nlohmann::json::parse(read("summary.json"));
    ASSERT_TRUE(j.contains("execution"));
    for (const char *s : {"current_sensitive", "greedy"})
    {
        const auto &o = j["execution"][s];
        for (const char *key : {"final_distance", "arrival_time", "reached", "grounded"})
            EXPECT_TRUE(o.contains(key)) << s << " " << key;
        EXPECT_TRUE(o["reached"].get<bool>());
        EXPECT_EQ(o["batch"]["runs"].get<int>(), 3);
    }
    EXPECT_FALSE(j["execution"].contains("replan"));
    bool listed = false;
    for (const auto &f : j["files"])
        listed = listed || f.get<std::string>() == "execution.csv";
    EXPECT_TRUE(listed);
}

// A NetCDF truth whose time axis starts a day later than the forecast's (another origin and units) is read at the
// same dates: with the same values it flies exactly as truth = forecast.
TEST(MissionExecution, NetCdfTruthIsAlignedByDate)
{
    TempDir dir;
    MfFile f;
    f.units = "hours since 2026-03-01 00:00:00";
    f.hours = mfHours(0.0, kMfRecords);
    f.raw = f.hours;
    f.bias.assign(f.hours.size(), 0.0);
    f.landHour = -1.0;
    f.stillUntil = -1.0;
    writeMfFile(dir.file("forecast.nc"), f);
    MfFile t = f; // the same ocean, counted in minutes from the next day
    t.units = "minutes since 2026-03-02 00:00:00";
    t.hours = mfHours(24.0, kMfRecords - 8);
    t.raw.clear();
    for (double h : t.hours)
        t.raw.push_back(60.0 * (h - 24.0));
    t.bias.assign(t.hours.size(), 0.0);
    writeMfFile(dir.file("truth.nc"), t);
    MfFile n = t;
    n.calendar = "noleap";
    writeMfFile(dir.file("noleap.nc"), n);

    auto mission = [&](const std::string &truth) {
        return R"(name: nc
current: {type: netcdf, file: )" +
               dir.file("forecast.nc") + R"(}
start: {lon: -52.8, lat: 47.3}
goal: {lon: -52.25, lat: 47.75}
departure: {time: "2026-03-02T03:00:00Z"}
vehicle: {speed: 0.5}
execution:
  truth: )" + truth +
               R"(
  surfacing_interval: 1 h
  strategies: [current_sensitive, greedy]
)";
    };
    const MissionProblem same(parseMission(mission("forecast"), "m.yaml"));
    const MissionProblem shifted(parseMission(mission("{type: netcdf, file: " + dir.file("truth.nc") + "}"), "m.yaml"));
    const MissionResult a = runMission(same), b = runMission(shifted);
    ASSERT_TRUE(a.plan.solved);
    EXPECT_EQ(b.execution->truth.rfind("netcdf:", 0), 0u);
    for (ControlStrategy s : {ControlStrategy::CurrentSensitive, ControlStrategy::Greedy})
    {
        const FlownTrack &x = flown(*a.execution, 0, s), &y = flown(*b.execution, 0, s);
        EXPECT_TRUE(x.reached);
        EXPECT_NEAR(x.finalDistance, y.finalDistance, 1e-3); // metres
        EXPECT_NEAR(x.arrivalTime, y.arrivalTime, 1e-3);     // seconds
    }
    // the truth is on the same dates: at the departure it is the forecast's current there
    const double t0 = a.plan.departure;
    const Point2 p = same.getStart();
    EXPECT_NEAR(shifted.getTruth()->velocity(p.x, p.y, 0.0, t0).u, same.getField()->velocity(p.x, p.y, 0.0, t0).u,
                1e-6);

    try
    {
        MissionProblem bad(parseMission(mission("{type: netcdf, file: " + dir.file("noleap.nc") + "}"), "m.yaml"));
        ADD_FAILURE() << "a truth in another calendar was accepted";
    }
    catch (const Error &e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("field 'execution.truth'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("calendar"), std::string::npos) << msg;
    }
}

namespace
{
/// A steady-looking forecast on lon -53.5..-51.5, lat 47..48 (0.1 degree; two records ten days apart): a weak
/// current u = 0.02 m/s everywhere, and, when @p adverse, u = -0.35 m/s in the box lon -52.65..-52.35,
/// lat 47.3..47.7 (the middle of the route of the test, against it).
void writeMember(const std::string &path, bool adverse)
{
    NcWriter w(path, NC_CLOBBER);
    const std::size_t nt = 2, ny = 11, nx = 21;
    const int dt = w.dim("time", nt), dy = w.dim("lat", ny), dx = w.dim("lon", nx);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy}),
              vx = w.var("lon", NC_DOUBLE, {dx});
    const int vu = w.var("u", NC_FLOAT, {dt, dy, dx}), vv = w.var("v", NC_FLOAT, {dt, dy, dx});
    w.text(vt, "units", "hours since 2026-03-01 00:00:00");
    w.text(vt, "standard_name", "time");
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    for (int v : {vu, vv})
        w.text(v, "units", "m s-1");
    w.text(vu, "standard_name", "eastward_sea_water_velocity");
    w.text(vv, "standard_name", "northward_sea_water_velocity");
    w.enddef();
    const std::vector<double> lat = linspace(47.0, 0.1, ny), lon = linspace(-53.5, 0.1, nx);
    std::vector<double> u, v;
    for (std::size_t k = 0; k < nt; ++k)
        for (std::size_t j = 0; j < ny; ++j)
            for (std::size_t i = 0; i < nx; ++i)
            {
                const bool box = lon[i] > -52.65 && lon[i] < -52.35 && lat[j] > 47.3 && lat[j] < 47.7;
                u.push_back(adverse && box ? -0.35 : 0.02);
                v.push_back(0.0);
            }
    w.put(vt, {0.0, 240.0});
    w.put(vy, lat);
    w.put(vx, lon);
    w.put(vu, u);
    w.put(vv, v);
}
} // namespace

// Two members that differ only in one region: the calm member's plan runs straight through the region where the
// other has a strong adverse current. The robust plan (worst case over the members) is never worse than any
// single member's plan by that measure, and here strictly better than the calm member's.
TEST(MissionEnsemble, RobustPlanOnTwoMembersThatDifferInOneRegion)
{
    TempDir dir;
    writeMember(dir.file("calm.nc"), false);
    writeMember(dir.file("adverse.nc"), true);
    auto mission = [&](const std::string &objective) {
        return "name: ensemble\ncurrent:\n  ensemble:\n    - {type: netcdf, file: " + dir.file("calm.nc") +
               "}\n    - {type: netcdf, file: " + dir.file("adverse.nc") +
               "}\nstart: {lon: -52.95, lat: 47.5}\ngoal: {lon: -52.05, lat: 47.5}\n"
               "departure: {time: \"2026-03-01T01:00:00Z\"}\nvehicle: {speed: 0.4}\n"
               "planner: {objective: " +
               objective + "}\n";
    };
    const MissionSpec spec = parseMission(mission("worst"), "m.yaml");
    ASSERT_EQ(spec.current.members.size(), 2u);
    EXPECT_EQ(spec.planner.objective, EnsembleObjective::Worst);
    const MissionProblem problem(spec);
    ASSERT_EQ(problem.getMembers().size(), 2u);
    // the planning field is the members' mean
    const Point2 mid = problem.toLocal({-52.5, 47.5});
    EXPECT_NEAR(problem.getField()->velocity(mid.x, mid.y, 0.0, 3600.0).u, 0.5 * (0.02 - 0.35), 1e-6);
    EXPECT_NEAR(problem.getMembers()[0]->velocity(mid.x, mid.y, 0.0, 3600.0).u, 0.02, 1e-6);

    const PlannedPath p = planRoute(problem, 3600.0);
    ASSERT_TRUE(p.solved) << p.reason;
    ASSERT_TRUE(p.ensemble.has_value());
    const EnsemblePlan &e = *p.ensemble;
    ASSERT_EQ(e.candidates.size(), 3u); // mean, member 0, member 1
    EXPECT_EQ(e.memberTravelTimes.size(), 2u);
    const double robust = *std::max_element(e.memberTravelTimes.begin(), e.memberTravelTimes.end());
    EXPECT_DOUBLE_EQ(e.objectiveValue, robust);
    for (const EnsemblePlan::Candidate &c : e.candidates)
    {
        ASSERT_TRUE(c.solved) << c.name;
        EXPECT_LE(robust, *std::max_element(c.memberTravelTimes.begin(), c.memberTravelTimes.end())) << c.name;
    }
    // the calm member's plan goes straight through the adverse box: much worse in the adverse member
    const EnsemblePlan::Candidate &calm = e.candidates[1];
    EXPECT_EQ(calm.name, "member 0");
    EXPECT_GT(calm.memberTravelTimes[1], calm.memberTravelTimes[0] * 1.2);
    EXPECT_LT(robust, calm.memberTravelTimes[1]);
    // the chosen path flown in each member is what the candidate table says
    for (std::size_t k = 0; k < 2; ++k)
    {
        const auto flown = retimePath(problem, problem.getMembers()[k], 0.4, p.path);
        ASSERT_FALSE(flown.empty());
        EXPECT_NEAR(flown.back().t - 3600.0, e.memberTravelTimes[k], 1e-6 * e.memberTravelTimes[k]);
    }
    // the expected objective judges the same candidates by the mean
    const PlannedPath x = planRoute(MissionProblem(parseMission(mission("expected"), "m.yaml")), 3600.0);
    ASSERT_TRUE(x.ensemble.has_value());
    for (const EnsemblePlan::Candidate &c : x.ensemble->candidates)
        EXPECT_LE(x.ensemble->objectiveValue, c.objectiveValue);
}

TEST(MissionEnsemble, ObjectivesAndBadSections)
{
    EXPECT_DOUBLE_EQ(ensembleObjective({1.0, 3.0, 2.0}, EnsembleObjective::Expected, 0.9), 2.0);
    EXPECT_DOUBLE_EQ(ensembleObjective({1.0, 3.0, 2.0}, EnsembleObjective::Worst, 0.9), 3.0);
    EXPECT_DOUBLE_EQ(ensembleObjective({1.0, 3.0, 2.0, 4.0}, EnsembleObjective::Quantile, 0.5), 2.0);
    EXPECT_DOUBLE_EQ(ensembleObjective({1.0, 3.0, 2.0, 4.0}, EnsembleObjective::Quantile, 0.75), 3.0);
    EXPECT_DOUBLE_EQ(ensembleObjective({1.0, 3.0, 2.0, 4.0}, EnsembleObjective::Quantile, 1.0), 4.0);
    EXPECT_TRUE(std::isinf(ensembleObjective({1.0, INFINITY}, EnsembleObjective::Expected, 0.9)));
    EXPECT_THROW(parseEnsembleObjective("median"), Error);
    for (EnsembleObjective o : {EnsembleObjective::Expected, EnsembleObjective::Worst, EnsembleObjective::Quantile})
        EXPECT_EQ(parseEnsembleObjective(ensembleObjectiveName(o)), o);

    const std::string head = "name: e\nregion: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\nstart: {x: 1, y: 0}\n"
                             "goal: {x: 9, y: 0}\n";
    const std::string two = "current:\n  ensemble:\n    - {type: uniform, parameters: {u: 0.1}}\n"
                            "    - {type: meandering_jet}\n";
    // analytic members: the mean of a uniform flow and the jet
    const MissionSpec ok = parseMission(head + two + "planner: {objective: quantile, quantile: 0.5}\n", "m.yaml");
    EXPECT_EQ(ok.current.members.size(), 2u);
    EXPECT_EQ(ok.current.type, "uniform");
    const MissionProblem problem(ok);
    const auto jet = makeAnalyticField("meandering_jet", {});
    EXPECT_NEAR(problem.getField()->velocity(3.0, 0.5, 0.0, 1.0).u, 0.5 * (0.1 + jet->velocity(3.0, 0.5, 0.0, 1.0).u),
                1e-12);

    struct Case
    {
        std::string yaml, phrase;
    };
    const Case cases[] = {
        {head + "current: {ensemble: [{type: uniform}]}\n", "field 'current.ensemble'"},
        {head + "current: {ensemble: [{type: uniform}, {type: netcdf, file: x.nc}]}\n", "current.ensemble[1]"},
        {head + "current: {type: uniform, ensemble: [{type: uniform}, {type: uniform}]}\n", "current.type"},
        {head + "current: {ensemble: [{type: uniform}, {type: vortex}]}\n", "field 'current.ensemble[1].type'"},
        {head + "current: {type: uniform}\nplanner: {objective: worst}\n", "needs an ensemble current"},
        {head + two + "planner: {objective: median}\n", "field 'planner.objective'"},
        {head + two + "planner: {objective: quantile, quantile: 1.5}\n", "field 'planner.quantile'"},
        {head + two + "planner: {objective: worst, quantile: 0.5}\n", "only with objective: quantile"},
    };
    for (const Case &c : cases)
    {
        const std::string msg = executionMessageOf(c.yaml);
        EXPECT_NE(msg.find(c.phrase), std::string::npos) << c.yaml << "\n-> " << msg;
    }
}

// A mission of several legs flown in a uniform truth: every strategy flies the legs in turn, holds at the station
// for its stay and until its window opens, and arrives at the closed-form times.
TEST(MissionExecutionLegs, StationsInTurnWithTheirStayAndWindowInClosedForm)
{
    // stations on the x axis downstream: at V 0.5 in the truth's 0.3 every leg is flown at 0.8 over ground
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
  strategies: [current_sensitive, current_blind, greedy, replan, dac, replan_observed]
  radius: 0.2
)",
                                          "m.yaml");
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    ASSERT_TRUE(r.execution.has_value());
    const ExecutionResult &e = *r.execution;
    ASSERT_EQ(e.stops.size(), 2u);
    EXPECT_EQ(e.stops[1].name, "B");
    ASSERT_EQ(e.runs[0].legs.size(), 3u);
    for (ControlStrategy s : e.strategies)
    {
        const FlownTrack &f = flown(e, 0, s);
        EXPECT_TRUE(f.reached) << controlStrategyName(s);
        EXPECT_EQ(f.stationsReached, 2u) << controlStrategyName(s);
        EXPECT_EQ(f.windowsMissed, 0u) << controlStrategyName(s);
        // A's radius (x = 3.9) after 2.9 / 0.8, held there for the stay of 2; B's radius (x = 6.9) at 9.375, held
        // until its window opens at 15; then 4.9 / 0.8 to the goal's radius (x = 11.8) for the strategies that head
        // for the station at full speed; those that keep to the plan's clock (its waypoints on the way) no later
        // than the plan
        const bool fullSpeed =
            s == ControlStrategy::Greedy || s == ControlStrategy::Replan || s == ControlStrategy::ReplanObserved;
        if (fullSpeed)
            EXPECT_NEAR(f.arrivalTime, 15.0 + (12.0 - 6.9 - 0.2) / 0.8, 1e-3) << controlStrategyName(s);
        else
            EXPECT_LE(f.arrivalTime, f.plannedArrival) << controlStrategyName(s);
        EXPECT_GE(f.arrivalTime, 15.0 + (12.0 - 6.9 - 0.2) / 0.8 - 1e-3) << controlStrategyName(s);
        // time never runs backwards along the flown track, and the glider stays on the axis
        for (std::size_t i = 1; i < f.track.size(); ++i)
            EXPECT_GE(f.track[i].t, f.track[i - 1].t);
        for (const TimedPoint &w : f.fixes)
            EXPECT_NEAR(w.y, 0.0, 1e-6);
    }
}

// truth = forecast on the jet: a mission of three stations flown by current_sensitive arrives where and when it was
// planned, through every station; the batch's pairs are missions through the same stations.
TEST(MissionExecutionLegs, TruthEqualToTheForecastFliesTheMissionOnTheJet)
{
    MissionSpec spec = defaultGulfStreamMission();
    spec.waypoints.resize(3);
    const Point2 via[3] = {{3.0, -2.0}, {5.0, 0.5}, {6.5, 2.0}};
    for (int i = 0; i < 3; ++i)
    {
        spec.waypoints[i].name = std::string(1, static_cast<char>('A' + i));
        spec.waypoints[i].position.xy = via[i];
        spec.waypoints[i].radius = 0.005; // the stations reached where they were planned: the plan's own clock
    }
    spec.planner.globalCheck = false; // the lattice's plan is the one flown
    spec.execution.enabled = true;
    spec.execution.surfacingInterval = 1.0 / 24.0;
    spec.execution.strategies = {"current_sensitive", "replan"};
    spec.execution.radius = 0.05;
    spec.execution.pairs = 2;
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const ExecutionResult &e = *r.execution;
    ASSERT_EQ(e.runs.size(), 3u);
    const FlownTrack &f = flown(e, 0, ControlStrategy::CurrentSensitive);
    EXPECT_TRUE(f.reached);
    EXPECT_EQ(f.stationsReached, 3u);
    EXPECT_LT(std::abs(f.arrivalTime - f.plannedArrival), 0.01 * r.plan.travelTime);
    for (std::size_t i = 1; i < e.runs.size(); ++i)
    {
        const ExecutionRun &run = e.runs[i];
        if (!run.planned)
            continue;
        EXPECT_EQ(run.legs.size(), 4u);
        // each leg of the pair's plan ends on its station
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_LT(std::hypot(run.plan[run.legs[k].end].x - via[k].x, run.plan[run.legs[k].end].y - via[k].y), 1e-6);
        const FlownTrack &g = flown(e, i, ControlStrategy::CurrentSensitive);
        EXPECT_TRUE(g.reached) << "pair " << i;
        EXPECT_LT(std::abs(g.arrivalTime - g.plannedArrival), 0.02 * (g.plannedArrival - run.departure)) << i;
    }
}

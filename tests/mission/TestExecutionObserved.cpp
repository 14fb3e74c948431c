// Execution with the glider's measurements: each dive's DAC is the truth's mean along it; with a truth equal to the
// forecast every innovation is zero and replan_observed flies as replan to the bit; with a truth that is the forecast
// plus a drift, the measured DAC are the truth's and the dac strategy steers with them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/execution/Execution.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

namespace
{
const char *kJetMission = "current: {type: meandering_jet}\nregion: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
                          "start: {x: 1, y: -3}\ngoal: {x: 8, y: 3}\nvehicle: {speed: 0.5}\n"
                          "planner: {grid_size: 0.4}\n";

/// The uniform case of the tests below: a still-water forecast, a truth drifting (0.2, -0.1), a straight plan 10
/// units east in 20 time units, flown at 0.5 surfacing every time unit, the goal reached within 0.05.
const UniformCurrent kStillWater(0.0, 0.0), kDrift(0.2, -0.1);
const std::vector<TimedPoint> kEastPlan{{0.0, 0.0, 0.0}, {10.0, 0.0, 20.0}};

ExecutionOptions surfacingEveryUnit()
{
    ExecutionOptions o;
    o.surfacingInterval = 1.0;
    o.step = 0.05;
    o.radius = 0.05;
    return o;
}
} // namespace

TEST(ExecutionObserved, TruthEqualToTheForecastReplanObservedIsReplanToTheBit)
{
    const MissionSpec m =
        parseMission(std::string(kJetMission) + "execution: {surfacing_interval: 0.5, replan_every: 4, radius: 0.1, "
                                                "strategies: [replan, replan_observed, current_sensitive, dac]}\n");
    const MissionResult r = runMission(MissionProblem(m));
    ASSERT_TRUE(r.execution.has_value());
    const ExecutionRun &run = r.execution->runs.front();
    ASSERT_EQ(run.flown.size(), 4u);
    const FlownTrack &replan = run.flown[0], &observed = run.flown[1];
    ASSERT_EQ(replan.fixes.size(), observed.fixes.size());
    for (std::size_t i = 0; i < replan.fixes.size(); ++i)
    {
        EXPECT_EQ(replan.fixes[i].x, observed.fixes[i].x) << i;
        EXPECT_EQ(replan.fixes[i].y, observed.fixes[i].y) << i;
        EXPECT_EQ(replan.fixes[i].t, observed.fixes[i].t) << i;
    }
    EXPECT_EQ(replan.reached, observed.reached);
    EXPECT_EQ(replan.replans, observed.replans);
    // one DAC per dive, each the forecast's own mean: zero innovation
    ASSERT_EQ(observed.measured.size(), observed.fixes.size() - 1);
    for (const DacObservation &d : observed.measured)
    {
        ASSERT_TRUE(d.forecast.has_value());
        EXPECT_EQ(d.dac.u, d.forecast->u);
        EXPECT_EQ(d.dac.v, d.forecast->v);
    }
    EXPECT_TRUE(replan.measured.empty()); // the forecast-only strategies measure nothing
}

TEST(ExecutionObserved, MeasuredDacIsTheTruthsMeanAlongTheDive)
{
    // a uniform truth: every DAC is that current exactly (no noise), and the dac strategy aims off by it
    const UniformCurrent &forecast = kStillWater, &truth = kDrift;
    const std::vector<TimedPoint> &plan = kEastPlan;
    ExecutionOptions o = surfacingEveryUnit();
    const FlownTrack dac = flyPlan(plan, 0.5, forecast, truth, nullptr, ControlStrategy::Dac, o);
    ASSERT_FALSE(dac.measured.empty());
    for (const DacObservation &d : dac.measured)
    {
        EXPECT_NEAR(d.dac.u, 0.2, 1e-12);
        EXPECT_NEAR(d.dac.v, -0.1, 1e-12);
    }
    // after the first dive (steered on the forecast's zero current) the glider aims off by the measured drift: each
    // dive ends where the measured current predicts, on the way from the drifted fix (fix + c dt) to the goal, as
    // near the goal as one dive gets
    EXPECT_TRUE(dac.reached);
    for (std::size_t i = 1; i + 2 < dac.fixes.size(); ++i)
    {
        const TimedPoint &a = dac.fixes[i], &b = dac.fixes[i + 1];
        const double dt = b.t - a.t, px = a.x + 0.2 * dt, py = a.y - 0.1 * dt; // the fix carried by the current
        const double lx = 10.0 - px, ly = 0.0 - py, len = std::hypot(lx, ly);
        EXPECT_NEAR(((b.x - px) * ly - (b.y - py) * lx) / len, 0.0, 1e-9) << i; // on that line
        EXPECT_NEAR(std::hypot(b.x - px, b.y - py), 0.5 * dt, 1e-9) << i;       // the whole speed along it
    }
    const FlownTrack blind = flyPlan(plan, 0.5, forecast, truth, nullptr, ControlStrategy::CurrentBlind, o);
    // current_blind re-aims at every surfacing but drifts 0.1 off course in every dive, and arrives later
    ASSERT_TRUE(blind.reached);
    for (std::size_t i = 2; i + 1 < blind.fixes.size(); ++i)
        EXPECT_LT(blind.fixes[i].y, -0.05) << i;
    EXPECT_LT(dac.arrivalTime, blind.arrivalTime);
    // noise: the measurements scatter about the truth with the given spread
    o.dacNoise = 0.05;
    const FlownTrack noisy = flyPlan(plan, 0.5, forecast, truth, nullptr, ControlStrategy::Dac, o);
    double sum = 0.0;
    for (const DacObservation &d : noisy.measured)
        sum += (d.dac.u - 0.2) * (d.dac.u - 0.2);
    EXPECT_GT(std::sqrt(sum / noisy.measured.size()), 0.01);
    EXPECT_LT(std::sqrt(sum / noisy.measured.size()), 0.15);
}

TEST(ExecutionObserved, ReplanObservedSteersWithTheCorrectedCurrentAtTheFix)
{
    // still water forecast, a uniform truth: between plans replan_observed crabs with the corrected forecast at the
    // fix, which after the first dive is near the measured current (the OI weight: 1 / (1 + 0.2^2) for one DAC at
    // the fix; less ahead of the DAC, which lie behind the glider), so it keeps close to its course to the goal;
    // replan, steering with the forecast's zero current, drifts off it in every dive
    const UniformCurrent &forecast = kStillWater, &truth = kDrift;
    const std::vector<TimedPoint> &plan = kEastPlan;
    ExecutionOptions o = surfacingEveryUnit();
    o.replanEvery = 1000; // the start's plan only: the plans keep the current one
    o.replan = [](double, double, double, const std::vector<TimedPoint> &) { return std::vector<TimedPoint>{}; };
    o.replanObserved = [](double, double, double, const std::vector<TimedPoint> &,
                          const std::shared_ptr<const CurrentField> &) { return std::vector<TimedPoint>{}; };
    o.correction.lengthScale = 5.0;
    o.correction.timeScale = 10.0;
    const FlownTrack seen = flyPlan(plan, 0.5, forecast, truth, nullptr, ControlStrategy::ReplanObserved, o);
    const FlownTrack replan = flyPlan(plan, 0.5, forecast, truth, nullptr, ControlStrategy::Replan, o);
    ASSERT_TRUE(seen.reached);
    ASSERT_TRUE(replan.reached);
    // the drift across the course to the goal in each dive: at most 10 % of the truth's 0.1 for replan_observed (from
    // its second dive on), the whole of it for replan
    const auto crossDrift = [](const FlownTrack &f, std::size_t i) {
        const TimedPoint &a = f.fixes[i], &b = f.fixes[i + 1];
        const double lx = 10.0 - a.x, ly = 0.0 - a.y, len = std::hypot(lx, ly);
        return ((b.x - a.x) * ly - (b.y - a.y) * lx) / len;
    };
    for (std::size_t i = 1; i + 2 < seen.fixes.size(); ++i)
        EXPECT_NEAR(crossDrift(seen, i), 0.0, 0.01) << i;
    for (std::size_t i = 1; i + 2 < replan.fixes.size(); ++i)
        EXPECT_GT(std::abs(crossDrift(replan, i)), 0.09) << i;
    EXPECT_LT(seen.arrivalTime, replan.arrivalTime);
    // with no measurement the correction is nothing: the first dive is the same
    EXPECT_EQ(seen.fixes[1].x, replan.fixes[1].x);
    EXPECT_EQ(seen.fixes[1].y, replan.fixes[1].y);
}

TEST(ExecutionObserved, CorrectionParametersWithoutGliderFiles)
{
    // an execution experiment sets the correction's scales without a glider's files: the start stays required
    const MissionSpec m =
        parseMission(std::string(kJetMission) + "observations: {length_scale: 2, time_scale: 3, error_ratio: 0.5}\n");
    ASSERT_TRUE(m.observations.has_value());
    EXPECT_FALSE(m.observations->hasFiles());
    const MissionProblem p(m);
    EXPECT_EQ(p.correctionParams().lengthScale, 2.0);
    EXPECT_EQ(p.correctionParams().timeScale, 3.0);
    EXPECT_EQ(p.correctionParams().errorRatio, 0.5);
    EXPECT_EQ(p.getStart().x, 1.0); // the mission's start, not a last fix
    std::string noStart = kJetMission;
    noStart.replace(noStart.find("start: {x: 1, y: -3}\n"), 21, "");
    try
    {
        parseMission(noStart + "observations: {time_scale: 3}\n");
        FAIL() << "a mission without a start nor glider files was accepted";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("'start'"), std::string::npos) << e.what();
    }
    try
    {
        parseMission(std::string(kJetMission) + "observations: {}\n");
        FAIL() << "an empty observations section was accepted";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("observations.file"), std::string::npos) << e.what();
    }
}

// Execution with the glider's measurements: each dive's DAC is the truth's mean along it; with a truth equal to the
// forecast every innovation is zero and replan_observed flies as replan to the bit; with a truth that is the forecast
// plus a drift, the measured DAC are the truth's and the dac strategy steers with them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

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
    // a uniform truth: every DAC is that current exactly (no noise), and the dac strategy crabs into it
    const UniformCurrent forecast(0.0, 0.0), truth(0.2, -0.1);
    const std::vector<TimedPoint> plan{{0.0, 0.0, 0.0}, {10.0, 0.0, 20.0}};
    ExecutionOptions o;
    o.surfacingInterval = 1.0;
    o.step = 0.05;
    o.radius = 0.05;
    const FlownTrack dac = flyPlan(plan, 0.5, forecast, truth, nullptr, ControlStrategy::Dac, o);
    ASSERT_FALSE(dac.measured.empty());
    for (const DacObservation &d : dac.measured)
    {
        EXPECT_NEAR(d.dac.u, 0.2, 1e-12);
        EXPECT_NEAR(d.dac.v, -0.1, 1e-12);
    }
    // after the first dive (steered on the forecast's zero current) the glider cancels the cross current: from the
    // first surfacing on it makes good the straight course to the goal
    EXPECT_TRUE(dac.reached);
    const TimedPoint a = dac.fixes[1];
    const double lx = 10.0 - a.x, ly = 0.0 - a.y, len = std::hypot(lx, ly);
    for (std::size_t i = 2; i < dac.fixes.size(); ++i)
        EXPECT_NEAR(((dac.fixes[i].x - a.x) * ly - (dac.fixes[i].y - a.y) * lx) / len, 0.0, 1e-9) << i;
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

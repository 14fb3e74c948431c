// Constant-bearing stints ([IsernObstacles]): closed forms in a uniform current, a stint into an island
// stops there, CTS-A* on a problem whose optimum is known, the optimisers never worse than their start, identical
// results for identical inputs, the stint planners through the one pipeline, and lattice paths flown as stints.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/Polygon.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/routes/BearingOptimizer.h"
#include "ompl_glider/stints/CtsAStar.h"
#include "ompl_glider/routes/PathToStints.h"
#include "ompl_glider/routes/StintSimulator.h"

using namespace ompl_glider;

namespace
{
StintSettings settings(double duration, double mission, StintObjective o = StintObjective::RemainingDistance,
                       double radius = 0.0)
{
    StintSettings s;
    s.duration = duration;
    s.missionDuration = mission;
    s.objective = o;
    s.radius = radius;
    return s;
}

/// The meandering jet ([EichhornRAS] Sec. 6.1) with an island across the straight line from (1, -3) to (8, 3).
std::shared_ptr<ForbiddenRegions> jetIsland()
{
    auto regions = std::make_shared<ForbiddenRegions>();
    regions->add(std::make_shared<StaticRegion>("Isle", Polygon({{4.0, -1.0}, {5.5, -1.0}, {5.5, 0.6}, {4.0, 0.6}})));
    return regions;
}
} // namespace

TEST(Stints, BearingConventionIsClockwiseFromNorth)
{
    EXPECT_NEAR(bearingVector(0.0).x, 0.0, 1e-15);
    EXPECT_NEAR(bearingVector(0.0).y, 1.0, 1e-15);
    EXPECT_NEAR(bearingVector(90.0).x, 1.0, 1e-15);
    EXPECT_NEAR(bearingVector(90.0).y, 0.0, 1e-15);
    for (double b : {0.0, 10.0, 135.0, 200.0, 359.0})
        EXPECT_NEAR(bearingOf(bearingVector(b).x, bearingVector(b).y), b, 1e-9);
}

TEST(Stints, UniformCurrentSurfacingsInClosedForm)
{
    // x_{k+1} = x_k + d_k (V h(b_k) + c), d_k = stint length (the last one shortened to the mission's end)
    const double u = 0.13, v = -0.07, V = 0.4, D = 2.5, T = 11.0;
    auto field = std::make_shared<UniformCurrent>(u, v);
    const StintSimulator sim(field, nullptr, V, std::hypot(u, v), {1.0, 2.0}, 3.0, {50.0, 50.0}, settings(D, T));
    ASSERT_EQ(sim.settings().stintCount(), 5u);
    const std::vector<double> b{10.0, 75.0, 200.0, 310.0, 45.0};
    const StintPlan p = sim.simulate(b);
    ASSERT_EQ(p.surfacings.size(), 6u);
    double x = 1.0, y = 2.0, t = 3.0;
    for (std::size_t k = 0; k < b.size(); ++k)
    {
        const double d = std::min(D, 3.0 + T - t);
        const Point2 h = bearingVector(b[k]);
        x += d * (V * h.x + u);
        y += d * (V * h.y + v);
        t += d;
        EXPECT_NEAR(p.surfacings[k + 1].x, x, 1e-12) << k;
        EXPECT_NEAR(p.surfacings[k + 1].y, y, 1e-12) << k;
        EXPECT_NEAR(p.surfacings[k + 1].t, t, 1e-12) << k;
    }
    EXPECT_NEAR(p.surfacings.back().t, 3.0 + T, 1e-12); // the last stint ends with the mission
    EXPECT_NEAR(p.remainingDistance, std::hypot(50.0 - x, 50.0 - y), 1e-12);
    EXPECT_DOUBLE_EQ(p.cost, p.remainingDistance);
    EXPECT_FALSE(p.grounded);
    EXPECT_FALSE(p.reached);
}

TEST(Stints, EarliestArrivalWithinRadiusInClosedForm)
{
    // no current, goal due east at L: direct arrives at (L - r) / V and the stints end there
    const double V = 0.5, L = 7.0, r = 0.1;
    auto field = std::make_shared<UniformCurrent>(0.0, 0.0);
    const StintSimulator sim(field, nullptr, V, 0.0, {0.0, 0.0}, 0.0, {L, 0.0},
                             settings(2.0, 40.0, StintObjective::EarliestArrival, r));
    const StintPlan p = sim.direct();
    ASSERT_TRUE(p.reached);
    EXPECT_NEAR(p.arrivalTime, (L - r) / V, 1e-9);
    EXPECT_NEAR(p.cost, (L - r) / V, 1e-9);
    EXPECT_EQ(p.bearings.size(), static_cast<std::size_t>(std::ceil((L - r) / V / 2.0)));
    for (double b : p.bearings)
        EXPECT_NEAR(b, 90.0, 1e-9);
}

TEST(Stints, StintIntoAnIslandStopsThere)
{
    const double V = 0.5;
    auto field = std::make_shared<UniformCurrent>(0.0, 0.0);
    auto regions = std::make_shared<ForbiddenRegions>();
    regions->add(std::make_shared<StaticRegion>("Rock", Polygon({{3.0, -1.0}, {4.0, -1.0}, {4.0, 1.0}, {3.0, 1.0}})));
    StintSettings s = settings(4.0, 20.0);
    s.step = 0.05;
    const StintSimulator sim(field, regions, V, 0.0, {0.0, 0.0}, 0.0, {10.0, 0.0}, s);
    const StintPlan p = sim.direct(); // due east, through the rock
    ASSERT_TRUE(p.grounded);
    EXPECT_NE(p.groundedWhy.find("Rock"), std::string::npos) << p.groundedWhy;
    const TimedPoint &end = p.surfacings.back();
    // it stops at the start of the step that meets the rock: within one step (V * step) west of x = 3
    EXPECT_LT(end.x, 3.0);
    EXPECT_GE(end.x, 3.0 - V * s.step - 1e-12);
    EXPECT_NEAR(end.y, 0.0, 1e-12);
    EXPECT_LT(end.t, sim.endTime());
    EXPECT_EQ(p.bearings.size(), 2u); // the second stint (from x = 2) meets it
    for (const TimedPoint &w : p.track)
        EXPECT_TRUE(regions->pointFree(w.x, w.y, w.t));
    EXPECT_NEAR(p.remainingDistance, 10.0 - end.x, 1e-12);
    // the optimisers pay for the time lost on the rock: more than the remaining distance
    EXPECT_GT(p.cost, p.remainingDistance + V * (sim.endTime() - end.t) - 1e-9);
}

TEST(Stints, CtsAStarFindsTheStraightOptimumInStillWater)
{
    // goal due north beyond reach: every optimal plan holds bearing 0 and leaves d - V T (on the rose of 20 deg)
    const double V = 0.5, D = 2.0, T = 12.0, d = 9.0;
    auto field = std::make_shared<UniformCurrent>(0.0, 0.0);
    const StintSimulator sim(field, nullptr, V, 0.0, {0.0, 0.0}, 0.0, {0.0, d}, settings(D, T));
    const CtsAStarResult r = ctsAStar(sim);
    EXPECT_TRUE(r.complete);
    ASSERT_EQ(r.plan.bearings.size(), 6u);
    for (double b : r.plan.bearings)
        EXPECT_NEAR(b, 0.0, 1e-12);
    EXPECT_NEAR(r.plan.remainingDistance, d - V * T, 1e-9);
    EXPECT_GT(r.expansions, 0u);
}

TEST(Stints, CtsAStarAvoidsTheIslandDirectMeets)
{
    auto field = std::make_shared<MeanderingJet>();
    const StintSimulator sim(field, jetIsland(), 0.5, field->maxSpeed(Region{}), {1.0, -3.0}, 0.0, {8.0, 3.0},
                             settings(1.0, 12.0, StintObjective::EarliestArrival, 0.2));
    const StintPlan direct = sim.direct();
    const CtsAStarResult cts = ctsAStar(sim);
    EXPECT_FALSE(cts.plan.grounded);
    EXPECT_LE(cts.plan.cost, direct.cost);
    // every surfacing of the plan is in water (the track was checked step by step)
    for (const TimedPoint &w : cts.plan.track)
        EXPECT_TRUE(jetIsland()->pointFree(w.x, w.y, w.t));
}

TEST(Stints, OptimisationIsNeverWorseThanItsInitialGuess)
{
    auto field = std::make_shared<MeanderingJet>();
    for (StintObjective o : {StintObjective::RemainingDistance, StintObjective::EarliestArrival})
        for (const auto &[sx, sy, gx, gy] :
             {std::array<double, 4>{1.0, -3.0, 8.0, 3.0}, std::array<double, 4>{1.0, 3.0, 9.0, -2.5},
              std::array<double, 4>{0.5, -2.0, 9.5, 2.0}})
        {
            const StintSimulator sim(field, jetIsland(), 0.5, field->maxSpeed(Region{}), {sx, sy}, 0.0, {gx, gy},
                                     settings(1.5, 9.0, o, o == StintObjective::EarliestArrival ? 0.2 : 0.0));
            const CtsAStarResult cts = ctsAStar(sim);
            BearingOptimizerParams p;
            p.maxEvaluations = 400;
            const BearingOptimizerResult init = optimiseBearings(sim, cts.plan.bearings, p);
            EXPECT_LE(init.plan.cost, cts.plan.cost) << sx << " " << sy;
            EXPECT_DOUBLE_EQ(init.initial.cost, cts.plan.cost);
            const BearingOptimizerResult optim = optimiseBearings(sim, {}, p);
            EXPECT_LE(optim.plan.cost, sim.direct().cost);
            EXPECT_LE(init.evaluations, p.maxEvaluations);
            // the reported cost is the cost of re-flying the reported bearings
            EXPECT_NEAR(sim.simulate(init.plan.bearings).cost, init.plan.cost, 1e-9 * (1.0 + init.plan.cost));
        }
}

TEST(Stints, IdenticalInputsGiveIdenticalPlans)
{
    auto field = std::make_shared<MeanderingJet>();
    auto run = [&] {
        const StintSimulator sim(field, jetIsland(), 0.5, field->maxSpeed(Region{}), {1.0, -3.0}, 0.0, {8.0, 3.0},
                                 settings(1.5, 9.0));
        const CtsAStarResult cts = ctsAStar(sim);
        BearingOptimizerParams p;
        p.maxEvaluations = 300;
        return optimiseBearings(sim, cts.plan.bearings, p).plan;
    };
    const StintPlan a = run(), b = run();
    ASSERT_EQ(a.bearings.size(), b.bearings.size());
    for (std::size_t k = 0; k < a.bearings.size(); ++k)
        EXPECT_EQ(a.bearings[k], b.bearings[k]) << k;
    EXPECT_EQ(a.remainingDistance, b.remainingDistance);
}

TEST(Stints, SettingsAreChecked)
{
    EXPECT_THROW(settings(0.0, 1.0).check(), Error);
    EXPECT_THROW(settings(1.0, -1.0).check(), Error);
    EXPECT_THROW(settings(1.0, 2.0, StintObjective::EarliestArrival, 0.0).check(), Error);
    StintSettings s = settings(1.0, 2.0);
    s.bearingStep = 0.0;
    EXPECT_THROW(s.check(), Error);
    s.bearingStep = 200.0;
    EXPECT_THROW(s.check(), Error);
    EXPECT_NO_THROW(settings(1.0, 2.5).check());
    EXPECT_EQ(settings(1.0, 2.5).stintCount(), 3u);
    EXPECT_EQ(settings(1.0, 3.0).stintCount(), 3u);
}

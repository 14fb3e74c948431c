// Flying plans in another ocean: the crab heading, closed forms in uniform currents (the track of a
// current-sensitive glider on its line, the drift of a current-blind one between surfacings, a forecast that misses
// the current), a grounding on an island, and a ZA*TVE plan on the Gulf Stream jet flown in its own field.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/execution/Execution.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

TEST(Execution, CrabHeadingMakesGoodTheCourse)
{
    const double V = 0.5;
    for (double ang : {0.0, 0.7, 2.0, -2.5})
        for (Velocity c : {Velocity{0.3, -0.2}, Velocity{-0.45, 0.1}, Velocity{0.0, 0.0}})
        {
            const double dx = std::cos(ang), dy = std::sin(ang);
            double hx, hy;
            crabHeading(dx, dy, c, V, hx, hy);
            EXPECT_NEAR(std::hypot(hx, hy), 1.0, 1e-12);
            const double gx = V * hx + c.u, gy = V * hy + c.v; // ground velocity
            const double cross = gx * (-dy) + gy * dx, cPerp = c.u * (-dy) + c.v * dx, cPar = c.u * dx + c.v * dy;
            if (std::abs(cPerp) < V)
            {
                EXPECT_NEAR(cross, 0.0, 1e-12) << ang; // along the course
                EXPECT_NEAR(gx * dx + gy * dy, std::sqrt(V * V - cPerp * cPerp) + cPar, 1e-12);
            }
        }
    // a cross current stronger than the speed: straight against it
    double hx, hy;
    crabHeading(1.0, 0.0, Velocity{0.0, 0.8}, 0.5, hx, hy);
    EXPECT_NEAR(hx, 0.0, 1e-15);
    EXPECT_NEAR(hy, -1.0, 1e-15);
}

TEST(Execution, CurrentSensitiveGliderInAUniformCurrentStaysOnItsLineAndArrivesOnTime)
{
    // the plan: a straight line of 100 km at the closed-form ground speed sqrt(V^2 - c_perp^2) + c_par
    const UniformCurrent c(0.15, 0.2);
    const double V = 0.4, L = 100000.0, dirx = 0.8, diry = 0.6;
    const double cPar = 0.15 * dirx + 0.2 * diry, cPerp = -0.15 * diry + 0.2 * dirx;
    const double ground = std::sqrt(V * V - cPerp * cPerp) + cPar, T = L / ground;
    const std::vector<TimedPoint> plan{{0, 0, 0}, {L * dirx * 0.5, L * diry * 0.5, 0.5 * T}, {L * dirx, L * diry, T}};
    ExecutionOptions o;
    o.surfacingInterval = 3600.0;
    o.radius = 1.0;
    const FlownTrack r = flyPlan(plan, V, c, c, nullptr, ControlStrategy::CurrentSensitive, o);
    ASSERT_TRUE(r.reached);
    EXPECT_FALSE(r.grounded);
    // within radius 1 m: arrival 1 m / ground speed before the plan's
    EXPECT_NEAR(r.arrivalTime, T - 1.0 / ground, 1e-6 * T);
    for (const TimedPoint &p : r.track)
        EXPECT_NEAR(p.x * diry - p.y * dirx, 0.0, 1e-6); // on the line
    EXPECT_LT(r.finalDistance, 1.0 + 1e-6);
    EXPECT_NEAR(r.madeGoodSpeed, ground, 1e-6 * ground);
}

TEST(Execution, CurrentBlindGliderDriftsBetweenSurfacingsAsTheClosedFormSays)
{
    // heading at the active waypoint at each surfacing, held for T through a uniform cross current: each dive ends
    // at p + T (V d + c), d the unit direction from p to the waypoint at the surfacing
    const Velocity cur{0.0, 0.25};
    const UniformCurrent c(cur.u, cur.v);
    const double V = 0.4, T = 3 * 3600.0;
    const std::vector<TimedPoint> plan{{0, 0, 0}, {60000, 0, 150000}, {120000, 10000, 300000}};
    ExecutionOptions o;
    o.surfacingInterval = T;
    o.step = 500.0;
    o.endTime = 300000.0;
    const FlownTrack r = flyPlan(plan, V, c, c, nullptr, ControlStrategy::CurrentBlind, o);
    double x = 0, y = 0, t = 0;
    std::size_t k = 1;
    for (; t < o.endTime - 1e-9; ++k)
    {
        const TimedPoint w = t < 150000 ? plan[1] : plan[2];
        const double dx = w.x - x, dy = w.y - y, n = std::hypot(dx, dy), h = std::min(T, o.endTime - t);
        x += h * (V * dx / n + cur.u);
        y += h * (V * dy / n + cur.v);
        t += h;
        ASSERT_LT(k, r.fixes.size());
        EXPECT_NEAR(r.fixes[k].x, x, 1e-6) << k;
        EXPECT_NEAR(r.fixes[k].y, y, 1e-6) << k;
        EXPECT_NEAR(r.fixes[k].t, t, 1e-9) << k;
    }
    EXPECT_EQ(r.fixes.size(), k);
    EXPECT_FALSE(r.reached); // radius 0: reached is never claimed
    EXPECT_NEAR(r.finalDistance, std::hypot(x - 120000, y - 10000), 1e-6);
}

TEST(Execution, AForecastWithoutTheCurrentSteersStraightAndTheTruthCarriesTheGlider)
{
    const UniformCurrent forecast(0.0, 0.0), truth(0.1, -0.05);
    const std::vector<TimedPoint> plan{{0, 0, 0}, {50000, 0, 125000}};
    ExecutionOptions o;
    o.endTime = 7200.0;
    const FlownTrack s = flyPlan(plan, 0.4, forecast, truth, nullptr, ControlStrategy::CurrentSensitive, o);
    // first dive: heading +x (no crab, the forecast has no current), carried by the truth
    ASSERT_GE(s.fixes.size(), 2u);
    EXPECT_NEAR(s.headings[0], 0.0, 1e-12);
    EXPECT_NEAR(s.fixes[1].x, 3600 * (0.4 + 0.1), 1e-6);
    EXPECT_NEAR(s.fixes[1].y, 3600 * -0.05, 1e-6);
    // with the truth as forecast the first heading crabs into the cross current
    const FlownTrack o2 = flyPlan(plan, 0.4, truth, truth, nullptr, ControlStrategy::CurrentSensitive, o);
    EXPECT_NEAR(o2.headings[0], std::asin(0.05 / 0.4), 1e-12);
    EXPECT_NEAR(o2.fixes[1].y, 0.0, 1e-6);
}

TEST(Execution, AGliderCarriedOntoAnIslandIsGroundedThere)
{
    // greedy toward a goal 40 km east; a 0.3 m/s northward current carries it onto an island north-east of the start
    const UniformCurrent c(0.0, 0.3);
    auto regions = std::make_shared<ForbiddenRegions>();
    regions->add(std::make_shared<StaticRegion>(
        "Reef", Polygon({{10000, 8000}, {30000, 8000}, {30000, 20000}, {10000, 20000}})));
    const std::vector<TimedPoint> plan{{0, 0, 0}, {40000, 0, 100000}};
    ExecutionOptions o;
    o.radius = 100.0;
    const FlownTrack r = flyPlan(plan, 0.4, c, c, regions.get(), ControlStrategy::Greedy, o);
    ASSERT_TRUE(r.grounded);
    EXPECT_FALSE(r.reached);
    EXPECT_NE(r.groundedWhy.find("Reef"), std::string::npos) << r.groundedWhy;
    const TimedPoint &last = r.track.back();
    EXPECT_TRUE(regions->pointFree(last.x, last.y, last.t));
    // stopped at the reef's edge, within one step: the ground speed is at most 0.4 + 0.3 m/s
    EXPECT_GT(last.y, 8000.0 - 0.7 * o.step);
    // without the reef it flies on past
    const FlownTrack free = flyPlan(plan, 0.4, c, c, nullptr, ControlStrategy::Greedy, o);
    EXPECT_FALSE(free.grounded);
}

TEST(Execution, AZaStarTvePlanOnTheJetFlownInItsOwnFieldArrivesOnTime)
{
    // the target: truth = forecast, hourly surfacings, current-sensitive control: within 1 % of the planned
    // time and 0.05 length units of the goal
    const MissionSpec spec = defaultGulfStreamMission();
    const MissionProblem problem(spec);
    const MissionResult res = runMission(problem);
    ASSERT_TRUE(res.plan.solved);
    const std::vector<TimedPoint> &plan = res.plan.path;
    ExecutionOptions o;
    // the built-in jet has no units; at the scale of examples/gulf_stream_window.yaml (a time unit is a day, a
    // length unit 50 km) an hour is 1/24 and 0.05 length units are 2.5 km
    o.surfacingInterval = 1.0 / 24.0;
    o.step = o.surfacingInterval / 20.0;
    o.radius = 0.05;
    const CurrentField &f = *problem.getField();
    const FlownTrack r =
        flyPlan(plan, res.plan.speed, f, f, problem.getEnvironment().get(), ControlStrategy::CurrentSensitive, o);
    EXPECT_FALSE(r.grounded) << r.groundedWhy;
    ASSERT_TRUE(r.reached);
    const double planned = plan.back().t - plan.front().t;
    EXPECT_LT(std::abs((r.arrivalTime - plan.front().t) - planned), 0.01 * planned)
        << "flown " << r.arrivalTime - plan.front().t << ", planned " << planned;
    EXPECT_LT(r.finalDistance, 0.05);
}

TEST(Execution, ReplanningWithAStraightLinePlannerAndNoForecastCurrentFliesAsGreedy)
{
    // the replanner gives the straight line from the fix to the goal; with a forecast without current the heading
    // at each surfacing is then the direction to the goal: the fixes of greedy control, whatever the truth does
    const UniformCurrent forecast(0.0, 0.0), truth(0.05, 0.2);
    const std::vector<TimedPoint> plan{{0, 0, 0}, {30000, 20000, 5000}, {60000, 0, 150000}};
    ExecutionOptions o;
    o.radius = 500.0;
    unsigned calls = 0;
    o.replan = [&](double x, double y, double t, const std::vector<TimedPoint> &) {
        ++calls;
        return std::vector<TimedPoint>{{x, y, t}, {60000, 0, t + std::hypot(60000 - x, y) / 0.4}};
    };
    const FlownTrack g = flyPlan(plan, 0.4, forecast, truth, nullptr, ControlStrategy::Greedy, o);
    const FlownTrack r = flyPlan(plan, 0.4, forecast, truth, nullptr, ControlStrategy::Replan, o);
    ASSERT_EQ(r.fixes.size(), g.fixes.size());
    for (std::size_t k = 0; k < r.fixes.size(); ++k)
    {
        EXPECT_NEAR(r.fixes[k].x, g.fixes[k].x, 1e-6) << k;
        EXPECT_NEAR(r.fixes[k].y, g.fixes[k].y, 1e-6) << k;
    }
    EXPECT_EQ(r.replans, calls);
    EXPECT_EQ(calls, r.headings.size()); // every surfacing, the start included
    // every third surfacing: a third of the plans (rounded up)
    calls = 0;
    o.replanEvery = 3;
    const FlownTrack third = flyPlan(plan, 0.4, forecast, truth, nullptr, ControlStrategy::Replan, o);
    EXPECT_EQ(calls, (third.headings.size() + 2) / 3);
    // the original plan's detour through (30000, 20000) is flown without replanning: another track
    const FlownTrack sensitive = flyPlan(plan, 0.4, forecast, truth, nullptr, ControlStrategy::CurrentSensitive, o);
    EXPECT_GT(std::abs(sensitive.fixes[1].y - g.fixes[1].y), 100.0);
    // no replanner: refused
    o.replan = nullptr;
    EXPECT_THROW(flyPlan(plan, 0.4, forecast, truth, nullptr, ControlStrategy::Replan, o), Error);
}

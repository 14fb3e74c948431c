// Wavefront ([ThompsonICRA] Sec. III, Algorithm 1) through OMPL: closed-form times in a uniform current (on a
// lattice direction: exact; off it: between the straight line and a two-offset lattice path), agreement with TVE on
// the meandering jet, a lane closed around the start that must be waited out (TVE cannot), a goal window met by
// holding at the goal, windows that cannot be met (no solution), parameters. Every returned path passes
// PathGeometric::check() under the motion validator.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <ompl/base/PlannerData.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/planners/Wavefront.h"
#include "ompl_glider/planners/ZAStarTVE.h"

using namespace ompl_glider;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
using TimeState = TimeSE2StateSpace::StateType;

struct WaveRun
{
    ob::PlannerStatus status;
    std::shared_ptr<Wavefront> planner;
    og::SimpleSetupPtr ss;
    bool checked{false};       ///< PathGeometric::check() of the returned path
    double lastStateTime{0.0}; ///< time of the path's last state
};

/// Solves p with a Wavefront on a lattice of spacing grid, sectors, intervals dt; checks the returned path.
WaveRun runWavefront(const GliderProblem &p, double grid, unsigned sectors, double dt)
{
    WaveRun r;
    std::shared_ptr<GliderContext> ctx;
    r.ss = makeSimpleSetup(p, &ctx);
    r.planner = std::make_shared<Wavefront>(r.ss->getSpaceInformation(), ctx);
    r.planner->setGridSize(grid);
    r.planner->setSectors(sectors);
    r.planner->setTimeStep(dt);
    r.ss->setPlanner(r.planner);
    r.status = r.ss->solve(ob::plannerNonTerminatingCondition());
    if (r.ss->haveExactSolutionPath())
    {
        og::PathGeometric path = r.ss->getSolutionPath();
        r.checked = path.check();
        r.lastStateTime = path.getStates().back()->as<TimeState>()->getTime();
    }
    return r;
}

/// Closed form: fastest time over a straight leg of displacement (dx, dy) in a uniform current (cu, cv) at speed
/// V (the upper root of the line-circle intersection, [EichhornRAS] Eq. 4-6); +inf when infeasible.
double straightTime(double dx, double dy, double cu, double cv, double V)
{
    const double L = std::hypot(dx, dy);
    const double pc = (dx * cu + dy * cv) / L;
    const double disc = pc * pc + V * V - (cu * cu + cv * cv);
    if (!(disc > 0.0))
        return std::numeric_limits<double>::infinity();
    const double vef = pc + std::sqrt(disc);
    return vef > 0.0 ? L / vef : std::numeric_limits<double>::infinity();
}

GliderProblem uniformProblem(double cu, double cv)
{
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(cu, cv);
    return p; // region x in [0, 10], y in [-4, 4], t0 = 0, horizon 60, V = 0.5
}
} // namespace

TEST(Wavefront, UniformCurrentOnALatticeDirectionGivesTheClosedFormStraightLineTime)
{
    // In a uniform current the time of a displacement d is a convex gauge F(d) = |d| / v_ef(d / |d|), so no lattice
    // path beats the straight line (triangle inequality), and the straight line along the offset (3, 1) is a lattice
    // path: the wavefront's arrival is F(goal - start) exactly, with no hold.
    const double cu = 0.2, cv = 0.1, g = 0.4;
    GliderProblem p = uniformProblem(cu, cv);
    p.start.x = 0.8;
    p.start.y = -2.0; // grid vertex (2, 5)
    p.goal.x = 0.8 + 5 * 3 * g;
    p.goal.y = -2.0 + 5 * 1 * g; // grid vertex (17, 10)
    const WaveRun r = runWavefront(p, g, 3, 0.0);
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(r.checked);
    const double exact = straightTime(p.goal.x - p.start.x, p.goal.y - p.start.y, cu, cv, 0.5);
    EXPECT_NEAR(r.planner->getTravelTime(), exact, 1e-6 * exact);
    EXPECT_DOUBLE_EQ(r.lastStateTime, p.t0 + r.planner->getTravelTime());
    EXPECT_EQ(r.planner->getHoldTime(), 0.0);
    // Nodes leave the queue in the order of the time they are occupied: none after the arrival is expanded, so at
    // most one node per vertex and interval up to the arrival (ordered by A alone, the hold chains would run to the
    // end of the 60-unit window first: about 546 x 76 nodes).
    const double dt = r.planner->effectiveTimeStep();
    const double vertices = 26.0 * 21.0 + 2.0;
    EXPECT_LE(static_cast<double>(r.planner->getExpandedNodes()),
              vertices * (std::floor(r.planner->getTravelTime() / dt) + 2.0));
}

TEST(Wavefront, UniformCurrentOffTheLatticeDirectionsLiesBetweenTheStraightLineAndATwoOffsetPath)
{
    // Goal - start = (7, 2) cells on the 8-neighbour lattice (sectors 1, [ThompsonICRA]'s compass directions):
    // lower bound the straight line F(7g, 2g); upper bound the lattice path of 5 steps (1, 0) and 2 steps (1, 1).
    const double cu = -0.15, cv = 0.2, g = 0.4, V = 0.5;
    GliderProblem p = uniformProblem(cu, cv);
    p.start.x = 1.2;
    p.start.y = -1.2;
    p.goal.x = 1.2 + 7 * g;
    p.goal.y = -1.2 + 2 * g;
    const WaveRun r = runWavefront(p, g, 1, 0.0);
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(r.checked);
    const double lower = straightTime(7 * g, 2 * g, cu, cv, V);
    const double upper = straightTime(5 * g, 0.0, cu, cv, V) + straightTime(2 * g, 2 * g, cu, cv, V);
    ASSERT_LT(lower, upper); // the bounds differ: the test can tell a wrong time
    EXPECT_GE(r.planner->getTravelTime(), lower * (1.0 - 1e-9));
    EXPECT_LE(r.planner->getTravelTime(), upper * (1.0 + 1e-6));
}

TEST(Wavefront, AgreesWithTveOnTheMeanderingJet)
{
    // Bound: every node whose arrival A lies in its own interval departs at A, as TVE departs at its labels, and
    // holding only adds options; where every leg's arrival is non-decreasing in its departure (FIFO, true of the
    // exact leg ODE) neither holding nor a later departure helps, so the wavefront's arrival equals TVE's up to
    // the integration tolerance of the legs, and is never later. The time-interval discretisation (dt) enters only
    // through holds. Asserted: W <= T_TVE (1 + 1e-6), |W - T_TVE| <= dt, and W = T_TVE (1e-6) when the path holds
    // nowhere.
    const double g = 0.4, dt = 0.5;
    for (const auto &sg : {std::array<double, 4>{0.0, 0.0, 8.0, 2.0}, std::array<double, 4>{1.0, -2.0, 9.0, 1.0}})
    {
        GliderProblem p;
        p.field = std::make_shared<MeanderingJet>();
        p.start.x = sg[0];
        p.start.y = sg[1];
        p.goal.x = sg[2];
        p.goal.y = sg[3];
        const WaveRun w = runWavefront(p, g, 2, dt);
        ASSERT_EQ(w.status, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_TRUE(w.checked);

        std::shared_ptr<GliderContext> ctx;
        auto ss = makeSimpleSetup(p, &ctx);
        auto tve = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "TVE");
        tve->setGridSize(g);
        tve->setSectors(2);
        tve->setSmooth(false);
        tve->setRefine(false);
        ss->setPlanner(tve);
        ASSERT_EQ(ss->solve(ob::plannerNonTerminatingCondition()), ob::PlannerStatus::EXACT_SOLUTION);
        const double T = tve->getTravelTime(), W = w.planner->getTravelTime();
        EXPECT_LE(W, T * (1.0 + 1e-6));
        EXPECT_LE(std::abs(W - T), dt);
        if (w.planner->getHoldTime() == 0.0)
        {
            EXPECT_NEAR(W, T, 1e-6 * T);
        }
    }
}

TEST(Wavefront, WaitsOutALaneClosedAroundTheStart)
{
    // Region x in [0, 6], y in [-1, 1]; a band x in [0.6, 1.0] across it (and beyond) closed during [0, 10]; start
    // (0.4, 0.2) west of it, goal (5.2, 0.2) east. Current (0.1, 0): along the line the glider makes V + 0.1 = 0.6
    // and can hold everywhere (|c| < V). Exact optimum: enter the band (x = 0.6) no earlier than t = 10, then fly
    // 4.6 at 0.6: T* = 10 + 4.6 / 0.6. The wavefront departs at an interval start, at most dt after the last
    // departure still blocked (10 - 0.2 / 0.6): T* < W <= T* + dt.
    const double g = 0.4, dt = 0.5, vg = 0.6;
    GliderProblem p = uniformProblem(0.1, 0.0);
    p.xMin = 0.0;
    p.xMax = 6.0;
    p.yMin = -1.0;
    p.yMax = 1.0;
    p.start.x = 0.4;
    p.start.y = 0.2;
    p.goal.x = 5.2;
    p.goal.y = 0.2;
    auto env = std::make_shared<ForbiddenRegions>();
    env->add(std::make_shared<TimeWindowedZone>("band", Polygon::rectangle(0.6, -2.0, 1.0, 2.0, "band"),
                                                std::vector<Interval>{{0.0, 10.0}}));
    p.environment = env;
    const WaveRun w = runWavefront(p, g, 3, dt);
    ASSERT_EQ(w.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(w.checked);
    const double best = 10.0 + 4.6 / vg;
    EXPECT_GT(w.planner->getTravelTime(), best);
    EXPECT_LE(w.planner->getTravelTime(), best + dt + 1e-9);
    // The path holds (without holding there is no path: TVE below), the hold shows in the timestamps (a motion
    // from a place to itself later), and the first waypoint at or past the band is reached after the closure.
    EXPECT_GT(w.planner->getHoldTime(), 0.0);
    const auto &wp = w.planner->getWaypoints();
    ASSERT_GE(wp.size(), 3u);
    bool held = false;
    for (std::size_t i = 1; i < wp.size(); ++i)
        held = held || (wp[i].x == wp[i - 1].x && wp[i].y == wp[i - 1].y && wp[i].t > wp[i - 1].t);
    EXPECT_TRUE(held);
    for (const TimedPoint &q : wp)
        if (q.x >= 0.6)
        {
            EXPECT_GT(q.t, 10.0);
            break;
        }

    // TVE and ZA*TVE wait too since their waiting edges (TveOptions::waiting), but only where a leg is
    // blocked, at a vertex, until a window's end: they hold at the start until 10 and then fly the whole 4.8 at 0.6,
    // 18 = T* + 0.2 / 0.6 (the wavefront holds at the band's edge instead and is earlier).
    for (const std::string conf : {"TVE", "ZA*TVE"})
    {
        std::shared_ptr<GliderContext> ctx;
        auto ss = makeSimpleSetup(p, &ctx);
        auto z = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, conf);
        z->setGridSize(g);
        z->setSectors(3);
        z->setSmooth(false);
        z->setRefine(false);
        ss->setPlanner(z);
        ss->solve(ob::plannerNonTerminatingCondition());
        ASSERT_TRUE(ss->haveExactSolutionPath()) << conf;
        EXPECT_GT(z->getTravelTime(), best) << conf;
        EXPECT_NEAR(z->getTravelTime(), best + 0.2 / vg, 1e-6) << conf;
        EXPECT_LT(w.planner->getTravelTime(), z->getTravelTime()) << conf;
    }
}

TEST(Wavefront, GoalWindowIsMetByHoldingAtTheGoal)
{
    // Uniform current (0.1, 0.05), |c| < V: the goal can be held. Earliest arrival T1 (closed form, lattice
    // direction (2, 1)); with arriveNotBefore = t0 + T1 + 3 the earliest valid arrival is exactly that time, reached
    // by arriving at T1 and holding 3 at the goal.
    const double cu = 0.1, cv = 0.05, g = 0.4;
    GliderProblem p = uniformProblem(cu, cv);
    p.t0 = 2.0;
    p.start.x = 1.2;
    p.start.y = 0.0;
    p.goal.x = 1.2 + 4 * 2 * g;
    p.goal.y = 0.0 + 4 * 1 * g;
    const double T1 = straightTime(p.goal.x - p.start.x, p.goal.y - p.start.y, cu, cv, 0.5);
    p.arriveNotBefore = p.t0 + T1 + 3.0;
    const WaveRun w = runWavefront(p, g, 3, 0.7);
    ASSERT_EQ(w.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(w.checked);
    EXPECT_DOUBLE_EQ(w.lastStateTime, p.arriveNotBefore);
    EXPECT_DOUBLE_EQ(w.planner->getTravelTime(), p.arriveNotBefore - p.t0);
    const auto &wp = w.planner->getWaypoints();
    ASSERT_GE(wp.size(), 3u);
    // the last motion is the hold at the goal from the earliest arrival to the window's opening
    const TimedPoint &a = wp[wp.size() - 2], &b = wp.back();
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_NEAR(a.x, p.goal.x, 1e-12);
    EXPECT_NEAR(a.y, p.goal.y, 1e-12);
    EXPECT_NEAR(a.t, p.t0 + T1, 1e-6 * T1);
    EXPECT_NEAR(w.planner->getHoldTime(), 3.0, 1e-6 * T1);

    // a window inside the horizon that opens after the earliest arrival but whose end is before it: no solution
    GliderProblem q = p;
    q.arriveNotBefore = -std::numeric_limits<double>::infinity();
    q.arriveNotAfter = p.t0 + 0.9 * T1;
    const WaveRun none = runWavefront(q, g, 3, 0.7);
    EXPECT_FALSE(none.ss->haveExactSolutionPath());
    EXPECT_FALSE(none.ss->haveSolutionPath());
    EXPECT_EQ(none.status, ob::PlannerStatus::ABORT);
    EXPECT_EQ(none.planner->lastOutcome(), WavefrontOutcome::Exhausted);
}

TEST(Wavefront, GoalWindowThatCannotBeHeldIsMetByTimingTheArrival)
{
    // A current of 0.6 > V = 0.5 along +x everywhere: nothing can hold. Goal 10 cells east: the earliest arrival is
    // T1 = 4 / 1.1 (closed form, straight east). A window [T1 + 2, T1 + 3] is met without holding, by a longer way
    // (a pair of diagonal steps NE + SE instead of two steps E adds 2 (0.4 sqrt 2 / v_ef(45 deg) - 0.4 / 1.1) = 0.92,
    // so three pairs reach the window): the arrival lies in the window and the path holds nowhere. A window ending
    // before T1 has no solution.
    const double g = 0.4;
    GliderProblem p = uniformProblem(0.6, 0.0);
    p.start.x = 0.4;
    p.start.y = 0.0;
    p.goal.x = 4.4;
    p.goal.y = 0.0;
    const double T1 = straightTime(4.0, 0.0, 0.6, 0.0, 0.5);
    ASSERT_NEAR(T1, 4.0 / 1.1, 1e-12);
    const WaveRun fastest = runWavefront(p, g, 1, 0.5);
    ASSERT_EQ(fastest.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_NEAR(fastest.planner->getTravelTime(), T1, 1e-6 * T1);

    p.arriveNotBefore = p.t0 + T1 + 2.0;
    p.arriveNotAfter = p.t0 + T1 + 3.0;
    const WaveRun timed = runWavefront(p, g, 1, 0.5);
    ASSERT_EQ(timed.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(timed.checked);
    EXPECT_GE(timed.lastStateTime, p.arriveNotBefore);
    EXPECT_LE(timed.lastStateTime, p.arriveNotAfter);
    EXPECT_EQ(timed.planner->getHoldTime(), 0.0);

    p.arriveNotBefore = -std::numeric_limits<double>::infinity();
    p.arriveNotAfter = p.t0 + 0.95 * T1;
    const WaveRun none = runWavefront(p, g, 1, 0.5);
    EXPECT_FALSE(none.ss->haveSolutionPath());
    EXPECT_EQ(none.planner->lastOutcome(), WavefrontOutcome::Exhausted);

    p.arriveNotAfter = p.t0 - 1.0; // a window that ends before the departure
    const WaveRun before = runWavefront(p, g, 1, 0.5);
    EXPECT_FALSE(before.ss->haveSolutionPath());
    EXPECT_EQ(before.status, ob::PlannerStatus::ABORT);
}

TEST(Wavefront, ParametersAreDeclaredCheckedAndReachedThroughTheRegistry)
{
    GliderProblem p = uniformProblem(0.0, 0.0);
    p.start.x = 1.0;
    p.start.y = 0.0;
    p.goal.x = 3.0;
    p.goal.y = 0.0;
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(p, &ctx);
    const PlannerEntry &e = plannerEntry("wavefront");
    EXPECT_EQ(e.name, "Wavefront");
    EXPECT_TRUE(e.lattice());
    auto planner = e.make(ss->getSpaceInformation(), ctx);
    ASSERT_NE(std::dynamic_pointer_cast<Wavefront>(planner), nullptr);
    EXPECT_TRUE(planner->params().setParam("grid_size", "0.25"));
    EXPECT_TRUE(planner->params().setParam("sectors", "2"));
    EXPECT_TRUE(planner->params().setParam("time_step", "0.3"));
    auto w = std::dynamic_pointer_cast<Wavefront>(planner);
    EXPECT_EQ(w->getGridSize(), 0.25);
    EXPECT_EQ(w->getSectors(), 2u);
    EXPECT_EQ(w->getTimeStep(), 0.3);
    EXPECT_THROW(w->setTimeStep(-1.0), Error);
    EXPECT_THROW(w->setTimeStep(std::numeric_limits<double>::infinity()), Error);
    EXPECT_THROW(w->setGridSize(0.0), Error);
    EXPECT_THROW(w->setSectors(6), Error);
    try
    {
        w->setTimeStep(-2.0);
    }
    catch (const Error &err)
    {
        EXPECT_NE(std::string(err.what()).find("time_step"), std::string::npos);
    }
    // automatic interval: grid_size / V
    w->setTimeStep(0.0);
    EXPECT_DOUBLE_EQ(w->effectiveTimeStep(), 0.25 / 0.5);
    // far too many intervals over the window: an Error naming time_step
    w->setTimeStep(1e-7);
    ss->setPlanner(planner);
    try
    {
        ss->solve(ob::plannerNonTerminatingCondition());
        ADD_FAILURE() << "no Error for 6e8 intervals";
    }
    catch (const Error &err)
    {
        EXPECT_NE(std::string(err.what()).find("time_step"), std::string::npos);
    }
    // solve / clear cycles give the same time; planner data holds the settled nodes
    w->setTimeStep(0.0);
    ss->clear();
    ASSERT_EQ(ss->solve(ob::plannerNonTerminatingCondition()), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(ss->getSolutionPath().check());
    const double first = w->getTravelTime();
    EXPECT_NEAR(first, 2.0 / 0.5, 1e-9);
    ob::PlannerData data(ss->getSpaceInformation());
    w->getPlannerData(data);
    EXPECT_EQ(data.numVertices(), w->getExpandedNodes());
    EXPECT_EQ(data.numStartVertices(), 1u);
    EXPECT_EQ(data.numGoalVertices(), 1u);
    ss->clear();
    ASSERT_EQ(ss->solve(ob::plannerNonTerminatingCondition()), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(w->getTravelTime(), first);
}

TEST(Wavefront, TheTerminationConditionEndsTheSearchWithoutAPath)
{
    GliderProblem p;
    p.field = std::make_shared<MeanderingJet>();
    p.start.x = 0.0;
    p.start.y = 0.0;
    p.goal.x = 8.0;
    p.goal.y = 2.0;
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(p, &ctx);
    auto w = std::make_shared<Wavefront>(ss->getSpaceInformation(), ctx);
    ss->setPlanner(w);
    const ob::PlannerStatus st = ss->solve(ob::PlannerTerminationCondition([] { return true; }));
    EXPECT_EQ(st, ob::PlannerStatus::TIMEOUT);
    EXPECT_EQ(w->lastOutcome(), WavefrontOutcome::Terminated);
    EXPECT_FALSE(ss->haveSolutionPath());
    EXPECT_LE(w->getExpandedNodes(), 64u); // the condition is asked every 64 expansions
}

TEST(Wavefront, ThePipelineGivesItTheMissionsLatticeAndItMatchesTve)
{
    // planRoute() hands the mission's grid size and sectors to the Wavefront as to ZA*TVE: on the built-in Gulf
    // Stream mission with a 0.5 lattice of 2 sectors both return the same raw lattice time (open water: see
    // AgreesWithTveOnTheMeanderingJet); with the Wavefront's defaults (0.4, 3 sectors) it would differ.
    double raw[2] = {0.0, 0.0};
    const char *names[2] = {"TVE", "Wavefront"};
    for (int i = 0; i < 2; ++i)
    {
        MissionSpec m = defaultGulfStreamMission();
        m.planner.name = names[i];
        m.planner.gridSize = 0.5;
        m.planner.sectors = 2;
        m.planner.smoothing = false;
        m.planner.refinement = false;
        const MissionResult r = runMission(MissionProblem(m));
        ASSERT_TRUE(r.plan.solved) << names[i] << ": " << r.plan.reason;
        EXPECT_EQ(r.plan.planner, names[i]);
        EXPECT_TRUE(r.plan.pathChecked) << names[i];
        raw[i] = r.plan.rawTravelTime;
    }
    EXPECT_NEAR(raw[1], raw[0], 1e-6 * raw[0]);
    MissionSpec m = defaultGulfStreamMission();
    m.planner.name = "Wavefront";
    m.planner.smoothing = false;
    m.planner.refinement = false;
    EXPECT_GT(std::abs(runMission(MissionProblem(m)).plan.rawTravelTime - raw[1]), 1e-3);
}

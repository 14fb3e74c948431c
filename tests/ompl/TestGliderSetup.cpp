#include <cmath>
#include <limits>
#include <memory>

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/util/RandomNumbers.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/GliderStateSampler.h"
#include "ompl_glider/ompl/PathResimulation.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "ompl_glider/ompl/TravelTimeObjective.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace ompl_glider;

namespace
{
GliderProblem uniformProblem(double cu, double cv)
{
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(cu, cv);
    p.start.x = 1.0;
    p.start.y = 0.0;
    p.goal.x = 9.0;
    p.goal.y = 0.0;
    return p;
}

/// Permanently forbidden disc.
class Disc : public Environment
{
public:
    Disc(double x, double y, double r) : x_(x), y_(y), r_(r) {}
    bool pointFree(double x, double y, double /*t*/) const override { return std::hypot(x - x_, y - y_) > r_; }
    bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override
    {
        for (int i = 0; i <= 200; ++i)
        {
            const double f = i / 200.0;
            if (!pointFree(x1 + f * (x2 - x1), y1 + f * (y2 - y1), t1 + f * (t2 - t1)))
                return false;
        }
        return true;
    }
    std::string whyBlocked(double x, double y, double t) const override
    {
        return pointFree(x, y, t) ? "" : "inside disc";
    }

private:
    double x_, y_, r_;
};
} // namespace

TEST(GliderSetup, BuildsReadySetup)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(uniformProblem(0.3, 0.0), &ctx);
    ASSERT_TRUE(ctx);
    EXPECT_DOUBLE_EQ(ctx->region.tMin, 0.0);
    EXPECT_DOUBLE_EQ(ctx->region.tMax, 60.0);
    EXPECT_DOUBLE_EQ(ctx->speed(), 0.5);
    auto space = std::dynamic_pointer_cast<TimeSE2StateSpace>(ss->getStateSpace());
    ASSERT_TRUE(space);
    EXPECT_NEAR(space->getTimeWeight(), 0.5 + ctx->maxCurrent(), 1e-12);
    EXPECT_NE(std::dynamic_pointer_cast<TravelTimeMotionValidator>(ss->getSpaceInformation()->getMotionValidator()),
              nullptr);
    EXPECT_NE(std::dynamic_pointer_cast<TravelTimeObjective>(ss->getOptimizationObjective()), nullptr);
    auto goal = std::dynamic_pointer_cast<PositionGoal>(ss->getGoal());
    ASSERT_TRUE(goal);
    EXPECT_DOUBLE_EQ(goal->getX(), 9.0);
    EXPECT_DOUBLE_EQ(goal->getTolerance(), 1e-3);
    EXPECT_NEAR(goal->getEarliestTime(), 8.0 / (0.5 + ctx->maxCurrent()), 1e-12);
    const auto *start = ss->getProblemDefinition()->getStartState(0)->as<TimeSE2StateSpace::StateType>();
    EXPECT_DOUBLE_EQ(start->getX(), 1.0);
    EXPECT_DOUBLE_EQ(start->getTime(), 0.0);
}

TEST(GliderSetup, DepartureIsTheStartStateTime)
{
    // The context holds no departure: makeSimpleSetup() puts problem.t0 into the start state, and the goal's
    // earliest time counts from it.
    GliderProblem p = uniformProblem(0.3, 0.0);
    p.t0 = 4.0;
    p.horizon = 30.0;
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(p, &ctx);
    EXPECT_EQ(ctx->region.tMin, 4.0);
    EXPECT_EQ(ctx->region.tMax, 34.0);
    const double vMax = 0.5 + ctx->maxCurrent();
    auto startTime = [](const og::SimpleSetupPtr &s) {
        return s->getProblemDefinition()->getStartState(0)->as<TimeSE2StateSpace::StateType>()->getTime();
    };
    EXPECT_EQ(startTime(ss), 4.0);
    EXPECT_EQ(std::dynamic_pointer_cast<PositionGoal>(ss->getGoal())->getEarliestTime(), 4.0 + 8.0 / vMax);
    // A setup on the same context departing later inside its window, and one departing outside it.
    p.t0 = 10.0;
    auto later = makeSimpleSetup(p, ctx);
    EXPECT_EQ(startTime(later), 10.0);
    EXPECT_EQ(std::dynamic_pointer_cast<PositionGoal>(later->getGoal())->getEarliestTime(), 10.0 + 8.0 / vMax);
    p.t0 = 40.0;
    EXPECT_THROW(makeSimpleSetup(p, ctx), Error);
}

TEST(GliderSetup, ErrorsNameTheField)
{
    auto expectError = [](GliderProblem p, const std::string &needle) {
        try
        {
            makeSimpleSetup(p);
            ADD_FAILURE() << "no exception, expected one mentioning '" << needle << "'";
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    GliderProblem p = uniformProblem(0.3, 0);
    p.field = nullptr;
    expectError(p, "field");
    p = uniformProblem(0.3, 0);
    p.horizon = 0;
    expectError(p, "horizon");
    p.horizon = -5;
    expectError(p, "horizon");
    p = uniformProblem(0.3, 0);
    p.start.x = 11;
    expectError(p, "start");
    p = uniformProblem(0.3, 0);
    p.goal.y = -4.5;
    expectError(p, "goal");
    p = uniformProblem(0.3, 0);
    p.goal.x = std::numeric_limits<double>::quiet_NaN();
    expectError(p, "goal");
    p = uniformProblem(0.3, 0);
    p.xMax = p.xMin;
    expectError(p, "x bounds");
    p = uniformProblem(0.3, 0);
    p.goalTolerance = -1;
    expectError(p, "goalTolerance");
    p = uniformProblem(0.3, 0);
    p.travel.speed = 0;
    expectError(p, "speed");
    p = uniformProblem(0.3, 0);
    p.t0 = std::numeric_limits<double>::infinity();
    expectError(p, "t0");
}

TEST(TravelTimeObjective, CostsAndHeuristics)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(uniformProblem(1.0, 0.0), &ctx);
    auto space = ss->getStateSpace();
    auto obj = ss->getOptimizationObjective();
    const double vMax = 0.5 + ctx->maxCurrent();
    ASSERT_GE(ctx->maxCurrent(), 1.0);
    ob::ScopedState<TimeSE2StateSpace> a(space), b(space);
    a->setXYT(1, 0, 2);
    a->setYaw(0);
    // c = (1, 0), V = 0.5, along +x: durations in [L / 1.5, L / 0.5] are valid.
    b->setXYT(4, 0, 2 + 3.0);
    b->setYaw(0);
    EXPECT_DOUBLE_EQ(obj->motionCost(a.get(), b.get()).value(), 3.0);
    b->setTime(2 + 1.9); // faster than L / 1.5 = 2
    EXPECT_FALSE(obj->isFinite(obj->motionCost(a.get(), b.get())));
    b->setTime(2 + 6.5); // slower than L / 0.5 = 6
    EXPECT_FALSE(obj->isFinite(obj->motionCost(a.get(), b.get())));
    EXPECT_DOUBLE_EQ(obj->stateCost(a.get()).value(), 0.0);
    EXPECT_FALSE(obj->isSymmetric());
    // heuristics
    b->setXYT(4, 4, 2.5);
    EXPECT_NEAR(obj->motionCostHeuristic(a.get(), b.get()).value(), 5.0 / vMax, 1e-12);
    b->setTime(20);
    EXPECT_NEAR(obj->motionCostHeuristic(a.get(), b.get()).value(), 18.0, 1e-12);
    EXPECT_NEAR(obj->costToGo(a.get(), ss->getGoal().get()).value(), (8.0 - 1e-3) / vMax, 1e-12);
    // path cost = arrival time - t0
    og::PathGeometric path(ss->getSpaceInformation());
    ob::ScopedState<TimeSE2StateSpace> s0(space), s1(space), s2(space);
    s0->setXYT(1, 0, 0);
    s1->setXYT(4, 0, 3);
    s2->setXYT(9, 0, 8);
    for (auto *s : {&s0, &s1, &s2})
        (*s)->setYaw(0);
    path.append(s0.get());
    path.append(s1.get());
    path.append(s2.get());
    EXPECT_TRUE(path.check());
    EXPECT_NEAR(path.cost(obj).value(), 8.0, 1e-12);
}

TEST(PositionGoal, SamplingAndDistance)
{
    std::shared_ptr<GliderContext> ctx;
    GliderProblem p = uniformProblem(0.3, 0.0);
    p.goalTolerance = 0.2;
    auto ss = makeSimpleSetup(p, &ctx);
    auto goal = std::dynamic_pointer_cast<PositionGoal>(ss->getGoal());
    ASSERT_TRUE(goal);
    const double tLo = 8.0 / (0.5 + ctx->maxCurrent());
    EXPECT_NEAR(goal->getEarliestTime(), tLo, 1e-12);
    EXPECT_DOUBLE_EQ(goal->getLatestTime(), 60.0);
    EXPECT_TRUE(goal->canSample());
    ob::ScopedState<TimeSE2StateSpace> s(ss->getStateSpace());
    double lo = 1e9, hi = -1e9;
    for (int i = 0; i < 2000; ++i)
    {
        goal->sampleGoal(s.get());
        ASSERT_DOUBLE_EQ(s->getX(), 9.0);
        ASSERT_DOUBLE_EQ(s->getY(), 0.0);
        ASSERT_GE(s->getTime(), tLo);
        ASSERT_LE(s->getTime(), 60.0);
        ASSERT_TRUE(goal->isSatisfied(s.get()));
        lo = std::min(lo, s->getTime());
        hi = std::max(hi, s->getTime());
    }
    // uniform over the window: both ends are approached
    EXPECT_LT(lo, tLo + 0.5);
    EXPECT_GT(hi, 59.5);
    s->setXYT(9.0, 0.15, 30);
    EXPECT_NEAR(goal->distanceGoal(s.get()), 0.15, 1e-12);
    EXPECT_TRUE(goal->isSatisfied(s.get()));
    s->setXYT(9.0, 0.25, 30);
    EXPECT_FALSE(goal->isSatisfied(s.get()));
    EXPECT_THROW(PositionGoal(ss->getSpaceInformation(), 1, 1, -0.1, 0, 1), Error);
    EXPECT_THROW(PositionGoal(ss->getSpaceInformation(), 1, 1, 0.1, 2, 1), Error);
}

TEST(GliderStateSampler, NoUnreachableTimes)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(uniformProblem(0.3, 0.0), &ctx);
    auto sampler = ss->getStateSpace()->allocStateSampler();
    ASSERT_NE(std::dynamic_pointer_cast<GliderStateSampler>(sampler), nullptr);
    const double vMax = 0.5 + ctx->maxCurrent();
    ob::ScopedState<TimeSE2StateSpace> s(ss->getStateSpace());
    for (int i = 0; i < 1000; ++i)
    {
        sampler->sampleUniform(s.get());
        ASSERT_TRUE(ss->getStateSpace()->satisfiesBounds(s.get()));
        ASSERT_GE(s->getTime(), std::hypot(s->getX() - 1.0, s->getY()) / vMax - 1e-12);
    }
}

TEST(PathResimulation, UniformCurrentClosedForm)
{
    std::shared_ptr<GliderContext> ctx = makeGliderContext(uniformProblem(0.3, 0.0));
    // (1,0) -> (4,0) downstream at 0.8, then (4,0) -> (4,2) across at 0.4, then back upstream (4,2) -> (2,2) at 0.2
    const std::vector<std::array<double, 2>> wp{{1, 0}, {4, 0}, {4, 2}, {2, 2}};
    const PathResimulation r = resimulatePath(*ctx, wp, 1.0);
    EXPECT_TRUE(r.valid);
    EXPECT_TRUE(r.finite);
    EXPECT_FALSE(r.waited);
    ASSERT_EQ(r.times.size(), 4u);
    EXPECT_NEAR(r.times[1], 1.0 + 3.0 / 0.8, 1e-9);
    EXPECT_NEAR(r.times[2], r.times[1] + 2.0 / 0.4, 1e-9);
    EXPECT_NEAR(r.times[3], r.times[2] + 2.0 / 0.2, 1e-9);
    EXPECT_NEAR(r.travelTime, 3.0 / 0.8 + 5.0 + 10.0, 1e-9);
    EXPECT_EQ(r.firstBadLeg, -1);
}

TEST(PathResimulation, InfeasibleAndBlockedLegs)
{
    // c = (1, 0) > V: upstream legs are infeasible whatever the waiting.
    auto ctx = makeGliderContext(uniformProblem(1.0, 0.0));
    const PathResimulation r = resimulatePath(*ctx, {{1, 0}, {4, 0}, {2, 0}, {3, 0}}, 0.0);
    EXPECT_FALSE(r.finite);
    EXPECT_FALSE(r.valid);
    EXPECT_EQ(r.firstBadLeg, 1);
    EXPECT_FALSE(std::isfinite(r.arrivalTime));
    EXPECT_NE(r.reason.find("leg 1"), std::string::npos) << r.reason; // names the first bad leg
    // A leg through a forbidden disc.
    GliderProblem p = uniformProblem(0.0, 0.0);
    p.environment = std::make_shared<Disc>(5, 0, 1);
    auto ctx2 = makeGliderContext(p);
    const PathResimulation r2 = resimulatePath(*ctx2, {{1, 2}, {3, 2}, {7, -0.5}, {9, 0}}, 0.0);
    EXPECT_FALSE(r2.valid);
    EXPECT_EQ(r2.firstBadLeg, 1);
    EXPECT_NE(r2.reason.find("leg 1"), std::string::npos) << r2.reason;
    const PathResimulation r3 = resimulatePath(*ctx2, {{1, 2}, {5, 2}, {9, 0}}, 0.0);
    EXPECT_TRUE(r3.valid);
    EXPECT_NEAR(r3.arrivalTime, (4.0 + std::hypot(4.0, 2.0)) / 0.5, 1e-9);
}

TEST(PathResimulation, WaitingForAWindow)
{
    // Forbidden disc around (5, 0) until t = 20 (then it vanishes): flying straight at V = 0.5 from (1, 0) at t0 = 0
    // reaches it at t = 6; with waiting the glider holds at the start (calm water) and arrives at the earliest
    // departure on the grid after 20 - (4 - r) / V, plus 8 / V.
    class TimedDisc : public Environment
    {
    public:
        bool pointFree(double x, double y, double t) const override { return t >= 20.0 || std::hypot(x - 5, y) > 1.0; }
        bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override
        {
            for (int i = 0; i <= 400; ++i)
            {
                const double f = i / 400.0;
                if (!pointFree(x1 + f * (x2 - x1), y1 + f * (y2 - y1), t1 + f * (t2 - t1)))
                    return false;
            }
            return true;
        }
        std::string whyBlocked(double, double, double) const override { return "disc"; }
    };
    GliderProblem p = uniformProblem(0.0, 0.0);
    p.environment = std::make_shared<TimedDisc>();
    auto ctx = makeGliderContext(p);
    ResimulationOptions noWait;
    noWait.allowWaiting = false;
    const PathResimulation direct = resimulatePath(*ctx, {{1, 0}, {9, 0}}, 0.0, noWait);
    EXPECT_FALSE(direct.valid);
    EXPECT_NEAR(direct.arrivalTime, 16.0, 1e-9);
    const PathResimulation w = resimulatePath(*ctx, {{1, 0}, {9, 0}}, 0.0);
    EXPECT_TRUE(w.valid);
    EXPECT_TRUE(w.waited);
    const double step = 60.0 / 512.0;
    const double depart = 20.0 - 3.0 / 0.5; // reaches the disc edge x = 4 exactly at t = 20
    EXPECT_GE(w.arrivalTime, depart + 16.0 - 1e-9);
    EXPECT_LE(w.arrivalTime, depart + 16.0 + step + 1e-9);
}

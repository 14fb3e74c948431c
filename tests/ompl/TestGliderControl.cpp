// OMPL control-based planning (GliderControl.h): the heading propagator against closed forms in a uniform
// current, groundings on land, on a forbidden region and at the planning box making the motion invalid, and oc::SST
// reaching the goal in a uniform current twice the glider's speed with a travel time that the re-flight of its
// controls confirms and that no path can beat (the closed-form earliest entry into the goal disc).
#include <cmath>
#include <iostream>
#include <memory>

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/control/planners/sst/SST.h>
#include <ompl/util/RandomNumbers.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/execution/GliderControl.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ob = ompl::base;
namespace oc = ompl::control;
using namespace ompl_glider;

namespace
{
/// A uniform current with land east of x = xLand.
class UniformWithLand : public UniformCurrent
{
public:
    UniformWithLand(double u, double v, double xLand) : UniformCurrent(u, v), xLand_(xLand) {}
    bool inWater(double x, double /*y*/, double /*z*/) const override { return x < xLand_; }
    std::string name() const override { return "uniform with land"; }

private:
    double xLand_;
};

/// Box [0, 10] x [0, 5], horizon 12, V = 0.5, current (cu, cv).
GliderProblem uniformControlProblem(std::shared_ptr<const CurrentField> field)
{
    GliderProblem p;
    p.field = std::move(field);
    p.travel.speed = 0.5;
    p.xMin = 0.0;
    p.xMax = 10.0;
    p.yMin = 0.0;
    p.yMax = 5.0;
    p.horizon = 12.0;
    p.start = {1.0, 2.5};
    p.goal = {7.0, 4.0};
    return p;
}

/// Earliest T > 0 with |d - c T| = V T + r: the first entry of the reachable disc (centre start + c T, radius V T)
/// into the goal disc of radius r, for |c| > V; NaN when there is none.
double earliestEntry(Point2 d, Velocity c, double V, double r)
{
    const double a = c.u * c.u + c.v * c.v - V * V, b = d.x * c.u + d.y * c.v + V * r;
    const double q = d.x * d.x + d.y * d.y - r * r;
    const double disc = b * b - a * q;
    if (disc < 0.0 || b <= 0.0)
        return std::nan("");
    return (b - std::sqrt(disc)) / a;
}

struct Propagation
{
    std::shared_ptr<GliderControlSetup> ss;
    oc::SpaceInformationPtr si;
    ob::ScopedState<TimeSE2StateSpace> from, to;
    oc::Control *control;

    explicit Propagation(const GliderProblem &p)
        : ss(makeControlSetup(p)), si(ss->getSpaceInformation()), from(si->getStateSpace()), to(si->getStateSpace())
    {
        ss->setup();
        control = si->allocControl();
    }
    ~Propagation() { si->freeControl(control); }
    /// Propagates from (x, y, t) with the bearing for the duration into `to`.
    void fly(double x, double y, double t, double bearing, double duration)
    {
        from->setXYT(x, y, t);
        from->setYaw(0.0);
        HeadingControlSpace::setBearing(control, bearing);
        si->getStatePropagator()->propagate(from.get(), control, duration, to.get());
    }
};
} // namespace

TEST(GliderControl, SetupHasHeadingControlsPropagatorAndDiscGoal)
{
    const auto field = std::make_shared<UniformCurrent>(1.0, 0.0);
    auto ss = makeControlSetup(uniformControlProblem(field));
    const oc::SpaceInformationPtr &si = ss->getSpaceInformation();
    ASSERT_NE(std::dynamic_pointer_cast<HeadingControlSpace>(si->getControlSpace()), nullptr);
    auto prop = std::dynamic_pointer_cast<GliderStatePropagator>(si->getStatePropagator());
    ASSERT_NE(prop, nullptr);
    EXPECT_FALSE(si->canPropagateBackward());
    // defaults: D = |(10, 5)|, vMax = V + |c| = 1.5, step D / vMax / 100, four RK4 steps per propagation step
    const double D = std::hypot(10.0, 5.0), step = D / 1.5 / 100.0;
    EXPECT_DOUBLE_EQ(si->getPropagationStepSize(), step);
    EXPECT_EQ(si->getMinControlDuration(), 1u);
    EXPECT_EQ(si->getMaxControlDuration(), 100u);
    EXPECT_DOUBLE_EQ(prop->diveSettings().step, step / 4.0);
    EXPECT_DOUBLE_EQ(prop->diveSettings().speed, 0.5);
    auto goal = std::dynamic_pointer_cast<PositionGoal>(ss->getGoal());
    ASSERT_NE(goal, nullptr);
    EXPECT_DOUBLE_EQ(goal->getTolerance(), D / 100.0);
    EXPECT_NE(
        std::dynamic_pointer_cast<ControlTravelTimeObjective>(ss->getProblemDefinition()->getOptimizationObjective()),
        nullptr);
    const auto bounds = std::dynamic_pointer_cast<HeadingControlSpace>(si->getControlSpace())->getBounds();
    EXPECT_EQ(bounds.low[0], 0.0);
    EXPECT_EQ(bounds.high[0], 360.0);
    ControlSettings bad;
    bad.minSteps = 5;
    bad.maxSteps = 2;
    EXPECT_THROW(makeControlSetup(uniformControlProblem(field), bad), Error);
}

TEST(GliderControl, PropagatorInUniformCurrentMatchesTheClosedForm)
{
    // dx/dt = V h + c is constant: the end point is start + (V h + c) T, h = (sin b, cos b); time advances by T
    const Velocity c{0.8, -0.35};
    const double V = 0.5;
    Propagation p(uniformControlProblem(std::make_shared<UniformCurrent>(c.u, c.v)));
    for (double bearing : {0.0, 37.0, 90.0, 200.0, 301.5})
        for (double T : {0.05, 0.4, 1.3})
        {
            p.fly(3.0, 2.5, 1.25, bearing, T);
            const Point2 h = bearingVector(bearing);
            EXPECT_NEAR(p.to->getX(), 3.0 + (V * h.x + c.u) * T, 1e-12) << bearing << " " << T;
            EXPECT_NEAR(p.to->getY(), 2.5 + (V * h.y + c.v) * T, 1e-12) << bearing << " " << T;
            EXPECT_EQ(p.to->getTime(), 1.25 + T);
            EXPECT_NEAR(p.to->getYaw(), std::atan2(h.y, h.x), 1e-12);
            EXPECT_TRUE(p.si->isValid(p.to.get()));
        }
    // k propagation steps through the space information: start + (V h + c) k dt
    const double dt = p.si->getPropagationStepSize();
    HeadingControlSpace::setBearing(p.control, 45.0);
    p.from->setXYT(3.0, 2.5, 0.0);
    ASSERT_EQ(p.si->propagateWhileValid(p.from.get(), p.control, 7, p.to.get()), 7u);
    const Point2 h = bearingVector(45.0);
    EXPECT_NEAR(p.to->getX(), 3.0 + (V * h.x + c.u) * 7 * dt, 1e-12);
    EXPECT_NEAR(p.to->getY(), 2.5 + (V * h.y + c.v) * 7 * dt, 1e-12);
    EXPECT_NEAR(p.to->getTime(), 7 * dt, 1e-12);
    // a zero duration is the state itself; a negative one is refused (invalid result)
    p.fly(3.0, 2.5, 1.0, 10.0, 0.0);
    EXPECT_EQ(p.to->getX(), 3.0);
    EXPECT_EQ(p.to->getTime(), 1.0);
    p.fly(3.0, 2.5, 1.0, 10.0, -0.5);
    EXPECT_FALSE(p.si->isValid(p.to.get()));
}

TEST(GliderControl, GroundingOnLandMakesTheMotionInvalid)
{
    // current (1, 0), heading east: ground speed 1.5 towards the coast at x = 5
    Propagation p(uniformControlProblem(std::make_shared<UniformWithLand>(1.0, 0.0, 5.0)));
    p.fly(4.0, 2.5, 0.0, 90.0, 2.0);
    EXPECT_FALSE(p.si->isValid(p.to.get()));
    EXPECT_TRUE(std::isinf(p.to->getTime()));
    EXPECT_LT(p.to->getX(), 5.0); // the last point in water
    EXPECT_GE(p.to->getX(), 5.0 - 1.5 * p.si->getPropagationStepSize() / 4.0);
    // the same heading for less time stays in water
    p.fly(4.0, 2.5, 0.0, 90.0, 0.5);
    EXPECT_TRUE(p.si->isValid(p.to.get()));
    EXPECT_NEAR(p.to->getX(), 4.75, 1e-12);
    // propagateWhileValid keeps the steps before the grounding: k valid steps end short of the coast and one more
    // would reach it
    const double dt = p.si->getPropagationStepSize();
    HeadingControlSpace::setBearing(p.control, 90.0);
    p.from->setXYT(4.0, 2.5, 0.0);
    const unsigned k = p.si->propagateWhileValid(p.from.get(), p.control, 40, p.to.get());
    EXPECT_LT(k, 40u);
    EXPECT_NEAR(p.to->getX(), 4.0 + 1.5 * k * dt, 1e-12);
    EXPECT_LT(4.0 + 1.5 * k * dt, 5.0);
    EXPECT_GE(4.0 + 1.5 * (k + 1) * dt, 5.0);
}

TEST(GliderControl, CrossingAForbiddenRegionWithinOneStepMakesTheMotionInvalid)
{
    // a wall x in [6, 6.02] thinner than one propagation step's travel (1.5 dt ~ 0.11): the end state beyond it is
    // free, the motion is not
    auto walls = std::make_shared<ForbiddenRegions>();
    walls->add(std::make_shared<StaticRegion>("wall", Polygon::rectangle(6.0, 0.0, 6.02, 5.0, "wall"), "island"));
    GliderProblem prob = uniformControlProblem(std::make_shared<UniformCurrent>(1.0, 0.0));
    prob.environment = walls;
    Propagation p(prob);
    const double dt = p.si->getPropagationStepSize();
    ASSERT_GT(1.5 * dt, 0.1);
    p.fly(5.95, 2.5, 0.0, 90.0, dt);
    EXPECT_FALSE(p.si->isValid(p.to.get()));
    EXPECT_LE(p.to->getX(), 6.0);
    const double endX = 5.95 + 1.5 * dt;
    ASSERT_GT(endX, 6.02);
    p.from->setXYT(endX, 2.5, dt);
    EXPECT_TRUE(p.si->isValid(p.from.get())); // the end point alone is free
    // the same step short of the wall is valid
    p.fly(5.7, 2.5, 0.0, 90.0, dt);
    EXPECT_TRUE(p.si->isValid(p.to.get()));
}

TEST(GliderControl, LeavingThePlanningBoxMakesTheMotionInvalid)
{
    // heading north in current (1, 0): ground velocity (1, 0.5) crosses y = 5 after 0.2
    Propagation p(uniformControlProblem(std::make_shared<UniformCurrent>(1.0, 0.0)));
    p.fly(5.0, 4.9, 0.0, 0.0, 1.0);
    EXPECT_FALSE(p.si->isValid(p.to.get()));
    EXPECT_LE(p.to->getY(), 5.0);
}

TEST(GliderControl, StartInForbiddenRegionIsRefused)
{
    auto regions = std::make_shared<ForbiddenRegions>();
    regions->add(std::make_shared<StaticRegion>("A", Polygon::regular(1.0, 2.5, 0.3, 12, 0.0, "A"), "island"));
    GliderProblem prob = uniformControlProblem(std::make_shared<UniformCurrent>(1.0, 0.0));
    prob.environment = regions;
    auto ss = makeControlSetup(prob);
    ss->setPlanner(std::make_shared<oc::SST>(ss->getSpaceInformation()));
    EXPECT_EQ(ss->solve(0.1), ob::PlannerStatus::INVALID_START);
    EXPECT_NE(ss->lastCheckMessage().find("A"), std::string::npos) << ss->lastCheckMessage();
}

TEST(GliderControl, SSTReachesTheGoalInACurrentTwiceTheSpeedAndItsTimeIsTheReflight)
{
    // current (1, 0) twice V = 0.5: the reachable cone from (1, 2.5) has half-angle asin(V / |c|) = 30 degrees and
    // holds the goal (7, 4) (14 degrees off the current)
    ompl::RNG::setSeed(24);
    const Velocity c{1.0, 0.0};
    const auto field = std::make_shared<UniformCurrent>(c.u, c.v);
    const GliderProblem prob = uniformControlProblem(field);
    auto ss = makeControlSetup(prob);
    const oc::SpaceInformationPtr &si = ss->getSpaceInformation();
    ss->setPlanner(std::make_shared<oc::SST>(si));
    int iterations = 0;
    const ob::PlannerTerminationCondition ptc([&iterations] { return ++iterations > 20000; });
    ASSERT_EQ(ss->solve(ob::plannerOrTerminationCondition(ptc, ob::timedPlannerTerminationCondition(8.0))),
              ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_TRUE(ss->haveExactSolutionPath());
    const oc::PathControl &path = ss->getSolutionPath();
    const double tol = ss->settings().goalTolerance;
    const auto *last = path.getState(path.getStateCount() - 1)->as<TimeSE2StateSpace::StateType>();
    EXPECT_LE(std::hypot(last->getX() - prob.goal.x, last->getY() - prob.goal.y), tol);
    // the path's duration is the sum of its control durations, the last state's time, and the objective's cost
    const double duration = path.length();
    EXPECT_NEAR(last->getTime() - prob.t0, duration, 1e-9 * duration);
    const ob::OptimizationObjectivePtr opt = ss->getProblemDefinition()->getOptimizationObjective();
    ob::Cost cost = opt->identityCost();
    for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
        cost = opt->combineCosts(cost, opt->motionCost(path.getState(i), path.getState(i + 1)));
    EXPECT_NEAR(cost.value(), duration, 1e-9 * duration);
    // no path enters the goal disc before the closed-form earliest entry; SST's is within 50 % of it
    const double best = earliestEntry({prob.goal.x - prob.start.x, prob.goal.y - prob.start.y}, c, 0.5, tol);
    ASSERT_TRUE(std::isfinite(best));
    EXPECT_GE(duration, best - 1e-9);
    EXPECT_LE(duration, 1.5 * best);
    std::cout << "SST: travel time " << duration << ", closed-form earliest entry into the goal disc " << best << "\n";
    // re-flown from the start with flyHeadingRoute: the same end, at t0 + duration, in the goal disc
    const HeadingRoute route = controlPathToHeadingRoute(path);
    ASSERT_EQ(route.segments.size(), path.getControlCount());
    EXPECT_NEAR(route.duration(), duration, 1e-9 * duration);
    const auto prop = std::dynamic_pointer_cast<GliderStatePropagator>(si->getStatePropagator());
    const HeadingFlight f = flyHeadingRoute(route, *field, nullptr, prop->diveSettings(), false);
    EXPECT_FALSE(f.grounded);
    ASSERT_EQ(f.ends.size(), path.getStateCount());
    for (std::size_t i = 0; i < f.ends.size(); ++i)
    {
        const auto *s = path.getState(i)->as<TimeSE2StateSpace::StateType>();
        EXPECT_NEAR(f.ends[i].x, s->getX(), 1e-9) << i;
        EXPECT_NEAR(f.ends[i].y, s->getY(), 1e-9) << i;
        EXPECT_NEAR(f.ends[i].t, s->getTime(), 1e-9 * duration) << i;
    }
    EXPECT_NEAR(f.ends.back().t - prob.t0, duration, 1e-9 * duration);
    EXPECT_LE(std::hypot(f.ends.back().x - prob.goal.x, f.ends.back().y - prob.goal.y), tol);
    EXPECT_TRUE(path.check());
}

// OMPL control-based planning on the glider problems: heading controls flown by the dive integrator (see
// GliderControl.h).
#include "ompl_glider/execution/GliderControl.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <ompl/base/ScopedState.h>
#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/GliderStateSampler.h"
#include "ompl_glider/ompl/GliderStateValidityChecker.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "../core/Numbers.h"

namespace ob = ompl::base;
namespace oc = ompl::control;

namespace ompl_glider
{
namespace
{

void requireContext(const std::shared_ptr<const GliderContext> &ctx, const char *who)
{
    if (!ctx || !ctx->field || !ctx->travel)
        throw Error(std::string(who) + ": the GliderContext (with its field and travel-time calculator) is required");
}

bool inBox(const Region &r, double x, double y)
{
    return x >= r.xMin && x <= r.xMax && y >= r.yMin && y <= r.yMax;
}

/// The result of a motion that cannot be flown: the last point before the failure with the time +inf, outside the
/// space's time bounds, so that no validity checker accepts it.
void setUnflyable(TimeSE2StateSpace::StateType *r, double x, double y, double yaw)
{
    r->setXYT(x, y, kInf);
    r->setYaw(yaw);
}
} // namespace

HeadingControlSpace::HeadingControlSpace(const ob::StateSpacePtr &stateSpace)
    : oc::RealVectorControlSpace(stateSpace, 1)
{
    setName("Heading");
    ob::RealVectorBounds b(1);
    b.setLow(0.0);
    b.setHigh(360.0);
    setBounds(b);
}

double HeadingControlSpace::bearing(const oc::Control *control)
{
    return control->as<oc::RealVectorControlSpace::ControlType>()->values[0];
}

void HeadingControlSpace::setBearing(oc::Control *control, double bearingDeg)
{
    control->as<oc::RealVectorControlSpace::ControlType>()->values[0] = bearingDeg;
}

GliderStatePropagator::GliderStatePropagator(oc::SpaceInformation *si, std::shared_ptr<const GliderContext> ctx,
                                             double diveStep)
    : oc::StatePropagator(si), ctx_(std::move(ctx))
{
    requireContext(ctx_, "GliderStatePropagator");
    if (!(diveStep > 0.0) || !std::isfinite(diveStep))
        throw Error("GliderStatePropagator: the dive step must be positive and finite (got " +
                    std::to_string(diveStep) + ")");
    dive_.speed = ctx_->speed();
    dive_.step = diveStep;
    dive_.depth = ctx_->travel->params().depth;
    dive_.radius = 0.0; // the planners test the goal on the propagated states
}

void GliderStatePropagator::propagate(const ob::State *state, const oc::Control *control, double duration,
                                      ob::State *result) const
{
    // read everything first: result may be state
    const auto *s = state->as<TimeSE2StateSpace::StateType>();
    const double x = s->getX(), y = s->getY(), t = s->getTime();
    const Point2 h = bearingVector(HeadingControlSpace::bearing(control));
    const double yaw = std::atan2(h.y, h.x);
    auto *r = result->as<TimeSE2StateSpace::StateType>();
    if (duration == 0.0)
    {
        if (result != state)
            si_->copyState(result, state);
        return;
    }
    if (!(duration > 0.0) || !std::isfinite(duration) || !std::isfinite(t))
    {
        setUnflyable(r, x, y, yaw);
        return;
    }
    thread_local std::vector<TimedPoint> track;
    track.clear();
    const DiveEnd e = flyHeading(x, y, t, h.x, h.y, t + duration, *ctx_->field, ctx_->environment.get(), dive_, &track);
    // the planning box along the dive (the end state's bounds are the validity checker's)
    double lx = x, ly = y;
    for (const TimedPoint &p : track)
    {
        if (!inBox(ctx_->region, p.x, p.y))
        {
            setUnflyable(r, lx, ly, yaw);
            return;
        }
        lx = p.x;
        ly = p.y;
    }
    if (e.grounded)
    {
        setUnflyable(r, e.x, e.y, yaw);
        return;
    }
    r->setXYT(e.x, e.y, t + duration);
    r->setYaw(yaw);
}

ControlTravelTimeObjective::ControlTravelTimeObjective(const ob::SpaceInformationPtr &si,
                                                       std::shared_ptr<const GliderContext> ctx)
    : ob::OptimizationObjective(si)
{
    requireContext(ctx, "ControlTravelTimeObjective");
    description_ = "travel time of heading controls";
    vMax_ = ctx->speed() + ctx->maxCurrent();
    setCostToGoHeuristic([this](const ob::State *st, const ob::Goal *goal) {
        const auto *pg = dynamic_cast<const PositionGoal *>(goal);
        if (!pg)
            return identityCost();
        const auto *s = st->as<TimeSE2StateSpace::StateType>();
        const double d = std::hypot(s->getX() - pg->getX(), s->getY() - pg->getY());
        return ob::Cost(std::max(0.0, d - pg->getTolerance()) / vMax_);
    });
}

ob::Cost ControlTravelTimeObjective::stateCost(const ob::State * /*s*/) const
{
    return identityCost();
}

ob::Cost ControlTravelTimeObjective::motionCost(const ob::State *s1, const ob::State *s2) const
{
    return ob::Cost(s2->as<TimeSE2StateSpace::StateType>()->getTime() -
                    s1->as<TimeSE2StateSpace::StateType>()->getTime());
}

ob::Cost ControlTravelTimeObjective::motionCostHeuristic(const ob::State *s1, const ob::State *s2) const
{
    const double dt =
        s2->as<TimeSE2StateSpace::StateType>()->getTime() - s1->as<TimeSE2StateSpace::StateType>()->getTime();
    return ob::Cost(std::max(TimeSE2StateSpace::xyDistance(s1, s2) / vMax_, dt));
}

GliderControlSetup::GliderControlSetup(const oc::ControlSpacePtr &controlSpace, std::shared_ptr<GliderContext> ctx,
                                       const ControlSettings &settings)
    : oc::SimpleSetup(controlSpace), ctx_(std::move(ctx)), settings_(settings)
{
}

bool GliderControlSetup::rejectStartOrGoal()
{
    setup();
    lastCheckMessage_.clear();
    const ob::PlannerStatus st = checkStartAndGoal(*pdef_, &lastCheckMessage_);
    if (st == ob::PlannerStatus::UNKNOWN)
        return false;
    OMPL_ERROR("%s", lastCheckMessage_.c_str());
    pdef_->clearSolutionPaths();
    last_status_ = st;
    planTime_ = 0.0;
    return true;
}

ob::PlannerStatus GliderControlSetup::solve(double time)
{
    if (rejectStartOrGoal())
        return last_status_;
    return oc::SimpleSetup::solve(time);
}

ob::PlannerStatus GliderControlSetup::solve(const ob::PlannerTerminationCondition &ptc)
{
    if (rejectStartOrGoal())
        return last_status_;
    return oc::SimpleSetup::solve(ptc);
}

ControlSettings resolveControlSettings(const GliderProblem &p, const GliderContext &ctx, const ControlSettings &in)
{
    ControlSettings s = in;
    const Region &r = ctx.region;
    const double diagonal = std::hypot(r.xMax - r.xMin, r.yMax - r.yMin);
    const double vMax = ctx.speed() + ctx.maxCurrent();
    if (!(s.propagationStep >= 0.0) || !std::isfinite(s.propagationStep))
        throw Error("ControlSettings: propagationStep must be finite and >= 0 (got " +
                    std::to_string(s.propagationStep) + ")");
    if (!(s.goalTolerance >= 0.0) || !std::isfinite(s.goalTolerance))
        throw Error("ControlSettings: goalTolerance must be finite and >= 0 (got " + std::to_string(s.goalTolerance) +
                    ")");
    if (s.minSteps < 1 || s.maxSteps < s.minSteps)
        throw Error("ControlSettings: need 1 <= minSteps <= maxSteps (got " + std::to_string(s.minSteps) + ", " +
                    std::to_string(s.maxSteps) + ")");
    if (s.diveSubsteps < 1)
        throw Error("ControlSettings: diveSubsteps must be >= 1");
    if (s.propagationStep == 0.0)
        s.propagationStep = diagonal / vMax / 100.0;
    if (s.goalTolerance == 0.0)
        s.goalTolerance = std::max(p.goalTolerance, diagonal / 100.0);
    return s;
}

std::shared_ptr<GliderControlSetup> makeControlSetup(const GliderProblem &p, const ControlSettings &settings,
                                                     std::shared_ptr<GliderContext> *ctxOut)
{
    auto ctx = makeGliderContext(p);
    if (ctxOut)
        *ctxOut = ctx;
    const ControlSettings s = resolveControlSettings(p, *ctx, settings);
    const Region &r = ctx->region;
    ob::RealVectorBounds b(2);
    b.setLow(0, r.xMin);
    b.setHigh(0, r.xMax);
    b.setLow(1, r.yMin);
    b.setHigh(1, r.yMax);
    auto space = std::make_shared<TimeSE2StateSpace>(b, r.tMin, r.tMax);
    const double vMax = ctx->speed() + ctx->maxCurrent();
    space->setTimeWeight(vMax);
    const double sx = p.start.x, sy = p.start.y, t0 = p.t0;
    space->setStateSamplerAllocator([sx, sy, t0, vMax](const ob::StateSpace *sp) {
        return std::make_shared<GliderStateSampler>(sp, sx, sy, t0, vMax);
    });

    auto ss = std::make_shared<GliderControlSetup>(std::make_shared<HeadingControlSpace>(space), ctx, s);
    const oc::SpaceInformationPtr &si = ss->getSpaceInformation();
    std::shared_ptr<const GliderContext> cctx = ctx;
    ss->setStateValidityChecker(std::make_shared<GliderStateValidityChecker>(si, cctx));
    si->setStatePropagator(std::make_shared<GliderStatePropagator>(si.get(), cctx, s.propagationStep / s.diveSubsteps));
    si->setPropagationStepSize(s.propagationStep);
    si->setMinMaxControlDuration(s.minSteps, s.maxSteps);
    ss->setOptimizationObjective(std::make_shared<ControlTravelTimeObjective>(si, cctx));

    ob::ScopedState<TimeSE2StateSpace> start(space);
    start->setXYT(p.start.x, p.start.y, p.t0);
    start->setYaw(0.0);
    ss->setStartState(start);

    const double straight = std::hypot(p.goal.x - p.start.x, p.goal.y - p.start.y);
    const double tEarliest = std::min(r.tMax, p.t0 + straight / vMax);
    ss->setGoal(std::make_shared<PositionGoal>(si, p.goal.x, p.goal.y, s.goalTolerance, tEarliest, r.tMax));
    return ss;
}

HeadingRoute controlPathToHeadingRoute(const oc::PathControl &path)
{
    HeadingRoute route;
    if (path.getStateCount() == 0)
        return route;
    const auto *s0 = path.getState(0)->as<TimeSE2StateSpace::StateType>();
    route.start = {s0->getX(), s0->getY()};
    route.departure = s0->getTime();
    for (std::size_t i = 0; i < path.getControlCount(); ++i)
        route.segments.push_back({HeadingControlSpace::bearing(path.getControl(i)), path.getControlDuration(i)});
    return route;
}
} // namespace ompl_glider

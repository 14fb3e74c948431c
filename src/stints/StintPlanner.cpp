// The stint planners as one OMPL planner; see StintPlanner.h.
#include "ompl_glider/stints/StintPlanner.h"

#include <algorithm>
#include <cmath>

#include <ompl/geometric/PathGeometric.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ResourceLimits.h"
#include "../io/NumberText.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/routes/BearingOptimizer.h"

namespace ompl_glider
{
std::string stintMethodName(StintMethod m)
{
    switch (m)
    {
    case StintMethod::Direct:
        return "direct";
    case StintMethod::CtsAStar:
        return "cts_astar";
    case StintMethod::Optim:
        return "optim";
    case StintMethod::InitOptim:
        return "init_optim";
    }
    return "unknown";
}

StintPlanner::StintPlanner(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx,
                           StintMethod method)
    : ompl::base::Planner(si, stintMethodName(method)), ctx_(std::move(ctx)), method_(method)
{
    if (!ctx_)
        throw Error("StintPlanner: no glider context");
    specs_.approximateSolutions = true;
    specs_.optimizingPaths = false;
    specs_.multithreaded = false;
    specs_.directed = true;
    declareParam<double>("cell_size", this, &StintPlanner::setCellSize, &StintPlanner::getCellSize, "0:0.1:1000000");
    declareParam<unsigned>("max_expansions", this, &StintPlanner::setMaxExpansions, &StintPlanner::getMaxExpansions,
                           "1:1000:100000000");
    declareParam<unsigned>("max_evaluations", this, &StintPlanner::setMaxEvaluations, &StintPlanner::getMaxEvaluations,
                           "1:100:100000000");
    addPlannerProgressProperty("remaining distance REAL", [this] { return std::to_string(plan_.remainingDistance); });
}

void StintPlanner::prepare(const PipelineSetup &setup)
{
    if (!setup.stints)
        throw Error(setup.where("planner.name") + ": planner '" + getName() +
                    "' flies constant-bearing stints: give a 'stints' section (duration, mission_duration)");
    setStintSettings(*setup.stints);
    if (method_ != StintMethod::CtsAStar && method_ != StintMethod::InitOptim)
        return; // only CTS-A* flies a rose of bearings
    const double rose = std::max(1.0, std::round(360.0 / settings_.bearingStep));
    const double flights = rose * static_cast<double>(maxExpansions_);
    if (rose <= kMaxStintBearings && flights <= kMaxStintFlights)
        return;
    const bool byExpansions = rose <= kMaxStintBearings && setup.isGiven("planner.parameters.max_expansions");
    throw Error(setup.where(byExpansions ? "planner.parameters.max_expansions" : "stints.bearing_step") +
                text::formatted(": a bearing step of %g degrees flies %.4g stints from every surfacing the search "
                                "expands, up to %.3g stints over its %.3g expansions",
                                settings_.bearingStep, rose, flights, static_cast<double>(maxExpansions_)) +
                text::formatted(", more than the limit of %.4g bearings and %.3g stints: use a bearing step of at "
                                "least %g degrees (or fewer max_expansions)",
                                kMaxStintBearings, kMaxStintFlights, 360.0 / kMaxStintBearings));
}

void StintPlanner::setStintSettings(const StintSettings &s)
{
    s.check();
    settings_ = s;
}

void StintPlanner::clear()
{
    Planner::clear();
    plan_ = StintPlan();
    initial_ = StintPlan();
}

ompl::base::PlannerStatus StintPlanner::solve(const ompl::base::PlannerTerminationCondition &ptc)
{
    checkValidity();
    const auto *goal = dynamic_cast<const PositionGoal *>(pdef_->getGoal().get());
    if (!goal)
        return ompl::base::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
    const ompl::base::State *startState = pis_.nextStart();
    if (!startState)
        return ompl::base::PlannerStatus::INVALID_START;
    const auto *st = startState->as<TimeSE2StateSpace::StateType>();
    const double t0 = st->getTime();
    Region r = ctx_->region;
    r.tMin = t0;
    r.tMax = t0 + settings_.missionDuration;
    StintSettings s = settings_;
    s.depth = ctx_->travel->params().depth;
    const StintSimulator sim(ctx_->field, ctx_->environment, ctx_->speed(), ctx_->field->maxSpeed(r),
                             {st->getX(), st->getY()}, t0, {goal->getX(), goal->getY()}, s);
    auto stop = [&ptc] { return ptc.eval(); };
    CtsAStarParams cp;
    cp.cellSize = cellSize_;
    cp.maxExpansions = maxExpansions_;
    cp.stop = stop;
    BearingOptimizerParams op;
    op.maxEvaluations = maxEvaluations_;
    op.stop = stop;
    switch (method_)
    {
    case StintMethod::Direct:
        plan_ = sim.direct();
        initial_ = plan_;
        break;
    case StintMethod::CtsAStar:
        plan_ = ctsAStar(sim, cp).plan;
        initial_ = plan_;
        break;
    case StintMethod::Optim:
    case StintMethod::InitOptim: {
        initial_ = method_ == StintMethod::Optim ? sim.direct() : ctsAStar(sim, cp).plan;
        const BearingOptimizerResult o = optimiseBearings(sim, initial_.bearings, op);
        plan_ = o.plan.cost <= initial_.cost ? o.plan : initial_;
        break;
    }
    }
    auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
    for (std::size_t k = 0; k < plan_.surfacings.size(); ++k)
    {
        ompl::base::State *state = si_->allocState();
        auto *ts = state->as<TimeSE2StateSpace::StateType>();
        const TimedPoint &w = plan_.surfacings[k];
        ts->setXYT(w.x, w.y, w.t);
        const double b = k < plan_.bearings.size() ? plan_.bearings[k] : (k > 0 ? plan_.bearings[k - 1] : 0.0);
        const Point2 h = bearingVector(b);
        ts->setYaw(std::atan2(h.y, h.x));
        path->append(state);
        si_->freeState(state);
    }
    pdef_->addSolutionPath(path, !plan_.reached, plan_.reached ? 0.0 : plan_.remainingDistance, getName());
    return plan_.reached ? ompl::base::PlannerStatus::EXACT_SOLUTION : ompl::base::PlannerStatus::APPROXIMATE_SOLUTION;
}

void StintPlanner::getPlannerData(ompl::base::PlannerData &data) const
{
    Planner::getPlannerData(data); // the progress properties (remaining distance) reach benchmark logs
}
} // namespace ompl_glider

/// @file Wavefront.cpp
/// @brief The Wavefront planner ([ThompsonICRA]): its parameters, the limits it refuses, solve() and the planner data
/// of its settled nodes; one search and its steps in WavefrontSearch.cpp.

#include "ompl_glider/planners/Wavefront.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <queue>
#include <unordered_map>

#include <ompl/base/PlannerData.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/GliderStateValidityChecker.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "detail/Lattice.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "SearchSetting.h"
#include "ompl_glider/ResourceLimits.h"
#include "../io/NumberText.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{
using TimeState = TimeSE2StateSpace::StateType;
} // namespace

Wavefront::Wavefront(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx)
    : LatticePlanner(si, "Wavefront", "Wavefront"), ctx_(std::move(ctx))
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("Wavefront: a GliderContext with field and travel is required");
    specs_.approximateSolutions = false;
    specs_.optimizingPaths = false;
    specs_.multithreaded = false;
    specs_.directed = true;

    declareParam<double>("time_step", this, &Wavefront::setTimeStep, &Wavefront::getTimeStep, "0.:0.05:100.");

    const TravelTimeCalculator *travel = ctx_->travel.get();
    const CurrentField *field = ctx_->field.get();
    addPlannerProgressProperty("cost function calls INTEGER", [this, travel] {
        return std::to_string(solving_ ? travel->costFunctionCalls() - cfcBase_ : cfc_);
    });
    addPlannerProgressProperty("current model calls INTEGER", [this, field] {
        return std::to_string(solving_ ? field->callCount() - cmcBase_ : cmc_);
    });
    addPlannerProgressProperty("best cost REAL", [this] {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g", bestCost_.load());
        return std::string(buf);
    });
}

Wavefront::~Wavefront()
{
    freeDataStates();
}

ompl::base::PlannerAllocator Wavefront::allocator(std::shared_ptr<const GliderContext> ctx)
{
    return [ctx](const ompl::base::SpaceInformationPtr &si) { return std::make_shared<Wavefront>(si, ctx); };
}

void Wavefront::setTimeStep(double dt)
{
    if (!(dt >= 0.0) || !std::isfinite(dt))
        throw Error("Wavefront: time_step must be a finite number >= 0 (0 = grid_size / V; got " + std::to_string(dt) +
                    ")");
    timeStep_ = dt;
}

void Wavefront::prepare(const PipelineSetup &setup)
{
    LatticePlanner::prepare(setup);
    const Region &r = setup.region;
    const std::string where = setup.placeOfFirstGiven({"planner.parameters.time_step"}, "planner.grid_size");
    const double dt = effectiveTimeStep();
    const double window = (r.tMax - setup.departure) / dt;
    if (!(window <= kMaxIntervals))
        throw Error(where +
                    text::formatted(": %.4g time intervals of %g over the planning window (at most %g)", window, dt,
                                    kMaxIntervals) +
                    ": use a larger time_step");
    const double vertices = (std::floor((r.xMax - r.xMin) / getGridSize() + 1e-9) + 1.0) *
                            (std::floor((r.yMax - r.yMin) / getGridSize() + 1e-9) + 1.0);
    const double tEnd = std::min(r.tMax, ctx_->arriveNotAfter);
    const double intervals = std::floor(std::max(tEnd - setup.departure, 0.0) / dt) + 1.0;
    // the search ends no earlier than the fastest conceivable arrival: every vertex reachable by then holds into
    // each interval up to it
    const double fastest = std::hypot(setup.goal.x - setup.start.x, setup.goal.y - setup.start.y) /
                           (ctx_->speed() + std::max(ctx_->maxCurrent(), 0.0));
    const double least = vertices * std::min(intervals, std::max(1.0, fastest / dt));
    if (least <= kMaxWavefrontNodes)
        return;
    throw Error(where +
                text::formatted(": the Wavefront search settles %.3g lattice vertices in each of its time intervals "
                                "of %g (at least %.3g space-time nodes before the fastest conceivable arrival, %.3g in "
                                "the window)",
                                vertices, dt, least, vertices * intervals) +
                text::formatted(", more than the limit of %.3g: use a larger planner.grid_size or time_step",
                                kMaxWavefrontNodes));
}

NoPath Wavefront::noPathReason(const ompl::base::PlannerStatus &, double timeLimit) const
{
    NoPath n;
    switch (outcome_)
    {
    case WavefrontOutcome::InvalidStart:
        n.cause = NoPathCause::BadInput;
        n.what = "invalid start: " + message_;
        break;
    case WavefrontOutcome::InvalidGoal:
        n.cause = NoPathCause::BadInput;
        n.what = "invalid goal: " + message_;
        break;
    case WavefrontOutcome::Exhausted:
        n.cause = NoPathCause::LatticeExhausted;
        n.what = "no path exists on this lattice: " + message_;
        break;
    case WavefrontOutcome::BadWindow:
        n.cause = NoPathCause::BadInput;
        n.what = message_;
        break;
    case WavefrontOutcome::Terminated:
        n.cause = NoPathCause::TimeLimit;
        n.timeLimit = timeLimit;
        n.what = "the time limit (" + text::number(timeLimit) + " s) ended the search: raise it";
        break;
    default:
        break;
    }
    return n;
}

double Wavefront::effectiveTimeStep() const
{
    return timeStep_ > 0.0 ? timeStep_ : getGridSize() / ctx_->speed();
}

double Wavefront::getHoldTime() const
{
    double h = 0.0;
    for (std::size_t i = 1; i < waypoints_.size(); ++i)
        if (waypoints_[i].x == waypoints_[i - 1].x && waypoints_[i].y == waypoints_[i - 1].y)
            h += waypoints_[i].t - waypoints_[i - 1].t;
    return h;
}

void Wavefront::setup()
{
    Planner::setup();
    if (!dynamic_cast<const TimeSE2StateSpace *>(si_->getStateSpace().get()))
    {
        OMPL_ERROR("%s: the state space must be a TimeSE2StateSpace", getName().c_str());
        setup_ = false;
        return;
    }
    // The holds are checked by the validator that will judge the path; another validator: one of our own.
    validator_ = std::dynamic_pointer_cast<const TravelTimeMotionValidator>(si_->getMotionValidator());
    if (!validator_)
        validator_ = std::make_shared<TravelTimeMotionValidator>(si_, ctx_);
}

void Wavefront::freeDataStates() const
{
    for (ompl::base::State *s : dataStates_)
        si_->freeState(s);
    dataStates_.clear();
}

void Wavefront::clear()
{
    Planner::clear();
    freeDataStates();
    settled_.clear();
    waypoints_.clear();
    message_.clear();
    outcome_ = WavefrontOutcome::None;
    travelTime_ = kInf;
    expansions_ = cfc_ = cmc_ = 0;
    bestCost_ = kInf;
}

ompl::base::PlannerStatus Wavefront::solve(const ompl::base::PlannerTerminationCondition &ptc)
{
    checkValidity();
    ompl::base::PlannerStatus status;
    const std::optional<StartAndGoal> sg = startAndGoal(*pdef_, getName(), status);
    if (!sg)
        return status;
    const double sx = sg->sx, sy = sg->sy, t0 = sg->t0;
    const std::optional<Point2> goal = sg->goal;

    freeDataStates();
    settled_.clear();
    waypoints_.clear();
    message_.clear();
    travelTime_ = kInf;
    expansions_ = 0;
    bestCost_ = kInf;
    cfcBase_ = ctx_->travel->costFunctionCalls();
    cmcBase_ = ctx_->field->callCount();
    solving_ = true;
    try
    {
        outcome_ = search(sx, sy, t0, goal->x, goal->y, ptc);
    }
    catch (...)
    {
        solving_ = false;
        throw;
    }
    cfc_ = ctx_->travel->costFunctionCalls() - cfcBase_;
    cmc_ = ctx_->field->callCount() - cmcBase_;
    solving_ = false;

    switch (outcome_)
    {
    case WavefrontOutcome::InvalidStart:
        OMPL_ERROR("%s: invalid start: %s", getName().c_str(), message_.c_str());
        return ompl::base::PlannerStatus::INVALID_START;
    case WavefrontOutcome::InvalidGoal:
        OMPL_ERROR("%s: invalid goal: %s", getName().c_str(), message_.c_str());
        return ompl::base::PlannerStatus::INVALID_GOAL;
    case WavefrontOutcome::Exhausted:
    case WavefrontOutcome::BadWindow:
        OMPL_INFORM("%s: %s", getName().c_str(), message_.c_str());
        return ompl::base::PlannerStatus::ABORT; // more time would not help (OMPL 1.5: no "infeasible")
    case WavefrontOutcome::Terminated:
        return ompl::base::PlannerStatus::TIMEOUT;
    default:
        break;
    }
    auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
    waypointsToPath(waypoints_, *path);
    bestCost_ = travelTime_;
    ompl::base::PlannerSolution sol(path);
    sol.setPlannerName(getName());
    if (pdef_->getOptimizationObjective())
        sol.setOptimized(pdef_->getOptimizationObjective(), ompl::base::Cost(travelTime_), true);
    pdef_->addSolutionPath(sol);
    return ompl::base::PlannerStatus::EXACT_SOLUTION;
}

void Wavefront::getPlannerData(ompl::base::PlannerData &data) const
{
    Planner::getPlannerData(data);
    if (settled_.empty())
        return;
    // The states live until the next solve() / clear() (PlannerData keeps pointers to them).
    if (dataStates_.size() != settled_.size())
    {
        freeDataStates();
        for (const SettledNode &n : settled_)
        {
            ompl::base::State *s = si_->allocState();
            s->as<TimeState>()->setXYT(n.x, n.y, n.a);
            s->as<TimeState>()->setYaw(0.0);
            dataStates_.push_back(s);
        }
    }
    for (std::size_t i = 0; i < settled_.size(); ++i)
    {
        const SettledNode &n = settled_[i];
        const ompl::base::PlannerDataVertex vertex(dataStates_[i]);
        if (n.parent < 0)
            data.addStartVertex(vertex);
        else
        {
            const SettledNode &p = settled_[static_cast<std::size_t>(n.parent)];
            data.addEdge(ompl::base::PlannerDataVertex(dataStates_[static_cast<std::size_t>(n.parent)]), vertex,
                         ompl::base::PlannerDataEdge(), ompl::base::Cost(n.a - p.a));
        }
    }
    if (outcome_ == WavefrontOutcome::Exact)
        data.markGoalState(dataStates_.back());
}
} // namespace ompl_glider

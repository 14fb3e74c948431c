#include "ompl_glider/planners/ZAStarTVE.h"
#include "TveSearch.h"

#include <cmath>
#include <map>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>

#include <ompl/base/PlannerData.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/PositionGoal.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "ompl_glider/routes/WaypointRefiner.h"
#include "../io/NumberText.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
NoPath ZAStarTVE::noPathReason(const ompl::base::PlannerStatus &, double timeLimit) const
{
    NoPath n;
    switch (last_.outcome)
    {
    case TveOutcome::InvalidStart:
        n.cause = NoPathCause::BadInput;
        n.what = "invalid start: " + last_.message;
        break;
    case TveOutcome::InvalidGoal:
        n.cause = NoPathCause::BadInput;
        n.what = "invalid goal: " + last_.message;
        break;
    case TveOutcome::Exhausted:
        n.cause = NoPathCause::LatticeExhausted;
        n.expanded = last_.expansions;
        n.what = "no path exists on this lattice (" + std::to_string(last_.expansions) + " vertices expanded)";
        n.advice = ": a finer grid, more sectors or a higher speed may find one";
        break;
    case TveOutcome::Terminated:
        n.cause = NoPathCause::TimeLimit;
        n.timeLimit = timeLimit;
        n.what = "the time limit (" + text::number(timeLimit) + " s) ended the search: raise it";
        break;
    default:
        break;
    }
    return n;
}

namespace
{
using TimeState = TimeSE2StateSpace::StateType;

/// Heading of the leg (x1, y1) -> (x2, y2) in SO(2)'s range [-pi, pi) (atan2 may return +pi).
double legYaw(double x1, double y1, double x2, double y2)
{
    const double yaw = std::atan2(y2 - y1, x2 - x1);
    return yaw >= 3.14159265358979323846 ? yaw - 2.0 * 3.14159265358979323846 : yaw;
}

/// The range of a numeric parameter, stated once: what declareParam suggests ("lo:step:hi", which mission files and
/// the command line check) and what the setter accepts.
struct Range
{
    double lo, step, hi;
    std::string suggestion() const { return text::number(lo) + ":" + text::number(step) + ":" + text::number(hi); }
};

const Range &rangeOf(const std::string &name)
{
    static const std::map<std::string, Range> ranges = {
        {"delta_phi_max", {0.1, 1.0, 180.0}},       // degrees, half-width of the accepted courses
        {"course_extrapolation", {0.0, 0.25, 2.0}}, // k of the predicted course
        {"turn_widening", {0.0, 0.25, 5.0}},        // cone widening with the predicted turn
        {"certify_tolerance", {-1.0, 0.05, 1.0}},   // relative; < 0: off
        {"coarse_factor", {0.0, 1.0, 64.0}},        // 0 automatic, 1 off
        {"corridor_blocks", {1.0, 1.0, 1000.0}},
        {"zermelo_steps", {1.0, 1.0, 10000.0}},
        {"refiner_max_evaluations", {kMinRefinerEvaluations, 1000.0, kMaxRefinerEvaluations}}};
    return ranges.at(name);
}

/// v when it lies in the parameter's range; else throws "ZAStarTVE: <name> must be in lo..hi (<note>got v)".
double checkedReal(const char *name, double v, const char *note = "")
{
    const Range &r = rangeOf(name);
    if (!(v >= r.lo && v <= r.hi))
        throw Error(std::string("ZAStarTVE: ") + name + " must be in " + text::number(r.lo) + ".." +
                    text::number(r.hi) + " (" + note + "got " + text::number(v) + ")");
    return v;
}

/// n when it lies in the parameter's range; else throws "ZAStarTVE: <name> must be an integer in lo..hi (...)".
unsigned checkedInteger(const char *name, unsigned n, const char *note = "")
{
    const Range &r = rangeOf(name);
    if (n < r.lo || n > r.hi)
        throw Error(std::string("ZAStarTVE: ") + name + " must be an integer in " + text::number(r.lo) + ".." +
                    text::number(r.hi) + " (" + note + "got " + std::to_string(n) + ")");
    return n;
}
} // namespace

ZAStarTVE::ZAStarTVE(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx,
                     const std::string &configuration)
    : LatticePlanner(si, configuration, "ZAStarTVE"), ctx_(std::move(ctx))
{
    if (!ctx_ || !ctx_->field || !ctx_->travel)
        throw Error("ZAStarTVE: a GliderContext with field and travel is required");
    // each configuration's (heuristic, Zermelo-guided) switches
    static const std::map<std::string, std::pair<bool, bool>> configurations = {
        {"TVE", {false, false}}, {"A*TVE", {true, false}}, {"ZTVE", {false, true}}, {"ZA*TVE", {true, true}}};
    if (const auto it = configurations.find(configuration); it != configurations.end())
        std::tie(options_.heuristic, options_.zermelo) = it->second;
    else
        throw Error("ZAStarTVE: unknown configuration '" + configuration + "' (expected TVE, A*TVE, ZTVE or ZA*TVE)");

    specs_.approximateSolutions = true;
    specs_.optimizingPaths = false;
    specs_.multithreaded = false;
    specs_.directed = true;

    declareParam<bool>("heuristic", this, &ZAStarTVE::setHeuristic, &ZAStarTVE::getHeuristic, "0,1");
    declareParam<bool>("zermelo", this, &ZAStarTVE::setZermelo, &ZAStarTVE::getZermelo, "0,1");
    declareParam<double>("delta_phi_max", this, &ZAStarTVE::setDeltaPhiMax, &ZAStarTVE::getDeltaPhiMax,
                         rangeOf("delta_phi_max").suggestion());
    declareParam<double>("course_extrapolation", this, &ZAStarTVE::setCourseExtrapolation,
                         &ZAStarTVE::getCourseExtrapolation, rangeOf("course_extrapolation").suggestion());
    declareParam<double>("turn_widening", this, &ZAStarTVE::setTurnWidening, &ZAStarTVE::getTurnWidening,
                         rangeOf("turn_widening").suggestion());
    declareParam<double>("certify_tolerance", this, &ZAStarTVE::setCertifyTolerance, &ZAStarTVE::getCertifyTolerance,
                         rangeOf("certify_tolerance").suggestion());
    declareParam<bool>("tight_bounds", this, &ZAStarTVE::setTightBounds, &ZAStarTVE::getTightBounds, "0,1");
    declareParam<unsigned>("coarse_factor", this, &ZAStarTVE::setCoarseFactor, &ZAStarTVE::getCoarseFactor,
                           rangeOf("coarse_factor").suggestion());
    declareParam<unsigned>("corridor_blocks", this, &ZAStarTVE::setCorridorBlocks, &ZAStarTVE::getCorridorBlocks,
                           rangeOf("corridor_blocks").suggestion());
    declareParam<unsigned>("zermelo_steps", this, &ZAStarTVE::setZermeloSteps, &ZAStarTVE::getZermeloSteps,
                           rangeOf("zermelo_steps").suggestion());
    declareParam<bool>("smooth", this, &ZAStarTVE::setSmooth, &ZAStarTVE::getSmooth, "0,1");
    declareParam<bool>("refine", this, &ZAStarTVE::setRefine, &ZAStarTVE::getRefine, "0,1");
    declareParam<unsigned>("refiner_max_evaluations", this, &ZAStarTVE::setRefinerMaxEvaluations,
                           &ZAStarTVE::getRefinerMaxEvaluations, rangeOf("refiner_max_evaluations").suggestion());

    const TravelTimeCalculator *travel = ctx_->travel.get();
    const CurrentField *field = ctx_->field.get();
    addPlannerProgressProperty("cost function calls INTEGER", [this, travel] {
        const std::uint64_t n =
            solving_ ? travel->costFunctionCalls() - cfcBase_ : last_.costFunctionCalls + postprocessCfc_;
        return std::to_string(n);
    });
    addPlannerProgressProperty("current model calls INTEGER", [this, field] {
        const std::uint64_t n = solving_ ? field->callCount() - cmcBase_ : last_.currentModelCalls;
        return std::to_string(n);
    });
    addPlannerProgressProperty("best cost REAL", [this] {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g", bestCost_.load());
        return std::string(buf);
    });
}

ZAStarTVE::~ZAStarTVE()
{
    freeDataStates();
}

ompl::base::PlannerAllocator ZAStarTVE::allocator(std::shared_ptr<const GliderContext> ctx,
                                                  const std::string &configuration)
{
    return [ctx, configuration](const ompl::base::SpaceInformationPtr &si) {
        return std::make_shared<ZAStarTVE>(si, ctx, configuration);
    };
}

void ZAStarTVE::setDeltaPhiMax(double degrees)
{
    options_.deltaPhiMax = checkedReal("delta_phi_max", degrees, "degrees; ") * kRadPerDeg;
}

void ZAStarTVE::setCourseExtrapolation(double k)
{
    options_.courseExtrapolation = checkedReal("course_extrapolation", k);
}

double ZAStarTVE::getDeltaPhiMax() const
{
    return options_.deltaPhiMax / kRadPerDeg;
}

void ZAStarTVE::setTurnWidening(double w)
{
    options_.turnWidening = checkedReal("turn_widening", w);
}

void ZAStarTVE::setCertifyTolerance(double tol)
{
    options_.certifyTolerance = checkedReal("certify_tolerance", tol, "< 0 for off; ");
}

void ZAStarTVE::setZermeloSteps(unsigned n)
{
    options_.zermeloSteps = checkedInteger("zermelo_steps", n);
}

void ZAStarTVE::setCoarseFactor(unsigned f)
{
    options_.coarseFactor = checkedInteger("coarse_factor", f, "0 automatic, 1 off; ");
}

void ZAStarTVE::setCorridorBlocks(unsigned b)
{
    options_.corridorBlocks = checkedInteger("corridor_blocks", b);
}

void ZAStarTVE::setRefinerMaxEvaluations(unsigned n)
{
    refinerMaxEvaluations_ = checkedInteger("refiner_max_evaluations", n);
}

void ZAStarTVE::latticeChanged()
{
    search_.reset();
}

void ZAStarTVE::setup()
{
    Planner::setup();
    if (!dynamic_cast<const TimeSE2StateSpace *>(si_->getStateSpace().get()))
    {
        OMPL_ERROR("%s: the state space must be a TimeSE2StateSpace", getName().c_str());
        setup_ = false;
        return;
    }
    if (!search_)
        search_ = std::make_unique<TveSearch>(ctx_, getGridSize(), getSectors()); // throws Error on bad lattice params
}

void ZAStarTVE::freeDataStates() const
{
    for (ompl::base::State *s : dataStates_)
        si_->freeState(s);
    dataStates_.clear();
}

void ZAStarTVE::clear()
{
    Planner::clear();
    freeDataStates();
    tree_.clear();
    last_ = TveResult{};
    solution_.clear();
    postprocessCfc_ = 0;
    bestCost_ = std::numeric_limits<double>::infinity();
}

ompl::base::PlannerStatus ZAStarTVE::solve(const ompl::base::PlannerTerminationCondition &ptc)
{
    checkValidity();
    if (!search_)
        search_ = std::make_unique<TveSearch>(ctx_, getGridSize(), getSectors());

    // Start (its time is the departure t0) and goal position (startAndGoal(): read so that solve() can be repeated).
    ompl::base::PlannerStatus status;
    const std::optional<StartAndGoal> sg = startAndGoal(*pdef_, getName(), status);
    if (!sg)
        return status;
    const double sx = sg->sx, sy = sg->sy, t0 = sg->t0, gx = sg->goal.x, gy = sg->goal.y;

    freeDataStates();
    solution_.clear();
    postprocessCfc_ = 0;
    bestCost_ = std::numeric_limits<double>::infinity();
    cfcBase_ = ctx_->travel->costFunctionCalls();
    cmcBase_ = ctx_->field->callCount();
    solving_ = true;
    TveResult r;
    try
    {
        r = search_->run(sx, sy, t0, gx, gy, options_, [&ptc] { return ptc(); });
    }
    catch (...)
    {
        solving_ = false;
        throw;
    }
    last_ = r;
    tree_ = search_->tree();
    solution_ = r.waypoints;
    if (r.goalWindowMissed)
        OMPL_WARN("%s: no lattice path arrives in the goal window [%g, %g]; the path is the earliest arrival without "
                  "it (planRoute() times or refuses it)",
                  getName().c_str(), ctx_->arriveNotBefore, ctx_->arriveNotAfter);
    if (r.outcome == TveOutcome::Exact && (smooth_ || refine_))
    {
        // Post-processing of the exact lattice path: both never arrive later ([EichhornRAS] Table 3; refinement).
        const std::uint64_t before = ctx_->travel->costFunctionCalls();
        try
        {
            if (smooth_)
                solution_ = PathSmoother(ctx_).smooth(solution_).waypoints; // departure: solution_.front().t = t0
            if (refine_)
            {
                RefinerParams rp;
                rp.maxEvaluations = refinerMaxEvaluations_;
                rp.terminate = [&ptc] { return ptc(); }; // a time limit bounds refinement too
                solution_ = WaypointRefiner(ctx_, rp).refine(solution_).waypoints;
            }
        }
        catch (...)
        {
            solving_ = false;
            throw;
        }
        postprocessCfc_ = ctx_->travel->costFunctionCalls() - before;
    }
    solving_ = false;

    switch (r.outcome)
    {
    case TveOutcome::InvalidStart:
        OMPL_ERROR("%s: invalid start: %s", getName().c_str(), r.message.c_str());
        return ompl::base::PlannerStatus::INVALID_START;
    case TveOutcome::InvalidGoal:
        OMPL_ERROR("%s: invalid goal: %s", getName().c_str(), r.message.c_str());
        return ompl::base::PlannerStatus::INVALID_GOAL;
    case TveOutcome::Exhausted:
        OMPL_INFORM("%s: the lattice holds no feasible path to the goal (%llu vertices expanded, %llu CFC)",
                    getName().c_str(), static_cast<unsigned long long>(r.expansions),
                    static_cast<unsigned long long>(r.costFunctionCalls));
        // not a timeout (more time would not help): OMPL 1.5 has no "infeasible" status, ABORT is "no solution
        // for another reason"
        return ompl::base::PlannerStatus::ABORT;
    default:
        break;
    }
    if (r.waypoints.empty())
        return ompl::base::PlannerStatus::TIMEOUT; // terminated before reaching anything closer to the goal

    auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
    const auto &w = solution_;
    waypointsToPath(w, *path); // yaw of each state: the leg reaching it (the first leg for the start)

    const bool exact = r.outcome == TveOutcome::Exact;
    const double cost = w.back().t - t0;
    if (exact)
        bestCost_ = cost;
    const double difference = exact ? 0.0 : std::hypot(w.back().x - gx, w.back().y - gy);
    ompl::base::PlannerSolution sol(path);
    sol.setPlannerName(getName());
    if (!exact)
        sol.setApproximate(difference);
    if (pdef_->getOptimizationObjective())
        sol.setOptimized(pdef_->getOptimizationObjective(), ompl::base::Cost(cost), exact);
    pdef_->addSolutionPath(sol);
    return exact ? ompl::base::PlannerStatus::EXACT_SOLUTION : ompl::base::PlannerStatus::APPROXIMATE_SOLUTION;
}

void ZAStarTVE::getPlannerData(ompl::base::PlannerData &data) const
{
    Planner::getPlannerData(data);
    if (tree_.empty() || !search_)
        return;
    const Lattice &lat = search_->lattice();
    // Map lattice vertex -> index in tree_ for the predecessor lookup.
    std::unordered_map<Lattice::VertexId, std::size_t> index;
    index.reserve(tree_.size());
    for (std::size_t i = 0; i < tree_.size(); ++i)
        index[tree_[i].id] = i;
    // The states live until the next solve() / clear() (PlannerData keeps pointers to them).
    const bool build = dataStates_.size() != tree_.size();
    if (build)
        freeDataStates();
    std::vector<ompl::base::State *> states(tree_.size(), nullptr);
    for (std::size_t i = 0; i < tree_.size(); ++i)
    {
        if (!build)
        {
            states[i] = dataStates_[i];
            continue;
        }
        const TveTreeVertex &v = tree_[i];
        ompl::base::State *s = si_->allocState();
        auto *ts = s->as<TimeState>();
        ts->setXYT(v.x, v.y, v.t);
        double yaw = 0.0;
        if (v.parent != Lattice::kNone)
            yaw = legYaw(lat.x(v.parent), lat.y(v.parent), v.x, v.y);
        ts->setYaw(yaw);
        states[i] = s;
        dataStates_.push_back(s);
    }
    for (std::size_t i = 0; i < tree_.size(); ++i)
    {
        const TveTreeVertex &v = tree_[i];
        if (v.parent == Lattice::kNone)
            data.addStartVertex(ompl::base::PlannerDataVertex(states[i]));
        else if (v.id == lat.goal())
            data.addGoalVertex(ompl::base::PlannerDataVertex(states[i]));
    }
    for (std::size_t i = 0; i < tree_.size(); ++i)
    {
        const TveTreeVertex &v = tree_[i];
        if (v.parent == Lattice::kNone)
            continue;
        const auto it = index.find(v.parent);
        if (it == index.end())
            continue;
        const TveTreeVertex &p = tree_[it->second];
        data.addEdge(ompl::base::PlannerDataVertex(states[it->second]), ompl::base::PlannerDataVertex(states[i]),
                     ompl::base::PlannerDataEdge(), ompl::base::Cost(v.t - p.t));
    }
}
} // namespace ompl_glider

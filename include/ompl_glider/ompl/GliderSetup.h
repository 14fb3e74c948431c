#pragma once
/// @file GliderSetup.h
/// @brief One call from a glider problem (field, bounds, start, goal, t0, V) to a ready OMPL SimpleSetup.

#include <limits>
#include <memory>
#include <string>

#include <ompl/geometric/SimpleSetup.h>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/Geometry.h"
#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief A glider planning problem. Defaults: the meandering-jet region of [EichhornRAS] Sec. 6.1 (x in [0, 10],
/// y in [-4, 4]), t0 = 0, horizon 60, TravelTimeParams defaults (V = 0.5), no environment, goal tolerance 1e-3
/// (field units: set it for metric missions). field, start and goal have no default (null / NaN) and must be set.
struct GliderProblem
{
    std::shared_ptr<const CurrentField> field;           ///< required
    TravelTimeParams travel;                             ///< vehicle speed V and integration parameters
    std::shared_ptr<const Environment> environment;      ///< forbidden regions, null for none
    double xMin{0.0}, xMax{10.0}, yMin{-4.0}, yMax{4.0}; ///< planning box
    double t0{0.0};                                      ///< departure time
    double horizon{60.0};                                ///< the time window is [t0, t0 + horizon]
    /// start position (NaN until set: makeSimpleSetup() refuses an unset start)
    Point2 start{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    /// goal position (NaN until set)
    Point2 goal{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    double goalTolerance{1e-3}; ///< xy distance within which the goal counts as reached
    /// Arrival window at the goal (absolute times; GliderContext::arriveNotBefore / arriveNotAfter). Unbounded
    /// by default.
    double arriveNotBefore{-std::numeric_limits<double>::infinity()};
    double arriveNotAfter{std::numeric_limits<double>::infinity()};
};

/// @brief Checks the start and goal of a problem definition on a TimeSE2StateSpace before planning: every start
/// state must be valid for the space information (else INVALID_START), and a PositionGoal must be valid at some
/// time of its window (PositionGoal::maxSampleCount() > 0, else INVALID_GOAL); other goal types are not checked.
/// @param why if non-null, receives a message naming the position, the time and the reason (e.g. "inside island
/// 'A'", from GliderStateValidityChecker::whyInvalid()) when the status is not UNKNOWN.
/// @return INVALID_START, INVALID_GOAL, or UNKNOWN when both are fine.
ompl::base::PlannerStatus checkStartAndGoal(const ompl::base::ProblemDefinition &pdef, std::string *why = nullptr);

/// @brief A SimpleSetup whose solve() first runs checkStartAndGoal(): a start inside a forbidden region gives
/// INVALID_START and a goal inside one (at every time of the goal window) gives INVALID_GOAL for every planner,
/// with the reason logged by OMPL_ERROR and kept in lastCheckMessage(), and the planner is not called. Needed
/// because OMPL 1.5's RRT* (and others) never check the goal and would return an approximate solution.
class GliderSimpleSetup : public ompl::geometric::SimpleSetup
{
public:
    /// @brief As ompl::geometric::SimpleSetup(space).
    explicit GliderSimpleSetup(const ompl::base::StateSpacePtr &space);

    /// @brief checkStartAndGoal(), then SimpleSetup::solve(time) when both are valid.
    ompl::base::PlannerStatus solve(double time = 1.0) override;
    /// @brief checkStartAndGoal(), then SimpleSetup::solve(ptc) when both are valid.
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;

    /// @brief The message of the last failed start/goal check (empty when the last solve() passed it).
    const std::string &lastCheckMessage() const { return lastCheckMessage_; }

private:
    /// Runs the check; on failure sets lastStatus_, clears solutions and returns true.
    bool rejectStartOrGoal();

    std::string lastCheckMessage_;
};

/// @brief Why the departure time of @p problem cannot be planned with (not finite, or so large that doubles
/// cannot resolve the integration tolerance over the horizon); empty when it can. makeGliderContext() refuses such
/// a problem; callers that know where the departure came from check first to name it.
std::string departureProblem(const GliderProblem &problem);

/// @brief Checks the problem and builds its context (TravelTimeCalculator from field + travel, region = box and
/// [t0, t0 + horizon]). The context does not hold t0 itself: the departure is the start state's time (see
/// makeSimpleSetup()). @throws ompl_glider::Error naming the bad field (no field, bounds not finite or
/// empty, horizon <= 0, t0 outside the field's time span, start/goal not set or outside the box, tolerance < 0,
/// bad travel-time parameters).
std::shared_ptr<GliderContext> makeGliderContext(const GliderProblem &problem);

/// @brief A ready SimpleSetup: TimeSE2StateSpace over the box and [t0, t0 + horizon] with time weight V + max|c|
/// and GliderStateSampler as its state sampler (no samples earlier than reachable from the start),
/// GliderStateValidityChecker, TravelTimeMotionValidator, TravelTimeObjective, start state (start, t0,
/// yaw 0) and a PositionGoal whose sampled times lie in [t0 + |start - goal| / (V + max|c|), t0 + horizon].
/// No planner is set (SimpleSetup picks OMPL's default unless setPlanner() is called). The returned object is a
/// GliderSimpleSetup: a start or goal inside a forbidden region is not an error here, solve() reports
/// INVALID_START / INVALID_GOAL with a message naming the region, whatever the planner.
/// @param ctxOut if non-null, receives the context (shared with the validator and the objective).
/// @throws ompl_glider::Error as makeGliderContext().
std::shared_ptr<GliderSimpleSetup> makeSimpleSetup(const GliderProblem &problem,
                                                   std::shared_ptr<GliderContext> *ctxOut = nullptr);

/// @brief The same for an existing context (e.g. one shared by several setups). The start state's time is
/// problem.t0. @throws ompl_glider::Error also when ctx is null or problem.t0 lies outside
/// [ctx->region.tMin, ctx->region.tMax].
std::shared_ptr<GliderSimpleSetup> makeSimpleSetup(const GliderProblem &problem, std::shared_ptr<GliderContext> ctx);
} // namespace ompl_glider

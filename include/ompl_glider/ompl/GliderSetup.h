#pragma once
/// @file GliderSetup.h
/// @brief One call from a glider problem (field, bounds, start, goal, t0, V) to a ready OMPL SimpleSetup.

#include <limits>
#include <memory>

#include <ompl/geometric/SimpleSetup.h>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief A glider planning problem. Defaults: the meandering-jet region of 000 Sec. 6.1 (x in [0, 10],
/// y in [-4, 4]), t0 = 0, horizon 60, TravelTimeParams defaults (V = 0.5), no environment, goal tolerance 1e-3
/// (field units: set it for metric missions). field, start and goal have no default (null / NaN) and must be set.
struct GliderProblem
{
    std::shared_ptr<const CurrentField> field;       ///< required
    TravelTimeParams travel;                         ///< vehicle speed V and integration parameters
    std::shared_ptr<const Environment> environment;  ///< forbidden regions, null for none
    double xMin{0.0}, xMax{10.0}, yMin{-4.0}, yMax{4.0};  ///< planning box
    double t0{0.0};                                       ///< departure time
    double horizon{60.0};                                 ///< the time window is [t0, t0 + horizon]
    double startX{std::numeric_limits<double>::quiet_NaN()};
    double startY{std::numeric_limits<double>::quiet_NaN()};
    double goalX{std::numeric_limits<double>::quiet_NaN()};
    double goalY{std::numeric_limits<double>::quiet_NaN()};
    double goalTolerance{1e-3};  ///< xy distance within which the goal counts as reached
};

/// @brief Checks the problem and builds its context (TravelTimeCalculator from field + travel, region = box and
/// [t0, t0 + horizon], t0). @throws ompl_glider::Error naming the bad field (no field, bounds not finite or
/// empty, horizon <= 0, t0 outside the field's time span, start/goal not set or outside the box, tolerance < 0,
/// bad travel-time parameters).
std::shared_ptr<GliderContext> makeGliderContext(const GliderProblem &problem);

/// @brief A ready SimpleSetup: TimeSE2StateSpace over the box and [t0, t0 + horizon] with time weight V + max|c|
/// and GliderStateSampler as its state sampler (no samples earlier than reachable from the start),
/// GliderStateValidityChecker, TravelTimeMotionValidator, TravelTimeObjective, start state (startX, startY, t0,
/// yaw 0) and a PositionGoal whose sampled times lie in [t0 + |start - goal| / (V + max|c|), t0 + horizon].
/// No planner is set (SimpleSetup picks OMPL's default unless setPlanner() is called). A start or goal inside a
/// forbidden region is not an error here: planners report INVALID_START / INVALID_GOAL.
/// @param ctxOut if non-null, receives the context (shared with the validator and the objective).
/// @throws ompl_glider::Error as makeGliderContext().
ompl::geometric::SimpleSetupPtr makeSimpleSetup(const GliderProblem &problem,
                                                std::shared_ptr<GliderContext> *ctxOut = nullptr);

/// @brief The same for an existing context (e.g. one shared by several setups).
ompl::geometric::SimpleSetupPtr makeSimpleSetup(const GliderProblem &problem, std::shared_ptr<GliderContext> ctx);
}  // namespace ompl_glider

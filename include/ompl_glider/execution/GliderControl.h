#pragma once
/// @file GliderControl.h
/// @brief OMPL control-based planning on the glider problems: a heading control space, a state
/// propagator that flies the held heading with the one dive integrator (flyHeading(), Dive.h), a travel-time
/// objective for propagated motions, and makeControlSetup(), the ompl::control counterpart of makeSimpleSetup(), so
/// that OMPL's control planners (oc::SST, oc::RRT, oc::KPIECE1, ...) plan on the same problems with the same dynamics.
///
/// It lives in the execution layer, not in ompl/, because it flies the dive integrator of this layer; it reuses the
/// OMPL adapters below it (TimeSE2StateSpace, GliderStateValidityChecker, GliderStateSampler, PositionGoal).
///
/// A control is one heading through the water, a bearing in degrees clockwise from north (unit heading (sin b, cos b),
/// as HeadingSegment and the stints use), held for the control's duration. A control path (oc::PathControl) is
/// therefore a HeadingRoute: its travel time is the sum of its control durations, and its last state is where
/// flyHeading() ended (controlPathToHeadingRoute() and flyHeadingRoute() re-fly it).

#include <memory>

#include <ompl/base/OptimizationObjective.h>
#include <ompl/control/PathControl.h>
#include <ompl/control/SimpleSetup.h>
#include <ompl/control/StatePropagator.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>

#include "ompl_glider/execution/Dive.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/ompl/GliderSetup.h"

namespace ompl_glider
{
/// @brief How makeControlSetup() discretises the controls. Zeros choose defaults from the problem's scale: with
/// D the diagonal of the planning box and vMax = V + max|c| (the fastest ground speed), the time a glider needs to
/// cross the box at best is D / vMax.
struct ControlSettings
{
    /// Duration of one propagation step (oc::SpaceInformation::setPropagationStepSize); the validity of the state is
    /// checked at the end of every step. 0: D / vMax / 100.
    double propagationStep{0.0};
    unsigned minSteps{1}; ///< shortest control: this many propagation steps (>= 1)
    /// Longest control: this many propagation steps (>= minSteps). The default 100 lets one heading be held for the
    /// whole best crossing time D / vMax of the box: on the strong-current campaign problems, oc::SST reached the goal
    /// more often and faster with it than with 20 or 50 (optimal heading schedules change slowly).
    unsigned maxSteps{100};
    /// RK4 steps of flyHeading() per propagation step (>= 1): the dive step is propagationStep / diveSubsteps, so a
    /// control of k propagation steps is flown with the same RK4 steps as one flyHeading() call over k
    /// propagationStep with that dive step (the re-flight of a path gives its states).
    unsigned diveSubsteps{4};
    /// xy distance within which the goal counts as reached. 0: max(problem.goalTolerance, D / 100). The control
    /// planners end their motions at propagation steps, so they hit a point only by chance (OMPL then reports an
    /// APPROXIMATE solution): the goal is a disc, and the travel time is the time to enter it.
    double goalTolerance{0.0};
};

/// @brief The control space: one heading through the water, a bearing in degrees clockwise from north, bounded by
/// [0, 360] (uniform sampling over the bounds gives every heading with equal probability).
class HeadingControlSpace : public ompl::control::RealVectorControlSpace
{
public:
    /// @param stateSpace the TimeSE2StateSpace of the problem
    explicit HeadingControlSpace(const ompl::base::StateSpacePtr &stateSpace);

    /// @brief The bearing (degrees clockwise from north) of a control of this space.
    static double bearing(const ompl::control::Control *control);
    /// @brief Sets the bearing (degrees clockwise from north) of a control of this space.
    static void setBearing(ompl::control::Control *control, double bearingDeg);
};

/// @brief Flies a heading control through the problem's current: from the state's (x, y) at its time, the heading
/// (HeadingControlSpace::bearing) held through the water at V for the duration with flyHeading() (fixed-step RK4 of
/// dx/dt = V h + c(x, t), land of the field and the forbidden regions checked along every step), at the depth of the
/// context's travel-time parameters. The result's time is the state's time plus the duration (exactly: time is
/// part of the state and advances by the duration), its (x, y) where flyHeading() ended, its yaw the heading as a
/// mathematical angle (atan2(hy, hx), informational like the yaw of the geometric planners).
///
/// A motion that cannot be flown makes the result invalid for every validity checker: when flyHeading() reports a
/// grounding (land or a forbidden region, checked on every RK4 step's chord) or the end of an RK4 step lies outside
/// the planning box, the result is the last point before it with the time +infinity, outside the space's time bounds
/// (so a wall thinner than a propagation step is not jumped over). OMPL's control planners propagate with
/// oc::SpaceInformation::propagateWhileValid(), which checks the state after every propagation step and keeps the
/// motion only up to the last valid one. A negative duration (backward propagation, which canPropagateBackward()
/// refuses) gives such an invalid result too; a zero duration copies the state.
class GliderStatePropagator : public ompl::control::StatePropagator
{
public:
    /// @param si the control space information (TimeSE2StateSpace, HeadingControlSpace)
    /// @param ctx the problem's context (field, V, forbidden regions, region)
    /// @param diveStep the RK4 step of flyHeading() (> 0)
    /// @throws ompl_glider::Error when ctx is null or diveStep is not positive and finite.
    GliderStatePropagator(ompl::control::SpaceInformation *si, std::shared_ptr<const GliderContext> ctx,
                          double diveStep);

    /// @brief Flies the control for @p duration from @p state into @p result (may be the same state).
    void propagate(const ompl::base::State *state, const ompl::control::Control *control, double duration,
                   ompl::base::State *result) const override;
    /// @brief False: the glider's flight is not run backwards.
    bool canPropagateBackward() const override { return false; }
    /// @brief The settings of every dive (speed V, RK4 step, depth; no goal radius).
    const DiveSettings &diveSettings() const { return dive_; }
    /// @brief The context in use.
    const std::shared_ptr<const GliderContext> &context() const { return ctx_; }

private:
    std::shared_ptr<const GliderContext> ctx_;
    DiveSettings dive_;
};

/// @brief Minimises the travel time of control paths: a motion s1 -> s2 costs t2 - t1 (the propagated duration,
/// GliderStatePropagator), states cost nothing, so a path from the start costs the sum of its control durations.
/// Heuristics as TravelTimeObjective's, with vMax = V + max|c| ([EichhornRAS] Eq. 1): motionCostHeuristic(s1, s2) =
/// max(|xy1 - xy2| / vMax, t2 - t1) and costToGo(s) = max(0, d - tol) / vMax for a PositionGoal at distance d with
/// tolerance tol (zero for other goals); both admissible. The cost threshold is OMPL's default (never satisfied), so
/// anytime planners (oc::SST) use their whole time.
class ControlTravelTimeObjective : public ompl::base::OptimizationObjective
{
public:
    /// @throws ompl_glider::Error when @p ctx is null or has no field / travel-time calculator.
    ControlTravelTimeObjective(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx);

    /// @brief Zero.
    ompl::base::Cost stateCost(const ompl::base::State *s) const override;
    /// @brief t2 - t1.
    ompl::base::Cost motionCost(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    /// @brief max(|xy1 - xy2| / vMax, t2 - t1).
    ompl::base::Cost motionCostHeuristic(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    /// @brief False.
    bool isSymmetric() const override { return false; }

private:
    double vMax_;
};

/// @brief The oc::SimpleSetup of makeControlSetup(): its solve() first runs checkStartAndGoal() as
/// GliderSimpleSetup's does (a start or goal inside a forbidden region gives INVALID_START / INVALID_GOAL, the
/// planner is not called), and it keeps the context and the resolved settings.
class GliderControlSetup : public ompl::control::SimpleSetup
{
public:
    /// @brief As ompl::control::SimpleSetup(controlSpace).
    GliderControlSetup(const ompl::control::ControlSpacePtr &controlSpace, std::shared_ptr<GliderContext> ctx,
                       const ControlSettings &settings);

    /// @brief checkStartAndGoal(), then SimpleSetup::solve(time) when both are valid.
    ompl::base::PlannerStatus solve(double time = 1.0) override;
    /// @brief checkStartAndGoal(), then SimpleSetup::solve(ptc) when both are valid.
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;

    /// @brief The message of the last failed start/goal check (empty when the last solve() passed it).
    const std::string &lastCheckMessage() const { return lastCheckMessage_; }
    /// @brief The problem's context.
    const std::shared_ptr<GliderContext> &context() const { return ctx_; }
    /// @brief The settings in use, defaults resolved (every field positive).
    const ControlSettings &settings() const { return settings_; }

private:
    bool rejectStartOrGoal();

    std::shared_ptr<GliderContext> ctx_;
    ControlSettings settings_;
    std::string lastCheckMessage_;
};

/// @brief The ControlSettings of @p problem with every zero default resolved (see ControlSettings).
/// @throws ompl_glider::Error when a setting is invalid (minSteps 0 or above maxSteps, diveSubsteps 0, a negative or
/// non-finite step or tolerance).
ControlSettings resolveControlSettings(const GliderProblem &problem, const GliderContext &ctx,
                                       const ControlSettings &settings);

/// @brief A ready GliderControlSetup for @p problem: TimeSE2StateSpace over the box and [t0, t0 + horizon] (time
/// weight V + max|c|, GliderStateSampler as in makeSimpleSetup()), HeadingControlSpace, GliderStatePropagator with
/// the dive step propagationStep / diveSubsteps, propagation step and control durations of @p settings,
/// GliderStateValidityChecker, ControlTravelTimeObjective, the start state (start, t0, yaw 0) and a PositionGoal
/// with the settings' goal tolerance (sampled times in [t0 + |start - goal| / vMax, t0 + horizon]). No planner is
/// set (OMPL's default for control planning, KPIECE1 with a projection, unless setPlanner() is called).
/// @param ctxOut if non-null, receives the context.
/// @throws ompl_glider::Error as makeGliderContext() and resolveControlSettings().
std::shared_ptr<GliderControlSetup> makeControlSetup(const GliderProblem &problem,
                                                     const ControlSettings &settings = ControlSettings(),
                                                     std::shared_ptr<GliderContext> *ctxOut = nullptr);

/// @brief The heading route of a control path of a GliderControlSetup: its first state's position and time, then
/// one segment (bearing, duration) per control, in order.
HeadingRoute controlPathToHeadingRoute(const ompl::control::PathControl &path);
} // namespace ompl_glider

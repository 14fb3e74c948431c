#pragma once
/// @file Execution.h
/// @brief Flying a plan in an ocean other than the one it was planned in ([ThompsonICRA] Sec. III-IV).
///
/// A glider dives with a fixed heading and corrects it only at the surface: at every surfacing (every
/// ExecutionOptions::surfacingInterval) it takes a GPS fix, a control strategy chooses the heading from the fix,
/// the time, the plan and the forecast, and the glider holds that heading through still water at its speed until
/// the next surfacing while the "truth" current carries it (classic RK4 on dx/dt = V h + c_truth(x, t), step
/// ExecutionOptions::step). Land of the truth field (inWater() / segmentInWater()) and the forbidden regions are
/// checked along every step: meeting them ends the run as a grounding.
///
/// Units are those of the planning frame: positions in its x/y units, times and intervals in field time units,
/// the speed in x/y units per time unit (MissionSpec::timeUnitSeconds converts from seconds).

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/current/CorrectedField.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/Environment.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/Geometry.h"

namespace ompl_glider
{
/// @brief How the heading is chosen at each surfacing ([ThompsonICRA] Sec. III).
enum class ControlStrategy
{
    /// Toward the end of the plan's segment active at the fix's time (waypoints advance by time), with the heading
    /// that, with the forecast current at the fix, makes good that course (crab angle).
    CurrentSensitive,
    /// Toward the end of the active segment, ignoring the current.
    CurrentBlind,
    /// Toward the goal, without a plan.
    Greedy,
    /// A new plan from the fix at every ExecutionOptions::replanEvery-th surfacing (ExecutionOptions::replan, e.g.
    /// the planner on the forecast), then flown as CurrentSensitive. Not in [ThompsonICRA]; what operators do.
    Replan,
    /// The plan's own held headings (a heading route): each segment's heading from its start to its end
    /// (a surfacing also at every segment end), the last one held after the plan's end. For a plan of straight legs
    /// (no ExecutionOptions::headings) it flies as CurrentSensitive.
    PlannedHeadings,
    /// Toward the end of the active segment corrected for the depth-averaged current the glider measured over its
    /// last dive (as Slocum and Seaglider correct their heading with it): aimed off upstream by the drift that current
    /// gives over the coming dive (the heading that brings the dive's end nearest the waypoint if the current holds);
    /// the first dive, before any measurement, with the crab angle for the forecast at the fix.
    Dac,
    /// As Replan, on the forecast corrected by every DAC measured so far (ExecutionOptions::replanObserved), and
    /// steered between plans with the crab angle for that corrected forecast's current at the fix.
    ReplanObserved
};

/// @brief The name of a strategy as outputs write it: "current_sensitive", "current_blind", "greedy", "replan",
/// "planned_headings".
std::string controlStrategyName(ControlStrategy s);
/// @brief Every strategy, in the order above.
const std::vector<ControlStrategy> &controlStrategies();
/// @brief The strategy of a name of controlStrategyName(); nullopt for any other text.
std::optional<ControlStrategy> parseControlStrategy(const std::string &name);

/// @brief A new plan from a GPS fix (x, y at time t) to the goal, given the plan flown so far (@p current, with its
/// planned times); empty when there is none (the current plan is kept).
using Replanner =
    std::function<std::vector<TimedPoint>(double x, double y, double t, const std::vector<TimedPoint> &current)>;

/// @brief A new plan as Replanner, on the forecast the depth-averaged currents measured so far make
/// (@p learned: ExecutionOptions::learn's, made once per surfacing and shared with the steering).
using ObservedReplanner =
    std::function<std::vector<TimedPoint>(double x, double y, double t, const std::vector<TimedPoint> &current,
                                          const std::shared_ptr<const CurrentField> &learned)>;

/// @brief The forecast the DAC measured so far make (e.g. learnForecast(): the forecast corrected, an ensemble's
/// members weighed and updated).
using DacLearning = std::function<std::shared_ptr<const CurrentField>(const std::vector<DacObservation> &measured)>;

/// @brief Options of flyPlan().
struct ExecutionOptions
{
    double surfacingInterval{3600.0}; ///< time between surfacings (field time units)
    double step{60.0};                ///< RK4 step while submerged (field time units); the last step of an
                                      ///< interval is shortened to end at the surfacing
    double radius{0.0};               ///< the goal counts as reached within this distance (x/y units)
    double depth{0.0};                ///< depth at which the currents are read (m)
    double endTime{std::numeric_limits<double>::quiet_NaN()}; ///< the run ends here at the latest (field time);
                                                              ///< NaN: twice the plan's duration after its start
    Replanner replan;        ///< ControlStrategy::Replan: makes the new plans (required by it)
    unsigned replanEvery{1}; ///< ControlStrategy::Replan: replan at every n-th surfacing (the start counts)
    /// The replanning strategies also replan at the first surfacing at or after each of these times (ascending):
    /// when a new forecast run becomes available (ForecastRuns::arrivalsAfter())
    std::vector<double> replanAt;
    /// ControlStrategy::PlannedHeadings: the plan's held headings (null: the plan is straight legs)
    const HeadingRoute *headings{nullptr};
    ObservedReplanner replanObserved; ///< ControlStrategy::ReplanObserved: makes the new plans (required by it)
    /// Dac, ReplanObserved: the standard deviation of the noise on each measured DAC component (field units; 0: none)
    double dacNoise{0.0};
    unsigned dacSeed{1}; ///< seed of that noise
    /// ReplanObserved: the correction it plans on, also steered with between plans (the crab angle for the corrected
    /// forecast's current at the fix), when no `learn` is given: CorrectedField(forecast, measured, correction)
    CorrectionParams correction;
    /// ReplanObserved (and Dac with learnSteersDac): the forecast the DAC make, once per surfacing that brought a new
    /// one, shared by the steering and the replanning; empty: the forecast corrected with `correction`
    DacLearning learn;
    /// Dac: aim off with the learned forecast's current at the fix (an ensemble's members weighed by the DAC) instead
    /// of the last dive's DAC alone
    bool learnSteersDac{false};
    /// Dac, ReplanObserved: what the glider measured before this flight (the earlier legs of a mission): the flight
    /// starts from it (FlownTrack::measured begins with it)
    std::vector<DacObservation> measuredBefore;
};

/// @brief One flown run.
struct FlownTrack
{
    std::vector<TimedPoint> fixes; ///< the start, every surfacing (GPS fixes) and the end of the run
    std::vector<TimedPoint> track; ///< every integration step
    std::vector<double> headings;  ///< heading (radians from +x, counter-clockwise) chosen at each fix but the last
    double plannedArrival{0.0};    ///< the plan's arrival time
    /// Distance to the goal at the plan's arrival time (the position then, interpolated on the track; at the end of
    /// the run when it ended earlier by a grounding)
    double finalDistance{std::numeric_limits<double>::infinity()};
    double arrivalTime{std::numeric_limits<double>::quiet_NaN()}; ///< first time within radius of the goal (NaN: never)
    bool reached{false}; ///< the goal was reached within radius before the run ended
    /// A mission of several legs (MissionExecution.h): its stations reached, and those reached after their window
    std::size_t stationsReached{0};
    std::size_t windowsMissed{0}; ///< see stationsReached
    bool grounded{false};         ///< the run ended on land or in a forbidden region
    std::string groundedWhy;      ///< what was met, and where (planning frame)
    /// Why the run does not count as reached, said for a pilot (empty when it reached): grounded, not within the
    /// radius by the end of the run (and what ended it), a station not reached, a station reached after its window
    /// (also when the run ended inside the goal's radius). Set by the mission's execution (MissionExecution.h).
    std::string notReachedWhy;
    double madeGoodSpeed{0.0}; ///< straight distance start -> last position divided by the time flown
    unsigned replans{0};       ///< ControlStrategy::Replan: surfacings that renewed the plan (a new plan, or the
                               ///< replanner's re-timed rest of the current one)
    /// Dac, ReplanObserved: the depth-averaged current measured over each dive (the mean of the truth along the dive,
    /// plus noise), with the forecast averaged along the same dive
    std::vector<DacObservation> measured;
};

/// @brief Flies `plan` (waypoints with planned times; the last is the goal) at `speed` through `truth`, choosing
/// headings with `strategy` from `forecast` (which may be `truth` itself). The run ends when the goal is reached
/// (within options.radius, when radius > 0), on a grounding, or at options.endTime. `forbidden` may be null.
/// The plan's last waypoint stays the goal for every strategy, replanning included.
/// @throws Error for an empty plan, a speed or interval that is not positive and finite, a step that is not, or
/// ControlStrategy::Replan without options.replan or with replanEvery 0.
FlownTrack flyPlan(const std::vector<TimedPoint> &plan, double speed, const CurrentField &forecast,
                   const CurrentField &truth, const Environment *forbidden, ControlStrategy strategy,
                   const ExecutionOptions &options);

/// @brief The position on a timed plan (or track) at time t: linear between its points, its first point before
/// it and its last point after it. The plan must not be empty.
TimedPoint planAt(const std::vector<TimedPoint> &plan, double t);

/// @brief The unit heading (hx, hy) that, added at `speed` to the current c, makes good the unit direction (dx, dy):
/// the cross-current part of c is cancelled and the rest of the speed goes along d. Where the cross current is
/// stronger than the speed, the heading points straight against it. [ThompsonICRA] Sec. III (current-sensitive
/// control).
void crabHeading(double dx, double dy, Velocity c, double speed, double &hx, double &hy);
} // namespace ompl_glider

#pragma once
/// @file Planning.h
/// @brief The one planning pipeline. Every way in (the built-in Gulf Stream problem, a NetCDF forecast from the
/// command line, a mission file, the library API) builds a MissionProblem and calls runMission(), which finds the
/// departure (a fixed time, or the optimal one in a window, [EichhornRAS] Sec. 5), calls planRoute() (the planner
/// through OMPL's SimpleSetup, then smoothing and refinement) and evaluates the result (straight line, dive
/// profiles per leg, the optimal-control reference, the speed sweep). The result is one MissionResult, written by
/// the output layer (output/OutputWriter.h).

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Progress.h"
#include "ompl_glider/cost/DiveProfile.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/mission/DepartureTimeSearch.h"
#include "ompl_glider/mission/Isochrones.h"
#include "ompl_glider/mission/MissionExecution.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/PlanStatus.h"
#include "ompl_glider/mission/ReachProbability.h"
#include "ompl_glider/ompl/NoPath.h"
#include "ompl_glider/execution/Stints.h"

namespace ompl_glider
{
/// @brief Overrides of the mission's planner settings for one plan (NaN / 0 / unset: the mission's value).
struct PlanOptions
{
    double speed{std::numeric_limits<double>::quiet_NaN()}; ///< vehicle speed
    double gridSize{0.0};                                   ///< lattice spacing
    int sectors{0};                                         ///< lattice sectors
    std::optional<bool> smoothing;                          ///< smoothing ([EichhornRAS] Table 3)
    std::optional<bool> refinement;                         ///< waypoint refinement
    /// Another planner than the mission's (by registry name; the mission's planner parameters are then not applied):
    /// the pipeline's switch to a heading planner; empty: the mission's
    std::string planner;
    std::optional<bool> globalCheck; ///< the global check of the route class (PlannerSpec::globalCheck)
    /// The planner's time limit in seconds (0: the mission's planner.time_limit, else the planner's default); the
    /// pipeline's switch to heading planners bounds them so (PlanningInternal.h kFallbackTimeLimit)
    double timeLimit{0.0};
    /// The switch to heading planners (Isochrone, then the level set) where straight legs find no path (default on);
    /// off, the planner's own outcome stands (replans at sea: the plan being flown is kept, at once)
    std::optional<bool> headingFallback;
};

/// @brief One candidate route of the global check: the planner's own, or one made from an extremal.
struct RouteCandidate
{
    std::string name;   ///< "ZA*TVE" (the planner's route), "extremal as straight legs", "extremal as headings"
    bool solved{false}; ///< a route that reaches the goal and passes its accurate re-flight
    double travelTime{std::numeric_limits<double>::infinity()}; ///< its re-flown travel time
    std::string why;                                            ///< why it has no route (empty when solved)
};

/// @brief The global check of the default pipeline (planRoute() with a lattice planner): the planner's route is
/// refined within its route class (the side of the jet, of an island it passes), so before the answer is final
/// extremals of Zermelo's heading law ([EichhornRAS] Eq. 2, Eq. 10) are shot from the start over a sweep of initial
/// headings, stopped where they meet land, a forbidden region or the region's edge. The fastest extremal through the
/// goal is a route of another class when it beats the planner's route; it is then flown as straight legs along its
/// track (refined like the planner's path) or as held headings following it, and the faster flyable route wins.
/// Where the planner found no route at all, the extremals are shot over the whole planning window: every extremal
/// through the goal is a flyable route.
struct GlobalCheck
{
    unsigned headings{0}; ///< initial headings swept over the circle
    /// Headings shot in finer scans of narrow windows, where the sweep found no extremal through the goal: about the
    /// heading whose extremal came nearest it, and about the level set's initial headings
    unsigned finerHeadings{0};
    /// The level set's first arrival at the goal (travel time, an estimate first order in its cell), computed where
    /// the sweep found no extremal through the goal; +inf when not computed or the front never reached the goal
    double levelSetTime{std::numeric_limits<double>::infinity()};
    /// The level set's budget of node updates (in proportion to the plan's own work, its cost-function calls and the
    /// front points of a heading planner it switched to: work, not time, so that the check gives the same answer on
    /// any machine), the updates it did, and whether the budget ended it before its front reached the goal
    std::uint64_t levelSetBudget{0};
    std::uint64_t levelSetUpdates{0};
    bool levelSetBudgetSpent{false};
    /// The check's time limit (the plan's, else the fallbacks' 30 s) ended its scans before they were done: an
    /// extremal or a level-set route it would have found may be missing (the one part of the check that depends on
    /// the machine's speed)
    bool timedOut{false};
    double timeLimit{0.0};     ///< that limit (s)
    bool extremalFound{false}; ///< an admissible extremal reaches the goal within the time bound
    /// Its travel time (the integrator's, a flyable schedule of continuous headings), +inf when none; the bound was
    /// the planner's route's travel time (or the planning window without a route)
    double extremalTime{std::numeric_limits<double>::infinity()};
    std::vector<RouteCandidate> candidates; ///< the planner's route first, then the extremal's routes tried
    std::string winner;                     ///< the candidate whose route is the plan (empty: none has one)
    /// 1 - winner's travel time / the planner's route's (0 when the planner's route won; 1 when it had none)
    double gain{0.0};
    double seconds{0.0};                ///< wall time of the check
    std::uint64_t currentModelCalls{0}; ///< CMC of the check
};

/// @brief How a plan fares over the members of an ensemble current (planRoute() with MissionProblem::getMembers()).
struct EnsemblePlan
{
    EnsembleObjective objective{EnsembleObjective::Expected}; ///< PlannerSpec::objective
    double quantile{0.9};                                     ///< the quantile of objective quantile
    /// The chosen plan's travel time by the objective over the members (+inf when a member cannot fly it)
    double objectiveValue{std::numeric_limits<double>::infinity()};
    std::vector<double> memberTravelTimes; ///< the chosen path flown in each member (+inf: impassable there)
    /// The share of the members in which the chosen path arrives (equal weights): 1 for a robust plan; below 1 when
    /// no candidate arrives in every member and the plan is the one most likely to arrive (objectiveValue then over
    /// the members it arrives in); 0 without a path
    double arrivalProbability{0.0};
    /// One candidate plan: planned on the members' mean or on one member, judged on every member.
    struct Candidate
    {
        std::string name; ///< "mean" or "member N" (0-based, in the mission's order)
        bool solved{false};
        double objectiveValue{std::numeric_limits<double>::infinity()};
        std::vector<double> memberTravelTimes;
    };
    std::vector<Candidate> candidates; ///< every candidate, the chosen one included
    std::string chosen;                ///< name of the chosen candidate
};

/// @brief The objective over members' travel times: their mean (expected), maximum (worst) or the q-quantile
/// (the ceil(q M)-th smallest of M; quantile); +inf when any is +inf (a plan that fails in a member is not robust).
double ensembleObjective(const std::vector<double> &travelTimes, EnsembleObjective objective, double q);

/// @brief What a glider flies ([IsernObstacles]): the plan of a stint planner, or the conversion of another
/// planner's path to a heading per surfacing (when the mission has a `stints` section).
struct StintOutcome
{
    StintPlan plan;        ///< bearings (degrees clockwise from north), surfacings, track, remaining distance
    bool converted{false}; ///< converted from the planner's path (stintsFromPath()), not planned on stints
    /// The stints flown: time between surfacings, the mission length (a conversion: long enough to arrive), what
    /// they minimise, the goal radius
    StintSettings settings;
    /// Conversion: the path's travel time, the stints' (+inf: they do not arrive) and the loss
    /// stintTravelTime / pathTravelTime - 1
    double pathTravelTime{std::numeric_limits<double>::infinity()};
    double stintTravelTime{std::numeric_limits<double>::infinity()}; ///< see pathTravelTime
    double loss{std::numeric_limits<double>::infinity()};            ///< see pathTravelTime
    double seconds{0.0}; ///< wall time of the conversion (the planning time of a stint planner is planningSeconds)
};

/// @brief What the accurate re-flight made the pipeline fall back on (PlannedPath::reflightFallback).
enum class ReflightFallback : std::uint8_t
{
    None = 0,     ///< the final path flies as planned
    EarlierStage, ///< the final path failed its re-flight or arrived later: the smoothed (or planner's) is flown
    Reaimed       ///< a heading route's last segment re-aimed to end on the goal when flown accurately
};

/// @brief The input at fault when a problem itself is bad (PlannedPath::badInput).
struct BadInput
{
    enum class Input
    {
        None,
        Start,
        Goal,
        ViaPoint, ///< waypoints[via]
        DepartureTime
    };
    Input input{Input::None};
    std::size_t via{0}; ///< the via point's index (Input::ViaPoint)

    /// @brief True when some input is at fault.
    bool any() const { return input != Input::None; }
    /// @brief Its dotted field name for MissionSpec::place(): "start", "goal", "waypoints[2]", "departure.time"; ""
    /// for none.
    std::string field() const;
};

/// @brief One planned path: what planRoute() returns.
struct PlannedPath
{
    bool solved{false};                     ///< an exact path to the goal was found
    PlanStatus status{PlanStatus::Unknown}; ///< how the plan ended (statusText(): "Exact solution", "No path", ...)
    /// What OMPL's solve() returned (Unknown when no planner ran: a start or goal refused before); status differs
    /// where the pipeline knows more (NoPath for a planner's Abort or Timeout that proved no path exists, Stopped)
    PlanStatus plannerStatus{PlanStatus::Unknown};
    std::string reason; ///< why there is no path, in words (empty when solved): noPath.text()
    /// Why there is no path, typed: its cause (what code branches on), figures and the parts of reason
    NoPath noPath;
    /// The input at fault when the problem itself is bad (start, goal, a via point, departure); none when there is a
    /// path or the problem is well-formed and has none
    BadInput badInput;
    std::string planner;                                           ///< canonical planner name (PlannerRegistry.h)
    double departure{0.0};                                         ///< departure time (field units)
    double speed{0.0};                                             ///< vehicle speed used
    std::vector<TimedPoint> raw;                                   ///< the planner's path (its own times)
    std::vector<TimedPoint> smoothed;                              ///< after smoothing (== raw when smoothing is off)
    std::vector<TimedPoint> path;                                  ///< the final path (after refinement when it is on)
    double rawTravelTime{std::numeric_limits<double>::infinity()}; ///< raw path arrival - departure
    double smoothedTravelTime{std::numeric_limits<double>::infinity()}; ///< smoothed path arrival - departure
    double travelTime{std::numeric_limits<double>::infinity()};         ///< final path arrival - departure
    /// Total time spent holding position on the final path (its zero-length legs: at the goal or a waypoint to
    /// arrive in the goal window, or the lattice's waits at a time-windowed zone); field time units
    double holdTime{0.0};
    /// How the arrival was moved into the goal window (MissionSpec::goalWindow): "hold at the goal", "hold at
    /// waypoint K", "later departure (hold at the start)", "slower leg K -> K+1"; empty when the planner's arrival
    /// was in the window or there is none
    std::string arrivalTiming;
    double rawPathLength{0.0};                                        ///< raw path length
    double pathLength{0.0};                                           ///< final path length
    double straightLineTime{std::numeric_limits<double>::infinity()}; ///< direct leg (+inf: impassable)
    double straightLineLength{0.0};                                   ///< start-goal distance
    std::uint64_t searchCostFunctionCalls{0};                         ///< CFC of the planner ([EichhornRAS] Table 4)
    std::uint64_t postprocessCostFunctionCalls{0};                    ///< CFC of smoothing and refinement
    std::uint64_t currentModelCalls{0};                               ///< CMC of the planner ([EichhornRAS] Table 4)
    std::uint64_t expandedVertices{0};                                ///< lattice vertices expanded (lattice planners)
    double planningSeconds{0.0};                                      ///< planner wall time
    double postprocessSeconds{0.0};                                   ///< smoothing + refinement wall time
    bool pathChecked{false}; ///< the final OMPL path passed PathGeometric::check() (stint plans: no
                             ///< stint met land or a forbidden region)
    /// Stints: the plan of a stint planner (then path holds its surfacings), or the path converted to stints
    std::optional<StintOutcome> stints;
    std::optional<EnsemblePlan> ensemble; ///< with an ensemble current: how the plan fares per member
    /// A route of held headings (IsochronePlanner, LevelSet in strong currents): the headings flown from the
    /// start; then path holds the segment ends (with their times) and track the flown track. Unset for straight legs.
    std::optional<HeadingRoute> headings;
    std::vector<TimedPoint> track; ///< the flown track of a heading route (every integration step; start first)
    /// The planner first asked when the pipeline switched to another one (a lattice without a path), and
    /// why; both empty when it did not switch
    std::string switchedFrom;
    std::string switchReason;                   ///< see switchedFrom
    NoPathCause switchCause{NoPathCause::None}; ///< why the planner first asked found none (None: no switch)
    /// Honest times: the route re-flown by the accurate Dormand-Prince re-flight (execution/Reflight.h).
    /// Straight legs are re-timed leg by leg by it (full speed; holds and legs the plan flies slower on purpose keep
    /// their planned arrival when the re-flight is earlier), so path and travelTime are the re-flight's; a leg it
    /// cannot fly makes the plan fail. Heading routes are re-flown whole: their end must lie within the goal tolerance,
    /// or within V * 1e-6 of the travel time of the goal (the gap still water closes in 1e-6 of the trip).
    bool reflown{false};
    /// The planner's own travel time of the final path before the re-timing (straight legs; its integrator's
    /// tolerance, [EichhornIWK] Table III); NaN when not re-timed
    double plannerTravelTime{std::numeric_limits<double>::quiet_NaN()};
    double reflownTravelTime{std::numeric_limits<double>::quiet_NaN()}; ///< the re-flight's travel time
    /// Set when the final path failed its re-flight and an earlier stage (smoothed, or the planner's) is flown: why
    std::string reflightNote;
    /// What the re-flight changed, typed: nothing, an earlier stage flown in place of the final path, or a heading
    /// route's last segment re-aimed (reflightNote says it in words)
    ReflightFallback reflightFallback{ReflightFallback::None};
    /// Heading routes: the distance from the goal at which the re-flight ends (straight legs end on it: 0)
    double reflownEndDistance{std::numeric_limits<double>::quiet_NaN()};
    /// The global check of the route class (lattice planners in the default pipeline); unset when it did not run
    std::optional<GlobalCheck> globalCheck;

    /// @brief Sets noPath to @p why and reason to its words.
    void setNoPath(NoPath why)
    {
        noPath = std::move(why);
        reason = noPath.text();
    }

    /// @brief True for a route of held headings.
    bool headingRoute() const { return headings.has_value(); }

    /// @brief CFC of planner and post-processing together.
    std::uint64_t totalCostFunctionCalls() const { return searchCostFunctionCalls + postprocessCostFunctionCalls; }
};

/// @brief A waypoint as written for the pilot.
struct MissionWaypoint
{
    Point2 position;        ///< planning frame
    bool geographic{false}; ///< lon/lat known
    LonLat lonLat;          ///< degrees (longitude in -180..180)
    double time{0.0};       ///< arrival (field units), with the dive profiles when they are enabled
    std::string iso;        ///< arrival as ISO 8601 UTC when the mission has a calendar, else empty
    int profile{-1};        ///< dive profile index of the leg that reaches this waypoint (-1: none)
    DiveProfile dive;       ///< that profile (climb-to / dive-to depths)
    double legTime{0.0};    ///< travel time of the leg that reaches it
    /// The mission's leg (1-based, MissionResult::legs) this waypoint belongs to: a via point closes its leg (its
    /// stay's end opens the next); 0 for a mission of one leg
    int missionLeg{0};
    /// Heading routes (PlannedPath::headingRoute()): the heading to hold FROM this waypoint, the bearing of the
    /// segment that leaves it (degrees clockwise from north in [0, 360), through the water), and how long it is held
    /// (field time units, as flown: the last segment ends at the arrival). The leaving segment is what the pilot sets
    /// at the waypoint; the segment that reaches waypoint i is waypoint i-1's. NaN for straight legs, at the last
    /// waypoint and where a hold (goal window) leaves the waypoint.
    double heading{std::numeric_limits<double>::quiet_NaN()};
    double headingDuration{std::numeric_limits<double>::quiet_NaN()}; ///< see heading
};

/// @brief One row of the speed sweep ([EichhornOceans] Table VI).
struct SpeedSweepRow
{
    double speed{0.0};                                                ///< vehicle speed
    bool solved{false};                                               ///< path found
    double travelTime{std::numeric_limits<double>::infinity()};       ///< path travel time
    double pathLength{0.0};                                           ///< path length
    double straightLineTime{std::numeric_limits<double>::infinity()}; ///< direct leg (+inf: impassable)
    double straightLineLength{0.0};                                   ///< direct distance
};

/// @brief The optimal-control reference (Zermelo's problem solved by shooting, ZermeloReference): extremals end where
/// they meet land, a forbidden region or leave the planning region, so the reference is a route the glider can fly;
/// where such an obstacle bounds the optimum, the best route may be slower than the fastest admissible extremal
/// (it follows the obstacle's edge) and none may be found.
struct OptimumReference
{
    bool found{false};                                          ///< an extremal through the goal was found
    double travelTime{std::numeric_limits<double>::infinity()}; ///< its travel time
    std::vector<TimedPoint> path;                               ///< samples of the optimal trajectory
};

/// @brief How runMission() runs.
struct RunOptions
{
    std::optional<std::vector<double>> speeds; ///< speed sweep (overrides the mission's `speeds`)
    bool optimum{false};                       ///< also solve the optimal-control reference
    ProgressSink progress;                     ///< progress lines (departure search, speed sweep)
};

/// @brief One leg of a mission's plan.
struct PlannedLeg
{
    std::size_t index{0}; ///< 0-based leg number
    std::string from, to; ///< names: "start", the via points' names, "goal"
    /// The via point index (MissionSpec::waypoints) the leg leaves from / goes to; -1 for the start / the goal
    int fromVia{-1}, toVia{-1};
    Point2 fromPoint, toPoint; ///< planning frame
    GoalWindowSpec window;     ///< arrival window at the leg's end (the via point's `arrive`, the goal's window)
    double stay{0.0};          ///< held at the leg's end after the arrival (the via point's stay; 0 at the goal)
    PlannedPath plan;          ///< the leg's own plan (planRoute() from its departure)
    /// Indices of the leg's first and last point in the mission's whole path (PlannedPath::path of the mission)
    std::size_t firstPoint{0}, lastPoint{0};

    /// @brief The leg's departure (its plan's departure).
    double departure() const { return plan.departure; }
    /// @brief The arrival at the leg's end (before the stay); NaN without a route.
    double arrival() const
    {
        return plan.solved && !plan.path.empty() ? plan.path.back().t : std::numeric_limits<double>::quiet_NaN();
    }
};

/// @brief What the free-order search (`order: free`) did.
struct OrderSearch
{
    std::vector<std::size_t> given;  ///< the order listed (indices into MissionSpec::waypoints)
    std::vector<std::size_t> chosen; ///< the fastest order found (empty when no order has a route)
    std::size_t ordersTotal{0};      ///< n! orders of n via points
    std::size_t ordersEvaluated{0};  ///< complete orders planned to the goal (the rest were pruned by the bound)
    std::size_t legsPlanned{0};      ///< leg plans made (each a planRoute())
    /// Travel time of the given order (+inf without a route) and of the chosen one
    double givenTime{std::numeric_limits<double>::infinity()};
    double chosenTime{std::numeric_limits<double>::infinity()}; ///< see givenTime
    /// 1 - chosenTime / givenTime (1 when only the chosen order has a route; 0 when the given order is the fastest)
    double gain{0.0};
    /// Why the search stopped before it proved its order the fastest ("the time limit of 5 s", "a stop request", "the
    /// budget of 1000 leg plans"): the chosen order is the fastest of those planned; empty when the search finished
    std::string stopped;
};

/// @brief Everything a run produced: the one result type of the pipeline.
struct MissionResult
{
    MissionSpec spec; ///< the mission
    /// The path at the chosen departure; with via points the whole route (legs in turn, stays as holds, MissionLegs.h)
    PlannedPath plan;
    /// A mission with via points: its legs in the order flown (each with its own plan); empty for a one-leg mission
    std::vector<PlannedLeg> legs;
    /// The via points in the order visited (indices into MissionSpec::waypoints); empty without via points
    std::vector<std::size_t> order;
    std::optional<OrderSearch> orderSearch; ///< with `order: free`: what the search did
    std::vector<MissionWaypoint> waypoints; ///< final path for the pilot (start first; empty without a path)
    std::string departureIso;               ///< the departure's date (empty without dates), also without a path
    bool diveProfiles{false};               ///< dive profiles evaluated
    std::vector<DiveProfile> profileSet;    ///< the generated profile set ([EichhornOceans] Sec. III.B)
    double diveTravelTime{std::numeric_limits<double>::infinity()}; ///< travel time flying the chosen profiles
    std::optional<DepartureSearchResult> departureSearch;           ///< when a window was given
    std::optional<OptimumReference> optimum;                        ///< when asked (RunOptions::optimum)
    std::vector<SpeedSweepRow> speedSweep;                          ///< speed sweep rows
    std::optional<ExecutionResult> execution; ///< the plan flown in the truth (MissionSpec::execution)
    std::optional<IsochroneSet> isochrones;   ///< reachable-set contours (output format "isochrones")
    /// The probability of reach over the ensemble's members (output format "reachability", section `reachability`)
    std::optional<ReachProbability> reachability;
    /// The final route's closest approach to land (the flown track of a heading route, else the legs): distance in
    /// planning units (NaN without land or path) and where; lonLat set when the mission is geographic
    LandApproach closestLand;
    std::optional<LonLat> closestLandLonLat;
    std::string safetyNote; ///< what the depth limit read (MissionProblem::safetyNote())
    /// what the forecast's reading decided that a pilot should know (MissionProblem::forecastNotes()): a derived
    /// grid angle, land from zero velocities, planning on a frozen last field
    std::vector<std::string> forecastNotes;
    std::string coastlineNote; ///< what the coastline gave and repaired (MissionProblem::coastlineNote())
    /// What the glider's observations gave and the correction they made (MissionProblem::observations(); null
    /// without them): the report's correction lines (correctionLines(), output/Report.h), summary.json's figures
    std::shared_ptr<const ObservationReport> observations;
    double wallSeconds{0.0}; ///< whole run
};

/// @brief The path's waypoints flown leg by leg in @p field at @p speed from path.front().t (each leg's fastest
/// straight travel time, TravelTimeCalculator), legs checked against the forbidden regions; empty when a leg is
/// impassable there.
std::vector<TimedPoint> retimePath(const MissionProblem &problem, std::shared_ptr<const CurrentField> field,
                                   double speed, const std::vector<TimedPoint> &path);

/// @brief Plans from the start at @p departure: makeSimpleSetup(), the planner named by planner.name (from the
/// registry, with the mission's planner.parameters set through OMPL's ParamSet), solve within planner.time_limit,
/// then smoothing (PathSmoother, [EichhornRAS] Table 3) and refinement (WaypointRefiner) as asked, and the
/// straight-line time for comparison. No path is an outcome (solved false, status and reason say why), not an
/// exception. Thread-safe for concurrent calls on one problem.
/// With an ensemble current (MissionProblem::getMembers()) the plan is robust: candidates are planned on the
/// members' mean and on every member (in parallel), each candidate path is flown in every member (retimePath()),
/// and the one with the least planner.objective over the members is returned (PlannedPath::ensemble), its times
/// those of the mean field. The robust plan is thus never worse by the objective than any single-member plan.
/// @throws Error for an unknown planner or parameter, or a bad problem (see makeGliderContext()).
/// A stint planner (PlannerFamily::Stints) flies the mission's `stints` section: its plan is the surfacings (not
/// smoothed or refined), solved when a plan was flown (exactly reaching the goal or not: PlannedPath::stints has the
/// remaining distance). With another planner and a `stints` section, the final path is converted to stints
/// (stintsFromPath()).
/// Goals in time (MissionSpec::goalWindow; [ThompsonICRA] Sec. III): after any planner, post-processing and
/// the ensemble's choice, an arrival before the window is moved into it (a hold at the goal where the glider can hold
/// there, else a hold at an earlier waypoint or a slower leg, latest first; PlannedPath::holdTime, arrivalTiming); an
/// arrival after it, or one that cannot be delayed, is no path (solved false, reason says why). The stint conversion
/// is made from the path before these holds.
PlannedPath planRoute(const MissionProblem &problem, double departure, const PlanOptions &options = {});

/// @brief The stint settings of the mission's `stints` section for a departure (depth from the vehicle).
/// @throws Error naming the section's field when the mission would run past the forecast.
StintSettings stintSettings(const MissionProblem &problem, double departure);

/// @brief Travel time of a full planner run against departure time ([EichhornRAS] Sec. 5), for the departure
/// search: thread-safe, +inf when no path. @p gridSize / @p sectors 0: the planner's.
TravelTimeOfDeparture departureFunction(const MissionProblem &problem, double gridSize = 0.0, int sectors = 0);

/// @brief The speed sweep ([EichhornOceans] Table VI): planRoute() at every speed from the departure tDep.
std::vector<SpeedSweepRow> speedSweep(const MissionProblem &problem, double tDep, const std::vector<double> &speeds,
                                      const ProgressSink &progress = {});

/// @brief Waypoints for the pilot and the travel time flying them.
struct PilotWaypoints
{
    std::vector<MissionWaypoint> waypoints; ///< start first
    /// Travel time with the chosen dive profiles (+inf when a leg is impassable with every profile); the 2-D travel
    /// time when dive profiles are off.
    double travelTime{std::numeric_limits<double>::infinity()};
};

/// @brief Waypoints for the pilot from a planned path: geographic coordinates, ISO times and, with dive profiles
/// ([EichhornOceans] Sec. III), the profile chosen for each leg (evaluated in parallel) and the arrival times flying
/// it. A mission of several legs (@p legs, MissionPlan::legs, with their places in @p plan's path) is written leg by
/// leg: a leg flown as held headings keeps its headings and flown times (MissionWaypoint::heading), a leg of straight
/// legs its dive profiles, so that a mission whose legs mix both kinds says for each leg how it is flown.
PilotWaypoints missionWaypoints(const MissionProblem &problem, const PlannedPath &plan,
                                const std::vector<PlannedLeg> &legs = {});

/// @brief The optimal-control reference from the start at @p departure (shooting; no forbidden regions).
OptimumReference optimumReference(const MissionProblem &problem, double departure, double speed, double maxTravelTime);

/// @brief The pipeline: departure (fixed or searched in the window), planRoute(), pilot waypoints with dive
/// profiles, the optimal-control reference when asked, the speed sweep. Writes nothing (see writeOutputs()).
/// A mission without a path is an outcome (plan.solved false), not an exception.
/// @throws Error for configuration errors, and for a mission with a fleet (plan it with runFleet(), Fleet.h).
MissionResult runMission(const MissionProblem &problem, const RunOptions &options = {});
} // namespace ompl_glider

#pragma once
/// @file PlanningInternal.h
/// @brief Internal pieces of the planning pipeline (planRoute(), runMission(), Planning.h); not installed.
///
/// The pipeline is split by concern, one source file each in src/mission/planning/; the declarations below are
/// grouped under the name of the file that defines them.

#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>
#include <ompl/base/PlannerStatus.h>
#include <ompl/base/SpaceInformation.h>

#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/routes/WaypointRefiner.h"
#include "ompl_glider/reference/ZermeloReference.h"
#include "../../core/Numbers.h"

namespace ompl_glider
{
namespace planning_detail
{

/// Time limit of planners that use all the time they get (sampling planners) when the mission gives none.
inline constexpr double kDefaultSamplingTimeLimit = 10.0;
/// Time limit of each heading planner (Isochrone, then LevelSet) that the pipeline runs after a lattice planner found
/// no path, when the mission gives none: an unbounded front in a strong circulating current would run for hours.
inline constexpr double kFallbackTimeLimit = 30.0;

/// Wall time in seconds since @p a.
inline double secondsSince(std::chrono::steady_clock::time_point a)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

// PlannerSetup.cpp

/// Where the mission gave the planner parameter @p name ("file:line: field 'planner.parameters.NAME'").
std::string parameterPlace(const MissionSpec &m, const std::string &name);

/// The waypoint refiner's settings from the mission's pipeline parameter refiner_max_evaluations.
/// @throws Error naming the parameter when its value is not an integer in 1..100000000.
RefinerParams refinerParams(const MissionSpec &m);

/// The configured planner of the mission on the setup's space information (@p other: another planner of the
/// registry in place of the mission's, without its parameters): its parameters set, then prepared
/// (PipelinePlanner::prepare()), which refuses work beyond the limits naming the field; @p gridField is the field
/// that gave @p grid.
ompl::base::PlannerPtr makePlanner(const MissionProblem &problem, const ompl::base::SpaceInformationPtr &si,
                                   const std::shared_ptr<const GliderContext> &ctx, double grid, int sectors,
                                   double departure, const std::string &other = "",
                                   const std::string &gridField = "planner.grid_size");

/// The problem of one departure, its departure time checked first so that the error names where it was given.
GliderProblem checkedProblem(const MissionProblem &problem, double departure, double speed);

// WorkEstimates.cpp: the limits of the work a parameter controls (refused up front, with the estimate)

inline constexpr double kMaxSurfacingsPerFlight = 1e5; ///< surfacings of one flown execution
inline constexpr double kMaxSurfacings = 2e7;          ///< surfacings of all runs and strategies of an execution
inline constexpr std::size_t kMaxIsochrones = 1000;    ///< isochrones of the isochrone output

/// Refuses an execution whose surfacing interval gives too many surfacings over @p window per flight, or in all.
void checkExecutionWork(const MissionSpec &m, double interval, double window, std::size_t runs, std::size_t strategies);

// NoPathReason.cpp

/// Why a search ended without an exact path: the setup's own check, the planner's own cause and words
/// (PipelinePlanner::noPathReason()), or OMPL's status.
NoPath noPathReason(const ompl::base::PlannerStatus &status, const ompl::base::Planner &planner,
                    const GliderSimpleSetup &setup, double timeLimit, const MissionSpec &m);

/// What bounds the arrival of an exhausted search (the end of the forecast or the planning horizon): sets @p n's
/// bound, boundSpan and boundText.
void boundArrival(const MissionProblem &problem, const GliderProblem &gp, NoPath &n);

// NoPathDiagnosis.cpp

/// A final plan without a path (no bad input, not stopped by a time limit): its reason led by what blocks the route and
/// the advice that helps (start or goal enclosed, the forecast too short, the current faster than V), the planner's
/// generic advice dropped; unchanged when none of these is found.
void diagnoseNoPath(const MissionProblem &problem, double departure, PlannedPath &plan);
/// Start or goal cut off from the other's water at the departure (a flood fill over the box at half the model's
/// cell, by the field's land, then also by the static forbidden regions): which, and by what; empty when connected
/// or undecided. @p byModelLand (optional) is set when the field's own land closes every way (then no heading can
/// reach the goal either; the forbidden regions' verdict is sampled, a gap narrower than a sample may be missed).
std::string enclosure(const MissionProblem &problem, double departure, bool *byModelLand = nullptr);

// Planning.cpp

/// planRoute() on the problem's one field.
PlannedPath planOnField(const MissionProblem &problem, double departure, const PlanOptions &o);

/// The final path of a (non-stint) planner flown as stints (stintsFromPath()), for a mission with a `stints` section.
StintOutcome convertToStints(const MissionProblem &problem, const PlannedPath &r);

// GlobalCheck.cpp

/// Where an extremal may go in @p ctx: inside the region's x/y bounds, in the field's water, out of the forbidden
/// regions at the times it passes them (ZermeloParams::admissible).
std::function<bool(double, double, double, double, double, double)> admissibleSet(
    const std::shared_ptr<const GliderContext> &ctx);

/// Shooting parameters for extremals in @p ctx up to @p maxTime: admissibleSet(), the scan on all cores, a goal miss
/// of 1e-9 of the trip.
ZermeloParams checkedExtremalParams(const MissionProblem &problem, const std::shared_ptr<const GliderContext> &ctx,
                                    double speed, double maxTime);

/// The global check (GlobalCheck, Planning.h) of a lattice planner's outcome in the default pipeline: returns @p r
/// with PlannedPath::globalCheck set, or the extremal's route when that is faster (or @p r had none); @p r unchanged
/// for other planners, an override planner (PlanOptions::planner), ensembles, bad input, a proven "no path" or
/// PlannerSpec::globalCheck false.
PlannedPath checkGlobally(const MissionProblem &problem, double departure, const PlanOptions &o, PlannedPath r);

// HeadingRoutes.cpp

/// The result of a planner that returned a heading route (PipelinePlanner::lastHeadingRoute()): the route flown once
/// more by the one integrator at a fine step, its segment ends as the path, its track kept; no smoothing or waypoint
/// refinement.
PlannedPath headingResult(const MissionProblem &problem, const GliderContext &ctx, const HeadingRoute &route,
                          PlannedPath r);

/// Honest times: re-flies the final route of a solved plan with the accurate re-flight (Reflight.h) and
/// makes the plan's times the re-flight's (PlannedPath::reflown); a straight leg or heading route the re-flight
/// cannot fly makes the plan fail with the reason.
void reflyRoute(const MissionProblem &problem, const GliderContext &ctx, PlannedPath &r);

/// The default's switch: a lattice planner that found no path on a well-formed problem hands over to the
/// heading planner (Isochrone), and that one to the level set; "no path" stays only when the level set's front
/// never reaches the goal within the time window. Returns @p failed unchanged for other planners and outcomes.
PlannedPath switchToHeadings(const MissionProblem &problem, double departure, const PlanOptions &o, PlannedPath failed);

// Ensembles.cpp

/// A robust plan over the members of an ensemble (see planRoute()).
PlannedPath planRobust(const MissionProblem &problem, double departure, const PlanOptions &o);

// GoalWindow.cpp

/// Total time spent holding position: the zero-length legs of a timed path.
double holdTimeOf(const std::vector<TimedPoint> &path);

/// A field time for messages: "t = T", followed by its ISO 8601 date when the mission has a calendar.
std::string timeText(const MissionProblem &problem, double t);

/// Moves the arrival of a solved plan into the mission's goal window (see GoalWindow.cpp).
void timeArrival(const MissionProblem &problem, PlannedPath &r);

// Evaluations.cpp

/// Adds @p from's search and post-processing work (CFC, CMC, expanded vertices, wall times) to @p to: the work of
/// several plans reported as one (an ensemble's candidates, a mission's legs).
void addPlanningWork(PlannedPath &to, const PlannedPath &from);

/// A solved plan that arrives after the forecast's last time under current.horizon hold_last (--beyond hold):
/// "planned past the forecast's last time (DATE) on its last field, held frozen for the last 5 d 2.0 h of the route
/// (...)"; empty otherwise.
std::string frozenFieldNote(const MissionProblem &problem, const PlannedPath &plan);

/// With forecast runs: "planned on forecast run 5 of 21, 'FILE': reference time DATE (where it was read), available
/// since DATE, the newest at the departure; lead time at arrival 18 d 9.3 h"; empty for one forecast.
std::string forecastRunNote(const MissionProblem &problem, const PlannedPath &plan);

// Isochrones.cpp

/// Contour @p lines of the planning frame in lon/lat: the isochrones' and the probability of reach's; empty where
/// the problem is not geographic.
std::vector<std::vector<LonLat>> linesToGeographic(const MissionProblem &problem,
                                                   const std::vector<std::vector<Point2>> &lines);
} // namespace planning_detail
} // namespace ompl_glider

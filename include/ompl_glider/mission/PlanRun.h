#pragma once
/// @file PlanRun.h
/// @brief One route plan from a GliderProblem with any planner (ZA*TVE family or OMPL's sampling planners),
/// smoothing (000 Table 3) and waypoint refinement, and its outputs (summary JSON, path CSV, map). The reusable
/// core of the glider_plan CLI.

#include <cstdint>
#include <map>
#include <optional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "ompl_glider/mission/MapRenderer.h"
#include "ompl_glider/mission/MissionRunner.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/planners/TveSearch.h"

namespace ompl_glider
{
/// @brief What to plan and how.
struct PlanRequest
{
    GliderProblem problem;           ///< field, speed, box, t0, horizon, start, goal, environment
    std::string planner{"ZA*TVE"};   ///< one of plannerNames()
    double gridSize{0.4};            ///< lattice spacing (ZA*TVE family)
    unsigned sectors{3};             ///< lattice sectors 1..5 (ZA*TVE family)
    bool smooth{true};               ///< run PathSmoother (000 Table 3)
    bool refine{true};               ///< run WaypointRefiner after smoothing
    double timeLimit{10.0};          ///< seconds for the planner (sampling planners use all of it)
    std::string title;               ///< map title (default: field name and planner)
    std::vector<MapPolygon> polygons;  ///< forbidden regions to draw on the map
    bool optimum{false};             ///< also solve Zermelo's problem (ZermeloReference) for comparison and the map
};

/// @brief Result of runPlan().
struct PlanRunResult
{
    bool feasible{false};                   ///< an exact path to the goal was found
    std::string status;                     ///< OMPL planner status as text ("Exact solution", ...)
    std::string planner;                    ///< planner used
    std::vector<TimedWaypoint> raw;         ///< planner's path (its own times)
    std::vector<TimedWaypoint> smoothed;    ///< after smoothing (== raw when smoothing is off or not possible)
    std::vector<TimedWaypoint> refined;     ///< after refinement (== smoothed when refinement is off)
    std::vector<TimedWaypoint> path;        ///< the final path (times re-simulated from t0 when flyable)
    double travelTimeRaw{std::numeric_limits<double>::infinity()};       ///< raw path arrival - t0
    double travelTimeSmoothed{std::numeric_limits<double>::infinity()};  ///< smoothed path arrival - t0
    double travelTime{std::numeric_limits<double>::infinity()};          ///< final path arrival - t0
    double pathLength{0.0};                 ///< final path length
    double straightLineTime{std::numeric_limits<double>::infinity()};    ///< direct leg (+inf: impassable)
    std::uint64_t costFunctionCalls{0};     ///< CFC of the planner (000 Table 4)
    std::uint64_t currentModelCalls{0};     ///< CMC of the planner (000 Table 4)
    std::uint64_t postprocessCostFunctionCalls{0};  ///< CFC of smoothing + refinement
    double planningSeconds{0.0};            ///< planner wall time
    double postprocessSeconds{0.0};         ///< smoothing + refinement wall time
    bool pathChecked{false};                ///< the final OMPL path passed PathGeometric::check()
    double optimumTime{std::numeric_limits<double>::infinity()};  ///< optimal-control travel time (when asked)
    std::vector<TimedWaypoint> optimumPath;  ///< samples of the optimal trajectory (when asked and found)
    std::vector<SpeedSweepRow> speedSweep;  ///< speed sweep (003 Table VI) when asked (planSpeedSweep())
};

/// @brief Planner names runPlan() accepts: "TVE", "A*TVE", "ZTVE", "ZA*TVE" (ZAStarTVE configurations) and OMPL's
/// "RRTstar", "InformedRRTstar", "PRM", "PRMstar", "RRT" on the time-augmented space.
const std::vector<std::string> &plannerNames();

/// @brief The built-in Gulf Stream mission: meandering jet (000 Sec. 6.1), x in [0, 10], y in [-4, 4], t0 = 0,
/// V = 0.5, start (1, -3) south of the jet, goal (8, 3) north of it, horizon 60.
GliderProblem gulfStreamProblem();

/// @brief Plans: makeSimpleSetup(), the named planner, solve within timeLimit, then smoothing and refinement on
/// the path (each never arrives later). No path is an outcome (feasible false), not an exception.
/// @throws Error for an unknown planner name, bad lattice parameters or a bad problem (see makeGliderContext).
PlanRunResult runPlan(const PlanRequest &request);

/// @brief JSON summary with the keys travel_time, path_length, waypoints_raw, waypoints_smoothed,
/// cost_function_calls, current_model_calls, planning_time_s, feasible (+ planner, start, goal, departure, speed,
/// waypoints_refined, travel_time_raw, travel_time_smoothed, straight_line_time, postprocess_cost_function_calls,
/// postprocess_time_s, status, optimal_control_time when asked). Infinite times are written as null.
std::string planSummaryJson(const PlanRequest &request, const PlanRunResult &result);

/// @brief The final path as CSV with header `t,x,y`, one line per waypoint.
std::string planPathCsv(const PlanRunResult &result);

/// @brief The map of the plan (field at departure, forbidden regions, raw / smoothed / refined paths with time
/// ticks, start and goal, legend).
MapRenderer planMap(const PlanRequest &request, const PlanRunResult &result);

/// @brief Writes DIR/summary.json, DIR/path.csv, DIR/map.svg and DIR/map.png (DIR is created when missing).
/// @return the files written. @throws Error naming the file that cannot be written.
std::vector<std::string> writePlanOutputs(const PlanRequest &request, const PlanRunResult &result,
                                          const std::string &directory);

/// @brief Human-readable report: travel time, path length, waypoints raw/smoothed/refined, CFC, CMC, times.
void printPlanReport(std::ostream &out, const PlanRequest &request, const PlanRunResult &result);

/// @brief The speed sweep of 003 Table VI for a PlanRequest: runPlan() at every speed (same start, goal,
/// departure, planner and post-processing). @throws Error for a speed <= 0 or as runPlan().
std::vector<SpeedSweepRow> planSpeedSweep(const PlanRequest &request, const std::vector<double> &speeds);

/// @brief A plan on a NetCDF forecast from command-line flags (`glider_plan --currents FILE`, issue 5).
struct ForecastPlanRequest
{
    std::string file;                              ///< the NetCDF forecast
    std::map<std::string, std::string> variables;  ///< role (u, v, lon, lat, depth, time) -> variable name
    std::string xyInterpolation{"bilinear"};       ///< nearest | bilinear | bicubic
    std::string depthInterpolation{"linear"};      ///< nearest | linear | cubic | akima
    std::string timeInterpolation{"linear"};       ///< nearest | linear | cubic | akima
    std::string horizonPolicy{"refuse"};           ///< refuse | hold_last (beyond the last forecast time)
    double depth{0.0};                             ///< depth (m, positive down) at which the current is read
    bool startSet{false}, goalSet{false};          ///< start / goal given
    double startA{0}, startB{0};                   ///< start: lon,lat (geographic file) or x,y (Cartesian file)
    double goalA{0}, goalB{0};                     ///< goal: lon,lat or x,y
    double speed{0.3};                             ///< vehicle speed through water, m/s
    std::string departure;  ///< ISO 8601 date or seconds after the first forecast time; empty: first forecast time
    std::string planner{"ZA*TVE"};                 ///< one of plannerNames()
    double gridSize{0.0};                          ///< lattice spacing in metres; 0: defaultForecastGridSize()
    unsigned sectors{3};                           ///< lattice sectors 1..5
    bool smooth{true};                             ///< smoothing (000 Table 3)
    bool refine{true};                             ///< waypoint refinement
    double timeLimit{10.0};                        ///< planner time limit (s)
};

/// @brief Default lattice spacing (metres) on a forecast: half the smallest grid cell, but no coarser than 1/25
/// of the start-goal distance and no finer than 1/200 of it, rounded to two significant digits. (Half a cell
/// resolves the interpolated field; 25 steps keep the path's shape; 200 steps bound the search on fine grids.)
double defaultForecastGridSize(double minCellSize, double startGoalDistance);

/// @brief The MissionSpec of a forecast request (one code path with `--mission`): loads the file once to check
/// it and to convert the start, goal and departure; checks that start and goal lie on the grid and in water, that
/// the depth is not below the deepest layer and that the departure lies within the forecast; picks the default
/// grid size. Only the trip's region is loaded (start-goal box plus half its larger side, at least 0.2 degrees,
/// on each side; the whole file across the antimeridian); for geographic files the mission gets that region
/// (clipped to the grid) and its local frame, so the mission loads the same subset. Writes nothing.
/// @throws Error with a one-line message naming the flag, file or variable at fault.
MissionSpec forecastMission(const ForecastPlanRequest &request);

/// @brief The final path as CSV with header `t,x,y,lon,lat` (t in seconds of field time, i.e. after the first
/// forecast time; x/y metres in the local projection; lon/lat degrees, empty for a Cartesian file).
std::string forecastPathCsv(const MissionResult &result);

/// @brief Writes DIR/summary.json (summaryJson()), DIR/path.csv (forecastPathCsv()), DIR/waypoints.csv,
/// DIR/path.geojson, DIR/goto_lNN.ma (geographic files), DIR/map.svg and DIR/map.png (missionMap()).
/// @return the files written. @throws Error naming the file that cannot be written.
std::vector<std::string> writeForecastOutputs(const MissionResult &result, const MissionProblem &problem,
                                              const std::string &directory);

/// @brief What `glider_plan --currents FILE` does: forecastMission(), runMission() (no files), the report on @p out
/// and the outputs in @p directory (none when empty); errors on @p err as one line.
/// @return 0 path found, 1 no path, 2 bad input (nothing written).
int runForecastCommand(const ForecastPlanRequest &request, const std::optional<std::vector<double>> &speeds,
                       const std::string &directory, bool progress, std::ostream &out, std::ostream &err);
}  // namespace ompl_glider

#pragma once
/// @file PlanRun.h
/// @brief One route plan from a GliderProblem with any planner (ZA*TVE family or OMPL's sampling planners),
/// smoothing (000 Table 3) and waypoint refinement, and its outputs (summary JSON, path CSV, map). The reusable
/// core of the glider_plan CLI.

#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "ompl_glider/mission/MapRenderer.h"
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
}  // namespace ompl_glider

#pragma once
/// @file WaypointRefiner.h
/// @brief Continuous optimisation of waypoint positions against the re-simulated travel time ("beyond the paper":
/// a graph search seeds a continuous optimisation, the idea of [IsernObstacles] Init-Optim, applied to the smoothed
/// path of [EichhornRAS] Table 3).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <ompl/geometric/PathGeometric.h>

#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/routes/PathSmoother.h"

namespace ompl_glider
{
/// The range of RefinerParams::maxEvaluations a mission may give (planner.parameters.refiner_max_evaluations):
/// stated here once, read by the pipeline and by the planners that declare the parameter.
constexpr double kMinRefinerEvaluations = 1.0, kMaxRefinerEvaluations = 1e8;

/// @brief Tunables of WaypointRefiner; the defaults suit paths of a few to a few tens of legs.
struct RefinerParams
{
    unsigned maxEvaluations{40000}; ///< budget of path re-simulations (each costs one CFC per leg)
    double initialStep{0.0};        ///< first trial move (field length units); <= 0: 1/4 of the mean leg length
    double minStep{0.0};            ///< moves stop below this length; <= 0: 1e-4 of the path length
    unsigned insertionRounds{4};    ///< rounds of "insert midpoints on the long legs, then optimise"
    double splitFraction{0.75};     ///< an insertion round splits the legs longer than this fraction of the mean
                                    ///< leg length (0: every leg), so waypoints do not bunch up
    std::size_t maxWaypoints{40};   ///< no insertion round makes the path longer than this
    double bumpFraction{0.2};       ///< neighbours moved along with a waypoint when it cannot move alone, as a
                                    ///< fraction of the waypoint count (0: single-waypoint moves only)
    double minRelativeGain{1e-3};   ///< an insertion round is kept only if it shortens the travel time by this
                                    ///< fraction (otherwise its extra waypoints are not worth it)
    /// Asked before every path re-simulation: true ends the refinement with the best path found so far (a
    /// planner's termination condition, so that a time limit also bounds refinement). Empty: only the budget.
    std::function<bool()> terminate;
};

/// @brief What refinement did.
struct RefinementResult
{
    std::vector<TimedPoint> waypoints;  ///< refined path, times re-simulated from t0
    std::size_t waypointsBefore{0};     ///< waypoint count of the input
    std::size_t waypointsAfter{0};      ///< waypoint count of the result
    double arrivalBefore{0.0};          ///< arrival of the input, re-simulated from t0
    double arrivalAfter{0.0};           ///< arrival of the result (<= arrivalBefore)
    unsigned evaluations{0};            ///< path re-simulations
    unsigned acceptedMoves{0};          ///< improving moves, insertions and removals accepted
    std::uint64_t costFunctionCalls{0}; ///< CFC spent
};

/// @brief Optimises the interior waypoints of a path (start and goal fixed) continuously against the arrival time
/// at the goal, re-simulated from t0 with the travel-time code (fastest pace on each straight leg).
///
/// Method: a pattern (compass) search. Each interior waypoint has its own step length; it tries moves across and
/// along the local path direction, accepts the first move that makes the arrival strictly earlier (the step then
/// grows); when none does, it tries a "bump" that moves the waypoint across the path together with its neighbours
/// (weights falling linearly over bumpFraction of the waypoints), since a stretch of path often cannot move one
/// waypoint at a time without kinks; failing that it halves its step. The search ends when every step is below
/// minStep or the evaluation
/// budget is spent. Derivative-free on purpose: the adaptive travel-time integration makes the cost piecewise
/// smooth, which finite-difference gradients handle badly. Waypoint count: an insertion round puts a midpoint on
/// every leg and optimises again, kept only when it gains at least minRelativeGain; finally each interior
/// waypoint whose removal does not make the arrival later is dropped.
///
/// Guarantees: only improving (or, for removals, not worsening) changes are accepted, so the arrival is never later
/// than the input's; every leg of every accepted path has a finite travel time, is legFree in ctx.environment and
/// its waypoints lie inside ctx.region's x/y bounds. A path that is infeasible on input is returned unchanged.
class WaypointRefiner
{
public:
    /// @throws Error when ctx is null or lacks a field or travel-time calculator, or a parameter is out of range.
    explicit WaypointRefiner(std::shared_ptr<const GliderContext> ctx, RefinerParams params = {});

    /// @brief Refines the waypoints for departure at t0 = waypoints.front().t (the start's time; the other input
    /// times are ignored). An empty input gives an empty result.
    RefinementResult refine(const std::vector<TimedPoint> &waypoints) const;

    /// @brief Refines an OMPL path on a TimeSE2StateSpace in place (departure at the first state's time); the path
    /// is replaced only when the result arrives no later than its own last state time.
    RefinementResult refine(ompl::geometric::PathGeometric &path) const;

    /// @brief The parameters in use.
    const RefinerParams &params() const { return params_; }

private:
    std::shared_ptr<const GliderContext> ctx_;
    RefinerParams params_;
};
} // namespace ompl_glider

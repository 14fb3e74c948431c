#pragma once
/// @file PathSmoother.h
/// @brief Path smoothing in a time-varying field ([EichhornRAS] Sec. 4, Table 3) and the path timing it relies on.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <functional>

#include <ompl/geometric/PathGeometric.h>

#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief Travel time of the straight leg (x1, y1) -> (x2, y2) leaving at tStart, with the environment check:
/// TravelTimeCalculator::travelTime (one CFC), then +inf when ctx.environment forbids the leg at the times it is
/// flown (Environment::legFree) or when the arrival lies after ctx.region.tMax.
double legTravelTime(const GliderContext &ctx, double x1, double y1, double x2, double y2, double tStart);

/// @brief The waypoints' positions with arrival times re-simulated from t0 (fastest pace on every leg):
/// t[0] = t0, t[i] = t[i-1] + legTravelTime(i-1 -> i). Times are +inf from the first infeasible leg on.
std::vector<TimedPoint> retimeWaypoints(const GliderContext &ctx, std::vector<TimedPoint> waypoints, double t0);

/// @brief Arrival time at the last waypoint re-simulated from t0 (+inf when a leg is infeasible; t0 for < 2 points).
double arrivalTime(const GliderContext &ctx, const std::vector<TimedPoint> &waypoints, double t0);

/// @brief Sum of the leg lengths.
double pathLength(const std::vector<TimedPoint> &waypoints);

/// @brief Index k >= 1 of the waypoint that ends the path's last hold (waypoints k - 1 and k at the same position:
/// the glider holds position from t[k - 1] to t[k]); 0 when the path never holds.
std::size_t lastHoldEnd(const std::vector<TimedPoint> &waypoints);

/// @brief Post-processing of a path that holds position (a lattice wait at a time-windowed zone, a hold for the goal
/// window): @p improve (smoothing or refinement, which fly every leg at full speed from the departure and
/// would drop the holds) is applied only to hold-free pieces, the holds kept: the piece after the last hold (from the
/// hold's end, its time fixed) or, when the path ends with a hold (at the goal), the part before it, the hold then
/// lengthened to its old end where the glider can hold from the new arrival (GliderContext::canHold and the
/// environment; else that part is kept). @p improve returns its input when it cannot improve it. A path without holds
/// is passed to @p improve whole.
std::vector<TimedPoint> improveAroundHolds(
    const GliderContext &ctx, const std::vector<TimedPoint> &waypoints,
    const std::function<std::vector<TimedPoint>(const std::vector<TimedPoint> &)> &improve);

/// @brief Waypoints (x, y, t) of a path on a TimeSE2StateSpace (see ompl/TimeSE2StateSpace.h).
/// @throws Error when the path's space is not a TimeSE2StateSpace.
std::vector<TimedPoint> waypointsFromPath(const ompl::geometric::PathGeometric &path);

/// @brief Replaces the states of @p path (on a TimeSE2StateSpace) by the waypoints; each state's yaw is the
/// direction of the leg that reaches it (the first state takes the first leg's direction).
/// @throws Error when the path's space is not a TimeSE2StateSpace.
void waypointsToPath(const std::vector<TimedPoint> &waypoints, ompl::geometric::PathGeometric &path);

/// @brief Merges consecutive legs of a timed path while keeping its schedule: from a kept waypoint a (time t_a), the
/// farthest later waypoint b is joined directly when the straight leg can be flown in exactly t_b - t_a (the
/// duration lies in TravelTimeCalculator::arrivalWindow(a -> b, t_a)), stays in the region's time window
/// and is legFree at those times. Every kept waypoint keeps its time, so the arrival is unchanged and every merged
/// leg is valid for TravelTimeMotionValidator. Meant for paths that wait or fly slow legs (sampling planners on
/// TimeSE2StateSpace), whose waypoints cannot all be flown at full speed from t0.
std::vector<TimedPoint> mergeKeepingSchedule(const GliderContext &ctx, const std::vector<TimedPoint> &timed);

/// @brief Relative tolerance of the smoother's "no later" tests (IV, V and the final guard): an arrival a counts as
/// no later than b when a <= b + 1e-12 |b|. It only lets exact ties that differ by rounding merge (a straight path
/// through collinear waypoints in a uniform current); the running bound is the minimum arrival seen, so the
/// tolerance never accumulates.
constexpr double kSmoothingTieTolerance = 1e-12;

/// @brief What smoothing did.
struct SmoothingResult
{
    std::vector<TimedPoint> waypoints; ///< smoothed path, times re-simulated from t0
    std::size_t waypointsBefore{0};    ///< waypoint count of the input (start and goal included)
    std::size_t waypointsAfter{0};     ///< waypoint count of the result
    double arrivalBefore{0.0};         ///< arrival at the goal of the input, re-simulated from t0
    double arrivalAfter{0.0}; ///< arrival at the goal of the result (<= arrivalBefore (1 + kSmoothingTieTolerance))
    unsigned passes{0};       ///< passes of loop I of [EichhornRAS] Table 3
    std::uint64_t costFunctionCalls{0}; ///< CFC spent by the smoothing
};

/// @brief SMOOTHING(WP, t0) of [EichhornRAS] Table 3 (also [EichhornIWK] Table II): merges consecutive legs of a
/// waypoint path in the time-varying field. From the kept waypoint WP[i_start], the direct leg to WP[i_path] replaces
/// the legs through WP[i_path - 1] when (III) it is feasible (finite travel time, legFree in ctx.environment), (IV) it
/// arrives at WP[i_path] no later than the legs it replaces, and (V) the rest of the path, re-simulated from the new
/// arrival time, reaches the goal no later than before. Otherwise WP[i_path - 1] is kept and merging restarts there
/// (VI). Passes repeat until the waypoint count stops changing (I).
///
/// Guarantees: the first and last waypoints are kept; every leg of the result is feasible and free; the result
/// never arrives later than the input (both re-simulated from t0 with the same travel-time code), up to the
/// relative rounding tolerance kSmoothingTieTolerance (1e-12: exact ties merge); a path with an
/// infeasible leg is returned unchanged (re-timed). Usable on any planner's path (waypoint list or, through the
/// PathGeometric overload, an OMPL path on a TimeSE2StateSpace).
class PathSmoother
{
public:
    /// @throws Error when ctx is null or lacks a field or travel-time calculator.
    explicit PathSmoother(std::shared_ptr<const GliderContext> ctx);

    /// @brief Smooths the waypoints with departure at t0 = waypoints.front().t (the start's time; the other input
    /// times are ignored). An empty input gives an empty result.
    SmoothingResult smooth(const std::vector<TimedPoint> &waypoints) const;

    /// @brief Smooths an OMPL path on a TimeSE2StateSpace in place (departure at the first state's time). The path
    /// is replaced only when the smoothed path arrives no later than the path's own last state time. When its
    /// waypoints cannot be flown at full speed from the departure (paths that wait, from sampling planners), the
    /// legs are first merged keeping the schedule (mergeKeepingSchedule()), then smoothed at full speed if that
    /// becomes possible and arrives no later; otherwise the schedule-keeping merge is the result.
    /// @return what smoothing did (result.waypoints is the path now held).
    SmoothingResult smooth(ompl::geometric::PathGeometric &path) const;

private:
    std::shared_ptr<const GliderContext> ctx_;
};
} // namespace ompl_glider

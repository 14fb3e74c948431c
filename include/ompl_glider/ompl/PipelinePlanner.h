#pragma once
/// @file PipelinePlanner.h
/// @brief What the planning pipeline (mission/Planning.h) asks of a planner beyond OMPL's Planner: to take the
/// mission's settings and refuse work beyond the limits before the search, its counters, the route model of its
/// result (a heading route, a stint plan) and, after a search without a path, why (its cause and its words,
/// NoPath.h). A planner of this project implements PipelinePlanner beside ompl::base::Planner; OMPL's own planners do
/// not, and pipelineView() answers for them with the defaults. The pipeline asks every planner through this interface
/// only, so adding a planner is its class, its row in the registry (registry/PlannerRegistry.h) and its tests.

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/ompl/NoPath.h"

namespace ompl_glider
{
struct HeadingRoute;  // execution/HeadingRoute.h
struct StintPlan;     // execution/Stints.h
struct StintSettings; // execution/Stints.h

/// @brief What the pipeline tells a planner before its search, and how to name the mission's fields in a message.
struct PipelineSetup
{
    double departure{0.0};  ///< departure time (field units)
    Point2 start{}, goal{}; ///< in the planning frame
    Region region;          ///< the planning region and time window (GliderContext::region)
    /// The mission's `stints` section (surfacing interval, mission duration, bearing step, ...); null without one.
    const StintSettings *stints{nullptr};
    /// Where a field of the mission was given, for messages: "file:line: field 'planner.grid_size'", or the flag
    /// or keyword that set it. Planner parameters are named "planner.parameters.NAME".
    std::function<std::string(const std::string &field)> place;
    /// True when the mission (or a flag, a keyword) gave the field or parameter itself, not its default.
    std::function<bool(const std::string &field)> given;

    /// @brief place(@p field), or "field '@p field'" when no place() is set (a setup made by hand).
    std::string where(const std::string &field) const;
    /// @brief given(@p field); false when no given() is set.
    bool isGiven(const std::string &field) const;
    /// @brief where() of the first of @p fields that was given; else of @p fallback.
    std::string placeOfFirstGiven(std::initializer_list<const char *> fields, const std::string &fallback) const;
};

/// @brief What the pipeline asks of a reachable set (PipelinePlanner::reachableSet()): the times of its isochrones, how
/// far the front runs, its cell, a goal whose first arrival is recorded on the way, the threads of the one solve and
/// a stop hook.
struct ReachRequest
{
    std::vector<double> times; ///< the isochrones' times (absolute, ascending); may be empty
    /// The absolute time the front runs to; NaN: the last of times (the departure when there are none)
    double until{std::numeric_limits<double>::quiet_NaN()};
    double cellScale{1.0}; ///< the cell as a multiple of the planner's default cell (when cellSize is 0)
    double cellSize{0.0};  ///< the cell itself (the field's length unit); 0: cellScale times the default
    /// A goal whose first arrival is recorded (ReachableSet::goalTime) while the front runs on to `until`
    std::optional<Point2> goal;
    unsigned threads{0};        ///< threads of the one solve (0: all cores)
    std::function<bool()> stop; ///< checked every step; true ends the front where it is (ReachableSet::stopped)
};

/// @brief The set reachable from the start by each of a few times ([LollaLevelSet]): first-arrival times on a grid
/// and the boundary of the set at each time (the isochrones of mission/Isochrones.h).
struct ReachableSet
{
    double resolution{0.0}; ///< cell size of the grid (the field's length unit)
    double seconds{0.0};    ///< wall time of the computation
    /// Node (i, j) at (x0 + i h, y0 + j h) in the planning frame; arrival[j * nx + i] the absolute first-arrival time
    /// (+inf where the set never came)
    double x0{0.0}, y0{0.0}, h{0.0};
    int nx{0}, ny{0};            ///< node counts
    std::vector<double> arrival; ///< see x0
    /// The boundary at each asked time, in the order asked: polylines in the planning frame
    std::vector<std::vector<std::vector<Point2>>> lines;
    /// The first arrival at ReachRequest::goal (absolute; +inf when the front did not reach it by `until`)
    double goalTime{std::numeric_limits<double>::infinity()};
    bool goalReached{false}; ///< the front reached ReachRequest::goal
    bool stopped{false};     ///< ReachRequest::stop ended the front before `until`
};

/// @brief What a reachable set would cost (PipelinePlanner::reachWork()), known before it runs, so that the pipeline
/// refuses work and memory beyond the limits of ResourceLimits.h before any is spent.
struct ReachWork
{
    double cell{0.0};         ///< the grid's cell (the field's length unit)
    double nodes{0.0};        ///< the grid's nodes
    double dt{0.0};           ///< the shortest time step
    double steps{0.0};        ///< time steps to the request's `until` (+inf when it never ends)
    double bytesPerNode{0.0}; ///< the memory of one solve under way, per node

    /// @brief Node updates: nodes times steps.
    double work() const { return nodes * steps; }
};

/// @brief The first arrival at the goal of a front from the start ([LollaLevelSet]) and the time-optimal path to it:
/// what PipelinePlanner::firstArrival() answers (the default pipeline's global check asks the registry's level-set
/// planner for it where no extremal reaches the goal).
struct FirstArrival
{
    bool reached{false}; ///< the front reached the goal (before tEnd, a stop and the work budget)
    double time{std::numeric_limits<double>::infinity()}; ///< absolute first-arrival time at the goal (+inf if not)
    /// The time-optimal path backtracked from the goal, start first (a hold: two points at one position); empty
    /// when the goal was not reached
    std::vector<TimedPoint> path;
    std::uint64_t work{0};   ///< the work done, in the planner's unit of its budget (the level set: node updates)
    bool budgetSpent{false}; ///< the work budget ended the computation
};

/// @brief The pipeline's questions to a planner. Every answer has a default, so a planner overrides only what it
/// has to say.
class PipelinePlanner
{
public:
    virtual ~PipelinePlanner() = default;

    /// @brief Takes the pipeline's settings before the search (called once the planner's parameters are set) and
    /// refuses a problem it cannot plan or work beyond the limits of ResourceLimits.h: throws Error naming the field
    /// through PipelineSetup::place().
    virtual void prepare(const PipelineSetup &setup) { (void)setup; }

    /// @brief Vertices (states) the last solve expanded; 0 when the planner does not count them.
    virtual std::uint64_t expandedVertices() const { return 0; }

    /// @brief Why the last solve ended without a path: its cause, figures and words (NoPath.h); cause None when the
    /// planner has nothing to add to OMPL's status (the pipeline then says what the status says). @p timeLimit: the
    /// limit it was given (s).
    virtual NoPath noPathReason(const ompl::base::PlannerStatus &status, double timeLimit) const
    {
        (void)status;
        (void)timeLimit;
        return {};
    }

    /// @brief The set reachable from @p setup's start, departing at its departure, up to @p request's `until` (the
    /// last of its times by default), with its isochrones at @p request's times and the first arrival at its goal
    /// if it names one; nullopt when the planner does not compute reachable sets (the default). The pipeline asks
    /// the registry's level-set planner for isochrones and for the probability of reach over an ensemble's members.
    virtual std::optional<ReachableSet> reachableSet(const PipelineSetup &setup, const ReachRequest &request) const
    {
        (void)setup;
        (void)request;
        return std::nullopt;
    }

    /// @brief What reachableSet(@p setup, @p request) would cost (its grid, its steps at their shortest, its memory);
    /// nullopt when the planner does not compute reachable sets (the default).
    virtual std::optional<ReachWork> reachWork(const PipelineSetup &setup, const ReachRequest &request) const
    {
        (void)setup;
        (void)request;
        return std::nullopt;
    }

    /// @brief The isochrones of a first-arrival field given on @p grid's nodes (its x0, y0, h, nx, ny and arrival;
    /// +inf: never): at each of @p times the boundary of {arrival <= t}, polylines in the planning frame, drawn as
    /// reachableSet() draws its own; nullopt when the planner draws none (the default). The pipeline contours the
    /// probability of reach with it: p(x, t) >= level where the members' weighted level-quantile of arrival is <= t.
    virtual std::optional<std::vector<std::vector<std::vector<Point2>>>> isochronesOf(
        const ReachableSet &grid, const std::vector<double> &times) const
    {
        (void)grid;
        (void)times;
        return std::nullopt;
    }

    /// @brief The first arrival at @p setup's goal of the front from its start, departing at its departure, followed
    /// until the absolute time @p tEnd, with its backtracked path; @p maxWork bounds the work (0: no bound) so that a
    /// problem gets the same answer on any machine and under any load, and @p stop (if set) ends it early. nullopt
    /// when the planner does not compute first arrivals (the default). The pipeline asks the registry's level-set
    /// planner (plannerOfFamily(PlannerFamily::LevelSet), registry/PlannerRegistry.h).
    virtual std::optional<FirstArrival> firstArrival(const PipelineSetup &setup, double tEnd, std::uint64_t maxWork,
                                                     const std::function<bool()> &stop) const
    {
        (void)setup;
        (void)tEnd;
        (void)maxWork;
        (void)stop;
        return std::nullopt;
    }

    /// @brief The last solve's route as held headings (execution/HeadingRoute.h), which the pipeline flies instead
    /// of straight legs between the path's states; null when the result is straight legs (the default) or nothing.
    virtual const HeadingRoute *lastHeadingRoute() const { return nullptr; }

    /// @brief The last solve's constant-bearing stint plan ([IsernObstacles]): its surfacings are the path and it is
    /// flown as it is, not smoothed; null for any other planner (the default).
    virtual const StintPlan *lastStintPlan() const { return nullptr; }
};

/// @brief @p planner as the pipeline sees it: itself when it implements PipelinePlanner, else a view whose answers
/// are the defaults (OMPL's own planners).
const PipelinePlanner &pipelineView(const ompl::base::Planner &planner);

/// @brief As above, for prepare().
PipelinePlanner &pipelineView(ompl::base::Planner &planner);
} // namespace ompl_glider

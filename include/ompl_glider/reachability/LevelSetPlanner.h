#pragma once
/// @file LevelSetPlanner.h
/// @brief The level-set solver as an OMPL planner ("LevelSet").

#include <memory>
#include <string>

#include <ompl/base/Planner.h>

#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/reachability/LevelSet.h"

namespace ompl_glider
{
/// @brief Time-optimal path by the level-set solver (LevelSetSolver, [LollaLevelSet]): the front is propagated from
/// the start state (its time is the departure) until it reaches the goal position, and the path is backtracked.
///
/// The returned PathGeometric (TimeSE2 states) is valid under TravelTimeMotionValidator: the front keeps half a
/// cell of clearance from forbidden regions; the backtracked points are thinned to straight legs that stay within a
/// third of a cell of the backtracked curve and timed by the project's travel-time code from the departure, at full
/// speed, or slower within the leg's arrival window where the level set reaches a point later (it waited, e.g. for a
/// lane to open, in a current too strong to hold); where the backtracked path holds, the path holds too (two states
/// at one position) when the glider can hold there. Its cost is therefore the travel-time code's time of those legs,
/// close to, not equal to, the front's arrival time getLevelSetTime() (the continuous optimum at this resolution,
/// with the clearance).
///
/// Where no straight legs can follow the backtracked path (a cross current stronger than the vehicle) the
/// result is a heading route instead (PipelinePlanner::lastHeadingRoute()): the steering direction along the path, the
/// direction of the velocity through the water (dx/dt - c) between backtracked points ([LollaLevelSet]: "a sequence of
/// steering directions"), refined by direct shooting (HeadingRefiner.h) so that its flight ends at the goal. The
/// returned PathGeometric then holds the segment ends.
///
/// Declared parameters: "resolution" (cell size, the field's length unit; 0: 1/200 of the region's larger side),
/// "cfl", "threads". Outcomes: EXACT_SOLUTION; ABORT when the front never reaches the goal within the region's time
/// window (no path: walled in, a lane that never opens); TIMEOUT when the termination condition stopped it;
/// INVALID_START / INVALID_GOAL outside the region; UNRECOGNIZED_GOAL_TYPE for goals without a position.
class LevelSetPlanner : public ompl::base::Planner, public PipelinePlanner
{
public:
    LevelSetPlanner(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx);
    ~LevelSetPlanner() override;

    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    void clear() override;
    /// @brief PipelinePlanner: refuses, naming resolution, cfl or planner.horizon, a front that would take more than
    /// kMaxLevelSetSteps time steps or kMaxLevelSetWork node updates (ResourceLimits.h) over the planning window.
    void prepare(const PipelineSetup &setup) override;
    /// @brief PipelinePlanner: why the front found no path (walled in, never reaching the goal, or lastReason()).
    NoPath noPathReason(const ompl::base::PlannerStatus &status, double timeLimit) const override;
    /// @brief The level set's reachable set from the setup's start (default LevelSetParams, no clearance, the cell
    /// the request gives or its cellScale times defaultLevelSetResolution(), the request's threads), run to the
    /// request's `until` without stopping at its goal (whose first arrival is recorded), and its isochrones.
    std::optional<ReachableSet> reachableSet(const PipelineSetup &setup, const ReachRequest &request) const override;
    /// The grid of the request's cell (its size, else cellScale times the default resolution), the steps at the
    /// automatic step's shortest (near a forbidden set) to its `until`, and the solve's 3 doubles a node.
    std::optional<ReachWork> reachWork(const PipelineSetup &setup, const ReachRequest &request) const override;
    /// @brief Reachability::isochrone() (marching squares) on the given first-arrival field at each time.
    std::optional<std::vector<std::vector<std::vector<Point2>>>> isochronesOf(
        const ReachableSet &grid, const std::vector<double> &times) const override;
    /// @brief The level set's first arrival at the setup's goal and its backtracked path (default LevelSetParams, the
    /// cell defaultLevelSetResolution() and half of it as clearance, as solve() with resolution 0), stopping at the
    /// goal, at @p tEnd, after @p maxWork node updates (LevelSetParams::maxNodeUpdates) or when @p stop answers true.
    std::optional<FirstArrival> firstArrival(const PipelineSetup &setup, double tEnd, std::uint64_t maxWork,
                                             const std::function<bool()> &stop) const override;

    /// @brief Cell size (0: automatic). @throws Error when negative or not finite.
    void setResolution(double h);
    double getResolution() const { return resolution_; }
    /// @brief The cell size used by the last solve.
    double getUsedResolution() const { return usedResolution_; }
    /// @brief Time step factor (LevelSetParams::cfl).
    void setCfl(double c);
    double getCfl() const { return params_.cfl; }
    /// @brief Threads (0: all cores).
    void setThreads(unsigned n) { params_.threads = n; }
    unsigned getThreads() const { return params_.threads; }

    /// @brief Arrival time minus departure of the front at the goal in the last solve (+inf when not reached).
    double getLevelSetTime() const { return levelSetTime_; }
    /// @brief The last solve's reachability (arrival field, backtracked path, work done).
    const Reachability &lastReachability() const { return last_; }
    /// @brief The heading route of the last solve when its backtracked path could not be flown as straight legs
    /// (in strong currents): the steering directions along the backtracked path, refined to end at the goal; null
    /// otherwise.
    const HeadingRoute *lastHeadingRoute() const override { return headings_.segments.empty() ? nullptr : &headings_; }
    /// @brief Why the last solve returned no path (empty otherwise).
    const std::string &lastReason() const { return reason_; }
    /// @brief The last solve's path as waypoints (the states of the returned path).
    const std::vector<TimedPoint> &getWaypoints() const { return waypoints_; }

private:
    std::shared_ptr<const GliderContext> ctx_;
    LevelSetParams params_;
    double resolution_{0.0};
    double usedResolution_{0.0};
    double levelSetTime_{0.0};
    Reachability last_;
    std::vector<TimedPoint> waypoints_;
    HeadingRoute headings_;
    std::string reason_;
};

} // namespace ompl_glider

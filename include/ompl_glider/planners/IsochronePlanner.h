#pragma once
/// @file IsochronePlanner.h
/// @brief A heading planner for strong currents ("Isochrone"): the isochrone method of weather routing on a
/// heading lattice, then a refinement of the headings by direct shooting (HeadingRefiner.h).
///
/// The search (IsochroneSearch.h) keeps, step by step, the boundary of the cells that held headings reach from the
/// start.
/// The first flight whose track passes within one cell of the goal ends the search. Its points are followed by held
/// headings (a new search from where following stops, followWithRestarts()), and its headings, followed back to the
/// start, are shot as N equal segments that end exactly at the goal in least time (refineHeadingRoute()); the faster
/// valid route is kept. As the cell, the step and the segments shrink, the route tends to the continuous optimum that
/// the level set approximates ([ZermeloNav]).
///
/// Unlike the straight-leg planners it needs no leg to be flyable against the current: a held heading that drifts
/// is a valid motion whatever the ratio of the current to the speed. Its result is a heading route
/// (PipelinePlanner::lastHeadingRoute()); the PathGeometric it returns holds the segment ends.
///
/// Parameters: "resolution" (cell size, length units; 0: 1/150 of the region's larger side), "headings" (K, default
/// 36), "time_step" (0: 2.5 cells at the speed),
/// "segments" (N of the refinement, 0: the number of steps, within 16..32), "shooting" (the refinement; default true),
/// "threads". Outcomes: EXACT_SOLUTION; ABORT when the front dies out or passes the end of the time window without
/// meeting the goal (the reason is kept in lastReason()); TIMEOUT; INVALID_START / INVALID_GOAL outside the region.

#include <memory>
#include <string>

#include <ompl/base/Planner.h>

#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/ompl/PipelinePlanner.h"

namespace ompl_glider
{
/// @brief The isochrone heading planner (see the file comment).
class IsochronePlanner : public ompl::base::Planner, public PipelinePlanner
{
public:
    IsochronePlanner(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx);
    ~IsochronePlanner() override;

    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    void clear() override;
    const HeadingRoute *lastHeadingRoute() const override { return route_.segments.empty() ? nullptr : &route_; }
    /// @brief PipelinePlanner: the front points the last solve expanded (expandedPoints()).
    std::uint64_t expandedVertices() const override { return expanded_; }
    /// @brief PipelinePlanner: lastReason() after an ABORT (no route), else nothing to add.
    NoPath noPathReason(const ompl::base::PlannerStatus &status, double) const override
    {
        NoPath n;
        if (status == ompl::base::PlannerStatus::ABORT)
            n = {reasonCause_, reason_};
        return n;
    }

    void setResolution(double h); ///< @throws Error when negative or not finite
    double getResolution() const { return resolution_; }
    void setHeadings(unsigned k); ///< @throws Error outside 8..720
    unsigned getHeadings() const { return headings_; }
    void setTimeStep(double dt); ///< @throws Error when negative or not finite
    double getTimeStep() const { return timeStep_; }
    void setSegments(unsigned n); ///< @throws Error above 1000
    unsigned getSegments() const { return segments_; }
    void setRefine(bool on) { refine_ = on; }
    bool getRefine() const { return refine_; }
    void setThreads(unsigned n); ///< @throws Error above 64
    unsigned getThreads() const { return threads_; }

    /// @brief Why the last solve found no route (empty after a success).
    const std::string &lastReason() const { return reason_; }
    /// @brief Front points expanded (cells reached) by the last solve.
    std::size_t expandedPoints() const { return expanded_; }
    /// @brief The travel time of the search's own route before refinement (+inf when none).
    double searchTravelTime() const { return searchTime_; }

private:
    std::shared_ptr<const GliderContext> ctx_;
    double resolution_{0.0};
    unsigned headings_{36};
    double timeStep_{0.0};
    unsigned segments_{0};
    bool refine_{true};
    unsigned threads_{0};
    HeadingRoute route_;
    std::string reason_;
    NoPathCause reasonCause_{NoPathCause::None}; ///< the cause of reason_
    std::size_t expanded_{0};
    double searchTime_{0.0};
};
} // namespace ompl_glider

#pragma once
/// @file IsochroneSearch.h
/// @brief The isochrone search of weather routing on a heading lattice, and a route closed on the goal by following
/// its points with held headings, searching again from where following stops. Used by the Isochrone planner
/// (IsochronePlanner.h) and by LevelSet's heading routes.
///
/// From the start, every point of the front flies K headings through the water for one time step with the one dive
/// integrator (flyHeading(): land and forbidden regions checked at the times they are passed); of the points that
/// land in a cell of a square grid, one per cell is kept (the one nearest the cell's centre), and of those only the
/// ones on the boundary of the cells reached at this step (a cell whose eight neighbours were all reached too is
/// inside the set, not on its front): the discrete form of the reachable set's boundary that [LollaLevelSet]'s front
/// tracks. A cell reached once stays closed for 8 steps, then reopens: where the current is stronger than the vehicle
/// the reachable set cannot hold still, so it may leave a place and come back to it later. The first flight whose
/// track passes within the dive's radius of the goal ends the search.

#include <limits>
#include <string>
#include <vector>

#include <ompl/base/PlannerTerminationCondition.h>

#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/execution/Dive.h"
#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/ompl/GliderContext.h"
#include "ompl_glider/routes/HeadingRefiner.h"

namespace ompl_glider
{
/// @brief A point of a front: where a chain of held headings from the start is at the end of a step.
struct FrontPoint
{
    double x, y, t;
    long parent;    ///< index of the point it was flown from (-1: the start)
    double bearing; ///< heading flown from the parent
};

/// @brief The first arrival found in a step.
struct GoalHit
{
    double arrival{std::numeric_limits<double>::infinity()};
    long parent{-1};
    double bearing{0.0};
};

/// @brief What an isochrone search needs besides its start: the cell, the step, the K headings and the dive settings
/// (speed, depth, integrator step, goal and the radius within which a flight meets it).
struct IsochroneSetup
{
    const GliderContext *ctx{nullptr};
    double cell{0.0};         ///< cell size of the grid that keeps one point per cell (length units)
    double dt{0.0};           ///< the time step of a front
    double tEnd{0.0};         ///< the end of the time window
    std::vector<Point2> rose; ///< the K headings' unit vectors (bearings 360 k / K)
    DiveSettings dive;        ///< flights: speed, depth, step, goal, radius
};

/// @brief The setup the Isochrone planner uses by default: cell @p cell (0: 1/150 of the region's larger side), step
/// @p dt (0: 2.5 cells at the speed), @p headings headings, flights at a quarter of the step, the goal met within a
/// cell (or @p tolerance if larger).
IsochroneSetup makeIsochroneSetup(const GliderContext &ctx, Point2 goal, double tolerance, double cell = 0.0,
                                  double dt = 0.0, unsigned headings = 36);

/// @brief The result of one search: its points (the start first) and the first arrival at the goal.
struct IsochroneSearch
{
    std::vector<FrontPoint> points;
    GoalHit hit;
    std::size_t expanded{0};
    bool timedOut{false};
    std::string why; ///< why the goal was not met (when !hit)
};

/// @brief Isochrone fronts from @p from until a flight passes within the dive's radius of the goal (hit), the front
/// dies out, the time window ends, the point cap is met (the reason in why) or @p ptc stops it (timedOut).
IsochroneSearch searchIsochrones(const IsochroneSetup &setup, TimedPoint from, ThreadPool &pool,
                                 const ompl::base::PlannerTerminationCondition &ptc);

/// @brief The timed points of a search from its start to the goal hit, the goal last at the hit's arrival;
/// @p bearings gets the bearing flown into each point (the start's is unused).
std::vector<TimedPoint> searchChain(const IsochroneSearch &search, Point2 goal, std::vector<double> &bearings);

/// @brief The search's own route: the headings flown from its start to the hit.
HeadingRoute searchRoute(const IsochroneSearch &search);

/// @brief Follows @p path with held headings (trackPathWithHeadings(), targets @p spacing apart, @p bearings as first
/// guesses when given); where a piece cannot be flown, keeps the pieces flown so far and runs a new isochrone search
/// from where the glider stopped (flights at half the step each time), whose points are followed in turn, at most
/// @p restarts times. Every piece is flown from where the glider really is, so long trips through sensitive flows
/// (where the search's coarse flights or a backtracked path lead through places that no accurately flown heading
/// links) still close on the goal. settings.step must be set (one check step for every piece). The joined route is
/// checked whole (verifyHeadingRoute()).
RefinedHeadings followWithRestarts(const std::vector<TimedPoint> &path, const std::vector<double> *bearings,
                                   Point2 goal, const GliderContext &ctx, const HeadingRefineSettings &settings,
                                   double spacing, const IsochroneSetup &setup, ThreadPool &pool,
                                   const ompl::base::PlannerTerminationCondition &ptc, int restarts = 4);
} // namespace ompl_glider

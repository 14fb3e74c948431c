#pragma once
/// @file HeadingRefiner.h
/// @brief Refinement of a heading route: the headings of N equal segments and the total duration T are optimised
/// (NLopt's SLSQP) to minimise T subject to the flown end point being the goal, the flight integrated by the one dive
/// integrator (flyHeadingRoute()). This is the direct-shooting form of Zermelo's problem ([ZermeloNav]; the direct
/// method of [BettsOC]): as N grows the piecewise-constant optimum tends to the continuous one, so a heading planner
/// that is refined converges to the level-set optimum ([LollaLevelSet]) as its segments shrink.

#include <optional>
#include <string>

#include "ompl_glider/execution/HeadingRoute.h"
#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief Settings of refineHeadingRoute().
struct HeadingRefineSettings
{
    unsigned segments{32}; ///< N equal segments of the refined route (the initial route is resampled)
    /// RK4 step of the route's check and of its final closing on the goal (0: headingCheckStep()); the optimiser's
    /// own flights use T / (16 N)
    double step{0.0};
    double depth{0.0};            ///< depth of the currents (m)
    double radius{1e-3};          ///< the refined route must end within this distance of the goal
    unsigned maxEvaluations{400}; ///< SLSQP iterations at most (each costs N + 2 flights)
    double tEnd{std::numeric_limits<double>::infinity()}; ///< no flight may last past this time
    unsigned threads{0};                                  ///< threads of the finite-difference flights (0: all cores)
};

/// @brief The outcome of refineHeadingRoute().
struct RefinedHeadings
{
    bool ok{false};       ///< a valid route to the goal: reached within the radius, no land, forbidden region or
                          ///< exit from the region on the way
    HeadingRoute route;   ///< the refined route, its last segment ending at the arrival
    HeadingFlight flight; ///< its flight (track kept)
    unsigned flights{0};  ///< flights flown by the refinement
    std::string why;      ///< why it failed (when !ok)
    /// trackPathWithHeadings() only: where following stopped when a piece could not be flown (route then holds the
    /// pieces flown up to there); empty when it did not stop part-way.
    std::optional<TimedPoint> stoppedAt;
};

/// @brief The RK4 step at which heading routes are checked and reported: 1/2000 of their duration, and at most the
/// time to cross 1/150 of the region's larger side at V + max|c| (the fixed-step error is then far below the 1e-5
/// relative that an accurate re-flight may differ by, on long routes too).
double headingCheckStep(double duration, const GliderContext &ctx);

/// @brief Flies the whole of @p route in @p ctx (its field, forbidden regions and speed) and checks it: no land or
/// forbidden region, the track inside the region, the end within the goal radius and before the end of the time
/// window. Then reached is set and arrivalTime is the end of the route (a heading route ends at the goal point, as
/// straight legs do); otherwise @p why says what failed. The verification every heading route gets.
HeadingFlight verifyHeadingRoute(const HeadingRoute &route, const GliderContext &ctx, Point2 goal,
                                 const HeadingRefineSettings &settings, std::string *why = nullptr);

/// @brief Refines @p initial (whose flight should end near @p goal) into N equal segments whose end point is the goal
/// and whose duration is least (SLSQP on the N headings and T, gradients by forward differences of flights). When the
/// full refinement leaves the water, a forbidden region or the region, the headings are frozen but for the last
/// segments (3, then 1) and refined again, so that a valid initial route near the goal always closes on it. Each
/// result is closed on the goal at the check step by Newton on its last segment's bearing and duration.
RefinedHeadings refineHeadingRoute(const HeadingRoute &initial, Point2 goal, const GliderContext &ctx,
                                   const HeadingRefineSettings &settings);

/// @brief The route @p initial resampled to @p n equal segments over @p duration: each new segment holds the bearing
/// the initial route has at its middle.
HeadingRoute resampleHeadingRoute(const HeadingRoute &initial, unsigned n, double duration);
} // namespace ompl_glider

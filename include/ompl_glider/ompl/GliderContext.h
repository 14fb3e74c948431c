#pragma once
/// @file GliderContext.h
/// @brief Everything a glider planning problem shares between the OMPL adapters and the planners.

#include <limits>
#include <memory>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/Environment.h"

namespace ompl_glider
{
/// @brief The field, the travel-time code (with the vehicle speed), the forbidden regions and the planning region
/// of one problem. Built once (see the setup helper) and shared read-only by the motion validator, the travel-time
/// objective and the planners (ZAStarTVE and friends). The departure time is not part of it: it is the start state's
/// time (GliderProblem::t0 in the setup helper), passed to the searches and read from the waypoints by the
/// post-processing.
struct GliderContext
{
    std::shared_ptr<const CurrentField> field;          ///< the current field (counts CMC)
    std::shared_ptr<const TravelTimeCalculator> travel; ///< travel time of legs (counts CFC); holds V
    std::shared_ptr<const Environment> environment;     ///< forbidden regions; null when there are none
    Region region;                                      ///< x/y bounds, time bounds [t0, t0 + horizon]
    /// Arrival window at the goal ("goals in time", [ThompsonICRA] Sec. III): the goal counts as reached
    /// only at a time in [arriveNotBefore, arriveNotAfter] (absolute times, the field's unit). Unbounded by default.
    double arriveNotBefore{-std::numeric_limits<double>::infinity()};
    double arriveNotAfter{std::numeric_limits<double>::infinity()};

    /// @brief Vehicle speed through water.
    double speed() const { return travel->params().speed; }
    /// @brief True when the glider can hold position at (x, y) over [t1, t2] (t2 >= t1): in water, within the
    /// field's time, and |c| < V at t1 + (t2 - t1) i / n, i = 0..n, n = max(1, ceil((t2 - t1) / step)) * subdivide.
    /// The one hold test of the motion validator (TravelTimeMotionValidator::canHold, subdivide 1) and of the lattice
    /// search's waiting edges (TveSearch; subdivide > 1 samples a superset of the validator's times).
    bool canHold(double x, double y, double t1, double t2, double step, int subdivide = 1) const;
    /// @brief The motion validator's default spacing of hold samples: 1/256 of the time window (1 if unbounded).
    double holdTimeStep() const;

    /// @brief Upper bound of the current speed over the region and time window ([EichhornRAS] Eq. 1).
    double maxCurrent() const { return field->maxSpeed(region); }
};
} // namespace ompl_glider

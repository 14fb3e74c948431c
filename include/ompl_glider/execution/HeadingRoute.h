#pragma once
/// @file HeadingRoute.h
/// @brief A route flown as held headings: a list of (heading, duration) segments from the start, the ground track
/// integrated through the current by the one dive integrator (flyHeading(), Dive.h). This is what a glider does
/// ([IsernObstacles] Sec. II) and how [LollaLevelSet] presents optimal paths in strong currents ("a sequence of
/// steering directions"): where the cross current exceeds the speed no straight ground leg exists, but a held heading
/// with drift still arrives.
///
/// Headings are bearings through the water, degrees clockwise from north (+y), unit vector (sin b, cos b), as the
/// stints use (StintSimulator.h). Durations are in field time units.

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/Environment.h"
#include "ompl_glider/execution/Dive.h"

namespace ompl_glider
{
/// @brief One segment of a heading route.
struct HeadingSegment
{
    double bearing{0.0};  ///< heading through the water, degrees clockwise from north
    double duration{0.0}; ///< how long it is held (field time units, > 0)
};

/// @brief A heading route: where and when it starts and the headings flown from there.
struct HeadingRoute
{
    Point2 start;                         ///< start (planning frame)
    double departure{0.0};                ///< departure (field time)
    std::vector<HeadingSegment> segments; ///< flown in order
    /// RK4 step at which the route was computed and checked (0: none given); flights of the route use it so that
    /// they follow the planner's own
    double step{0.0};

    /// @brief Sum of the segments' durations.
    double duration() const
    {
        double d = 0.0;
        for (const HeadingSegment &s : segments)
            d += s.duration;
        return d;
    }
};

/// @brief A flown heading route.
struct HeadingFlight
{
    std::vector<TimedPoint> ends;  ///< the start, then the end of every segment flown (the last one: where the
                                   ///< flight ended: the arrival, a grounding or the end of the segments)
    std::vector<TimedPoint> track; ///< every integration step, start first (when asked for)
    std::size_t segmentsFlown{0};  ///< segments begun (the last may have been cut by the arrival or a grounding)
    bool reached{false};           ///< the goal came within the radius (DiveSettings::radius > 0)
    double arrivalTime{std::numeric_limits<double>::quiet_NaN()}; ///< first time within the radius
    bool grounded{false};                                         ///< land or a forbidden region ended the flight
    std::string why;                                              ///< what was met, and where
    /// With a radius: the closest approach to the goal over the flight, and its time
    double closestDistance{std::numeric_limits<double>::infinity()};
    double closestTime{std::numeric_limits<double>::quiet_NaN()}; ///< see closestDistance
};

/// @brief Flies @p route through @p field with flyHeading() segment by segment (RK4 with DiveSettings::step, the last
/// step of a segment shortened to end it), checking land, @p forbidden (may be null) at the times they are passed and,
/// with DiveSettings::radius > 0, the goal radius: the flight ends at the first point within it (the arrival).
/// Segments with a duration <= 0 are skipped. DiveSettings::speed is the speed through water.
HeadingFlight flyHeadingRoute(const HeadingRoute &route, const CurrentField &field, const Environment *forbidden,
                              const DiveSettings &settings, bool keepTrack = true);

/// @brief Degrees clockwise from north -> unit heading (hx, hy) = (sin b, cos b).
inline Point2 bearingVector(double bearingDeg)
{
    constexpr double kDeg = 3.14159265358979323846 / 180.0;
    return {std::sin(bearingDeg * kDeg), std::cos(bearingDeg * kDeg)};
}

/// @brief (dx, dy) -> bearing in degrees clockwise from north, in [0, 360).
double bearingOf(double dx, double dy);
} // namespace ompl_glider

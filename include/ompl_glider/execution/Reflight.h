#pragma once
/// @file Reflight.h
/// @brief An accurate re-flight of a reported route, the yardstick of "honest times": a reported travel
/// time is honest when it is within 1e-5 relative of the re-flight of the route it reports.
///
/// The re-flight has its own integrator, an embedded Dormand-Prince 5(4) Runge-Kutta pair with an adaptive step
/// ([DormandPrince]; the tableau also in [HairerODE] Sec. II.5, the step-size control as in [HairerODE] Sec. II.4):
/// every step is judged by the difference of its fifth- and fourth-order solutions, accepted when that error is
/// within atol + rtol * |state| (root mean square over the state's components), and the fifth-order solution is
/// carried on. It shares no code with the planners' integrators: TravelTimeCalculator's adaptive rule with an
/// absolute tolerance per step (CALC-TRAVELTIME, [EichhornIWK] Table III) and flyHeading()'s fixed-step classic RK4
/// (Dive.h). "Accurate" means: with the default rtol = 1e-10, the re-flown times and positions agree with the exact
/// solution to about 1e-10 relative in smooth fields (the tests compare with closed forms, with RK4 at a step of
/// 1e-4 and with TravelTimeCalculator at eps = 1e-9), five orders inside the 1e-5 that "honest" asks for; the error
/// shrinks in proportion to rtol down to about 1e-13.
///
/// "Relative" is relative to the route, never to the position of the frame's origin or to the epoch of the field's
/// time axis: a heading route integrates the displacement from its start, a straight leg the time elapsed on the leg.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "ompl_glider/Geometry.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/Environment.h"
#include "ompl_glider/execution/HeadingRoute.h"

namespace ompl_glider
{
/// @brief Tolerances of the re-flight's Dormand-Prince 5(4) integrator (per step).
struct ReflightTolerance
{
    /// Relative tolerance of a step's local error: relative to the displacement from the route's start (heading
    /// routes, x/y units) or to the time elapsed on the leg (straight legs).
    double rtol{1e-10};
    /// Absolute tolerance of a step's local error, in the state's unit (x/y units for heading routes, time units for
    /// straight legs); 0: automatic, rtol times the route's own scale: rtol * V * (the route's duration) for a
    /// heading route, rtol * L / V (the leg's still-water time) for a straight leg of length L.
    double atol{0.0};
    /// Most steps (accepted and rejected) per segment or leg; beyond it the re-flight gives up and says so.
    std::size_t maxSteps{20000000};
};

/// @brief Settings of a re-flight.
struct ReflightSettings
{
    double speed{0.5};           ///< speed through water V (x/y units per time unit)
    double depth{0.0};           ///< depth at which the currents are read (m)
    double radius{0.0};          ///< heading routes: > 0, the flight ends when the goal is within this distance
    Point2 goal;                 ///< heading routes: the goal (used when radius > 0)
    ReflightTolerance tolerance; ///< the integrator's tolerances
    /// reflyPath(): a leg the plan flies more than 0.1 % slower than the re-flight at full speed (a wait for a lane,
    /// a goal window) keeps its planned arrival when that is later than the re-flown one, and a hold keeps its
    /// planned end, so the re-flight follows the plan's schedule; false: every leg at full speed, holds keep their
    /// planned duration
    bool keepSlowLegs{false};
};

/// @brief A re-flown heading route.
struct HeadingReflight
{
    /// The start, then the end of every segment flown; the last one is where the flight ended (the arrival, the
    /// start of the step that met land or a forbidden region, or the end of the last segment).
    std::vector<TimedPoint> ends;
    std::size_t segmentsFlown{0}; ///< segments begun (the last may have been cut by the arrival or a grounding)
    bool reached{false};          ///< the goal came within the radius (radius > 0)
    double arrivalTime{std::numeric_limits<double>::quiet_NaN()};   ///< first time within the radius, when reached
    TimedPoint end;                                                 ///< where the flight ended (ends.back())
    double finalDistance{std::numeric_limits<double>::quiet_NaN()}; ///< distance from end to the goal (radius > 0)
    bool grounded{false};    ///< land, a forbidden region or a non-finite current ended the flight
    std::string why;         ///< what was met, and where (planning frame); what failed when !ok
    bool ok{true};           ///< false when the integrator gave up (ReflightTolerance::maxSteps)
    std::size_t steps{0};    ///< accepted steps
    std::size_t rejected{0}; ///< rejected steps (error too large, or shortened to locate land)
};

/// @brief Re-flies @p route through @p field: dx/dt = V h + c(x, y, depth, t) for each held heading h
/// (bearingVector() of the segment's bearing), segment by segment (the last step of a segment shortened to end it;
/// segments with a duration <= 0 are skipped), with the Dormand-Prince 5(4) integrator of this file.
///
/// As flyHeading() (Dive.h) does, every accepted step is checked for land (CurrentField::segmentInWater() of its
/// chord) and, when @p forbidden is not null, for the forbidden regions (Environment::legFree() from the step's start
/// to its end at their times); a step that fails is halved until the blocked step is shorter than 1e-9 of the
/// segment's duration, and the flight ends grounded at the start of that step. A step whose current is not finite is
/// also halved, and grounds the flight the same way.
///
/// With settings.radius > 0 the flight ends at the first time the position is within the radius of the goal: a step
/// that ends inside, or whose chord enters the circle, is searched for the entry (bisection on the length of a fresh
/// Dormand-Prince step from the step's start, to 1e-15 of the step), so the arrival time is as accurate as the
/// integration itself. A route that starts inside the radius arrives at its departure.
HeadingReflight reflyHeadingRoute(const HeadingRoute &route, const CurrentField &field, const Environment *forbidden,
                                  const ReflightSettings &settings);

/// @brief One re-flown straight leg.
struct LegReflight
{
    double duration{std::numeric_limits<double>::infinity()}; ///< the leg's time at full speed; +inf if infeasible
    bool feasible{false};                                     ///< the leg can be flown straight at full speed
    /// When infeasible: where and when the re-flight stopped (for land: the first point of the leg on land, time NaN)
    TimedPoint where;
    std::string why;         ///< when infeasible: why
    std::size_t steps{0};    ///< accepted steps
    std::size_t rejected{0}; ///< rejected steps
};

/// @brief Re-flies the straight ground-track leg (x1, y1) -> (x2, y2) leaving at @p tStart at full speed V with the
/// crab angle that keeps the glider on the leg ([EichhornRAS] Eq. 4-6): with p the leg's unit direction and c the
/// current at the glider, the along-track speed is the fast root s = p.c + sqrt((p.c)^2 + V^2 - |c|^2), and the time
/// solves dt/dl = 1 / s(x(l), t) from l = 0 to the leg's length L, integrated in l with the Dormand-Prince 5(4) pair.
///
/// Infeasible (duration +inf, with where and why) where the discriminant (p.c)^2 + V^2 - |c|^2 <= 0 or s <= 0 (the
/// current pushes the glider off the leg or back; a step that meets it is halved until it is shorter than 1e-12 of the
/// leg, so @c where is the place of the first such point), where the leg touches land (CurrentField::segmentInWater()
/// of the whole leg, as TravelTimeCalculator does), where a step meets a forbidden region of @p forbidden (may be
/// null; Environment::legFree() at the re-flown times), and before CurrentField::timeBegin() or after timeEnd().
/// A leg of zero length takes no time. Only settings.speed, depth and tolerance are used.
LegReflight reflyLeg(double x1, double y1, double x2, double y2, double tStart, const CurrentField &field,
                     const Environment *forbidden, const ReflightSettings &settings);

/// @brief A re-flown straight-leg path.
struct PathReflight
{
    bool feasible{false}; ///< every leg could be flown
    /// The re-flown time at each waypoint from path.front().t (all of them when feasible; up to the start of the
    /// failed leg otherwise)
    std::vector<double> times;
    double arrivalTime{std::numeric_limits<double>::infinity()}; ///< times.back() when feasible, else +inf
    std::size_t failedLeg{0}; ///< when infeasible: the first leg (path[i] -> path[i + 1]) that cannot be flown
    TimedPoint where;         ///< when infeasible: where and when it failed
    std::string why;          ///< when infeasible: why ("leg i: ...")
    std::size_t steps{0};     ///< accepted steps over all legs
};

/// @brief Re-flies the straight-leg path @p path (the planners' usual output: ground-track legs flown with a crab
/// angle) from path.front().t, leg by leg with reflyLeg() at full speed V. A leg of zero length is a hold: it keeps its
/// planned duration (path[i + 1].t - path[i].t). A leg the plan flies slower than full speed on purpose (to meet a
/// goal window) is re-flown at full speed and so comes out faster than planned; that is expected, not dishonest:
/// compare such plans leg by leg or only where they fly at full speed. A path of one waypoint arrives at its time.
PathReflight reflyPath(const std::vector<TimedPoint> &path, const CurrentField &field, const Environment *forbidden,
                       const ReflightSettings &settings);

/// @brief Signed relative difference (reported - reflown) / |reflown| of two durations (travel times, not absolute
/// times of a field whose origin is arbitrary; see the three-argument form): negative when the reported time is
/// better than the truth. 0 when they are equal (both +inf included); -inf when only @p reflown is infinite,
/// +inf when only @p reported is; +-inf when @p reflown is 0 and @p reported is not; NaN when either is NaN.
double relativeDifference(double reported, double reflown);

/// @brief relativeDifference() of the durations since @p departure of two arrival times.
inline double relativeDifference(double reportedArrival, double reflownArrival, double departure)
{
    return relativeDifference(reportedArrival - departure, reflownArrival - departure);
}
} // namespace ompl_glider

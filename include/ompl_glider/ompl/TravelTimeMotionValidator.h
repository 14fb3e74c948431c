#pragma once
/// @file TravelTimeMotionValidator.h
/// @brief Which time-stamped straight legs a glider can fly.

#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include <ompl/base/MotionValidator.h>

#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief Verdict on a motion (x1, y1, t1) -> (x2, y2, t2); Valid or the first reason it is not.
enum class MotionVerdict
{
    Valid,          ///< the glider can fly the leg arriving exactly at t2
    NotForward,     ///< t2 <= t1 for a leg of positive length, or t2 < t1
    CannotHold,     ///< zero-length motion with t2 > t1 where the current is at least V at some time
    Infeasible,     ///< no heading keeps the glider on the leg (earliest arrival is +inf)
    TooEarly,       ///< t2 - t1 < earliest travel time
    TooLate,        ///< t2 - t1 > latest travel time (the glider cannot go slow enough and cannot hold)
    Blocked,        ///< the environment forbids the leg (Environment::legFree is false)
    InvalidEndState ///< the end state is invalid (bounds, time window, land, forbidden region)
};

/// @brief Human-readable name of a verdict ("valid", "too early", ...).
std::string toString(MotionVerdict v);

/// @brief Motion validator of the time-augmented space: a motion (x1, y1, t1) -> (x2, y2, t2) along the straight
/// leg is valid iff
///   - t2 > t1 (a zero-length motion may have t2 >= t1: t2 == t1 is the state itself; t2 > t1 means holding
///     position, allowed only where the glider can hold, |c| < V, checked at times spaced at most holdTimeStep
///     apart over [t1, t2]);
///   - t2 - t1 lies in [earliest, latest] of TravelTimeCalculator::arrivalWindow(x1, y1, x2, y2, t1): between the
///     two roots of the line-circle intersection the glider chooses its pace ([EichhornRAS] Eq. 4-6), and where
///     the slow root is <= 0 it can hold, latest = +inf. The bounds are widened by a relative tolerance
///     (default 1e-6, setRelativeTolerance()) so that times computed with the same travel-time code and added
///     to t1 (rounding) are accepted: earliest * (1 - tol) <= t2 - t1 <= latest * (1 + tol);
///   - the environment (if any) allows the leg at those times: Environment::legFree(x1, y1, t1, x2, y2, t2);
///   - for the State overloads also: the end state is valid (SpaceInformation::isValid, as OMPL's
///     DiscreteMotionValidator does, since planners like RRT* do not check sampled states separately).
/// The start state is assumed valid (OMPL convention). Caveat: the window is that of the whole leg, so a state
/// interpolated linearly in time along a valid motion (PathGeometric::interpolate()) need not split it into two
/// valid motions in a non-uniform field; OMPL's simplifiers re-check every motion they create and are safe. Each
/// positive-length check costs one cost-function call (CFC) of the context's TravelTimeCalculator, except legs rejected
/// early because t2 - t1 < |xy2 - xy1| / (V + max|c|) and repeats of the thread's previous query (one-entry per-thread
/// cache). Thread-safe.
class TravelTimeMotionValidator : public ompl::base::MotionValidator
{
public:
    /// @throws ompl_glider::Error when @p ctx is null or has no field / travel-time calculator.
    TravelTimeMotionValidator(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx);
    /// @brief Same, from a raw SpaceInformation pointer (as OMPL's own validators allow).
    TravelTimeMotionValidator(ompl::base::SpaceInformation *si, std::shared_ptr<const GliderContext> ctx);

    /// @brief True iff the motion s1 -> s2 is valid (see the class documentation).
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;

    /// @brief As above; when invalid, lastValid.second is the largest fraction tau in [0, 1) found such that the
    /// sub-motion s1 -> interpolate(s1, s2, tau) is valid (coarse scan at 8 points, then 12 bisection steps;
    /// 0 when none is), and lastValid.first (if non-null) is set to that state.
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                     std::pair<ompl::base::State *, double> &lastValid) const override;

    /// @brief Verdict for the leg on raw coordinates (no end-state validity check; counts no OMPL motion).
    MotionVerdict classify(double x1, double y1, double t1, double x2, double y2, double t2) const;

    /// @brief Verdict for the motion s1 -> s2 including the end-state validity check.
    MotionVerdict classify(const ompl::base::State *s1, const ompl::base::State *s2) const;

    /// @brief True when the glider can hold position at (x, y) over [t1, t2]: |c| < V at t1, t2 and at times at
    /// most holdTimeStep apart in between.
    bool canHold(double x, double y, double t1, double t2) const;

    /// @brief Relative tolerance on the arrival window (default 1e-6). Must be in [0, 0.1].
    void setRelativeTolerance(double tol);
    /// @brief Current relative tolerance.
    double getRelativeTolerance() const { return relTol_; }
    /// @brief Largest spacing of the current samples of canHold() (default: 1/256 of the context's time window,
    /// or 1 time unit if that window is unbounded). Must be > 0.
    void setHoldTimeStep(double dt);
    /// @brief Current hold time step.
    double getHoldTimeStep() const { return holdStep_; }

    /// @brief The context in use.
    const std::shared_ptr<const GliderContext> &context() const { return ctx_; }

private:
    void init();
    static std::uint64_t newCacheId();
    bool record(bool ok) const;
    MotionVerdict classifyUncached(double x1, double y1, double t1, double x2, double y2, double t2) const;

    std::shared_ptr<const GliderContext> ctx_;
    double relTol_{1e-6};
    double holdStep_{1.0};
    double vMax_{0.0};    ///< V + max|c| over the context's region
    std::uint64_t id_{0}; ///< unique id of this validator (key of the per-thread cache)
};
} // namespace ompl_glider

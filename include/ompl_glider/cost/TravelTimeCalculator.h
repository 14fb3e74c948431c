#pragma once
/// @file TravelTimeCalculator.h
/// @brief Travel time along a straight leg through a time-varying current.

#include <cstdint>
#include <limits>
#include <memory>

#include "ompl_glider/ShardedCounter.h"
#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief The two along-track speeds at which a vehicle of speed V through water stays on a leg of unit
/// direction p in current c: the roots of |s p - c| = V (line-circle intersection, [EichhornRAS] Eq. 4-6).
struct AlongTrackSpeeds
{
    bool feasible{false}; ///< false when disc <= 0 or the fast root <= 0 (the current pushes the vehicle off or back)
    double fast{0.0};     ///< p.c + sqrt(disc): the fastest progress along the leg
    double slow{0.0};     ///< p.c - sqrt(disc): the slowest progress that stays on the leg (<= 0: it can hold)
};

/// @brief Roots of the line-circle intersection for unit direction (px, py), current c and speed V.
/// disc = (p.c)^2 + V^2 - c.c ([EichhornRAS] Eq. 5); feasible iff disc > 0 and p.c + sqrt(disc) > 0 ([EichhornRAS] Eq.
/// 6).
AlongTrackSpeeds alongTrackSpeeds(double px, double py, const Velocity &c, double V);

/// @brief Parameters of the adaptive-step travel-time integration (CALC-TRAVELTIME, [EichhornIWK] Table III).
/// Step sizes are fractions of the leg length, as in the paper; eps is an absolute time tolerance, so it must be
/// chosen in the field's time unit (1e-3 for the dimensionless jet; about 1 s for missions in metres/seconds).
struct TravelTimeParams
{
    double speed{0.5}; ///< vehicle speed through water V (0.5 in the meandering-jet problem)
    double h{0.1};     ///< initial step, fraction of the leg length
    double hMin{1e-3}; ///< smallest step, fraction of the leg length
    double hMax{0.5};  ///< largest step, fraction of the leg length
    double eps{1e-3};  ///< tolerance of the local error |t_rough - t_improved| per step (time units)
    /// Optional tolerance relative to the leg ("honest times"): > 0, a step is judged against
    /// min(eps, rtol * t_step) instead of eps, t_step being the step's own (improved) time, so that the errors
    /// accepted along a leg add up to at most rtol times the leg's time whatever the field's time unit. 0: off, the
    /// absolute eps alone (bit-identical to the behaviour without it). Steps at hMin are still accepted whatever
    /// their error, so a tight rtol also needs a small hMin. Costly with this step law: err is the error of the
    /// first-order (rough) time, about quadratic in the step, so the step shrinks in proportion to rtol and soon
    /// sits at hMin; on the jet rtol = 1e-6 takes 34-68 times the current-model calls per CFC of the default, while
    /// the kept (second-order) time is far better than rtol (TestTravelTime, RelativeToleranceCostOnTheJetMeasured).
    double rtol{0.0};
    double tau{0.9};   ///< safety factor in (0, 1] of the step-size law [EichhornIWK] Eq. 5
    double depth{0.0}; ///< depth at which the current is read (positive down)
    /// Longest step (x/y units): the step law judges a step by the current at its two ends only, so a step longer
    /// than the field's features could pass over a feature between calm ends. Gridded fields set half a grid cell
    /// (MissionProblem); +inf: no limit beyond hMax.
    double maxStep{std::numeric_limits<double>::infinity()};
};

/// @brief Earliest and latest durations to fly a leg: between the two roots the vehicle chooses its
/// pace; where the slow root is <= 0 it can hold position and the latest arrival is unbounded.
struct ArrivalWindow
{
    double earliest; ///< fastest travel time; +inf when the leg is infeasible
    double latest;   ///< slowest travel time; +inf when the vehicle can hold somewhere along the leg
};

/// @brief Travel time of straight legs in a current field, integrated with the adaptive step of CALC-TRAVELTIME
/// ([EichhornIWK] Table III, [EichhornRAS] Sec. 3.2): per step a rough time with the current at the step's start, an
/// improved time with the mean of the start and end currents, local error = their difference, and the new step
/// h_new = max(h_min, min(h_max, tau h sqrt(tol / err))); a step is accepted when err < tol or h = h_min. The tolerance
/// is tol = eps, or with TravelTimeParams::rtol > 0 tol = min(eps, rtol * t_improved) (a tolerance relative to the
/// step's time, hence to the leg's).
///
/// Infeasible legs (a step with disc <= 0 or a non-positive effective speed, a leg that touches land anywhere
/// (CurrentField::segmentInWater), or a time after the field's end) cost +infinity, never NaN. Each call to
/// travelTime() or arrivalWindow() counts one cost-function call (CFC, [EichhornRAS] Table 4); the counter
/// (ShardedCounter) is exact across threads and the object is safe to share.
class TravelTimeCalculator
{
public:
    TravelTimeCalculator(std::shared_ptr<const CurrentField> field, TravelTimeParams params = {});

    /// @brief Fastest travel time from (x1, y1) leaving at tStart to (x2, y2); +inf if infeasible. One CFC.
    /// @note CALC-TRAVELTIME, [EichhornIWK] Table III; [EichhornRAS] Eq. 3-6.
    double travelTime(double x1, double y1, double x2, double y2, double tStart) const;

    /// @brief Fastest travel time of a leg along which the depth changes linearly from z1 to z2 (one segment of a
    /// glider's dive, [EichhornOceans] Table I); the same integration as travelTime(), which is the case z1 = z2 =
    /// depth. One CFC.
    double travelTimeThroughDepth(double x1, double y1, double z1, double x2, double y2, double z2,
                                  double tStart) const;

    /// @brief Earliest and latest travel times of the leg (fast and slow roots integrated). One CFC.
    ArrivalWindow arrivalWindow(double x1, double y1, double x2, double y2, double tStart) const;

    /// @brief Number of cost-function calls so far.
    std::uint64_t costFunctionCalls() const { return calls_.load(); }
    /// @brief Reset the CFC counter.
    void resetCostFunctionCalls() const { calls_.reset(); }

    /// @brief The field in use.
    const CurrentField &field() const { return *field_; }
    /// @brief Shared pointer to the field in use.
    const std::shared_ptr<const CurrentField> &fieldPtr() const { return field_; }
    /// @brief The parameters in use.
    const TravelTimeParams &params() const { return params_; }

private:
    /// Integrates the leg (depth linear from z1 to z2) with the fast (slow = false) or the slow root; returns +inf
    /// when infeasible or, for the slow root, when the vehicle can hold.
    double integrate(double x1, double y1, double z1, double x2, double y2, double z2, double tStart, bool slow) const;

    std::shared_ptr<const CurrentField> field_;
    TravelTimeParams params_;
    mutable ShardedCounter calls_;
};
} // namespace ompl_glider

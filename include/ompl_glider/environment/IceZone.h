#pragma once
/// @file IceZone.h
/// @brief A drifting ice zone under which a glider may stay submerged only for a limited time.

#include <vector>

#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/environment/ForbiddenRegion.h"
#include "ompl_glider/environment/Polygon.h"

namespace ompl_glider
{
/// @brief How the reference point of an ice zone carried by the current is advected (IceZone, carried form).
struct IceAdvectionParams
{
    double tolerance{1e-4};  ///< target bound of the position error of the zone (field length unit)
    double initialStep{0.1}; ///< first RK4 step tried (field time unit); halved until the tolerance is met
    int maxHalvings{12};     ///< at most this many halvings (then the reached tolerance is reported, not thrown)
    double depth{0.0};       ///< depth at which the current is read (positive down)
};

/// @brief A polygon of ice that moves rigidly (translation only) and under which a glider may stay submerged for
/// at most maxSubmergedTime, because it cannot surface there (ice operations: [EichhornIce]).
///
/// Motion: the shape is given at time tRef; at time t it is the shape shifted by the displacement d(t), d(tRef) = 0.
/// - Drifting form: d(t) = v (t - tRef) with a constant velocity v (exact).
/// - Carried form: d(t) = X(t) - X(tRef), X the trajectory of a reference point advected by the current field,
///   dX/dt = c(X, t), integrated with classical RK4 on a fixed step h over [tBegin, tEnd] and interpolated
///   linearly between the nodes. The step starts at initialStep and is halved until the estimated position error
///   |X_h - X_h/2| / 15 (Richardson, integration) + max |X_k+1 - 2 X_k + X_k-1| / 8 (linear interpolation) is at
///   most the tolerance; positionTolerance() reports the estimate reached. The zone keeps its shape (no
///   deformation by shear). Outside [tBegin, tEnd] d is extrapolated linearly from the end segment (outside the
///   stated tolerance). The constructor queries the field (it counts CMC once, before planning).
///
/// Legs. A glider surfaces at its waypoints, so a waypoint (a point at its time) under ice is blocked: pointFree()
/// is false inside the moving polygon, and a leg whose end is under ice is blocked. Along a leg (time linear in arc
/// length) the position relative to the zone, p(t) - d(t), is a straight segment between consecutive displacement
/// nodes (one segment for the drifting form), so the time intervals under ice follow exactly from
/// Polygon::segmentInsideIntervals piece by piece; touching pieces are merged into continuous stays. The leg is
/// blocked iff a continuous stay lasts longer than maxSubmergedTime (strictly). Tolerance: exact up to rounding
/// (relative 1e-15) for the drifting form; for the carried form a boundary-crossing time is off by at most
/// positionTolerance() / (relative speed normal to the boundary).
class IceZone : public ForbiddenRegion
{
public:
    /// @brief Drifting form: the shape at time tRef moves with constant velocity (vx, vy).
    /// @throws ompl_glider::Error for a non-finite velocity or tRef, or maxSubmergedTime < 0
    IceZone(std::string name, Polygon shape, double tRef, double vx, double vy, double maxSubmergedTime);

    /// @brief Carried form: the shape at time tRef moves with the point refPoint advected by the field over
    /// [tBegin, tEnd] (tBegin <= tRef <= tEnd).
    /// @throws ompl_glider::Error for a bad time window, a negative limit, or a non-finite current on the way
    IceZone(std::string name, Polygon shape, double tRef, const CurrentField &field, Point2 refPoint, double tBegin,
            double tEnd, double maxSubmergedTime, IceAdvectionParams params = {});

    bool pointFree(double x, double y, double t) const override;
    bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override;
    /// @brief "under ice zone '<name>'" when (x, y, t) is under the ice.
    std::string whyBlocked(double x, double y, double t) const override;
    /// @brief Names the zone and the time spent under it ("... for 1.25 (limit 1)").
    std::string whyLegBlocked(double x1, double y1, double t1, double x2, double y2, double t2) const override;

    /// @brief The maximal time intervals during which the leg is continuously under the ice (sorted).
    std::vector<Interval> underIceTimes(double x1, double y1, double t1, double x2, double y2, double t2) const;
    /// @brief Length of the longest continuous stay under ice along the leg (0 when it never is).
    double longestUnderIce(double x1, double y1, double t1, double x2, double y2, double t2) const;

    /// @brief Displacement d(t) of the zone since tRef.
    Point2 displacement(double t) const;
    /// @brief The limit of continuous submerged time under ice.
    double maxSubmergedTime() const { return maxSubmerged_; }
    /// @brief Bound of the position error of the zone (0 for the drifting form).
    double positionTolerance() const { return positionTolerance_; }
    /// @brief The shape at tRef.
    const Polygon &shape() const { return shape_; }
    /// @brief Number of displacement nodes (2 for the drifting form).
    std::size_t nodeCount() const { return times_.size(); }

private:
    Polygon shape_;
    double maxSubmerged_;
    bool constantVelocity_{true};
    double positionTolerance_{0.0};
    std::vector<double> times_; // displacement nodes (sorted)
    std::vector<double> dx_, dy_;
};
} // namespace ompl_glider

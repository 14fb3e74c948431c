#pragma once
/// @file ZermeloReference.h
/// @brief Exact time-optimal travel time between two points in an analytic current field: Zermelo's navigation
/// problem solved by shooting over the initial heading ([EichhornRAS] Sec. 6.1, Eq. 2 and Eq. 10).

#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief Parameters of the shooting method. Defaults give about 1e-8 relative accuracy on smooth fields.
struct ZermeloParams
{
    double speed{0.5};       ///< vehicle speed through water V
    double depth{0.0};       ///< depth at which the current is read
    double relTol{1e-10};    ///< relative tolerance of the Dormand-Prince RK5(4) integrator (refinement)
    double scanRelTol{1e-7}; ///< relative tolerance while scanning headings (only brackets the solutions)
    double absTol{1e-12};    ///< absolute tolerance of the integrator
    double maxTime{0.0};     ///< longest trajectory to follow (an upper bound of the optimal time, e.g. the
                             ///< travel time of any feasible path); <= 0: 6 * |goal - start| / V
    int headingSamples{720}; ///< initial headings scanned uniformly over the window below to bracket the
                             ///< solutions
    double headingFrom{0.0}; ///< first heading of the scan (radians)
    /// Width of the scanned window (radians, in (0, 2 pi]): 2 pi scans the whole circle (the last heading neighbours
    /// the first); less, a window about a guess (headingSamples + 1 headings from headingFrom to
    /// headingFrom + headingSpan)
    double headingSpan{6.283185307179586};
    double goalTolerance{1e-9}; ///< largest miss distance accepted as "passes through the goal" (where the
                                ///< heading bracket has shrunk to rounding, 1e-7 of the start-goal distance: in a
                                ///< sensitive flow the miss of the nearest representable heading can exceed it)
    int maxSteps{2000000};      ///< safety bound on integrator steps per trajectory
    /// Where an extremal may go: called with every accepted integrator step (from (x1, y1) at t1 to (x2, y2) at
    /// t2, absolute times); once it is false (land, a forbidden region, outside the planning region) no later
    /// closest approach of the extremal is a solution: such approaches only bracket the headings, and the extremal
    /// is followed only while it stays within the start-goal distance of the goal. Empty: everywhere (open water).
    std::function<bool(double x1, double y1, double t1, double x2, double y2, double t2)> admissible;
    unsigned threads{1}; ///< threads of the heading scan (0: all cores); the field must be thread-safe
    /// Asked before each extremal is shot (empty: never): once it answers true, solve() returns what it has found so
    /// far (a caller's time limit, a stop request)
    std::function<bool()> stop;
    /// An upper bound of the ground speed V + max|c| over the region and time (0: none). With it an extremal is no
    /// longer followed once the goal lies farther than this speed times the time left: it cannot reach it in time.
    double groundSpeedBound{0.0};
};

/// @brief One point of an extremal: time, position and heading (direction of the vehicle's velocity through water).
struct ZermeloState
{
    double t{0.0};
    double x{0.0};
    double y{0.0};
    double theta{0.0};
};

/// @brief A point of closest approach of an extremal to the goal (a local minimum of the distance).
struct ClosestApproach
{
    double t{0.0};    ///< time since departure
    double miss{0.0}; ///< signed distance to the goal (sign: side of the track the goal lies on)
    ZermeloState state;
    /// The extremal stayed in the admissible set (ZermeloParams::admissible) up to here; an approach after it left
    /// is kept to bracket the headings (a neighbour that misses the goal on the far side of a nearby coast or edge)
    bool admissible{true};
};

/// @brief The time-optimal solution found by shooting.
struct ZermeloSolution
{
    bool found{false};           ///< an extremal through the goal was found
    double travelTime{0.0};      ///< time-optimal travel time (arrival - departure); +inf when not found
    double initialHeading{0.0};  ///< heading at departure of the fastest extremal through the goal (radians)
    double missDistance{0.0};    ///< distance between the extremal and the goal at arrival
    int extremalsThroughGoal{0}; ///< number of distinct extremals found that pass through the goal
    /// The scanned heading whose extremal came nearest the goal while in the admissible set, and that distance (+inf
    /// when none came near): where no extremal through the goal was found, the centre of a finer scan.
    double nearestHeading{0.0};
    double nearestMiss{std::numeric_limits<double>::infinity()};
    int headingsShot{0}; ///< extremals of the scan shot (fewer than asked where ZermeloParams::stop answered true)
};

/// @brief Zermelo's navigation problem by shooting: the state (x, y, theta) obeys the equations of motion
/// dx/dt = u + V cos theta, dy/dt = v + V sin theta ([EichhornRAS] Eq. 10) and Zermelo's law
/// dtheta/dt = -u_y cos^2 theta + (u_x - v_y) cos theta sin theta + v_x sin^2 theta ([EichhornRAS] Eq. 2).
///
/// Every time-optimal trajectory is such an extremal, so the fastest extremal through the goal is the time-optimal
/// route. The initial heading is scanned over [0, 2 pi); for each heading the extremal is integrated with an
/// adaptive Dormand-Prince RK5(4) method up to a time bound, and its closest approaches to the goal are located
/// exactly (event location by single RK steps of the located size). A sign change of the signed miss distance
/// between neighbouring headings brackets an extremal through the goal, refined by the Illinois method until the
/// miss is below the tolerance; the fastest such extremal is kept. The paper used a collocation BVP solver (bvp6c)
/// for the same equations; shooting needs no initial guess of the path. With ZermeloParams::admissible an extremal
/// ends where it meets land, a forbidden region or the region's edge: the fastest extremal found is then the fastest
/// flyable one, and where an obstacle bounds the optimal route the true optimum (which follows the obstacle's edge)
/// may be slower than any extremal through the goal, never faster.
/// @note Uses CurrentField::velocity and CurrentField::jacobian (counts CMC like any other caller).
class ZermeloReference
{
public:
    /// @throws Error when field is null or a parameter is out of range.
    ZermeloReference(std::shared_ptr<const CurrentField> field, ZermeloParams params = {});

    /// @brief Time-optimal travel time from (x1, y1) departing at t0 to (x2, y2).
    ZermeloSolution solve(double x1, double y1, double x2, double y2, double t0) const;

    /// @brief Closest approaches to (gx, gy) of the extremal leaving (x1, y1) at t0 with heading theta0, up to
    /// duration maxTime after departure.
    /// @param relTol integrator tolerance (params().relTol when <= 0)
    std::vector<ClosestApproach> shoot(double x1, double y1, double theta0, double t0, double gx, double gy,
                                       double maxTime, double relTol = 0.0) const;

    /// @brief Samples of the extremal leaving (x1, y1) at t0 with heading theta0 for the given duration (every
    /// accepted integrator step plus the end point), e.g. to draw the optimal path.
    std::vector<ZermeloState> trajectory(double x1, double y1, double theta0, double t0, double duration) const;

    /// @brief The parameters in use.
    const ZermeloParams &params() const { return params_; }

private:
    struct Y
    {
        double x, y, th;
    };
    /// Right-hand side of Eq. 10 + Eq. 2 at absolute time t.
    Y rhs(double t, const Y &s) const;
    /// One Dormand-Prince step of size h from (t, s); returns the 5th-order solution and sets err (scaled norm).
    Y step(double t, const Y &s, const Y &k1, double h, double relTol, double &err) const;

    std::shared_ptr<const CurrentField> field_;
    ZermeloParams params_;
};
} // namespace ompl_glider

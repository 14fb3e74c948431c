#pragma once
/// @file Environment.h
/// @brief What is forbidden where and when: the interface the motion validator and the planners query.

#include <string>
#include <vector>

namespace ompl_glider
{
/// @brief A set of forbidden regions (land, islands, restricted areas, time-windowed zones, ice zones).
///
/// Times along a leg: a leg flown from (x1, y1) at t1 to (x2, y2) at t2 is taken to pass its points at times
/// linear in the arc length between t1 and t2 (constant pace); implementations document their tolerance for
/// moving or timed regions. Implementations must be thread-safe for const use.
class Environment
{
public:
    virtual ~Environment() = default;

    /// @brief True when (x, y) is in no forbidden region at time t.
    virtual bool pointFree(double x, double y, double t) const = 0;

    /// @brief True when the straight leg (x1, y1, t1) -> (x2, y2, t2) meets no forbidden region at the times it
    /// passes it (and, for ice zones, stays under ice no longer than allowed).
    virtual bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const = 0;

    /// @brief The times at which a timed restriction ends: the ends of the closed windows of time-windowed zones,
    /// sorted, without repeats. A planner that waits (TveSearch) tries departing just after them when a leg
    /// is blocked. Empty by default (static regions; drifting ice has no end).
    virtual std::vector<double> releaseTimes() const { return {}; }

    /// @brief True when the region never changes with time (pointFree() ignores t): a planner may then evaluate it
    /// once (LevelSet's static forbidden set). False by default.
    virtual bool isStatic() const { return false; }

    /// @brief Why (x, y, t) is not free ("inside island 'A'"); empty when it is free.
    virtual std::string whyBlocked(double x, double y, double t) const = 0;

    /// @brief Why the leg (x1, y1, t1) -> (x2, y2, t2) is not free ("leg crosses island 'A'"); empty when it is.
    /// The default names no region; ForbiddenRegions and its members override it.
    virtual std::string whyLegBlocked(double x1, double y1, double t1, double x2, double y2, double t2) const
    {
        return legFree(x1, y1, t1, x2, y2, t2) ? std::string() : std::string("leg meets a forbidden region");
    }
};
} // namespace ompl_glider

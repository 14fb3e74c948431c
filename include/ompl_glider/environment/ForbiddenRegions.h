#pragma once
/// @file ForbiddenRegions.h
/// @brief The composite Environment: any number of islands, land polygons, restricted areas, closures, ice zones.

#include <memory>
#include <vector>

#include "ompl_glider/environment/ForbiddenRegion.h"

namespace ompl_glider
{
/// @brief A set of named forbidden regions queried as one Environment (what the motion validator, the state
/// validity checker and the lattice planners see through GliderContext::environment).
///
/// A point or leg is free iff it is free for every member; whyBlocked() / whyLegBlocked() list every member that
/// blocks, separated by "; " ("inside island 'A'; inside closure 'lane'"). Each member documents its own method
/// and tolerance (StaticRegion, TimeWindowedZone, IceZone). Thread-safe for const use; add() is not.
class ForbiddenRegions : public Environment
{
public:
    ForbiddenRegions() = default;

    /// @brief Add a region (its name should be unique; not enforced). Null is rejected with ompl_glider::Error.
    void add(std::shared_ptr<const ForbiddenRegion> region);

    /// @brief The members in insertion order.
    const std::vector<std::shared_ptr<const ForbiddenRegion>> &regions() const { return regions_; }
    /// @brief Number of members.
    std::size_t size() const { return regions_.size(); }

    bool pointFree(double x, double y, double t) const override;
    bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override;
    std::string whyBlocked(double x, double y, double t) const override;
    /// @brief True when every member is static.
    bool isStatic() const override;
    /// @brief The members' release times, merged (sorted, no repeats).
    std::vector<double> releaseTimes() const override;
    std::string whyLegBlocked(double x1, double y1, double t1, double x2, double y2, double t2) const override;

private:
    std::vector<std::shared_ptr<const ForbiddenRegion>> regions_;
};

/// @brief Another name for ForbiddenRegions.
using EnvironmentSet = ForbiddenRegions;
} // namespace ompl_glider

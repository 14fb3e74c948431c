#pragma once
/// @file ForbiddenRegion.h
/// @brief Base class of one named forbidden region (island, land, restricted area, time-windowed zone, ice zone).

#include <string>

#include "ompl_glider/environment/Environment.h"

namespace ompl_glider
{
/// @brief One named forbidden region. It is an Environment by itself; ForbiddenRegions combines several.
///
/// whyBlocked() and whyLegBlocked() name the region as "<kind> '<name>'" (e.g. "inside island 'A'",
/// "leg crosses island 'A'"). Non-finite coordinates or times are never free.
class ForbiddenRegion : public Environment
{
public:
    /// @param name the region's name as given by the user ("A", "Funk Island")
    /// @param kind what it is ("island", "land", "restricted area", "closure", "ice zone")
    ForbiddenRegion(std::string name, std::string kind) : name_(std::move(name)), kind_(std::move(kind)) {}

    /// @brief The region's name.
    const std::string &name() const { return name_; }
    /// @brief What the region is ("island", ...).
    const std::string &kind() const { return kind_; }
    /// @brief "<kind> '<name>'".
    std::string label() const { return kind_ + " '" + name_ + "'"; }

    /// @brief "inside <kind> '<name>'" when (x, y, t) is blocked, else empty.
    std::string whyBlocked(double x, double y, double t) const override
    {
        return pointFree(x, y, t) ? std::string() : "inside " + label();
    }
    /// @brief "leg crosses <kind> '<name>'" when the leg is blocked, else empty.
    std::string whyLegBlocked(double x1, double y1, double t1, double x2, double y2, double t2) const override
    {
        return legFree(x1, y1, t1, x2, y2, t2) ? std::string() : "leg crosses " + label();
    }

private:
    std::string name_;
    std::string kind_;
};
} // namespace ompl_glider

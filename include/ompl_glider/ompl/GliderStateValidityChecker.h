#pragma once
/// @file GliderStateValidityChecker.h
/// @brief Validity of a single (x, y, yaw, t) state of a glider.

#include <memory>
#include <string>

#include <ompl/base/StateValidityChecker.h>

#include "ompl_glider/ompl/GliderContext.h"

namespace ompl_glider
{
/// @brief A state of TimeSE2StateSpace is valid when it lies inside the space's bounds (x/y box and time window),
/// its time lies in the context's window [region.tMin, region.tMax] and in the field's [timeBegin(), timeEnd()],
/// the point is in water (CurrentField::inWater at the travel-time depth) and, when the context has an
/// environment, not inside a forbidden region at that time (Environment::pointFree).
class GliderStateValidityChecker : public ompl::base::StateValidityChecker
{
public:
    /// @throws ompl_glider::Error when @p ctx is null or has no field / travel-time calculator.
    GliderStateValidityChecker(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const GliderContext> ctx);

    /// @brief True when the state is valid (see the class documentation).
    bool isValid(const ompl::base::State *state) const override;

    /// @brief Same test on raw coordinates (without the space's bounds).
    bool isValidPoint(double x, double y, double t) const;

    /// @brief Why the state is invalid ("time 61 after the window end 60", "inside island 'A'", ...);
    /// empty when it is valid.
    std::string whyInvalid(const ompl::base::State *state) const;

    /// @brief The context in use.
    const std::shared_ptr<const GliderContext> &context() const { return ctx_; }

private:
    std::shared_ptr<const GliderContext> ctx_;
};
} // namespace ompl_glider

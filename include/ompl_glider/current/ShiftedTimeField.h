#pragma once
/// @file ShiftedTimeField.h
/// @brief A field read on another time axis: field time t of this field is time t + shift of the wrapped one. Used
/// where a second source (the "truth" of an execution) counts its time from another origin than the
/// mission's forecast: both are then asked at the same dates.

#include <memory>
#include <string>

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief c(x, y, z, t) = inner(x, y, z, t + shift). Space and land are the inner field's; a query counts a CMC on
/// both. Everything the inner field tells (bounds, stream function, its grid with record times shifted) is told on
/// the shifted clock, so planning on it is planning on the inner field (a forecast run read on the mission's clock).
class ShiftedTimeField : public CurrentField, private FieldGrid
{
public:
    /// @brief Wraps @p inner (not null) with the time shift @p shift (finite).
    ShiftedTimeField(std::shared_ptr<const CurrentField> inner, double shift);

    double maxSpeed(const Region &region) const override;
    bool velocityBounds(const Region &region, double &uMin, double &uMax, double &vMin, double &vMax) const override;
    bool hasVelocityBounds() const override { return inner_->hasVelocityBounds(); }
    std::optional<double> streamFunction(double x, double y, double z, double t) const override
    {
        return inner_->streamFunction(x, y, z, t + shift_);
    }
    const FieldGrid *grid() const override { return innerGrid_ ? this : nullptr; }
    bool divergenceFree() const override { return inner_->divergenceFree(); }
    bool inWater(double x, double y, double z) const override { return inner_->inWater(x, y, z); }
    bool segmentInWater(double x1, double y1, double x2, double y2, double z) const override
    {
        return inner_->segmentInWater(x1, y1, x2, y2, z);
    }
    std::vector<Segment2> landBoundary(double z) const override { return inner_->landBoundary(z); }
    double timeBegin() const override { return inner_->timeBegin() - shift_; }
    double timeEnd() const override { return inner_->timeEnd() - shift_; }
    std::string name() const override { return inner_->name(); }
    /// @brief The time shift (inner time - this field's time).
    double shift() const { return shift_; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override
    {
        return inner_->velocity(x, y, z, t + shift_);
    }
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override
    {
        return inner_->jacobian(x, y, z, t + shift_);
    }

private:
    // the inner field's grid on this clock (grid())
    Region extent() const override;
    double minCellSize() const override { return innerGrid_->minCellSize(); }
    const std::vector<double> &recordTimes() const override { return recordTimes_; }
    bool covers(double x, double y) const override { return innerGrid_->covers(x, y); }

    std::shared_ptr<const CurrentField> inner_;
    double shift_;
    const FieldGrid *innerGrid_{nullptr};
    std::vector<double> recordTimes_; ///< the inner grid's, minus the shift
};
} // namespace ompl_glider

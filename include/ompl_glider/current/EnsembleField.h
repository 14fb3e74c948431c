#pragma once
/// @file EnsembleField.h
/// @brief The mean of an ensemble of current fields (members: forecasts of several models or runs, or an analytic
/// flow with several parameter sets). The planner's heuristics and the maps use the mean; robust plans
/// are judged member by member (mission/Planning.h, planRoute()).

#include <memory>
#include <string>
#include <vector>

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief c(x, t) = (1/M) sum_m c_m(x, t), or a combination sum_m a_m c_m(x, t). Water where every member has water;
/// defined where every member is.
class EnsembleMeanField : public CurrentField
{
public:
    /// @brief @p members: at least one, none null. @throws Error otherwise.
    explicit EnsembleMeanField(std::vector<std::shared_ptr<const CurrentField>> members);
    /// @brief A combination sum_m a_m c_m of the members (the members weighted by what a glider measured, and
    /// updated from their anomalies: current/EnsembleLearning.h); @p coefficients: one per member, finite.
    /// @throws Error otherwise.
    EnsembleMeanField(std::vector<std::shared_ptr<const CurrentField>> members, std::vector<double> coefficients);

    /// |mean| <= max over members of |c_m|, so the largest member bound bounds the mean (a combination: the sum of
    /// |a_m| times the members' bounds).
    double maxSpeed(const Region &region) const override;
    bool divergenceFree() const override;
    bool inWater(double x, double y, double z) const override;
    bool segmentInWater(double x1, double y1, double x2, double y2, double z) const override;
    /// @brief The members' land boundaries together (a point is in water only where every member has water).
    std::vector<Segment2> landBoundary(double z) const override;
    double timeBegin() const override;
    double timeEnd() const override;
    std::string name() const override;

    /// @brief The coefficients a_m of a combination (empty: the plain mean).
    const std::vector<double> &coefficients() const { return coefficients_; }
    /// @brief The members.
    const std::vector<std::shared_ptr<const CurrentField>> &members() const { return members_; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override;
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override;

private:
    std::vector<std::shared_ptr<const CurrentField>> members_;
    std::vector<double> coefficients_; // empty: the mean
};
} // namespace ompl_glider

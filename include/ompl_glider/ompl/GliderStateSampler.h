#pragma once
/// @file GliderStateSampler.h
/// @brief Uniform sampler of TimeSE2StateSpace restricted to times the glider could have reached.

#include <ompl/base/StateSampler.h>

namespace ompl_glider
{
/// @brief Samples x, y and yaw uniformly and the time uniformly in [max(tMin, t0 + d / vMax), tMax], where d is
/// the xy distance from the start and vMax = V + max|c| the fastest ground speed ([EichhornRAS] Eq. 1): no state
/// earlier than that can be reached from the start, so such samples would only be rejected by the motion validator.
/// sampleUniformNear() and sampleGaussian() use the space's default sampler and then raise the time to that
/// lower bound. The setup helper installs it on the space (StateSpace::setStateSamplerAllocator).
class GliderStateSampler : public ompl::base::StateSampler
{
public:
    /// @param space a TimeSE2StateSpace
    GliderStateSampler(const ompl::base::StateSpace *space, double startX, double startY, double t0, double vMax);

    /// @brief Uniform x, y, yaw; time uniform over the reachable part of the window.
    void sampleUniform(ompl::base::State *state) override;
    /// @brief Default near-sampling, time raised to the reachable lower bound.
    void sampleUniformNear(ompl::base::State *state, const ompl::base::State *near, double distance) override;
    /// @brief Default Gaussian sampling, time raised to the reachable lower bound.
    void sampleGaussian(ompl::base::State *state, const ompl::base::State *mean, double stdDev) override;

    /// @brief Earliest time at which (x, y) can be reached (clamped to the window).
    double earliestTime(double x, double y) const;

private:
    void raiseTime(ompl::base::State *state) const;

    ompl::base::StateSamplerPtr base_;
    double startX_, startY_, t0_, vMax_;
};
} // namespace ompl_glider

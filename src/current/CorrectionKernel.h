#pragma once
/// @file CorrectionKernel.h
/// @brief The correction's space-time covariance kernel ([RasmussenGP] Sec. 4.2.1, a Gaussian in distance and in time):
/// the one definition the optimal interpolation (CorrectedField), its sampled grid and the estimate of its scales
/// (CorrectionFit) use.

#include <cmath>

namespace ompl_glider
{
/// @brief exp(-r2 / (2 L2) - dt^2 / (2 T2)): the correlation of two points @p r2 (the squared distance) and @p dt
/// apart, at the squared length and time scales @p L2 and @p T2.
inline double correctionKernel(double r2, double dt, double L2, double T2)
{
    return std::exp(-r2 / (2.0 * L2) - dt * dt / (2.0 * T2));
}

/// @brief exp(-d2 / (2 s2)): one factor of the kernel (space or time, separately), @p d2 the squared offset and
/// @p s2 the squared scale.
inline double correctionKernelFactor(double d2, double s2)
{
    return std::exp(-d2 / (2.0 * s2));
}
} // namespace ompl_glider

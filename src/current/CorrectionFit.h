#pragma once
/// @file CorrectionFit.h
/// @brief The correction's parameters learned from the glider's DAC (CorrectedField's constructor calls it): the
/// length and time scales and the error ratio that maximise the innovations' marginal likelihood under the
/// correction's covariance model ([RasmussenGP] Sec. 5.4.1), with the innovations' mean (a bias, and the tidal
/// constituents the record resolves, [MerckelbachDAC], [PawlowiczTide]) as explicit basis functions whose coefficients
/// are integrated out (the restricted likelihood, [RasmussenGP] Sec. 2.7).
///
/// Along one glider's track distance and time grow together and the likelihood cannot tell a short length scale from a
/// short time scale, so the estimate is judged on DAC not used to fit it before it is kept (HeldOutCheck): estimated
/// again from the earlier half of the DAC alone, it predicts the later half from the earlier (forward in time, a
/// rolling origin's one step, as the planner predicts ahead), and so do the priors (what learning off uses), the
/// priors with the learned mean, and the learned scales without it. The best prediction wins (the priors on a tie);
/// what it kept is then estimated from all the DAC.

#include <vector>

#include <Eigen/Dense>

#include "CorrectionKernel.h"
#include "ompl_glider/current/CorrectedField.h"

namespace ompl_glider::correction_fit
{
/// At most this many of the most recent DAC enter the estimate (each likelihood is an O(n^3) factorisation).
constexpr std::size_t kMaxFitted = 200;

/// @brief The estimate: @p summary's heldOut, sources, learnedFrom and likelihoodGain are set, and where the held-out
/// check keeps them its params (the free scales replaced) and mean. @p used: the observations by time; @p du, @p dv:
/// their innovations (not all zero).
void learn(const std::vector<DacObservation> &used, const Eigen::VectorXd &du, const Eigen::VectorXd &dv,
           CorrectionSummary &summary);

/// @brief The correction's correlation (correctionKernel()) between observations @p a and @p b.
inline double correlation(const DacObservation &a, const DacObservation &b, double L2, double T2)
{
    const double dx = a.at.x - b.at.x, dy = a.at.y - b.at.y, dt = a.t - b.t;
    return correctionKernel(dx * dx + dy * dy, dt, L2, T2);
}
} // namespace ompl_glider::correction_fit

#pragma once
/// @file CorrectionFit.h
/// @brief The correction's parameters learned from the glider's DAC (CorrectedField's constructor calls it): the
/// length and time scales and the error ratio that maximise the innovations' marginal likelihood under the
/// correction's covariance model ([RasmussenGP] Sec. 5.4.1), with the innovations' mean (a bias, and the tidal
/// constituents the record resolves, [MerckelbachDAC], [PawlowiczTide]) as explicit basis functions whose coefficients
/// are integrated out (the restricted likelihood, [RasmussenGP] Sec. 2.7).

#include <vector>

#include <Eigen/Dense>

#include "CorrectionKernel.h"
#include "ompl_glider/current/CorrectedField.h"

namespace ompl_glider::correction_fit
{
/// At most this many of the most recent DAC enter the estimate (each likelihood is an O(n^3) factorisation).
constexpr std::size_t kMaxFitted = 200;

/// @brief The estimate: @p summary's params (the free scales replaced), sources, learnedFrom, likelihoodGain and
/// mean are set. @p used: the observations by time; @p du, @p dv: their innovations (not all zero).
void learn(const std::vector<DacObservation> &used, const Eigen::VectorXd &du, const Eigen::VectorXd &dv,
           CorrectionSummary &summary);

/// @brief The correction's correlation (correctionKernel()) between observations @p a and @p b.
inline double correlation(const DacObservation &a, const DacObservation &b, double L2, double T2)
{
    const double dx = a.at.x - b.at.x, dy = a.at.y - b.at.y, dt = a.t - b.t;
    return correctionKernel(dx * dx + dy * dy, dt, L2, T2);
}
} // namespace ompl_glider::correction_fit

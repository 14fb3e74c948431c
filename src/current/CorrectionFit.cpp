/// @file CorrectionFit.cpp
/// @brief The correction's scales, bias and tides learned from the glider's DAC (CorrectionFit.h).

#include "CorrectionFit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <tuple>

#include <nlopt.hpp>
#include "../core/Numbers.h"

namespace ompl_glider::correction_fit
{
namespace
{

/// The main constituents, by priority ([PawlowiczTide]: periods in hours): the semidiurnal lunar, the diurnal
/// luni-solar, the semidiurnal solar, the diurnal lunar.
struct TidalPeriod
{
    const char *name;
    double hours;
};
constexpr std::array<TidalPeriod, 4> kConstituents{
    {{"M2", 12.4206012}, {"K1", 23.9344697}, {"S2", 12.0}, {"O1", 25.8193417}}};

/// The constituents a record of @p spanHours resolves: each at least one period long, and each pair apart by the
/// Rayleigh criterion (span >= 1 / |f1 - f2|).
std::vector<TidalPeriod> resolvedConstituents(double spanHours)
{
    std::vector<TidalPeriod> out;
    if (!(spanHours > 24.0))
        return out; // a day or less: no tide is told from a bias or a trend
    for (const TidalPeriod &c : kConstituents)
    {
        bool apart = spanHours >= c.hours;
        for (const TidalPeriod &o : out)
            apart = apart && spanHours * std::abs(1.0 / c.hours - 1.0 / o.hours) >= 1.0;
        if (apart)
            out.push_back(c);
    }
    return out;
}

/// The restricted log marginal likelihood of the innovations (both components, one covariance) and the mean's
/// coefficients at given scales.
struct Likelihood
{
    const std::vector<DacObservation> *obs{nullptr}; // the fitted ones
    Eigen::MatrixXd G;                               // basis of the mean (columns), one row per fitted observation
    Eigen::MatrixXd D;                               // the innovations, u then v
    double floor2{0.0};                              // the smallest observation error variance allowed (field units^2)

    /// ln p(d | L, T, ratio) up to a constant, the forecast error variance at its maximum; @p beta: the mean's
    /// coefficients (p x 2). -infinity where the covariance cannot be factored.
    double operator()(double L, double T, double ratio, Eigen::MatrixXd *beta = nullptr) const
    {
        const std::size_t n = obs->size();
        const Eigen::Index p = G.cols();
        const double L2 = L * L, T2 = T * T;
        Eigen::MatrixXd K(n, n);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j <= i; ++j)
                K(i, j) = K(j, i) = correlation((*obs)[i], (*obs)[j], L2, T2);
        K.diagonal().array() += ratio * ratio;
        const Eigen::LLT<Eigen::MatrixXd> llt(K);
        if (llt.info() != Eigen::Success)
            return -std::numeric_limits<double>::infinity();
        double logDet = 0.0;
        for (Eigen::Index i = 0; i < K.rows(); ++i)
            logDet += 2.0 * std::log(llt.matrixL()(i, i));
        const Eigen::MatrixXd KiD = llt.solve(D);
        double q = (D.transpose() * KiD).trace();
        double logDetG = 0.0;
        Eigen::MatrixXd b = Eigen::MatrixXd::Zero(p, 2);
        if (p > 0)
        {
            const Eigen::MatrixXd KiG = llt.solve(G);
            const Eigen::MatrixXd A = G.transpose() * KiG;
            const Eigen::LLT<Eigen::MatrixXd> a(A);
            if (a.info() != Eigen::Success)
                return -std::numeric_limits<double>::infinity();
            for (Eigen::Index i = 0; i < p; ++i)
                logDetG += 2.0 * std::log(a.matrixL()(i, i));
            const Eigen::MatrixXd GtKiD = KiG.transpose() * D;
            b = a.solve(GtKiD);
            q -= (GtKiD.transpose() * b).trace();
        }
        if (beta)
            *beta = b;
        const double dof = static_cast<double>(static_cast<Eigen::Index>(n) - p);
        // the forecast error variance s_f^2 at its maximum (q / (2 dof)), the observation error s_o = ratio s_f
        // kept at or above the DAC's own error
        const double s2 = std::max({q / (2.0 * dof), floor2 / (ratio * ratio), 1e-300});
        return -dof * std::log(s2) - logDet - logDetG - std::max(q, 0.0) / (2.0 * s2);
    }
};

/// The box, span and long scales of the mean fitted to @p obs with scales L, T.
void meanExtent(const std::vector<DacObservation> &obs, double L, double T, InnovationMean &m)
{
    m.tBegin = obs.front().t;
    m.tEnd = obs.back().t;
    m.xMin = m.xMax = obs.front().at.x;
    m.yMin = m.yMax = obs.front().at.y;
    for (const DacObservation &o : obs)
    {
        m.xMin = std::min(m.xMin, o.at.x);
        m.xMax = std::max(m.xMax, o.at.x);
        m.yMin = std::min(m.yMin, o.at.y);
        m.yMax = std::max(m.yMax, o.at.y);
    }
    // the mean is a large-scale error: it fades over ten of the correction's own scales, never less than the data's
    // own extent
    m.lengthScale = std::max(10.0 * L, std::hypot(m.xMax - m.xMin, m.yMax - m.yMin));
    m.timeScale = std::max(10.0 * T, m.tEnd - m.tBegin);
}

/// The angular frequency of constituent @p c, in radians per time unit of @p secondsPerTimeUnit seconds.
double angularFrequency(const TidalPeriod &c, double secondsPerTimeUnit)
{
    return 2.0 * kPi * secondsPerTimeUnit / (c.hours * 3600.0);
}

/// The likelihood of the innovations @p du, @p dv of @p fitted (from index @p first on) under a mean of a bias and
/// the constituents @p tides (their phases from @p tRef).
Likelihood likelihoodOf(const std::vector<DacObservation> &fitted, const Eigen::VectorXd &du, const Eigen::VectorXd &dv,
                        std::size_t first, const std::vector<TidalPeriod> &tides, double tRef,
                        const CorrectionParams &p)
{
    const std::size_t m = fitted.size();
    Likelihood like;
    like.obs = &fitted;
    like.G.resize(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(1 + 2 * tides.size()));
    like.D.resize(static_cast<Eigen::Index>(m), 2);
    for (std::size_t i = 0; i < m; ++i)
    {
        const auto r = static_cast<Eigen::Index>(i);
        like.D(r, 0) = du[static_cast<Eigen::Index>(first + i)];
        like.D(r, 1) = dv[static_cast<Eigen::Index>(first + i)];
        like.G(r, 0) = 1.0;
        for (std::size_t k = 0; k < tides.size(); ++k)
        {
            const double w = angularFrequency(tides[k], p.secondsPerTimeUnit);
            like.G(r, static_cast<Eigen::Index>(1 + 2 * k)) = std::cos(w * (fitted[i].t - tRef));
            like.G(r, static_cast<Eigen::Index>(2 + 2 * k)) = std::sin(w * (fitted[i].t - tRef));
        }
    }
    like.floor2 = p.dacError * p.dacError;
    return like;
}

/// A free scale: where it is kept and its bounds.
struct Free
{
    double *value;
    double lo, hi;
};

/// The scales of @p p not given, each within bounds around its prior (a tenth to fifty times the length and time
/// scales; the error ratio from 0.02 to 5, wider to include its prior).
std::vector<Free> freeScales(CorrectionParams &p)
{
    std::vector<Free> free;
    if (!p.lengthGiven)
        free.push_back({&p.lengthScale, p.lengthScale / 10.0, p.lengthScale * 50.0});
    if (!p.timeGiven)
        free.push_back({&p.timeScale, p.timeScale / 10.0, p.timeScale * 50.0});
    if (!p.ratioGiven)
        free.push_back({&p.errorRatio, std::min(0.02, p.errorRatio), std::max(5.0, p.errorRatio)});
    return free;
}

using Objective = std::function<double(const std::vector<double> &)>;

/// The maximum of @p at over the logarithms of the @p free scales, from @p x (where it is @p best): a coarse grid
/// first (the likelihood has broad ridges and a local optimiser alone can stall on one), then a local search from
/// its best point. @p x becomes the best point found; returns the value there.
double maximise(const Objective &at, const std::vector<Free> &free, double best, std::vector<double> &x)
{
    std::vector<double> lo(free.size()), hi(free.size()), trial(free.size()), bestX = x;
    for (std::size_t k = 0; k < free.size(); ++k)
    {
        lo[k] = std::log(free[k].lo);
        hi[k] = std::log(free[k].hi);
    }
    constexpr int kGrid = 4;
    std::size_t cells = 1;
    for (std::size_t k = 0; k < free.size(); ++k)
        cells *= kGrid;
    for (std::size_t c = 0; c < cells; ++c)
    {
        std::size_t rest = c;
        for (std::size_t k = 0; k < free.size(); ++k, rest /= kGrid)
            trial[k] = lo[k] + (hi[k] - lo[k]) * static_cast<double>(rest % kGrid) / (kGrid - 1);
        const double v = at(trial);
        if (v > best)
        {
            best = v;
            bestX = trial;
        }
    }
    nlopt::opt opt(nlopt::LN_SBPLX, static_cast<unsigned>(free.size()));
    opt.set_lower_bounds(lo);
    opt.set_upper_bounds(hi);
    opt.set_xtol_rel(1e-4);
    opt.set_maxeval(300);
    Objective objective = at;
    opt.set_max_objective(
        [](const std::vector<double> &v, std::vector<double> &, void *data) {
            const double l = (*static_cast<Objective *>(data))(v);
            return std::isfinite(l) ? l : -1e300;
        },
        &objective);
    std::vector<double> y = bestX;
    double found = best;
    try
    {
        opt.optimize(y, found);
    }
    catch (const std::exception &)
    {
        // stopped by round-off or a failure: the best point it reached, if any, else the grid's
        found = at(y);
        if (!std::isfinite(found))
            found = -std::numeric_limits<double>::infinity();
    }
    x = found > best ? y : bestX;
    return std::max(found, best);
}
/// An estimate from some DAC: the scales (the free ones estimated, or the priors) and the innovations' mean at them.
struct Estimate
{
    CorrectionParams params;
    InnovationMean mean; // inactive: nothing factors
    double gain{0.0};    // ln likelihood at the scales minus at the priors
    bool finite{false};  // the likelihood factors at the scales
};

/// The estimate from @p fitted (their innovations @p du, @p dv from index @p first on) about the priors @p prior: with
/// @p scales the free ones are estimated (maximum a posteriori), else the priors kept; the mean (a bias and the tides
/// the record resolves) fitted at the scales.
Estimate estimate(const std::vector<DacObservation> &fitted, const Eigen::VectorXd &du, const Eigen::VectorXd &dv,
                  std::size_t first, const CorrectionParams &prior, bool scales)
{
    Estimate e;
    e.params = prior;
    CorrectionParams &p = e.params;
    const std::size_t m = fitted.size();
    InnovationMean mean;
    mean.tRef = fitted.back().t;
    const double spanHours = (fitted.back().t - fitted.front().t) * p.secondsPerTimeUnit / 3600.0;
    std::vector<TidalPeriod> tides =
        p.secondsPerTimeUnit > 0.0 ? resolvedConstituents(spanHours) : std::vector<TidalPeriod>{};
    while (!tides.empty() && m < 1 + 2 * tides.size() + 4)
        tides.pop_back(); // each constituent costs two coefficients: keep four degrees of freedom at least
    const Likelihood like = likelihoodOf(fitted, du, dv, first, tides, mean.tRef, p);
    const std::vector<Free> free = scales ? freeScales(p) : std::vector<Free>{};
    std::vector<double> x(free.size()), x0(free.size());
    for (std::size_t k = 0; k < free.size(); ++k)
        x[k] = x0[k] = std::log(*free[k].value);
    // the maximum a posteriori: the likelihood times a log-normal prior about each default (a factor of 3 one standard
    // deviation), so that a few DAC move the scales a little and many DAC as far as they say ([RasmussenGP] Sec. 5.2)
    const double spread = std::log(3.0);
    const auto at = [&](const std::vector<double> &v) {
        double penalty = 0.0;
        for (std::size_t k = 0; k < free.size(); ++k)
        {
            *free[k].value = std::exp(v[k]);
            penalty += 0.5 * std::pow((v[k] - x0[k]) / spread, 2);
        }
        return like(p.lengthScale, p.timeScale, p.errorRatio) - penalty;
    };
    const double prior0 = at(x), priorLikelihood = like(p.lengthScale, p.timeScale, p.errorRatio);
    double best = prior0;
    if (!free.empty())
        best = maximise(at, free, best, x);
    if (!std::isfinite(best))
        x = x0; // the priors
    for (std::size_t k = 0; k < free.size(); ++k)
        *free[k].value = std::exp(x[k]);
    Eigen::MatrixXd beta;
    const double final = like(p.lengthScale, p.timeScale, p.errorRatio, &beta);
    if (!std::isfinite(final))
        return e; // nothing factors: no mean
    e.finite = true;
    e.gain = std::isfinite(priorLikelihood) ? final - priorLikelihood : 0.0;
    mean.bias = {beta(0, 0), beta(0, 1)};
    for (std::size_t k = 0; k < tides.size(); ++k)
    {
        InnovationMean::Constituent c;
        c.name = tides[k].name;
        c.omega = angularFrequency(tides[k], p.secondsPerTimeUnit);
        const auto r = static_cast<Eigen::Index>(1 + 2 * k);
        c.cosine = {beta(r, 0), beta(r, 1)};
        c.sine = {beta(r + 1, 0), beta(r + 1, 1)};
        mean.tides.push_back(c);
    }
    meanExtent(fitted, p.lengthScale, p.timeScale, mean);
    e.mean = mean;
    return e;
}

/// The RMS error of the prediction of the DAC @p obs[k..] from @p obs[0..k) alone (their innovations @p du, @p dv
/// from index @p first on) by the correction of scales @p p and mean @p mean (inactive: none), as CorrectedField
/// makes it: the mean plus the optimal interpolation of the earlier innovations less the mean. Infinity where the
/// system cannot be solved.
double heldOutError(const std::vector<DacObservation> &obs, const Eigen::VectorXd &du, const Eigen::VectorXd &dv,
                    std::size_t first, std::size_t k, const CorrectionParams &p, const InnovationMean &mean)
{
    const auto e = static_cast<Eigen::Index>(k);
    const double L2 = p.lengthScale * p.lengthScale, T2 = p.timeScale * p.timeScale;
    Eigen::MatrixXd K(e, e);
    Eigen::MatrixXd R(e, 2);
    for (std::size_t i = 0; i < k; ++i)
    {
        for (std::size_t j = 0; j <= i; ++j)
            K(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                K(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = correlation(obs[i], obs[j], L2, T2);
        const Velocity m = mean.at(obs[i].at.x, obs[i].at.y, obs[i].t);
        R(static_cast<Eigen::Index>(i), 0) = du[static_cast<Eigen::Index>(first + i)] - m.u;
        R(static_cast<Eigen::Index>(i), 1) = dv[static_cast<Eigen::Index>(first + i)] - m.v;
    }
    // (the nugget of CorrectedField's system)
    K.diagonal().array() += std::max(p.errorRatio * p.errorRatio, 1e-6);
    const Eigen::LDLT<Eigen::MatrixXd> solver(K);
    if (solver.info() != Eigen::Success)
        return std::numeric_limits<double>::infinity();
    const Eigen::MatrixXd alpha = solver.solve(R);
    double squares = 0.0;
    for (std::size_t j = k; j < obs.size(); ++j)
    {
        Velocity c = mean.at(obs[j].at.x, obs[j].at.y, obs[j].t);
        for (std::size_t i = 0; i < k; ++i)
        {
            const double w = correlation(obs[j], obs[i], L2, T2);
            c.u += w * alpha(static_cast<Eigen::Index>(i), 0);
            c.v += w * alpha(static_cast<Eigen::Index>(i), 1);
        }
        squares += std::pow(du[static_cast<Eigen::Index>(first + j)] - c.u, 2) +
                   std::pow(dv[static_cast<Eigen::Index>(first + j)] - c.v, 2);
    }
    const double rms = std::sqrt(squares / static_cast<double>(obs.size() - k));
    return std::isfinite(rms) ? rms : std::numeric_limits<double>::infinity();
}
} // namespace

void learn(const std::vector<DacObservation> &used, const Eigen::VectorXd &du, const Eigen::VectorXd &dv,
           CorrectionSummary &summary)
{
    const CorrectionParams prior = summary.params;
    const std::size_t n = used.size(), m = std::min(n, kMaxFitted), first = n - m;
    const std::vector<DacObservation> fitted(used.begin() + static_cast<std::ptrdiff_t>(first), used.end());
    const Estimate full = estimate(fitted, du, dv, first, prior, true);
    if (!full.finite)
        return; // nothing factors: the priors, no mean
    summary.learnedFrom = m;
    summary.likelihoodGain = full.gain;
    const bool free = !prior.lengthGiven || !prior.timeGiven || !prior.ratioGiven;
    const std::string estimated = "estimated from " + std::to_string(m) + " DAC";
    // the estimate judged on DAC not used to fit it: fitted on the earlier half (at least minLearn), it predicts the
    // later ones from the earlier alone (forward in time, as the planner uses it), against the priors
    HeldOutCheck &h = summary.heldOut;
    const std::size_t k = std::max(prior.minLearn, (m + 1) / 2);
    std::string why = "too few DAC to judge the estimate from " + std::to_string(m);
    if (k < m)
    {
        const std::vector<DacObservation> earlier(fitted.begin(), fitted.begin() + static_cast<std::ptrdiff_t>(k));
        const Estimate meanOnly = estimate(earlier, du, dv, first, prior, false);
        // (every scale given, as a flight holds its last estimate: only the mean is learned)
        const Estimate learned = free ? estimate(earlier, du, dv, first, prior, true) : meanOnly;
        const InnovationMean none;
        h.fitted = k;
        h.scored = m - k;
        h.lengthScale = learned.params.lengthScale;
        h.timeScale = learned.params.timeScale;
        h.errorRatio = learned.params.errorRatio;
        const double inf = std::numeric_limits<double>::infinity();
        h.priorError = heldOutError(fitted, du, dv, first, k, prior, none);
        h.meanError = meanOnly.finite ? heldOutError(fitted, du, dv, first, k, prior, meanOnly.mean) : inf;
        h.scalesError = learned.finite && free ? heldOutError(fitted, du, dv, first, k, learned.params, none) : inf;
        h.learnedError = !free            ? h.meanError
                         : learned.finite ? heldOutError(fitted, du, dv, first, k, learned.params, learned.mean)
                                          : inf;
        // the best prediction wins, the priors on a tie (then the fewer learned)
        double best = h.priorError;
        for (const auto &[error, scales, mean] :
             {std::make_tuple(h.meanError, false, true), std::make_tuple(h.scalesError, true, false),
              std::make_tuple(h.learnedError, free, true)})
            if (error < best)
            {
                best = error;
                h.scalesKept = scales;
                h.meanKept = mean;
            }
        why = "the scales estimated from the first " + std::to_string(k) + " DAC predicted the next " +
              std::to_string(m - k) + " no better";
    }
    std::string *sources[] = {&summary.lengthSource, &summary.timeSource, &summary.ratioSource};
    const bool given[] = {prior.lengthGiven, prior.timeGiven, prior.ratioGiven};
    for (std::size_t s = 0; s < 3; ++s)
        if (!given[s])
            *sources[s] = h.scalesKept                          ? estimated
                          : s < 2 && !prior.priorSource.empty() ? prior.priorSource + " (" + why + ")"
                                                                : "default (" + why + ")";
    if (h.scalesKept)
    {
        summary.params = full.params;
        if (h.meanKept)
            summary.mean = full.mean;
    }
    else if (h.meanKept)
    {
        const Estimate atPriors = estimate(fitted, du, dv, first, prior, false);
        if (atPriors.finite)
            summary.mean = atPriors.mean;
    }
}
} // namespace ompl_glider::correction_fit

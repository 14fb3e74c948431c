/// @file EnsembleLearning.cpp
/// @brief Members weighed and updated by a glider's DAC, what is left interpolated (EnsembleLearning.h).

#include "ompl_glider/current/EnsembleLearning.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "ompl_glider/current/EnsembleField.h"

namespace ompl_glider
{
namespace
{
/// The DAC every member can be compared with: finite, within every member's time, in water; the most recent
/// kMaxWeighing of them.
std::vector<DacObservation> comparable(const std::vector<std::shared_ptr<const CurrentField>> &members,
                                       const std::vector<DacObservation> &observations, double depth)
{
    double begin = -std::numeric_limits<double>::infinity(), end = std::numeric_limits<double>::infinity();
    for (const auto &m : members)
    {
        begin = std::max(begin, m->timeBegin());
        end = std::min(end, m->timeEnd());
    }
    std::vector<DacObservation> out;
    for (const DacObservation &o : observations)
    {
        const bool finite = std::isfinite(o.t) && std::isfinite(o.at.x) && std::isfinite(o.at.y) &&
                            std::isfinite(o.dac.u) && std::isfinite(o.dac.v);
        if (finite && o.t >= begin && o.t <= end && std::all_of(members.begin(), members.end(), [&](const auto &m) {
                return m->inWater(o.at.x, o.at.y, depth);
            }))
            out.push_back({o.t, o.at, o.dac, std::nullopt, o.depthTop,
                           o.depthBottom}); // the forecast along the dive is not the members'
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const DacObservation &a, const DacObservation &b) { return a.t < b.t; });
    if (out.size() > kMaxWeighing)
        out.erase(out.begin(), out.end() - static_cast<std::ptrdiff_t>(kMaxWeighing));
    return out;
}
} // namespace

LearnedForecast learnForecast(const std::shared_ptr<const CurrentField> &forecast,
                              const std::vector<std::shared_ptr<const CurrentField>> &members,
                              const std::vector<DacObservation> &observations, const CorrectionParams &params)
{
    LearnedForecast out;
    const std::size_t M = members.size();
    const std::vector<DacObservation> obs =
        M >= 2 ? comparable(members, observations, params.depthTop) : std::vector<DacObservation>{};
    if (obs.empty())
    {
        auto c = std::make_shared<CorrectedField>(forecast, observations, params);
        out.correction = c->summary();
        out.field = c;
        for (std::size_t m = 0; m < M; ++m)
            out.members.push_back({1.0 / M, 0.0, 1.0 / M});
        return out;
    }
    const std::size_t n = obs.size();
    // each member's depth-averaged current at each DAC: H (2n x M), u then v
    Eigen::MatrixXd H(2 * n, M);
    Eigen::VectorXd d(2 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
        d[static_cast<Eigen::Index>(i)] = obs[i].dac.u;
        d[static_cast<Eigen::Index>(n + i)] = obs[i].dac.v;
        for (std::size_t m = 0; m < M; ++m)
        {
            const Velocity h = forecastAtDac(*members[m], obs[i], params); // (obs: no forecast of their own)
            H(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(m)) = h.u;
            H(static_cast<Eigen::Index>(n + i), static_cast<Eigen::Index>(m)) = h.v;
        }
    }
    const Eigen::VectorXd mean = H.rowwise().mean();
    const Eigen::MatrixXd anomalies = H.colwise() - mean;
    // the likelihood of each member: innovations against the DAC's error plus the members' spread there
    const double so2 = std::max(params.dacError * params.dacError, 1e-12);
    const Eigen::VectorXd spread2 = anomalies.rowwise().squaredNorm() / static_cast<double>(M - 1);
    std::vector<double> logLike(M);
    out.members.resize(M);
    for (std::size_t m = 0; m < M; ++m)
    {
        const Eigen::VectorXd e = d - H.col(static_cast<Eigen::Index>(m));
        logLike[m] = -0.5 * (e.array().square() / (so2 + spread2.array())).sum();
        out.members[m].rmsInnovation = std::sqrt(e.squaredNorm() / static_cast<double>(n));
    }
    const double top = *std::max_element(logLike.begin(), logLike.end());
    double total = 0.0;
    for (std::size_t m = 0; m < M; ++m)
        total += std::exp(logLike[m] - top);
    Eigen::VectorXd w(M);
    for (std::size_t m = 0; m < M; ++m)
    {
        w[static_cast<Eigen::Index>(m)] = std::exp(logLike[m] - top) / total;
        out.members[m].weight = w[static_cast<Eigen::Index>(m)];
    }
    // the update of the weighted mean from the members' anomalies, in the members' space: with S = R^-1/2 Y
    // (Y: the anomalies / sqrt(M - 1)) and the innovation of the weighted mean delta, gamma = (I + S'S)^-1 S' R^-1/2
    // delta, and the forecast sum_m c_m (w_m + (gamma_m - mean gamma) / sqrt(M - 1))
    const double root = std::sqrt(static_cast<double>(M - 1));
    const Eigen::MatrixXd S = anomalies / (root * std::sqrt(so2));
    const Eigen::VectorXd delta = (d - H * w) / std::sqrt(so2);
    const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(M, M) + S.transpose() * S;
    const Eigen::VectorXd gamma = A.ldlt().solve(S.transpose() * delta);
    std::vector<double> a(M);
    for (std::size_t m = 0; m < M; ++m)
    {
        a[m] = w[static_cast<Eigen::Index>(m)] + (gamma[static_cast<Eigen::Index>(m)] - gamma.mean()) / root;
        out.members[m].coefficient = a[m];
    }
    out.weighedBy = n;
    const auto combined = std::make_shared<EnsembleMeanField>(members, a);
    // what is left, interpolated about the glider's track
    std::vector<DacObservation> rest = observations;
    for (DacObservation &o : rest)
        o.forecast.reset();
    auto corrected = std::make_shared<CorrectedField>(combined, rest, params);
    out.correction = corrected->summary();
    out.field = corrected;
    return out;
}

FlightLearning::FlightLearning(std::shared_ptr<const CurrentField> forecast,
                               std::vector<std::shared_ptr<const CurrentField>> members, CorrectionParams params)
    : forecast_(std::move(forecast)), members_(std::move(members)), params_(params)
{
}

std::shared_ptr<const CurrentField> FlightLearning::operator()(const std::vector<DacObservation> &measured)
{
    CorrectionParams p = params_;
    const bool hold = estimatedAt_ > 0 && 2 * measured.size() < 3 * estimatedAt_;
    if (hold)
    {
        // the last estimate held as given until the DAC have grown by half
        p.lengthScale = estimated_.lengthScale;
        p.timeScale = estimated_.timeScale;
        p.errorRatio = estimated_.errorRatio;
        p.lengthGiven = p.timeGiven = p.ratioGiven = true;
    }
    last_ = learnForecast(forecast_, members_, measured, p);
    const bool free = !params_.lengthGiven || !params_.timeGiven || !params_.ratioGiven;
    if (!hold && free && last_.correction.learnedFrom > 0)
    {
        estimated_ = last_.correction.params;
        estimatedAt_ = measured.size();
    }
    return last_.field;
}
} // namespace ompl_glider

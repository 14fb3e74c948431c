/// @file CorrectedField.cpp
/// @brief Optimal interpolation of a glider's depth-averaged currents onto a forecast (CorrectedField.h).

#include "ompl_glider/current/CorrectedField.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <Eigen/Dense>

#include "ompl_glider/Exception.h"
#include "CorrectionFit.h"
#include "CorrectionKernel.h"
#include "ompl_glider/current/GriddedCurrentField.h"

namespace ompl_glider
{
double InnovationMean::Constituent::amplitude(bool u) const
{
    return u ? std::hypot(cosine.u, sine.u) : std::hypot(cosine.v, sine.v);
}

double InnovationMean::Constituent::phase(bool u) const
{
    return u ? std::atan2(sine.u, cosine.u) : std::atan2(sine.v, cosine.v);
}

Velocity InnovationMean::at(double x, double y, double t, Jacobian *j) const
{
    if (!active())
        return {};
    Velocity m = bias;
    for (const Constituent &c : tides)
    {
        const double co = std::cos(c.omega * (t - tRef)), si = std::sin(c.omega * (t - tRef));
        m.u += c.cosine.u * co + c.sine.u * si;
        m.v += c.cosine.v * co + c.sine.v * si;
    }
    // outside the data's box and span the mean fades with its long scales
    const double dx = x < xMin ? x - xMin : x > xMax ? x - xMax : 0.0;
    const double dy = y < yMin ? y - yMin : y > yMax ? y - yMax : 0.0;
    const double dt = t < tBegin ? tBegin - t : t > tEnd ? t - tEnd : 0.0;
    const double L2 = lengthScale * lengthScale, T2 = timeScale * timeScale;
    const double fade = correctionKernel(dx * dx + dy * dy, dt, L2, T2);
    if (j)
    {
        j->ux -= m.u * fade * dx / L2;
        j->uy -= m.u * fade * dy / L2;
        j->vx -= m.v * fade * dx / L2;
        j->vy -= m.v * fade * dy / L2;
    }
    return {m.u * fade, m.v * fade};
}

void InnovationMean::bound(double &u, double &v) const
{
    u = v = 0.0;
    if (!active())
        return;
    u = std::abs(bias.u);
    v = std::abs(bias.v);
    for (const Constituent &c : tides)
    {
        u += c.amplitude(true);
        v += c.amplitude(false);
    }
}

namespace
{
std::string sourceOf(bool given, bool learn, const std::string &prior)
{
    const std::string name = prior.empty() ? "default" : prior;
    return given ? "given" : learn ? name + " (too few DAC to estimate)" : name;
}

/// The innovations' RMS (of their sum of squares @p squares) and mean, and the span of the DAC used, for the words of
/// the report (CorrectionSummary).
void noteInnovations(CorrectionSummary &s, const std::vector<DacObservation> &used, const Eigen::VectorXd &du,
                     const Eigen::VectorXd &dv, double squares)
{
    s.rmsBefore = std::sqrt(squares / static_cast<double>(used.size()));
    s.meanInnovation = {du.mean(), dv.mean()};
    s.firstUsed = used.front().t;
    s.lastUsed = used.back().t;
}

/// The observations the correction uses: finite, within the forecast's span, box and water, by time, and the most
/// recent CorrectionParams::maxObservations of them; @p s counts those given and those left out.
std::vector<DacObservation> usableDac(const CurrentField &base, const std::vector<DacObservation> &observations,
                                      const CorrectionParams &params, CorrectionSummary &s)
{
    s.given = observations.size();
    std::vector<DacObservation> kept;
    const FieldGrid *grid = base.grid();
    for (const DacObservation &o : observations)
    {
        if (!std::isfinite(o.t) || !std::isfinite(o.at.x) || !std::isfinite(o.at.y) || !std::isfinite(o.dac.u) ||
            !std::isfinite(o.dac.v))
            ++s.notFinite;
        else if (o.t < base.timeBegin() || o.t > base.timeEnd() || (grid && !grid->covers(o.at.x, o.at.y)) ||
                 !base.inWater(o.at.x, o.at.y, params.depthTop))
            ++s.outsideForecast;
        else
            kept.push_back(o);
    }
    std::stable_sort(kept.begin(), kept.end(),
                     [](const DacObservation &a, const DacObservation &b) { return a.t < b.t; });
    if (kept.size() > params.maxObservations)
    {
        s.older = kept.size() - params.maxObservations;
        kept.erase(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(s.older));
    }
    return kept;
}

/// The innovations of @p used (each DAC less the depth-averaged forecast) into @p du and @p dv; returns their sum of
/// squares.
double innovationsOf(const CurrentField &base, const std::vector<DacObservation> &used, const CorrectionParams &params,
                     Eigen::VectorXd &du, Eigen::VectorXd &dv)
{
    double squares = 0.0;
    for (std::size_t i = 0; i < used.size(); ++i)
    {
        const Velocity f = forecastAtDac(base, used[i], params);
        du[i] = used[i].dac.u - f.u;
        dv[i] = used[i].dac.v - f.v;
        // a DAC equal to the forecast but for the rounding of its numbers (a float file, a CSV): no innovation
        const double noise = 1e-12 * std::max({1.0, std::abs(f.u), std::abs(f.v)});
        if (std::abs(du[i]) < noise)
            du[i] = 0.0;
        if (std::abs(dv[i]) < noise)
            dv[i] = 0.0;
        squares += du[i] * du[i] + dv[i] * dv[i];
    }
    return squares;
}

/// A superobservation: the DAC of one cell averaged (their mean time, place and innovation) and their number.
struct DacCell
{
    double t;
    Point2 at;
    double u, v, count;
};

/// The superobservations of @p used: DAC within a cell of @p cellL by @p cellT of each other (an eighth of the
/// scales: correlated above 0.98) are averaged into one whose error variance is divided by their number; many nearly
/// equal rows would leave the system ill-conditioned and cost each evaluation of the field a term per DAC. By time.
std::vector<DacCell> superobservations(const std::vector<DacObservation> &used, const Eigen::VectorXd &du,
                                       const Eigen::VectorXd &dv, double cellL, double cellT)
{
    std::map<std::tuple<long long, long long, long long>, std::size_t> index;
    std::vector<DacCell> cells;
    for (std::size_t i = 0; i < used.size(); ++i)
    {
        // (the cell's index kept within what a long long holds, whatever the scale's size)
        const auto cell = [](double v, double size) {
            return static_cast<long long>(std::clamp(std::floor(v / size), -1e18, 1e18));
        };
        const auto key = std::make_tuple(cell(used[i].at.x, cellL), cell(used[i].at.y, cellL), cell(used[i].t, cellT));
        const auto [it, added] = index.emplace(key, cells.size());
        if (added)
            cells.push_back({0.0, {0.0, 0.0}, 0.0, 0.0, 0.0});
        DacCell &c = cells[it->second];
        c.t += used[i].t;
        c.at.x += used[i].at.x;
        c.at.y += used[i].at.y;
        c.u += du[i];
        c.v += dv[i];
        c.count += 1.0;
    }
    for (DacCell &c : cells)
    {
        c.t /= c.count;
        c.at.x /= c.count;
        c.at.y /= c.count;
    }
    std::stable_sort(cells.begin(), cells.end(), [](const DacCell &a, const DacCell &b) { return a.t < b.t; });
    for (DacCell &c : cells)
    {
        c.u /= c.count;
        c.v /= c.count;
    }
    return cells;
}

/// The covariance of the superobservations @p cells at scales @p L and @p T, their error variances @p noise on its
/// diagonal.
Eigen::MatrixXd cellCovariance(const std::vector<DacCell> &cells, const Eigen::VectorXd &noise, double L, double T)
{
    const std::size_t m = cells.size();
    const double L2 = L * L, T2 = T * T;
    Eigen::MatrixXd C(m, m);
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j)
        {
            const double dx = cells[i].at.x - cells[j].at.x, dy = cells[i].at.y - cells[j].at.y;
            C(i, j) = correctionKernel(dx * dx + dy * dy, cells[i].t - cells[j].t, L2, T2);
        }
    C.diagonal() += noise;
    return C;
}
} // namespace

CorrectedField::CorrectedField(std::shared_ptr<const CurrentField> base,
                               const std::vector<DacObservation> &observations, CorrectionParams params)
    : base_(std::move(base)), params_(params)
{
    if (!base_)
        throw Error("CorrectedField: no forecast");
    for (const double v : {params_.lengthScale, params_.timeScale, params_.errorRatio})
        if (!(v > 0.0) || !std::isfinite(v))
            throw Error("CorrectedField: the length scale, time scale and error ratio must be finite and > 0");
    summary_.params = params_;
    summary_.lengthSource = sourceOf(params_.lengthGiven, params_.learn, params_.priorSource);
    summary_.timeSource = sourceOf(params_.timeGiven, params_.learn, params_.priorSource);
    summary_.ratioSource = sourceOf(params_.ratioGiven, params_.learn, std::string());
    used_ = usableDac(*base_, observations, params_, summary_);
    summary_.used = used_.size();
    const std::size_t n = used_.size();
    if (n == 0)
        return;
    // innovations against the depth-averaged forecast, and the covariance of the observations
    Eigen::VectorXd du(n), dv(n);
    const double before = innovationsOf(*base_, used_, params_, du, dv);
    noteInnovations(summary_, used_, du, dv, before);
    if (params_.learn && n >= params_.minLearn && before > 0.0)
    {
        // learn the scales not given, and the innovations' mean; the interpolation spreads what is left
        correction_fit::learn(used_, du, dv, summary_);
        params_ = summary_.params;
        for (std::size_t i = 0; i < n; ++i)
        {
            const Velocity m = summary_.mean.at(used_[i].at.x, used_[i].at.y, used_[i].t);
            du[i] -= m.u;
            dv[i] -= m.v;
        }
    }
    const std::vector<DacCell> cells =
        superobservations(used_, du, dv, params_.lengthScale / 8.0, params_.timeScale / 8.0);
    const std::size_t m = cells.size();
    Eigen::VectorXd nu(m), nv(m), noise(m);
    for (std::size_t k = 0; k < m; ++k)
    {
        const auto e = static_cast<Eigen::Index>(k);
        nodes_.push_back({cells[k].t, cells[k].at});
        nu[e] = cells[k].u;
        nv[e] = cells[k].v;
        // a nugget of 1e-6 of the forecast error's variance keeps the system solvable for a tiny error ratio (below
        // 1e-3) and superobservations that nearly coincide
        noise[e] = std::max(params_.errorRatio * params_.errorRatio / cells[k].count, 1e-6);
        uLow_ = std::min(uLow_, nu[e]);
        uHigh_ = std::max(uHigh_, nu[e]);
        vLow_ = std::min(vLow_, nv[e]);
        vHigh_ = std::max(vHigh_, nv[e]);
    }
    const Eigen::MatrixXd C = cellCovariance(cells, noise, params_.lengthScale, params_.timeScale);
    const Eigen::LDLT<Eigen::MatrixXd> solver(C);
    const Eigen::VectorXd au = solver.solve(nu), av = solver.solve(nv);
    alphaU_.assign(au.data(), au.data() + m);
    alphaV_.assign(av.data(), av.data() + m);
    double after = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        Velocity c = forecastAtDac(
            *base_, DacObservation{used_[i].t, used_[i].at, {}, std::nullopt, used_[i].depthTop, used_[i].depthBottom},
            params_);
        addCorrection(used_[i].at.x, used_[i].at.y, used_[i].t, c, nullptr, true);
        after += std::pow(used_[i].dac.u - c.u, 2) + std::pow(used_[i].dac.v - c.v, 2);
    }
    summary_.rmsAfter = std::sqrt(after / n);
}

void CorrectedField::sample() const
{
    const std::size_t m = nodes_.size();
    if (m <= params_.sampleAbove)
        return;
    const double L = params_.lengthScale, T = params_.timeScale;
    const double reach = kCutoff * L, window = kCutoff * T;
    double x0 = nodes_[0].at.x, x1 = x0, y0 = nodes_[0].at.y, y1 = y0;
    for (const Node &n : nodes_)
    {
        x0 = std::min(x0, n.at.x);
        x1 = std::max(x1, n.at.x);
        y0 = std::min(y0, n.at.y);
        y1 = std::max(y1, n.at.y);
    }
    x0 -= reach;
    x1 += reach;
    y0 -= reach;
    y1 += reach;
    const double t0 = nodes_.front().t - window, t1 = nodes_.back().t + window;
    // a quarter of the scales: the Gaussian sum's bicubic error is below 0.1 % of its amplitude, linear in time 1 %
    const auto count = [](double span, double step) { return static_cast<std::size_t>(std::ceil(span / step)) + 1; };
    const std::size_t nx = count(x1 - x0, L / 4.0), ny = count(y1 - y0, L / 4.0), nt = count(t1 - t0, T / 4.0);
    if (static_cast<double>(nx) * static_cast<double>(ny) * static_cast<double>(nt) > 4e6)
        return; // a correction spread too wide for a grid: the exact sum
    // each time slice sums the superobservations within the cut-off of it (the nodes are in time order): the work is
    // the grid's nodes times those, bounded so that sampling never costs more than about a second
    const auto reachOf = [&](double t) {
        const auto lo =
            std::lower_bound(nodes_.begin(), nodes_.end(), t - window, [](const Node &o, double v) { return o.t < v; });
        const auto hi =
            std::upper_bound(nodes_.begin(), nodes_.end(), t + window, [](double v, const Node &o) { return v < o.t; });
        return std::make_pair(static_cast<Eigen::Index>(lo - nodes_.begin()), static_cast<Eigen::Index>(hi - lo));
    };
    double work = 0.0;
    for (std::size_t it = 0; it < nt; ++it)
    {
        const double t = t0 + (t1 - t0) * static_cast<double>(it) / static_cast<double>(nt - 1); // as d.time below
        work += static_cast<double>(nx * ny) * static_cast<double>(reachOf(t).second);
    }
    if (work > 2e9)
        return; // the exact sum
    GriddedData d;
    d.nx = nx;
    d.ny = ny;
    const auto axis = [](double from, double to, std::size_t n) {
        std::vector<double> a(n);
        for (std::size_t i = 0; i < n; ++i)
            a[i] = from + (to - from) * static_cast<double>(i) / static_cast<double>(n - 1);
        return a;
    };
    d.x = axis(x0, x1, nx);
    d.y = axis(y0, y1, ny);
    d.time = axis(t0, t1, nt);
    d.u.resize(nx * ny * nt);
    d.v.resize(nx * ny * nt);
    // the Gaussian is separable: at each time the grid is X diag(alpha w_t) Y^T, X and Y the spatial weights of the
    // nodes (each cut off past kCutoff scales, as the exact sum)
    const Eigen::Index M = static_cast<Eigen::Index>(m);
    Eigen::MatrixXd X(static_cast<Eigen::Index>(nx), M), Y(static_cast<Eigen::Index>(ny), M);
    for (Eigen::Index k = 0; k < M; ++k)
    {
        const Node &n = nodes_[static_cast<std::size_t>(k)];
        for (std::size_t i = 0; i < nx; ++i)
            X(static_cast<Eigen::Index>(i), k) =
                std::abs(d.x[i] - n.at.x) > reach ? 0.0 : correctionKernelFactor(std::pow(d.x[i] - n.at.x, 2), L * L);
        for (std::size_t j = 0; j < ny; ++j)
            Y(static_cast<Eigen::Index>(j), k) =
                std::abs(d.y[j] - n.at.y) > reach ? 0.0 : correctionKernelFactor(std::pow(d.y[j] - n.at.y, 2), L * L);
    }
    for (std::size_t it = 0; it < nt; ++it)
    {
        const auto [first, count] = reachOf(d.time[it]);
        Eigen::VectorXd wu(count), wv(count);
        for (Eigen::Index k = 0; k < count; ++k)
        {
            const std::size_t n = static_cast<std::size_t>(first + k);
            const double dt = d.time[it] - nodes_[n].t;
            const double w = correctionKernelFactor(dt * dt, T * T);
            wu[k] = w * alphaU_[n];
            wv[k] = w * alphaV_[n];
        }
        const auto Xs = X.middleCols(first, count), Ys = Y.middleCols(first, count);
        const Eigen::MatrixXd gu = Xs * wu.asDiagonal() * Ys.transpose(), gv = Xs * wv.asDiagonal() * Ys.transpose();
        for (std::size_t j = 0; j < ny; ++j)
            for (std::size_t i = 0; i < nx; ++i)
            {
                const std::size_t at = (it * ny + j) * nx + i;
                const auto ei = static_cast<Eigen::Index>(i), ej = static_cast<Eigen::Index>(j);
                d.u[at] = static_cast<float>(std::clamp(gu(ei, ej), uLow_, uHigh_));
                d.v[at] = static_cast<float>(std::clamp(gv(ei, ej), vLow_, vHigh_));
            }
    }
    GriddedFieldOptions o;
    o.xy = Interp2D::Bicubic;
    o.time = Interp1D::Linear;
    o.beyond = BeyondForecast::HoldLast;
    o.name = "correction";
    sampled_ = std::make_shared<const GriddedCurrentField>(std::move(d), o);
    sampleXMin_ = x0;
    sampleXMax_ = x1;
    sampleYMin_ = y0;
    sampleYMax_ = y1;
    sampleTMin_ = t0;
    sampleTMax_ = t1;
}

Velocity depthAveragedCurrent(const CurrentField &field, double x, double y, double t, double top, double bottom)
{
    bottom = std::max(top, bottom);
    if (!(bottom > top))
        return field.velocity(x, y, top, t);
    // the trapezoidal rule over 8 intervals of the depth range
    constexpr int kIntervals = 8;
    Velocity sum;
    for (int k = 0; k <= kIntervals; ++k)
    {
        const double w = (k == 0 || k == kIntervals) ? 0.5 : 1.0;
        const Velocity c = field.velocity(x, y, top + (bottom - top) * k / kIntervals, t);
        sum.u += w * c.u;
        sum.v += w * c.v;
    }
    return {sum.u / kIntervals, sum.v / kIntervals};
}

Velocity forecastAtDac(const CurrentField &field, const DacObservation &o, const CorrectionParams &params)
{
    if (o.forecast)
        return *o.forecast;
    const bool own = std::isfinite(o.depthTop) && std::isfinite(o.depthBottom);
    return depthAveragedCurrent(field, o.at.x, o.at.y, o.t, own ? o.depthTop : params.depthTop,
                                own ? o.depthBottom : params.depthBottom);
}

Velocity CorrectedField::depthAveraged(double x, double y, double t) const
{
    return depthAveragedCurrent(*base_, x, y, t, params_.depthTop, params_.depthBottom);
}

const GriddedCurrentField *CorrectedField::sampledGrid() const
{
    std::call_once(sampleOnce_, [this] { sample(); });
    return sampled_.get();
}

void CorrectedField::addCorrection(double x, double y, double t, Velocity &c, Jacobian *j, bool exact) const
{
    if (used_.empty())
        return;
    if (summary_.mean.active())
    {
        const Velocity m = summary_.mean.at(x, y, t, j);
        c.u += m.u;
        c.v += m.v;
    }
    const double L2 = params_.lengthScale * params_.lengthScale, T2 = params_.timeScale * params_.timeScale;
    const double window = kCutoff * params_.timeScale, reach2 = kCutoff * kCutoff * L2;
    Velocity g;  // the interpolated part
    Jacobian dg; // and its derivatives
    // sampled: read from the grid, zero outside it (past the cut-off of every superobservation)
    const GriddedCurrentField *sampled = exact ? nullptr : sampledGrid();
    const bool inSample = sampled && x >= sampleXMin_ && x <= sampleXMax_ && y >= sampleYMin_ && y <= sampleYMax_ &&
                          t >= sampleTMin_ && t <= sampleTMax_;
    if (inSample)
    {
        g = sampled->velocity(x, y, 0.0, t);
        if (j)
            dg = sampled->jacobian(x, y, 0.0, t);
    }
    auto first = sampled ? nodes_.end()
                         : std::lower_bound(nodes_.begin(), nodes_.end(), t - window,
                                            [](const Node &o, double v) { return o.t < v; });
    for (auto it = first; it != nodes_.end() && it->t <= t + window; ++it)
    {
        const double dx = x - it->at.x, dy = y - it->at.y, r2 = dx * dx + dy * dy;
        if (r2 > reach2)
            continue;
        const double dt = t - it->t;
        const double w = correctionKernel(r2, dt, L2, T2);
        const std::size_t i = static_cast<std::size_t>(it - nodes_.begin());
        g.u += w * alphaU_[i];
        g.v += w * alphaV_[i];
        // d w / dx = -w dx / L^2
        dg.ux -= w * alphaU_[i] * dx / L2;
        dg.uy -= w * alphaU_[i] * dy / L2;
        dg.vx -= w * alphaV_[i] * dx / L2;
        dg.vy -= w * alphaV_[i] * dy / L2;
    }
    // never beyond what the data support: where the sum leaves the innovations' range it is held at its edge (and
    // does not vary there)
    const bool uHeld = g.u < uLow_ || g.u > uHigh_, vHeld = g.v < vLow_ || g.v > vHigh_;
    c.u += std::clamp(g.u, uLow_, uHigh_);
    c.v += std::clamp(g.v, vLow_, vHigh_);
    if (j)
    {
        j->ux += uHeld ? 0.0 : dg.ux;
        j->uy += uHeld ? 0.0 : dg.uy;
        j->vx += vHeld ? 0.0 : dg.vx;
        j->vy += vHeld ? 0.0 : dg.vy;
    }
}

Velocity CorrectedField::correction(double x, double y, double t) const
{
    Velocity c;
    addCorrection(x, y, t, c, nullptr);
    return c;
}

Velocity CorrectedField::velocityOnce(double x, double y, double z, double t) const
{
    Velocity c = base_->velocity(x, y, z, t);
    addCorrection(x, y, t, c, nullptr, true);
    return c;
}

Velocity CorrectedField::evaluate(double x, double y, double z, double t) const
{
    Velocity c = base_->velocity(x, y, z, t);
    addCorrection(x, y, t, c, nullptr);
    return c;
}

Jacobian CorrectedField::evaluateJacobian(double x, double y, double z, double t) const
{
    Jacobian j = base_->jacobian(x, y, z, t);
    Velocity unused;
    addCorrection(x, y, t, unused, &j);
    return j;
}

void CorrectedField::reach(const Region &region, double &su, double &sv, double &s) const
{
    // every weight is at most 1: the correction is no faster than the sums of the |alpha_i| of the observations that
    // reach the region (within the cut-off in time and space)
    double meanU = 0.0, meanV = 0.0;
    summary_.mean.bound(meanU, meanV);
    su = sv = s = 0.0;
    const double window = kCutoff * params_.timeScale, far = kCutoff * params_.lengthScale;
    for (std::size_t i = 0; i < nodes_.size(); ++i)
    {
        const Node &o = nodes_[i];
        if (o.t < region.tMin - window || o.t > region.tMax + window)
            continue;
        const double dx = std::max({region.xMin - o.at.x, 0.0, o.at.x - region.xMax});
        const double dy = std::max({region.yMin - o.at.y, 0.0, o.at.y - region.yMax});
        if (dx * dx + dy * dy > far * far)
            continue;
        su += std::abs(alphaU_[i]);
        sv += std::abs(alphaV_[i]);
        s += std::hypot(alphaU_[i], alphaV_[i]);
    }
    // the interpolated part is held within the data's range (addCorrection())
    const double heldU = std::max(-uLow_, uHigh_), heldV = std::max(-vLow_, vHigh_);
    su = std::min(su, heldU) + meanU;
    sv = std::min(sv, heldV) + meanV;
    s = std::min(s, std::hypot(heldU, heldV)) + std::hypot(meanU, meanV);
}

double CorrectedField::maxSpeed(const Region &region) const
{
    double su = 0.0, sv = 0.0, s = 0.0;
    reach(region, su, sv, s);
    return base_->maxSpeed(region) + s;
}

bool CorrectedField::velocityBounds(const Region &region, double &uMin, double &uMax, double &vMin, double &vMax) const
{
    if (!base_->velocityBounds(region, uMin, uMax, vMin, vMax))
        return false;
    double su = 0.0, sv = 0.0, s = 0.0;
    reach(region, su, sv, s);
    uMin -= su;
    uMax += su;
    vMin -= sv;
    vMax += sv;
    return true;
}

std::string CorrectedField::name() const
{
    return base_->name() + " corrected by " + std::to_string(summary_.used) + " glider DAC";
}
} // namespace ompl_glider

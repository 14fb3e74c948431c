/// @file ForecastRuns.cpp
/// @brief A stream of forecast runs and the forecast as known at a time (ForecastRuns.h).
#include "ompl_glider/current/ForecastRuns.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
ForecastRuns::ForecastRuns(std::vector<ForecastRun> runs, Loader load) : runs_(std::move(runs)), load_(std::move(load))
{
    if (runs_.empty())
        throw Error("ForecastRuns: no run");
    if (!load_)
        throw Error("ForecastRuns: no loader");
    std::stable_sort(runs_.begin(), runs_.end(),
                     [](const ForecastRun &a, const ForecastRun &b) { return a.reference < b.reference; });
    for (std::size_t k = 0; k < runs_.size(); ++k)
        slots_.push_back(std::make_unique<Slot>());
}

std::optional<std::size_t> ForecastRuns::newestAt(double t) const
{
    std::optional<std::size_t> out;
    for (std::size_t k = 0; k < runs_.size(); ++k)
        if (runs_[k].available <= t && (!out || runs_[k].reference >= runs_[*out].reference))
            out = k;
    return out;
}

std::vector<double> ForecastRuns::arrivalsAfter(double t0) const
{
    std::vector<double> out;
    for (const ForecastRun &r : runs_)
        if (r.available > t0)
            out.push_back(r.available);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    // a run that arrives after t0 but is older than the one newest at its arrival changes nothing
    std::vector<double> newer;
    std::optional<std::size_t> last = newestAt(t0);
    for (double t : out)
    {
        const std::optional<std::size_t> k = newestAt(t);
        if (k && (!last || *k != *last))
            newer.push_back(t);
        last = k;
    }
    return newer;
}

std::shared_ptr<const CurrentField> ForecastRuns::field(std::size_t k) const
{
    Slot &s = *slots_.at(k);
    std::lock_guard<std::mutex> hold(s.lock);
    if (!s.field)
        s.field = load_(runs_[k]);
    return s.field;
}

void ForecastRuns::setField(std::size_t k, std::shared_ptr<const CurrentField> f)
{
    Slot &s = *slots_.at(k);
    std::lock_guard<std::mutex> hold(s.lock);
    s.field = std::move(f);
}

namespace
{
/// Sums of products of pairs of differences at one lag: their correlation is prod / sqrt(a2 b2).
struct LagSums
{
    double prod{0.0}, a2{0.0}, b2{0.0};
    void add(double a, double b)
    {
        prod += a * b;
        a2 += a * a;
        b2 += b * b;
    }
    double correlation() const { return a2 > 0.0 && b2 > 0.0 ? prod / std::sqrt(a2 * b2) : 0.0; }
};

/// The Gaussian scale s of correlations c(lag k) ~ exp(-(k step)^2 / (2 s^2)): least squares of -2 ln c against
/// (k step)^2 through the origin, over the lags whose correlation is resolved (0.05 < c < 0.98); NaN with fewer than
/// two such lags before the correlation first drops below 0.05.
double gaussianScale(const std::vector<LagSums> &lags, double step)
{
    double sxy = 0.0, sxx = 0.0;
    int used = 0;
    for (std::size_t k = 1; k < lags.size(); ++k)
    {
        const double c = lags[k].correlation();
        if (!(c > 0.05))
            break;
        if (c >= 0.98)
            continue;
        const double x = std::pow(static_cast<double>(k) * step, 2.0), y = -2.0 * std::log(c);
        sxy += x * y;
        sxx += x * x;
        ++used;
    }
    return used >= 2 && sxy > 0.0 ? std::sqrt(sxx / sxy) : std::numeric_limits<double>::quiet_NaN();
}
} // namespace

std::vector<RunSource> forecastRunSources(const GriddedSource &source, ForecastRequest request,
                                          const std::vector<std::string> &entries)
{
    std::vector<RunSource> out;
    std::vector<std::vector<double>> firstTimes; // per run in several files: each file's first time
    request.run.reset();
    const auto stated = [](const ForecastTimeAxis &a) {
        return a.dated && a.referenceFrom.rfind("its first time", 0) != 0; // (not the fallback)
    };
    for (const std::string &entry : entries)
    {
        request.files = {entry};
        const ForecastTimeAxis all = source.timeAxis(request);
        for (std::size_t k = 0; k < all.runs.size(); ++k) // a file of several runs: each of them
        {
            out.push_back({{entry}, all.runs[k].index, all.runAxis(k)});
            firstTimes.emplace_back();
        }
        if (!all.runs.empty())
            continue;
        // a file whose stated reference time an earlier file states: the same run, in several files
        const auto same = std::find_if(out.begin(), out.end(), [&](const RunSource &r) {
            return stated(all) && !r.runIndex && stated(r.axis) && r.axis.referenceSeconds == all.referenceSeconds &&
                   r.axis.calendar == all.calendar;
        });
        if (same == out.end())
        {
            out.push_back({{entry}, std::nullopt, all});
            firstTimes.push_back({all.originSeconds});
            continue;
        }
        same->files.push_back(entry);
        firstTimes[std::size_t(same - out.begin())].push_back(all.originSeconds);
    }
    for (std::size_t k = 0; k < out.size(); ++k)
    {
        RunSource &r = out[k];
        if (r.files.size() < 2)
            continue;
        // in time order, read as one forecast in several files: its joined axis, its reference time kept
        std::vector<std::size_t> order(r.files.size());
        for (std::size_t q = 0; q < order.size(); ++q)
            order[q] = q;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return firstTimes[k][a] < firstTimes[k][b]; });
        std::vector<std::string> files;
        for (std::size_t q : order)
            files.push_back(r.files[q]);
        r.files = files;
        request.files = files;
        ForecastTimeAxis joined = source.timeAxis(request);
        joined.referenceSeconds = r.axis.referenceSeconds;
        joined.referenceFrom = r.axis.referenceFrom + " (one run in " + std::to_string(files.size()) + " files)";
        r.axis = joined;
    }
    return out;
}

RunSpread runSpread(const ForecastRuns &runs, const Region &box, double depth)
{
    constexpr std::size_t n = 24, nt = 17;
    const double dx = (box.xMax - box.xMin) / static_cast<double>(n - 1),
                 dy = (box.yMax - box.yMin) / static_cast<double>(n - 1);
    RunSpread out;
    double squares = 0.0;
    std::vector<LagSums> alongX(n / 2), alongY(n / 2), time(nt / 2);
    double step = 0.0; // the time step of the overlaps (their mean)
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t k = 1; k < runs.size(); ++k)
    {
        const double t0 = std::max(runs[k].begin, runs[k - 1].begin), t1 = std::min(runs[k].end, runs[k - 1].end);
        if (!(t1 > t0))
            continue;
        const auto a = runs.field(k - 1), b = runs.field(k);
        ++out.pairs;
        step += (t1 - t0) / static_cast<double>(nt - 1);
        // the differences (u then v) at each time, node (i, j): NaN on land
        std::vector<double> d(nt * n * n * 2, nan);
        for (std::size_t it = 0; it < nt; ++it)
        {
            const double t = t0 + (t1 - t0) * static_cast<double>(it) / static_cast<double>(nt - 1);
            double mu = 0.0, mv = 0.0;
            std::size_t wet = 0;
            for (std::size_t j = 0; j < n; ++j)
                for (std::size_t i = 0; i < n; ++i)
                {
                    const double x = box.xMin + dx * static_cast<double>(i), y = box.yMin + dy * static_cast<double>(j);
                    if (!a->inWater(x, y, depth) || !b->inWater(x, y, depth))
                        continue;
                    const Velocity va = a->velocity(x, y, depth, t), vb = b->velocity(x, y, depth, t);
                    if (!std::isfinite(va.u + va.v + vb.u + vb.v))
                        continue;
                    double *q = &d[((it * n + j) * n + i) * 2];
                    q[0] = vb.u - va.u;
                    q[1] = vb.v - va.v;
                    mu += q[0];
                    mv += q[1];
                    ++wet;
                }
            for (std::size_t q = 0; wet > 0 && q < n * n; ++q)
            {
                double *e = &d[(it * n * n + q) * 2];
                e[0] -= mu / static_cast<double>(wet); // (NaN stays NaN)
                e[1] -= mv / static_cast<double>(wet);
                if (std::isfinite(e[0]))
                {
                    squares += e[0] * e[0] + e[1] * e[1];
                    ++out.samples;
                }
            }
        }
        const auto at = [&](std::size_t it, std::size_t j, std::size_t i) { return &d[((it * n + j) * n + i) * 2]; };
        for (std::size_t it = 0; it < nt; ++it)
            for (std::size_t j = 0; j < n; ++j)
                for (std::size_t i = 0; i < n; ++i)
                {
                    const double *p = at(it, j, i);
                    if (!std::isfinite(p[0]))
                        continue;
                    for (std::size_t l = 1; l < alongX.size(); ++l)
                    {
                        const double *qx = i + l < n ? at(it, j, i + l) : nullptr;
                        const double *qy = j + l < n ? at(it, j + l, i) : nullptr;
                        for (int c = 0; c < 2; ++c)
                        {
                            if (qx && std::isfinite(qx[0]))
                                alongX[l].add(p[c], qx[c]);
                            if (qy && std::isfinite(qy[0]))
                                alongY[l].add(p[c], qy[c]);
                        }
                    }
                    for (std::size_t l = 1; l < time.size() && it + l < nt; ++l)
                        if (const double *q = at(it + l, j, i); std::isfinite(q[0]))
                            for (int c = 0; c < 2; ++c)
                                time[l].add(p[c], q[c]);
                }
    }
    if (out.samples == 0)
        return out;
    out.sigma = std::sqrt(squares / (2.0 * static_cast<double>(out.samples)) / 2.0);
    // east-west and north-south alike (the kernel is isotropic): their mean, or the one resolved
    const double lx = gaussianScale(alongX, dx), ly = gaussianScale(alongY, dy);
    out.lengthScale = std::isfinite(lx) && std::isfinite(ly) ? 0.5 * (lx + ly) : std::isfinite(lx) ? lx : ly;
    out.timeScale = gaussianScale(time, step / static_cast<double>(out.pairs));
    return out;
}

RunStreamField::RunStreamField(std::shared_ptr<const ForecastRuns> runs) : runs_(std::move(runs))
{
    if (!runs_)
        throw Error("RunStreamField: no runs");
    for (std::size_t k = 0; k < runs_->size(); ++k)
        fields_.push_back(runs_->field(k));
    first_ = fields_.front();
}

RunStreamField::RunStreamField(std::shared_ptr<const ForecastRuns> runs, double asOf) : RunStreamField(std::move(runs))
{
    asOf_ = runs_->runAt(asOf);
}

std::size_t RunStreamField::runFor(double t) const
{
    if (!asOf_)
        return runs_->runAt(t);
    // as known at the fixed time: its newest run (before its first time, its first field held)
    return *asOf_;
}

double RunStreamField::maxSpeed(const Region &region) const
{
    double out = 0.0;
    for (const auto &f : fields_)
        out = std::max(out, f->maxSpeed(region));
    return out;
}

double RunStreamField::timeEnd() const
{
    double out = -std::numeric_limits<double>::infinity();
    for (const auto &f : fields_)
        out = std::max(out, f->timeEnd());
    return out;
}

std::string RunStreamField::name() const
{
    return first_->name() + " (" + std::to_string(runs_->size()) + " runs, " + (asOf_ ? "as known then" : "newest") +
           ")";
}

Velocity RunStreamField::evaluate(double x, double y, double z, double t) const
{
    return fields_[runFor(t)]->velocity(x, y, z, t);
}

Jacobian RunStreamField::evaluateJacobian(double x, double y, double z, double t) const
{
    return fields_[runFor(t)]->jacobian(x, y, z, t);
}
} // namespace ompl_glider

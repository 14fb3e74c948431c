#include "ompl_glider/mission/DepartureTimeSearch.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>

#include "ompl_glider/Exception.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/current/AkimaSpline.h"
#include "../../core/Numbers.h"

namespace ompl_glider
{
namespace
{

void validate(const DepartureSearchParams &p)
{
    if (!std::isfinite(p.windowBegin) || !std::isfinite(p.windowEnd) || p.windowEnd < p.windowBegin)
        throw Error("departure window: need finite begin <= end");
    if (!(p.spacing > 0.0))
        throw Error("departure window: spacing must be > 0");
    if (!(p.tolerance > 0.0))
        throw Error("departure window: tolerance must be > 0");
    if (!(p.minTripDuration >= 0.0))
        throw Error("departure window: minTripDuration must be >= 0");
}

double cutWindow(const DepartureSearchParams &p)
{
    double end = p.windowEnd;
    if (std::isfinite(p.horizon))
        end = std::min(end, p.horizon - p.minTripDuration);
    return end;
}

std::vector<double> grid(double a, double b, double spacing)
{
    std::vector<double> t;
    const auto n = static_cast<long>(std::floor((b - a) / spacing + 1e-9));
    for (long k = 0; k <= n; ++k)
        t.push_back(a + static_cast<double>(k) * spacing);
    if (b - t.back() > 1e-9 * std::max(1.0, std::abs(b)))
        t.push_back(b);
    return t;
}

/// Evaluates f at every t in parallel (threads, or the processes of a job: TaskSpread.h), honouring the horizon; prints
/// a progress line when asked.
std::vector<DepartureSample> evaluateAll(const TravelTimeOfDeparture &f, const std::vector<double> &ts,
                                         const DepartureSearchParams &p, bool coarse, const char *what)
{
    std::vector<DepartureSample> out(ts.size());
    std::atomic<std::size_t> done{0};
    std::mutex printMutex;
    const auto report = [&](std::size_t n) {
        char line[128];
        std::snprintf(line, sizeof line, "%s: %zu/%zu departures searched", what, n, ts.size());
        p.progress(line, n == ts.size());
    };
    const auto evaluate = [&](std::size_t i) {
        double tt = f(ts[i]);
        if (!(tt >= 0.0) || ts[i] + tt > p.horizon)
            tt = kInf;
        return tt;
    };
    if (TaskSpreader *spread = activeTaskSpreader())
    {
        // the supporting points spread over the processes of a job: each returns its travel time (every bit)
        const std::vector<std::string> times = spread->run(
            "departure evaluation", ts.size(),
            [&](std::size_t i) {
                ByteWriter w;
                w.put(evaluate(i));
                return w.take();
            },
            [&](std::size_t n, std::size_t) {
                if (p.progress)
                    report(n);
            });
        for (std::size_t i = 0; i < ts.size(); ++i)
            out[i] = {ts[i], ByteReader(times[i]).value<double>(), coarse};
        return out;
    }
    ThreadPool pool(p.threads);
    pool.parallelFor(ts.size(), [&](std::size_t i) {
        out[i] = {ts[i], evaluate(i), coarse};
        if (p.progress)
        {
            std::lock_guard<std::mutex> lock(printMutex);
            report(++done);
        }
    });
    return out;
}

double seconds(std::chrono::steady_clock::time_point a)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}
} // namespace

std::pair<double, double> brentMinimize(const std::function<double(double)> &f, double a, double b, double x0,
                                        double tol, unsigned maxEvaluations, std::vector<DepartureSample> *calls)
{
    if (!(b >= a))
        throw Error("brentMinimize: need a <= b");
    // Non-finite values: the search sees a large finite penalty so that the parabolic steps stay defined.
    double penalty = 0.0;
    bool anyFinite = false;
    std::vector<std::pair<double, double>> raw;
    auto eval = [&](double x) {
        const double v = f(x);
        if (calls)
            calls->push_back({x, v, false});
        raw.push_back({x, v});
        if (std::isfinite(v))
        {
            penalty = std::max(penalty, 10.0 * std::abs(v) + 1.0);
            anyFinite = true;
            return v;
        }
        return kInf;
    };
    auto key = [&](double v) { return std::isfinite(v) ? v : (anyFinite ? penalty : 1e300); };
    const double golden = 0.3819660112501051; // (3 - sqrt(5)) / 2
    double x = (x0 > a && x0 < b) ? x0 : a + golden * (b - a);
    double w = x, v = x;
    double fx = eval(x);
    double fw = fx, fv = fx;
    double d = 0.0, e = 0.0;
    unsigned evals = 1;
    while (evals < maxEvaluations)
    {
        const double m = 0.5 * (a + b);
        const double tol1 = tol + 1e-12 * std::abs(x);
        const double tol2 = 2.0 * tol1;
        if (std::abs(x - m) <= tol2 - 0.5 * (b - a))
            break;
        bool parabolic = false;
        if (std::abs(e) > tol1)
        {
            const double kx = key(fx), kw = key(fw), kv = key(fv);
            double r = (x - w) * (kx - kv);
            double q = (x - v) * (kx - kw);
            double p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if (q > 0.0)
                p = -p;
            else
                q = -q;
            const double eOld = e;
            e = d;
            if (std::abs(p) < std::abs(0.5 * q * eOld) && p > q * (a - x) && p < q * (b - x))
            {
                d = p / q;
                const double u = x + d;
                if (u - a < tol2 || b - u < tol2)
                    d = x < m ? tol1 : -tol1;
                parabolic = true;
            }
        }
        if (!parabolic)
        {
            e = (x < m ? b : a) - x;
            d = golden * e;
        }
        const double u = x + (std::abs(d) >= tol1 ? d : (d > 0.0 ? tol1 : -tol1));
        const double fu = eval(u);
        ++evals;
        if (key(fu) <= key(fx))
        {
            (u < x ? b : a) = x;
            v = w;
            fv = fw;
            w = x;
            fw = fx;
            x = u;
            fx = fu;
        }
        else
        {
            (u < x ? a : b) = u;
            if (key(fu) <= key(fw) || w == x)
            {
                v = w;
                fv = fw;
                w = u;
                fw = fu;
            }
            else if (key(fu) <= key(fv) || v == x || v == w)
            {
                v = u;
                fv = fu;
            }
        }
    }
    // Best raw value seen (x holds it unless all were non-finite).
    double bx = x, bf = fx;
    for (const auto &r : raw)
        if (r.second < bf)
        {
            bx = r.first;
            bf = r.second;
        }
    return {bx, bf};
}

DepartureSearchResult optimalDepartureTime(const TravelTimeOfDeparture &fine, const DepartureSearchParams &p,
                                           const TravelTimeOfDeparture &coarse)
{
    validate(p);
    if (!fine)
        throw Error("optimalDepartureTime: no travel-time function given");
    const auto start = std::chrono::steady_clock::now();
    DepartureSearchResult r;
    r.windowEnd = cutWindow(p);
    if (r.windowEnd < p.windowBegin)
    {
        r.wallSeconds = seconds(start);
        return r; // the forecast does not cover any trip from the window
    }
    // Step 1: supporting points.
    const bool useCoarse = static_cast<bool>(coarse);
    const std::vector<double> ts = grid(p.windowBegin, r.windowEnd, p.spacing);
    r.supportingPoints =
        evaluateAll(useCoarse ? coarse : fine, ts, p, useCoarse, useCoarse ? "departure (coarse)" : "departure");
    (useCoarse ? r.coarseEvaluations : r.fineEvaluations) += ts.size();

    double maxFinite = -kInf, minFinite = kInf;
    for (const auto &s : r.supportingPoints)
        if (std::isfinite(s.travelTime))
        {
            maxFinite = std::max(maxFinite, s.travelTime);
            minFinite = std::min(minFinite, s.travelTime);
        }
    if (!useCoarse && std::isfinite(minFinite))
    {
        for (const auto &s : r.supportingPoints)
            if (s.travelTime == minFinite && !r.found)
            {
                r.found = true;
                r.departure = s.tDep;
                r.travelTime = s.travelTime;
            }
    }
    if (!std::isfinite(minFinite))
    {
        if (!useCoarse)
        {
            r.wallSeconds = seconds(start);
            return r;
        }
        minFinite = maxFinite = 0.0; // nothing known: Brent over the whole window
    }

    // Step 2: Akima curve; impassable points sit above every finite value.
    double tStar = p.windowBegin;
    if (ts.size() >= 2)
    {
        const double penalty = maxFinite + std::max(1.0, maxFinite - minFinite);
        std::vector<double> y;
        for (const auto &s : r.supportingPoints)
            y.push_back(std::isfinite(s.travelTime) ? s.travelTime : penalty);
        const AkimaSpline spline(ts, y);
        tStar = spline.minimum().first;
        const double w = (p.bracketSpacings > 0 ? p.bracketSpacings : (useCoarse ? 2.0 : 1.0)) * p.spacing;
        r.bracketLo = std::max(p.windowBegin, tStar - w);
        r.bracketHi = std::min(r.windowEnd, tStar + w);
    }
    else
        r.bracketLo = r.bracketHi = tStar;
    r.interpolatedMinimum = tStar;

    // Step 3: Brent's method with the fine search.
    if (r.bracketHi > r.bracketLo)
    {
        auto f = [&](double t) {
            double tt = fine(t);
            if (!(tt >= 0.0) || t + tt > p.horizon)
                tt = kInf;
            if (p.progress)
            {
                char line[128];
                std::snprintf(line, sizeof line, "departure (Brent): %zu refining searches, t=%.6g -> %.6g",
                              r.refinements.size() + 1, t, tt);
                p.progress(line, false);
            }
            return tt;
        };
        const auto best =
            brentMinimize(f, r.bracketLo, r.bracketHi, tStar, p.tolerance, p.maxBrentEvaluations, &r.refinements);
        if (p.progress)
            p.progress("departure (Brent): " + std::to_string(r.refinements.size()) + " refining searches", true);
        for (auto &s : r.refinements)
            if (!(s.travelTime >= 0.0) || s.tDep + s.travelTime > p.horizon)
                s.travelTime = kInf;
        r.fineEvaluations += r.refinements.size();
        if (std::isfinite(best.second) && (!r.found || best.second < r.travelTime))
        {
            r.found = true;
            r.departure = best.first;
            r.travelTime = best.second;
        }
    }
    else if (useCoarse)
    {
        const double tt = fine(tStar);
        r.refinements.push_back({tStar, tt, false});
        ++r.fineEvaluations;
        if (std::isfinite(tt) && tStar + tt <= p.horizon)
        {
            r.found = true;
            r.departure = tStar;
            r.travelTime = tt;
        }
    }
    r.wallSeconds = seconds(start);
    return r;
}

DepartureSearchResult bruteForceDepartureTime(const TravelTimeOfDeparture &fine, const DepartureSearchParams &p)
{
    validate(p);
    const auto start = std::chrono::steady_clock::now();
    DepartureSearchResult r;
    r.windowEnd = cutWindow(p);
    if (r.windowEnd >= p.windowBegin)
    {
        r.supportingPoints = evaluateAll(fine, grid(p.windowBegin, r.windowEnd, p.spacing), p, false, "brute force");
        r.fineEvaluations = r.supportingPoints.size();
        for (const auto &s : r.supportingPoints)
            if (std::isfinite(s.travelTime) && (!r.found || s.travelTime < r.travelTime))
            {
                r.found = true;
                r.departure = s.tDep;
                r.travelTime = s.travelTime;
            }
    }
    r.bracketLo = p.windowBegin;
    r.bracketHi = r.windowEnd;
    r.wallSeconds = seconds(start);
    return r;
}
} // namespace ompl_glider

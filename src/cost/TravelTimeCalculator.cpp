#include "ompl_glider/cost/TravelTimeCalculator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ompl_glider/Exception.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
AlongTrackSpeeds alongTrackSpeeds(double px, double py, const Velocity &c, double V)
{
    AlongTrackSpeeds r;
    const double pc = px * c.u + py * c.v;
    const double disc = pc * pc + V * V - (c.u * c.u + c.v * c.v);
    if (!(disc > 0.0)) // also false for NaN
        return r;
    const double sq = std::sqrt(disc);
    r.fast = pc + sq;
    r.slow = pc - sq;
    r.feasible = r.fast > 0.0;
    return r;
}

TravelTimeCalculator::TravelTimeCalculator(std::shared_ptr<const CurrentField> field, TravelTimeParams params)
    : field_(std::move(field)), params_(params)
{
    if (!field_)
        throw Error("TravelTimeCalculator: no current field given");
    if (!(params_.speed > 0.0))
        throw Error("TravelTimeCalculator: vehicle speed must be > 0 (got " + std::to_string(params_.speed) + ")");
    if (!(params_.hMin > 0.0) || !(params_.hMax >= params_.hMin) || !(params_.h >= params_.hMin) || params_.hMax > 1.0)
        throw Error("TravelTimeCalculator: step fractions must satisfy 0 < hMin <= h, hMin <= hMax <= 1");
    if (!(params_.eps > 0.0))
        throw Error("TravelTimeCalculator: eps must be > 0");
    if (!(params_.rtol >= 0.0) || !std::isfinite(params_.rtol))
        throw Error("TravelTimeCalculator: rtol must be finite and >= 0 (0: off)");
    if (!(params_.tau > 0.0 && params_.tau <= 1.0))
        throw Error("TravelTimeCalculator: tau must be in (0, 1]");
    if (!(params_.maxStep > 0.0))
        throw Error("TravelTimeCalculator: maxStep must be > 0");
}

double TravelTimeCalculator::travelTime(double x1, double y1, double x2, double y2, double tStart) const
{
    calls_.add();
    return integrate(x1, y1, params_.depth, x2, y2, params_.depth, tStart, false);
}

double TravelTimeCalculator::travelTimeThroughDepth(double x1, double y1, double z1, double x2, double y2, double z2,
                                                    double tStart) const
{
    calls_.add();
    return integrate(x1, y1, z1, x2, y2, z2, tStart, false);
}

ArrivalWindow TravelTimeCalculator::arrivalWindow(double x1, double y1, double x2, double y2, double tStart) const
{
    calls_.add();
    const double z = params_.depth;
    ArrivalWindow w{integrate(x1, y1, z, x2, y2, z, tStart, false), kInf};
    if (std::isfinite(w.earliest))
        w.latest = integrate(x1, y1, z, x2, y2, z, tStart, true);
    return w;
}

double TravelTimeCalculator::integrate(double x1, double y1, double z1, double x2, double y2, double z2, double tStart,
                                       bool slow) const
{
    if (!std::isfinite(tStart) || !std::isfinite(x1) || !std::isfinite(y1) || !std::isfinite(x2) ||
        !std::isfinite(y2) || !std::isfinite(z1) || !std::isfinite(z2))
        return kInf;
    const CurrentField &f = *field_;
    const double V = params_.speed;
    const double tEnd = f.timeEnd();
    if (tStart < f.timeBegin() || tStart > tEnd)
        return kInf;
    const double dx = x2 - x1, dy = y2 - y1;
    const double len = std::hypot(dx, dy);
    if (len == 0.0)
        return 0.0;
    if (!f.segmentInWater(x1, y1, x2, y2, z1) || (z2 != z1 && !f.segmentInWater(x1, y1, x2, y2, z2)))
        return kInf; // the leg touches land somewhere (not only at an integration step), at either end depth
    const double px = dx / len, py = dy / len;

    // Progress along the leg as a fraction in [0, 1] and the local time.
    double frac = 0.0, t = tStart;
    const double hCap = std::min(params_.hMax, std::max(params_.hMin, params_.maxStep / len));
    double h = std::min({params_.h, 1.0, hCap});
    Velocity cStart = f.velocity(x1, y1, z1, t);
    // Speed chosen from the roots: the fast one for the earliest arrival, the slow one for the latest.
    auto pace = [&](const Velocity &c, double &speed) -> bool {
        const AlongTrackSpeeds r = alongTrackSpeeds(px, py, c, V);
        if (!r.feasible)
            return false;
        speed = slow ? r.slow : r.fast;
        return true;
    };
    constexpr double kDone = 1.0 - 1e-12;
    while (frac < kDone)
    {
        if (frac + h > 1.0)
            h = 1.0 - frac;
        const double segLen = h * len;
        double v1;
        if (!pace(cStart, v1) || v1 <= 0.0)
            return kInf; // infeasible (fast root) or, for the slow root, the vehicle can hold: unbounded
        const double tRough = segLen / v1;
        const double fe = frac + h;
        const double xe = x1 + fe * dx, ye = y1 + fe * dy;
        if (t + tRough > tEnd)
            return kInf;
        const double ze = z1 + fe * (z2 - z1);
        const Velocity cEnd = f.velocity(xe, ye, ze, t + tRough);
        const Velocity cMean{0.5 * (cStart.u + cEnd.u), 0.5 * (cStart.v + cEnd.v)};
        double v2;
        if (!pace(cMean, v2) || v2 <= 0.0)
            return kInf;
        const double tImproved = segLen / v2;
        const double err = std::abs(tRough - tImproved);
        // the step's tolerance: eps, or tighter relative to the step's own time (rtol > 0)
        const double tol = params_.rtol > 0.0 ? std::min(params_.eps, params_.rtol * tImproved) : params_.eps;
        const double hNew = std::max(params_.hMin, std::min(hCap, params_.tau * h * std::sqrt(tol / err)));
        if (err < tol || h <= params_.hMin)
        {
            cStart = cEnd;
            frac = fe;
            t += tImproved;
            if (t > tEnd)
                return kInf;
        }
        h = hNew;
    }
    return t - tStart;
}
} // namespace ompl_glider

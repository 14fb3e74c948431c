#include "ompl_glider/cost/DiveProfile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ompl_glider/Exception.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

std::vector<double> levels(double lo, double hi, int n)
{
    std::vector<double> v;
    if (n == 1)
        return {lo};
    for (int i = 0; i < n; ++i)
        v.push_back(lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1));
    return v;
}
} // namespace

DiveProfileSelection diveProfileSelectionFromString(const std::string &name)
{
    if (name == "fastest")
        return DiveProfileSelection::Fastest;
    if (name == "deepest_under_limit")
        return DiveProfileSelection::DeepestUnderLimit;
    throw Error("dive profile selection '" + name + "' unknown (expected fastest or deepest_under_limit)");
}

std::string toString(DiveProfileSelection selection)
{
    return selection == DiveProfileSelection::Fastest ? "fastest" : "deepest_under_limit";
}

std::vector<DiveProfile> makeDiveProfiles(const DiveProfileParams &p)
{
    auto bad = [](const std::string &what) { throw Error("dive profile parameters: " + what); };
    if (!std::isfinite(p.zMin) || p.zMin < 0.0)
        bad("z_min must be finite and >= 0");
    if (!std::isfinite(p.zMax) || !(p.zMax > p.zMin))
        bad("z_max must be finite and > z_min");
    if (!std::isfinite(p.minRange) || p.minRange < 0.0)
        bad("min_range must be >= 0");
    if (!std::isfinite(p.climbToMax) || p.climbToMax < p.zMin)
        bad("climb_to_max must be >= z_min");
    if (p.zMin + p.minRange > p.zMax)
        bad("z_min + min_range must be <= z_max");
    if (p.climbToLevels < 1 || p.diveToLevels < 1)
        bad("climb_to_levels and dive_to_levels must be >= 1");
    if (!(p.step > 0.0 && p.step <= 1.0))
        bad("step must be in (0, 1]");
    if (!(p.maxTimeFactor >= 1.0))
        bad("max_time_factor must be >= 1");
    if (!(p.maxTime > 0.0))
        bad("max_time must be > 0");
    if (!(p.clearance >= 0.0) || !std::isfinite(p.clearance))
        bad("clearance must be >= 0");
    const std::vector<double> climb = levels(p.zMin, p.climbToMax, p.climbToLevels);
    const std::vector<double> dive =
        p.diveToLevels == 1 ? std::vector<double>{p.zMax} : levels(p.zMin + p.minRange, p.zMax, p.diveToLevels);
    std::vector<DiveProfile> out;
    for (double c : climb)
        for (double d : dive)
            if (d - c >= p.minRange - 1e-9 * std::max(1.0, p.zMax))
                out.push_back({c, d});
    if (out.empty())
    {
        std::ostringstream s;
        s << "no climb-to/dive-to pair has an amplitude >= min_range (" << p.minRange << ")";
        bad(s.str());
    }
    return out;
}

DiveProfileTravelTime::DiveProfileTravelTime(std::shared_ptr<const CurrentField> field, TravelTimeParams travel,
                                             DiveProfileParams dive, std::shared_ptr<const Bathymetry> bathymetry,
                                             unsigned threads)
    : segments_(std::move(field), travel), dive_(dive), bathymetry_(std::move(bathymetry))
{
    profiles_ = makeDiveProfiles(dive_);
    if (threads != 1)
        pool_ = std::make_unique<ThreadPool>(threads);
}

double DiveProfileTravelTime::travelTime(const DiveProfile &profile, double x1, double y1, double x2, double y2,
                                         double tStart) const
{
    calls_.add();
    if (!std::isfinite(tStart) || !std::isfinite(x1) || !std::isfinite(y1) || !std::isfinite(x2) || !std::isfinite(y2))
        return kInf;
    const int n = static_cast<int>(std::ceil(1.0 / dive_.step - 1e-9));
    const double dx = x2 - x1, dy = y2 - y1;
    double total = 0.0; // summed segment times (so that one segment gives its time exactly)
    for (int i = 0; i < n; ++i)
    {
        const double a = static_cast<double>(i) / n, b = static_cast<double>(i + 1) / n;
        const double xs = x1 + a * dx, ys = y1 + a * dy;
        const double xe = i + 1 == n ? x2 : x1 + b * dx, ye = i + 1 == n ? y2 : y1 + b * dy;
        double zc = profile.climbTo, zd = profile.diveTo;
        if (bathymetry_)
        {
            const double floorDepth = std::min({bathymetry_->seafloorDepth(xs, ys),
                                                bathymetry_->seafloorDepth(0.5 * (xs + xe), 0.5 * (ys + ye)),
                                                bathymetry_->seafloorDepth(xe, ye)}) -
                                      dive_.clearance;
            if (!(floorDepth > 0.0))
                return kInf;
            zd = std::min(zd, floorDepth);
            zc = std::min(zc, zd);
        }
        const double dt = segments_.travelTimeThroughDepth(xs, ys, zc, xe, ye, zd, tStart + total);
        if (!std::isfinite(dt))
            return kInf;
        total += dt;
    }
    return total;
}

int DiveProfileTravelTime::choose(const std::vector<double> &times) const
{
    int fastest = -1;
    for (std::size_t i = 0; i < times.size(); ++i)
        if (std::isfinite(times[i]) && (fastest < 0 || times[i] < times[fastest]))
            fastest = static_cast<int>(i);
    if (fastest < 0 || dive_.selection == DiveProfileSelection::Fastest)
        return fastest;
    const double limit = std::min(dive_.maxTime, dive_.maxTimeFactor * times[fastest]);
    int best = -1;
    for (std::size_t i = 0; i < times.size(); ++i)
    {
        if (!(times[i] <= limit))
            continue;
        if (best < 0)
        {
            best = static_cast<int>(i);
            continue;
        }
        const DiveProfile &p = profiles_[i], &q = profiles_[best];
        // Largest amplitude first; then the deeper dive; then the faster.
        if (p.amplitude() > q.amplitude() + 1e-12 ||
            (std::abs(p.amplitude() - q.amplitude()) <= 1e-12 &&
             (p.diveTo > q.diveTo || (p.diveTo == q.diveTo && times[i] < times[best]))))
            best = static_cast<int>(i);
    }
    return best >= 0 ? best : fastest;
}

DiveLegResult DiveProfileTravelTime::evaluate(double x1, double y1, double x2, double y2, double tStart,
                                              bool parallel) const
{
    DiveLegResult r;
    r.profileTimes.assign(profiles_.size(), kInf);
    auto one = [&](std::size_t i) { r.profileTimes[i] = travelTime(profiles_[i], x1, y1, x2, y2, tStart); };
    if (parallel && pool_)
        pool_->parallelFor(profiles_.size(), one);
    else
        for (std::size_t i = 0; i < profiles_.size(); ++i)
            one(i);
    r.profile = choose(r.profileTimes);
    if (r.profile >= 0)
        r.travelTime = r.profileTimes[r.profile];
    return r;
}

DiveLegResult DiveProfileTravelTime::bestProfile(double x1, double y1, double x2, double y2, double tStart) const
{
    return evaluate(x1, y1, x2, y2, tStart, true);
}

DiveLegResult DiveProfileTravelTime::bestProfileSerial(double x1, double y1, double x2, double y2, double tStart) const
{
    return evaluate(x1, y1, x2, y2, tStart, false);
}
} // namespace ompl_glider

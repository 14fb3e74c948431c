#include "ompl_glider/environment/TimeWindowedZone.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
TimeWindowedZone::TimeWindowedZone(std::string name, Polygon polygon, std::vector<Interval> windows, std::string kind)
    : ForbiddenRegion(std::move(name), std::move(kind)), polygon_(std::move(polygon))
{
    if (windows.empty())
        throw Error("time-windowed zone '" + this->name() + "': expected at least one time window [lo, hi]");
    for (std::size_t i = 0; i < windows.size(); ++i)
    {
        const Interval &w = windows[i];
        if (std::isnan(w.lo) || std::isnan(w.hi) || w.lo > w.hi || w.lo == INFINITY || w.hi == -INFINITY)
        {
            std::ostringstream os;
            os << "time-windowed zone '" << this->name() << "': window " << i << " = [" << w.lo << ", " << w.hi
               << "] is invalid (expected lo <= hi, not NaN)";
            throw Error(os.str());
        }
    }
    std::sort(windows.begin(), windows.end(), [](const Interval &a, const Interval &b) { return a.lo < b.lo; });
    for (const Interval &w : windows)
        if (!windows_.empty() && w.lo <= windows_.back().hi)
            windows_.back().hi = std::max(windows_.back().hi, w.hi);
        else
            windows_.push_back(w);
}

bool TimeWindowedZone::active(double t) const
{
    for (const Interval &w : windows_)
        if (t >= w.lo && t <= w.hi)
            return true;
    return false;
}

bool TimeWindowedZone::pointFree(double x, double y, double t) const
{
    if (!std::isfinite(x) || !std::isfinite(y) || std::isnan(t))
        return false;
    return !(active(t) && polygon_.contains(x, y));
}

std::vector<Interval> TimeWindowedZone::insideTimes(double x1, double y1, double t1, double x2, double y2,
                                                    double t2) const
{
    std::vector<Interval> out;
    for (const Interval &s : polygon_.segmentInsideIntervals(x1, y1, x2, y2))
    {
        // exact ends: s = 0 -> t1 and s = 1 -> t2 without rounding
        const double a = s.lo == 0.0 ? t1 : (s.lo == 1.0 ? t2 : t1 + s.lo * (t2 - t1));
        const double b = s.hi == 0.0 ? t1 : (s.hi == 1.0 ? t2 : t1 + s.hi * (t2 - t1));
        out.push_back({std::min(a, b), std::max(a, b)});
    }
    return out;
}

bool TimeWindowedZone::legFree(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    if (!std::isfinite(x1) || !std::isfinite(y1) || !std::isfinite(x2) || !std::isfinite(y2) || std::isnan(t1) ||
        std::isnan(t2))
        return false;
    const double tLo = std::min(t1, t2), tHi = std::max(t1, t2);
    bool anyWindow = false;
    for (const Interval &w : windows_)
        anyWindow = anyWindow || (w.lo <= tHi && w.hi >= tLo);
    if (!anyWindow)
        return true;
    for (const Interval &in : insideTimes(x1, y1, t1, x2, y2, t2))
        for (const Interval &w : windows_)
            if (w.lo <= in.hi && w.hi >= in.lo)
                return false;
    return true;
}
std::vector<double> TimeWindowedZone::releaseTimes() const
{
    std::vector<double> ends;
    for (const Interval &w : windows_) // sorted and merged: the ends are increasing
        ends.push_back(w.hi);
    return ends;
}
} // namespace ompl_glider

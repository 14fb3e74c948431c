#include "ompl_glider/environment/IceZone.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
bool finite(double a, double b, double c, double d, double e, double f)
{
    return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d) && std::isfinite(e) &&
           std::isfinite(f);
}
} // namespace

IceZone::IceZone(std::string name, Polygon shape, double tRef, double vx, double vy, double maxSubmergedTime)
    : ForbiddenRegion(std::move(name), "ice zone"), shape_(std::move(shape)), maxSubmerged_(maxSubmergedTime)
{
    if (!std::isfinite(tRef) || !std::isfinite(vx) || !std::isfinite(vy))
        throw Error("ice zone '" + this->name() + "': reference time and drift velocity must be finite");
    if (!(maxSubmergedTime >= 0))
        throw Error("ice zone '" + this->name() + "': maxSubmergedTime must be >= 0");
    times_ = {tRef, tRef + 1.0};
    dx_ = {0.0, vx};
    dy_ = {0.0, vy};
}

IceZone::IceZone(std::string name, Polygon shape, double tRef, const CurrentField &field, Point2 refPoint,
                 double tBegin, double tEnd, double maxSubmergedTime, IceAdvectionParams params)
    : ForbiddenRegion(std::move(name), "ice zone"), shape_(std::move(shape)), maxSubmerged_(maxSubmergedTime)
{
    const std::string who = "ice zone '" + this->name() + "'";
    if (!(maxSubmergedTime >= 0))
        throw Error(who + ": maxSubmergedTime must be >= 0");
    if (!std::isfinite(tBegin) || !std::isfinite(tEnd) || !(tBegin <= tRef && tRef <= tEnd) || !(tBegin < tEnd))
        throw Error(who + ": expected finite tBegin <= tRef <= tEnd with tBegin < tEnd");
    if (!(params.initialStep > 0) || !(params.tolerance > 0))
        throw Error(who + ": advection initialStep and tolerance must be > 0");
    if (!std::isfinite(refPoint.x) || !std::isfinite(refPoint.y))
        throw Error(who + ": reference point must be finite");
    constantVelocity_ = false;

    struct Table
    {
        std::vector<double> t, x, y;
    };
    auto vel = [&](double x, double y, double t) {
        const Velocity c = field.velocity(x, y, params.depth, t);
        if (!std::isfinite(c.u) || !std::isfinite(c.v))
        {
            std::ostringstream os;
            os << who << ": current is not finite at (" << x << ", " << y << ", t = " << t
               << ") while advecting the zone";
            throw Error(os.str());
        }
        return c;
    };
    // RK4 from tRef towards tStop on the grid tRef + k h (last step shortened).
    auto run = [&](double h, double tStop, Table &out) {
        const double dir = tStop >= tRef ? 1.0 : -1.0;
        double x = refPoint.x, y = refPoint.y, t = tRef;
        out.t.push_back(t);
        out.x.push_back(x);
        out.y.push_back(y);
        for (long k = 1; dir * (tStop - t) > 0; ++k)
        {
            double tn = tRef + dir * k * h;
            if (dir * (tn - tStop) > 0)
                tn = tStop;
            const double dt = tn - t;
            const Velocity k1 = vel(x, y, t);
            const Velocity k2 = vel(x + 0.5 * dt * k1.u, y + 0.5 * dt * k1.v, t + 0.5 * dt);
            const Velocity k3 = vel(x + 0.5 * dt * k2.u, y + 0.5 * dt * k2.v, t + 0.5 * dt);
            const Velocity k4 = vel(x + dt * k3.u, y + dt * k3.v, tn);
            x += dt / 6.0 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u);
            y += dt / 6.0 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
            t = tn;
            out.t.push_back(t);
            out.x.push_back(x);
            out.y.push_back(y);
        }
    };
    auto build = [&](double h) {
        Table fwd, bwd, all;
        run(h, tEnd, fwd);
        run(h, tBegin, bwd);
        for (std::size_t i = bwd.t.size(); i-- > 1;)
        {
            all.t.push_back(bwd.t[i]);
            all.x.push_back(bwd.x[i]);
            all.y.push_back(bwd.y[i]);
        }
        all.t.insert(all.t.end(), fwd.t.begin(), fwd.t.end());
        all.x.insert(all.x.end(), fwd.x.begin(), fwd.x.end());
        all.y.insert(all.y.end(), fwd.y.begin(), fwd.y.end());
        return all;
    };
    double h = params.initialStep;
    Table coarse = build(h);
    Table fine;
    for (int halving = 0;; ++halving)
    {
        fine = build(0.5 * h);
        // integration error of the fine table ~ |coarse - fine| / 15 at common nodes (same times exactly)
        double integ = 0.0;
        for (std::size_t i = 0; i < coarse.t.size(); ++i)
        {
            const auto it = std::lower_bound(fine.t.begin(), fine.t.end(), coarse.t[i]);
            if (it != fine.t.end() && *it == coarse.t[i])
            {
                const std::size_t j = it - fine.t.begin();
                integ = std::max(integ, std::hypot(coarse.x[i] - fine.x[j], coarse.y[i] - fine.y[j]));
            }
        }
        double interp = 0.0;
        for (std::size_t j = 1; j + 1 < fine.t.size(); ++j)
            interp = std::max(interp, std::hypot(fine.x[j + 1] - 2 * fine.x[j] + fine.x[j - 1],
                                                 fine.y[j + 1] - 2 * fine.y[j] + fine.y[j - 1]));
        positionTolerance_ = integ / 15.0 + interp / 8.0;
        if (positionTolerance_ <= params.tolerance || halving >= params.maxHalvings || fine.t.size() > 500000)
            break;
        h *= 0.5;
        coarse = std::move(fine);
    }
    const auto ref = std::find(fine.t.begin(), fine.t.end(), tRef) - fine.t.begin();
    times_ = fine.t;
    dx_.resize(times_.size());
    dy_.resize(times_.size());
    for (std::size_t i = 0; i < times_.size(); ++i)
    {
        dx_[i] = fine.x[i] - fine.x[ref];
        dy_[i] = fine.y[i] - fine.y[ref];
    }
}

Point2 IceZone::displacement(double t) const
{
    std::size_t i;
    if (t <= times_.front())
        i = 0;
    else if (t >= times_.back())
        i = times_.size() - 2;
    else
        i = std::upper_bound(times_.begin(), times_.end(), t) - times_.begin() - 1;
    if (t == times_[i])
        return {dx_[i], dy_[i]};
    const double w = (t - times_[i]) / (times_[i + 1] - times_[i]);
    return {dx_[i] + w * (dx_[i + 1] - dx_[i]), dy_[i] + w * (dy_[i + 1] - dy_[i])};
}

bool IceZone::pointFree(double x, double y, double t) const
{
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(t))
        return false;
    const Point2 d = displacement(t);
    return !shape_.contains(x - d.x, y - d.y);
}

std::string IceZone::whyBlocked(double x, double y, double t) const
{
    return pointFree(x, y, t) ? std::string() : "under " + label() + " (a glider cannot surface there)";
}

std::vector<Interval> IceZone::underIceTimes(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    std::vector<Interval> out;
    if (!finite(x1, y1, t1, x2, y2, t2))
        return out;
    if (t2 < t1)
    {
        std::swap(x1, x2);
        std::swap(y1, y2);
        std::swap(t1, t2);
    }
    if (t1 == t2)
    {
        if (!pointFree(x1, y1, t1) || !pointFree(x2, y2, t2))
            out.push_back({t1, t1});
        return out;
    }
    std::vector<double> cuts{t1};
    if (!constantVelocity_)
    {
        auto it = std::upper_bound(times_.begin(), times_.end(), t1);
        for (; it != times_.end() && *it < t2; ++it)
            cuts.push_back(*it);
    }
    cuts.push_back(t2);
    auto at = [&](double t) -> Point2 {
        if (t == t1)
            return {x1, y1};
        if (t == t2)
            return {x2, y2};
        const double w = (t - t1) / (t2 - t1);
        return {x1 + w * (x2 - x1), y1 + w * (y2 - y1)};
    };
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
    {
        const double ta = cuts[k], tb = cuts[k + 1];
        const Point2 pa = at(ta), pb = at(tb), da = displacement(ta), db = displacement(tb);
        for (const Interval &s : shape_.segmentInsideIntervals(pa.x - da.x, pa.y - da.y, pb.x - db.x, pb.y - db.y))
        {
            const double lo = s.lo == 0.0 ? ta : (s.lo == 1.0 ? tb : ta + s.lo * (tb - ta));
            const double hi = s.hi == 0.0 ? ta : (s.hi == 1.0 ? tb : ta + s.hi * (tb - ta));
            if (!out.empty() && lo <= out.back().hi)
                out.back().hi = std::max(out.back().hi, hi);
            else
                out.push_back({lo, hi});
        }
    }
    return out;
}

double IceZone::longestUnderIce(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    double longest = 0.0;
    for (const Interval &i : underIceTimes(x1, y1, t1, x2, y2, t2))
        longest = std::max(longest, i.hi - i.lo);
    return longest;
}

bool IceZone::legFree(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    if (!finite(x1, y1, t1, x2, y2, t2))
        return false;
    if (!pointFree(x1, y1, t1) || !pointFree(x2, y2, t2))
        return false;
    // quick reject: the leg's box against the box swept by the zone over [t1, t2]
    const double tLo = std::min(t1, t2), tHi = std::max(t1, t2);
    Point2 a = displacement(tLo), b = displacement(tHi);
    double dxMin = std::min(a.x, b.x), dxMax = std::max(a.x, b.x), dyMin = std::min(a.y, b.y),
           dyMax = std::max(a.y, b.y);
    if (!constantVelocity_)
        for (auto it = std::upper_bound(times_.begin(), times_.end(), tLo); it != times_.end() && *it < tHi; ++it)
        {
            const std::size_t i = it - times_.begin();
            dxMin = std::min(dxMin, dx_[i]);
            dxMax = std::max(dxMax, dx_[i]);
            dyMin = std::min(dyMin, dy_[i]);
            dyMax = std::max(dyMax, dy_[i]);
        }
    const Box &s = shape_.bounds();
    if (std::max(x1, x2) < s.xMin + dxMin || std::min(x1, x2) > s.xMax + dxMax || std::max(y1, y2) < s.yMin + dyMin ||
        std::min(y1, y2) > s.yMax + dyMax)
        return true;
    return longestUnderIce(x1, y1, t1, x2, y2, t2) <= maxSubmerged_;
}

std::string IceZone::whyLegBlocked(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    if (legFree(x1, y1, t1, x2, y2, t2))
        return {};
    if (!pointFree(x1, y1, t1))
        return "leg starts under " + label();
    if (!pointFree(x2, y2, t2))
        return "leg ends under " + label();
    std::ostringstream os;
    os << "leg stays under " << label() << " for " << longestUnderIce(x1, y1, t1, x2, y2, t2) << " (limit "
       << maxSubmerged_ << ")";
    return os.str();
}
} // namespace ompl_glider

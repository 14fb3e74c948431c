// The accurate re-flight of a route: an embedded Dormand-Prince 5(4) integrator with an adaptive step, flying heading
// routes and straight crabbed legs (see Reflight.h).
#include "ompl_glider/execution/Reflight.h"
#include "DormandPrince.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

using namespace dormand_prince; // the tableau (DormandPrince.h)

template <std::size_t N> using Vec = std::array<double, N>;

/// One trial step of the pair.
template <std::size_t N> struct Trial
{
    Vec<N> y{};         ///< the fifth-order solution at the step's end
    Vec<N> err{};       ///< fifth- minus fourth-order solution
    Vec<N> fEnd{};      ///< the right-hand side at the step's end (the next step's first stage)
    bool finite{false}; ///< every stage was defined and finite
};

/// Right-hand sides: bool f(s, y, out), false where it is not defined (then out is not used).
template <std::size_t N, class F>
Trial<N> dormandPrinceStep(const F &f, double s, const Vec<N> &y, const Vec<N> &k1, double h)
{
    Trial<N> r;
    Vec<N> k2{}, k3{}, k4{}, k5{}, k6{}, z{};
    auto stage = [&](double c, Vec<N> &k, auto increment) {
        for (std::size_t i = 0; i < N; ++i)
            z[i] = y[i] + h * increment(i);
        if (!std::all_of(z.begin(), z.end(), [](double v) { return std::isfinite(v); }) || !f(s + c * h, z, k))
            return false;
        return std::all_of(k.begin(), k.end(), [](double v) { return std::isfinite(v); });
    };
    const bool ok =
        stage(kC2, k2, [&](std::size_t i) { return kA21 * k1[i]; }) &&
        stage(kC3, k3, [&](std::size_t i) { return kA31 * k1[i] + kA32 * k2[i]; }) &&
        stage(kC4, k4, [&](std::size_t i) { return kA41 * k1[i] + kA42 * k2[i] + kA43 * k3[i]; }) &&
        stage(kC5, k5, [&](std::size_t i) { return kA51 * k1[i] + kA52 * k2[i] + kA53 * k3[i] + kA54 * k4[i]; }) &&
        stage(
            1.0, k6,
            [&](std::size_t i) { return kA61 * k1[i] + kA62 * k2[i] + kA63 * k3[i] + kA64 * k4[i] + kA65 * k5[i]; }) &&
        stage(1.0, r.fEnd,
              [&](std::size_t i) { return kB1 * k1[i] + kB3 * k3[i] + kB4 * k4[i] + kB5 * k5[i] + kB6 * k6[i]; });
    if (!ok)
        return r;
    r.y = z; // the last stage was evaluated at the fifth-order solution
    for (std::size_t i = 0; i < N; ++i)
        r.err[i] = h * (kE1 * k1[i] + kE3 * k3[i] + kE4 * k4[i] + kE5 * k5[i] + kE6 * k6[i] + kE7 * r.fEnd[i]);
    r.finite = true;
    return r;
}

/// Root mean square of the error over the components, each in units of atol + rtol * max(|y0|, |y1|).
template <std::size_t N> double errorNorm(const Trial<N> &trial, const Vec<N> &y0, double rtol, double atol)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < N; ++i)
    {
        const double sc = atol + rtol * std::max(std::abs(y0[i]), std::abs(trial.y[i]));
        const double q = trial.err[i] / sc;
        sum += q * q;
    }
    return std::sqrt(sum / double(N));
}

/// The factor of the next step after a step of error @p err ([HairerODE] Sec. II.4: 0.9 err^(-1/5), within
/// [0.2, 5]; not above 1 right after a rejection).
double stepFactor(double err, bool afterRejection)
{
    const double fac = err > 0.0 ? 0.9 * std::pow(err, -0.2) : 5.0;
    return std::clamp(fac, 0.2, afterRejection ? 1.0 : 5.0);
}

void checkSettings(const ReflightSettings &s, const char *who)
{
    const ReflightTolerance &tol = s.tolerance;
    if (!(s.speed > 0.0) || !std::isfinite(s.speed))
        throw Error(std::string(who) + ": the speed must be positive and finite");
    if (!(tol.rtol >= 0.0) || !(tol.atol >= 0.0) || !(tol.rtol > 0.0 || tol.atol > 0.0) || !std::isfinite(tol.rtol) ||
        !std::isfinite(tol.atol))
        throw Error(std::string(who) + ": the tolerances must be finite, >= 0, and not both 0");
    if (tol.maxSteps == 0)
        throw Error(std::string(who) + ": maxSteps must be > 0");
    if (!(s.radius >= 0.0))
        throw Error(std::string(who) + ": the goal radius must be >= 0");
}

std::string where(double x, double y, double t)
{
    std::ostringstream os;
    os << "(" << x << ", " << y << ") at t = " << t;
    return os.str();
}

/// The step-size state of one integration: the step proposed next and whether the last trial was rejected.
struct Controller
{
    double h{0.0};
    bool afterRejection{false};

    /// A trial of length @p tried failed with error @p err (> 1) or, with err = NaN, could not be evaluated.
    void reject(double tried, double err)
    {
        h = tried * (std::isnan(err) ? 0.5 : stepFactor(err, true));
        afterRejection = true;
    }
    /// A trial of length @p tried (possibly shortened below h to end a segment or a leg) was accepted.
    void accept(double tried, double err)
    {
        const double next = tried * stepFactor(err, afterRejection);
        h = tried < h ? std::max(h, next) : next;
        afterRejection = false;
    }
};

/// Re-flies the segments of a heading route; the state is the displacement from the route's start.
class HeadingFlier
{
public:
    HeadingFlier(const HeadingRoute &route, const CurrentField &field, const Environment *forbidden,
                 const ReflightSettings &s)
        : route_(route), field_(field), forbidden_(forbidden), s_(s)
    {
        const ReflightTolerance &tol = s.tolerance;
        atol_ = tol.atol > 0.0 ? tol.atol : tol.rtol * s.speed * std::max(route.duration(), 0.0);
        if (!(atol_ > 0.0))
            atol_ = tol.rtol * std::max(1.0, std::hypot(route.start.x, route.start.y));
    }

    HeadingReflight fly()
    {
        r_.ends.push_back({route_.start.x, route_.start.y, route_.departure});
        t_ = route_.departure;
        if (s_.radius > 0.0 && distanceToGoal(d_) <= s_.radius)
        {
            r_.reached = true;
            r_.arrivalTime = t_;
        }
        else
            for (const HeadingSegment &seg : route_.segments)
            {
                if (!(seg.duration > 0.0))
                    continue;
                ++r_.segmentsFlown;
                const bool goOn = flySegment(bearingVector(seg.bearing), seg.duration);
                if (!r_.reached)
                    r_.ends.push_back(position());
                if (!goOn)
                    break;
            }
        r_.end = r_.ends.back();
        if (s_.radius > 0.0)
            r_.finalDistance = std::hypot(r_.end.x - s_.goal.x, r_.end.y - s_.goal.y);
        return r_;
    }

private:
    TimedPoint position() const { return {route_.start.x + d_[0], route_.start.y + d_[1], t_}; }
    double distanceToGoal(const Vec<2> &d) const
    {
        return std::hypot(route_.start.x + d[0] - s_.goal.x, route_.start.y + d[1] - s_.goal.y);
    }

    /// Flies one segment; false when the flight ended (arrival, grounding, or the integrator gave up).
    bool flySegment(const Point2 &heading, double duration)
    {
        const double V = s_.speed;
        auto rate = [&](double t, const Vec<2> &d, Vec<2> &out) {
            const Velocity c = field_.velocity(route_.start.x + d[0], route_.start.y + d[1], s_.depth, t);
            out = {V * heading.x + c.u, V * heading.y + c.v};
            return true;
        };
        const double tEnd = t_ + duration, hLocate = 1e-9 * duration;
        Vec<2> k1{};
        rate(t_, d_, k1);
        if (!(ctl_.h > 0.0))
            ctl_.h = duration / 16.0;
        double blocked = kInf; // a step from here longer than this meets land or a forbidden region
        std::size_t trials = 0;
        while (t_ < tEnd)
        {
            if (++trials > s_.tolerance.maxSteps)
            {
                r_.ok = false;
                r_.why = "the re-flight gave up after " + std::to_string(trials - 1) + " steps near " +
                         where(position().x, position().y, t_);
                return false;
            }
            const double h = std::min({ctl_.h, tEnd - t_, blocked});
            const bool last = h >= tEnd - t_;
            const double t1 = last ? tEnd : t_ + h;
            const Trial<2> tr = dormandPrinceStep<2>(rate, t_, d_, k1, h);
            const double err = tr.finite ? errorNorm(tr, d_, s_.tolerance.rtol, atol_) : std::nan("");
            if (!tr.finite || !std::isfinite(err))
            {
                if (h <= hLocate)
                    return ground("the current is not finite just after " + where(position().x, position().y, t_));
                ctl_.reject(h, std::nan(""));
                ++r_.rejected;
                continue;
            }
            if (err > 1.0)
            {
                ctl_.reject(h, err);
                ++r_.rejected;
                continue;
            }
            const TimedPoint p0 = position();
            const double x1 = route_.start.x + tr.y[0], y1 = route_.start.y + tr.y[1];
            const std::string why = blockedWhy(p0, x1, y1, t1);
            if (!why.empty())
            {
                if (h <= hLocate)
                    return ground(why);
                blocked = h;
                ctl_.reject(h, std::nan(""));
                ++r_.rejected;
                continue;
            }
            if (s_.radius > 0.0 && arrives(rate, k1, tr, h))
                return false;
            d_ = tr.y;
            t_ = t1;
            k1 = tr.fEnd;
            blocked -= h;
            ctl_.accept(h, err);
            ++r_.steps;
        }
        return true;
    }

    /// Why the chord from @p p0 to (x1, y1) at t1 is blocked (land, forbidden region); empty when it is free.
    std::string blockedWhy(const TimedPoint &p0, double x1, double y1, double t1) const
    {
        if (!field_.segmentInWater(p0.x, p0.y, x1, y1, s_.depth))
            return "land of the current field between " + where(p0.x, p0.y, p0.t) + " and " + where(x1, y1, t1);
        if (forbidden_ && !forbidden_->legFree(p0.x, p0.y, p0.t, x1, y1, t1))
            return forbidden_->whyLegBlocked(p0.x, p0.y, p0.t, x1, y1, t1) + " between " + where(p0.x, p0.y, p0.t) +
                   " and " + where(x1, y1, t1);
        return {};
    }

    bool ground(const std::string &why)
    {
        r_.grounded = true;
        r_.why = why;
        return false;
    }

    /// When the accepted step @p tr of length @p h from the current state enters the goal's circle: finds the first
    /// entry, ends the flight there and returns true.
    template <class F> bool arrives(const F &rate, const Vec<2> &k1, const Trial<2> &tr, double h)
    {
        // distance to the circle after a fresh step of theta * h from the step's start (<= 0: inside)
        auto gap = [&](double theta, Vec<2> &d) {
            if (theta >= 1.0)
                d = tr.y;
            else
            {
                const Trial<2> part = dormandPrinceStep<2>(rate, t_, d_, k1, theta * h);
                if (!part.finite)
                    return kInf; // not evaluated: taken as outside
                d = part.y;
            }
            return distanceToGoal(d) - s_.radius;
        };
        Vec<2> d{};
        double hi = -1.0;
        if (gap(1.0, d) <= 0.0)
            hi = 1.0;
        else
        {
            // the chord may enter the circle although the step ends outside: probe the chord's entry and the step
            const double ex = tr.y[0] - d_[0], ey = tr.y[1] - d_[1];
            const double fx = route_.start.x + d_[0] - s_.goal.x, fy = route_.start.y + d_[1] - s_.goal.y;
            const double a = ex * ex + ey * ey, b = 2.0 * (ex * fx + ey * fy);
            const double c = fx * fx + fy * fy - s_.radius * s_.radius, disc = b * b - 4.0 * a * c;
            const double enter = a > 0.0 && disc >= 0.0 ? (-b - std::sqrt(disc)) / (2.0 * a) : kInf;
            const double leave = a > 0.0 && disc >= 0.0 ? (-b + std::sqrt(disc)) / (2.0 * a) : -kInf;
            if (enter <= 1.0 && leave >= 0.0)
            {
                std::vector<double> probes{std::clamp(enter, 0.0, 1.0)};
                for (int k = 1; k < 16; ++k)
                    probes.push_back(k / 16.0);
                for (double q : probes)
                    if (q > 0.0 && gap(q, d) <= 0.0 && (hi < 0.0 || q < hi))
                        hi = q;
            }
        }
        if (hi < 0.0)
            return false;
        double lo = 0.0;
        while (hi - lo > 1e-15)
        {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi)
                break;
            (gap(mid, d) <= 0.0 ? hi : lo) = mid;
        }
        gap(hi, d);
        d_ = d;
        t_ += hi * h;
        ++r_.steps;
        r_.reached = true;
        r_.arrivalTime = t_;
        r_.ends.push_back(position());
        return true;
    }

    const HeadingRoute &route_;
    const CurrentField &field_;
    const Environment *forbidden_;
    const ReflightSettings &s_;
    double atol_{0.0};
    HeadingReflight r_;
    Vec<2> d_{}; // displacement from the route's start
    double t_{0.0};
    Controller ctl_;
};

/// Re-flies one straight leg: the time elapsed on the leg, integrated in the distance flown along it.
class LegFlier
{
public:
    LegFlier(double x1, double y1, double x2, double y2, double tStart, const CurrentField &field,
             const Environment *forbidden, const ReflightSettings &s)
        : x1_(x1), y1_(y1), tStart_(tStart), field_(field), forbidden_(forbidden), s_(s)
    {
        len_ = std::hypot(x2 - x1, y2 - y1);
        px_ = len_ > 0.0 ? (x2 - x1) / len_ : 0.0;
        py_ = len_ > 0.0 ? (y2 - y1) / len_ : 0.0;
        atol_ = s.tolerance.atol > 0.0 ? s.tolerance.atol : s.tolerance.rtol * len_ / s.speed;
    }

    LegReflight fly()
    {
        r_.where = {x1_, y1_, tStart_};
        if (!std::isfinite(len_) || !std::isfinite(tStart_))
            return fail("the leg or its departure is not finite");
        if (len_ == 0.0)
        {
            r_.feasible = true;
            r_.duration = 0.0;
            return r_;
        }
        if (tStart_ < field_.timeBegin() || tStart_ > field_.timeEnd())
            return fail("the departure is outside the field's time range");
        if (!field_.segmentInWater(x1_, y1_, x1_ + len_ * px_, y1_ + len_ * py_, s_.depth))
            return failAtLand();
        return integrate();
    }

private:
    /// dt/dl = 1 / s(x(l), t): false where the leg cannot be flown there (reason kept in why_).
    bool rate(double l, const Vec<1> &tau, Vec<1> &out) const
    {
        const double t = tStart_ + tau[0];
        if (t > field_.timeEnd())
        {
            why_ = "the field ends (t = " + std::to_string(field_.timeEnd()) + ")";
            return false;
        }
        const Velocity c = field_.velocity(x1_ + l * px_, y1_ + l * py_, s_.depth, t);
        if (!std::isfinite(c.u) || !std::isfinite(c.v))
        {
            why_ = "the current is not finite";
            return false;
        }
        const AlongTrackSpeeds v = alongTrackSpeeds(px_, py_, c, s_.speed);
        if (!v.feasible)
        {
            const double pc = px_ * c.u + py_ * c.v;
            why_ = pc * pc + s_.speed * s_.speed - (c.u * c.u + c.v * c.v) > 0.0
                       ? "the current against the leg is stronger than the speed"
                       : "the cross current is stronger than the speed (no crab angle keeps the glider on the leg)";
            return false;
        }
        out[0] = 1.0 / v.fast;
        return true;
    }

    LegReflight integrate()
    {
        auto f = [this](double l, const Vec<1> &tau, Vec<1> &out) { return rate(l, tau, out); };
        const double hLocate = 1e-12 * len_;
        Vec<1> tau{0.0}, k1{};
        if (!f(0.0, tau, k1))
            return fail(why_);
        Controller ctl;
        ctl.h = len_ / 16.0;
        double l = 0.0, blocked = kInf;
        std::size_t trials = 0;
        while (l < len_)
        {
            r_.where = {x1_ + l * px_, y1_ + l * py_, tStart_ + tau[0]};
            if (++trials > s_.tolerance.maxSteps)
                return fail("the re-flight gave up after " + std::to_string(trials - 1) + " steps");
            const double h = std::min({ctl.h, len_ - l, blocked});
            const bool last = h >= len_ - l;
            const Trial<1> tr = dormandPrinceStep<1>(f, l, tau, k1, h);
            const double err = tr.finite ? errorNorm(tr, tau, s_.tolerance.rtol, atol_) : std::nan("");
            if (!tr.finite || !std::isfinite(err))
            {
                if (h <= hLocate)
                    return fail(why_);
                ctl.reject(h, std::nan(""));
                ++r_.rejected;
                continue;
            }
            if (err > 1.0)
            {
                ctl.reject(h, err);
                ++r_.rejected;
                continue;
            }
            const double l1 = last ? len_ : l + h;
            if (forbidden_)
            {
                const TimedPoint &p0 = r_.where;
                const double xe = x1_ + l1 * px_, ye = y1_ + l1 * py_, te = tStart_ + tr.y[0];
                if (!forbidden_->legFree(p0.x, p0.y, p0.t, xe, ye, te))
                {
                    if (h <= hLocate)
                        return fail(forbidden_->whyLegBlocked(p0.x, p0.y, p0.t, xe, ye, te));
                    blocked = h;
                    ctl.reject(h, std::nan(""));
                    ++r_.rejected;
                    continue;
                }
            }
            l = l1;
            tau = tr.y;
            k1 = tr.fEnd;
            blocked -= h;
            ctl.accept(h, err);
            ++r_.steps;
        }
        r_.where = {x1_ + len_ * px_, y1_ + len_ * py_, tStart_ + tau[0]};
        r_.feasible = true;
        r_.duration = tau[0];
        return r_;
    }

    LegReflight fail(const std::string &why)
    {
        r_.feasible = false;
        r_.duration = kInf;
        r_.why = why + " at " + where(r_.where.x, r_.where.y, r_.where.t);
        return r_;
    }

    /// The leg touches land: bisects for the first point where the leg from its start leaves the water.
    LegReflight failAtLand()
    {
        double lo = 0.0, hi = len_;
        for (int k = 0; k < 60 && hi - lo > 1e-12 * len_; ++k)
        {
            const double mid = 0.5 * (lo + hi);
            (field_.segmentInWater(x1_, y1_, x1_ + mid * px_, y1_ + mid * py_, s_.depth) ? lo : hi) = mid;
        }
        r_.where = {x1_ + lo * px_, y1_ + lo * py_, std::nan("")};
        r_.feasible = false;
        r_.duration = kInf;
        std::ostringstream os;
        os << "the leg meets land of the current field at (" << r_.where.x << ", " << r_.where.y << ")";
        r_.why = os.str();
        return r_;
    }

    double x1_, y1_, tStart_;
    const CurrentField &field_;
    const Environment *forbidden_;
    const ReflightSettings &s_;
    double len_{0.0}, px_{0.0}, py_{0.0}, atol_{0.0};
    mutable std::string why_;
    LegReflight r_;
};
} // namespace

HeadingReflight reflyHeadingRoute(const HeadingRoute &route, const CurrentField &field, const Environment *forbidden,
                                  const ReflightSettings &settings)
{
    checkSettings(settings, "reflyHeadingRoute");
    return HeadingFlier(route, field, forbidden, settings).fly();
}

LegReflight reflyLeg(double x1, double y1, double x2, double y2, double tStart, const CurrentField &field,
                     const Environment *forbidden, const ReflightSettings &settings)
{
    checkSettings(settings, "reflyLeg");
    return LegFlier(x1, y1, x2, y2, tStart, field, forbidden, settings).fly();
}

PathReflight reflyPath(const std::vector<TimedPoint> &path, const CurrentField &field, const Environment *forbidden,
                       const ReflightSettings &settings)
{
    checkSettings(settings, "reflyPath");
    PathReflight r;
    if (path.empty())
    {
        r.why = "empty path";
        return r;
    }
    r.times.push_back(path.front().t);
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
    {
        const TimedPoint &a = path[i], &b = path[i + 1];
        if (a.x == b.x && a.y == b.y)
        {
            // a hold keeps its planned duration, or with keepSlowLegs its planned end (a wait for a time)
            r.times.push_back(settings.keepSlowLegs ? std::max(r.times.back(), b.t) : r.times.back() + (b.t - a.t));
            continue;
        }
        const LegReflight leg = reflyLeg(a.x, a.y, b.x, b.y, r.times.back(), field, forbidden, settings);
        r.steps += leg.steps;
        if (!leg.feasible)
        {
            r.failedLeg = i;
            r.where = leg.where;
            r.why = "leg " + std::to_string(i) + ": " + leg.why;
            return r;
        }
        const bool slow = settings.keepSlowLegs && b.t - a.t > leg.duration * (1.0 + 1e-3);
        r.times.push_back(slow ? std::max(r.times.back() + leg.duration, b.t) : r.times.back() + leg.duration);
    }
    r.feasible = true;
    r.arrivalTime = r.times.back();
    return r;
}

double relativeDifference(double reported, double reflown)
{
    if (std::isnan(reported) || std::isnan(reflown))
        return std::nan("");
    if (reported == reflown)
        return 0.0;
    if (std::isinf(reflown))
        return -kInf;
    if (std::isinf(reported) || reflown == 0.0)
        return reported > reflown ? kInf : -kInf;
    return (reported - reflown) / std::abs(reflown);
}
} // namespace ompl_glider

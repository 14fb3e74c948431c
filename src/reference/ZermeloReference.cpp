#include "ompl_glider/reference/ZermeloReference.h"
#include "../io/NumberText.h"
#include "../execution/DormandPrince.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ThreadPool.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{
constexpr double kTwoPi = 6.283185307179586;

using namespace dormand_prince; // the tableau (execution/DormandPrince.h)

/// Step-size control after a rejected step (scaled error err > 1, or not finite): shrinks h; false when h became
/// too small to proceed at time t (a singular field).
bool shrinkStep(double err, double t, double &h)
{
    h *= std::isfinite(err) ? std::max(0.2, 0.9 * std::pow(err, -0.2)) : 0.2;
    return !(h < 1e-14 * std::max(1.0, t));
}

/// Factor of the next step size after an accepted step with scaled error err.
double growthFactor(double err)
{
    return std::min(5.0, 0.9 * std::pow(std::max(err, 1e-10), -0.2));
}

/// The adaptive step loop of shoot() and trajectory(): from t = 0 to `duration`, at most maxSteps tries, step sizes
/// from shrinkStep() and growthFactor(). attempt(t, h, err) makes one step of size h from t (setting its scaled
/// error) and returns false to stop; accept(t, h) takes the step just made, before t advances by h.
template <typename Attempt, typename Accept>
void stepLoop(double duration, int maxSteps, Attempt &&attempt, Accept &&accept)
{
    double t = 0.0;
    double h = std::max(1e-6, 1e-3 * duration);
    int steps = 0;
    while (t < duration && steps < maxSteps)
    {
        ++steps;
        h = std::min(h, duration - t);
        double err = 0.0;
        if (!attempt(t, h, err))
            break;
        if (!(err <= 1.0))
        {
            if (!shrinkStep(err, t, h))
                break; // cannot proceed (singular field)
            continue;
        }
        accept(t, h);
        t += h;
        h *= growthFactor(err);
    }
}

/// Trial point of the Illinois method on the bracket (a, fa), (b, fb): the secant's root, or the middle when that
/// root is not strictly inside the bracket.
double illinoisPoint(double a, double fa, double b, double fb)
{
    const double c = (a * fb - b * fa) / (fb - fa);
    if (!(c > std::min(a, b) && c < std::max(a, b)))
        return 0.5 * (a + b);
    return c;
}

/// Illinois update with the trial point (c, fc): c replaces b; when fc has the sign of fb the kept end a has its
/// value halved, else b becomes the new a.
void illinoisUpdate(double &a, double &fa, double &b, double &fb, double c, double fc)
{
    if ((fc < 0.0) == (fb < 0.0))
        fa *= 0.5;
    else
    {
        a = b;
        fa = fb;
    }
    b = c;
    fb = fc;
}
} // namespace

ZermeloReference::ZermeloReference(std::shared_ptr<const CurrentField> field, ZermeloParams params)
    : field_(std::move(field)), params_(params)
{
    if (!field_)
        throw Error("ZermeloReference: no current field given");
    if (!(params_.speed > 0.0))
        throw Error("ZermeloReference: speed must be > 0 (got " + text::number(params_.speed) + ")");
    if (!(params_.relTol > 0.0) || !(params_.absTol > 0.0) || !(params_.scanRelTol > 0.0))
        throw Error("ZermeloReference: integrator tolerances relTol, scanRelTol and absTol must be > 0");
    if (params_.headingSamples < 8)
        throw Error("ZermeloReference: headingSamples must be >= 8 (got " + std::to_string(params_.headingSamples) +
                    ")");
    if (!(params_.goalTolerance > 0.0))
        throw Error("ZermeloReference: goalTolerance must be > 0");
    if (!(params_.headingSpan > 0.0 && params_.headingSpan <= kTwoPi) || !std::isfinite(params_.headingFrom))
        throw Error("ZermeloReference: headingSpan must be in (0, 2 pi] and headingFrom finite");
}

ZermeloReference::Y ZermeloReference::rhs(double t, const Y &s) const
{
    const Velocity c = field_->velocity(s.x, s.y, params_.depth, t);
    const Jacobian J = field_->jacobian(s.x, s.y, params_.depth, t);
    const double cs = std::cos(s.th), sn = std::sin(s.th);
    const double V = params_.speed;
    // [EichhornRAS] Eq. 10 (motion) and Eq. 2 (Zermelo's navigation law).
    return {c.u + V * cs, c.v + V * sn, -J.uy * cs * cs + (J.ux - J.vy) * cs * sn + J.vx * sn * sn};
}

ZermeloReference::Y ZermeloReference::step(double t, const Y &s, const Y &k1, double h, double relTol,
                                           double &err) const
{
    auto comb = [&](std::initializer_list<std::pair<double, const Y *>> terms) {
        Y r = s;
        for (const auto &[a, k] : terms)
        {
            r.x += h * a * k->x;
            r.y += h * a * k->y;
            r.th += h * a * k->th;
        }
        return r;
    };
    const Y k2 = rhs(t + kC2 * h, comb({{kA21, &k1}}));
    const Y k3 = rhs(t + kC3 * h, comb({{kA31, &k1}, {kA32, &k2}}));
    const Y k4 = rhs(t + kC4 * h, comb({{kA41, &k1}, {kA42, &k2}, {kA43, &k3}}));
    const Y k5 = rhs(t + kC5 * h, comb({{kA51, &k1}, {kA52, &k2}, {kA53, &k3}, {kA54, &k4}}));
    const Y k6 = rhs(t + h, comb({{kA61, &k1}, {kA62, &k2}, {kA63, &k3}, {kA64, &k4}, {kA65, &k5}}));
    const Y y5 = comb({{kB1, &k1}, {kB3, &k3}, {kB4, &k4}, {kB5, &k5}, {kB6, &k6}});
    const Y k7 = rhs(t + h, y5);
    const double ex = h * (kE1 * k1.x + kE3 * k3.x + kE4 * k4.x + kE5 * k5.x + kE6 * k6.x + kE7 * k7.x);
    const double ey = h * (kE1 * k1.y + kE3 * k3.y + kE4 * k4.y + kE5 * k5.y + kE6 * k6.y + kE7 * k7.y);
    const double et = h * (kE1 * k1.th + kE3 * k3.th + kE4 * k4.th + kE5 * k5.th + kE6 * k6.th + kE7 * k7.th);
    const double a = params_.absTol;
    const double sx = a + relTol * std::max(std::abs(s.x), std::abs(y5.x));
    const double sy = a + relTol * std::max(std::abs(s.y), std::abs(y5.y));
    const double st = a + relTol * std::max(1.0, std::abs(y5.th));
    err = std::max({std::abs(ex) / sx, std::abs(ey) / sy, std::abs(et) / st});
    if (!std::isfinite(y5.x) || !std::isfinite(y5.y) || !std::isfinite(y5.th))
        err = kInf;
    return y5;
}

std::vector<ClosestApproach> ZermeloReference::shoot(double x1, double y1, double theta0, double t0, double gx,
                                                     double gy, double maxTime, double relTol) const
{
    if (relTol <= 0.0)
        relTol = params_.relTol;
    std::vector<ClosestApproach> events;
    const double tEndField = field_->timeEnd();
    Y s{x1, y1, theta0};
    Y k1 = rhs(t0, s);
    Y sNew{};
    auto g = [&](const Y &st, const Y &d) { return (st.x - gx) * d.x + (st.y - gy) * d.y; };
    double gPrev = g(s, k1);
    bool left = false, stopped = false; // left the admissible set; too far from the goal since
    const double D = std::hypot(gx - x1, gy - y1);
    auto attempt = [&](double t, double h, double &err) {
        if (stopped || t0 + t + h > tEndField)
            return false;
        sNew = step(t0 + t, s, k1, h, relTol, err);
        return true;
    };
    auto accept = [&](double t, double h) {
        if (params_.admissible && !left && !params_.admissible(s.x, s.y, t0 + t, sNew.x, sNew.y, t0 + t + h))
            left = true; // no solution past here; approaches near the goal still bracket the headings
        const double away = std::hypot(sNew.x - gx, sNew.y - gy);
        if ((left && away > D) ||
            (params_.groundSpeedBound > 0.0 && away > params_.groundSpeedBound * (maxTime - t - h)))
            stopped = true; // too far from the goal to bracket it, or to reach it in the time left
        const Y kNew = rhs(t0 + t + h, sNew);
        const double gNew = g(sNew, kNew);
        if (gPrev < 0.0 && gNew >= 0.0)
        {
            // Closest approach inside the step: locate g = 0 by the Illinois method, each trial point reached by one
            // Dormand-Prince step of the trial size from the step's start (5th-order accurate).
            double a = 0.0, fa = gPrev, b = h, fb = gNew;
            double sz = b;
            Y sAt = sNew;
            Y dAt = kNew;
            for (int it = 0; it < 80 && b - a > 1e-15 * std::max(1.0, t); ++it)
            {
                const double c = illinoisPoint(a, fa, b, fb);
                double dummy;
                const Y sc = step(t0 + t, s, k1, c, relTol, dummy);
                const Y dc = rhs(t0 + t + c, sc);
                const double fc = g(sc, dc);
                sz = c;
                sAt = sc;
                dAt = dc;
                if (fc == 0.0)
                    break;
                illinoisUpdate(a, fa, b, fb, c, fc);
                if (a > b)
                {
                    std::swap(a, b);
                    std::swap(fa, fb);
                }
            }
            ClosestApproach e;
            e.t = t + sz;
            const double sp = std::hypot(dAt.x, dAt.y);
            const double dist = std::hypot(sAt.x - gx, sAt.y - gy);
            if (sp > 1e-14)
                e.miss = (dAt.x * (gy - sAt.y) - dAt.y * (gx - sAt.x)) / sp;
            else
                e.miss = dist;
            e.state = {t0 + e.t, sAt.x, sAt.y, sAt.th};
            e.admissible = !left;
            events.push_back(e);
        }
        s = sNew;
        k1 = kNew;
        gPrev = gNew;
    };
    stepLoop(maxTime, params_.maxSteps, attempt, accept);
    return events;
}

std::vector<ZermeloState> ZermeloReference::trajectory(double x1, double y1, double theta0, double t0,
                                                       double duration) const
{
    std::vector<ZermeloState> out;
    Y s{x1, y1, theta0};
    out.push_back({t0, s.x, s.y, s.th});
    Y k1 = rhs(t0, s);
    Y sNew{};
    auto attempt = [&](double t, double h, double &err) {
        sNew = step(t0 + t, s, k1, h, params_.relTol, err);
        return true;
    };
    auto accept = [&](double t, double h) {
        const double tNext = t + h;
        s = sNew;
        k1 = rhs(t0 + tNext, s);
        out.push_back({t0 + tNext, s.x, s.y, s.th});
    };
    stepLoop(duration, params_.maxSteps, attempt, accept);
    return out;
}

namespace
{
/// A bracket of the initial heading: neighbouring headings a and b whose closest approaches miss the goal on either
/// side (by fa and fb), and the earlier of their approach times.
struct Bracket
{
    double a, fa, b, fb, tEst;
};

/// The closest approach of @p ev nearest in time to @p t (null: none).
const ClosestApproach *nearestInTime(const std::vector<ClosestApproach> &ev, double t)
{
    const ClosestApproach *best = nullptr;
    for (const ClosestApproach &f : ev)
        if (!best || std::abs(f.t - t) < std::abs(best->t - t))
            best = &f;
    return best;
}

/// The brackets of a scan @p shots of headings @p from, @p from + @p dTheta, ... (around the whole @p circle or
/// not): a closest approach whose signed miss changes sign between neighbouring headings (matched by the nearest
/// approach time), unless it is far from the goal (@p D the start's distance to it); by approach time.
std::vector<Bracket> headingBrackets(const std::vector<std::vector<ClosestApproach>> &shots, bool circle, double from,
                                     double dTheta, double D, double speed)
{
    const int shotsCount = static_cast<int>(shots.size());
    std::vector<Bracket> brackets;
    for (int j = 0; j + (circle ? 0 : 1) < shotsCount; ++j)
    {
        const int k = (j + 1) % shotsCount;
        for (const ClosestApproach &e : shots[j])
        {
            const ClosestApproach *best = nearestInTime(shots[k], e.t);
            if (!best || (e.miss < 0.0) == (best->miss < 0.0))
                continue;
            // A sign flip far from the goal is the swap of two sides of a loop, not a crossing.
            if (std::abs(e.miss) + std::abs(best->miss) > 0.5 * D + 10.0 * dTheta * speed * e.t)
                continue;
            brackets.push_back(
                {from + j * dTheta, e.miss, from + (j + 1) * dTheta, best->miss, std::min(e.t, best->t)});
        }
    }
    std::sort(brackets.begin(), brackets.end(), [](const Bracket &p, const Bracket &q) { return p.tEst < q.tEst; });
    return brackets;
}

/// The shooting problem: from (x1, y1) at t0 to the goal (x2, y2).
struct ShootingProblem
{
    double x1, y1, x2, y2, t0;
};

/// Refines the bracket @p br by the Illinois method on the initial heading (extremals shot to @p horizon), and keeps
/// in @p sol an extremal through the goal, the fastest found (@p D the start's distance to the goal).
void refineBracket(const ZermeloReference &ref, const ZermeloParams &params, const ShootingProblem &s, Bracket br,
                   double horizon, double D, ZermeloSolution &sol)
{
    double tRef = br.tEst;
    ClosestApproach last;
    auto F = [&](double th, double &out) -> bool {
        const std::vector<ClosestApproach> ev = ref.shoot(s.x1, s.y1, th, s.t0, s.x2, s.y2, horizon);
        const ClosestApproach *best = nearestInTime(ev, tRef);
        if (!best)
            return false;
        last = *best;
        out = best->miss;
        return true;
    };
    double a = br.a, fa = 0.0, b = br.b, fb = 0.0;
    if (!F(a, fa))
        return;
    ClosestApproach la = last;
    if (!F(b, fb))
        return;
    ClosestApproach lb = last;
    if ((fa < 0.0) == (fb < 0.0))
        return;
    ClosestApproach cur = std::abs(fa) < std::abs(fb) ? la : lb;
    double curTh = std::abs(fa) < std::abs(fb) ? a : b;
    bool collapsed = false;
    for (int it = 0; it < 200; ++it)
    {
        collapsed = std::abs(b - a) < 1e-15;
        if (std::abs(cur.miss) <= 0.1 * params.goalTolerance || collapsed)
            break;
        const double c = illinoisPoint(a, fa, b, fb);
        double fc;
        tRef = cur.t;
        if (!F(c, fc))
            break;
        cur = last;
        curTh = c;
        illinoisUpdate(a, fa, b, fb, c, fc);
    }
    const double tolerance = collapsed ? std::max(params.goalTolerance, 1e-7 * D) : params.goalTolerance;
    if (!(std::abs(cur.miss) <= tolerance) || !cur.admissible)
        return;
    ++sol.extremalsThroughGoal;
    if (cur.t < sol.travelTime)
    {
        sol.found = true;
        sol.travelTime = cur.t;
        sol.initialHeading = std::remainder(curTh, kTwoPi);
        sol.missDistance = std::abs(cur.miss);
    }
}
} // namespace

ZermeloSolution ZermeloReference::solve(double x1, double y1, double x2, double y2, double t0) const
{
    ZermeloSolution sol;
    sol.travelTime = kInf;
    for (double v : {x1, y1, x2, y2, t0})
        if (!std::isfinite(v))
            throw Error("ZermeloReference::solve: start, goal and departure time must be finite");
    const double D = std::hypot(x2 - x1, y2 - y1);
    if (D == 0.0)
    {
        sol.found = true;
        sol.travelTime = 0.0;
        return sol;
    }
    const double tMax = params_.maxTime > 0.0 ? params_.maxTime : 6.0 * D / params_.speed;
    // the whole circle (the last heading neighbours the first) or a window with both ends scanned
    const bool circle = params_.headingSpan >= kTwoPi;
    const int n = params_.headingSamples;
    const int shotsCount = circle ? n : n + 1;
    const double dTheta = params_.headingSpan / n;
    const double from = params_.headingFrom;

    // 1. Scan: closest approaches of n extremals (loose tolerance: only brackets are needed).
    std::vector<std::vector<ClosestApproach>> shots(shotsCount);
    const auto stopped = [this] { return params_.stop && params_.stop(); };
    std::atomic<int> shot{0};
    const auto scan = [&](std::size_t j) {
        if (stopped())
            return;
        shots[j] = shoot(x1, y1, from + double(j) * dTheta, t0, x2, y2, tMax, params_.scanRelTol);
        ++shot;
    };
    if (params_.threads == 1)
        for (int j = 0; j < shotsCount; ++j)
            scan(std::size_t(j));
    else
        ThreadPool(params_.threads).parallelFor(std::size_t(shotsCount), scan);
    sol.headingsShot = shot.load();
    for (int j = 0; j < shotsCount; ++j)
        for (const ClosestApproach &e : shots[j])
            if (e.admissible && std::abs(e.miss) < sol.nearestMiss)
            {
                sol.nearestMiss = std::abs(e.miss);
                sol.nearestHeading = std::remainder(from + double(j) * dTheta, kTwoPi);
            }

    // 2. Brackets: a closest approach whose signed miss changes sign between neighbouring headings.
    const std::vector<Bracket> brackets = headingBrackets(shots, circle, from, dTheta, D, params_.speed);

    // 3. Refine each bracket (Illinois on the initial heading), keep the fastest extremal through the goal.
    for (Bracket br : brackets)
    {
        if ((sol.found && br.tEst > 1.1 * sol.travelTime + 1e-9) || stopped())
            break;
        const double horizon = std::min(tMax, 1.5 * br.tEst + 10.0 * dTheta * D / params_.speed) + 1e-9;
        refineBracket(*this, params_, {x1, y1, x2, y2, t0}, br, horizon, D, sol);
    }
    return sol;
}
} // namespace ompl_glider

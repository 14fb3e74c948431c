/// @file GoalWindow.cpp
/// @brief Goals in time ([ThompsonICRA] Sec. III): the arrival of a solved plan moved into the mission's
/// goal window (timeArrival()) by a hold at the goal, a hold at an earlier waypoint or a slower leg.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>

#include <ompl/geometric/PathGeometric.h>

#include "../../io/NumberText.h"
#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "ompl_glider/routes/PathSmoother.h"

namespace ompl_glider
{
namespace planning_detail
{
namespace
{
/// Marks a plan as having no path in the goal window, for the reason @p why.
void failArrival(PlannedPath &r, const std::string &why)
{
    r.solved = false;
    r.status = PlanStatus::NoPath;
    r.setNoPath({NoPathCause::ArrivalWindow, why});
    r.pathChecked = false;
}

/// Delays the arrival of one planned path into the goal window [begin, end] (timeArrival(), an arrival before the
/// window): the OMPL setup of the plan's departure checks every candidate path (every motion by the motion
/// validator, every state valid), and the first candidate that lands in the window is kept in the plan.
class ArrivalTimer
{
public:
    /// The setup of the plan's problem @p gp; its motion validator samples the current of a hold at least 512 times
    /// over the trip's time.
    /// @throws Error when the space has no TravelTimeMotionValidator (internal error)
    ArrivalTimer(PlannedPath &r, double begin, double end, double tol, const GliderProblem &gp)
        : r_(r), B_(begin), E_(end), tol_(tol), P_(r.path), n_(r.path.size() - 1)
    {
        ss_ = makeSimpleSetup(gp, &ctx_);
        si_ = ss_->getSpaceInformation();
        mv_ = std::dynamic_pointer_cast<TravelTimeMotionValidator>(si_->getMotionValidator());
        if (!mv_)
            throw Error("planRoute: the space has no TravelTimeMotionValidator (internal error)");
        // sample the current of a hold at least 512 times over the trip's time
        mv_->setHoldTimeStep(std::min(mv_->getHoldTimeStep(), std::max(B_ - r_.departure, 1e-9) / 512.0));
        cfc0_ = ctx_->travel->costFunctionCalls();
    }

    /// The cost function calls of the candidates tried so far.
    std::uint64_t costFunctionCalls() const { return ctx_->travel->costFunctionCalls() - cfc0_; }

    /// Step 1, the earliest valid arrival: hold at the goal from the arrival @p ta until the window opens.
    bool holdAtGoal(double ta)
    {
        if (!holdable(P_[n_], ta, B_))
            return false;
        std::vector<TimedPoint> cand = P_;
        cand.push_back({P_[n_].x, P_[n_].y, B_});
        return accept(std::move(cand), "hold at the goal");
    }

    /// Step 2 at waypoint @p k (tried from the last waypoint before the goal back to the start): a hold at waypoint
    /// k, else, when the leg k -> k + 1 is not itself a hold, that leg flown slower.
    bool delayAt(std::size_t k)
    {
        const TimedPoint &a = P_[k], &b = P_[k + 1];
        const bool holdLeg = a.x == b.x && a.y == b.y; // an existing hold: lengthen it below
        if (holdAtWaypoint(k, holdLeg))
            return true;
        return !holdLeg && slowerLeg(k);
    }

private:
    /// A candidate path: kept (in the plan, with how it was timed) when its arrival lies in the window and it passes
    /// PathGeometric::check().
    bool accept(std::vector<TimedPoint> cand, const std::string &how)
    {
        // land exactly on the window's begin when the arrival is within rounding of it
        if (std::abs(cand.back().t - B_) <= tol_ && cand.size() >= 2 && cand.back().t != B_)
            cand.back().t = std::max(B_, cand[cand.size() - 2].t);
        if (!(cand.back().t >= B_ - tol_ && cand.back().t <= E_ + tol_))
            return false;
        ompl::geometric::PathGeometric path(si_);
        waypointsToPath(cand, path);
        if (!path.check())
            return false;
        r_.path = std::move(cand);
        r_.travelTime = r_.path.back().t - r_.departure;
        r_.pathChecked = true;
        r_.arrivalTiming = how;
        return true;
    }

    /// The glider can hold at @p p over [t1, t2] (|c| < V there) and no forbidden region covers it then.
    bool holdable(const TimedPoint &p, double t1, double t2) const
    {
        const auto &env = ctx_->environment;
        return mv_->canHold(p.x, p.y, t1, t2) && (!env || env->legFree(p.x, p.y, t1, p.x, p.y, t2));
    }

    /// Waypoints 0..k as planned, then k -> k + 1 departing at @p tDepart in @p legDuration, then as fast as
    /// possible (legTravelTime()).
    std::vector<TimedPoint> flyOn(std::size_t k, double tDepart, double legDuration) const
    {
        std::vector<TimedPoint> out(P_.begin(), P_.begin() + static_cast<std::ptrdiff_t>(k) + 1);
        if (tDepart > out.back().t)
            out.push_back({P_[k].x, P_[k].y, tDepart});
        out.push_back({P_[k + 1].x, P_[k + 1].y, tDepart + legDuration});
        for (std::size_t i = k + 2; i <= n_ && std::isfinite(out.back().t); ++i)
        {
            const TimedPoint &a = out.back();
            const double dt = legTravelTime(*ctx_, a.x, a.y, P_[i].x, P_[i].y, a.t);
            out.push_back({P_[i].x, P_[i].y, a.t + dt});
        }
        return out;
    }

    /// The flight of the smallest x in [lo, hi] with arrival(x) >= B: a scan at 33 points for the first bracket
    /// [a, b] with a finite arrival before B at a and in reach of B at b (the arrival jumps or is infeasible where
    /// the path meets the current at other times), then bisection inside it (arrival non-decreasing in x there).
    /// Empty when no x in [lo, hi] arrives in the window.
    std::vector<TimedPoint> bisect(double lo, double hi,
                                   const std::function<std::vector<TimedPoint>(double)> &fly) const
    {
        constexpr int kScan = 32;
        double a = lo;
        std::vector<TimedPoint> best;
        for (int i = 0; i <= kScan; ++i)
        {
            const double x = lo + (hi - lo) * i / kScan;
            std::vector<TimedPoint> c = fly(x);
            const double t = c.back().t;
            if (!std::isfinite(t))
                continue;
            if (t < B_ - tol_)
                a = x;
            else if (t <= E_ + tol_ && x > a)
            {
                best = std::move(c);
                hi = x;
                break;
            }
        }
        if (best.empty())
            return {};
        lo = a;
        for (int it = 0; it < 60 && best.back().t > B_ + tol_ && hi - lo > 1e-12 * std::max(1.0, std::abs(hi)); ++it)
        {
            const double mid = 0.5 * (lo + hi);
            std::vector<TimedPoint> c = fly(mid);
            if (std::isfinite(c.back().t) && c.back().t >= B_ - tol_)
            {
                hi = mid;
                if (c.back().t <= E_ + tol_)
                    best = std::move(c);
            }
            else
                lo = mid;
        }
        return best;
    }

    /// The longest hold at @p a from @p tk, at most until the window opens: all of it when the glider can hold
    /// that long, else the longest it can, found by bisection.
    double longestHold(const TimedPoint &a, double tk) const
    {
        double hMax = B_ - tk;
        if (!holdable(a, tk, tk + hMax))
        {
            double lo = 0.0, hi = hMax;
            for (int it = 0; it < 40; ++it)
            {
                const double mid = 0.5 * (lo + hi);
                (holdable(a, tk, tk + mid) ? lo : hi) = mid;
            }
            hMax = lo;
        }
        return hMax;
    }

    /// Hold at waypoint @p k (k = 0: a later departure from the start), as long as the glider can; @p holdLeg:
    /// the leg k -> k + 1 is a hold, which is lengthened.
    bool holdAtWaypoint(std::size_t k, bool holdLeg)
    {
        const TimedPoint &a = P_[k], &b = P_[k + 1];
        const double tk = a.t;
        const double hMax = longestHold(a, tk);
        if (!(hMax > 0.0))
            return false;
        auto fly = [&](double h) {
            if (holdLeg) // lengthen the hold k -> k + 1
                return flyOn(k, tk, b.t - tk + h);
            const double dt = legTravelTime(*ctx_, a.x, a.y, b.x, b.y, tk + h);
            return flyOn(k, tk + h, dt);
        };
        std::vector<TimedPoint> c = bisect(0.0, hMax, fly);
        const std::string how =
            k == 0 ? std::string("later departure (hold at the start)") : "hold at waypoint " + std::to_string(k);
        return !c.empty() && accept(std::move(c), how);
    }

    /// Fly the leg k -> k + 1 slower: any duration in its arrival window.
    bool slowerLeg(std::size_t k)
    {
        const TimedPoint &a = P_[k], &b = P_[k + 1];
        const double tk = a.t;
        const ArrivalWindow aw = ctx_->travel->arrivalWindow(a.x, a.y, b.x, b.y, tk);
        if (!std::isfinite(aw.earliest))
            return false;
        const double dMax = std::min(std::isfinite(aw.latest) ? aw.latest : kInf, B_ - tk);
        if (!(dMax > aw.earliest))
            return false;
        std::vector<TimedPoint> c = bisect(aw.earliest, dMax, [&](double d) { return flyOn(k, tk, d); });
        char how[96];
        std::snprintf(how, sizeof how, "slower leg %zu -> %zu", k, k + 1);
        return !c.empty() && accept(std::move(c), how);
    }

    PlannedPath &r_;
    const double B_, E_, tol_; ///< the window's begin and end, and the rounding tolerance of arrivals
    /// The planned path (the plan's own, replaced only by the accepted candidate) and the index of its goal
    const std::vector<TimedPoint> &P_;
    const std::size_t n_;
    std::shared_ptr<GliderContext> ctx_;
    ompl::geometric::SimpleSetupPtr ss_;
    ompl::base::SpaceInformationPtr si_;
    std::shared_ptr<TravelTimeMotionValidator> mv_;
    std::uint64_t cfc0_{0}; ///< the travel time calculator's cost function calls before any candidate
};
} // namespace

double holdTimeOf(const std::vector<TimedPoint> &path)
{
    double hold = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
        if (path[i].x == path[i - 1].x && path[i].y == path[i - 1].y)
            hold += path[i].t - path[i - 1].t;
    return hold;
}

std::string timeText(const MissionProblem &problem, double t)
{
    char text[64];
    std::snprintf(text, sizeof text, "t = %.6g", t);
    const std::string iso = problem.isoTime(t);
    return iso.empty() ? std::string(text) : std::string(text) + " (" + iso + ")";
}

/// Goals in time ([ThompsonICRA] Sec. III, the earliest valid arrival): moves the arrival of a solved plan
/// into the goal window [begin, end] of the mission. Early: hold at the goal where the glider can (|c| < V over the
/// hold, TravelTimeMotionValidator::canHold); else time the arrival: from the last waypoint before the goal back to
/// the start, hold there (where |c| < V) or fly the leg leaving it slower (any pace in its arrival window), the rest of
/// the path flown as fast as possible (legTravelTime), the delay found by bisection (the arrival of a fastest flight
/// does not decrease with its departure on each leg, FIFO); the first candidate whose arrival lands in the window and
/// whose path passes PathGeometric::check() is kept. Late, or no candidate: no path in the window (solved false).
void timeArrival(const MissionProblem &problem, PlannedPath &r)
{
    const MissionSpec &m = problem.getSpec();
    const GoalWindowSpec &w = m.goalWindow;
    if (!w.set || !r.solved || r.path.empty() || (r.stints && !r.stints->converted))
        return;
    const double B = w.begin, E = w.end;
    // the rounding tolerance of the ends given (a via point's window may give one end only, the other infinite)
    const double tol =
        1e-9 * std::max({1.0, std::isfinite(B) ? std::abs(B) : 0.0, std::isfinite(E) ? std::abs(E) : 0.0});
    const std::string window =
        !std::isfinite(E)   ? "the arrival window opening at " + timeText(problem, B)
        : !std::isfinite(B) ? "the arrival window closing at " + timeText(problem, E)
                            : "the goal's arrival window [" + timeText(problem, B) + ", " + timeText(problem, E) + "]";
    const double ta = r.path.back().t;
    if (ta > E + tol)
    {
        failArrival(r, "the path reaches the goal at " + timeText(problem, ta) + ", after the end of " + window +
                           ": no path arrives in the window (depart earlier, or widen the window)");
        return;
    }
    if (ta >= B - tol)
    {
        // already in the window (a lattice planner holds at the goal itself: TveOptions::waiting)
        if (r.path.size() >= 2 && lastHoldEnd(r.path) == r.path.size() - 1)
            r.arrivalTiming = "hold at the goal";
        return;
    }

    GliderProblem gp = checkedProblem(problem, r.departure, r.speed);
    if (B > gp.t0 + gp.horizon)
    {
        failArrival(r,
                    window + " opens after the planning horizon ends (" + timeText(problem, gp.t0 + gp.horizon) + ")");
        return;
    }
    ArrivalTimer timer(r, B, E, tol, gp);
    // 1. hold at the goal: the earliest valid arrival
    if (timer.holdAtGoal(ta))
    {
        r.postprocessCostFunctionCalls += timer.costFunctionCalls();
        return;
    }
    if (r.headingRoute())
    {
        // a route of held headings has no leg to slow down, and its waypoints are not places to hold at
        r.postprocessCostFunctionCalls += timer.costFunctionCalls();
        failArrival(r, "the heading route reaches the goal at " + timeText(problem, ta) + ", before " + window +
                           " opens, and the glider cannot hold at the goal (the current reaches its speed there)");
        return;
    }
    // 2. time the arrival: a slower leg or a hold at an earlier waypoint, latest first
    for (std::size_t k = r.path.size() - 1; k-- > 0;)
        if (timer.delayAt(k))
            break;
    r.postprocessCostFunctionCalls += timer.costFunctionCalls();
    if (r.arrivalTiming.empty())
        failArrival(r, "the path reaches the goal at " + timeText(problem, ta) + ", before " + window +
                           " opens; the glider cannot hold at the goal (the current reaches its speed there) and no "
                           "slower leg or hold at an earlier waypoint lands the arrival in the window");
}
} // namespace planning_detail
} // namespace ompl_glider

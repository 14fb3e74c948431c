/// @file MissionLegs.cpp
/// @brief Missions of several legs (MissionLegs.h): the legs planned in turn on one clock, stays held, the whole route
/// assembled, and the free-order search (branch and bound over the via points' orders with planned leg times).

#include "ompl_glider/mission/MissionLegs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "../../io/NumberText.h"
#include "PlanningInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/routes/PathSmoother.h"

namespace ompl_glider
{
namespace
{
using planning_detail::durationText;
using planning_detail::timeText;

/// Names and places of the mission's points: index -1 the start, n the goal, 0..n-1 the via points.
struct Stops
{
    const MissionProblem &problem;
    std::size_t n;
    explicit Stops(const MissionProblem &p) : problem(p), n(p.getViaPoints().size()) {}
    Point2 point(int i) const
    {
        return i < 0 ? problem.getStart() : i >= static_cast<int>(n) ? problem.getGoal() : problem.getViaPoints()[i];
    }
    std::string name(int i) const
    {
        return i < 0 ? "start" : i >= static_cast<int>(n) ? "goal" : problem.getSpec().waypoints[i].name;
    }
    GoalWindowSpec window(int i) const
    {
        return i >= static_cast<int>(n) ? problem.getSpec().goalWindow : problem.getSpec().waypoints[i].arrive;
    }
    double stay(int i) const { return i < 0 || i >= static_cast<int>(n) ? 0.0 : problem.getSpec().waypoints[i].stay; }
};

/// Why the glider cannot hold at @p p over [t1, t2] (the motion validator's hold test: in water, within the forecast,
/// |c| < V at its samples; no forbidden region there then); empty when it can.
std::string whyNoStay(const MissionProblem &problem, Point2 p, double t1, double t2, double speed)
{
    const double end = problem.getField()->timeEnd();
    if (std::isfinite(end) && t2 > end)
        return "the stay would end at " + timeText(problem, t2) + ", after the forecast ends (" +
               timeText(problem, end) + ")";
    std::shared_ptr<GliderContext> ctx;
    makeSimpleSetup(problem.gliderProblem(t1, speed), &ctx);
    if (ctx->canHold(p.x, p.y, t1, t2, ctx->holdTimeStep()) &&
        (!ctx->environment || ctx->environment->legFree(p.x, p.y, t1, p.x, p.y, t2)))
        return "";
    // the figures: the fastest current met over the stay
    double fastest = 0.0, when = t1;
    const int samples = 256;
    for (int i = 0; i <= samples; ++i)
    {
        const double t = t1 + (t2 - t1) * i / samples;
        const Velocity c = problem.getField()->velocity(p.x, p.y, problem.getSpec().vehicle.depth, t);
        if (std::hypot(c.u, c.v) > fastest)
        {
            fastest = std::hypot(c.u, c.v);
            when = t;
        }
    }
    if (fastest >= speed)
    {
        const bool metres = problem.getSpec().current.isForecast();
        return "the current there reaches " + text::number(fastest, 4) + (metres ? " m/s" : "") + " at " +
               timeText(problem, when) + ", faster than the glider's " + text::number(speed, 4) +
               (metres ? " m/s" : "") + ": it cannot hold position for the stay (a virtual mooring needs |c| < V)";
    }
    return "a forbidden region covers the point during the stay";
}

/// A leg's bad input in the mission's terms: the leg's start or goal is a via point, its departure a time on the
/// mission's clock (only the first leg's is the pilot's).
std::string legBadInput(const std::string &badInput, int from, int to, std::size_t n, std::size_t leg)
{
    if (badInput.empty())
        return "";
    if (badInput == "start")
        return from < 0 ? "start" : "waypoints[" + std::to_string(from) + "]";
    if (badInput == "goal")
        return to >= static_cast<int>(n) ? "goal" : "waypoints[" + std::to_string(to) + "]";
    return leg == 0 ? badInput : ""; // a later leg's departure after the forecast: no path, not bad input
}

/// Plans the legs of the stops in @p order (via indices) from @p departure; each leg planned once per (from, to,
/// departure) over a search (the cache).
class LegPlanner
{
public:
    LegPlanner(const MissionProblem &problem, const PlanOptions &options)
        : problem_(problem), stops_(problem), options_(options)
    {
    }

    /// The leg from stop @p from to stop @p to departing at @p t (planRoute() on withLeg()).
    const PlannedLeg &leg(int from, int to, double t)
    {
        const auto key = std::make_tuple(from, to, t);
        const auto it = cache_.find(key);
        if (it != cache_.end())
            return it->second;
        PlannedLeg l;
        l.from = stops_.name(from);
        l.to = stops_.name(to);
        l.fromVia = from;
        l.toVia = to >= static_cast<int>(stops_.n) ? -1 : to;
        l.fromPoint = stops_.point(from);
        l.toPoint = stops_.point(to);
        l.window = stops_.window(to);
        l.stay = stops_.stay(to);
        const MissionProblem legProblem = problem_.withLeg(l.fromPoint, l.toPoint, l.window);
        l.plan = planRoute(legProblem, t, options_);
        planning_detail::diagnoseNoPath(legProblem, t, l.plan);
        ++planned_;
        return cache_.emplace(key, std::move(l)).first->second;
    }

    /// Why the stay at the end of @p l cannot be held (empty when it can, or there is none).
    std::string stayProblem(const PlannedLeg &l) const
    {
        if (!(l.stay > 0.0) || !l.plan.solved)
            return "";
        return whyNoStay(problem_, l.toPoint, l.arrival(), l.arrival() + l.stay, l.plan.speed);
    }

    std::size_t planned() const { return planned_; }
    const Stops &stops() const { return stops_; }

private:
    const MissionProblem &problem_;
    Stops stops_;
    PlanOptions options_;
    std::map<std::tuple<int, int, double>, PlannedLeg> cache_;
    std::size_t planned_{0};
};

/// The legs of @p order from @p departure, in turn, until the goal or the first leg without a route (or a stay that
/// cannot be held: that leg is kept, marked unsolved with the reason).
std::vector<PlannedLeg> flyOrder(LegPlanner &planner, const std::vector<std::size_t> &order, double departure)
{
    std::vector<PlannedLeg> legs;
    int from = -1;
    double t = departure;
    for (std::size_t k = 0; k <= order.size(); ++k)
    {
        const int to = k < order.size() ? static_cast<int>(order[k]) : static_cast<int>(planner.stops().n);
        PlannedLeg l = planner.leg(from, to, t);
        l.index = k;
        const std::string why = planner.stayProblem(l);
        if (!why.empty())
        {
            l.plan.solved = false;
            l.plan.status = PlanStatus::NoPath;
            l.plan.setNoPath({NoPathCause::ArrivalWindow,
                              "stay at " + l.to + " for " + durationText(planner.stops().problem, l.stay) + ": " + why});
        }
        legs.push_back(std::move(l));
        if (!legs.back().plan.solved)
            break;
        t = legs.back().arrival() + legs.back().stay;
        from = to;
    }
    return legs;
}

/// Appends @p add to @p to, leaving out a first point at the time of the last one there and within @p gap of it (a
/// heading route ends within its goal tolerance of the via point the next leg leaves from).
void append(std::vector<TimedPoint> &to, const std::vector<TimedPoint> &add, double gap = 0.0)
{
    for (std::size_t i = 0; i < add.size(); ++i)
    {
        if (i == 0 && !to.empty() && to.back().t == add[i].t &&
            std::hypot(to.back().x - add[i].x, to.back().y - add[i].y) <= gap)
            continue;
        to.push_back(add[i]);
    }
}

/// The whole route of @p legs (all solved, or the first unsolved one last).
PlannedPath assemble(const MissionProblem &problem, std::vector<PlannedLeg> &legs, double departure)
{
    const MissionSpec &m = problem.getSpec();
    PlannedPath r;
    r.departure = departure;
    r.speed = legs.front().plan.speed;
    r.planner = legs.front().plan.planner;
    bool all = true, headings = true, anyHeadings = false, stays = false;
    for (const PlannedLeg &l : legs)
    {
        all = all && l.plan.solved;
        headings = headings && l.plan.headingRoute();
        anyHeadings = anyHeadings || l.plan.headingRoute();
        stays = stays || l.stay > 0.0;
    }
    const PlannedLeg &last = legs.back();
    if (!all)
    {
        const PlannedLeg &bad = last;
        r.status = bad.plan.status == PlanStatus::ExactSolution ? PlanStatus::NoPath : bad.plan.status;
        r.plannerStatus = bad.plan.plannerStatus;
        // the leg's cause and figures, its words after the leg's name
        const std::string leg = "leg " + std::to_string(bad.index + 1) + ", " + bad.from + " to " + bad.to + ": ";
        NoPath why = bad.plan.noPath;
        why.leg = bad.index + 1;
        why.what = leg + why.what;
        if (bad.plan.badInput == "departure.time" && bad.index > 0)
            why.what = leg + "it would depart at " + timeText(problem, bad.plan.departure) +
                       ", after the end of the forecast";
        r.setNoPath(std::move(why));
        r.badInput = legBadInput(bad.plan.badInput, bad.fromVia,
                                 bad.toVia < 0 ? static_cast<int>(m.waypoints.size()) : bad.toVia, m.waypoints.size(),
                                 bad.index);
        for (const PlannedLeg &l : legs)
            planning_detail::addPlanningWork(r, l.plan);
        return r;
    }
    r.solved = true;
    r.status = last.plan.status;
    r.plannerStatus = last.plan.plannerStatus;
    r.pathChecked = r.reflown = true;
    double rawTime = 0.0, smoothedTime = 0.0;
    for (PlannedLeg &l : legs)
    {
        const PlannedPath &p = l.plan;
        l.firstPoint = r.path.empty() ? 0 : r.path.size() - 1;
        if (!r.path.empty() && r.path.back().t != p.path.front().t)
            l.firstPoint = r.path.size(); // after a stay the leg starts with a hold's end
        const double gap = problem.gliderProblem(p.departure, r.speed).goalTolerance + 1e-9 * r.pathLength;
        append(r.path, p.path, gap);
        l.lastPoint = r.path.size() - 1;
        append(r.raw, p.raw, gap);
        append(r.smoothed, p.smoothed, gap);
        if (anyHeadings)
            append(r.track, p.headingRoute() ? p.track : p.path, gap);
        rawTime += p.rawTravelTime;
        smoothedTime += p.smoothedTravelTime;
        r.rawPathLength += p.rawPathLength;
        r.pathLength += p.pathLength;
        planning_detail::addPlanningWork(r, p);
        r.pathChecked = r.pathChecked && p.pathChecked;
        r.reflown = r.reflown && p.reflown;
        if (r.switchedFrom.empty() && !p.switchedFrom.empty())
        {
            r.switchedFrom = p.switchedFrom;
            r.switchReason = "leg " + std::to_string(l.index + 1) + ": " + p.switchReason;
            r.planner = p.planner;
        }
        if (!p.arrivalTiming.empty())
            r.arrivalTiming += (r.arrivalTiming.empty() ? "" : "; ") + std::string("leg ") +
                               std::to_string(l.index + 1) + ": " + p.arrivalTiming;
        if (l.stay > 0.0 && &l != &legs.back())
        {
            TimedPoint hold = r.path.back();
            hold.t += l.stay;
            r.path.push_back(hold); // the stay: a hold, flown as the motion validator's hold
            r.raw.push_back(hold);
            r.smoothed.push_back(hold);
            if (anyHeadings)
                r.track.push_back(hold);
        }
        rawTime += &l != &legs.back() ? l.stay : 0.0;
        smoothedTime += &l != &legs.back() ? l.stay : 0.0;
    }
    if (headings && !stays)
    {
        HeadingRoute h = *legs.front().plan.headings;
        for (std::size_t k = 1; k < legs.size(); ++k)
            for (const HeadingSegment &s : legs[k].plan.headings->segments)
                h.segments.push_back(s);
        r.headings = std::move(h);
    }
    r.travelTime = r.path.back().t - departure;
    r.rawTravelTime = rawTime;
    r.smoothedTravelTime = smoothedTime;
    r.reflownTravelTime = r.reflown ? r.travelTime : std::numeric_limits<double>::quiet_NaN();
    // straight legs end on their via point; a heading route where its re-flight ended
    r.reflownEndDistance = 0.0;
    for (const PlannedLeg &l : legs)
        if (l.plan.headingRoute() && std::isfinite(l.plan.reflownEndDistance))
            r.reflownEndDistance = std::max(r.reflownEndDistance, l.plan.reflownEndDistance);
    r.holdTime = planning_detail::holdTimeOf(r.path);
    // the straight line of the mission: each leg flown straight in turn from the previous straight leg's arrival
    double t = departure;
    for (const PlannedLeg &l : legs)
    {
        r.straightLineLength += std::hypot(l.toPoint.x - l.fromPoint.x, l.toPoint.y - l.fromPoint.y);
        if (!std::isfinite(t))
            continue;
        const double end = problem.getField()->timeEnd();
        if (std::isfinite(end) && t >= end)
        {
            t = kInf;
            continue;
        }
        std::shared_ptr<GliderContext> ctx;
        makeSimpleSetup(problem.withLeg(l.fromPoint, l.toPoint, {}).gliderProblem(t, r.speed), &ctx);
        t += legTravelTime(*ctx, l.fromPoint.x, l.fromPoint.y, l.toPoint.x, l.toPoint.y, t) + l.stay;
    }
    r.straightLineTime = std::isfinite(t) ? t - departure - legs.back().stay : kInf;
    return r;
}

/// Lower bounds of the free-order search: the shortest straight tour from a point through a set of via points to the
/// goal (exact over their orders, by dynamic programming over subsets of distances).
class TourBound
{
public:
    explicit TourBound(const Stops &s) : s_(s), n_(s.n), memo_((std::size_t{1} << n_) * n_, -1.0) {}

    /// Shortest straight tour from @p at through the via points of @p mask (any order) ending at the goal.
    double from(Point2 at, unsigned mask)
    {
        if (mask == 0)
            return dist(at, s_.point(static_cast<int>(n_)));
        double best = kInf;
        for (std::size_t j = 0; j < n_; ++j)
            if (mask & (1u << j))
                best = std::min(best, dist(at, s_.point(static_cast<int>(j))) + tail(j, mask & ~(1u << j)));
        return best;
    }

private:
    static double dist(Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.y - a.y); }
    /// From via point @p i through @p mask to the goal.
    double tail(std::size_t i, unsigned mask)
    {
        double &v = memo_[mask * n_ + i];
        if (v < 0.0)
            v = from(s_.point(static_cast<int>(i)), mask);
        return v;
    }
    const Stops &s_;
    std::size_t n_;
    std::vector<double> memo_;
};

/// remainingTimeBound() over the via points of @p mask, with the search's @p tour (its memo kept between calls).
double timeBound(const Stops &s, TourBound &tour, Point2 at, double t, unsigned mask, double fastest)
{
    double stays = 0.0;
    for (std::size_t i = 0; i < s.n; ++i)
        if (mask & (1u << i))
            stays += s.stay(static_cast<int>(i));
    double bound = t + tour.from(at, mask) / fastest + stays;
    // a point's window opens at its begin: the rest of the tour cannot start from it earlier
    const Point2 goal = s.problem.getGoal();
    for (std::size_t i = 0; i < s.n; ++i)
    {
        const GoalWindowSpec w = s.window(static_cast<int>(i));
        if ((mask & (1u << i)) && w.set)
        {
            const Point2 p = s.point(static_cast<int>(i));
            bound = std::max(bound,
                             w.begin + s.stay(static_cast<int>(i)) + std::hypot(goal.x - p.x, goal.y - p.y) / fastest);
        }
    }
    const GoalWindowSpec &g = s.problem.getSpec().goalWindow;
    return g.set ? std::max(bound, g.begin) : bound;
}

/// The most leg plans the free-order search makes without a time limit (its work bounded by a count, so that two
/// runs agree on any machine): a few minutes of legs on a fine lattice; a pilot who wants more sets a time limit.
constexpr std::size_t kMaxOrderLegs = 1000;

/// The free-order search: depth first over orders, each prefix's legs planned once (the cache), a prefix dropped as
/// soon as its arrival plus the time bound (timeBound()) cannot beat the best complete order so far. The given order is
/// planned first: its time is the first bound and the reference of the gain.
class OrderSearcher
{
public:
    /// @p timeLimit: the pilot's time limit for the whole search (seconds; 0: none, the budget of leg plans bounds it)
    OrderSearcher(const MissionProblem &problem, LegPlanner &planner, double departure, double speed, double timeLimit)
        : planner_(planner), departure_(departure), speed_(speed), tour_(planner.stops()), timeLimit_(timeLimit),
          started_(std::chrono::steady_clock::now())
    {
        Region box = problem.getBox();
        maxCurrent_ = problem.getField()->maxSpeed(box);
    }

    OrderSearch run(std::vector<PlannedLeg> &bestLegs, std::vector<std::size_t> &bestOrder)
    {
        const std::size_t n = planner_.stops().n;
        OrderSearch s;
        s.given.resize(n);
        std::iota(s.given.begin(), s.given.end(), std::size_t{0});
        s.ordersTotal = 1;
        for (std::size_t k = 2; k <= n; ++k)
            s.ordersTotal *= k;
        std::vector<PlannedLeg> given = flyOrder(planner_, s.given, departure_);
        evaluatedOrders_.insert(s.given);
        if (given.back().plan.solved && given.size() == n + 1)
        {
            s.givenTime = given.back().arrival() - departure_;
            best_ = s.givenTime;
            bestOrder_ = s.given;
            bestLegs_ = given;
        }
        std::vector<std::size_t> prefix;
        std::vector<PlannedLeg> legs;
        search(-1, departure_, (1u << n) - 1u, prefix, legs);
        s.stopped = stopped_;
        s.ordersEvaluated = evaluatedOrders_.size();
        s.legsPlanned = planner_.planned();
        if (std::isfinite(best_))
        {
            s.chosen = bestOrder_;
            s.chosenTime = best_;
            s.gain = std::isfinite(s.givenTime) ? 1.0 - s.chosenTime / s.givenTime : 1.0;
            bestLegs = bestLegs_;
            bestOrder = bestOrder_;
        }
        else
        {
            bestLegs = std::move(given); // no order has a route: the given order's failure is the reason
            bestOrder = s.given;
        }
        return s;
    }

private:
    void search(int from, double t, unsigned remaining, std::vector<std::size_t> &prefix, std::vector<PlannedLeg> &legs)
    {
        const std::size_t n = planner_.stops().n;
        if (remaining == 0)
        {
            if (outOfTime())
                return;
            PlannedLeg l = planner_.leg(from, static_cast<int>(n), t);
            l.index = legs.size();
            evaluatedOrders_.insert(prefix);
            if (l.plan.solved && l.arrival() - departure_ < best_)
            {
                best_ = l.arrival() - departure_;
                bestOrder_ = prefix;
                bestLegs_ = legs;
                bestLegs_.push_back(std::move(l));
            }
            return;
        }
        for (std::size_t j = 0; j < n; ++j)
        {
            if (!(remaining & (1u << j)))
                continue;
            const unsigned rest = remaining & ~(1u << j);
            // the bound before planning the leg: from here through j first
            const Point2 here = planner_.stops().point(from);
            const Point2 pj = planner_.stops().point(static_cast<int>(j));
            const double reach = t + std::hypot(pj.x - here.x, pj.y - here.y) / (speed_ + maxCurrent_);
            if (bound(j, std::max(reach, windowBegin(j)), rest) >= best_ || windowMissed(j, reach, rest))
                continue;
            if (outOfTime())
                return;
            PlannedLeg l = planner_.leg(from, static_cast<int>(j), t);
            l.index = legs.size();
            if (!l.plan.solved || !planner_.stayProblem(l).empty())
                continue; // this prefix has no route
            const double next = l.arrival() + l.stay;
            if (bound(j, l.arrival(), rest) >= best_ || windowMissed(j, l.arrival(), rest))
                continue;
            prefix.push_back(j);
            legs.push_back(std::move(l));
            search(static_cast<int>(j), next, rest, prefix, legs);
            legs.pop_back();
            prefix.pop_back();
        }
    }

    /// True when the search must stop (the reason in stopped_): a stop request, the pilot's time limit, or the budget
    /// of leg plans spent. The best order so far stands.
    bool outOfTime()
    {
        if (!stopped_.empty())
            return true;
        if (stopRequested())
            stopped_ = "a stop request";
        else if (timeLimit_ > 0.0 &&
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() > timeLimit_)
            stopped_ = "the time limit of " + text::number(timeLimit_) + " s";
        else if (planner_.planned() >= kMaxOrderLegs)
            stopped_ = "the budget of " + std::to_string(kMaxOrderLegs) + " leg plans";
        return !stopped_.empty();
    }

    /// True when arriving at via point @p j at @p t (or later) misses its window's end, or leaves a via point of
    /// @p rest or the goal no time to be reached before its window ends (straight at the fastest speed, after the stay
    /// at j): no order through this prefix keeps its windows.
    bool windowMissed(std::size_t j, double t, unsigned rest) const
    {
        const Stops &s = planner_.stops();
        const GoalWindowSpec wj = s.window(static_cast<int>(j));
        if (wj.set && t > wj.end)
            return true;
        const double leave = (wj.set ? std::max(t, wj.begin) : t) + s.stay(static_cast<int>(j));
        const Point2 pj = s.point(static_cast<int>(j));
        for (std::size_t i = 0; i <= s.n; ++i)
        {
            if (i < s.n && !(rest & (1u << i)))
                continue;
            const GoalWindowSpec w = s.window(static_cast<int>(i));
            const Point2 p = s.point(static_cast<int>(i));
            if (w.set && leave + std::hypot(p.x - pj.x, p.y - pj.y) / (speed_ + maxCurrent_) > w.end)
                return true;
        }
        return false;
    }

    double windowBegin(std::size_t j) const
    {
        const GoalWindowSpec w = planner_.stops().window(static_cast<int>(j));
        return w.set ? w.begin : -kInf;
    }

    /// Lower bound of the mission's travel time arriving at via point @p j at @p t with @p rest still to visit.
    double bound(std::size_t j, double t, unsigned rest)
    {
        const Stops &s = planner_.stops();
        const double after = t + s.stay(static_cast<int>(j));
        return timeBound(s, tour_, s.point(static_cast<int>(j)), after, rest, speed_ + maxCurrent_) - departure_;
    }

    LegPlanner &planner_;
    double departure_, speed_, maxCurrent_{0.0};
    TourBound tour_; // the shortest straight tours, memoised over the whole search
    double timeLimit_;
    std::chrono::steady_clock::time_point started_;
    std::string stopped_; // why the search stopped early (empty: it finished)
    double best_{kInf};
    std::vector<std::size_t> bestOrder_;
    std::vector<PlannedLeg> bestLegs_;
    std::set<std::vector<std::size_t>> evaluatedOrders_; // complete orders planned to the goal
};
} // namespace

double remainingTimeBound(const MissionProblem &problem, Point2 at, double t, const std::vector<std::size_t> &remaining,
                          double speed, double maxCurrent)
{
    const Stops s(problem);
    TourBound tour(s);
    unsigned mask = 0;
    for (const std::size_t i : remaining)
        mask |= 1u << i;
    return timeBound(s, tour, at, t, mask, speed + maxCurrent);
}

OptimumReference missionOptimumReference(const MissionProblem &problem, const MissionResult &result)
{
    OptimumReference out;
    double t = result.plan.departure;
    for (const PlannedLeg &l : result.legs)
    {
        const MissionProblem leg = problem.withLeg(l.fromPoint, l.toPoint, {});
        const double bound = l.plan.solved ? 1.2 * l.plan.travelTime + std::max(0.0, l.departure() - t)
                                           : leg.gliderProblem(t, result.plan.speed).horizon;
        const OptimumReference r = optimumReference(leg, t, result.plan.speed, bound);
        if (!r.found)
            return OptimumReference{};
        append(out.path, r.path);
        t += r.travelTime;
        if (l.window.set)
            t = std::max(t, l.window.begin);
        if (&l != &result.legs.back())
            t += l.stay;
    }
    out.found = true;
    out.travelTime = t - result.plan.departure;
    return out;
}

MissionPlan planMission(const MissionProblem &problem, double departure, const PlanOptions &options)
{
    const MissionSpec &m = problem.getSpec();
    MissionPlan out;
    if (m.waypoints.empty())
    {
        out.plan = planRoute(problem, departure, options);
        return out;
    }
    if (m.stints.set)
        throw Error(m.place("stints") + ": a mission with via points ('waypoints') is planned leg by leg; the stints "
                                        "section (one stint plan from start to goal) cannot be combined with it");
    LegPlanner planner(problem, options);
    if (m.order == VisitOrder::Free)
    {
        OrderSearcher search(problem, planner, departure, std::isnan(options.speed) ? m.vehicle.speed : options.speed,
                             options.timeLimit > 0.0 ? options.timeLimit : m.planner.timeLimit);
        out.orderSearch = search.run(out.legs, out.order);
    }
    else
    {
        out.order.resize(m.waypoints.size());
        std::iota(out.order.begin(), out.order.end(), std::size_t{0});
        out.legs = flyOrder(planner, out.order, departure);
    }
    out.plan = assemble(problem, out.legs, departure);
    return out;
}
} // namespace ompl_glider

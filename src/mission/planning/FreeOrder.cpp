/// @file FreeOrder.cpp
/// @brief The free-order search of a mission of several legs (`order: free`): branch and bound over the via points'
/// orders with planned leg times, bounded below by the shortest straight tour (MissionLegs.h).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <set>

#include "../../io/NumberText.h"
#include "LegPlanner.h"
#include "PlanningInternal.h"
#include "ompl_glider/StopRequest.h"

namespace ompl_glider
{
namespace
{
using planning_detail::LegPlanner;
using planning_detail::Stops;

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

namespace planning_detail
{
OrderSearch searchFreeOrder(const MissionProblem &problem, LegPlanner &planner, double departure, double speed,
                            double timeLimit, std::vector<PlannedLeg> &bestLegs, std::vector<std::size_t> &bestOrder)
{
    OrderSearcher search(problem, planner, departure, speed, timeLimit);
    return search.run(bestLegs, bestOrder);
}
} // namespace planning_detail
} // namespace ompl_glider

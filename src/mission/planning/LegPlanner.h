#pragma once
/// @file LegPlanner.h
/// @brief Internal to planning/: the stops of a mission of several legs and the planner of its legs (MissionLegs.cpp),
/// shared with the free-order search (FreeOrder.cpp). Not installed.

#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "ompl_glider/mission/MissionLegs.h"
#include "ompl_glider/mission/MissionProblem.h"

namespace ompl_glider::planning_detail
{
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
    const PlannedLeg &leg(int from, int to, double t);

    /// Why the stay at the end of @p l cannot be held (empty when it can, or there is none).
    std::string stayProblem(const PlannedLeg &l) const;

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
std::vector<PlannedLeg> flyOrder(LegPlanner &planner, const std::vector<std::size_t> &order, double departure);

/// The free-order search (FreeOrder.cpp) from @p departure at @p speed within @p timeLimit seconds (0: its budget of
/// leg plans): the best order and its legs into @p bestOrder and @p bestLegs.
OrderSearch searchFreeOrder(const MissionProblem &problem, LegPlanner &planner, double departure, double speed,
                            double timeLimit, std::vector<PlannedLeg> &bestLegs, std::vector<std::size_t> &bestOrder);
} // namespace ompl_glider::planning_detail

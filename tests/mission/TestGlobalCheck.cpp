// The global check of the route class: the default finds the route of another class that the lattice misses (against
// the jet), says which candidate won in the report and summary.json, and the optimal-control reference (--optimum)
// keeps to the region. References: the independent extremal sweep (ExtremalSweep.h, its own RK4) and closed forms.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>
#include <sstream>

#include <nlohmann/json.hpp>
#include <ompl/util/Console.h>

#include "TrustCases.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/output/Report.h"
#include "ompl_glider/output/SummaryJson.h"

namespace
{
using namespace ompl_glider;

MissionSpec jetPair(Point2 s, Point2 g, double speed, double departure)
{
    MissionSpec m = defaultGulfStreamMission();
    m.start.xy = s;
    m.goal.xy = g;
    m.vehicle.speed = m.travel.speed = speed;
    m.departure.time = departure;
    return m;
}

/// An analytic flow with a busy wait of @p waitNs nanoseconds before each velocity and Jacobian after its first
/// @p after calls: the same flow on a machine that other work slows down from then on.
class SlowedField : public CurrentField
{
public:
    SlowedField(std::shared_ptr<const CurrentField> inner, double waitNs, double after)
        : inner_(std::move(inner)), wait_(static_cast<long>(waitNs)), after_(static_cast<std::uint64_t>(after))
    {
    }
    double maxSpeed(const Region &r) const override { return inner_->maxSpeed(r); }
    bool velocityBounds(const Region &r, double &uMin, double &uMax, double &vMin, double &vMax) const override
    {
        return inner_->velocityBounds(r, uMin, uMax, vMin, vMax);
    }
    bool hasVelocityBounds() const override { return inner_->hasVelocityBounds(); }
    std::optional<double> streamFunction(double x, double y, double z, double t) const override
    {
        return inner_->streamFunction(x, y, z, t);
    }
    bool divergenceFree() const override { return inner_->divergenceFree(); }
    double timeBegin() const override { return inner_->timeBegin(); }
    double timeEnd() const override { return inner_->timeEnd(); }
    std::string name() const override { return "slowed " + inner_->name(); }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override
    {
        wait();
        return inner_->velocity(x, y, z, t);
    }
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override
    {
        wait();
        return inner_->jacobian(x, y, z, t);
    }

private:
    void wait() const
    {
        if (seen_.fetch_add(1) < after_)
            return;
        const auto until = std::chrono::steady_clock::now() + std::chrono::nanoseconds(wait_);
        while (std::chrono::steady_clock::now() < until)
        {
        }
    }
    std::shared_ptr<const CurrentField> inner_;
    long wait_;
    std::uint64_t after_;
    mutable std::atomic<std::uint64_t> seen_{0};
};

/// @p m with its analytic flow slowed by @p waitNs per velocity after its first @p after calls (the kind
/// "slowed_<type>", registered once).
MissionSpec slowed(MissionSpec m, double waitNs, std::uint64_t after)
{
    const std::string inner = m.current.type, name = "slowed_" + inner;
    if (!findCurrentFieldKind(name))
    {
        CurrentFieldKind k = *findCurrentFieldKind(inner);
        k.name = name;
        k.description = "the " + inner + " flow, each velocity after a busy wait (a test's)";
        k.parameters.push_back({"wait_ns", 0.0});
        k.parameters.push_back({"after_calls", 0.0});
        k.make = [inner](std::map<std::string, double> p) {
            const double w = p.at("wait_ns"), after = p.at("after_calls");
            p.erase("wait_ns");
            p.erase("after_calls");
            return std::make_shared<SlowedField>(makeAnalyticField(inner, p), w, after);
        };
        registerCurrentFieldKind(k);
    }
    m.current.type = name;
    m.current.parameters["wait_ns"] = waitNs;
    m.current.parameters["after_calls"] = static_cast<double>(after);
    return m;
}

/// The independent sweep's fastest extremal through the goal of @p problem, up to @p maxTime.
extremal_sweep::Best reference(const MissionProblem &problem, double maxTime, int headings = 360)
{
    const MissionSpec &m = problem.getSpec();
    extremal_sweep::Setup s = trust::sweepSetup(problem, m.departure.time, m.vehicle.speed, maxTime, 0.01);
    s.headings = headings;
    return extremal_sweep::fastest(s, problem.getStart().x, problem.getStart().y, m.departure.time, problem.getGoal().x,
                                   problem.getGoal().y);
}
} // namespace

TEST(GlobalCheck, UpstreamCrossingOfTheJetComesOutInTheBestRouteClass)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // Against the jet: the lattice path crosses where the optimum does not (8.8 % slower after its refinement).
    MissionSpec m = jetPair({5.66, 1.20}, {1.58, -2.61}, 0.5, 0.0);
    const MissionProblem problem(m);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const extremal_sweep::Best best = reference(problem, 1.25 * r.plan.travelTime);
    ASSERT_TRUE(best.found);
    EXPECT_LE(r.plan.travelTime, 1.005 * best.time) << "reference " << best.time;
    // an honest time: no flyable route is faster than the optimum by more than the reference's own accuracy
    EXPECT_GE(r.plan.travelTime, (1.0 - 1e-4) * best.time);
    ASSERT_TRUE(r.plan.globalCheck.has_value());
    const GlobalCheck &g = *r.plan.globalCheck;
    EXPECT_TRUE(g.extremalFound);
    EXPECT_EQ(g.candidates.front().name, "ZA*TVE");
    EXPECT_NE(g.winner, "ZA*TVE");
    EXPECT_GT(g.gain, 0.05); // the planner's route was more than 5 % slower
    EXPECT_NEAR(g.gain, 1.0 - r.plan.travelTime / g.candidates.front().travelTime, 1e-12);
    // raw and smoothed remain the planner's own stages
    EXPECT_NEAR(r.plan.rawTravelTime, r.plan.raw.back().t - r.plan.departure, 1e-12);
    EXPECT_GT(r.plan.smoothedTravelTime, 1.05 * r.plan.travelTime);

    // without the check: the planner's route, in the other class
    m.planner.globalCheck = false;
    const MissionResult off = runMission(MissionProblem(m));
    ASSERT_TRUE(off.plan.solved);
    EXPECT_FALSE(off.plan.globalCheck.has_value());
    EXPECT_GT(off.plan.travelTime, 1.05 * best.time);
    EXPECT_NEAR(off.plan.travelTime, g.candidates.front().travelTime, 1e-9 * off.plan.travelTime);

    // the pilot is told: the report and summary.json name the candidates and the winner
    std::ostringstream report;
    printReport(report, r);
    EXPECT_NE(report.str().find("Global check:"), std::string::npos);
    EXPECT_NE(report.str().find("<- the route"), std::string::npos);
    const nlohmann::json j = nlohmann::json::parse(summaryJson(r, problem));
    EXPECT_EQ(j["global_check"]["winner"], g.winner);
    EXPECT_EQ(j["global_check"]["candidates"].size(), g.candidates.size());
    EXPECT_NEAR(j["global_check"]["gain"].get<double>(), g.gain, 1e-12);
    EXPECT_TRUE(nlohmann::json::parse(summaryJson(off, problem))["global_check"].is_null());
}

TEST(GlobalCheck, StrongCurrentAtSpeedPointOneWithinOnePointFivePercentOfTheBestExtremal)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // V = 0.1 across the jet (the issue: the default 48.22 where an extremal reaches the goal in 47.67)
    const MissionProblem problem(jetPair({1.0, -3.0}, {8.0, 3.0}, 0.1, 0.0));
    const PlannedPath p = planRoute(problem, 0.0);
    ASSERT_TRUE(p.solved) << p.reason;
    const extremal_sweep::Best best = reference(problem, 1.25 * p.travelTime);
    ASSERT_TRUE(best.found);
    EXPECT_LE(p.travelTime, 1.015 * best.time) << "reference " << best.time;
    EXPECT_GE(p.travelTime, (1.0 - 1e-4) * best.time);
}

TEST(GlobalCheck, NarrowExtremalFamiliesInTheJetAreFoundByFinerScans)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // The extremals through these goals lie within a fraction of the sweep's 1440 or 2880 headings: the lattice's
    // route was 11 % slow in the first, and the second had no route at all (the level set's backtrack cannot be
    // flown from the start). The independent sweep (its own zoom about its nearest miss) finds the optimum.
    struct Case
    {
        Point2 start, goal;
        double speed, departure;
    };
    for (const Case &c : {Case{{8.30, 1.92}, {8.12, -2.83}, 0.3, 2.0}, Case{{6.64, 1.44}, {7.98, -2.61}, 0.2, 0.0}})
    {
        const MissionProblem problem(jetPair(c.start, c.goal, c.speed, c.departure));
        const PlannedPath p = planRoute(problem, c.departure);
        const std::string what = "V = " + std::to_string(c.speed) + " to (" + std::to_string(c.goal.x) + ", " +
                                 std::to_string(c.goal.y) + ")";
        ASSERT_TRUE(p.solved) << what << ": " << p.reason;
        ASSERT_TRUE(p.globalCheck.has_value());
        EXPECT_TRUE(p.globalCheck->extremalFound) << what;
        EXPECT_GT(p.globalCheck->finerHeadings, 0u) << what << ": the sweep alone found it";
        const extremal_sweep::Best best = reference(problem, 1.25 * p.travelTime, 1440);
        ASSERT_TRUE(best.found) << what;
        EXPECT_LE(p.travelTime, (1.0 + trust::tolerance(c.speed)) * best.time) << what << ": reference " << best.time;
        EXPECT_GE(p.travelTime, (1.0 - 1e-4) * best.time) << what;
        // the route is flown as planned: the accurate re-flight ends on the goal
        EXPECT_TRUE(p.reflown) << what;
    }
}

TEST(GlobalCheck, OptimumReferenceKeepsToTheRegion)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // Zermelo's shear u = -y: the fast lane for a trip to +x lies at y < 0, below a region that ends at y = -1. The
    // reference in open water dips below it; the one the program prints must stay inside.
    MissionSpec m = trust::analytic("linear_shear", {{"a", -1.0}}, Box{-1.0, 9.0, -1.0, 2.0});
    m.start.xy = {0.0, -0.8};
    m.goal.xy = {8.0, -0.8};
    m.vehicle.speed = m.travel.speed = 0.5;
    const MissionProblem problem(m);
    const OptimumReference inside = optimumReference(problem, 0.0, 0.5, 40.0);
    for (const TimedPoint &q : inside.path)
        EXPECT_GE(q.y, -1.0 - 1e-9) << "the optimal-control path leaves the region at t = " << q.t;
    // the same problem in a region wide enough for the fast lane: the extremal through the goal dips below y = -1,
    // so the narrow region's reference is not it (none at all here: every extremal through the goal leaves)
    MissionSpec wide = m;
    wide.region.xy = Box{-1.0, 9.0, -4.0, 2.0};
    const OptimumReference open = optimumReference(MissionProblem(wide), 0.0, 0.5, 40.0);
    ASSERT_TRUE(open.found);
    double lowest = 0.0;
    for (const TimedPoint &q : open.path)
        lowest = std::min(lowest, q.y);
    EXPECT_LT(lowest, -1.0);
    EXPECT_FALSE(inside.found && std::abs(inside.travelTime - open.travelTime) < 1e-6 * open.travelTime);
    // the default keeps to the region too, and is no faster than the open-water optimum
    const PlannedPath p = planRoute(problem, 0.0);
    ASSERT_TRUE(p.solved) << p.reason;
    EXPECT_GT(p.travelTime, open.travelTime);
    if (inside.found)
    {
        EXPECT_LE(p.travelTime, 1.005 * inside.travelTime);
    }
    for (const TimedPoint &q : p.track.empty() ? p.path : p.track)
        EXPECT_GE(q.y, -1.0 - 1e-9);
}

TEST(GlobalCheck, NoPathReasonGivesTheHorizonInTheMissionsOwnUnits)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // the built-in trip cannot be made in 2 time units: the reason names the horizon as the mission counts time
    MissionSpec m = defaultGulfStreamMission();
    m.planner.horizon = 2.0;
    const PlannedPath dimensionless = planRoute(MissionProblem(m), 0.0);
    ASSERT_FALSE(dimensionless.solved);
    EXPECT_NE(dimensionless.reason.find("2 time units after departure"), std::string::npos) << dimensionless.reason;
    EXPECT_EQ(dimensionless.reason.find(" h)"), std::string::npos) << dimensionless.reason;
    // a mission whose time unit is a day: days and hours
    m.lengthUnitMetres = 50000.0;
    m.timeUnitSeconds = 86400.0;
    const PlannedPath days = planRoute(MissionProblem(m), 0.0);
    ASSERT_FALSE(days.solved);
    EXPECT_NE(days.reason.find("2 d"), std::string::npos) << days.reason;
    EXPECT_EQ(days.reason.find("time units"), std::string::npos) << days.reason;
}

TEST(GlobalCheck, NeverLosesARouteThatMeetsTheArrivalWindow)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // Against the jet with the window [20, 21]: the fastest extremal arrives at 14.45 where the glider cannot hold, so
    // it cannot meet the window; the planner's route, which holds, does. The default must keep it (it said "no path").
    // Then random pairs of the jet with a window that opens after the default's unwindowed arrival: wherever the plan
    // without the check meets the window, the default does too, no later, inside it.
    struct Case
    {
        Point2 s, g;
        double begin, end;
    };
    std::vector<Case> cases{{{5.66, 1.20}, {1.58, -2.61}, 20.0, 21.0}};
    std::mt19937 rng(44);
    std::uniform_real_distribution<double> x(0.5, 9.5), y(-3.5, 3.5), late(1.05, 1.6);
    while (cases.size() < 5)
    {
        MissionSpec m = jetPair({x(rng), y(rng)}, {x(rng), y(rng)}, 0.5, 0.0);
        const PlannedPath free = planRoute(MissionProblem(m), 0.0);
        if (!free.solved)
            continue;
        const double b = late(rng) * free.travelTime;
        cases.push_back({m.start.xy, m.goal.xy, b, b + 1.0});
    }
    int checked = 0; // cases where the plan without the check meets the window
    for (const Case &c : cases)
    {
        SCOPED_TRACE("start (" + std::to_string(c.s.x) + ", " + std::to_string(c.s.y) + "), goal (" +
                     std::to_string(c.g.x) + ", " + std::to_string(c.g.y) + "), window [" + std::to_string(c.begin) +
                     ", " + std::to_string(c.end) + "]");
        MissionSpec m = jetPair(c.s, c.g, 0.5, 0.0);
        m.goalWindow = {true, c.begin, c.end};
        const PlannedPath p = planRoute(MissionProblem(m), 0.0);
        m.planner.globalCheck = false;
        const PlannedPath off = planRoute(MissionProblem(m), 0.0);
        if (!off.solved)
            continue;
        ++checked;
        ASSERT_TRUE(p.solved) << p.reason;
        EXPECT_GE(p.path.back().t, c.begin - 1e-9);
        EXPECT_LE(p.path.back().t, c.end + 1e-9);
        EXPECT_LE(p.path.back().t, off.path.back().t + 1e-9);
        ASSERT_TRUE(p.globalCheck.has_value());
        for (const RouteCandidate &k : p.globalCheck->candidates) // a candidate that is a route meets the window
        {
            if (k.solved)
            {
                EXPECT_GE(k.travelTime, c.begin - 1e-9) << k.name;
            }
        }
    }
    std::printf("cases checked: %d of %zu\n", checked, cases.size());
    EXPECT_EQ(checked, static_cast<int>(cases.size())); // every case has a route without the check: none is vacuous
}

TEST(GlobalCheck, TheRescueGivesTheSameAnswerOnASlowerMachine)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // Around the Rankine vortex at V = 0.3 the sweep finds no extremal through the goal: the rescue scans finer and
    // runs the level set, and its extremal wins. The rescue is bounded by its work (the level set's node updates),
    // not by a clock: the same problem on a machine that other work slows down once the plan is made (every velocity
    // of the check 100 ns slower: the check takes about twice as long) gets the same check and the same route, to the
    // bit. (With a budget in seconds, ten times the plan's, the slowed run's level set was cut before its front reached
    // the goal.)
    const trust::Flow vortex = trust::flows()[2];
    MissionSpec m = vortex.mission;
    m.start.xy = {0.55, -0.16};
    m.goal.xy = {2.89, 3.49};
    m.vehicle.speed = m.travel.speed = 0.3;
    const MissionProblem plain(m);
    const PlannedPath fast = planRoute(plain, 0.0);
    ASSERT_TRUE(fast.globalCheck);
    const std::uint64_t beforeCheck = plain.getField()->callCount() - fast.globalCheck->currentModelCalls;
    const PlannedPath slow = planRoute(MissionProblem(slowed(m, 100.0, beforeCheck)), 0.0);
    ASSERT_TRUE(fast.solved) << fast.reason;
    ASSERT_TRUE(slow.solved) << slow.reason;
    ASSERT_TRUE(fast.globalCheck && slow.globalCheck);
    const GlobalCheck &a = *fast.globalCheck, &b = *slow.globalCheck;
    std::printf("plan %.2f s before the check (%llu velocities); ", fast.planningSeconds + fast.postprocessSeconds,
                static_cast<unsigned long long>(beforeCheck));
    std::printf("check: %.2f s, slowed %.2f s; level set %llu of %llu node updates, first arrival %.6f; winner %s\n",
                a.seconds, b.seconds, static_cast<unsigned long long>(a.levelSetUpdates),
                static_cast<unsigned long long>(a.levelSetBudget), a.levelSetTime, a.winner.c_str());
    EXPECT_GT(b.seconds, 2.0 * a.seconds); // the slowdown took effect
    EXPECT_GT(a.finerHeadings, 0u);
    EXPECT_GT(a.levelSetUpdates, 0u); // the rescue ran its level set
    EXPECT_TRUE(std::isfinite(a.levelSetTime));
    EXPECT_FALSE(a.timedOut);
    EXPECT_FALSE(b.timedOut);
    EXPECT_EQ(a.finerHeadings, b.finerHeadings);
    EXPECT_EQ(a.levelSetUpdates, b.levelSetUpdates);
    EXPECT_EQ(a.levelSetTime, b.levelSetTime);
    EXPECT_EQ(a.extremalFound, b.extremalFound);
    EXPECT_EQ(a.extremalTime, b.extremalTime);
    EXPECT_EQ(a.winner, b.winner);
    EXPECT_EQ(fast.travelTime, slow.travelTime);
    ASSERT_EQ(fast.path.size(), slow.path.size());
    for (std::size_t i = 0; i < fast.path.size(); ++i)
    {
        EXPECT_EQ(fast.path[i].x, slow.path[i].x);
        EXPECT_EQ(fast.path[i].y, slow.path[i].y);
    }
}

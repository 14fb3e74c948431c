// An ensemble whose members disagree on whether the goal can be reached: never "no path" while members arrive. The
// plan is the route most likely to arrive (its share of the members, the members it misses named), solved; "no
// path" only when no member is reached, with that reason first. Checked on a uniform current against the glider
// drawn within 25 %: a member is reachable exactly when its current is slower than the glider (a closed form read
// from the members' own parameters, not from the planner).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/Report.h"
#include "ompl_glider/output/SummaryJson.h"

using namespace ompl_glider;

namespace
{
/// The glider (0.5) crosses 6 units straight against a uniform current u drawn about @p u within 25 %.
std::string upstream(double u, const std::string &objective = "expected")
{
    std::ostringstream y;
    y << "name: upstream\nregion: {x_min: 0, x_max: 10, y_min: -2, y_max: 2}\nstart: {x: 8, y: 0}\n"
      << "goal: {x: 2, y: 0}\nvehicle: {speed: 0.5}\n"
      << "current: {type: uniform, parameters: {u: " << u << ", v: 0}, members: 12, spread: {u: 0.25}, seed: 3}\n"
      << "planner: {name: zastartve, grid_size: 0.5, objective: " << objective << "}\n";
    return y.str();
}
} // namespace

TEST(EnsembleArrival, NoRouteArrivesInEveryMemberSoThePlanIsTheMostLikelyWithItsShare)
{
    for (const std::string objective : {"expected", "worst"})
    {
        SCOPED_TRACE(objective);
        const MissionProblem problem(parseMission(upstream(0.45, objective), "m.yaml"));
        const auto &members = problem.getMembers();
        ASSERT_EQ(members.size(), 12u);
        // the members the glider can cross: current slower than the glider (against it, head on)
        std::size_t reachable = 0;
        for (const auto &f : members)
            reachable += std::abs(f->velocity(5.0, 0.0, 0.0, 0.0).u) < 0.5 ? 1 : 0;
        ASSERT_GT(reachable, 0u);
        ASSERT_LT(reachable, members.size()); // the draw straddles the glider's speed: no robust route exists
        const MissionResult r = runMission(problem);
        ASSERT_TRUE(r.plan.solved) << r.plan.reason;
        ASSERT_TRUE(r.plan.ensemble);
        const EnsemblePlan &e = *r.plan.ensemble;
        // every route from 8 to 2 against the current arrives in exactly the reachable members: the best share
        EXPECT_DOUBLE_EQ(e.arrivalProbability, double(reachable) / double(members.size()));
        for (std::size_t k = 0; k < members.size(); ++k)
        {
            const bool slower = std::abs(members[k]->velocity(5.0, 0.0, 0.0, 0.0).u) < 0.5;
            EXPECT_EQ(std::isfinite(e.memberTravelTimes[k]), slower) << "member " << k;
            if (slower) // straight upstream: 6 / (0.5 - |u|), within the lattice's and the flight's accuracy
            {
                EXPECT_NEAR(e.memberTravelTimes[k], 6.0 / (0.5 - std::abs(members[k]->velocity(5, 0, 0, 0).u)),
                            0.02 * e.memberTravelTimes[k])
                    << "member " << k;
            }
        }
        EXPECT_TRUE(std::isfinite(e.objectiveValue));
        // the report and summary.json say it
        std::ostringstream report;
        printReport(report, r, &problem);
        EXPECT_NE(report.str().find("Ensemble:           arrives in " + std::to_string(reachable) + " of 12 members"),
                  std::string::npos)
            << report.str();
        const nlohmann::json j = nlohmann::json::parse(summaryJson(r, problem, {}));
        EXPECT_DOUBLE_EQ(j["arrival_probability"].get<double>(), e.arrivalProbability);
        EXPECT_EQ(j["ensemble"]["members_arriving"].size(), reachable);
        EXPECT_EQ(j["ensemble"]["members_not_arriving"].size(), members.size() - reachable);
        EXPECT_TRUE(j["travel_time"].is_number());
    }
}

TEST(EnsembleArrival, NoPathOnlyWhenNoMemberIsReachedWithThatReasonFirst)
{
    // every member's current at least 0.6: none can be crossed upstream
    const MissionProblem problem(parseMission(upstream(0.8), "m.yaml"));
    for (const auto &f : problem.getMembers())
        ASSERT_GE(std::abs(f->velocity(5.0, 0.0, 0.0, 0.0).u), 0.5);
    const MissionResult r = runMission(problem);
    ASSERT_FALSE(r.plan.solved);
    EXPECT_EQ(r.plan.reason.rfind("no member of the ensemble is reached", 0), 0u) << r.plan.reason;
    const nlohmann::json j = nlohmann::json::parse(summaryJson(r, problem, {}));
    EXPECT_TRUE(j["travel_time"].is_null());
    EXPECT_EQ(j["arrival_probability"].get<double>(), 0.0);
}

TEST(EnsembleArrival, ARobustPlanArrivesInEveryMember)
{
    // every member below 0.5 (0.2 within 25 %): robust, p = 1
    const MissionProblem problem(parseMission(upstream(0.2), "m.yaml"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    EXPECT_EQ(r.plan.ensemble->arrivalProbability, 1.0);
    std::ostringstream report;
    printReport(report, r, &problem);
    EXPECT_NE(report.str().find("Ensemble:           robust: arrives in every one of the 12 members"),
              std::string::npos)
        << report.str();
}

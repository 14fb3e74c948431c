// The robust plan's work grows with the members as the members do: a small ensemble plans on every member and flies
// every candidate in every member; a large one (up to the documented 1000 drawn members) plans 33 candidates and flies
// a bounded number of them in every member, the chosen one among those; the time limit bounds the candidates'
// planning as a whole.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ompl_glider/ThreadPool.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "mission/planning/PlanningInternal.h"

using namespace ompl_glider;

namespace
{
/// A uniform current (slower than the glider in every member) drawn as an ensemble of @p members.
MissionSpec drawnMission(unsigned members)
{
    return parseMission("name: drawn\nunits: {length_m: 1000, time_s: 3600}\n"
                        "current: {type: uniform, parameters: {u: 0.1, v: 0.05}, members: " +
                            std::to_string(members) +
                            ", spread: {u: 0.5, v: 0.5}, seed: 3}\n"
                            "region: {x_min: 0, x_max: 14, y_min: -4, y_max: 4}\nstart: {x: 1, y: 0}\n"
                            "goal: {x: 12, y: 0}\nvehicle: {speed: 0.5}\nplanner: {name: zastartve, grid_size: 1}\n",
                        "m.yaml");
}

/// Candidate paths flown in a member, in all (a travel time or +inf where flown, NaN where not).
std::size_t flights(const EnsemblePlan &e)
{
    std::size_t n = 0;
    for (const EnsemblePlan::Candidate &c : e.candidates)
        for (double t : c.memberTravelTimes)
            n += std::isnan(t) ? 0 : 1;
    return n;
}

/// Checks @p e chose a candidate flown in every member whose objective is the least of those so flown.
void expectChosenFlownEverywhere(const EnsemblePlan &e, std::size_t members)
{
    ASSERT_EQ(e.memberTravelTimes.size(), members);
    for (double t : e.memberTravelTimes)
        ASSERT_TRUE(std::isfinite(t));
    EXPECT_DOUBLE_EQ(e.objectiveValue, ensembleObjective(e.memberTravelTimes, e.objective, e.quantile));
    for (const EnsemblePlan::Candidate &c : e.candidates)
    {
        bool everywhere = c.memberTravelTimes.size() == members;
        for (double t : c.memberTravelTimes)
            everywhere = everywhere && !std::isnan(t);
        if (everywhere && c.solved)
        {
            EXPECT_LE(e.objectiveValue, c.objectiveValue) << c.name;
        }
    }
}
} // namespace

TEST(EnsembleWork, ASmallEnsembleFliesEveryCandidateInEveryMember)
{
    const MissionProblem problem(drawnMission(10));
    const PlannedPath p = planRoute(problem, 0.0);
    ASSERT_TRUE(p.solved) << p.reason;
    ASSERT_TRUE(p.ensemble.has_value());
    EXPECT_EQ(p.ensemble->candidates.size(), 11u); // the mean and every member
    EXPECT_EQ(flights(*p.ensemble), 11u * 10u);
    expectChosenFlownEverywhere(*p.ensemble, 10);
}

TEST(EnsembleWork, ALargeEnsemblePlansABoundedSetOfCandidatesAndFliesFewInEveryMember)
{
    // before: M + 1 candidates each flown in all M members (1000 members: 1001 plans and 1e6 flights, no end in
    // minutes); now 33 plans, 32 screening flights each, and the 4 best flown in every member (all pass here)
    std::size_t previous = 0;
    for (unsigned members : {200u, 1000u})
    {
        const MissionProblem problem(drawnMission(members));
        const PlannedPath p = planRoute(problem, 0.0);
        ASSERT_TRUE(p.solved) << p.reason;
        ASSERT_TRUE(p.ensemble.has_value());
        const EnsemblePlan &e = *p.ensemble;
        ASSERT_EQ(e.candidates.size(), 33u) << members;
        EXPECT_EQ(e.candidates[0].name, "mean");
        EXPECT_EQ(e.candidates[1].name, "member 0"); // the control run
        const std::size_t n = flights(e);
        EXPECT_EQ(n, 33u * 32u + 4u * (members - 32u)) << members;
        expectChosenFlownEverywhere(e, members);
        if (previous > 0) // five times the members, less than three times the flights
        {
            EXPECT_LT(n, 3 * previous);
        }
        previous = n;
    }
}

TEST(EnsembleWork, TheTimeLimitBoundsTheCandidatesPlanningAsAWhole)
{
    // a time limit of a millisecond: the candidates begun at once (one a thread) plan, the others are left out
    const MissionProblem problem(drawnMission(200));
    PlanOptions o;
    o.timeLimit = 1e-3;
    const PlannedPath p = planning_detail::planRobust(problem, 0.0, o);
    ASSERT_TRUE(p.ensemble.has_value());
    EXPECT_LE(p.ensemble->candidates.size(), static_cast<std::size_t>(ThreadPool(0).size()));
    EXPECT_GE(p.ensemble->candidates.size(), 1u);
    EXPECT_EQ(p.ensemble->candidates[0].name, "mean"); // always planned
}

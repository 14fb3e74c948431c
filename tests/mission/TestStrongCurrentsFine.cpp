// The meandering jet at low speeds against the level set at a fine resolution (0.025, 400 x 320
// cells): slow, labelled ci. The default pipeline's travel time is within 1 % of the fine level set's, and both
// routes fly again to the goal independently of their planners (StrongCurrentChecks.h).
#include <gtest/gtest.h>

#include <cstdio>

#include "StrongCurrentChecks.h"

using namespace ompl_glider;
using namespace strong_checks;

TEST(StrongCurrentsFine, JetAtLowSpeedsDefaultWithinOnePercentOfTheFineLevelSet)
{
    for (double V : {0.2, 0.15})
    {
        const MissionProblem problem(jetAt(V));
        const PlannedPath plan = planRoute(problem, 0.0);
        ASSERT_TRUE(plan.solved) << "V " << V << ": " << plan.reason;
        MissionSpec fine = jetAt(V);
        fine.planner.name = "LevelSet";
        fine.planner.parameters = {{"resolution", "0.025"}};
        const MissionProblem fineProblem(fine);
        const PlannedPath level = planRoute(fineProblem, 0.0);
        ASSERT_TRUE(level.solved) << "V " << V << ": " << level.reason;
        std::printf("jet V %.2f: default (%s) %.6f in %.2f s, LevelSet at 0.025 %.6f in %.2f s (rel %.3e)\n", V,
                    plan.planner.c_str(), plan.travelTime, plan.planningSeconds + plan.postprocessSeconds,
                    level.travelTime, level.planningSeconds + level.postprocessSeconds,
                    plan.travelTime / level.travelTime - 1.0);
        EXPECT_NEAR(plan.travelTime, level.travelTime, 0.01 * level.travelTime) << "V " << V;
        const std::string what = "jet V " + std::to_string(V);
        if (level.headings)
            expectHeadingReflight(fineProblem, level, what + " LevelSet 0.025");
        else
            expectStraightLegRetiming(fineProblem, level, what + " LevelSet 0.025");
    }
}

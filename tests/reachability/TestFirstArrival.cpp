// The level set's first arrival as the pipeline's global check asks it (PipelinePlanner::firstArrival() of the
// registry's level-set planner, no planner type named): the solver's own answer at the planner's default cell with
// half a cell of clearance, to the bit; in a uniform current the straight course's time; a work budget that ends it
// early is reported; planners of the other families compute none.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/PipelinePlanner.h"
#include "ompl_glider/reachability/LevelSet.h"
#include "ompl_glider/registry/PlannerRegistry.h"

using namespace ompl_glider;

TEST(FirstArrival, TheLevelSetFamilysAnswerIsTheSolversAndTheStraightCoursesTime)
{
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(0.2, -0.1);
    p.travel.speed = 1.0;
    p.xMin = -6;
    p.xMax = 6;
    p.yMin = -6;
    p.yMax = 6;
    p.start = {-1.0, 0.5};
    p.goal = {3.0, 0.0};
    std::shared_ptr<GliderContext> ctx;
    const auto ss = makeSimpleSetup(p, &ctx);
    PipelineSetup setup;
    setup.start = p.start;
    setup.goal = p.goal;
    setup.departure = p.t0;
    setup.region = ctx->region;
    const double tEnd = p.t0 + 20.0;
    const auto planner = plannerOfFamily(PlannerFamily::LevelSet).make(ss->getSpaceInformation(), ctx);
    const std::optional<FirstArrival> a = pipelineView(*planner).firstArrival(setup, tEnd, 0, {});
    ASSERT_TRUE(a);
    ASSERT_TRUE(a->reached);

    LevelSetParams lp;
    lp.cellSize = defaultLevelSetResolution(*ctx);
    lp.clearance = 0.5 * lp.cellSize;
    const Reachability r = LevelSetSolver(ctx, lp).solve(p.start.x, p.start.y, p.t0, tEnd, p.goal, true);
    EXPECT_EQ(a->time, r.goalTime);
    EXPECT_EQ(a->work, r.stats.nodeUpdates);
    EXPECT_FALSE(a->budgetSpent);
    ASSERT_EQ(a->path.size(), r.path.size());
    for (std::size_t i = 0; i < r.path.size(); ++i)
    {
        EXPECT_EQ(a->path[i].x, r.path[i].x);
        EXPECT_EQ(a->path[i].y, r.path[i].y);
        EXPECT_EQ(a->path[i].t, r.path[i].t);
    }
    // the straight course: ground speed c.d + sqrt(V^2 - (c x d)^2) along the unit direction d
    const double dx = p.goal.x - p.start.x, dy = p.goal.y - p.start.y, d = std::hypot(dx, dy);
    const double along = (0.2 * dx - 0.1 * dy) / d, across = (0.2 * dy + 0.1 * dx) / d;
    const double exact = d / (along + std::sqrt(1.0 - across * across));
    EXPECT_NEAR(a->time - p.t0, exact, 0.02 * exact);
    EXPECT_GE(a->time - p.t0, exact * (1.0 - 1e-3)); // first order, never early by much

    // a budget far below the trip's work ends it before the goal, and says so
    const std::optional<FirstArrival> cut = pipelineView(*planner).firstArrival(setup, tEnd, a->work / 10, {});
    ASSERT_TRUE(cut);
    EXPECT_FALSE(cut->reached);
    EXPECT_TRUE(cut->budgetSpent);
    EXPECT_TRUE(cut->path.empty());
    EXPECT_LT(cut->work, a->work);

    // the other families' built-in planners compute none (the default answer)
    for (const PlannerFamily f : {PlannerFamily::Lattice, PlannerFamily::Headings, PlannerFamily::Sampling})
    {
        const auto other = plannerOfFamily(f).make(ss->getSpaceInformation(), ctx);
        EXPECT_FALSE(pipelineView(*other).firstArrival(setup, tEnd, 0, {})) << plannerFamilyName(f);
    }
}

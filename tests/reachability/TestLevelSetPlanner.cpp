// The LevelSet planner through OMPL's SimpleSetup: exact solutions whose paths pass
// PathGeometric::check() and whose travel time is the front's within the resolution, around islands, waiting out a
// closed lane, and no path for a walled-in start; the name is in the planner registry.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <ompl/geometric/PathGeometric.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#include "ompl_glider/planners/ZAStarTVE.h"
#include "ompl_glider/reachability/LevelSetPlanner.h"

using namespace ompl_glider;

namespace
{
struct LsRun
{
    ompl::base::PlannerStatus status;
    std::shared_ptr<LevelSetPlanner> planner;
    ompl::geometric::SimpleSetupPtr ss;
    std::shared_ptr<GliderContext> ctx;
};

LsRun plan(const GliderProblem &p, double resolution)
{
    LsRun r;
    r.ss = makeSimpleSetup(p, &r.ctx);
    auto planner = plannerEntry("LevelSet").make(r.ss->getSpaceInformation(), r.ctx);
    r.planner = std::dynamic_pointer_cast<LevelSetPlanner>(planner);
    EXPECT_TRUE(r.planner);
    EXPECT_TRUE(planner->params().setParam("resolution", std::to_string(resolution)));
    r.ss->setPlanner(planner);
    r.status = r.ss->solve(600.0);
    return r;
}

double latticeTime(const GliderProblem &p)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(p, &ctx);
    auto z = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE");
    z->setGridSize(0.2);
    ss->setPlanner(z);
    EXPECT_EQ(ss->solve(600.0), ompl::base::PlannerStatus::EXACT_SOLUTION);
    return z->getWaypoints().back().t - p.t0; // refined: the pipeline's best
}
} // namespace

TEST(LevelSetPlanner, JetAndIslandsGiveCheckedPathsNoSlowerThanRefinedLattice)
{
    GliderProblem p = gulfStreamProblem();
    p.start.x = 0.6;
    p.start.y = -2.6;
    p.goal.x = 9.4;
    p.goal.y = 2.6;
    p.horizon = 40.0;
    for (int withIslands = 0; withIslands < 2; ++withIslands)
    {
        SCOPED_TRACE(withIslands ? "islands" : "open water");
        if (withIslands)
        {
            auto env = std::make_shared<ForbiddenRegions>();
            env->add(std::make_shared<StaticRegion>("A", Polygon::regular(3.0, -1.6, 0.7, 40, 0.1, "A"), "island"));
            env->add(std::make_shared<StaticRegion>(
                "B", Polygon({{5.2, -0.4}, {6.6, -0.2}, {6.8, 1.2}, {6.1, 0.5}, {5.4, 1.0}}, {}, "B"), "island"));
            p.environment = env;
        }
        const LsRun r = plan(p, 0.05);
        ASSERT_EQ(r.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
        auto &path = static_cast<ompl::geometric::PathGeometric &>(*r.ss->getProblemDefinition()->getSolutionPath());
        EXPECT_TRUE(path.check()); // every leg valid for the motion validator: no island crossed
        const double flown = r.planner->getWaypoints().back().t - p.t0;
        const double front = r.planner->getLevelSetTime();
        const double lattice = latticeTime(p);
        std::printf("%s: level set %.4f, its path flown %.4f (%zu waypoints), ZA*TVE refined %.4f\n",
                    withIslands ? "islands" : "open water", front, flown, r.planner->getWaypoints().size(), lattice);
        // The flown path is the front's within the resolution (legs timed by the travel-time code).
        EXPECT_NEAR(flown, front, 0.01 * front);
        // The level set is the continuous optimum: the refined lattice path is not faster (beyond its accuracy).
        EXPECT_GE(lattice, front * (1 - 0.003));
    }
}

TEST(LevelSetPlanner, WaitsOutAClosedLaneAndReportsNoPathWhenWalledIn)
{
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(0.0, 0.0);
    p.travel.speed = 0.5;
    p.xMin = 0;
    p.xMax = 10;
    p.yMin = -4;
    p.yMax = 4;
    p.horizon = 40;
    p.start.x = 1;
    p.start.y = 0;
    p.goal.x = 8;
    p.goal.y = 0;
    auto env = std::make_shared<ForbiddenRegions>();
    env->add(std::make_shared<StaticRegion>("north", Polygon::rectangle(3.0, 0.5, 3.5, 5.0, "north"), "island"));
    env->add(std::make_shared<StaticRegion>("south", Polygon::rectangle(3.0, -5.0, 3.5, -0.5, "south"), "island"));
    env->add(std::make_shared<TimeWindowedZone>("lane", Polygon::rectangle(3.0, -0.5, 3.5, 0.5, "lane"),
                                                std::vector<Interval>{{0.0, 10.0}}));
    p.environment = env;
    {
        const LsRun r = plan(p, 0.05);
        ASSERT_EQ(r.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
        auto &path = static_cast<ompl::geometric::PathGeometric &>(*r.ss->getProblemDefinition()->getSolutionPath());
        EXPECT_TRUE(path.check());
        // Arrival: the lane opens at 10, then 5 units at V = 0.5 (the front's 20 within the resolution).
        const double arrival = r.planner->getWaypoints().back().t;
        EXPECT_NEAR(arrival, 20.0, 0.1);
        EXPECT_GE(arrival, 20.0 - 1e-9); // it cannot pass the lane before it opens
        // The path holds (a repeated position with a later time).
        bool holds = false;
        const auto &w = r.planner->getWaypoints();
        for (std::size_t k = 1; k < w.size(); ++k)
            holds = holds || (w[k].x == w[k - 1].x && w[k].y == w[k - 1].y && w[k].t > w[k - 1].t + 1.0);
        EXPECT_TRUE(holds);
    }
    {
        // The lane never opens within the horizon: walled in, no path (ABORT, not a timeout).
        auto env2 = std::make_shared<ForbiddenRegions>();
        for (const auto &m : env->regions())
            if (m->name() != "lane")
                env2->add(m);
        env2->add(std::make_shared<TimeWindowedZone>("lane", Polygon::rectangle(3.0, -0.5, 3.5, 0.5, "lane"),
                                                     std::vector<Interval>{{0.0, 100.0}}));
        p.environment = env2;
        const LsRun r = plan(p, 0.1);
        EXPECT_EQ(r.status, ompl::base::PlannerStatus::ABORT);
        EXPECT_FALSE(r.ss->haveExactSolutionPath());
        EXPECT_FALSE(r.planner->lastReachability().goalReached);
    }
}

TEST(LevelSetPlanner, ParametersAreChecked)
{
    GliderProblem p = gulfStreamProblem();
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(p, &ctx);
    LevelSetPlanner planner(ss->getSpaceInformation(), ctx);
    EXPECT_THROW(planner.setResolution(-1.0), Error);
    EXPECT_THROW(planner.setCfl(0.0), Error);
    EXPECT_THROW(planner.setCfl(9.0), Error);
    EXPECT_NE(findPlanner("levelset"), nullptr);
}

// The reachable set as the pipeline asks it (PipelinePlanner::reachableSet(), no planner type named): the level
// set's isochrones in a uniform current are the circles of radius V t about start + c t; every planner of another
// family answers that it computes none.
TEST(LevelSetPlanner, ReachableSetThroughThePipelineInterfaceIsTheDriftingCircle)
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
    const std::vector<double> times{1.5, 3.0};
    int levelSets = 0;
    for (const PlannerEntry &entry : plannerRegistry())
    {
        // stint planners need the mission's stints section; of OMPL's own planners (the default answers) one is asked
        if (entry.family == PlannerFamily::Stints ||
            (entry.family == PlannerFamily::Sampling && entry.name != "RRTstar"))
            continue;
        const auto planner = entry.make(ss->getSpaceInformation(), ctx);
        ReachRequest request;
        request.times = times;
        const std::optional<ReachableSet> r = pipelineView(*planner).reachableSet(setup, request);
        if (entry.family != PlannerFamily::LevelSet)
        {
            EXPECT_FALSE(r) << entry.name;
            continue;
        }
        ++levelSets;
        ASSERT_TRUE(r) << entry.name;
        ASSERT_EQ(r->lines.size(), times.size());
        EXPECT_GT(r->resolution, 0.0);
        EXPECT_EQ(r->arrival.size(), static_cast<std::size_t>(r->nx) * r->ny);
        for (std::size_t k = 0; k < times.size(); ++k)
        {
            const double t = times[k], cx = p.start.x + 0.2 * t, cy = p.start.y - 0.1 * t;
            std::size_t points = 0;
            for (const auto &line : r->lines[k])
                for (const Point2 &q : line)
                {
                    ++points;
                    EXPECT_NEAR(std::hypot(q.x - cx, q.y - cy), t, 2.0 * r->resolution) << "t = " << t;
                }
            EXPECT_GT(points, 20u);
        }
    }
    EXPECT_EQ(levelSets, 1);
}

// The reachable set with a goal and a horizon (ReachRequest: what the probability of reach asks of each member): the
// front records the goal's first arrival, the closed form of a uniform current (|d - c T| = V T), and runs on to the
// horizon instead of stopping there; isochronesOf() draws a given field as reachableSet() draws its own.
TEST(LevelSetPlanner, ReachableSetRecordsTheGoalAndRunsOnToTheHorizon)
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
    const PlannerEntry *entry = findPlanner("LevelSet");
    ASSERT_NE(entry, nullptr);
    const auto planner = entry->make(ss->getSpaceInformation(), ctx);
    ReachRequest request;
    request.times = {2.0};
    request.until = 4.5;
    request.cellSize = 0.1;
    request.goal = p.goal;
    request.threads = 1;
    const std::optional<ReachableSet> r = pipelineView(*planner).reachableSet(setup, request);
    ASSERT_TRUE(r);
    EXPECT_DOUBLE_EQ(r->resolution, 0.1);
    EXPECT_FALSE(r->stopped);
    // |d|^2 - 2 T d.c + T^2 |c|^2 = V^2 T^2 with d = (4, -0.5), c = (0.2, -0.1), V = 1
    const double exact = (-1.7 + std::sqrt(1.7 * 1.7 + 4 * 0.95 * 16.25)) / (2 * 0.95);
    ASSERT_TRUE(r->goalReached);
    EXPECT_GT(r->goalTime, exact);        // the front is slow, never fast
    EXPECT_LT(r->goalTime, exact * 1.01); // first order in the cell
    double latest = 0.0;                  // the front ran on past the goal's arrival, up to the horizon
    for (const double t : r->arrival)
        if (std::isfinite(t))
            latest = std::max(latest, t);
    EXPECT_GT(latest, 4.0);
    // the front runs one step past the horizon (a step is at most 2 cells crossed at V): at most two steps past it
    EXPECT_LE(latest, 4.5 + 2 * (2.0 * 0.1 / 1.0));
    const auto drawn = pipelineView(*planner).isochronesOf(*r, request.times);
    ASSERT_TRUE(drawn);
    ASSERT_EQ(drawn->size(), 1u);
    ASSERT_EQ((*drawn)[0].size(), r->lines[0].size());
    for (std::size_t k = 0; k < r->lines[0].size(); ++k)
        ASSERT_EQ((*drawn)[0][k].size(), r->lines[0][k].size());
    // a stop request ends the front where it is
    ReachRequest stopping = request;
    int checks = 0;
    stopping.stop = [&checks] { return ++checks > 3; };
    const std::optional<ReachableSet> s = pipelineView(*planner).reachableSet(setup, stopping);
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->stopped);
    EXPECT_FALSE(s->goalReached);
}

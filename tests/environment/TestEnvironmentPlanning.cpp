// Forbidden regions seen through the planners: a start or goal inside an island gives INVALID_START /
// INVALID_GOAL with a message naming the island (RRT* via SimpleSetup and ZA*TVE); paths planned around islands
// never cross them (every leg re-checked with an independent dense sampling of the polygon test); a drifting ice
// zone and a time-windowed closure are respected by the returned paths at the times they are flown.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/base/goals/GoalSampleableRegion.h>

#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/GliderStateValidityChecker.h"
#include "ompl_glider/ompl/PathResimulation.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/planners/ZAStarTVE.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace ompl_glider;

namespace
{
// Captures OMPL's log messages so that tests can check what the planners say.
class CaptureHandler : public ompl::msg::OutputHandler
{
public:
    void log(const std::string &text, ompl::msg::LogLevel, const char *, int) override
    {
        std::lock_guard<std::mutex> lock(m_);
        text_ += text + "\n";
    }
    std::string text() const
    {
        std::lock_guard<std::mutex> lock(m_);
        return text_;
    }

private:
    mutable std::mutex m_;
    std::string text_;
};

struct Capture
{
    CaptureHandler handler;
    Capture() { ompl::msg::useOutputHandler(&handler); }
    ~Capture() { ompl::msg::restorePreviousOutputHandler(); }
};

GliderProblem jetProblem(std::shared_ptr<const Environment> env)
{
    GliderProblem p;
    p.field = std::make_shared<MeanderingJet>();
    p.environment = std::move(env);
    p.horizon = 40.0;
    p.start.x = 0.6;
    p.start.y = -2.6;
    p.goal.x = 9.4;
    p.goal.y = 2.6;
    return p;
}

std::shared_ptr<ForbiddenRegions> islandAt(double cx, double cy, double r, const std::string &name)
{
    auto env = std::make_shared<ForbiddenRegions>();
    env->add(std::make_shared<StaticRegion>(name, Polygon::regular(cx, cy, r, 24, 0.0, name), "island"));
    return env;
}

// Independent check of a leg against a polygon: dense sampling (step 1e-3 of the leg) of the point test.
bool legTouchesBySampling(const Polygon &poly, double x1, double y1, double x2, double y2)
{
    for (int i = 0; i <= 1000; ++i)
    {
        const double s = i / 1000.0;
        if (poly.contains(x1 + s * (x2 - x1), y1 + s * (y2 - y1)))
            return true;
    }
    return false;
}

std::vector<std::array<double, 3>> states(const og::PathGeometric &path)
{
    std::vector<std::array<double, 3>> out;
    for (std::size_t i = 0; i < path.getStateCount(); ++i)
    {
        const auto *s = path.getState(i)->as<TimeSE2StateSpace::StateType>();
        out.push_back({s->getX(), s->getY(), s->getTime()});
    }
    return out;
}
} // namespace

TEST(EnvironmentPlanning, StartInsideIslandIsInvalidStartForBothPlanners)
{
    auto env = islandAt(0.6, -2.6, 0.5, "A"); // covers the start
    const GliderProblem p = jetProblem(env);
    for (const std::string which : {"RRTstar", "ZA*TVE"})
    {
        std::shared_ptr<GliderContext> ctx;
        og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);
        if (which == "RRTstar")
        {
            ss->setPlanner(std::make_shared<og::RRTstar>(ss->getSpaceInformation()));
        }
        else
        {
            ss->setPlanner(std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE"));
        }
        Capture cap;
        const ob::PlannerStatus st = ss->solve(0.5);
        EXPECT_EQ(st, ob::PlannerStatus::INVALID_START) << which << ": " << st.asString();
        EXPECT_FALSE(ss->haveExactSolutionPath());
        // the clear message: the validity checker names the island
        auto checker =
            std::dynamic_pointer_cast<GliderStateValidityChecker>(ss->getSpaceInformation()->getStateValidityChecker());
        ASSERT_TRUE(checker);
        const std::string why = checker->whyInvalid(ss->getProblemDefinition()->getStartState(0));
        EXPECT_NE(why.find("inside island 'A'"), std::string::npos) << why;
        // RRT* learns of it from OMPL's PlannerInputStates ("Skipping invalid start state"); ZA*TVE names the island
        if (which == "ZA*TVE")
            EXPECT_NE(cap.handler.text().find("inside island 'A'"), std::string::npos) << cap.handler.text();
        else
            EXPECT_NE(cap.handler.text().find("invalid start"), std::string::npos) << cap.handler.text();
    }
}

TEST(EnvironmentPlanning, GoalInsideIslandIsInvalidGoalForBothPlanners)
{
    auto env = islandAt(9.4, 2.6, 0.4, "G"); // covers the goal
    const GliderProblem p = jetProblem(env);
    for (const std::string which : {"RRTstar", "ZA*TVE"})
    {
        std::shared_ptr<GliderContext> ctx;
        og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);
        if (which == "RRTstar")
        {
            ss->setPlanner(std::make_shared<og::RRTstar>(ss->getSpaceInformation()));
        }
        else
        {
            ss->setPlanner(std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE"));
        }
        Capture cap;
        const ob::PlannerStatus st = ss->solve(0.5);
        EXPECT_FALSE(ss->haveExactSolutionPath());
        EXPECT_EQ(env->whyBlocked(9.4, 2.6, 0.0), "inside island 'G'");
        // the goal cannot be sampled at any time: PositionGoal says so
        auto goal = ss->getProblemDefinition()->getGoal()->as<ob::GoalSampleableRegion>();
        EXPECT_FALSE(goal->couldSample());
        if (which == "ZA*TVE")
        {
            EXPECT_EQ(st, ob::PlannerStatus::INVALID_GOAL) << st.asString();
            EXPECT_NE(cap.handler.text().find("inside island 'G'"), std::string::npos) << cap.handler.text();
        }
        else
        {
            // OMPL 1.5's RRT* does not check the goal: it searches until the time limit and reports an
            // approximate solution (documented here as it is; see the campaign report)
            EXPECT_TRUE(st == ob::PlannerStatus::INVALID_GOAL || st == ob::PlannerStatus::APPROXIMATE_SOLUTION ||
                        st == ob::PlannerStatus::TIMEOUT)
                << st.asString();
        }
    }
}

TEST(EnvironmentPlanning, LatticePathsAroundIslandsNeverCrossThem)
{
    // Islands across the open-water route of the jet problem (it passes (3.6, -1.6) and (6.4, 0)).
    auto env = std::make_shared<ForbiddenRegions>();
    const Polygon a = Polygon::regular(3.4, -1.6, 0.6, 40, 0.1, "A");
    const Polygon b({{5.8, -0.6}, {7.0, -0.4}, {7.2, 0.9}, {6.5, 0.3}, {5.9, 0.8}}, {}, "B");
    env->add(std::make_shared<StaticRegion>("A", a, "island"));
    env->add(std::make_shared<StaticRegion>("B", b, "island"));
    const GliderProblem p = jetProblem(env);
    for (const char *config : {"TVE", "ZA*TVE"})
    {
        std::shared_ptr<GliderContext> ctx;
        og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);
        ss->setPlanner(std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, config));
        ASSERT_EQ(ss->solve(20.0), ob::PlannerStatus::EXACT_SOLUTION) << config;
        const auto w = states(ss->getSolutionPath());
        ASSERT_GE(w.size(), 2u);
        for (std::size_t i = 0; i + 1 < w.size(); ++i)
        {
            EXPECT_FALSE(legTouchesBySampling(a, w[i][0], w[i][1], w[i + 1][0], w[i + 1][1])) << config << " leg " << i;
            EXPECT_FALSE(legTouchesBySampling(b, w[i][0], w[i][1], w[i + 1][0], w[i + 1][1])) << config << " leg " << i;
            EXPECT_TRUE(env->legFree(w[i][0], w[i][1], w[i][2], w[i + 1][0], w[i + 1][1], w[i + 1][2]));
        }
        const PathResimulation r = resimulatePath(*ctx, ss->getSolutionPath(), p.t0);
        EXPECT_TRUE(r.valid) << r.reason;
        // the islands cost time: the same problem without them is faster
        GliderProblem open = p;
        open.environment = nullptr;
        std::shared_ptr<GliderContext> octx;
        og::SimpleSetupPtr oss = makeSimpleSetup(open, &octx);
        oss->setPlanner(std::make_shared<ZAStarTVE>(oss->getSpaceInformation(), octx, config));
        ASSERT_EQ(oss->solve(20.0), ob::PlannerStatus::EXACT_SOLUTION);
        const auto ow = states(oss->getSolutionPath());
        bool openCrosses = false;
        for (std::size_t i = 0; i + 1 < ow.size(); ++i)
            openCrosses =
                openCrosses || !env->legFree(ow[i][0], ow[i][1], ow[i][2], ow[i + 1][0], ow[i + 1][1], ow[i + 1][2]);
        EXPECT_TRUE(openCrosses) << "the islands should lie on the open-water route";
        EXPECT_GT(w.back()[2], ow.back()[2]);
    }
}

TEST(EnvironmentPlanning, RrtStarPathAroundIslandNeverCrossesIt)
{
    // Uniform weak current: RRT* finds paths quickly; a wide island sits on the straight line.
    auto env = islandAt(5.0, 0.0, 1.5, "A");
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(0.1, 0.0);
    p.environment = env;
    p.horizon = 60.0;
    p.start.x = 1.0;
    p.start.y = 0.0;
    p.goal.x = 9.0;
    p.goal.y = 0.0;
    p.goalTolerance = 1e-3;
    std::shared_ptr<GliderContext> ctx;
    og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);
    ss->setPlanner(std::make_shared<og::RRTstar>(ss->getSpaceInformation()));
    ss->setup();
    // stop at the first solution (any cost satisfies the threshold) or after a generous 30 s: the test checks the
    // path, not the speed
    ss->getProblemDefinition()->getOptimizationObjective()->setCostThreshold(ob::Cost(1e9));
    ss->solve(30.0);
    ASSERT_TRUE(ss->haveExactSolutionPath());
    const auto w = states(ss->getSolutionPath());
    const Polygon island = Polygon::regular(5.0, 0.0, 1.5, 24, 0.0, "A");
    for (std::size_t i = 0; i + 1 < w.size(); ++i)
    {
        EXPECT_FALSE(legTouchesBySampling(island, w[i][0], w[i][1], w[i + 1][0], w[i + 1][1])) << "leg " << i;
        EXPECT_LE(w[i][2], w[i + 1][2]);
    }
}

TEST(EnvironmentPlanning, LatticeRespectsDriftingIceAndClosure)
{
    // Ice drifting across the route with a short limit, and a lane closed during [0, 8]: the returned paths obey
    // both at the times they are flown (checked on every leg with the zones' own exact tests).
    auto env = std::make_shared<ForbiddenRegions>();
    auto ice = std::make_shared<IceZone>("I", Polygon::rectangle(1.0, -1.6, 3.4, 0.4, "I"), 0.0, 0.12, 0.0, 0.3);
    auto lane = std::make_shared<TimeWindowedZone>("lane", Polygon::rectangle(4.6, -4.0, 5.4, 2.2, "lane"),
                                                   std::vector<Interval>{{0.0, 8.0}});
    env->add(ice);
    env->add(lane);
    const GliderProblem p = jetProblem(env);
    std::shared_ptr<GliderContext> ctx;
    og::SimpleSetupPtr ss = makeSimpleSetup(p, &ctx);
    ss->setPlanner(std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE"));
    ASSERT_EQ(ss->solve(20.0), ob::PlannerStatus::EXACT_SOLUTION);
    const auto w = states(ss->getSolutionPath());
    for (std::size_t i = 0; i + 1 < w.size(); ++i)
    {
        EXPECT_LE(ice->longestUnderIce(w[i][0], w[i][1], w[i][2], w[i + 1][0], w[i + 1][1], w[i + 1][2]), 0.3);
        for (const Interval &in : lane->insideTimes(w[i][0], w[i][1], w[i][2], w[i + 1][0], w[i + 1][1], w[i + 1][2]))
        {
            EXPECT_GT(in.lo, 8.0) << "leg " << i << " is in the lane at t = " << in.lo;
        }
    }
    const PathResimulation r = resimulatePath(*ctx, ss->getSolutionPath(), p.t0);
    EXPECT_TRUE(r.valid) << r.reason;
}

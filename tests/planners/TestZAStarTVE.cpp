// ZAStarTVE (TVE / A*TVE / ZTVE / ZA*TVE, [EichhornRAS] Tables 1-2) through OMPL: equal optimum of TVE and A*TVE,
// ZA*TVE close to TVE on the meandering jet, closed-form straight-line times in a uniform current, unreachable goals,
// the termination condition, solve/clear cycles, forbidden regions, planner data, parameters and CALC-OPTDIR.
#include <gtest/gtest.h>

#include <sstream>

#include <map>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include <ompl/base/PlannerData.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "planners/TveSearch.h" // internal to the library (src/)
#include "ompl_glider/planners/ZAStarTVE.h"

using namespace ompl_glider;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
/// A disk that is forbidden at all times.
class DiskEnvironment : public Environment
{
public:
    DiskEnvironment(double cx, double cy, double r) : cx_(cx), cy_(cy), r_(r) {}
    bool pointFree(double x, double y, double) const override { return std::hypot(x - cx_, y - cy_) > r_; }
    bool legFree(double x1, double y1, double, double x2, double y2, double) const override
    {
        // Distance from the centre to the segment.
        const double dx = x2 - x1, dy = y2 - y1, L2 = dx * dx + dy * dy;
        double s = L2 > 0 ? ((cx_ - x1) * dx + (cy_ - y1) * dy) / L2 : 0.0;
        s = std::min(1.0, std::max(0.0, s));
        return std::hypot(x1 + s * dx - cx_, y1 + s * dy - cy_) > r_;
    }
    std::string whyBlocked(double x, double y, double t) const override
    {
        return pointFree(x, y, t) ? "" : "inside test disk";
    }

private:
    double cx_, cy_, r_;
};

struct PlanRun
{
    ob::PlannerStatus status;
    double time{0.0};
    std::uint64_t cfc{0}, cmc{0};
    bool checked{false};
    std::shared_ptr<ZAStarTVE> planner;
    og::SimpleSetupPtr ss;
};

GliderProblem jetProblem(double sx, double sy, double gx, double gy)
{
    GliderProblem p;
    p.field = std::make_shared<MeanderingJet>();
    p.start.x = sx;
    p.start.y = sy;
    p.goal.x = gx;
    p.goal.y = gy;
    return p;
}

PlanRun plan(const GliderProblem &p, const std::string &config, double seconds = 60.0)
{
    PlanRun r;
    std::shared_ptr<GliderContext> ctx;
    r.ss = makeSimpleSetup(p, &ctx);
    r.planner = std::make_shared<ZAStarTVE>(r.ss->getSpaceInformation(), ctx, config);
    r.ss->setPlanner(r.planner);
    r.ss->setup();
    r.status = r.ss->solve(ob::timedPlannerTerminationCondition(seconds));
    r.time = r.planner->getTravelTime();
    r.cfc = r.planner->getCostFunctionCalls();
    r.cmc = r.planner->getCurrentModelCalls();
    if (r.status == ob::PlannerStatus::EXACT_SOLUTION)
        r.checked = r.ss->getSolutionPath().check();
    return r;
}

double uniformTime(double L, double px, double py, double cu, double cv, double V)
{
    const double pc = px * cu + py * cv;
    return L / (pc + std::sqrt(pc * pc + V * V - cu * cu - cv * cv));
}

class Quiet : public ::testing::Environment
{
public:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
};
const auto *const kQuiet = ::testing::AddGlobalTestEnvironment(new Quiet);
} // namespace

// The five start positions of bench_table4 (goal (7.6, 1.2)) and two more pairs crossing the jet.
struct Pair
{
    double sx, sy, gx, gy;
};
static const Pair kJetPairs[] = {{0.4, -3.2, 7.6, 1.2}, {2.0, -2.4, 7.6, 1.2}, {3.2, -1.6, 7.6, 1.2},
                                 {4.8, -0.4, 7.6, 1.2}, {6.0, 0.4, 7.6, 1.2},  {9.6, -3.2, 1.2, 2.8},
                                 {1.0, 3.1, 8.3, -2.7}};

TEST(ZAStarTVE, AStarTveEqualsTveOnTheJet)
{
    for (const Pair &q : kJetPairs)
    {
        const PlanRun tve = plan(jetProblem(q.sx, q.sy, q.gx, q.gy), "TVE");
        const PlanRun astar = plan(jetProblem(q.sx, q.sy, q.gx, q.gy), "A*TVE");
        ASSERT_EQ(tve.status, ob::PlannerStatus::EXACT_SOLUTION);
        ASSERT_EQ(astar.status, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_NEAR(astar.time, tve.time, 1e-9) << "from (" << q.sx << ", " << q.sy << ")";
        EXPECT_LE(astar.cfc, tve.cfc);
        EXPECT_TRUE(tve.checked);
        EXPECT_TRUE(astar.checked);
    }
}

TEST(ZAStarTVE, ZAStarTveWithinHalfPercentOfTveOnTheJet)
{
    // The five Table-4 starts (see benchmarks/table4): pruning keeps the lattice optimum to 0.5 %.
    for (int i = 0; i < 5; ++i)
    {
        const Pair &q = kJetPairs[i];
        const PlanRun tve = plan(jetProblem(q.sx, q.sy, q.gx, q.gy), "TVE");
        const PlanRun z = plan(jetProblem(q.sx, q.sy, q.gx, q.gy), "ZA*TVE");
        const PlanRun zt = plan(jetProblem(q.sx, q.sy, q.gx, q.gy), "ZTVE");
        ASSERT_EQ(z.status, ob::PlannerStatus::EXACT_SOLUTION);
        ASSERT_EQ(zt.status, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_GE(z.time, tve.time - 1e-9); // TVE is the lattice optimum
        EXPECT_LE(z.time, 1.005 * tve.time) << "from (" << q.sx << ", " << q.sy << ")";
        EXPECT_LE(zt.time, 1.005 * tve.time);
        EXPECT_LT(z.cfc, tve.cfc); // pruning and the heuristic save cost-function calls
        EXPECT_LT(z.cmc, tve.cmc);
        EXPECT_TRUE(z.checked);
        EXPECT_TRUE(zt.checked);
    }
}

TEST(ZAStarTVE, UniformCurrentGivesClosedFormStraightLineTime)
{
    // Start and goal lattice-aligned along the offset (3, 1): 5 edges on one straight line, which is the fastest
    // path in a uniform current, so every configuration must return its closed-form time.
    const double cu = 0.2, cv = 0.1, V = 0.5;
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(cu, cv);
    p.start.x = 0.4;
    p.start.y = -2.0;
    p.goal.x = 6.4;
    p.goal.y = 0.0;
    const double L = std::hypot(6.0, 2.0);
    const double expected = uniformTime(L, 6.0 / L, 2.0 / L, cu, cv, V);
    for (const char *config : {"TVE", "A*TVE", "ZTVE", "ZA*TVE"})
    {
        const PlanRun r = plan(p, config);
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION) << config;
        EXPECT_NEAR(r.time, expected, 1e-9 * expected) << config;
        EXPECT_TRUE(r.checked) << config;
        const auto &w = r.planner->getWaypoints();
        ASSERT_EQ(w.size(), 6u) << config; // 5 edges of offset (3, 1)
        for (const auto &wp : w)
            EXPECT_NEAR((wp.x - 0.4) * 1.0 / 3.0, wp.y + 2.0, 1e-9); // on the line
        // The path's cost under the travel-time objective is the travel time.
        const auto &path = r.ss->getSolutionPath();
        const double cost = path.cost(r.ss->getOptimizationObjective()).value();
        EXPECT_NEAR(cost, expected, 1e-6 * expected) << config;
    }
}

TEST(ZAStarTVE, ExactOffGridStartAndGoalAreKept)
{
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(0.2, 0.1);
    p.start.x = 0.53;
    p.start.y = -1.91;
    p.goal.x = 6.27;
    p.goal.y = 0.17;
    const PlanRun r = plan(p, "ZA*TVE");
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    const auto &w = r.planner->getWaypoints();
    ASSERT_GE(w.size(), 2u);
    EXPECT_DOUBLE_EQ(w.front().x, 0.53);
    EXPECT_DOUBLE_EQ(w.front().y, -1.91);
    EXPECT_DOUBLE_EQ(w.back().x, 6.27);
    EXPECT_DOUBLE_EQ(w.back().y, 0.17);
    EXPECT_DOUBLE_EQ(w.front().t, 0.0);
    // No path can beat the straight line in a uniform current.
    const double L = std::hypot(6.27 - 0.53, 0.17 + 1.91);
    EXPECT_GE(r.time, uniformTime(L, (6.27 - 0.53) / L, (0.17 + 1.91) / L, 0.2, 0.1, 0.5) - 1e-9);
    EXPECT_TRUE(r.checked);
}

TEST(ZAStarTVE, UnreachableGoalGivesNoSolution)
{
    // Current of 1.0 eastward, V = 0.5: nothing west of the start can be reached.
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(1.0, 0.0);
    p.start.x = 6.0;
    p.start.y = 0.0;
    p.goal.x = 2.0;
    p.goal.y = 0.4;
    for (const char *config : {"TVE", "A*TVE", "ZTVE", "ZA*TVE"})
    {
        const PlanRun r = plan(p, config);
        EXPECT_EQ(r.status, ob::PlannerStatus::ABORT) << config; // not TIMEOUT: more time would not help
        EXPECT_EQ(r.planner->lastOutcome(), TveOutcome::Exhausted) << config;
        EXPECT_FALSE(r.ss->getProblemDefinition()->hasSolution()) << config;
        // Exhaustion is bounded: each vertex expanded a few times at most (546 vertices).
        EXPECT_LT(r.planner->getExpandedVertices(), 4u * 546u) << config;
    }
}

TEST(ZAStarTVE, AlreadyTrueTerminationConditionReturnsAtOnce)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(jetProblem(0.4, -3.2, 7.6, 1.2), &ctx);
    auto planner = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE");
    ss->setPlanner(planner);
    ss->setup();
    const auto status = ss->solve(ob::plannerAlwaysTerminatingCondition());
    EXPECT_EQ(status, ob::PlannerStatus::TIMEOUT);
    EXPECT_EQ(planner->lastOutcome(), TveOutcome::Terminated);
    EXPECT_EQ(planner->getExpandedVertices(), 0u);
    EXPECT_EQ(planner->getCostFunctionCalls(), 0u);
    EXPECT_FALSE(ss->getProblemDefinition()->hasSolution());
}

TEST(ZAStarTVE, EarlyTerminationGivesApproximateSolution)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(jetProblem(0.4, -3.2, 7.6, 1.2), &ctx);
    auto planner = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "TVE");
    ss->setPlanner(planner);
    ss->setup();
    int calls = 0;
    const ob::PlannerTerminationCondition ptc([&calls] { return ++calls > 10; });
    const auto status = ss->solve(ptc);
    EXPECT_EQ(status, ob::PlannerStatus::APPROXIMATE_SOLUTION);
    EXPECT_EQ(planner->lastOutcome(), TveOutcome::Terminated);
    EXPECT_TRUE(ss->getProblemDefinition()->hasApproximateSolution());
    const auto &w = planner->getWaypoints();
    ASSERT_GE(w.size(), 2u);
    EXPECT_LT(std::hypot(w.back().x - 7.6, w.back().y - 1.2), std::hypot(0.4 - 7.6, -3.2 - 1.2));
    EXPECT_TRUE(ss->getSolutionPath().check());
    // Far fewer expansions than a full search.
    const PlanRun full = plan(jetProblem(0.4, -3.2, 7.6, 1.2), "TVE");
    EXPECT_LT(planner->getExpandedVertices(), full.planner->getExpandedVertices());
}

TEST(ZAStarTVE, SolveClearCyclesGiveTheSameAnswer)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(jetProblem(2.0, -2.4, 7.6, 1.2), &ctx);
    auto planner = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE");
    ss->setPlanner(planner);
    ss->setup();
    double t0 = 0.0;
    std::uint64_t cfc0 = 0, cmc0 = 0;
    for (int i = 0; i < 3; ++i)
    {
        ss->clear();
        ASSERT_EQ(ss->solve(10.0), ob::PlannerStatus::EXACT_SOLUTION);
        if (i == 0)
        {
            t0 = planner->getTravelTime();
            cfc0 = planner->getCostFunctionCalls();
            cmc0 = planner->getCurrentModelCalls();
        }
        EXPECT_EQ(planner->getTravelTime(), t0);
        EXPECT_EQ(planner->getCostFunctionCalls(), cfc0);
        EXPECT_EQ(planner->getCurrentModelCalls(), cmc0);
        EXPECT_TRUE(ss->getSolutionPath().check());
    }
    // solve() again without clear(): same answer (the start is read from the problem definition each time).
    ASSERT_EQ(planner->solve(ob::timedPlannerTerminationCondition(10.0)), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(planner->getTravelTime(), t0);
}

TEST(ZAStarTVE, PathStatesCarryArrivalTimesAndLegHeadings)
{
    const PlanRun r = plan(jetProblem(3.2, -1.6, 7.6, 1.2), "ZA*TVE");
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    const auto &path = r.ss->getSolutionPath();
    const auto &w = r.planner->getSolutionWaypoints(); // the returned (smoothed, refined) path
    ASSERT_EQ(path.getStateCount(), w.size());
    ASSERT_GE(w.size(), 2u);
    for (std::size_t i = 0; i < w.size(); ++i)
    {
        const auto *s = path.getState(i)->as<TimeSE2StateSpace::StateType>();
        EXPECT_EQ(s->getX(), w[i].x);
        EXPECT_EQ(s->getY(), w[i].y);
        EXPECT_EQ(s->getTime(), w[i].t);
        EXPECT_GE(s->getYaw(), -M_PI); // SO(2)'s range [-pi, pi)
        EXPECT_LT(s->getYaw(), M_PI);
        // The yaw is the direction of the leg reaching the state (the first leg's for the start).
        const std::size_t a = i == 0 ? 0 : i - 1, b = i == 0 ? 1 : i;
        const double d = s->getYaw() - std::atan2(w[b].y - w[a].y, w[b].x - w[a].x);
        EXPECT_NEAR(std::remainder(d, 2.0 * M_PI), 0.0, 1e-12) << "state " << i;
        if (i > 0)
        {
            EXPECT_GT(w[i].t, w[i - 1].t);
        }
    }
    // getTravelTime() is the lattice path's time; the returned path is post-processed and never slower.
    const auto &lattice = r.planner->getWaypoints();
    EXPECT_NEAR(lattice.back().t - lattice.front().t, r.time, 1e-12);
    EXPECT_LE(w.back().t - w.front().t, r.time + 1e-12);
    EXPECT_EQ(w.front().t, lattice.front().t);
}

TEST(ZAStarTVE, ForbiddenStartGoalAndObstacle)
{
    GliderProblem p;
    p.field = std::make_shared<UniformCurrent>(0.2, 0.0);
    p.start.x = 1.0;
    p.start.y = 0.0;
    p.goal.x = 9.0;
    p.goal.y = 0.0;
    // Obstacle across the straight line.
    p.environment = std::make_shared<DiskEnvironment>(5.0, 0.0, 1.0);
    const PlanRun r = plan(p, "ZA*TVE");
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    const auto &w = r.planner->getWaypoints();
    for (std::size_t i = 1; i < w.size(); ++i)
        EXPECT_TRUE(p.environment->legFree(w[i - 1].x, w[i - 1].y, w[i - 1].t, w[i].x, w[i].y, w[i].t));
    EXPECT_GT(r.time, 8.0 / 0.7 + 1e-6); // slower than the blocked straight line
    EXPECT_TRUE(r.checked);

    // Blocked start / goal: the status and an error message saying which and why.
    struct Capture : ompl::msg::OutputHandler
    {
        std::string text;
        void log(const std::string &t, ompl::msg::LogLevel, const char *, int) override { text += t + "\n"; }
    } capture;
    ompl::msg::useOutputHandler(&capture);
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    GliderProblem bs = p;
    bs.environment = std::make_shared<DiskEnvironment>(1.0, 0.0, 0.5);
    const auto startStatus = plan(bs, "ZA*TVE").status;
    const std::string startLog = capture.text;
    capture.text.clear();
    GliderProblem bg = p;
    bg.environment = std::make_shared<DiskEnvironment>(9.0, 0.0, 0.5);
    const auto goalStatus = plan(bg, "TVE").status;
    const std::string goalLog = capture.text;
    ompl::msg::restorePreviousOutputHandler();
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    EXPECT_EQ(startStatus, ob::PlannerStatus::INVALID_START);
    EXPECT_NE(startLog.find("invalid start"), std::string::npos) << startLog;
    EXPECT_NE(startLog.find("inside test disk"), std::string::npos) << startLog;
    EXPECT_EQ(goalStatus, ob::PlannerStatus::INVALID_GOAL);
    EXPECT_NE(goalLog.find("invalid goal"), std::string::npos) << goalLog;
    EXPECT_NE(goalLog.find("inside test disk"), std::string::npos) << goalLog;
}

TEST(ZAStarTVE, PlannerDataHoldsTheExploredTreeAndCounters)
{
    const PlanRun r = plan(jetProblem(4.8, -0.4, 7.6, 1.2), "A*TVE");
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    ob::PlannerData pd(r.ss->getSpaceInformation());
    r.planner->getPlannerData(pd);
    EXPECT_GT(pd.numVertices(), r.planner->getWaypoints().size());
    EXPECT_EQ(pd.numEdges(), pd.numVertices() - 1); // a tree
    EXPECT_EQ(pd.numStartVertices(), 1u);
    EXPECT_EQ(pd.numGoalVertices(), 1u);
    // CFC of the search plus the smoothing and refinement of the returned path
    EXPECT_GT(r.planner->getPostprocessCostFunctionCalls(), 0u);
    EXPECT_EQ(pd.properties.at("cost function calls INTEGER"),
              std::to_string(r.planner->getCostFunctionCalls() + r.planner->getPostprocessCostFunctionCalls()));
    EXPECT_EQ(pd.properties.at("current model calls INTEGER"), std::to_string(r.planner->getCurrentModelCalls()));
    // best cost: the returned path's travel time, which post-processing makes no later than the lattice path's
    const auto &sol = r.planner->getSolutionWaypoints();
    EXPECT_NEAR(std::stod(pd.properties.at("best cost REAL")), sol.back().t - sol.front().t, 1e-9);
    EXPECT_LE(sol.back().t - sol.front().t, r.time * (1.0 + 1e-12));
    // Calling it twice is fine (states are kept by the planner).
    ob::PlannerData pd2(r.ss->getSpaceInformation());
    r.planner->getPlannerData(pd2);
    EXPECT_EQ(pd2.numVertices(), pd.numVertices());
}

TEST(ZAStarTVE, ConfigurationsAndParameters)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(jetProblem(4.8, -0.4, 7.6, 1.2), &ctx);
    const auto si = ss->getSpaceInformation();
    for (const char *c : {"TVE", "A*TVE", "ZTVE", "ZA*TVE"})
    {
        auto pl = ZAStarTVE::allocator(ctx, c)(si);
        EXPECT_EQ(pl->getName(), c);
    }
    ZAStarTVE tve(si, ctx, "TVE");
    EXPECT_FALSE(tve.getHeuristic());
    EXPECT_FALSE(tve.getZermelo());
    ZAStarTVE za(si, ctx);
    EXPECT_EQ(za.getName(), "ZA*TVE");
    EXPECT_TRUE(za.getHeuristic());
    EXPECT_TRUE(za.getZermelo());
    EXPECT_TRUE(za.params().setParam("sectors", "2"));
    EXPECT_EQ(za.getSectors(), 2u);
    EXPECT_TRUE(za.params().setParam("grid_size", "0.5"));
    EXPECT_DOUBLE_EQ(za.getGridSize(), 0.5);
    EXPECT_TRUE(za.params().setParam("delta_phi_max", "30"));
    EXPECT_DOUBLE_EQ(za.getDeltaPhiMax(), 30.0);
    EXPECT_TRUE(za.params().setParam("heuristic", "0"));
    EXPECT_FALSE(za.getHeuristic());
    EXPECT_TRUE(za.params().hasParam("zermelo"));
    EXPECT_TRUE(za.params().setParam("turn_widening", "0"));
    EXPECT_DOUBLE_EQ(za.getTurnWidening(), 0.0);
    EXPECT_TRUE(za.params().setParam("course_extrapolation", "0"));
    EXPECT_DOUBLE_EQ(za.getCourseExtrapolation(), 0.0);
    EXPECT_THROW(ZAStarTVE(si, ctx, "RRT"), Error);
    EXPECT_THROW(za.setSectors(0), Error);
    EXPECT_THROW(za.setGridSize(-1.0), Error);
}

TEST(ZAStarTVE, EveryNumericParameterTakesItsDeclaredRangeAndNothingBeyond)
{
    // One statement of each range: the suggestion mission files and the command line check ("lo:step:hi") is what
    // the setter accepts, both ends in, just beyond either end refused (by the setter itself: the C++ API).
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(jetProblem(4.8, -0.4, 7.6, 1.2), &ctx);
    ZAStarTVE za(ss->getSpaceInformation(), ctx);
    const std::map<std::string, ompl::base::GenericParamPtr> params = za.params().getParams();
    int checked = 0;
    for (const auto &[name, param] : params)
    {
        const std::string range = param->getRangeSuggestion();
        const std::size_t a = range.find(':'), b = range.rfind(':');
        if (a == std::string::npos || a == b)
            continue; // "0,1": a switch
        const double lo = std::stod(range.substr(0, a)), hi = std::stod(range.substr(b + 1));
        ASSERT_LT(lo, hi) << name << " " << range;
        const bool integer = name == "sectors" || name == "coarse_factor" || name == "corridor_blocks" ||
                             name == "zermelo_steps" || name == "refiner_max_evaluations";
        const auto text = [&](double v) {
            std::ostringstream os;
            os.precision(17);
            os << (integer ? std::round(v) : v);
            return os.str();
        };
        for (const double v : {lo, hi})
        {
            EXPECT_TRUE(za.params().setParam(name, text(v))) << name << " = " << text(v) << " (range " << range << ")";
            EXPECT_EQ(std::stod(za.params().getParam(name)->getValue()), std::stod(text(v))) << name;
        }
        const double beyond = integer ? 1.0 : 1e-6 * std::max(1.0, hi - lo);
        for (const double v : {lo - beyond, hi + beyond})
        {
            if (integer && v < 0.0)
                continue; // an unsigned parameter cannot be given a negative number
            bool taken = false;
            try
            {
                taken = za.params().setParam(name, text(v));
            }
            catch (const Error &)
            {
            }
            EXPECT_FALSE(taken) << name << " = " << text(v) << " taken beyond its range " << range;
        }
        ++checked;
    }
    EXPECT_GE(checked, 9); // grid_size, sectors and ZA*TVE's own numbers
    // a value the C++ API and the declared range both take (1..64 declared against 1..10000 accepted before)
    EXPECT_TRUE(za.params().setParam("zermelo_steps", "100"));
    EXPECT_EQ(za.getZermeloSteps(), 100u);
}

TEST(ZAStarTVE, CoarserConnectivityIsNeverFaster)
{
    // The 1-sector lattice's edges are a subset of the 3-sector lattice's: TVE on it cannot be faster.
    GliderProblem p = jetProblem(0.4, -3.2, 7.6, 1.2);
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(p, &ctx);
    auto one = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "TVE");
    one->setSectors(1);
    ss->setPlanner(one);
    ss->setup();
    ASSERT_EQ(ss->solve(30.0), ob::PlannerStatus::EXACT_SOLUTION);
    const PlanRun three = plan(p, "TVE");
    EXPECT_GE(one->getTravelTime(), three.time - 1e-12);
}

TEST(TveSearch, CalcOptDirInUniformCurrentKeepsTheEdgeCourse)
{
    auto ctx = std::make_shared<GliderContext>();
    ctx->field = std::make_shared<UniformCurrent>(0.3, -0.2);
    ctx->travel = std::make_shared<TravelTimeCalculator>(ctx->field);
    ctx->region = Region{0, 10, -4, 4, 0, 0, 0, 100};
    TveSearch s(ctx, 0.4, 3);
    const auto phi = s.calcOptimalCourse(1.0, 1.0, 0.0, 2.2, 1.4, 2.0, 3);
    ASSERT_TRUE(phi.has_value());
    EXPECT_NEAR(*phi, std::atan2(0.4, 1.2), 1e-12); // no gradients: the heading, hence the course, is constant
}

TEST(TveSearch, CalcOptDirMatchesAnIndependentZermeloIntegrationInShear)
{
    // Shear u = a y ([EichhornRAS] Eq. 2 reduces to dtheta/dt = -a cos^2 theta). Reference: RK4 with 4000 steps.
    const double a = -0.8, V = 0.5;
    auto ctx = std::make_shared<GliderContext>();
    ctx->field = std::make_shared<LinearShear>(a);
    ctx->travel = std::make_shared<TravelTimeCalculator>(ctx->field);
    ctx->region = Region{-10, 10, -10, 10, 0, 0, 0, 100};
    TveSearch s(ctx, 0.4, 3);
    const double px = 0.0, py = 0.2, ux = 1.2, uy = 0.6, tp = 0.0, tu = 3.0;
    const auto phi = s.calcOptimalCourse(px, py, tp, ux, uy, tu, 400);
    ASSERT_TRUE(phi.has_value());

    // Independent reference.
    double x = 0.5 * (px + ux), y = 0.5 * (py + uy);
    const double L = std::hypot(ux - px, uy - py), ex = (ux - px) / L, ey = (uy - py) / L;
    const double cu = a * y, pc = ex * cu, sp = pc + std::sqrt(pc * pc + V * V - cu * cu);
    double th = std::atan2(sp * ey, sp * ex - cu);
    auto f = [&](double, const double st[3], double d[3]) {
        d[0] = a * st[1] + V * std::cos(st[2]);
        d[1] = V * std::sin(st[2]);
        d[2] = -a * std::cos(st[2]) * std::cos(st[2]);
    };
    double st[3] = {x, y, th};
    const int n = 4000;
    const double h = (tu - 0.5 * (tp + tu)) / n;
    for (int i = 0; i < n; ++i)
    {
        double k1[3], k2[3], k3[3], k4[3], tmp[3];
        f(0, st, k1);
        for (int j = 0; j < 3; ++j)
            tmp[j] = st[j] + 0.5 * h * k1[j];
        f(0, tmp, k2);
        for (int j = 0; j < 3; ++j)
            tmp[j] = st[j] + 0.5 * h * k2[j];
        f(0, tmp, k3);
        for (int j = 0; j < 3; ++j)
            tmp[j] = st[j] + h * k3[j];
        f(0, tmp, k4);
        for (int j = 0; j < 3; ++j)
            st[j] += h / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
    const double ref = std::atan2(V * std::sin(st[2]), a * st[1] + V * std::cos(st[2]));
    EXPECT_NEAR(*phi, ref, 1e-5);
    // And the course really turned (the test is not trivial).
    EXPECT_GT(std::abs(ref - std::atan2(ey, ex)), 0.05);
}

TEST(ZAStarTVE, BenchmarkLogsCostFunctionAndCurrentModelCalls)
{
    std::shared_ptr<GliderContext> ctx;
    auto ss = makeSimpleSetup(jetProblem(4.8, -0.4, 7.6, 1.2), &ctx);
    ompl::tools::Benchmark bench(*ss, "table4");
    bench.addPlannerAllocator(ZAStarTVE::allocator(ctx, "TVE"));
    bench.addPlannerAllocator(ZAStarTVE::allocator(ctx, "ZA*TVE"));
    ompl::tools::Benchmark::Request req(10.0, 1000.0, 1, 0.05, false, false, false);
    bench.benchmark(req);
    const auto &exp = bench.getRecordedExperimentData();
    ASSERT_EQ(exp.planners.size(), 2u);
    std::uint64_t cfc[2];
    for (int i = 0; i < 2; ++i)
    {
        ASSERT_EQ(exp.planners[i].runs.size(), 1u);
        const auto &run = exp.planners[i].runs[0];
        ASSERT_TRUE(run.count("cost function calls INTEGER"));
        ASSERT_TRUE(run.count("current model calls INTEGER"));
        cfc[i] = std::stoull(run.at("cost function calls INTEGER"));
        EXPECT_GT(cfc[i], 0u);
    }
    EXPECT_EQ(exp.planners[0].name, "geometric_TVE"); // Benchmark prefixes the planner type
    EXPECT_LT(cfc[1], cfc[0]);
}

TEST(ZAStarTVE, CampaignOpenWaterWithinHalfPercentOfTve)
{
    // The benchmark campaign's open-water problem (benchmarks/campaign/CampaignProblems.h). Without the
    // certification phase the Zermelo cone missed the lattice optimum here: ZTVE / ZA*TVE were 1.25 % slower.
    GliderProblem p = jetProblem(0.6, -2.6, 9.4, 2.6);
    p.horizon = 40.0;
    const PlanRun tve = plan(p, "TVE");
    ASSERT_EQ(tve.status, ob::PlannerStatus::EXACT_SOLUTION);
    for (const char *config : {"ZTVE", "ZA*TVE"})
    {
        const PlanRun z = plan(p, config);
        ASSERT_EQ(z.status, ob::PlannerStatus::EXACT_SOLUTION) << config;
        EXPECT_GE(z.time, tve.time - 1e-9) << config;
        EXPECT_LE(z.time, 1.005 * tve.time) << config;
        EXPECT_LT(z.cfc, tve.cfc) << config;
        EXPECT_TRUE(z.checked) << config;
    }
}

TEST(TveSearch, CertificationToleranceBoundsTheDeviationFromTve)
{
    // Random lattice start/goal pairs on the jet: the certified pruned search (tolerance tol) is within (1 + tol)
    // of TVE's lattice optimum, and with tol = 0 equals it; the paper's rule (off) has no such bound.
    GliderProblem p = jetProblem(0.0, 0.0, 0.0, 0.0);
    auto ctx = makeGliderContext(p);
    TveSearch search(ctx, 0.4, 3);
    TveOptions tve;
    tve.heuristic = tve.zermelo = false;
    TveOptions exact, loose;
    exact.certifyTolerance = 0.0;
    loose.certifyTolerance = 0.3;
    std::uint64_t seed = 12345;
    auto next = [&seed](int n) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<int>((seed >> 33) % static_cast<std::uint64_t>(n));
    };
    int compared = 0;
    for (int i = 0; i < 12; ++i)
    {
        const double sx = 0.4 * (1 + next(24)), sy = -4.0 + 0.4 * (1 + next(19));
        const double gx = 0.4 * (1 + next(24)), gy = -4.0 + 0.4 * (1 + next(19));
        const TveResult a = search.run(sx, sy, p.t0, gx, gy, tve);
        const TveResult b = search.run(sx, sy, p.t0, gx, gy, exact);
        const TveResult c = search.run(sx, sy, p.t0, gx, gy, loose);
        if (a.outcome != TveOutcome::Exact)
            continue;
        ++compared;
        ASSERT_EQ(b.outcome, TveOutcome::Exact);
        ASSERT_EQ(c.outcome, TveOutcome::Exact);
        EXPECT_NEAR(b.travelTime, a.travelTime, 1e-9 * a.travelTime)
            << "(" << sx << ", " << sy << ") -> (" << gx << ", " << gy << ")";
        EXPECT_LE(c.travelTime, 1.3 * a.travelTime + 1e-9);
        EXPECT_GE(c.travelTime, a.travelTime - 1e-9);
    }
    EXPECT_GE(compared, 8);
}

TEST(TveSearch, DepartsAtTheGivenTimeInsideTheWindow)
{
    // run() departs at its t0 (d[s] = t0); a t0 outside [region.tMin, region.tMax] or not finite is an invalid start.
    GliderProblem p = jetProblem(3.2, -1.6, 7.6, 1.2);
    p.t0 = 2.0;
    auto ctx = makeGliderContext(p); // window [2, 62]
    TveSearch search(ctx, 0.4, 3);
    const TveResult r = search.run(3.2, -1.6, 2.0, 7.6, 1.2, TveOptions{});
    ASSERT_EQ(r.outcome, TveOutcome::Exact);
    EXPECT_EQ(r.waypoints.front().t, 2.0);
    EXPECT_EQ(r.travelTime, r.waypoints.back().t - 2.0);
    const TveResult later = search.run(3.2, -1.6, 5.0, 7.6, 1.2, TveOptions{});
    ASSERT_EQ(later.outcome, TveOutcome::Exact);
    EXPECT_EQ(later.waypoints.front().t, 5.0);
    EXPECT_NE(later.travelTime, r.travelTime); // the jet meanders: the departure time matters
    for (double t0 : {1.0, 62.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        const TveResult bad = search.run(3.2, -1.6, t0, 7.6, 1.2, TveOptions{});
        EXPECT_EQ(bad.outcome, TveOutcome::InvalidStart) << t0;
        EXPECT_NE(bad.message.find("start time"), std::string::npos) << bad.message;
    }
}

TEST(ZAStarTVE, DepartsAtTheStartStateTime)
{
    // The departure is the start state's time: a start moved to t = 7 on a setup made for t0 = 5 gives the same
    // search as a setup made for t0 = 7; a start time outside the window is an invalid start.
    GliderProblem p = jetProblem(3.2, -1.6, 7.6, 1.2);
    p.t0 = 5.0;
    PlanRun r = plan(p, "TVE");
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(r.planner->getWaypoints().front().t, 5.0);
    EXPECT_EQ(r.planner->getSolutionWaypoints().front().t, 5.0);
    const ob::ProblemDefinitionPtr &pdef = r.ss->getProblemDefinition();
    EXPECT_EQ(pdef->getSolutions().front().cost_.value(), r.planner->getSolutionWaypoints().back().t - 5.0);

    auto restart = [&](double t) {
        ob::ScopedState<TimeSE2StateSpace> start(r.ss->getStateSpace());
        start->setXYT(3.2, -1.6, t);
        start->setYaw(0.0);
        pdef->clearStartStates();
        pdef->clearSolutionPaths();
        pdef->addStartState(start);
        r.planner->clear();
        return r.planner->solve(ob::timedPlannerTerminationCondition(60.0));
    };
    ASSERT_EQ(restart(7.0), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(r.planner->getWaypoints().front().t, 7.0);
    p.t0 = 7.0;
    const PlanRun at7 = plan(p, "TVE");
    ASSERT_EQ(at7.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(r.planner->getTravelTime(), at7.time);
    EXPECT_EQ(restart(66.0), ob::PlannerStatus::INVALID_START); // after the window [5, 65]
}

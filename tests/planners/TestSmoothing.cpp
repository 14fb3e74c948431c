// Path smoothing in a time-varying field ([EichhornRAS] Table 3): closed forms in a uniform current, never a later
// arrival on random paths in the meandering jet, obstacles respected, infeasible input untouched, OMPL path adapter.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include <ompl/base/SpaceInformation.h>

#include "PostprocessTestUtil.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"
#include "ompl_glider/routes/PathSmoother.h"
#include "planners/TveSearch.h" // internal to the library (src/)

using namespace ompl_glider;
using namespace ompl_glider::test;

namespace
{
/// Still water, except an adverse current u = -1 (twice V = 0.5) east of x = 1 before t = 5: a glider must wait
/// west of x = 1 until the current stops.
class AdverseUntilFive : public CurrentField
{
public:
    double maxSpeed(const Region &) const override { return 1.0; }
    std::string name() const override { return "adverse until t=5"; }

protected:
    Velocity evaluate(double x, double, double, double t) const override
    {
        return {x > 1.0 && t < 5.0 ? -1.0 : 0.0, 0.0};
    }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }
};

double smoothingUniformTime(double L, double px, double py, double cu, double cv, double V)
{
    const double pc = px * cu + py * cv;
    return L / (pc + std::sqrt(pc * pc + V * V - cu * cu - cv * cv));
}
} // namespace

TEST(PathSmoother, StaircaseInUniformCurrentBecomesStraightLeg)
{
    auto ctx = makeContext(std::make_shared<UniformCurrent>(0.2, 0.1), 0.5, box(-1, 10, -1, 10));
    std::vector<TimedPoint> stairs;
    for (int i = 0; i <= 8; ++i)
        stairs.push_back({0.5 * ((i + 1) / 2), 0.5 * (i / 2), 0.0}); // (0,0),(0.5,0),(0.5,0.5),(1,0.5),...
    const std::uint64_t cfc0 = ctx->travel->costFunctionCalls();
    const SmoothingResult r = PathSmoother(ctx).smooth(stairs);
    const std::uint64_t cfc = ctx->travel->costFunctionCalls() - cfc0;
    ASSERT_EQ(r.waypointsBefore, 9u);
    ASSERT_EQ(r.waypointsAfter, 2u); // the straight leg is the fastest in a uniform current
    EXPECT_EQ(r.waypoints.front().x, 0.0);
    EXPECT_EQ(r.waypoints.back().x, 2.0);
    EXPECT_EQ(r.waypoints.back().y, 2.0);
    const double L = std::hypot(2.0, 2.0);
    EXPECT_NEAR(r.arrivalAfter, smoothingUniformTime(L, 2 / L, 2 / L, 0.2, 0.1, 0.5), 1e-9);
    EXPECT_LT(r.arrivalAfter, r.arrivalBefore);
    EXPECT_EQ(r.costFunctionCalls, cfc);     // the calculator's own count
    EXPECT_GE(r.costFunctionCalls, 8u + 1u); // at least the retiming of the 8 input legs and the merged leg
}

TEST(PathSmoother, NeverLaterOnJetLatticePaths)
{
    // Inputs: lattice paths (ZA*TVE core on a 0.5 grid) across the jet, as found and with random jitter of the
    // interior waypoints, at several departure times.
    auto jet = std::make_shared<MeanderingJet>();
    auto ctx = makeContext(jet, 0.5, box(0, 10, -4, 4));
    PathSmoother smoother(ctx);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jit(-0.15, 0.15);
    const double pairs[][4] = {{1, -3, 8, 3}, {1, 3, 9, -2.5}, {2, -3.5, 7, 3.5}, {0.5, 0, 9.5, 1}};
    int feasible = 0, smoothedSome = 0;
    for (const auto &pr : pairs)
        for (double t0 : {0.0, 5.0})
        {
            TveSearch s2(ctx, 0.5, 2);
            const TveResult lat = s2.run(pr[0], pr[1], t0, pr[2], pr[3], TveOptions{});
            ASSERT_EQ(lat.outcome, TveOutcome::Exact);
            for (int variant = 0; variant < 4; ++variant)
            {
                std::vector<TimedPoint> wp = lat.waypoints;
                if (variant > 0)
                    for (std::size_t i = 1; i + 1 < wp.size(); ++i)
                    {
                        wp[i].x += jit(rng);
                        wp[i].y += jit(rng);
                    }
                const SmoothingResult r = smoother.smooth(wp); // departure: wp.front().t = t0
                if (!std::isfinite(r.arrivalBefore))
                {
                    EXPECT_EQ(r.waypointsAfter, r.waypointsBefore); // infeasible input is returned unchanged
                    continue;
                }
                ++feasible;
                if (variant == 0)
                {
                    EXPECT_NEAR(r.arrivalBefore, lat.waypoints.back().t, 1e-9); // same travel-time code
                }
                EXPECT_LE(r.arrivalAfter, r.arrivalBefore * (1.0 + kSmoothingTieTolerance));
                EXPECT_LE(r.waypointsAfter, r.waypointsBefore);
                smoothedSome += r.waypointsAfter < r.waypointsBefore;
                ASSERT_GE(r.waypoints.size(), 2u);
                EXPECT_EQ(r.waypoints.front().x, wp.front().x);
                EXPECT_EQ(r.waypoints.back().y, wp.back().y);
                // The reported times are the re-simulation of the reported waypoints.
                const auto re = retimeWaypoints(*ctx, r.waypoints, t0);
                for (std::size_t i = 0; i < re.size(); ++i)
                    EXPECT_EQ(re[i].t, r.waypoints[i].t);
            }
        }
    EXPECT_GE(feasible, 16);
    EXPECT_GT(smoothedSome, feasible * 3 / 4);
}

TEST(PathSmoother, DoesNotMergeAcrossObstacle)
{
    // A box between start and goal; the path goes round it. The direct leg would be faster but is blocked.
    auto env = std::make_shared<BoxEnvironment>(2, 3, -1, 1);
    auto ctx = makeContext(std::make_shared<UniformCurrent>(0.0, 0.0), 0.5, box(-1, 6, -3, 3), env);
    const std::vector<TimedPoint> wp = {{0, 0, 0}, {1, 1.5, 0}, {2, 1.5, 0}, {3, 1.5, 0}, {4, 1.5, 0}, {5, 0, 0}};
    const SmoothingResult r = PathSmoother(ctx).smooth(wp);
    EXPECT_LT(r.waypointsAfter, r.waypointsBefore);
    EXPECT_GE(r.waypointsAfter, 3u);
    EXPECT_LE(r.arrivalAfter, r.arrivalBefore * (1.0 + kSmoothingTieTolerance));
    for (std::size_t i = 1; i < r.waypoints.size(); ++i)
        EXPECT_TRUE(env->legFree(r.waypoints[i - 1].x, r.waypoints[i - 1].y, r.waypoints[i - 1].t, r.waypoints[i].x,
                                 r.waypoints[i].y, r.waypoints[i].t));
    // In still water the result must be the straight line around the corners: (0,0)->(2,1.5)?->... at least no
    // leg crosses the box, and the length shrank.
    EXPECT_LT(pathLength(r.waypoints), pathLength(wp));
}

TEST(PathSmoother, InfeasiblePathUnchanged)
{
    // Current 1.0 eastward, V = 0.5: any leg heading west is infeasible.
    auto ctx = makeContext(std::make_shared<UniformCurrent>(1.0, 0.0), 0.5, box(-10, 10, -10, 10));
    const std::vector<TimedPoint> wp = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-3, 1, 0}};
    const SmoothingResult r = PathSmoother(ctx).smooth(wp);
    EXPECT_FALSE(std::isfinite(r.arrivalBefore));
    ASSERT_EQ(r.waypointsAfter, 4u);
    for (std::size_t i = 0; i < wp.size(); ++i)
    {
        EXPECT_EQ(r.waypoints[i].x, wp[i].x);
        EXPECT_EQ(r.waypoints[i].y, wp[i].y);
    }
}

TEST(PathSmoother, OmplPathAdapter)
{
    ompl::base::RealVectorBounds b(2);
    b.setLow(0, -1);
    b.setHigh(0, 10);
    b.setLow(1, -1);
    b.setHigh(1, 10);
    auto space = std::make_shared<TimeSE2StateSpace>(b, 0.0, 100.0);
    auto si = std::make_shared<ompl::base::SpaceInformation>(space);
    si->setStateValidityChecker([](const ompl::base::State *) { return true; });
    si->setup();
    auto ctx = makeContext(std::make_shared<UniformCurrent>(0.1, 0.0), 0.5, box(-1, 10, -1, 10));
    std::vector<TimedPoint> wp = {{0, 0, 0}, {1, 0.2, 0}, {2, 0, 0}, {3, 0.2, 0}, {4, 0, 0}};
    wp = retimeWaypoints(*ctx, wp, 0.0);
    ompl::geometric::PathGeometric path(si);
    waypointsToPath(wp, path);
    ASSERT_EQ(path.getStateCount(), 5u);
    const SmoothingResult r = PathSmoother(ctx).smooth(path);
    ASSERT_EQ(path.getStateCount(), r.waypointsAfter);
    EXPECT_EQ(r.waypointsAfter, 2u);
    const auto *last = path.getState(path.getStateCount() - 1)->as<TimeSE2StateSpace::StateType>();
    EXPECT_DOUBLE_EQ(last->getX(), 4.0);
    EXPECT_DOUBLE_EQ(last->getTime(), r.arrivalAfter);
    EXPECT_NEAR(r.arrivalAfter, 4.0 / 0.6, 1e-9);
    EXPECT_NEAR(last->getYaw(), 0.0, 1e-12);
}

TEST(PathSmoother, WaitingPathMergedKeepingItsSchedule)
{
    // A path that waits (slow first leg) because flying at full speed would meet the adverse current: its
    // waypoints cannot be flown at full speed from t0, so smoothing merges legs keeping the schedule.
    auto ctx = makeContext(std::make_shared<AdverseUntilFive>(), 0.5, box(-1, 5, -1, 1));
    const std::vector<TimedPoint> timed = {{0, 0, 0}, {1, 0, 6}, {2, 0, 8}, {3, 0, 10}};
    EXPECT_FALSE(std::isfinite(arrivalTime(*ctx, timed, 0.0)));
    const std::vector<TimedPoint> merged = mergeKeepingSchedule(*ctx, timed);
    ASSERT_EQ(merged.size(), 3u); // (0,0,0) -> (1,0,6) -> (3,0,10): the last two legs flown in exactly 4
    EXPECT_EQ(merged[1].x, 1.0);
    EXPECT_EQ(merged[1].t, 6.0);
    EXPECT_EQ(merged[2].t, 10.0);

    ompl::base::RealVectorBounds b(2);
    b.setLow(0, -1);
    b.setHigh(0, 5);
    b.setLow(1, -1);
    b.setHigh(1, 1);
    auto space = std::make_shared<TimeSE2StateSpace>(b, 0.0, 100.0);
    auto si = std::make_shared<ompl::base::SpaceInformation>(space);
    si->setStateValidityChecker([](const ompl::base::State *) { return true; });
    si->setMotionValidator(std::make_shared<TravelTimeMotionValidator>(si, ctx));
    si->setup();
    ompl::geometric::PathGeometric path(si);
    waypointsToPath(timed, path);
    ASSERT_TRUE(path.check()); // the input is a valid (waiting) plan on the time-augmented space
    const SmoothingResult r = PathSmoother(ctx).smooth(path);
    EXPECT_EQ(r.waypointsBefore, 4u);
    EXPECT_EQ(r.waypointsAfter, 3u);
    EXPECT_EQ(r.arrivalAfter, 10.0);
    ASSERT_EQ(path.getStateCount(), 3u);
    EXPECT_EQ(path.getState(1)->as<TimeSE2StateSpace::StateType>()->getTime(), 6.0);
    EXPECT_TRUE(path.check()); // every merged leg is valid for the motion validator
}

TEST(PathSmoother, DepartsAtTheFirstWaypointsTime)
{
    // The departure is the first waypoint's time; the other input times are ignored. Empty input: empty result.
    auto ctx = makeContext(std::make_shared<UniformCurrent>(0.2, 0.0), 0.5, box(0, 10, -1, 1));
    const std::vector<TimedPoint> wp{{1.0, 0.0, 3.0}, {4.0, 0.5, 99.0}, {9.0, 0.0, -1.0}};
    const SmoothingResult r = PathSmoother(ctx).smooth(wp);
    ASSERT_EQ(r.waypoints.size(), 2u);
    EXPECT_EQ(r.waypoints.front().t, 3.0);
    EXPECT_EQ(r.arrivalBefore, arrivalTime(*ctx, wp, 3.0));
    EXPECT_NEAR(r.arrivalAfter, 3.0 + 8.0 / 0.7, 1e-9);
    const SmoothingResult e = PathSmoother(ctx).smooth(std::vector<TimedPoint>{});
    EXPECT_TRUE(e.waypoints.empty());
    EXPECT_EQ(e.waypointsBefore, 0u);
}

TEST(PathSmoother, CollinearTieMergedDespiteRounding)
{
    // A straight path through collinear waypoints in a uniform current: the direct leg arrives at exactly the same
    // time as the legs it replaces, up to rounding (here the sum of legs is 1 ulp earlier). The tie must merge, so
    // only start and goal remain, and the arrival is the closed form to rounding.
    auto ctx = makeContext(std::make_shared<UniformCurrent>(0.2, 0.0), 0.5, box(0, 10, -1, 1));
    const std::vector<TimedPoint> wp{{1.0, 0.0, 0.0}, {4.0, 0.0, 0.0}, {4.5, 0.0, 0.0}, {9.0, 0.0, 0.0}};
    const SmoothingResult r = PathSmoother(ctx).smooth(wp);
    EXPECT_EQ(r.waypointsBefore, 4u);
    EXPECT_EQ(r.waypointsAfter, 2u);
    ASSERT_EQ(r.waypoints.size(), 2u);
    EXPECT_EQ(r.waypoints.back().x, 9.0);
    EXPECT_NEAR(r.arrivalAfter, 8.0 / 0.7, 1e-9);
    // "Never later" up to the documented relative tolerance of 1e-12.
    EXPECT_LE(r.arrivalAfter, r.arrivalBefore * (1.0 + 1e-12));
}

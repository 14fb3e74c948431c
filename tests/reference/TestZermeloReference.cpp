// Optimal-control reference (Zermelo shooting): Betts' shear-flow benchmark, closed forms in a uniform current,
// the extremal really ends at the goal, and it is never slower than any straight leg in the meandering jet.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ompl_glider/Exception.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/reference/ZermeloReference.h"

using namespace ompl_glider;

TEST(ZermeloReference, BettsShearFlow)
{
    // u = a y with a = -1, V = 1, (3.5, -1.8) -> (0, 0): optimal time 5.26493205 ([BettsOC] Ex. 10.148).
    ZermeloParams p;
    p.speed = 1.0;
    ZermeloReference ref(std::make_shared<LinearShear>(-1.0), p);
    const ZermeloSolution s = ref.solve(3.5, -1.8, 0.0, 0.0, 0.0);
    ASSERT_TRUE(s.found);
    EXPECT_NEAR(s.travelTime, 5.26493205, 5.26493205 * 1e-5);
    EXPECT_LE(s.missDistance, 1e-9);
    // Steady field: the departure time does not matter.
    const ZermeloSolution s2 = ref.solve(3.5, -1.8, 0.0, 0.0, 7.0);
    ASSERT_TRUE(s2.found);
    EXPECT_NEAR(s2.travelTime, s.travelTime, 1e-8);
}

TEST(ZermeloReference, UniformCurrentClosedForm)
{
    struct Case
    {
        double cu, cv, V, x1, y1, x2, y2;
    };
    // Weak current, cross current, and a current faster than the vehicle (goal downstream, reachable).
    const Case cases[] = {{0.3, 0.1, 1.0, 0, 0, 4, 3}, {0.0, 0.4, 0.5, 1, 1, -3, 2}, {0.8, 0.0, 0.5, 0, 0, 5, 1}};
    for (const Case &c : cases)
    {
        ZermeloParams p;
        p.speed = c.V;
        ZermeloReference ref(std::make_shared<UniformCurrent>(c.cu, c.cv), p);
        const double L = std::hypot(c.x2 - c.x1, c.y2 - c.y1);
        const double px = (c.x2 - c.x1) / L, py = (c.y2 - c.y1) / L;
        const double pc = px * c.cu + py * c.cv;
        const double vef = pc + std::sqrt(pc * pc + c.V * c.V - c.cu * c.cu - c.cv * c.cv);
        const double expected = L / vef;
        const ZermeloSolution s = ref.solve(c.x1, c.y1, c.x2, c.y2, 0.0);
        ASSERT_TRUE(s.found) << "case goal (" << c.x2 << ", " << c.y2 << ")";
        EXPECT_NEAR(s.travelTime, expected, expected * 1e-8);
        // The heading is constant in a uniform field: V (cos, sin) + c = v_ef p.
        EXPECT_NEAR(c.V * std::cos(s.initialHeading) + c.cu, vef * px, 1e-7);
        EXPECT_NEAR(c.V * std::sin(s.initialHeading) + c.cv, vef * py, 1e-7);
    }
}

TEST(ZermeloReference, ExtremalEndsAtGoalInJet)
{
    auto jet = std::make_shared<MeanderingJet>();
    ZermeloReference ref(jet);
    const ZermeloSolution s = ref.solve(2.0, -3.0, 7.0, 3.0, 0.0);
    ASSERT_TRUE(s.found);
    const auto traj = ref.trajectory(2.0, -3.0, s.initialHeading, 0.0, s.travelTime);
    ASSERT_GE(traj.size(), 2u);
    EXPECT_NEAR(traj.back().t, s.travelTime, 1e-12);
    EXPECT_NEAR(traj.back().x, 7.0, 1e-6);
    EXPECT_NEAR(traj.back().y, 3.0, 1e-6);
}

TEST(ZermeloReference, NeverSlowerThanStraightLegInJet)
{
    // The optimal time is a lower bound of any path's time, in particular the straight leg's (computed by the
    // independent travel-time code with a tight tolerance), at several departure times.
    auto jet = std::make_shared<MeanderingJet>();
    TravelTimeParams tp;
    tp.eps = 1e-7;
    tp.hMin = 1e-5;
    TravelTimeCalculator calc(jet, tp);
    ZermeloReference ref(jet);
    const double legs[][5] = {{1, -2, 8, 2, 0}, {1, 2.5, 9, -2, 3}, {5, -3, 4, 3, 10}};
    for (const auto &l : legs)
    {
        const ZermeloSolution s = ref.solve(l[0], l[1], l[2], l[3], l[4]);
        ASSERT_TRUE(s.found);
        const double straight = calc.travelTime(l[0], l[1], l[2], l[3], l[4]);
        if (std::isfinite(straight))
        {
            EXPECT_LE(s.travelTime, straight * (1 + 1e-6));
        }
        EXPECT_GT(s.travelTime, std::hypot(l[2] - l[0], l[3] - l[1]) / (0.5 + jet->maxSpeed({})));
    }
}

TEST(ZermeloReference, RejectsBadInput)
{
    EXPECT_THROW(ZermeloReference(nullptr), Error);
    ZermeloParams p;
    p.speed = 0.0;
    EXPECT_THROW(ZermeloReference(std::make_shared<UniformCurrent>(0, 0), p), Error);
    ZermeloReference ref(std::make_shared<UniformCurrent>(0, 0));
    EXPECT_THROW(ref.solve(0, 0, NAN, 1, 0), Error);
    const ZermeloSolution same = ref.solve(1, 1, 1, 1, 0);
    EXPECT_TRUE(same.found);
    EXPECT_EQ(same.travelTime, 0.0);
}

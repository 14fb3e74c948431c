#include <cmath>
#include <limits>
#include <memory>

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/ompl/GliderStateValidityChecker.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"
#include "ompl_glider/ompl/TravelTimeMotionValidator.h"

namespace ob = ompl::base;
using namespace ompl_glider;

namespace
{
/// Forbidden: the vertical wall x in [4.9, 5.1], y in [-1, 1] while t < 10.
class TimedWall : public Environment
{
public:
    bool pointFree(double x, double y, double t) const override
    {
        return !(x >= 4.9 && x <= 5.1 && y >= -1 && y <= 1 && t < 10);
    }
    bool legFree(double x1, double y1, double t1, double x2, double y2, double t2) const override
    {
        for (int i = 0; i <= 1000; ++i)
        {
            const double f = i / 1000.0;
            if (!pointFree(x1 + f * (x2 - x1), y1 + f * (y2 - y1), t1 + f * (t2 - t1)))
                return false;
        }
        return true;
    }
    std::string whyBlocked(double x, double y, double t) const override
    {
        return pointFree(x, y, t) ? "" : "inside the timed wall";
    }
};

struct Fixture
{
    std::shared_ptr<GliderContext> ctx;
    std::shared_ptr<TimeSE2StateSpace> space;
    ob::SpaceInformationPtr si;
    std::shared_ptr<TravelTimeMotionValidator> mv;

    Fixture(double cu, double cv, std::shared_ptr<const Environment> env = nullptr)
    {
        ctx = std::make_shared<GliderContext>();
        ctx->field = std::make_shared<UniformCurrent>(cu, cv);
        TravelTimeParams p;
        p.speed = 0.5;
        ctx->travel = std::make_shared<TravelTimeCalculator>(ctx->field, p);
        ctx->environment = std::move(env);
        ctx->region.xMin = 0;
        ctx->region.xMax = 10;
        ctx->region.yMin = -4;
        ctx->region.yMax = 4;
        ctx->region.tMin = 0;
        ctx->region.tMax = 60;
        ob::RealVectorBounds b(2);
        b.setLow(0, 0);
        b.setHigh(0, 10);
        b.setLow(1, -4);
        b.setHigh(1, 4);
        space = std::make_shared<TimeSE2StateSpace>(b, 0.0, 60.0);
        si = std::make_shared<ob::SpaceInformation>(space);
        si->setStateValidityChecker(std::make_shared<GliderStateValidityChecker>(si, ctx));
        mv = std::make_shared<TravelTimeMotionValidator>(si, ctx);
        si->setMotionValidator(mv);
        si->setup();
    }

    bool check(double x1, double y1, double t1, double x2, double y2, double t2) const
    {
        ob::ScopedState<TimeSE2StateSpace> a(space), b(space);
        a->setXYT(x1, y1, t1);
        a->setYaw(0);
        b->setXYT(x2, y2, t2);
        b->setYaw(0);
        return si->checkMotion(a.get(), b.get());
    }
    MotionVerdict verdict(double x1, double y1, double t1, double x2, double y2, double t2) const
    {
        return mv->classify(x1, y1, t1, x2, y2, t2);
    }
};

/// Closed forms of the along-track speeds in a uniform current.
void roots(double px, double py, double cu, double cv, double V, double &fast, double &slow)
{
    const double pc = px * cu + py * cv;
    const double disc = pc * pc + V * V - (cu * cu + cv * cv);
    fast = pc + std::sqrt(disc);
    slow = pc - std::sqrt(disc);
}
} // namespace

TEST(TravelTimeMotionValidator, WindowInCurrentFasterThanGlider)
{
    // c = (1, 0), V = 0.5: along +x the roots are 1.5 and 0.5, so a leg of length 3 takes between 2 and 6.
    Fixture f(1.0, 0.0);
    double vf, vs;
    roots(1, 0, 1, 0, 0.5, vf, vs);
    ASSERT_DOUBLE_EQ(vf, 1.5);
    ASSERT_DOUBLE_EQ(vs, 0.5);
    const double L = 3.0, earliest = L / vf, latest = L / vs;
    EXPECT_TRUE(f.check(1, 0, 5, 4, 0, 5 + earliest));
    EXPECT_TRUE(f.check(1, 0, 5, 4, 0, 5 + latest));
    EXPECT_TRUE(f.check(1, 0, 5, 4, 0, 5 + 0.5 * (earliest + latest)));
    EXPECT_FALSE(f.check(1, 0, 5, 4, 0, 5 + earliest * (1 - 1e-4)));
    EXPECT_FALSE(f.check(1, 0, 5, 4, 0, 5 + latest * (1 + 1e-4)));
    EXPECT_EQ(f.verdict(1, 0, 5, 4, 0, 5 + earliest * 0.9), MotionVerdict::TooEarly);
    EXPECT_EQ(f.verdict(1, 0, 5, 4, 0, 5 + latest * 1.1), MotionVerdict::TooLate);
    // A 20-degree leg (inside the +-30 degree feasible cone) against the closed form.
    const double a = 20.0 * M_PI / 180.0;
    roots(std::cos(a), std::sin(a), 1, 0, 0.5, vf, vs);
    ASSERT_GT(vs, 0.0);
    const double l2 = 2.0;
    const double x2 = 1 + l2 * std::cos(a), y2 = l2 * std::sin(a);
    EXPECT_TRUE(f.check(1, 0, 0, x2, y2, l2 / vf));
    EXPECT_TRUE(f.check(1, 0, 0, x2, y2, l2 / vs));
    EXPECT_EQ(f.verdict(1, 0, 0, x2, y2, l2 / vf * 0.999), MotionVerdict::TooEarly);
    EXPECT_EQ(f.verdict(1, 0, 0, x2, y2, l2 / vs * 1.001), MotionVerdict::TooLate);
}

TEST(TravelTimeMotionValidator, InfeasibleHeadings)
{
    Fixture f(1.0, 0.0);
    // upstream, across and 45 degrees: disc <= 0 or fast root <= 0
    EXPECT_EQ(f.verdict(5, 0, 0, 3, 0, 10), MotionVerdict::Infeasible);
    EXPECT_EQ(f.verdict(5, 0, 0, 5, 2, 10), MotionVerdict::Infeasible);
    EXPECT_EQ(f.verdict(5, 0, 0, 7, 2, 10), MotionVerdict::Infeasible);
    EXPECT_FALSE(f.check(5, 0, 0, 3, 0, 30));
}

TEST(TravelTimeMotionValidator, HoldingMakesLatestUnbounded)
{
    // |c| = 0.3 < V = 0.5: the slow root is negative on every heading, so any time after the earliest is valid.
    Fixture f(0.3, 0.0);
    double vf, vs;
    roots(0, 1, 0.3, 0, 0.5, vf, vs);
    ASSERT_NEAR(vf, 0.4, 1e-12);
    ASSERT_LT(vs, 0.0);
    EXPECT_TRUE(f.check(2, -2, 1, 2, 2, 1 + 4 / 0.4));
    EXPECT_TRUE(f.check(2, -2, 1, 2, 2, 59.0));
    EXPECT_FALSE(f.check(2, -2, 1, 2, 2, 1 + 4 / 0.4 * 0.99));
    // upstream with the current: fast root 0.2
    EXPECT_TRUE(f.check(8, 0, 0, 6, 0, 10.0));
    EXPECT_FALSE(f.check(8, 0, 0, 6, 0, 9.9));
    // Holding in place: allowed here, not in c = (1, 0).
    EXPECT_TRUE(f.check(3, 3, 2, 3, 3, 40));
    Fixture strong(1.0, 0.0);
    EXPECT_EQ(strong.verdict(3, 3, 2, 3, 3, 40), MotionVerdict::CannotHold);
    EXPECT_FALSE(strong.check(3, 3, 2, 3, 3, 40));
    // The state itself (zero length, zero duration) is a valid motion in both.
    EXPECT_TRUE(strong.check(3, 3, 2, 3, 3, 2));
}

TEST(TravelTimeMotionValidator, TimeMustGoForward)
{
    Fixture f(0.3, 0.0);
    EXPECT_EQ(f.verdict(1, 0, 5, 2, 0, 5), MotionVerdict::NotForward);
    EXPECT_EQ(f.verdict(1, 0, 5, 2, 0, 4), MotionVerdict::NotForward);
    EXPECT_EQ(f.verdict(1, 0, 5, 1, 0, 4), MotionVerdict::NotForward);
    EXPECT_FALSE(f.check(1, 0, 5, 2, 0, 5));
    EXPECT_FALSE(f.check(2, 0, 10, 1, 0, 3));
    // The reverse of a valid motion is invalid.
    EXPECT_TRUE(f.check(1, 0, 3, 2, 0, 10));
    EXPECT_FALSE(f.check(2, 0, 10, 1, 0, 3));
}

TEST(TravelTimeMotionValidator, EndStateAndEnvironment)
{
    auto wall = std::make_shared<TimedWall>();
    Fixture f(0.0, 0.0, wall);
    // Crossing the wall at x = 5 before t = 10 is blocked, after t = 10 free.
    EXPECT_EQ(f.verdict(3, 0, 0, 7, 0, 9), MotionVerdict::Blocked);
    EXPECT_FALSE(f.check(3, 0, 0, 7, 0, 9));
    EXPECT_TRUE(f.check(3, 0, 10, 7, 0, 19));
    // passing the wall line late enough: at constant pace it is at x = 5 at t = 12
    EXPECT_TRUE(f.check(3, 0, 2, 7, 0, 22));
    // End state out of the time window or inside the wall.
    EXPECT_FALSE(f.check(3, 0, 50, 7, 0, 61));
    ob::ScopedState<TimeSE2StateSpace> a(f.space), b(f.space);
    a->setXYT(3, 0, 0);
    b->setXYT(5, 0, 5);
    a->setYaw(0);
    b->setYaw(0);
    EXPECT_EQ(f.mv->classify(a.get(), b.get()), MotionVerdict::InvalidEndState);
    auto vc = std::static_pointer_cast<GliderStateValidityChecker>(f.si->getStateValidityChecker());
    EXPECT_NE(vc->whyInvalid(b.get()).find("timed wall"), std::string::npos);
    b->setTime(15);
    EXPECT_TRUE(vc->whyInvalid(b.get()).empty());
}

TEST(TravelTimeMotionValidator, LastValidFraction)
{
    auto wall = std::make_shared<TimedWall>();
    Fixture f(0.0, 0.0, wall);
    ob::ScopedState<TimeSE2StateSpace> a(f.space), b(f.space), last(f.space);
    a->setXYT(3, 0, 0);
    b->setXYT(7, 0, 9); // reaches the wall face x = 4.9 at fraction 0.475
    a->setYaw(0);
    b->setYaw(0);
    std::pair<ob::State *, double> lv(last.get(), -1.0);
    EXPECT_FALSE(f.mv->checkMotion(a.get(), b.get(), lv));
    EXPECT_NEAR(lv.second, 0.475, 1e-3);
    EXPECT_LE(lv.second, 0.475);
    EXPECT_NEAR(last->getX(), 3 + 4 * lv.second, 1e-12);
    EXPECT_TRUE(f.mv->checkMotion(a.get(), last.get()));
    // A valid motion leaves lastValid untouched.
    b->setTime(30);
    lv.second = -1.0;
    EXPECT_TRUE(f.mv->checkMotion(a.get(), b.get(), lv));
    EXPECT_EQ(lv.second, -1.0);
    // Too early everywhere (same ratio on every sub-leg in a uniform field): last valid fraction 0.
    b->setTime(1.0);
    EXPECT_FALSE(f.mv->checkMotion(a.get(), b.get(), lv));
    EXPECT_EQ(lv.second, 0.0);
    EXPECT_TRUE(f.space->equalStates(last.get(), a.get()));
}

TEST(TravelTimeMotionValidator, RejectsNullContext)
{
    Fixture f(0.0, 0.0);
    EXPECT_THROW(TravelTimeMotionValidator(f.si, nullptr), Error);
    EXPECT_THROW(GliderStateValidityChecker(f.si, nullptr), Error);
    EXPECT_THROW(f.mv->setRelativeTolerance(-1), Error);
    EXPECT_THROW(f.mv->setHoldTimeStep(0), Error);
}

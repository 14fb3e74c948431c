// Tests of the glider dive-profile travel time ([EichhornOceans] Table I) and the optimal dive profile
// ([EichhornOceans] Sec. III.B).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "ompl_glider/Exception.h"
#include "ompl_glider/cost/DiveProfile.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"

using namespace ompl_glider;

namespace
{
/// Steady eastward current linear in depth: u = a + b z, v = 0 (depth positive down).
class DepthShear : public CurrentField
{
public:
    DepthShear(double a, double b) : a_(a), b_(b) {}
    double maxSpeed(const Region &r) const override
    {
        return std::max(std::abs(a_ + b_ * r.zMin), std::abs(a_ + b_ * r.zMax));
    }
    std::string name() const override { return "depth shear"; }

protected:
    Velocity evaluate(double, double, double z, double) const override { return {a_ + b_ * z, 0.0}; }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }

private:
    double a_, b_;
};

/// Closed form of an eastward leg of length L through u = a + b z with the depth going linearly from zc to zd in
/// every segment: dt/ds = 1 / (V + u(s)); the time does not depend on the number of segments.
double closedForm(double L, double V, double a, double b, double zc, double zd)
{
    const double u0 = a + b * zc, u1 = a + b * zd;
    if (std::abs(u1 - u0) < 1e-15)
        return L / (V + u0);
    return L / (u1 - u0) * std::log((V + u1) / (V + u0));
}

DiveProfileParams sevenProfiles()
{
    DiveProfileParams p;
    p.zMin = 0;
    p.zMax = 100;
    p.climbToMax = 20;
    p.minRange = 50;
    p.climbToLevels = 3; // 0, 10, 20
    p.diveToLevels = 3;  // 50, 75, 100
    return p;
}

TravelTimeParams fine(double V)
{
    TravelTimeParams t;
    t.speed = V;
    t.eps = 1e-11;
    t.hMin = 1e-4;
    return t;
}
} // namespace

TEST(DiveProfile, GeneratedSetFollowsLevelsAndMinimumRange)
{
    const auto profiles = makeDiveProfiles(sevenProfiles());
    const double expected[][2] = {{0, 50}, {0, 75}, {0, 100}, {10, 75}, {10, 100}, {20, 75}, {20, 100}};
    ASSERT_EQ(profiles.size(), 7u);
    for (int i = 0; i < 7; ++i)
    {
        EXPECT_DOUBLE_EQ(profiles[i].climbTo, expected[i][0]);
        EXPECT_DOUBLE_EQ(profiles[i].diveTo, expected[i][1]);
        EXPECT_GE(profiles[i].amplitude(), 50.0);
    }
    DiveProfileParams one;
    one.zMin = 5;
    one.zMax = 200;
    one.climbToMax = 5;
    const auto single = makeDiveProfiles(one);
    ASSERT_EQ(single.size(), 1u);
    EXPECT_DOUBLE_EQ(single[0].climbTo, 5.0);
    EXPECT_DOUBLE_EQ(single[0].diveTo, 200.0);
}

TEST(DiveProfile, BadParametersNameTheParameter)
{
    auto expectError = [](DiveProfileParams p, const std::string &word) {
        try
        {
            makeDiveProfiles(p);
            FAIL() << "no error for " << word;
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
        }
    };
    DiveProfileParams p = sevenProfiles();
    p.zMax = -1;
    expectError(p, "z_max");
    p = sevenProfiles();
    p.climbToMax = -3;
    expectError(p, "climb_to_max");
    p = sevenProfiles();
    p.minRange = 200;
    expectError(p, "min_range");
    p = sevenProfiles();
    p.diveToLevels = 0;
    expectError(p, "levels");
    p = sevenProfiles();
    p.step = 0;
    expectError(p, "step");
}

TEST(DiveProfile, DepthUniformCurrentGivesThe2DTravelTime)
{
    auto jet = std::make_shared<MeanderingJet>();
    TravelTimeParams tp; // the jet's defaults
    TravelTimeCalculator calc(jet, tp);
    const double legs[][5] = {{0, -2, 2, 0, 0},      {2, 0, 5, 1, 1.3},   {5, 1, 8, -1, 3}, {1, 1, 3, 2, 7.5},
                              {0, -2, 0.5, -1.5, 0}, {3, 0.5, 1, 0.3, 2}, {0, 2, 1, 2.5, 4}};
    int finite = 0;
    for (const auto &l : legs)
    {
        if (!std::isfinite(calc.travelTime(l[0], l[1], l[2], l[3], l[4])))
        {
            // An impassable 2-D leg is impassable with every dive profile too.
            DiveProfileTravelTime d1(jet, tp, sevenProfiles(), nullptr, 1);
            EXPECT_TRUE(std::isinf(d1.bestProfile(l[0], l[1], l[2], l[3], l[4]).travelTime));
            continue;
        }
        ++finite;
        // One segment (h = 1): the 2-D travel time of the leg, bit for bit.
        DiveProfileParams d = sevenProfiles();
        d.step = 1.0;
        DiveProfileTravelTime one(jet, tp, d, nullptr, 1);
        const double t2d = calc.travelTime(l[0], l[1], l[2], l[3], l[4]);
        ASSERT_TRUE(std::isfinite(t2d));
        for (const auto &p : one.profiles())
            EXPECT_EQ(one.travelTime(p, l[0], l[1], l[2], l[3], l[4]), t2d);
        EXPECT_EQ(one.bestProfile(l[0], l[1], l[2], l[3], l[4]).travelTime, t2d);

        // Four segments: the 2-D times of the four segments flown one after the other, bit for bit, and the whole
        // leg's 2-D time within the integration tolerance.
        d.step = 0.25;
        DiveProfileTravelTime four(jet, tp, d, nullptr, 1);
        double sum = 0.0;
        for (int i = 0; i < 4; ++i)
        {
            const double a = i / 4.0, b = (i + 1) / 4.0;
            const double xs = l[0] + a * (l[2] - l[0]), ys = l[1] + a * (l[3] - l[1]);
            const double xe = i == 3 ? l[2] : l[0] + b * (l[2] - l[0]), ye = i == 3 ? l[3] : l[1] + b * (l[3] - l[1]);
            sum += calc.travelTime(xs, ys, xe, ye, l[4] + sum);
        }
        for (const auto &p : four.profiles())
            EXPECT_EQ(four.travelTime(p, l[0], l[1], l[2], l[3], l[4]), sum);
        EXPECT_NEAR(sum, t2d, 0.01 * t2d);
    }
    EXPECT_GE(finite, 3);
}

TEST(DiveProfile, UniformCurrentClosedForm)
{
    auto f = std::make_shared<UniformCurrent>(0.1, 0.0);
    DiveProfileTravelTime dive(f, fine(0.3), sevenProfiles(), nullptr, 1);
    // Eastward 3 units at 0.3 + 0.1; northward 2 units at sqrt(0.3^2 - 0.1^2).
    for (const auto &p : dive.profiles())
    {
        EXPECT_NEAR(dive.travelTime(p, 0, 0, 3, 0, 5), 3.0 / 0.4, 1e-12);
        EXPECT_NEAR(dive.travelTime(p, 0, 0, 0, 2, 5), 2.0 / std::sqrt(0.08), 1e-12);
    }
}

TEST(DiveProfile, DepthVaryingCurrentMatchesClosedFormAndFastestIsChosen)
{
    // Current grows with depth in the direction of travel: the deepest mean depth is fastest.
    const double a = 0.02, b = 0.002, V = 0.3, L = 4.0;
    auto f = std::make_shared<DepthShear>(a, b);
    DiveProfileParams d = sevenProfiles();
    d.step = 0.2;
    DiveProfileTravelTime dive(f, fine(V), d, nullptr, 1);
    const auto &ps = dive.profiles();
    int expectedBest = -1;
    double bestClosed = 1e300;
    for (std::size_t i = 0; i < ps.size(); ++i)
    {
        const double exact = closedForm(L, V, a, b, ps[i].climbTo, ps[i].diveTo);
        EXPECT_NEAR(dive.travelTime(ps[i], 0, 0, L, 0, 0), exact, 1e-6 * exact);
        if (exact < bestClosed)
        {
            bestClosed = exact;
            expectedBest = static_cast<int>(i);
        }
    }
    const DiveLegResult r = dive.bestProfile(0, 0, L, 0, 0);
    EXPECT_EQ(r.profile, expectedBest);
    EXPECT_DOUBLE_EQ(ps[r.profile].climbTo, 20.0);
    EXPECT_DOUBLE_EQ(ps[r.profile].diveTo, 100.0);
    EXPECT_NEAR(r.travelTime, bestClosed, 1e-6 * bestClosed);

    // Against the current (westward leg), the shallowest profile wins.
    const DiveLegResult w = dive.bestProfile(L, 0, 0, 0, 0);
    EXPECT_DOUBLE_EQ(ps[w.profile].climbTo, 0.0);
    EXPECT_DOUBLE_EQ(ps[w.profile].diveTo, 50.0);
}

TEST(DiveProfile, DeepestUnderLimitTakesLargestAmplitudeWithinTheLimit)
{
    // Against the current, deeper is slower; data at all depths asks for the largest amplitude within the limit.
    const double a = 0.02, b = 0.002, V = 0.3, L = 4.0;
    auto f = std::make_shared<DepthShear>(a, b);
    DiveProfileParams d = sevenProfiles();
    d.selection = DiveProfileSelection::DeepestUnderLimit;
    d.maxTimeFactor = 10.0; // generous: (0, 100) qualifies
    DiveProfileTravelTime generous(f, fine(V), d, nullptr, 1);
    const DiveLegResult g = generous.bestProfile(L, 0, 0, 0, 0);
    EXPECT_DOUBLE_EQ(generous.profiles()[g.profile].climbTo, 0.0);
    EXPECT_DOUBLE_EQ(generous.profiles()[g.profile].diveTo, 100.0);

    // Times grow with the mean depth here: (0,50) 25 < (0,75) 37.5 < (10,75) 42.5 < (20,75) 47.5 < (0,100) 50
    // < (10,100) 55 < (20,100) 60. A limit between the times of (0,75) and (10,75) leaves (0,50) and (0,75):
    // the largest amplitude among them is (0,75).
    const double fastest = closedForm(L, V, -a, -b, 0, 50);
    const double t075 = closedForm(L, V, -a, -b, 0, 75), t1075 = closedForm(L, V, -a, -b, 10, 75);
    ASSERT_LT(t075, t1075);
    d.maxTimeFactor = 1.0;
    d.maxTime = 0.5 * (t075 + t1075);
    DiveProfileTravelTime limited(f, fine(V), d, nullptr, 1);
    const DiveLegResult l = limited.bestProfile(L, 0, 0, 0, 0);
    // maxTimeFactor 1 means "no slower than the fastest": only the fastest qualifies.
    EXPECT_DOUBLE_EQ(limited.profiles()[l.profile].diveTo, 50.0);
    EXPECT_NEAR(l.travelTime, fastest, 1e-6 * fastest);
    d.maxTimeFactor = 100.0;
    DiveProfileTravelTime absolute(f, fine(V), d, nullptr, 1);
    const DiveLegResult ab = absolute.bestProfile(L, 0, 0, 0, 0);
    EXPECT_DOUBLE_EQ(absolute.profiles()[ab.profile].climbTo, 0.0);
    EXPECT_DOUBLE_EQ(absolute.profiles()[ab.profile].diveTo, 75.0);
    EXPECT_NEAR(ab.travelTime, t075, 1e-6 * t075);
    EXPECT_LE(ab.travelTime, d.maxTime);
}

TEST(DiveProfile, ParallelEqualsSerialAndCountsOneCallPerProfile)
{
    auto jet = std::make_shared<MeanderingJet>();
    DiveProfileParams d = sevenProfiles();
    DiveProfileTravelTime par(jet, TravelTimeParams{}, d, nullptr, 4);
    EXPECT_EQ(par.threads(), 4u);
    for (double t0 : {0.0, 2.0, 4.5})
    {
        const DiveLegResult a = par.bestProfile(0, -2, 2, 0, t0);
        const DiveLegResult b = par.bestProfileSerial(0, -2, 2, 0, t0);
        ASSERT_EQ(a.profileTimes.size(), b.profileTimes.size());
        for (std::size_t i = 0; i < a.profileTimes.size(); ++i)
            EXPECT_EQ(a.profileTimes[i], b.profileTimes[i]);
        EXPECT_EQ(a.profile, b.profile);
    }
    EXPECT_EQ(par.costFunctionCalls(), 3u * 2u * 7u);
}

TEST(DiveProfile, BathymetryLimitsTheDive)
{
    const double a = 0.02, b = 0.002, V = 0.3, L = 4.0;
    auto f = std::make_shared<DepthShear>(a, b);
    auto floor40 = std::make_shared<FunctionBathymetry>([](double, double) { return 45.0; });
    DiveProfileParams d = sevenProfiles();
    d.clearance = 5.0; // dives limited to 40
    DiveProfileTravelTime dive(f, fine(V), d, floor40, 1);
    for (const auto &p : dive.profiles())
    {
        const double exact = closedForm(L, V, a, b, std::min(p.climbTo, 40.0), 40.0);
        EXPECT_NEAR(dive.travelTime(p, 0, 0, L, 0, 0), exact, 1e-6 * exact);
    }
    // A shoal on the way (seafloor above the clearance): impassable for every profile.
    auto shoal =
        std::make_shared<FunctionBathymetry>([](double x, double) { return x > 1.9 && x < 2.1 ? 3.0 : 500.0; });
    DiveProfileTravelTime blocked(f, fine(V), d, shoal, 1);
    const DiveLegResult r = blocked.bestProfile(0, 0, L, 0, 0);
    EXPECT_EQ(r.profile, -1);
    EXPECT_TRUE(std::isinf(r.travelTime));
}

TEST(ThreadPool, EveryIndexOnceNestedAndExceptions)
{
    ThreadPool pool(3);
    EXPECT_EQ(pool.size(), 3u);
    for (int round = 0; round < 20; ++round)
    {
        std::vector<std::atomic<int>> hits(257);
        pool.parallelFor(hits.size(), [&](std::size_t i) { hits[i]++; });
        for (auto &h : hits)
            ASSERT_EQ(h.load(), 1);
    }
    std::atomic<int> inner{0};
    pool.parallelFor(8, [&](std::size_t) { pool.parallelFor(5, [&](std::size_t) { inner++; }); });
    EXPECT_EQ(inner.load(), 40);
    EXPECT_THROW(pool.parallelFor(10,
                                  [](std::size_t i) {
                                      if (i == 7)
                                          throw std::runtime_error("seven");
                                  }),
                 std::runtime_error);
    std::atomic<int> after{0};
    pool.parallelFor(10, [&](std::size_t) { after++; });
    EXPECT_EQ(after.load(), 10);
}

// Conformance suite every CurrentField must pass: velocity = curl of the stream function, divergence-free where
// it should be, Jacobian against finite differences, the speed bound holds on a dense sample, CMC counting.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include "ompl_glider/current/DoubleGyre.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/RankineVortex.h"
#include "ompl_glider/current/UniformCurrent.h"

using namespace ompl_glider;

namespace
{
struct FieldCase
{
    std::string label;
    std::function<std::shared_ptr<CurrentField>()> make;
    Region region; // where the field is sampled
};

std::vector<FieldCase> fieldCases()
{
    Region jetRegion{0.0, 10.0, -4.0, 4.0, 0.0, 0.0, 0.0, 40.0};
    Region unit{-3.0, 3.0, -2.0, 2.0, 0.0, 0.0, 0.0, 10.0};
    Region gyre{0.0, 2.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
    return {
        {"MeanderingJet", [] { return std::make_shared<MeanderingJet>(); }, jetRegion},
        {"MeanderingJetOtherParams",
         [] {
             MeanderingJetParams p;
             p.B0 = 0.8;
             p.epsilon = 0.5;
             p.k = 1.3;
             p.c = 0.3;
             p.omega = 1.1;
             return std::make_shared<MeanderingJet>(p);
         },
         jetRegion},
        {"Uniform", [] { return std::make_shared<UniformCurrent>(0.3, -0.2); }, unit},
        {"LinearShear", [] { return std::make_shared<LinearShear>(-1.0); }, unit},
        {"DoubleGyre", [] { return std::make_shared<DoubleGyre>(0.1, 1.0); }, gyre},
        // time-dependent: the time window holds a full period 2 pi / omega = 10 (the bound is reached at t = 7.5)
        {"DoubleGyreTimeDependent", [] { return std::make_shared<DoubleGyre>(0.1, 1.0, 0.25, 2 * M_PI / 10); },
         Region{0.0, 2.0, 0.0, 1.0, 0.0, 0.0, 0.0, 10.0}},
        {"DoubleGyreTimeDependentScaled", [] { return std::make_shared<DoubleGyre>(-0.3, 2.0, 0.1, 1.0); },
         Region{0.0, 4.0, 0.0, 2.0, 0.0, 0.0, 0.0, 2 * M_PI}},
        {"RankineVortex", [] { return std::make_shared<RankineVortex>(); }, unit},
        {"RankineVortexInStream",
         [] {
             RankineVortexParams p;
             p.x0 = 0.5;
             p.y0 = -0.3;
             p.radius = 0.7;
             p.vmax = -1.5; // clockwise
             p.u = 0.4;
             p.v = 0.3;
             return std::make_shared<RankineVortex>(p);
         },
         unit},
        // a region away from the core: the bound is the speed at the region's nearest point, vmax R / dMin
        {"RankineVortexOutsideCore", [] { return std::make_shared<RankineVortex>(); },
         Region{2.0, 5.0, 1.0, 3.0, 0.0, 0.0, 0.0, 1.0}},
    };
}

// Deterministic pseudo-random sample of points in a region.
std::vector<std::array<double, 3>> samplePoints(const Region &r, int n)
{
    std::vector<std::array<double, 3>> pts;
    unsigned s = 12345u;
    auto rnd = [&s] {
        s = s * 1664525u + 1013904223u;
        return (s >> 8) / double(1u << 24);
    };
    for (int i = 0; i < n; ++i)
        pts.push_back({r.xMin + (r.xMax - r.xMin) * rnd(), r.yMin + (r.yMax - r.yMin) * rnd(),
                       r.tMin + (r.tMax - r.tMin) * rnd()});
    return pts;
}
} // namespace

class CurrentConformance : public ::testing::TestWithParam<FieldCase>
{
};

TEST_P(CurrentConformance, VelocityIsCurlOfStreamFunction)
{
    auto f = GetParam().make();
    const double h = 1e-5;
    int checked = 0;
    for (auto [x, y, t] : samplePoints(GetParam().region, 300))
    {
        auto psi = f->streamFunction(x, y, 0, t);
        if (!psi)
            GTEST_FAIL() << "analytic field without stream function";
        const double psiX = (*f->streamFunction(x + h, y, 0, t) - *f->streamFunction(x - h, y, 0, t)) / (2 * h);
        const double psiY = (*f->streamFunction(x, y + h, 0, t) - *f->streamFunction(x, y - h, 0, t)) / (2 * h);
        const Velocity c = f->velocity(x, y, 0, t);
        EXPECT_NEAR(c.u, -psiY, 1e-6) << "at " << x << "," << y << "," << t;
        EXPECT_NEAR(c.v, psiX, 1e-6) << "at " << x << "," << y << "," << t;
        ++checked;
    }
    EXPECT_EQ(checked, 300);
}

TEST_P(CurrentConformance, JacobianMatchesFiniteDifferences)
{
    auto f = GetParam().make();
    const double h = 1e-5;
    for (auto [x, y, t] : samplePoints(GetParam().region, 300))
    {
        const Jacobian J = f->jacobian(x, y, 0, t);
        const Velocity px = f->velocity(x + h, y, 0, t), mx = f->velocity(x - h, y, 0, t);
        const Velocity py = f->velocity(x, y + h, 0, t), my = f->velocity(x, y - h, 0, t);
        EXPECT_NEAR(J.ux, (px.u - mx.u) / (2 * h), 1e-6);
        EXPECT_NEAR(J.vx, (px.v - mx.v) / (2 * h), 1e-6);
        EXPECT_NEAR(J.uy, (py.u - my.u) / (2 * h), 1e-6);
        EXPECT_NEAR(J.vy, (py.v - my.v) / (2 * h), 1e-6);
    }
}

TEST_P(CurrentConformance, DivergenceFreeWhereDeclared)
{
    auto f = GetParam().make();
    ASSERT_TRUE(f->divergenceFree());
    for (auto [x, y, t] : samplePoints(GetParam().region, 300))
    {
        const Jacobian J = f->jacobian(x, y, 0, t);
        EXPECT_NEAR(J.ux + J.vy, 0.0, 1e-12);
    }
}

TEST_P(CurrentConformance, SpeedBoundHoldsOnDenseSample)
{
    auto f = GetParam().make();
    const Region &r = GetParam().region;
    const double bound = f->maxSpeed(r);
    ASSERT_TRUE(std::isfinite(bound));
    double maxSeen = 0.0;
    const int n = 60;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            for (int k = 0; k <= 20; ++k)
            {
                const double x = r.xMin + (r.xMax - r.xMin) * i / n;
                const double y = r.yMin + (r.yMax - r.yMin) * j / n;
                const double t = r.tMin + (r.tMax - r.tMin) * k / 20;
                const Velocity c = f->velocity(x, y, 0, t);
                maxSeen = std::max(maxSeen, std::hypot(c.u, c.v));
            }
    EXPECT_LE(maxSeen, bound);
    // The bound must be useful for the A* heuristic, not just any large number.
    EXPECT_GE(maxSeen, 0.9 * bound) << "bound " << bound << " is loose; max seen " << maxSeen;
}

TEST_P(CurrentConformance, CountsCallsExactlyAcrossThreads)
{
    auto f = GetParam().make();
    f->resetCallCount();
    const int perThread = 20000, threads = 4;
    std::vector<std::thread> pool;
    for (int i = 0; i < threads; ++i)
        pool.emplace_back([&f, i] {
            for (int k = 0; k < perThread; ++k)
            {
                if (k % 2)
                    f->velocity(0.1 * i, 0.2, 0, 0.01 * k);
                else
                    f->jacobian(0.1 * i, 0.2, 0, 0.01 * k);
            }
        });
    for (auto &th : pool)
        th.join();
    EXPECT_EQ(f->callCount(), std::uint64_t(perThread) * threads);
    f->resetCallCount();
    EXPECT_EQ(f->callCount(), 0u);
}

INSTANTIATE_TEST_SUITE_P(AnalyticFields, CurrentConformance, ::testing::ValuesIn(fieldCases()),
                         [](const auto &info) { return info.param.label; });

TEST(MeanderingJet, PaperParametersPeakSpeedIsAboutOne)
{
    MeanderingJet jet;
    // On the jet axis (s = 0) the speed is exactly 1 for every phase.
    for (double x : {0.0, 0.7, 1.9, 3.3})
    {
        const double t = 2.5;
        const MeanderingJetParams &p = jet.params();
        const double B = p.B0 + p.epsilon * std::cos(p.omega * t + p.theta);
        const double y = B * std::cos(p.k * (x - p.c * t));
        const Velocity c = jet.velocity(x, y, 0, t);
        EXPECT_NEAR(std::hypot(c.u, c.v), 1.0, 1e-12);
    }
    EXPECT_GT(jet.maxSpeed({}), 1.0);
    EXPECT_LT(jet.maxSpeed({}), 1.2);
}

TEST(MeanderingJet, JetsThatDifferInOneParameterEvaluatedInTurnAtOneTimeEachKeepTheirOwnAmplitude)
{
    // each thread keeps the amplitude B(t) of its last evaluation (MeanderingJet.cpp): jets that differ only in B0,
    // epsilon, omega or theta, asked in turn at the same time on one thread, must each give the curl of their own
    // stream function (which computes B(t) itself), and the same value as when asked alone
    std::vector<MeanderingJetParams> params(5);
    params[1].B0 = 0.7;
    params[2].epsilon = -0.5;
    params[3].omega = 1.3;
    params[4].theta = 0.2;
    std::vector<std::unique_ptr<MeanderingJet>> jets;
    for (const MeanderingJetParams &p : params)
        jets.push_back(std::make_unique<MeanderingJet>(p));
    const double h = 1e-5;
    for (const double t : {0.0, 3.7, 11.25})
        for (const double x : {0.4, 2.9, 6.1})
            for (const double y : {-1.5, 0.3, 1.1})
                for (int round = 0; round < 2; ++round)
                    for (std::size_t k = 0; k < jets.size(); ++k)
                    {
                        const MeanderingJet &f = *jets[k];
                        const Velocity c = f.velocity(x, y, 0, t);
                        const double psiX =
                            (*f.streamFunction(x + h, y, 0, t) - *f.streamFunction(x - h, y, 0, t)) / (2 * h);
                        const double psiY =
                            (*f.streamFunction(x, y + h, 0, t) - *f.streamFunction(x, y - h, 0, t)) / (2 * h);
                        EXPECT_NEAR(c.u, -psiY, 1e-6) << "jet " << k << " at " << x << "," << y << "," << t;
                        EXPECT_NEAR(c.v, psiX, 1e-6) << "jet " << k << " at " << x << "," << y << "," << t;
                        const Velocity alone = MeanderingJet(params[k]).velocity(x, y, 0, t);
                        EXPECT_EQ(c.u, alone.u);
                        EXPECT_EQ(c.v, alone.v);
                    }
}

TEST(MeanderingJet, FlowsEastOnTheAxisAndDecaysAway)
{
    MeanderingJet jet;
    // At t with theta = k(x - ct) = 0 the axis is at y = B(t); the flow there is purely eastward.
    const double t = 0.0, x = 0.0;
    const double B = 1.2 + 0.3 * std::cos(M_PI / 2);
    const Velocity onAxis = jet.velocity(x, B, 0, t);
    EXPECT_NEAR(onAxis.u, 1.0, 1e-12);
    EXPECT_NEAR(onAxis.v, 0.0, 1e-12);
    const Velocity far = jet.velocity(x, B + 6.0, 0, t);
    EXPECT_LT(std::hypot(far.u, far.v), 1e-4);
}

TEST(LinearShear, VelocityIsAY)
{
    LinearShear s(-1.0);
    const Velocity c = s.velocity(3.0, 2.0, 0, 0);
    EXPECT_DOUBLE_EQ(c.u, -2.0);
    EXPECT_DOUBLE_EQ(c.v, 0.0);
    EXPECT_DOUBLE_EQ(s.maxSpeed({0, 1, -3, 2}), 3.0);
}

// A forecast corrected by glider DAC (optimal interpolation): no innovation, no change to the bit; a uniform error
// is recovered near the observations and fades far away and long after; the correction fits its observations.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include "ompl_glider/current/CorrectedField.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"

using namespace ompl_glider;

namespace
{
/// DAC along a track across the jet, each the truth @p truth at the dive's middle plus noise of @p sigma.
std::vector<DacObservation> track(const CurrentField &truth, int n, double sigma, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    std::vector<DacObservation> obs;
    for (int k = 0; k < n; ++k)
    {
        const double t = 0.5 * k, x = 2.0 + 0.2 * k, y = -2.0 + 0.1 * k;
        const Velocity c = truth.velocity(x, y, 0.0, t);
        obs.push_back(
            {t, {x, y}, {c.u + (sigma > 0 ? noise(rng) : 0.0), c.v + (sigma > 0 ? noise(rng) : 0.0)}, std::nullopt});
    }
    return obs;
}

/// The jet plus a uniform drift: a truth the forecast misses by (du, dv).
class DriftedJet : public CurrentField
{
public:
    DriftedJet(double du, double dv) : du_(du), dv_(dv) {}
    double maxSpeed(const Region &r) const override { return jet_.maxSpeed(r) + std::hypot(du_, dv_); }
    std::string name() const override { return "drifted jet"; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override
    {
        const Velocity c = jet_.velocity(x, y, z, t);
        return {c.u + du_, c.v + dv_};
    }
    Jacobian evaluateJacobian(double x, double y, double z, double t) const override
    {
        return jet_.jacobian(x, y, z, t);
    }

private:
    MeanderingJet jet_;
    double du_, dv_;
};
} // namespace

TEST(CorrectedField, NoInnovationChangesNothingToTheBit)
{
    auto jet = std::make_shared<MeanderingJet>();
    const CorrectedField corrected(jet, track(*jet, 20, 0.0, 1), {1.0, 3.0, 0.5});
    EXPECT_EQ(corrected.summary().used, 20u);
    EXPECT_EQ(corrected.summary().rmsBefore, 0.0);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> ux(0, 10), uy(-4, 4), ut(0, 20);
    for (int i = 0; i < 2000; ++i)
    {
        const double x = ux(rng), y = uy(rng), t = ut(rng);
        const Velocity a = jet->velocity(x, y, 0, t), b = corrected.velocity(x, y, 0, t);
        EXPECT_EQ(a.u, b.u);
        EXPECT_EQ(a.v, b.v);
        const Jacobian ja = jet->jacobian(x, y, 0, t), jb = corrected.jacobian(x, y, 0, t);
        EXPECT_EQ(ja.ux, jb.ux);
        EXPECT_EQ(ja.vy, jb.vy);
    }
}

TEST(CorrectedField, RecoversAUniformErrorNearTheGliderAndFadesAway)
{
    auto jet = std::make_shared<MeanderingJet>();
    const DriftedJet truth(0.12, -0.08);
    const double sigma = 0.01;
    const std::vector<DacObservation> obs = track(truth, 20, sigma, 7);
    CorrectionParams p;
    p.lengthScale = 1.0;
    p.timeScale = 3.0;
    p.errorRatio = 0.3;
    const CorrectedField corrected(jet, obs, p);
    const DacObservation &last = obs.back();
    const Velocity c = corrected.velocity(last.at.x, last.at.y, 0, last.t);
    const Velocity w = truth.velocity(last.at.x, last.at.y, 0, last.t);
    // within the noise (and the OI's shrinkage towards the forecast, ratio^2 / n of the error)
    EXPECT_LT(std::hypot(c.u - w.u, c.v - w.v), 3.0 * sigma + 0.01);
    // the forecast alone is 0.144 off there
    const Velocity f = jet->velocity(last.at.x, last.at.y, 0, last.t);
    EXPECT_GT(std::hypot(f.u - w.u, f.v - w.v), 0.14);
    EXPECT_LT(corrected.summary().rmsAfter, 0.3 * corrected.summary().rmsBefore);
    // far away (10 length scales) and long after (10 time scales): the forecast itself
    const Velocity far = corrected.correction(last.at.x + 10.0, last.at.y, last.t);
    EXPECT_EQ(far.u, 0.0);
    EXPECT_EQ(far.v, 0.0);
    const Velocity later = corrected.correction(last.at.x, last.at.y, last.t + 30.0);
    EXPECT_EQ(later.u, 0.0);
    EXPECT_EQ(later.v, 0.0);
}

TEST(CorrectedField, RejectsObservationsOutsideTheForecastAndNotFinite)
{
    auto uniform = std::make_shared<UniformCurrent>(0.1, 0.0);
    std::vector<DacObservation> obs{{0.0, {0, 0}, {0.2, 0.0}, std::nullopt},
                                    {1.0, {1, 0}, {std::nan(""), 0.0}, std::nullopt},
                                    {2.0, {2, 0}, {0.2, 0.0}, std::nullopt}};
    CorrectionParams p{1.0, 5.0, 0.5};
    p.maxObservations = 1;
    const CorrectedField c(uniform, obs, p);
    EXPECT_EQ(c.summary().given, 3u);
    EXPECT_EQ(c.summary().notFinite, 1u);
    EXPECT_EQ(c.summary().older, 1u); // the most recent one is kept
    EXPECT_EQ(c.summary().used, 1u);
    // one observation: the weight is 1 / (1 + ratio^2) of its innovation at its own place and time
    EXPECT_NEAR(c.correction(2.0, 0.0, 2.0).u, 0.1 / 1.25, 1e-15);
    EXPECT_THROW(CorrectedField(uniform, obs, CorrectionParams{0.0, 1.0, 0.5}), std::exception);
}

// The Jacobian against central differences, and the speed bound above every sampled speed.
TEST(CorrectedField, JacobianMatchesFiniteDifferencesAndTheBoundHolds)
{
    auto jet = std::make_shared<MeanderingJet>();
    const DriftedJet truth(0.15, -0.1);
    CorrectionParams p{1.5, 6.0, 0.5};
    const CorrectedField f(jet, track(truth, 12, 0.02, 5), p);
    const double h = 1e-5;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> ux(0, 10), uy(-4, 4), ut(0, 10);
    const Region r{0.0, 10.0, -4.0, 4.0, 0.0, 0.0, 0.0, 40.0};
    const double bound = f.maxSpeed(r);
    for (int i = 0; i < 500; ++i)
    {
        const double x = ux(rng), y = uy(rng), t = ut(rng);
        const Jacobian J = f.jacobian(x, y, 0, t);
        const Velocity px = f.velocity(x + h, y, 0, t), mx = f.velocity(x - h, y, 0, t);
        const Velocity py = f.velocity(x, y + h, 0, t), my = f.velocity(x, y - h, 0, t);
        EXPECT_NEAR(J.ux, (px.u - mx.u) / (2 * h), 1e-6);
        EXPECT_NEAR(J.vx, (px.v - mx.v) / (2 * h), 1e-6);
        EXPECT_NEAR(J.uy, (py.u - my.u) / (2 * h), 1e-6);
        EXPECT_NEAR(J.vy, (py.v - my.v) / (2 * h), 1e-6);
        const Velocity c = f.velocity(x, y, 0, t);
        EXPECT_LE(std::hypot(c.u, c.v), bound);
    }
}

// The same current measured 8, 200 or 2000 times along one track (DAC a few metres and seconds apart, as a glider's
// repeated readings are), with the error ratio of the defaults and a tiny one: the correction recovers the error
// along the track and never exceeds it anywhere, however ill-conditioned the system; the speed bound holds and stays
// within the forecast's bound plus the error.
TEST(CorrectedField, ManyCopiesOfOneCurrentNeverCorrectBeyondTheData)
{
    auto forecast = std::make_shared<UniformCurrent>(0.1, 0.0);
    const double error = 0.05; // every DAC: the forecast plus (0.05, 0)
    const Region r{-5.0, 15.0, -5.0, 5.0, 0.0, 0.0, -5.0, 20.0};
    for (const int n : {8, 200, 2000})
        for (const double ratio : {0.2, 1e-6})
        {
            std::vector<DacObservation> obs;
            for (int k = 0; k < n; ++k)
            {
                const double s = static_cast<double>(k) / (n - 1); // along the track, 0..1
                obs.push_back({10.0 * s,
                               {10.0 * s + 1e-4 * std::sin(7.0 * k), 1e-4 * std::cos(5.0 * k)},
                               {0.1 + error, 0.0},
                               std::nullopt});
            }
            CorrectionParams p{2.0, 4.0, ratio};
            const CorrectedField f(forecast, obs, p);
            SCOPED_TRACE(std::to_string(n) + " DAC, ratio " + std::to_string(ratio));
            std::mt19937 rng(11);
            std::uniform_real_distribution<double> ux(-5, 15), uy(-5, 5), ut(-5, 20);
            for (int i = 0; i < 3000; ++i)
            {
                const double x = ux(rng), y = uy(rng), t = ut(rng);
                const Velocity c = f.correction(x, y, t);
                ASSERT_GE(c.u, 0.0);
                ASSERT_LE(c.u, error + 1e-12) << "at " << x << ", " << y << ", " << t;
                ASSERT_EQ(c.v, 0.0);
            }
            // along the track the error is recovered (the interpolation's shrinkage is ratio^2 / readings at most)
            for (int k = 1; k < 10; ++k)
                EXPECT_NEAR(f.correction(k, 0.0, k).u, error, 0.003) << "at " << k;
            EXPECT_LE(f.maxSpeed(r), forecast->maxSpeed(r) + error + 1e-12);
            EXPECT_GE(f.maxSpeed(r), 0.1 + error - 0.003);
        }
}

// Varied readings (the truth's drift plus noise), many of them: the interpolated correction stays within the range of
// the innovations, and the speed bound holds at every sampled point.
TEST(CorrectedField, ManyNoisyReadingsStayWithinTheirRange)
{
    auto jet = std::make_shared<MeanderingJet>();
    const DriftedJet truth(0.1, -0.05);
    std::mt19937 rng(21);
    std::normal_distribution<double> noise(0.0, 0.03);
    std::vector<DacObservation> obs;
    double uLow = 0.0, uHigh = 0.0, vLow = 0.0, vHigh = 0.0;
    for (int k = 0; k < 1000; ++k)
    {
        const double t = 0.01 * k, x = 2.0 + 0.006 * k, y = -2.0 + 0.003 * k;
        const Velocity c = truth.velocity(x, y, 0.0, t), fc = jet->velocity(x, y, 0.0, t);
        DacObservation o{t, {x, y}, {c.u + noise(rng), c.v + noise(rng)}, std::nullopt};
        uLow = std::min(uLow, o.dac.u - fc.u);
        uHigh = std::max(uHigh, o.dac.u - fc.u);
        vLow = std::min(vLow, o.dac.v - fc.v);
        vHigh = std::max(vHigh, o.dac.v - fc.v);
        obs.push_back(o);
    }
    const CorrectedField f(jet, obs, CorrectionParams{1.0, 3.0, 0.05});
    std::uniform_real_distribution<double> ux(0, 10), uy(-4, 4), ut(0, 15);
    const Region r{0.0, 10.0, -4.0, 4.0, 0.0, 0.0, 0.0, 15.0};
    const double bound = f.maxSpeed(r);
    for (int i = 0; i < 3000; ++i)
    {
        const double x = ux(rng), y = uy(rng), t = ut(rng);
        const Velocity c = f.correction(x, y, t);
        ASSERT_GE(c.u, uLow - 1e-12);
        ASSERT_LE(c.u, uHigh + 1e-12);
        ASSERT_GE(c.v, vLow - 1e-12);
        ASSERT_LE(c.v, vHigh + 1e-12);
        const Velocity w = f.velocity(x, y, 0, t);
        ASSERT_LE(std::hypot(w.u, w.v), bound + 1e-12);
    }
    // near the track the drift is recovered far better than the forecast knows it
    const Velocity c = f.correction(4.0, -1.0, 3.33);
    EXPECT_NEAR(c.u, 0.1, 0.03);
    EXPECT_NEAR(c.v, -0.05, 0.03);
}

// Many superobservations: the correction sampled on a grid of a quarter of the scales reads as the exact sum over the
// superobservations (to a small fraction of the innovations), and its Jacobian as the exact one's.
TEST(CorrectedField, TheSampledCorrectionIsTheExactSum)
{
    auto jet = std::make_shared<MeanderingJet>();
    const DriftedJet truth(0.1, -0.05);
    const std::vector<DacObservation> obs = track(truth, 120, 0.03, 23);
    CorrectionParams sampled{1.0, 3.0, 0.2};
    CorrectionParams exact = sampled;
    exact.sampleAbove = std::numeric_limits<std::size_t>::max();
    const CorrectedField a(jet, obs, sampled), b(jet, obs, exact);
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> ux(-2, 30), uy(-6, 12), ut(-10, 75);
    // one query (a heading at a surfacing) is the exact sum, before the grid is sampled and after
    const auto once = [&](double x, double y, double t) {
        const Velocity va = a.velocityOnce(x, y, 0, t), vb = b.velocity(x, y, 0, t);
        EXPECT_EQ(va.u, vb.u);
        EXPECT_EQ(va.v, vb.v);
    };
    once(10.0, 2.0, 30.0);
    double worst = 0.0, worstJ = 0.0, largest = 0.0;
    for (int i = 0; i < 4000; ++i)
    {
        const double x = ux(rng), y = uy(rng), t = ut(rng);
        const Velocity ca = a.correction(x, y, t), cb = b.correction(x, y, t);
        worst = std::max({worst, std::abs(ca.u - cb.u), std::abs(ca.v - cb.v)});
        largest = std::max({largest, std::abs(cb.u), std::abs(cb.v)});
        const Jacobian ja = a.jacobian(x, y, 0, t), jb = b.jacobian(x, y, 0, t);
        worstJ = std::max({worstJ, std::abs(ja.ux - jb.ux), std::abs(ja.uy - jb.uy), std::abs(ja.vx - jb.vx),
                           std::abs(ja.vy - jb.vy)});
    }
    once(12.0, 1.0, 40.0);
    EXPECT_GT(largest, 0.05);          // the points met the correction
    EXPECT_LT(worst, 0.01 * largest);  // linear in time over a quarter of T: about 1 % at most
    EXPECT_LT(worstJ, 0.05 * largest); // per length scale (L = 1)
}

// The sampled grid is made at the first query that reads it, whichever thread asks: threads querying a fresh
// correction at once read what one thread reads alone, to the bit.
TEST(CorrectedField, ThreadsQueryingAFreshCorrectionAtOnceReadTheSameGrid)
{
    auto jet = std::make_shared<MeanderingJet>();
    const DriftedJet truth(0.1, -0.05);
    const std::vector<DacObservation> obs = track(truth, 120, 0.03, 23);
    const CorrectionParams p{1.0, 3.0, 0.2};
    const CorrectedField alone(jet, obs, p), shared(jet, obs, p);
    constexpr int kThreads = 4, kPoints = 300;
    std::vector<std::vector<Velocity>> got(kThreads);
    std::vector<std::thread> pool;
    for (int k = 0; k < kThreads; ++k)
        pool.emplace_back([&, k] {
            for (int i = 0; i < kPoints; ++i)
                got[k].push_back(shared.velocity(0.1 * i, 0.02 * (i + k), 0.0, 0.2 * i));
        });
    for (std::thread &t : pool)
        t.join();
    for (int k = 0; k < kThreads; ++k)
        for (int i = 0; i < kPoints; ++i)
        {
            const Velocity a = alone.velocity(0.1 * i, 0.02 * (i + k), 0.0, 0.2 * i);
            ASSERT_EQ(got[k][i].u, a.u) << k << " " << i;
            ASSERT_EQ(got[k][i].v, a.v) << k << " " << i;
        }
}

namespace
{
/// A current sheared in depth: u = a + b z (z in metres, positive down), the same everywhere and at every time.
class DepthShear : public CurrentField
{
public:
    DepthShear(double a, double b) : a_(a), b_(b) {}
    double maxSpeed(const Region &) const override { return std::abs(a_) + std::abs(b_) * 1000.0; }
    std::string name() const override { return "depth shear"; }

protected:
    Velocity evaluate(double, double, double z, double) const override { return {a_ + b_ * z, 0.0}; }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }

private:
    double a_, b_;
};
} // namespace

// A DAC is the current averaged over its dive: compared with the forecast averaged over the dive's own depths where
// it carries them (the mean of a linear profile: its value at the middle depth), else over the correction's range.
TEST(CorrectedField, EachDacIsComparedOverItsOwnDive)
{
    const auto forecast = std::make_shared<DepthShear>(0.3, -0.002); // 0.3 m/s at the surface, -0.06 at 180 m
    CorrectionParams p;
    p.lengthScale = 10.0;
    p.timeScale = 10.0;
    // the dive 0-180 m measured exactly the forecast's average there (0.3 - 0.002 * 90 = 0.12): no innovation
    DacObservation own{1.0, {0.0, 0.0}, {0.12, 0.0}, std::nullopt, 0.0, 180.0};
    EXPECT_NEAR(forecastAtDac(*forecast, own, p).u, 0.12, 1e-12);
    CorrectedField exact(forecast, {own}, p);
    EXPECT_NEAR(exact.summary().rmsBefore, 0.0, 1e-12);
    // the same DAC without its depths is compared with the surface current (the correction's range 0-0 m): 0.18 off
    DacObservation surface = own;
    surface.depthTop = surface.depthBottom = std::numeric_limits<double>::quiet_NaN();
    CorrectedField againstSurface(forecast, {surface}, p);
    EXPECT_NEAR(againstSurface.summary().rmsBefore, 0.18, 1e-12);
    // a range given to the correction (a dive profile 20-100 m: mean at 60 m, 0.18) serves the DAC without depths
    p.depthTop = 20.0;
    p.depthBottom = 100.0;
    EXPECT_NEAR(forecastAtDac(*forecast, surface, p).u, 0.18, 1e-12);
    EXPECT_NEAR(forecastAtDac(*forecast, own, p).u, 0.12, 1e-12); // its own depths first
    CorrectedField mixed(forecast, {own, DacObservation{2.0, {0.0, 0.0}, {0.12, 0.0}, std::nullopt}}, p);
    EXPECT_NEAR(mixed.summary().rmsBefore, std::sqrt((0.0 + 0.06 * 0.06) / 2.0), 1e-12);
}

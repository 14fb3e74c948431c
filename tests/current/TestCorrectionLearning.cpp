// The correction learned from the DAC (CorrectionParams::learn): scales recovered from DAC drawn from a Gaussian field
// of known scales, a bias recovered and carried ahead, an M2 tide's amplitude and phase recovered from a week of noisy
// DAC; given values kept; too few DAC leave the priors; innovations all zero change nothing to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "ompl_glider/current/CorrectedField.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"

using namespace ompl_glider;

namespace
{
constexpr double kPi = 3.14159265358979323846;

/// @p n DAC at random places and times in a 100 km square over @p days (a fleet's dives, seen as a cloud), their
/// innovations drawn (independently of the code under test: a Cholesky factor of the covariance built here) from a
/// Gaussian field of scales L, T, forecast error s_f and observation error s_o, plus a bias; the forecast is still
/// water, so each DAC is its innovation.
std::vector<DacObservation> gaussianDac(int n, double L, double T, double sf, double so, Velocity bias, double days,
                                        unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> place(0.0, 100000.0), when(0.0, days * 86400.0);
    std::normal_distribution<double> z(0.0, 1.0);
    std::vector<DacObservation> obs(static_cast<std::size_t>(n));
    for (DacObservation &o : obs)
        o = {when(rng), {place(rng), place(rng)}, {}, std::nullopt};
    Eigen::MatrixXd K(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
            const auto &a = obs[static_cast<std::size_t>(i)], &b = obs[static_cast<std::size_t>(j)];
            const double r2 = std::pow(a.at.x - b.at.x, 2) + std::pow(a.at.y - b.at.y, 2), dt = a.t - b.t;
            K(i, j) = sf * sf * std::exp(-r2 / (2 * L * L) - dt * dt / (2 * T * T)) + (i == j ? so * so : 0.0);
        }
    const Eigen::MatrixXd C = K.llt().matrixL();
    Eigen::VectorXd zu(n), zv(n);
    for (int i = 0; i < n; ++i)
    {
        zu[i] = z(rng);
        zv[i] = z(rng);
    }
    const Eigen::VectorXd u = C * zu, v = C * zv;
    for (int i = 0; i < n; ++i)
        obs[static_cast<std::size_t>(i)].dac = {bias.u + u[i], bias.v + v[i]};
    return obs;
}

/// The mission's defaults for a forecast in metres and seconds, every scale a prior to learn.
CorrectionParams learning()
{
    CorrectionParams p;
    p.lengthScale = 20000.0;
    p.timeScale = 86400.0;
    p.errorRatio = 0.2;
    p.learn = true;
    p.lengthGiven = p.timeGiven = p.ratioGiven = false;
    p.dacError = 0.005;
    p.secondsPerTimeUnit = 1.0;
    return p;
}
} // namespace

TEST(CorrectionLearning, ScalesAreRecoveredFromAGaussianFieldOfKnownScales)
{
    // three fields of other scales than the priors (L 20 km, T 1 day, ratio 0.2), each drawn three times: the median
    // estimate within 20 % (one draw of 200 DAC leaves the estimate a sampling spread of about that size)
    const auto still = std::make_shared<UniformCurrent>(0.0, 0.0);
    struct Case
    {
        double L, T, ratio;
    };
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[1];
    };
    for (const Case c :
         {Case{30000.0, 2.0 * 86400.0, 0.25}, Case{12000.0, 0.6 * 86400.0, 0.3}, Case{45000.0, 3.0 * 86400.0, 0.15}})
    {
        std::vector<double> L, T, ratio;
        for (unsigned seed : {11u, 12u, 13u})
        {
            const auto obs = gaussianDac(200, c.L, c.T, 0.1, c.ratio * 0.1, {}, 5.0, seed);
            const CorrectedField f(still, obs, learning());
            const CorrectionSummary &s = f.summary();
            L.push_back(s.params.lengthScale / c.L);
            T.push_back(s.params.timeScale / c.T);
            ratio.push_back(s.params.errorRatio / c.ratio);
            EXPECT_EQ(s.lengthSource, "estimated from 200 DAC");
            EXPECT_EQ(s.learnedFrom, 200u);
            EXPECT_GT(s.likelihoodGain, 0.0);
        }
        EXPECT_NEAR(median(L), 1.0, 0.2) << c.L;
        EXPECT_NEAR(median(T), 1.0, 0.2) << c.T;
        EXPECT_NEAR(median(ratio), 1.0, 0.2) << c.ratio;
    }
}

TEST(CorrectionLearning, ABiasIsRecoveredAndCarriedAhead)
{
    // a field of small scales on a bias of (0.12, -0.08) m/s: the bias is found, and a day after the last DAC and
    // 50 km beyond them the correction still carries it where the interpolation alone has faded
    const auto still = std::make_shared<UniformCurrent>(0.0, 0.0);
    const auto obs = gaussianDac(120, 8000.0, 0.5 * 86400.0, 0.03, 0.006, {0.12, -0.08}, 3.0, 5);
    const CorrectedField f(still, obs, learning());
    const InnovationMean &m = f.summary().mean;
    ASSERT_TRUE(m.active());
    EXPECT_NEAR(m.bias.u, 0.12, 0.015);
    EXPECT_NEAR(m.bias.v, -0.08, 0.015);
    const Velocity ahead = f.correction(150000.0, 50000.0, 4.0 * 86400.0);
    EXPECT_NEAR(ahead.u, m.bias.u, 0.2 * std::abs(m.bias.u));
    EXPECT_NEAR(ahead.v, m.bias.v, 0.2 * std::abs(m.bias.v));
    // without learning the same DAC leave no correction that far
    CorrectionParams fixed;
    fixed.lengthScale = 20000.0;
    fixed.timeScale = 86400.0;
    const CorrectedField plain(still, obs, fixed);
    EXPECT_LT(std::hypot(plain.correction(150000.0, 50000.0, 4.0 * 86400.0).u,
                         plain.correction(150000.0, 50000.0, 4.0 * 86400.0).v),
              1e-3);
}

TEST(CorrectionLearning, AnM2TideIsRecoveredFromAWeekOfNoisyDac)
{
    // hourly DAC over a week along a slow track, innovations an M2 current (0.15 m/s east at phase 40 deg, 0.08 north
    // at -70 deg) plus white noise of 1 cm/s: amplitude within 10 %, phase within 10 deg
    const double w = 2.0 * kPi / (12.4206012 * 3600.0);
    const double au = 0.15, pu = 40.0 * kPi / 180.0, av = 0.08, pv = -70.0 * kPi / 180.0;
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, 0.01);
    std::vector<DacObservation> obs;
    for (int k = 0; k < 7 * 24; ++k)
    {
        const double t = 3600.0 * k;
        obs.push_back({t,
                       {0.25 * t * 0.3, 1000.0 * std::sin(k / 10.0)},
                       {au * std::cos(w * t - pu) + noise(rng), av * std::cos(w * t - pv) + noise(rng)},
                       std::nullopt});
    }
    const auto still = std::make_shared<UniformCurrent>(0.0, 0.0);
    const CorrectedField f(still, obs, learning());
    const InnovationMean &m = f.summary().mean;
    const InnovationMean::Constituent *m2 = nullptr;
    for (const auto &c : m.tides)
        if (c.name == "M2")
            m2 = &c;
    ASSERT_NE(m2, nullptr);
    EXPECT_NEAR(m2->amplitude(true), au, 0.1 * au);
    EXPECT_NEAR(m2->amplitude(false), av, 0.1 * av);
    // the fitted phase is against the tides' origin tRef: back to the time origin of the DAC
    const auto phaseAt0 = [&](bool u) { return std::remainder(m2->phase(u) + m2->omega * m.tRef, 2.0 * kPi); };
    EXPECT_NEAR(std::remainder(phaseAt0(true) - pu, 2.0 * kPi), 0.0, 10.0 * kPi / 180.0);
    EXPECT_NEAR(std::remainder(phaseAt0(false) - pv, 2.0 * kPi), 0.0, 10.0 * kPi / 180.0);
    // carried ahead: six hours after the last DAC the correction follows the tide
    const double t = obs.back().t + 6.0 * 3600.0;
    const Velocity c = f.correction(obs.back().at.x, obs.back().at.y, t);
    EXPECT_NEAR(c.u, au * std::cos(w * t - pu), 0.03);
    EXPECT_NEAR(c.v, av * std::cos(w * t - pv), 0.03);
}

TEST(CorrectionLearning, GivenValuesWinAndFewDacKeepThePriors)
{
    const auto still = std::make_shared<UniformCurrent>(0.0, 0.0);
    const auto obs = gaussianDac(60, 30000.0, 2.0 * 86400.0, 0.1, 0.02, {}, 5.0, 2);
    CorrectionParams p = learning();
    p.lengthGiven = true; // L given: kept; T and the ratio learned
    const CorrectedField f(still, obs, p);
    EXPECT_EQ(f.summary().params.lengthScale, 20000.0);
    EXPECT_EQ(f.summary().lengthSource, "given");
    EXPECT_EQ(f.summary().timeSource, "estimated from 60 DAC");
    EXPECT_NE(f.summary().params.timeScale, 86400.0);
    // five DAC: nothing is estimated, no mean
    const std::vector<DacObservation> few(obs.begin(), obs.begin() + 5);
    const CorrectedField g(still, few, learning());
    EXPECT_EQ(g.summary().params.lengthScale, 20000.0);
    EXPECT_EQ(g.summary().params.timeScale, 86400.0);
    EXPECT_EQ(g.summary().learnedFrom, 0u);
    EXPECT_FALSE(g.summary().mean.active());
    EXPECT_EQ(g.summary().timeSource, "default (too few DAC to estimate)");
}

TEST(CorrectionLearning, NoInnovationLearnsNothingAndChangesNothingToTheBit)
{
    const auto jet = std::make_shared<MeanderingJet>();
    std::vector<DacObservation> obs;
    for (int k = 0; k < 40; ++k)
    {
        const double t = 0.25 * k, x = 1.0 + 0.1 * k, y = -1.0 + 0.05 * k;
        obs.push_back({t, {x, y}, jet->velocity(x, y, 0.0, t), std::nullopt});
    }
    CorrectionParams p = learning();
    p.lengthScale = 1.0;
    p.timeScale = 2.0;
    p.secondsPerTimeUnit = 0.0;
    const CorrectedField f(jet, obs, p);
    EXPECT_EQ(f.summary().learnedFrom, 0u);
    for (int i = 0; i < 20; ++i)
    {
        const double x = 0.5 * i, y = -3.0 + 0.3 * i, t = 0.4 * i;
        const Velocity a = f.velocity(x, y, 0.0, t), b = jet->velocity(x, y, 0.0, t);
        EXPECT_EQ(a.u, b.u);
        EXPECT_EQ(a.v, b.v);
    }
}

TEST(CorrectionLearning, TheLearnedFieldsJacobianMatchesFiniteDifferencesAndItsBoundHolds)
{
    const auto still = std::make_shared<UniformCurrent>(0.0, 0.0);
    const auto obs = gaussianDac(80, 15000.0, 86400.0, 0.05, 0.01, {0.1, 0.05}, 2.0, 9);
    const CorrectedField f(still, obs, learning());
    ASSERT_TRUE(f.summary().mean.active());
    const double h = 1.0;
    Region all; // everywhere, always
    const double bound = f.maxSpeed(all);
    for (int i = 0; i < 30; ++i)
    {
        // points inside and outside the data's box and span
        const double x = -50000.0 + 7000.0 * i, y = 120000.0 - 6000.0 * i, t = 86400.0 * (0.2 * i - 1.0);
        const Jacobian j = f.jacobian(x, y, 0.0, t);
        const Velocity px = f.velocity(x + h, y, 0.0, t), mx = f.velocity(x - h, y, 0.0, t);
        const Velocity py = f.velocity(x, y + h, 0.0, t), my = f.velocity(x, y - h, 0.0, t);
        EXPECT_NEAR(j.ux, (px.u - mx.u) / (2 * h), 1e-8) << i;
        EXPECT_NEAR(j.vy, (py.v - my.v) / (2 * h), 1e-8) << i;
        EXPECT_NEAR(j.uy, (py.u - my.u) / (2 * h), 1e-8) << i;
        EXPECT_NEAR(j.vx, (px.v - mx.v) / (2 * h), 1e-8) << i;
        const Velocity c = f.velocity(x, y, 0.0, t);
        EXPECT_LE(std::hypot(c.u, c.v), bound + 1e-12);
    }
}

namespace
{
/// The RMS of |DAC - F'| of @p later in @p field, F' the corrected still water (each DAC is its innovation).
double rmsError(const CorrectedField &field, const std::vector<DacObservation> &later)
{
    double squares = 0.0;
    for (const DacObservation &o : later)
    {
        const Velocity c = field.correction(o.at.x, o.at.y, o.t);
        squares += std::pow(o.dac.u - c.u, 2) + std::pow(o.dac.v - c.v, 2);
    }
    return std::sqrt(squares / static_cast<double>(later.size()));
}

std::vector<DacObservation> byTime(std::vector<DacObservation> obs)
{
    std::stable_sort(obs.begin(), obs.end(),
                     [](const DacObservation &a, const DacObservation &b) { return a.t < b.t; });
    return obs;
}
} // namespace

TEST(CorrectionLearning, ScalesThatPredictTheLaterDacBetterAreKept)
{
    // a field of longer scales than the priors (45 km, 3 days against 20 km, 1 day): the scales estimated from the
    // earlier DAC predict the later ones better than the priors, and are kept
    const auto still = std::make_shared<UniformCurrent>(0.0, 0.0);
    const auto obs = byTime(gaussianDac(160, 45000.0, 3.0 * 86400.0, 0.1, 0.015, {}, 5.0, 21));
    const CorrectedField f(still, obs, learning());
    const CorrectionSummary &s = f.summary();
    const HeldOutCheck &h = s.heldOut;
    ASSERT_GT(h.scored, 0u);
    EXPECT_EQ(h.fitted + h.scored, s.learnedFrom);
    EXPECT_TRUE(h.scalesKept);
    EXPECT_LT(std::min(h.scalesError, h.learnedError), h.priorError);
    EXPECT_EQ(s.lengthSource, "estimated from 160 DAC");
    EXPECT_NE(s.params.lengthScale, 20000.0);
    // the priors' score is the error of the priors' correction made of the earlier DAC alone at the later ones
    CorrectionParams priors = learning();
    priors.learn = false;
    const std::vector<DacObservation> earlier(obs.begin(), obs.begin() + static_cast<std::ptrdiff_t>(h.fitted));
    const std::vector<DacObservation> later(obs.begin() + static_cast<std::ptrdiff_t>(h.fitted), obs.end());
    EXPECT_NEAR(h.priorError, rmsError(CorrectedField(still, earlier, priors), later), 0.02 * h.priorError);
    // and the scales estimated from the earlier DAC predict the later ones as the check says
    CorrectionParams learned = priors;
    learned.lengthScale = h.lengthScale;
    learned.timeScale = h.timeScale;
    learned.errorRatio = h.errorRatio;
    EXPECT_NEAR(h.scalesError, rmsError(CorrectedField(still, earlier, learned), later), 0.02 * h.scalesError);
}

TEST(CorrectionLearning, TheHeldOutScoreUsesNoDacOfTheFit)
{
    // the check's estimate is made of the earlier DAC alone: a later DAC changed leaves it to the bit and changes the
    // score; an earlier one changed moves it
    const auto still = std::make_shared<UniformCurrent>(0.0, 0.0);
    const auto obs = byTime(gaussianDac(80, 30000.0, 2.0 * 86400.0, 0.1, 0.02, {}, 4.0, 4));
    const HeldOutCheck h = CorrectedField(still, obs, learning()).summary().heldOut;
    ASSERT_GT(h.scored, 0u);
    ASSERT_GT(h.fitted, 0u);
    auto lastChanged = obs, firstChanged = obs;
    lastChanged.back().dac.u += 0.3;
    firstChanged.front().dac.u += 0.3;
    const HeldOutCheck a = CorrectedField(still, lastChanged, learning()).summary().heldOut;
    EXPECT_EQ(a.fitted, h.fitted);
    EXPECT_EQ(a.lengthScale, h.lengthScale);
    EXPECT_EQ(a.timeScale, h.timeScale);
    EXPECT_EQ(a.errorRatio, h.errorRatio);
    EXPECT_NE(a.priorError, h.priorError);
    EXPECT_NE(a.learnedError, h.learnedError);
    const HeldOutCheck b = CorrectedField(still, firstChanged, learning()).summary().heldOut;
    EXPECT_TRUE(b.lengthScale != h.lengthScale || b.timeScale != h.timeScale || b.errorRatio != h.errorRatio);
}

TEST(CorrectionLearning, ATrackAcrossAFrontLeavesThePriors)
{
    // one glider's track (hourly DAC, 0.25 m/s) along a band the forecast misplaced for a day and a half, then out of
    // it into the opposite error: no stationary Gaussian error (what the kernel assumes). Its likelihood prefers long
    // scales and a bias over the priors, but what it learns from the earlier DAC (all in the band) carries the band's
    // error ahead, and predicts the later DAC worse than the priors: the priors stand, as without learning, to the bit
    const auto still = std::make_shared<UniformCurrent>(0.0, 0.0);
    std::vector<DacObservation> obs;
    for (int k = 0; k < 60; ++k)
    {
        const double t = 3600.0 * k, x = 900.0 * k;
        const double u = k < 36 ? 0.15 : -0.1;
        obs.push_back({t, {x, 300.0 * std::sin(k / 5.0)}, {u, 0.5 * u}, std::nullopt});
    }
    const CorrectedField f(still, obs, learning());
    const CorrectionSummary &s = f.summary();
    const HeldOutCheck &h = s.heldOut;
    ASSERT_GT(h.scored, 0u);
    EXPECT_GT(s.likelihoodGain, 0.0);
    EXPECT_FALSE(h.scalesKept);
    EXPECT_FALSE(h.meanKept);
    EXPECT_GT(h.learnedError, h.priorError);
    EXPECT_GT(h.scalesError, h.priorError);
    EXPECT_GT(h.meanError, h.priorError);
    EXPECT_EQ(s.params.lengthScale, 20000.0);
    EXPECT_EQ(s.params.timeScale, 86400.0);
    EXPECT_EQ(s.params.errorRatio, 0.2);
    EXPECT_FALSE(s.mean.active());
    EXPECT_EQ(s.lengthSource.rfind("default (", 0), 0u) << s.lengthSource;
    CorrectionParams off = learning();
    off.learn = false;
    const CorrectedField plain(still, obs, off);
    for (int i = 0; i < 10; ++i)
    {
        const double x = 6000.0 * i, y = 2000.0 - 500.0 * i, t = 7200.0 * i;
        EXPECT_EQ(f.velocity(x, y, 0.0, t).u, plain.velocity(x, y, 0.0, t).u);
        EXPECT_EQ(f.velocity(x, y, 0.0, t).v, plain.velocity(x, y, 0.0, t).v);
    }
}

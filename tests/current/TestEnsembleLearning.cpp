// An ensemble weighed and updated by a glider's DAC (learnForecast): the weights concentrate on the member that made
// the DAC and the forecast planned on is then that member; a truth between the members is forecast better ahead of
// the glider than by the members' mean; DAC that every member matches equally leave the weights equal.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ompl_glider/current/EnsembleField.h"
#include "ompl_glider/current/EnsembleLearning.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"

using namespace ompl_glider;

namespace
{
/// Six jets, B0, k and c each scaled by its own factor: a small ensemble of the jet.
std::vector<std::shared_ptr<const CurrentField>> jets()
{
    const double f[6][3] = {{1.0, 1.0, 1.0}, {1.2, 0.9, 1.1}, {0.85, 1.1, 0.9},
                            {1.1, 0.8, 1.2}, {0.9, 1.2, 0.8}, {1.15, 1.05, 0.85}};
    std::vector<std::shared_ptr<const CurrentField>> out;
    for (const auto &s : f)
    {
        MeanderingJetParams p;
        p.B0 *= s[0];
        p.k *= s[1];
        p.c *= s[2];
        out.push_back(std::make_shared<MeanderingJet>(p));
    }
    return out;
}

/// One DAC per 0.1 time units for two time units along a track across the jet, each @p truth at the dive's middle.
std::vector<DacObservation> ensembleTrack(const CurrentField &truth)
{
    std::vector<DacObservation> obs;
    for (int k = 0; k < 20; ++k)
    {
        const double t = 0.1 * k, x = 1.0 + 0.1 * k, y = -2.0 + 0.15 * k;
        obs.push_back({t, {x, y}, truth.velocity(x, y, 0.0, t), std::nullopt});
    }
    return obs;
}

CorrectionParams params()
{
    CorrectionParams p;
    p.lengthScale = 1.0;
    p.timeScale = 1.0;
    p.dacError = 0.01;
    return p;
}

/// RMS |a - b| over a grid ahead of the track (x 3..8, y -3..3) at time @p t.
double rmsAhead(const CurrentField &a, const CurrentField &b, double t)
{
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 12; ++j)
        {
            const double x = 3.0 + 0.5 * i, y = -3.0 + 0.5 * j;
            const Velocity u = a.velocity(x, y, 0.0, t), v = b.velocity(x, y, 0.0, t);
            sum += std::pow(u.u - v.u, 2) + std::pow(u.v - v.v, 2);
            ++n;
        }
    return std::sqrt(sum / n);
}
} // namespace

TEST(EnsembleLearning, WeightsConcentrateOnTheMemberThatMadeTheDac)
{
    const auto members = jets();
    const auto mean = std::make_shared<EnsembleMeanField>(members);
    for (std::size_t maker : {1u, 3u, 4u})
    {
        const LearnedForecast l = learnForecast(mean, members, ensembleTrack(*members[maker]), params());
        ASSERT_EQ(l.members.size(), members.size());
        EXPECT_GT(l.members[maker].weight, 0.99) << maker;
        EXPECT_EQ(l.weighedBy, 20u);
        EXPECT_NEAR(l.members[maker].rmsInnovation, 0.0, 1e-12);
        double sum = 0.0, coefficients = 0.0;
        for (const MemberScore &m : l.members)
        {
            sum += m.weight;
            coefficients += m.coefficient;
        }
        EXPECT_NEAR(sum, 1.0, 1e-12);
        EXPECT_NEAR(coefficients, 1.0, 1e-9);
        // the forecast planned on is the member that made them, near the track and far ahead of it, days later
        EXPECT_LT(rmsAhead(*l.field, *members[maker], 2.0), 0.02) << maker;
        EXPECT_LT(rmsAhead(*l.field, *members[maker], 5.0), 0.02) << maker;
    }
}

TEST(EnsembleLearning, ATruthBetweenTheMembersIsForecastBetterAheadThanByTheirMean)
{
    // the truth is none of the members: B0, k and c between theirs
    MeanderingJetParams p;
    p.B0 *= 1.08;
    p.k *= 0.93;
    p.c *= 1.06;
    const MeanderingJet truth(p);
    const auto members = jets();
    const auto mean = std::make_shared<EnsembleMeanField>(members);
    const LearnedForecast l = learnForecast(mean, members, ensembleTrack(truth), params());
    for (const double t : {2.0, 3.0, 4.0})
    {
        const double learned = rmsAhead(*l.field, truth, t), plain = rmsAhead(*mean, truth, t);
        EXPECT_LT(learned, 0.7 * plain) << "t = " << t << ": " << learned << " against the mean's " << plain;
    }
}

TEST(EnsembleLearning, DacEveryMemberMatchesLeaveTheWeightsEqualAndOneForecastIsCorrected)
{
    // members that differ only far from the track: every DAC matches each of them alike
    std::vector<std::shared_ptr<const CurrentField>> same{std::make_shared<UniformCurrent>(0.1, 0.0),
                                                          std::make_shared<UniformCurrent>(0.1, 0.0),
                                                          std::make_shared<UniformCurrent>(0.1, 0.0)};
    const auto mean = std::make_shared<EnsembleMeanField>(same);
    const LearnedForecast l = learnForecast(mean, same, ensembleTrack(*same[0]), params());
    for (const MemberScore &m : l.members)
        EXPECT_NEAR(m.weight, 1.0 / 3.0, 1e-12);
    const Velocity c = l.field->velocity(5.0, 1.0, 0.0, 2.0);
    EXPECT_DOUBLE_EQ(c.u, 0.1);
    EXPECT_DOUBLE_EQ(c.v, 0.0);
    // one forecast (no members): the forecast corrected by optimal interpolation alone
    const LearnedForecast one = learnForecast(same[0], {}, ensembleTrack(UniformCurrent(0.2, 0.0)), params());
    EXPECT_TRUE(one.members.empty());
    EXPECT_GT(one.field->velocity(1.5, -1.0, 0.0, 1.0).u, 0.15);
}

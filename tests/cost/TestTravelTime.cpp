// Travel time of a leg: closed forms (uniform current, shear flow), a fine fixed-step reference in the meandering
// jet, infeasible legs, degenerate inputs, and the arrival window used by the OMPL motion validator.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/UniformCurrent.h"

using namespace ompl_glider;

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

// Closed form in a uniform current: L / (p.c + sqrt((p.c)^2 + V^2 - |c|^2)), or inf.
double uniformClosedForm(double L, double px, double py, double cu, double cv, double V)
{
    const double pc = px * cu + py * cv;
    const double disc = pc * pc + V * V - cu * cu - cv * cv;
    if (disc <= 0)
        return kInf;
    const double v = pc + std::sqrt(disc);
    return v > 0 ? L / v : kInf;
}

// Reference: dt/ds = 1 / v_fast(c(x(s), t)) integrated with classical RK4 and a fine fixed step in s.
double referenceTravelTime(const CurrentField &f, double V, double x1, double y1, double x2, double y2, double t0,
                           int steps)
{
    const double L = std::hypot(x2 - x1, y2 - y1);
    const double px = (x2 - x1) / L, py = (y2 - y1) / L;
    auto rate = [&](double s, double t) {
        const Velocity c = f.velocity(x1 + s * px, y1 + s * py, 0, t);
        const AlongTrackSpeeds r = alongTrackSpeeds(px, py, c, V);
        return r.feasible ? 1.0 / r.fast : kInf;
    };
    double t = t0;
    const double ds = L / steps;
    for (int i = 0; i < steps; ++i)
    {
        const double s = i * ds;
        const double k1 = rate(s, t);
        const double k2 = rate(s + ds / 2, t + ds / 2 * k1);
        const double k3 = rate(s + ds / 2, t + ds / 2 * k2);
        const double k4 = rate(s + ds, t + ds * k3);
        t += ds / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return t - t0;
}
} // namespace

TEST(AlongTrackSpeeds, RootsOfLineCircleIntersection)
{
    // Current (0.3, 0.4) (|c| = 0.5), V = 1, heading +x: p.c = 0.3, disc = 0.09 + 1 - 0.25 = 0.84.
    const AlongTrackSpeeds r = alongTrackSpeeds(1, 0, {0.3, 0.4}, 1.0);
    ASSERT_TRUE(r.feasible);
    EXPECT_NEAR(r.fast, 0.3 + std::sqrt(0.84), 1e-15);
    EXPECT_NEAR(r.slow, 0.3 - std::sqrt(0.84), 1e-15);
    // Both roots put the vehicle's water velocity s p - c on the circle of radius V.
    for (double s : {r.fast, r.slow})
        EXPECT_NEAR(std::hypot(s - 0.3, -0.4), 1.0, 1e-12);
    // Cross current stronger than V: no intersection.
    EXPECT_FALSE(alongTrackSpeeds(1, 0, {0.0, 0.6}, 0.5).feasible);
    // Head current stronger than V: both roots negative, pushed backwards.
    EXPECT_FALSE(alongTrackSpeeds(1, 0, {-0.6, 0.0}, 0.5).feasible);
}

TEST(TravelTime, UniformCurrentClosedFormAllDirections)
{
    const double V = 0.5;
    for (auto [cu, cv] : {std::pair{0.3, 0.0}, {0.0, 0.45}, {-0.2, 0.35}, {0.6, -0.1}})
    {
        TravelTimeParams p;
        p.speed = V;
        TravelTimeCalculator calc(std::make_shared<UniformCurrent>(cu, cv), p);
        int infeasible = 0;
        for (int k = 0; k < 36; ++k)
        {
            const double a = 2 * M_PI * k / 36, L = 3.7;
            const double expected = uniformClosedForm(L, std::cos(a), std::sin(a), cu, cv, V);
            const double got = calc.travelTime(1.0, -2.0, 1.0 + L * std::cos(a), -2.0 + L * std::sin(a), 4.0);
            if (std::isinf(expected))
            {
                EXPECT_TRUE(std::isinf(got)) << "heading " << a;
                ++infeasible;
            }
            else
                EXPECT_NEAR(got, expected, 1e-9 * expected) << "heading " << a;
        }
        // The current faster than V must make some headings infeasible, a slower one none.
        if (std::hypot(cu, cv) > V)
            EXPECT_GT(infeasible, 0);
        else
            EXPECT_EQ(infeasible, 0);
    }
}

TEST(TravelTime, ShearFlowAlongAndAcrossTheFlow)
{
    const double a = -1.0, V = 1.0;
    TravelTimeParams p;
    p.speed = V;
    p.eps = 1e-8;
    TravelTimeCalculator calc(std::make_shared<LinearShear>(a), p);
    // Along the flow at y0 = -0.5: the current is (0.5, 0) all along: T = L / (V + 0.5).
    EXPECT_NEAR(calc.travelTime(0, -0.5, 3, -0.5, 0), 3.0 / 1.5, 1e-12);
    EXPECT_NEAR(calc.travelTime(3, -0.5, 0, -0.5, 0), 3.0 / 0.5, 1e-12);
    // Across the flow from y = 0 to y = 0.8: v_ef = sqrt(V^2 - a^2 y^2), T = asin(|a| y / V) / |a|.
    const double T = calc.travelTime(2.0, 0.0, 2.0, 0.8, 0.0);
    EXPECT_NEAR(T, std::asin(0.8), 1e-5);
    // Across into |a y| > V: infeasible.
    EXPECT_TRUE(std::isinf(calc.travelTime(2.0, 0.0, 2.0, 1.2, 0.0)));
}

TEST(TravelTime, CrossingTheJetAgreesWithFineReference)
{
    auto jet = std::make_shared<MeanderingJet>();
    TravelTimeParams p; // defaults: V = 0.5, eps = 1e-3
    TravelTimeCalculator calc(jet, p);
    struct Leg
    {
        double x1, y1, x2, y2, t0;
    };
    // Legs of 0.4 - 1.5 that cross or ride the jet, at several departure times.
    for (const Leg &l : {Leg{1.0, -1.0, 1.4, 0.2, 0.0}, Leg{2.0, 2.0, 3.5, -0.5, 4.5}, Leg{8.0, -2.0, 8.4, -0.6, 12.0},
                         Leg{3.0, 1.0, 3.4, -0.2, 9.0}, Leg{1.0, -1.0, 1.4, 0.2, 7.5}})
    {
        const double ref = referenceTravelTime(*jet, p.speed, l.x1, l.y1, l.x2, l.y2, l.t0, 20000);
        const double got = calc.travelTime(l.x1, l.y1, l.x2, l.y2, l.t0);
        ASSERT_TRUE(std::isfinite(ref));
        ASSERT_TRUE(std::isfinite(got));
        // Accepted steps have a rough-vs-improved difference below eps and keep the improved (second-order)
        // value, whose own error is far smaller: the whole leg stays within eps of the reference.
        EXPECT_NEAR(got, ref, p.eps) << "leg from " << l.x1 << "," << l.y1;
        // Tighter tolerance gives a tighter answer.
        TravelTimeParams tight = p;
        tight.eps = 1e-9;
        tight.hMin = 1e-5;
        EXPECT_NEAR(TravelTimeCalculator(jet, tight).travelTime(l.x1, l.y1, l.x2, l.y2, l.t0), ref, 1e-6);
    }
}

TEST(TravelTime, InfeasibleLegAgainstTheJetIsInfiniteNotNaN)
{
    auto jet = std::make_shared<MeanderingJet>();
    TravelTimeCalculator calc(jet);
    // Westward along the axis at t = 0 (axis at y = B(0) = 1.2 for x = 0): current 1.0 against V = 0.5.
    const double T = calc.travelTime(0.3, 1.2, -0.3, 1.2, 0.0);
    EXPECT_TRUE(std::isinf(T));
    EXPECT_FALSE(std::isnan(T));
}

TEST(TravelTime, DegenerateInputs)
{
    TravelTimeCalculator calc(std::make_shared<MeanderingJet>());
    EXPECT_EQ(calc.travelTime(1, 1, 1, 1, 3.0), 0.0);
    EXPECT_TRUE(std::isinf(calc.travelTime(1, 1, 2, 1, kInf)));
    EXPECT_TRUE(std::isinf(calc.travelTime(1, 1, 2, std::nan(""), 0.0)));
}

TEST(TravelTime, DependsOnDepartureTimeInTheJet)
{
    TravelTimeCalculator calc(std::make_shared<MeanderingJet>());
    const double a = calc.travelTime(1.0, -1.0, 1.4, 0.2, 0.0);
    const double b = calc.travelTime(1.0, -1.0, 1.4, 0.2, 6.0);
    ASSERT_TRUE(std::isfinite(a));
    ASSERT_TRUE(std::isfinite(b));
    EXPECT_GT(std::abs(a - b), 1.0); // about 8.9 against 4.4
}

TEST(TravelTime, CountsCostFunctionCallsAndCurrentModelCalls)
{
    auto jet = std::make_shared<MeanderingJet>();
    TravelTimeCalculator calc(jet);
    jet->resetCallCount();
    for (int i = 0; i < 7; ++i)
        calc.travelTime(1.0, -1.0, 1.4, 0.2, 0.5 * i);
    EXPECT_EQ(calc.costFunctionCalls(), 7u);
    // Each step reads the current once at its end (plus one read at the leg's start), so CMC > CFC.
    EXPECT_GT(jet->callCount(), 7u * 2);
    calc.resetCostFunctionCalls();
    EXPECT_EQ(calc.costFunctionCalls(), 0u);
}

TEST(ArrivalWindow, UniformCurrentBoundsAndHolding)
{
    TravelTimeParams p;
    p.speed = 0.5;
    // Current along the leg 0.3: roots 0.8 and -0.2: slow root <= 0, the vehicle can hold: latest unbounded.
    TravelTimeCalculator hold(std::make_shared<UniformCurrent>(0.3, 0.0), p);
    ArrivalWindow w = hold.arrivalWindow(0, 0, 2, 0, 0);
    EXPECT_NEAR(w.earliest, 2.0 / 0.8, 1e-12);
    EXPECT_TRUE(std::isinf(w.latest));
    // Current along the leg 0.7 > V: roots 1.2 and 0.2: the vehicle is swept along, latest = L / 0.2.
    TravelTimeCalculator swept(std::make_shared<UniformCurrent>(0.7, 0.0), p);
    w = swept.arrivalWindow(0, 0, 2, 0, 0);
    EXPECT_NEAR(w.earliest, 2.0 / 1.2, 1e-12);
    EXPECT_NEAR(w.latest, 2.0 / 0.2, 1e-9);
    // Against 0.7 > V: infeasible, both infinite.
    w = swept.arrivalWindow(2, 0, 0, 0, 0);
    EXPECT_TRUE(std::isinf(w.earliest));
}

TEST(TravelTimeParams, RejectsBadParameters)
{
    auto f = std::make_shared<UniformCurrent>(0, 0);
    TravelTimeParams p;
    p.speed = 0;
    EXPECT_THROW(TravelTimeCalculator(f, p), std::runtime_error);
    p = {};
    p.hMin = 0;
    EXPECT_THROW(TravelTimeCalculator(f, p), std::runtime_error);
    p = {};
    p.tau = 1.5;
    EXPECT_THROW(TravelTimeCalculator(f, p), std::runtime_error);
    p = {};
    p.rtol = -1e-6;
    EXPECT_THROW(TravelTimeCalculator(f, p), std::runtime_error);
    p.rtol = kInf;
    EXPECT_THROW(TravelTimeCalculator(f, p), std::runtime_error);
    EXPECT_THROW(TravelTimeCalculator(nullptr, {}), std::runtime_error);
}

namespace
{
// A uniform current with a thin north-south strip of land at |x - 5| < 0.01: narrower than any integration step.
class ThinIslandField : public CurrentField
{
public:
    double maxSpeed(const Region &) const override { return 0.2; }
    bool inWater(double x, double, double) const override { return std::abs(x - 5.0) >= 0.01; }
    bool segmentInWater(double x1, double, double x2, double, double) const override
    {
        return std::max(x1, x2) <= 4.99 || std::min(x1, x2) >= 5.01;
    }
    std::string name() const override { return "thin island"; }

protected:
    Velocity evaluate(double, double, double, double) const override { return {0.2, 0.0}; }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }
};
} // namespace

TEST(TravelTime, NeverCrossesLandBetweenIntegrationSteps)
{
    TravelTimeCalculator calc(std::make_shared<ThinIslandField>());
    // Both ends in water, steps of up to half the leg would jump over the strip: the whole-leg check catches it.
    EXPECT_TRUE(std::isinf(calc.travelTime(0.0, 0.0, 10.0, 0.0, 0.0)));
    EXPECT_TRUE(std::isinf(calc.travelTime(9.0, 1.0, 1.0, -1.0, 0.0)));
    // Legs on either side are flown as in open water: L / (V + 0.2).
    EXPECT_NEAR(calc.travelTime(0.0, 0.0, 4.9, 0.0, 0.0), 4.9 / 0.7, 1e-12);
    EXPECT_NEAR(calc.travelTime(5.1, 0.0, 9.0, 0.0, 0.0), 3.9 / 0.7, 1e-12);
}

namespace
{
// Calm water (u = 0.02) with an adverse band u = -0.3 for 3 < x < 4.5: a feature a long step can pass over when
// both its ends are calm.
class AdverseBandField : public CurrentField
{
public:
    double maxSpeed(const Region &) const override { return 0.3; }
    std::string name() const override { return "adverse band"; }

protected:
    Velocity evaluate(double x, double, double, double) const override
    {
        return {x > 3.0 && x < 4.5 ? -0.3 : 0.02, 0.0};
    }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }
};
} // namespace

// A 9-unit leg through the band: the closed form is 1.5 / 0.1 + 7.5 / 0.42. With maxStep smaller than the band
// the integration must see it (within the step law's tolerance). Without the cap the step law passes over the band
// (9 / 0.42 = 21.4 instead of 32.9), which is why MissionProblem caps gridded fields at half a grid cell.
TEST(TravelTime, MaxStepKeepsNarrowFeaturesBetweenCalmEnds)
{
    const auto field = std::make_shared<AdverseBandField>();
    const double exact = 1.5 / (0.4 - 0.3) + 7.5 / (0.4 + 0.02);
    TravelTimeParams p;
    p.speed = 0.4;
    p.maxStep = 0.25;
    const TravelTimeCalculator capped(field, p);
    EXPECT_NEAR(capped.travelTime(0.0, 0.0, 9.0, 0.0, 0.0), exact, 0.02 * exact);
    // the same leg in pieces agrees
    double pieces = 0.0;
    for (int k = 0; k < 9; ++k)
        pieces += capped.travelTime(k, 0.0, k + 1.0, 0.0, pieces);
    EXPECT_NEAR(capped.travelTime(0.0, 0.0, 9.0, 0.0, 0.0), pieces, 0.02 * exact);
    p.maxStep = 0.0;
    EXPECT_THROW(TravelTimeCalculator(field, p), std::runtime_error);
}

namespace
{
// The meandering jet in another time unit: t' = k t, so velocities are c / k and every travel time is k times the
// jet's (with the speed V / k).
class TimeScaledJet : public CurrentField
{
public:
    explicit TimeScaledJet(double k) : k_(k) {}
    double maxSpeed(const Region &) const override { return 1.1 / k_; }
    std::string name() const override { return "time-scaled jet"; }

protected:
    Velocity evaluate(double x, double y, double z, double t) const override
    {
        const Velocity c = jet_.velocity(x, y, z, t / k_);
        return {c.u / k_, c.v / k_};
    }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }

private:
    MeanderingJet jet_;
    double k_;
};

struct JetLeg
{
    double x1, y1, x2, y2, t0;
};
const JetLeg kJetLegs[] = {{1.0, -1.0, 1.4, 0.2, 0.0},
                           {2.0, 2.0, 3.5, -0.5, 4.5},
                           {8.0, -2.0, 8.4, -0.6, 12.0},
                           {3.0, 1.0, 3.4, -0.2, 9.0},
                           {1.0, -1.0, 1.4, 0.2, 7.5}};
} // namespace

// "leg tolerances relative to the leg": with rtol > 0 a step is judged against min(eps, rtol * its time).
TEST(TravelTime, RelativeToleranceOffIsTheAbsoluteOneBitForBit)
{
    // rtol so large that rtol * t_step >= eps on every step: the same steps, the same bits, as rtol = 0
    auto jet = std::make_shared<MeanderingJet>();
    TravelTimeParams p;
    const TravelTimeCalculator off(jet, p);
    p.rtol = 1e30;
    const TravelTimeCalculator loose(jet, p);
    for (const JetLeg &l : kJetLegs)
    {
        const double a = off.travelTime(l.x1, l.y1, l.x2, l.y2, l.t0);
        ASSERT_TRUE(std::isfinite(a));
        EXPECT_EQ(a, loose.travelTime(l.x1, l.y1, l.x2, l.y2, l.t0));
    }
    // a tight rtol changes the answer (towards the reference)
    p.rtol = 1e-6;
    const TravelTimeCalculator tight(jet, p);
    const JetLeg &l = kJetLegs[0];
    const double ref = referenceTravelTime(*jet, 0.5, l.x1, l.y1, l.x2, l.y2, l.t0, 20000);
    EXPECT_LT(std::abs(tight.travelTime(l.x1, l.y1, l.x2, l.y2, l.t0) - ref),
              std::abs(off.travelTime(l.x1, l.y1, l.x2, l.y2, l.t0) - ref));
}

TEST(TravelTime, RelativeToleranceHoldsInAnyTimeUnit)
{
    // the jet's legs in its own time unit and in units 1000 times longer and shorter: a purely relative tolerance
    // (eps out of the way, rtol = 1e-6, hMin small enough not to cap it) meets 1e-6 relative in every unit, where
    // the absolute eps = 1e-3 means 1e-3 of a time unit, whatever the unit
    for (double k : {1.0, 1e3, 1e-3})
    {
        auto field = std::make_shared<TimeScaledJet>(k);
        TravelTimeParams p;
        p.speed = 0.5 / k;
        p.eps = 1e300;
        p.rtol = 1e-6;
        p.hMin = 1e-6;
        const TravelTimeCalculator rel(field, p);
        TravelTimeParams a;
        a.speed = p.speed;
        const TravelTimeCalculator abs(field, a);
        for (const JetLeg &l : kJetLegs)
        {
            const double ref = referenceTravelTime(*field, p.speed, l.x1, l.y1, l.x2, l.y2, k * l.t0, 20000);
            ASSERT_TRUE(std::isfinite(ref));
            const double got = rel.travelTime(l.x1, l.y1, l.x2, l.y2, k * l.t0);
            EXPECT_LT(std::abs(got - ref), 1e-6 * ref) << "time unit x" << k << ", leg from " << l.x1 << "," << l.y1;
            const double absErr = std::abs(abs.travelTime(l.x1, l.y1, l.x2, l.y2, k * l.t0) - ref) / ref;
            std::printf("time unit x%g leg from (%g, %g): relative error rtol 1e-6 %.1e, eps 1e-3 %.1e\n", k, l.x1,
                        l.y1, std::abs(got - ref) / ref, absErr);
        }
    }
}

TEST(TravelTime, RelativeToleranceCostOnTheJetMeasured)
{
    // the cost of a cost-function call (current-model calls per CFC) with rtol = 1e-6 against the default, on the
    // micro-benchmark's legs (benchmarks/bench_travel_time.cpp) of length 0.4 and 1.2 at V = 0.5; printed, with
    // the relative error against the fine RK4 reference on every fifth leg. The last setting (hMin small enough
    // not to cap rtol) is run on those legs only: it costs about 1e5 CMC per CFC.
    auto jet = std::make_shared<MeanderingJet>();
    struct Setting
    {
        const char *name;
        double rtol, hMin;
        std::size_t every; // legs run: every one, or every fifth
    };
    for (double length : {0.4, 1.2})
    {
        std::vector<JetLeg> legs;
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j)
                for (int k = 0; k < 16; ++k)
                {
                    const double x = 1.0 + 2.0 * i, y = -3.0 + 1.5 * j, a = 2 * M_PI * k / 16;
                    legs.push_back({x, y, x + length * std::cos(a), y + length * std::sin(a), 0.7 * (i + j + k)});
                }
        std::vector<double> ref;
        for (std::size_t n = 0; n < legs.size(); n += 5)
        {
            const JetLeg &l = legs[n];
            ref.push_back(referenceTravelTime(*jet, 0.5, l.x1, l.y1, l.x2, l.y2, l.t0, 4000));
        }
        double defaultCmc = 0.0;
        for (const Setting &s : {Setting{"default (eps 1e-3)", 0.0, 1e-3, 1}, Setting{"rtol 1e-6", 1e-6, 1e-3, 1},
                                 Setting{"rtol 1e-6, hMin 1e-6", 1e-6, 1e-6, 5}})
        {
            TravelTimeParams p;
            p.rtol = s.rtol;
            p.hMin = s.hMin;
            const TravelTimeCalculator calc(jet, p);
            jet->resetCallCount();
            double worst = 0.0, sum = 0.0;
            int compared = 0;
            std::size_t run = 0;
            for (std::size_t n = 0; n < legs.size(); n += s.every, ++run)
            {
                const JetLeg &l = legs[n];
                const double t = calc.travelTime(l.x1, l.y1, l.x2, l.y2, l.t0);
                if (n % 5 == 0 && std::isfinite(t) && std::isfinite(ref[n / 5]))
                {
                    const double e = std::abs(t - ref[n / 5]) / ref[n / 5];
                    worst = std::max(worst, e);
                    sum += e;
                    ++compared;
                }
            }
            const double cmc = double(jet->callCount()) / double(run);
            if (s.rtol == 0.0)
                defaultCmc = cmc;
            else
                EXPECT_GT(cmc, defaultCmc); // a tighter tolerance takes more steps
            std::printf(
                "length %.1f, %-22s: %9.1f CMC per CFC (x%.0f), relative error mean %.1e worst %.1e (%d legs)\n",
                length, s.name, cmc, cmc / defaultCmc, sum / compared, worst, compared);
        }
    }
}

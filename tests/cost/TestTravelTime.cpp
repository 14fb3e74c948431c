// Travel time of a leg: closed forms (uniform current, shear flow), a fine fixed-step reference in the meandering
// jet, infeasible legs, degenerate inputs, and the arrival window used by the OMPL motion validator.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

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
}  // namespace

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
    TravelTimeParams p;  // defaults: V = 0.5, eps = 1e-3
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
    EXPECT_GT(std::abs(a - b), 1.0);  // about 8.9 against 4.4
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
    EXPECT_THROW(TravelTimeCalculator(nullptr, {}), std::runtime_error);
}

namespace
{
// A uniform current with a thin north-south strip of land at |x - 5| < 0.01: narrower than any integration step.
class ThinIslandField : public CurrentField
{
public:
    double maxSpeed(const Region &) const override
    {
        return 0.2;
    }
    bool inWater(double x, double, double) const override
    {
        return std::abs(x - 5.0) >= 0.01;
    }
    bool segmentInWater(double x1, double, double x2, double, double) const override
    {
        return std::max(x1, x2) <= 4.99 || std::min(x1, x2) >= 5.01;
    }
    std::string name() const override
    {
        return "thin island";
    }

protected:
    Velocity evaluate(double, double, double, double) const override
    {
        return {0.2, 0.0};
    }
    Jacobian evaluateJacobian(double, double, double, double) const override
    {
        return {};
    }
};
}  // namespace

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
    double maxSpeed(const Region &) const override
    {
        return 0.3;
    }
    std::string name() const override
    {
        return "adverse band";
    }

protected:
    Velocity evaluate(double x, double, double, double) const override
    {
        return {x > 3.0 && x < 4.5 ? -0.3 : 0.02, 0.0};
    }
    Jacobian evaluateJacobian(double, double, double, double) const override
    {
        return {};
    }
};
}  // namespace

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

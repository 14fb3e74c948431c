// 1-D interpolation schemes ([EichhornOceans] Sec. II.C): what each reproduces exactly, Akima's lack of overshoot at a
// step, and the overshoot factors used for the speed bound.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/Interpolation.h"

using namespace ompl_glider;

namespace
{
double applyW(const Stencil &s, const std::vector<double> &y)
{
    double r = 0;
    for (int i = 0; i < s.n; ++i)
        r += s.w[i] * y[s.first + i];
    return r;
}
double applyDW(const Stencil &s, const std::vector<double> &y)
{
    double r = 0;
    for (int i = 0; i < s.n; ++i)
        r += s.dw[i] * y[s.first + i];
    return r;
}
const std::vector<double> kNonUniform{-1.0, -0.3, 0.0, 0.7, 1.1, 2.0, 3.5, 3.6, 5.0};
} // namespace

TEST(Axis, LocatesOnUniformAndNonUniformAxes)
{
    const Axis u({0.0, 0.5, 1.0, 1.5, 2.0});
    EXPECT_TRUE(u.uniform());
    EXPECT_EQ(u.interval(-3.0), 0u);
    EXPECT_EQ(u.interval(0.5), 1u);
    EXPECT_EQ(u.interval(0.49999), 0u);
    EXPECT_EQ(u.interval(2.0), 3u);
    EXPECT_EQ(u.interval(9.0), 3u);
    const Axis n(kNonUniform);
    EXPECT_FALSE(n.uniform());
    for (std::size_t k = 0; k + 1 < kNonUniform.size(); ++k)
    {
        const double q = 0.5 * (kNonUniform[k] + kNonUniform[k + 1]);
        EXPECT_EQ(n.interval(q), k);
    }
    EXPECT_THROW(Axis({0.0, 1.0, 1.0}), Error);
    EXPECT_THROW(Axis(std::vector<double>{}), Error);
}

// Found by fuzz_netcdf (a time axis 0, 4.4e-318 hours): a spacing too small to invert, or a query far beyond the
// axis, made the cell index of a uniform axis infinite before its conversion to an integer (undefined behaviour).
TEST(Axis, LocatesFarQueriesAndTinySpacingsOnUniformAxes)
{
    const Axis u({0.0, 0.5, 1.0, 1.5, 2.0});
    EXPECT_EQ(u.interval(1e300), 3u);
    EXPECT_EQ(u.interval(std::numeric_limits<double>::infinity()), 3u);
    EXPECT_EQ(u.interval(-std::numeric_limits<double>::infinity()), 0u);
    EXPECT_EQ(u.interval(std::nan("")), 0u);
    const Axis tiny({0.0, 1.5e-314, 3e-314}); // subnormal spacing: 1 / spacing overflows
    EXPECT_TRUE(tiny.uniform());
    EXPECT_EQ(tiny.interval(3e-314), 1u);
    EXPECT_EQ(tiny.interval(1.0), 1u);
    EXPECT_EQ(tiny.interval(0.0), 0u);
}

TEST(Interpolation1D, NearestPicksTheClosestNode)
{
    const Axis a(kNonUniform);
    std::vector<double> y(kNonUniform.size());
    for (std::size_t i = 0; i < y.size(); ++i)
        y[i] = double(i * i) + 0.5;
    EXPECT_DOUBLE_EQ(applyW(makeStencil(a, Interp1D::Nearest, 0.3), y), y[2]); // 0.3 closer to 0.0 than 0.7
    EXPECT_DOUBLE_EQ(applyW(makeStencil(a, Interp1D::Nearest, 0.4), y), y[3]);
    EXPECT_DOUBLE_EQ(applyW(makeStencil(a, Interp1D::Nearest, 3.56), y), y[7]);
    EXPECT_DOUBLE_EQ(applyW(makeStencil(a, Interp1D::Nearest, -9.0), y), y[0]); // clamped
}

TEST(Interpolation1D, LinearReproducesLinearFunctions)
{
    const Axis a(kNonUniform);
    std::vector<double> y;
    for (double x : kNonUniform)
        y.push_back(2.5 - 1.25 * x);
    for (double q = -1.0; q <= 5.0; q += 0.0137)
    {
        const Stencil s = makeStencil(a, Interp1D::Linear, q);
        EXPECT_NEAR(applyW(s, y), 2.5 - 1.25 * q, 1e-13);
        EXPECT_NEAR(applyDW(s, y), -1.25, 1e-12);
    }
}

TEST(Interpolation1D, CubicReproducesCubicPolynomialsOnNonUniformAxes)
{
    const Axis a(kNonUniform);
    auto p = [](double x) { return 0.3 - 1.1 * x + 0.7 * x * x - 0.25 * x * x * x; };
    auto dp = [](double x) { return -1.1 + 1.4 * x - 0.75 * x * x; };
    std::vector<double> y;
    for (double x : kNonUniform)
        y.push_back(p(x));
    for (double q = -1.0; q <= 5.0; q += 0.0137)
    {
        const Stencil s = makeStencil(a, Interp1D::Cubic, q);
        EXPECT_EQ(s.n, 4);
        EXPECT_NEAR(applyW(s, y), p(q), 1e-11) << q;
        EXPECT_NEAR(applyDW(s, y), dp(q), 1e-10) << q;
    }
    // a quartic is not reproduced: the scheme really is cubic
    std::vector<double> y4;
    for (double x : kNonUniform)
        y4.push_back(x * x * x * x);
    EXPECT_GT(std::abs(applyW(makeStencil(a, Interp1D::Cubic, 1.5), y4) - std::pow(1.5, 4)), 1e-3);
}

TEST(Interpolation1D, CubicWithFewNodesDegradesToLowerDegree)
{
    const Axis a({0.0, 1.0, 3.0});
    std::vector<double> y{1.0, 2.0, 10.0}; // quadratic 1 + 0 x + x^2 ... check: 1, 2, 10 -> x^2 + 1
    for (double q = 0; q <= 3; q += 0.1)
        EXPECT_NEAR(applyW(makeStencil(a, Interp1D::Cubic, q), y), q * q + 1, 1e-12);
}

TEST(Interpolation1D, AkimaDoesNotOvershootAtAStep)
{
    // A tide-like abrupt change: 0 0 0 0 1 1 1 1. Akima stays within [0, 1] and is flat away from the step;
    // the 4-point cubic overshoots (the "unnatural wiggles" of [EichhornOceans] Sec. II.C).
    const Axis a({0, 1, 2, 3, 4, 5, 6, 7});
    const std::vector<double> y{0, 0, 0, 0, 1, 1, 1, 1};
    double cubicMin = 0, cubicMax = 1;
    for (double q = 0; q <= 7; q += 0.01)
    {
        const double v = akimaInterpolate(a, q, [&](std::size_t i) { return y[i]; });
        EXPECT_GE(v, -1e-15) << q;
        EXPECT_LE(v, 1 + 1e-15) << q;
        if (q <= 3.0)
        {
            EXPECT_NEAR(v, 0.0, 1e-15) << q;
        }
        if (q >= 4.0)
        {
            EXPECT_NEAR(v, 1.0, 1e-15) << q;
        }
        const double c = applyW(makeStencil(a, Interp1D::Cubic, q), y);
        cubicMin = std::min(cubicMin, c);
        cubicMax = std::max(cubicMax, c);
    }
    EXPECT_LT(cubicMin, -0.05);
    EXPECT_GT(cubicMax, 1.05);
    // monotone across the step
    double prev = -1;
    for (double q = 3; q <= 4; q += 0.01)
    {
        const double v = akimaInterpolate(a, q, [&](std::size_t i) { return y[i]; });
        EXPECT_GE(v, prev - 1e-15);
        prev = v;
    }
}

TEST(Interpolation1D, AkimaReproducesNodesAndLinearData)
{
    const Axis a(kNonUniform);
    std::vector<double> y;
    for (double x : kNonUniform)
        y.push_back(4.0 + 0.5 * x);
    for (double q = -1.0; q <= 5.0; q += 0.0137)
        EXPECT_NEAR(akimaInterpolate(a, q, [&](std::size_t i) { return y[i]; }), 4.0 + 0.5 * q, 1e-12);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-1, 1);
    for (double &v : y)
        v = U(rng);
    for (std::size_t i = 0; i < y.size(); ++i)
        EXPECT_NEAR(akimaInterpolate(a, kNonUniform[i], [&](std::size_t k) { return y[k]; }), y[i], 1e-14);
}

TEST(Interpolation1D, OvershootFactorsBoundEveryInterpolant)
{
    // The factor must bound |interpolant| / max|data| for any data: check the Lebesgue function (cubic) and
    // random plus adversarial data (Akima).
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-1, 1);
    const std::vector<std::vector<double>> axes{kNonUniform, std::vector<double>{0, 1, 2, 3, 4, 5, 6}};
    for (const std::vector<double> &nodes : axes)
    {
        const Axis a(nodes);
        const double fc = overshootFactor(a, Interp1D::Cubic);
        const double fa = overshootFactor(a, Interp1D::Akima);
        EXPECT_EQ(overshootFactor(a, Interp1D::Linear), 1.0);
        EXPECT_EQ(overshootFactor(a, Interp1D::Nearest), 1.0);
        double lebesgue = 0;
        for (double q = nodes.front(); q <= nodes.back(); q += 1e-3)
        {
            const Stencil s = makeStencil(a, Interp1D::Cubic, q);
            double sum = 0;
            for (int i = 0; i < s.n; ++i)
                sum += std::abs(s.w[i]);
            lebesgue = std::max(lebesgue, sum);
        }
        EXPECT_LE(lebesgue, fc + 1e-12);
        EXPECT_GT(lebesgue, 1.1); // the cubic does overshoot
        std::vector<double> y(nodes.size());
        double worst = 0;
        for (int trial = 0; trial < 300; ++trial)
        {
            for (double &v : y)
                v = trial % 3 == 0 ? (U(rng) > 0 ? 1.0 : -1.0) : U(rng);
            double mx = 0;
            for (double v : y)
                mx = std::max(mx, std::abs(v));
            for (double q = nodes.front(); q <= nodes.back(); q += 0.01)
                worst = std::max(worst, std::abs(akimaInterpolate(a, q, [&](std::size_t i) { return y[i]; })) / mx);
        }
        EXPECT_LE(worst, fa);
    }
    // uniform interior of the cubic: exactly 1.25 at mid-interval
    const Axis u({0, 1, 2, 3, 4, 5, 6, 7, 8});
    EXPECT_GE(overshootFactor(u, Interp1D::Cubic), 1.25);
}

TEST(Interpolation1D, ParsesSchemeNames)
{
    EXPECT_EQ(parseInterp1D("Akima"), Interp1D::Akima);
    EXPECT_EQ(parseInterp1D("linear"), Interp1D::Linear);
    EXPECT_EQ(parseInterp2D("BICUBIC"), Interp2D::Bicubic);
    EXPECT_EQ(parseInterp2D("bilinear"), Interp2D::Bilinear);
    try
    {
        parseInterp2D("spline");
        FAIL();
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("spline"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("bicubic"), std::string::npos);
    }
    EXPECT_THROW(parseInterp1D("quintic"), Error);
}

// GriddedCurrentField built in memory: each scheme reproduces what it must exactly (bilinear: bilinear functions;
// bicubic: cubic polynomials; linear/cubic in depth and time), Akima in time has no overshoot at a tide-like step,
// curvilinear grids, land cells, the after-forecast policies, Jacobians and the speed bound.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <thread>
#include <functional>
#include <memory>
#include <random>

#include "ompl_glider/Exception.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/GriddedCurrentField.h"

using namespace ompl_glider;

namespace
{
using Fn = std::function<double(double x, double y, double z, double t)>;

const std::vector<double> kX{0.0, 0.3, 0.5, 1.0, 1.4, 1.5, 2.1, 2.6, 3.0};
const std::vector<double> kY{-1.0, -0.6, 0.0, 0.25, 0.9, 1.5, 2.0};

GriddedData sampleRect(const std::vector<double> &x, const std::vector<double> &y, const std::vector<double> &z,
                       const std::vector<double> &t, const Fn &fu, const Fn &fv)
{
    GriddedData d;
    d.nx = x.size();
    d.ny = y.size();
    d.x = x;
    d.y = y;
    d.depth = z;
    d.time = t;
    for (double tt : t)
        for (double zz : z)
            for (double yy : y)
                for (double xx : x)
                {
                    d.u.push_back(float(fu(xx, yy, zz, tt)));
                    d.v.push_back(float(fv(xx, yy, zz, tt)));
                }
    return d;
}

GriddedFieldOptions schemes(Interp2D xy, Interp1D z = Interp1D::Linear, Interp1D t = Interp1D::Linear)
{
    GriddedFieldOptions o;
    o.xy = xy;
    o.depth = z;
    o.time = t;
    return o;
}
} // namespace

TEST(GriddedField, BilinearReproducesBilinearFunctionsAndTheirJacobian)
{
    auto fu = [](double x, double y, double, double) { return 0.2 + 0.1 * x - 0.3 * y + 0.05 * x * y; };
    auto fv = [](double x, double y, double, double) { return -0.1 + 0.2 * x + 0.15 * y - 0.08 * x * y; };
    GriddedCurrentField f(sampleRect(kX, kY, {0.0}, {0.0}, fu, fv), schemes(Interp2D::Bilinear));
    EXPECT_FALSE(f.curvilinear());
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> X(0, 3), Y(-1, 2);
    for (int i = 0; i < 500; ++i)
    {
        const double x = X(rng), y = Y(rng);
        const Velocity c = f.velocity(x, y, 0, 0);
        EXPECT_NEAR(c.u, fu(x, y, 0, 0), 2e-7);
        EXPECT_NEAR(c.v, fv(x, y, 0, 0), 2e-7);
        const Jacobian J = f.jacobian(x, y, 0, 0);
        EXPECT_NEAR(J.ux, 0.1 + 0.05 * y, 1e-6);
        EXPECT_NEAR(J.uy, -0.3 + 0.05 * x, 1e-6);
        EXPECT_NEAR(J.vx, 0.2 - 0.08 * y, 1e-6);
        EXPECT_NEAR(J.vy, 0.15 - 0.08 * x, 1e-6);
    }
    // a quadratic is not reproduced between nodes (the test would catch a wrong scheme)
    auto fq = [](double x, double, double, double) { return x * x; };
    GriddedCurrentField q(sampleRect(kX, kY, {0.0}, {0.0}, fq, fq), schemes(Interp2D::Bilinear));
    EXPECT_GT(std::abs(q.velocity(1.2, 0, 0, 0).u - 1.44), 1e-3);
}

TEST(GriddedField, BicubicReproducesCubicPolynomialsAndTheirJacobian)
{
    auto fu = [](double x, double y, double, double) {
        return 0.1 + 0.2 * x - 0.1 * y + 0.05 * x * x * x - 0.04 * y * y * y + 0.03 * x * x * y -
               0.02 * x * x * x * y * y * y;
    };
    auto fv = [](double x, double y, double, double) { return -0.2 + 0.07 * x * y * y - 0.01 * x * x * x * y; };
    GriddedCurrentField f(sampleRect(kX, kY, {0.0}, {0.0}, fu, fv), schemes(Interp2D::Bicubic));
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> X(0, 3), Y(-1, 2);
    const double h = 1e-5;
    for (int i = 0; i < 500; ++i)
    {
        const double x = X(rng), y = Y(rng);
        const Velocity c = f.velocity(x, y, 0, 0);
        EXPECT_NEAR(c.u, fu(x, y, 0, 0), 5e-6) << x << " " << y;
        EXPECT_NEAR(c.v, fv(x, y, 0, 0), 5e-6);
        const Jacobian J = f.jacobian(x, y, 0, 0);
        EXPECT_NEAR(J.ux, (fu(x + h, y, 0, 0) - fu(x - h, y, 0, 0)) / (2 * h), 5e-5);
        EXPECT_NEAR(J.uy, (fu(x, y + h, 0, 0) - fu(x, y - h, 0, 0)) / (2 * h), 5e-5);
        EXPECT_NEAR(J.vx, (fv(x + h, y, 0, 0) - fv(x - h, y, 0, 0)) / (2 * h), 5e-5);
        EXPECT_NEAR(J.vy, (fv(x, y + h, 0, 0) - fv(x, y - h, 0, 0)) / (2 * h), 5e-5);
    }
}

TEST(GriddedField, NearestReturnsTheNearestNodeValue)
{
    auto fu = [](double x, double y, double, double) { return 10 * x + y; };
    GriddedCurrentField f(sampleRect(kX, kY, {0.0}, {0.0}, fu, fu), schemes(Interp2D::Nearest));
    EXPECT_NEAR(f.velocity(0.41, 0.2, 0, 0).u, fu(0.5, 0.25, 0, 0), 1e-6);
    EXPECT_NEAR(f.velocity(1.44, -0.7, 0, 0).u, fu(1.4, -0.6, 0, 0), 1e-6);
    const Jacobian J = f.jacobian(1.44, -0.7, 0, 0);
    EXPECT_EQ(J.ux, 0.0);
    EXPECT_EQ(J.vy, 0.0);
}

TEST(GriddedField, TimeAndDepthSchemesReproduceWhatTheyMust)
{
    const std::vector<double> z{0, 5, 20, 50, 100, 200};
    const std::vector<double> t{0, 1, 2.5, 3, 4.5, 6, 8};
    auto lin = [](double x, double y, double zz, double tt) { return 0.1 * x + 0.2 * y - 0.003 * zz + 0.05 * tt; };
    auto cub = [](double x, double y, double zz, double tt) {
        const double s = zz / 100.0;
        return 0.1 * x - 0.2 * y + 0.3 * s - 0.2 * s * s * s + 0.01 * tt * tt * tt - 0.05 * tt * tt;
    };
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> X(0, 3), Y(-1, 2), Z(0, 200), T(0, 8);
    for (Interp1D zs : {Interp1D::Linear, Interp1D::Cubic})
        for (Interp1D ts : {Interp1D::Linear, Interp1D::Cubic})
        {
            const Fn &fn = (zs == Interp1D::Cubic && ts == Interp1D::Cubic) ? Fn(cub) : Fn(lin);
            GriddedCurrentField f(sampleRect(kX, kY, z, t, fn, lin), schemes(Interp2D::Bilinear, zs, ts));
            for (int i = 0; i < 300; ++i)
            {
                const double x = X(rng), y = Y(rng), zz = Z(rng), tt = T(rng);
                EXPECT_NEAR(f.velocity(x, y, zz, tt).u, fn(x, y, zz, tt), 3e-6)
                    << toString(zs) << "/" << toString(ts) << " z " << zz << " t " << tt;
                EXPECT_NEAR(f.velocity(x, y, zz, tt).v, lin(x, y, zz, tt), 3e-6);
            }
        }
    // linear in time does not reproduce the cubic in time
    GriddedCurrentField f(sampleRect(kX, kY, z, t, cub, cub),
                          schemes(Interp2D::Bilinear, Interp1D::Cubic, Interp1D::Linear));
    EXPECT_GT(std::abs(f.velocity(1, 1, 10, 5.2).u - cub(1, 1, 10, 5.2)), 1e-4);
    // nearest in time and depth
    GriddedCurrentField n(sampleRect(kX, kY, z, t, lin, lin),
                          schemes(Interp2D::Bilinear, Interp1D::Nearest, Interp1D::Nearest));
    EXPECT_NEAR(n.velocity(1, 1, 14, 2.7).u, lin(1, 1, 20, 2.5), 1e-6);
    // Akima reproduces linear data in depth and time
    GriddedCurrentField a(sampleRect(kX, kY, z, t, lin, lin),
                          schemes(Interp2D::Bilinear, Interp1D::Akima, Interp1D::Akima));
    for (int i = 0; i < 200; ++i)
    {
        const double x = X(rng), y = Y(rng), zz = Z(rng), tt = T(rng);
        EXPECT_NEAR(a.velocity(x, y, zz, tt).u, lin(x, y, zz, tt), 3e-6);
    }
}

TEST(GriddedField, AkimaInTimeHasNoOvershootAtATideLikeStep)
{
    auto step = [](double, double, double, double tt) { return tt < 3.5 ? 0.0 : 1.0; };
    const std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7};
    GriddedCurrentField ak(sampleRect({0, 1}, {0, 1}, {0}, t, step, step),
                           schemes(Interp2D::Bilinear, Interp1D::Linear, Interp1D::Akima));
    GriddedCurrentField cu(sampleRect({0, 1}, {0, 1}, {0}, t, step, step),
                           schemes(Interp2D::Bilinear, Interp1D::Linear, Interp1D::Cubic));
    double cmin = 0;
    for (double tt = 0; tt <= 7; tt += 0.01)
    {
        const double v = ak.velocity(0.5, 0.5, 0, tt).u;
        EXPECT_GE(v, -1e-7);
        EXPECT_LE(v, 1 + 1e-7);
        cmin = std::min(cmin, cu.velocity(0.5, 0.5, 0, tt).u);
    }
    EXPECT_LT(cmin, -0.05); // the cubic wiggles
}

TEST(GriddedField, CurvilinearRotatedGridReproducesPolynomialsInXY)
{
    // An affine (rotated, sheared) mesh: index space is affine in x/y, so bilinear reproduces linear functions
    // of x, y and bicubic reproduces cubic polynomials of x, y.
    const std::size_t nx = 9, ny = 7;
    GriddedData d;
    d.nx = nx;
    d.ny = ny;
    const double th = 0.4;
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
        {
            d.nodeX.push_back(100.0 + 50.0 * (i * std::cos(th) - 0.8 * j * std::sin(th)));
            d.nodeY.push_back(-20.0 + 50.0 * (i * std::sin(th) + 0.8 * j * std::cos(th)) + 3.0 * i);
        }
    auto lin = [](double x, double y) { return 0.3 + 0.002 * x - 0.001 * y; };
    auto cub = [](double x, double y) {
        const double a = x / 500.0, b = y / 500.0;
        return 0.1 + 0.2 * a * a * a - 0.1 * a * b * b + 0.05 * b * b * b - 0.3 * a * b;
    };
    for (Interp2D s : {Interp2D::Bilinear, Interp2D::Bicubic})
    {
        GriddedData dd = d;
        for (std::size_t n = 0; n < nx * ny; ++n)
        {
            dd.u.push_back(float(s == Interp2D::Bilinear ? lin(d.nodeX[n], d.nodeY[n]) : cub(d.nodeX[n], d.nodeY[n])));
            dd.v.push_back(float(lin(d.nodeX[n], d.nodeY[n])));
        }
        GriddedCurrentField f(dd, schemes(s));
        EXPECT_TRUE(f.curvilinear());
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> A(0, nx - 1), B(0, ny - 1);
        for (int k = 0; k < 300; ++k)
        {
            // a point inside the mesh: affine map of random index coordinates
            const double fi = A(rng), fj = B(rng);
            const double x = 100.0 + 50.0 * (fi * std::cos(th) - 0.8 * fj * std::sin(th));
            const double y = -20.0 + 50.0 * (fi * std::sin(th) + 0.8 * fj * std::cos(th)) + 3.0 * fi;
            double gi, gj;
            ASSERT_TRUE(f.locate(x, y, gi, gj));
            EXPECT_NEAR(gi, fi, 1e-9);
            EXPECT_NEAR(gj, fj, 1e-9);
            EXPECT_TRUE(f.inWater(x, y, 0));
            const double expect = s == Interp2D::Bilinear ? lin(x, y) : cub(x, y);
            EXPECT_NEAR(f.velocity(x, y, 0, 0).u, expect, 2e-6);
            const Jacobian J = f.jacobian(x, y, 0, 0);
            EXPECT_NEAR(J.vx, 0.002, 1e-7);
            EXPECT_NEAR(J.vy, -0.001, 1e-7);
            if (s == Interp2D::Bicubic)
            {
                const double h = 1e-3;
                EXPECT_NEAR(J.ux, (cub(x + h, y) - cub(x - h, y)) / (2 * h), 1e-6);
                EXPECT_NEAR(J.uy, (cub(x, y + h) - cub(x, y - h)) / (2 * h), 1e-6);
            }
        }
        double gi, gj;
        EXPECT_FALSE(f.locate(-500, -500, gi, gj));
        EXPECT_FALSE(f.inWater(-500, -500, 0));
        EXPECT_FALSE(f.inWater(5000, 0, 0));
    }
}

TEST(GriddedField, CurvilinearLocateInvertsACurvedMesh)
{
    // A polar sector mesh (cells are genuine quadrilaterals, not parallelograms).
    const std::size_t nx = 30, ny = 12;
    GriddedData d;
    d.nx = nx;
    d.ny = ny;
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
        {
            const double r = 1000.0 + 100.0 * j, a = 0.05 * i;
            d.nodeX.push_back(r * std::cos(a));
            d.nodeY.push_back(r * std::sin(a));
        }
    d.u.assign(nx * ny, 0.1f);
    d.v.assign(nx * ny, 0.0f);
    GriddedCurrentField f(d);
    std::mt19937 rng(6);
    std::uniform_real_distribution<double> A(0, nx - 1), B(0, ny - 1);
    for (int k = 0; k < 500; ++k)
    {
        const double fi = A(rng), fj = B(rng);
        const std::size_t ci = std::min<std::size_t>(std::size_t(fi), nx - 2),
                          cj = std::min<std::size_t>(std::size_t(fj), ny - 2);
        const double a = fi - ci, b = fj - cj;
        auto X = [&](std::size_t i, std::size_t j) { return d.nodeX[j * nx + i]; };
        auto Y = [&](std::size_t i, std::size_t j) { return d.nodeY[j * nx + i]; };
        const double x = (1 - a) * (1 - b) * X(ci, cj) + a * (1 - b) * X(ci + 1, cj) + (1 - a) * b * X(ci, cj + 1) +
                         a * b * X(ci + 1, cj + 1);
        const double y = (1 - a) * (1 - b) * Y(ci, cj) + a * (1 - b) * Y(ci + 1, cj) + (1 - a) * b * Y(ci, cj + 1) +
                         a * b * Y(ci + 1, cj + 1);
        double gi, gj;
        ASSERT_TRUE(f.locate(x, y, gi, gj));
        EXPECT_NEAR(gi, fi, 1e-8);
        EXPECT_NEAR(gj, fj, 1e-8);
    }
    double gi, gj;
    EXPECT_FALSE(f.locate(0, 0, gi, gj)); // inside the inner radius: not in the mesh
}

TEST(GriddedField, LandCellsAreDryAndNeverLeakFillValues)
{
    const std::vector<double> x{0, 1, 2, 3, 4}, y{0, 1, 2, 3, 4};
    auto fu = [](double, double, double, double) { return 0.4; };
    auto fv = [](double, double, double, double) { return -0.2; };
    GriddedData d = sampleRect(x, y, {0, 10}, {0, 1}, fu, fv);
    const std::size_t nh = 25;
    d.water.assign(2 * nh, 1);
    d.water[2 * 5 + 2] = 0; // land node (i 2, j 2) at the surface layer (and below)
    d.water[nh + 2 * 5 + 2] = 0;
    d.water[nh + 0] = 0; // land only at depth 10: node (0, 0)
    // fill values in the data at the land nodes
    for (std::size_t it = 0; it < 2; ++it)
    {
        d.u[(it * 2 + 0) * nh + 12] = 1e20f;
        d.u[(it * 2 + 1) * nh + 12] = std::nanf("");
        d.v[(it * 2 + 1) * nh + 0] = -30000.f;
    }
    GriddedCurrentField f(d);
    // the four cells around node (2, 2) are dry, the others wet
    EXPECT_FALSE(f.inWater(1.5, 1.5, 0));
    EXPECT_FALSE(f.inWater(2.5, 1.5, 0));
    EXPECT_FALSE(f.inWater(1.5, 2.5, 0));
    EXPECT_FALSE(f.inWater(2.5, 2.5, 0));
    EXPECT_TRUE(f.inWater(3.5, 3.5, 0));
    EXPECT_TRUE(f.inWater(0.5, 2.5, 0));
    // node (0, 0) is land only at 10 m: its cell is wet at 0 m, dry at 10 m and in between
    EXPECT_TRUE(f.inWater(0.5, 0.5, 0));
    EXPECT_FALSE(f.inWater(0.5, 0.5, 10));
    EXPECT_FALSE(f.inWater(0.5, 0.5, 5));
    // land nodes count as zero current: no fill value, no NaN
    EXPECT_NEAR(f.velocity(2, 2, 0, 0.5).u, 0.0, 1e-12);
    EXPECT_NEAR(f.velocity(1.5, 2, 0, 0.5).u, 0.2, 1e-6); // half way to the land node
    EXPECT_NEAR(f.velocity(1, 1, 0, 0.5).u, 0.4, 1e-6);   // water node next to land
    for (double xx = 0; xx <= 4; xx += 0.05)
        for (double yy = 0; yy <= 4; yy += 0.05)
            for (double zz : {0.0, 4.0, 10.0})
            {
                const Velocity c = f.velocity(xx, yy, zz, 0.3);
                ASSERT_TRUE(std::isfinite(c.u) && std::isfinite(c.v));
                ASSERT_LE(std::hypot(c.u, c.v), f.maxSpeed(Region{}));
            }
    // travel time code: a leg ending on land is infeasible, one in open water feasible
    TravelTimeParams p;
    p.speed = 1.0;
    GriddedFieldOptions hold;
    hold.beyond = BeyondForecast::HoldLast;
    TravelTimeCalculator tt(std::make_shared<GriddedCurrentField>(d, hold), p);
    EXPECT_TRUE(std::isinf(tt.travelTime(3.5, 3.5, 2.2, 2.2, 0.0)));
    EXPECT_TRUE(std::isfinite(tt.travelTime(3.5, 3.5, 3.5, 0.5, 0.0)));
    // whole legs: across the land node no, around it yes; a thin strip between water nodes is caught
    EXPECT_FALSE(f.segmentInWater(0.5, 0.5, 3.5, 3.5, 0));
    EXPECT_TRUE(f.segmentInWater(0.5, 3.5, 3.5, 3.5, 0));
    EXPECT_TRUE(f.segmentInWater(3.5, 0.5, 3.5, 3.5, 0));
    EXPECT_FALSE(f.segmentInWater(0.5, 0.5, 0.6, 0.6, 10));
    // non-finite data at a water node is an error
    GriddedData bad = sampleRect(x, y, {0}, {0}, fu, fv);
    bad.u[7] = std::nanf("");
    EXPECT_THROW(GriddedCurrentField{bad}, Error);
}

TEST(GriddedField, LegClippingTheCornerOfALandCellIsRefusedHoweverSmallTheClip)
{
    // unit cells on 0..10 x 0..10; node (5, 5) is land, so the four cells around it are dry: the dry square is
    // [4, 6] x [4, 6]
    std::vector<double> ax(11);
    for (int i = 0; i <= 10; ++i)
        ax[i] = i;
    auto zero = [](double, double, double, double) { return 0.0; };
    GriddedData d = sampleRect(ax, ax, {0}, {0}, zero, zero);
    d.water.assign(121, 1);
    d.water[5 * 11 + 5] = 0;
    const GriddedCurrentField f(d);
    // legs along x + y = 12 - e, from (4 - e, 8) to (8, 4 - e), both ends in water: they cut a triangle with legs
    // of length e off the square's corner (6, 6), a piece of length e * sqrt(2) (1.4e-7 for the smallest e, far
    // below any sampling step); the same legs along x + y = 12 + e miss the square
    for (double e : {0.1, 1e-2, 1e-4, 1e-7})
    {
        EXPECT_FALSE(f.segmentInWater(4.0 - e, 8.0, 8.0, 4.0 - e, 0)) << "e " << e;
        EXPECT_TRUE(f.segmentInWater(4.0 + e, 8.0, 8.0, 4.0 + e, 0)) << "e " << e;
    }
    // a leg one cell above the dry square passes; one through it does not
    EXPECT_TRUE(f.segmentInWater(0.5, 6.5, 9.5, 6.5, 0));
    EXPECT_FALSE(f.segmentInWater(0.5, 5.5, 9.5, 5.5, 0));
}

TEST(GriddedField, ExactLegCheckAgreesWithDenseSamplingOnACurvilinearCoast)
{
    // a rotated, sheared curvilinear grid with a random coast (about 30 % land nodes at two depths); legs of 0.3 to
    // 4 cells in random directions: whenever a dense sampling (every 1/2000 of the leg) finds a dry point the exact
    // check refuses the leg, and whenever the exact check refuses a leg with both ends in water a sampling every
    // 1e-6 of the leg finds the dry point (or the clipped piece is shorter than that)
    const std::size_t nx = 24, ny = 18;
    GriddedData d;
    d.nx = nx;
    d.ny = ny;
    d.depth = {0.0, 20.0};
    d.time = {0.0};
    const double a = 0.3;
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
        {
            const double u = double(i) + 0.15 * std::sin(0.7 * double(j)), v = double(j) + 0.1 * double(i);
            d.nodeX.push_back(std::cos(a) * u - std::sin(a) * v);
            d.nodeY.push_back(std::sin(a) * u + std::cos(a) * v);
        }
    d.u.assign(2 * nx * ny, 0.1f);
    d.v.assign(2 * nx * ny, 0.0f);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    d.water.assign(2 * nx * ny, 1);
    for (auto &w : d.water)
        w = U(rng) < 0.12 ? 0 : 1;
    const GriddedCurrentField f(d);
    int refused = 0, refusedThinClip = 0, agreedTrue = 0;
    for (int n = 0; n < 3000; ++n)
    {
        const double fi = 1.0 + U(rng) * double(nx - 3), fj = 1.0 + U(rng) * double(ny - 3);
        const std::size_t i = static_cast<std::size_t>(fi), j = static_cast<std::size_t>(fj);
        const double x1 = d.nodeX[j * nx + i] + (fi - double(i)) * 0.9,
                     y1 = d.nodeY[j * nx + i] + (fj - double(j)) * 0.9;
        const double len = 0.3 + 3.7 * U(rng), th = 6.283185307179586 * U(rng);
        const double x2 = x1 + len * std::cos(th), y2 = y1 + len * std::sin(th);
        const double z = U(rng) < 0.5 ? 0.0 : 10.0;
        if (!f.inWater(x1, y1, z) || !f.inWater(x2, y2, z))
        {
            EXPECT_FALSE(f.segmentInWater(x1, y1, x2, y2, z));
            continue;
        }
        auto dryAt = [&](int samples) {
            for (int k = 1; k < samples; ++k)
            {
                const double s = double(k) / samples;
                if (!f.inWater(x1 + s * (x2 - x1), y1 + s * (y2 - y1), z))
                    return true;
            }
            return false;
        };
        const bool exact = f.segmentInWater(x1, y1, x2, y2, z);
        if (exact)
        {
            ASSERT_FALSE(dryAt(2000)) << "leg " << x1 << "," << y1 << " -> " << x2 << "," << y2 << " z " << z;
            ++agreedTrue;
        }
        else
        {
            ++refused;
            if (!dryAt(1000000))
                ++refusedThinClip;
        }
    }
    EXPECT_GT(agreedTrue, 300);
    EXPECT_GT(refused, 100);
    EXPECT_LE(refusedThinClip, refused / 1000) << "refused legs without a dry point at 1e-6 spacing";
}

TEST(GriddedField, AfterTheLastForecastHoldOrRefuse)
{
    auto fu = [](double, double, double, double t) { return 0.1 + 0.1 * t; };
    auto fv = [](double, double, double, double) { return 0.0; };
    GriddedData d = sampleRect({0, 100, 200}, {0, 100}, {0}, {0, 10, 20}, fu, fv);
    GriddedFieldOptions hold;
    hold.beyond = BeyondForecast::HoldLast;
    GriddedFieldOptions refuse;
    refuse.beyond = BeyondForecast::Refuse;
    auto h = std::make_shared<GriddedCurrentField>(d, hold);
    auto r = std::make_shared<GriddedCurrentField>(d, refuse);
    EXPECT_EQ(r->timeBegin(), 0.0);
    EXPECT_EQ(r->timeEnd(), 20.0);
    EXPECT_TRUE(std::isinf(h->timeEnd()));
    EXPECT_NEAR(h->velocity(50, 50, 0, 35).u, 2.1, 1e-6); // held last field
    TravelTimeParams p;
    p.speed = 1.0;
    // 200 m at about 3 m/s from t = 15 needs the field until about t = 80
    EXPECT_TRUE(std::isfinite(TravelTimeCalculator(h, p).travelTime(0, 50, 200, 50, 15)));
    EXPECT_TRUE(std::isinf(TravelTimeCalculator(r, p).travelTime(0, 50, 200, 50, 15)));
    EXPECT_TRUE(std::isfinite(TravelTimeCalculator(r, p).travelTime(0, 50, 20, 50, 0)));
}

TEST(GriddedField, SpeedBoundHoldsForEverySchemeCombination)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    const std::vector<double> z{0, 10, 30, 60, 100}, t{0, 1, 2, 3, 4, 5};
    Fn noise = [&](double, double, double, double) { return U(rng) > 0 ? 1.0 : -1.0; }; // adversarial +-1
    GriddedData d = sampleRect(kX, kY, z, t, noise, noise);
    double nodeMax = 0;
    for (std::size_t n = 0; n < d.u.size(); ++n)
        nodeMax = std::max(nodeMax, std::hypot(double(d.u[n]), double(d.v[n])));
    std::uniform_real_distribution<double> X(0, 3), Y(-1, 2), Z(0, 100), T(0, 5);
    for (Interp2D xy : {Interp2D::Nearest, Interp2D::Bilinear, Interp2D::Bicubic})
        for (Interp1D zs : {Interp1D::Nearest, Interp1D::Linear, Interp1D::Cubic, Interp1D::Akima})
            for (Interp1D ts : {Interp1D::Nearest, Interp1D::Linear, Interp1D::Cubic, Interp1D::Akima})
            {
                GriddedCurrentField f(d, schemes(xy, zs, ts));
                const double bound = f.maxSpeed(Region{});
                double seen = 0;
                for (int i = 0; i < 3000; ++i)
                {
                    const Velocity c = f.velocity(X(rng), Y(rng), Z(rng), T(rng));
                    seen = std::max(seen, std::hypot(c.u, c.v));
                }
                EXPECT_LE(seen, bound) << toString(xy) << "/" << toString(zs) << "/" << toString(ts);
                if (xy != Interp2D::Bicubic && zs != Interp1D::Cubic && zs != Interp1D::Akima &&
                    ts != Interp1D::Cubic && ts != Interp1D::Akima)
                {
                    EXPECT_NEAR(bound, nodeMax, 1e-6); // tight for convex schemes
                }
            }
}

TEST(GriddedField, DataDependentSpeedBoundIsTightForSmoothDataAndStillHolds)
{
    // Uneven depth layers and Akima/cubic schemes inflate the product of overshoot factors; the bound from the
    // stencil diameters stays near the node maximum for smooth data, and holds for rough data too.
    const std::vector<double> z{0, 50, 200}, t{0, 1, 2, 3, 4, 5, 6, 7};
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> X(0, 3), Y(-1, 2), Z(0, 200), T(0, 7), U(-1, 1);
    // smooth on the scale of the stencils (a few per cent change across a box); the rough set adds random jumps
    auto smooth = [](double x, double y, double zz, double tt) {
        return 0.2 + 0.5 * std::sin(0.1 * x + 0.02 * tt) * std::cos(0.1 * y) * (1.0 - zz / 4000.0);
    };
    auto smoothV = [](double x, double y, double, double tt) { return 0.3 * std::cos(0.1 * x - 0.05 * y + 0.02 * tt); };
    Fn rough = [&](double x, double y, double zz, double tt) {
        return smooth(x, y, zz, tt) + (U(rng) > 0.7 ? 0.8 : 0.0);
    };
    for (int dataset = 0; dataset < 2; ++dataset)
    {
        const GriddedData d =
            dataset == 0 ? sampleRect(kX, kY, z, t, smooth, smoothV) : sampleRect(kX, kY, z, t, rough, smoothV);
        double nodeMax = 0;
        for (std::size_t n = 0; n < d.u.size(); ++n)
            nodeMax = std::max(nodeMax, std::hypot(double(d.u[n]), double(d.v[n])));
        for (Interp2D xy : {Interp2D::Bilinear, Interp2D::Bicubic})
            for (Interp1D zs : {Interp1D::Linear, Interp1D::Cubic, Interp1D::Akima})
                for (Interp1D ts : {Interp1D::Linear, Interp1D::Cubic, Interp1D::Akima})
                {
                    GriddedCurrentField f(d, schemes(xy, zs, ts));
                    const double bound = f.maxSpeed(Region{});
                    double seen = 0;
                    for (int i = 0; i < 4000; ++i)
                    {
                        const Velocity c = f.velocity(X(rng), Y(rng), Z(rng), T(rng));
                        seen = std::max(seen, std::hypot(c.u, c.v));
                    }
                    EXPECT_LE(seen, bound)
                        << dataset << " " << toString(xy) << "/" << toString(zs) << "/" << toString(ts);
                    EXPECT_GE(bound, nodeMax);
                    if (dataset == 0 && f.overshoot() > 1.5)
                    {
                        // tighter than the product of overshoot factors (which is loose on these uneven axes)
                        EXPECT_LT(bound, 0.75 * f.overshoot() * nodeMax)
                            << toString(xy) << "/" << toString(zs) << "/" << toString(ts);
                    }
                }
        if (dataset == 0)
        {
            GriddedCurrentField f(d, schemes(Interp2D::Bicubic, Interp1D::Akima, Interp1D::Akima));
            EXPECT_GT(f.overshoot(), 3.0); // the product alone would be loose
            EXPECT_LT(f.maxSpeed(Region{}), 0.5 * f.overshoot() * nodeMax);
        }
    }
}

TEST(GriddedField, SpeedBoundOfATimeWindowCoversItsStencil)
{
    // speed grows with time and with depth: the bound of [0, 2] is smaller than the global one but still holds
    // for every query in [0, 2] at every depth (the region's depth range is ignored on purpose)
    auto fu = [](double, double, double z, double t) { return 0.1 * (1.0 + t) * (1.0 + 0.01 * z); };
    auto fv = [](double, double, double, double) { return 0.0; };
    const std::vector<double> t = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    for (Interp1D ts : {Interp1D::Linear, Interp1D::Cubic, Interp1D::Akima})
    {
        GriddedCurrentField f(sampleRect(kX, kY, {0, 50, 100}, t, fu, fv),
                              schemes(Interp2D::Bilinear, Interp1D::Linear, ts));
        Region w;
        w.tMin = 0;
        w.tMax = 2; // zMin = zMax = 0
        const double bw = f.maxSpeed(w), bg = f.maxSpeed(Region{});
        EXPECT_LT(bw, bg);
        for (double tt = 0; tt <= 2; tt += 0.01)
            EXPECT_LE(f.velocity(1.0, 0.5, 100.0, tt).u, bw);
    }
}

TEST(GriddedField, JacobianMatchesFiniteDifferencesForEverySchemeCombination)
{
    auto fu = [](double x, double y, double z, double t) { return std::sin(x) * std::cos(y) + 0.01 * z * std::cos(t); };
    auto fv = [](double x, double y, double z, double t) { return std::cos(1.3 * x + 0.5 * y) - 0.005 * z * t; };
    const std::vector<double> z{0, 10, 30, 60, 100}, t{0, 1, 2, 3, 4, 5};
    const GriddedData d = sampleRect(kX, kY, z, t, fu, fv);
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> C(0.1, 0.9), Z(0, 100), T(0, 5);
    std::uniform_int_distribution<std::size_t> I(0, kX.size() - 2), J(0, kY.size() - 2);
    for (Interp2D xy : {Interp2D::Bilinear, Interp2D::Bicubic})
        for (Interp1D zs : {Interp1D::Linear, Interp1D::Cubic, Interp1D::Akima})
            for (Interp1D ts : {Interp1D::Linear, Interp1D::Akima})
            {
                GriddedCurrentField f(d, schemes(xy, zs, ts));
                for (int k = 0; k < 100; ++k)
                {
                    // points well inside a cell (the interpolant is smooth there)
                    const std::size_t i = I(rng), j = J(rng);
                    const double x = kX[i] + C(rng) * (kX[i + 1] - kX[i]), y = kY[j] + C(rng) * (kY[j + 1] - kY[j]);
                    const double zz = Z(rng), tt = T(rng), h = 1e-5;
                    const Jacobian Jc = f.jacobian(x, y, zz, tt);
                    const Velocity xp = f.velocity(x + h, y, zz, tt), xm = f.velocity(x - h, y, zz, tt);
                    const Velocity yp = f.velocity(x, y + h, zz, tt), ym = f.velocity(x, y - h, zz, tt);
                    EXPECT_NEAR(Jc.ux, (xp.u - xm.u) / (2 * h), 2e-3);
                    EXPECT_NEAR(Jc.uy, (yp.u - ym.u) / (2 * h), 2e-3);
                    EXPECT_NEAR(Jc.vx, (xp.v - xm.v) / (2 * h), 2e-3);
                    EXPECT_NEAR(Jc.vy, (yp.v - ym.v) / (2 * h), 2e-3);
                }
            }
}

TEST(GriddedField, ThreadsQueryingACurvilinearGridGetTheSameAnswers)
{
    // The point locator keeps a per-thread hint: concurrent queries (and several fields) must not disturb it.
    const std::size_t nx = 40, ny = 30;
    GriddedData d;
    d.nx = nx;
    d.ny = ny;
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
        {
            const double r = 1000.0 + 50.0 * j, a = 0.02 * i;
            d.nodeX.push_back(r * std::cos(a));
            d.nodeY.push_back(r * std::sin(a));
            d.u.push_back(float(std::sin(0.3 * i) + 0.1 * j));
            d.v.push_back(float(std::cos(0.2 * j)));
        }
    GriddedCurrentField f1(d), f2(d, schemes(Interp2D::Bicubic));
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> R(1000, 2450), A(0, 0.78);
    std::vector<std::array<double, 2>> pts(4000);
    for (auto &p : pts)
    {
        const double r = R(rng), a = A(rng);
        p = {r * std::cos(a), r * std::sin(a)};
    }
    std::vector<double> ref;
    for (const auto &p : pts)
        ref.push_back(f1.velocity(p[0], p[1], 0, 0).u + f2.velocity(p[0], p[1], 0, 0).v);
    f1.resetCallCount();
    std::vector<std::thread> th;
    std::atomic<int> mismatches{0};
    for (int k = 0; k < 4; ++k)
        th.emplace_back([&, k] {
            for (std::size_t n = 0; n < pts.size(); ++n)
            {
                const std::size_t q = (n * (k + 1) * 7919) % pts.size();
                const double val =
                    f1.velocity(pts[q][0], pts[q][1], 0, 0).u + f2.velocity(pts[q][0], pts[q][1], 0, 0).v;
                if (std::abs(val - ref[q]) > 1e-12)
                    ++mismatches;
            }
        });
    for (auto &t : th)
        t.join();
    EXPECT_EQ(mismatches.load(), 0);
    EXPECT_EQ(f1.callCount(), 4 * pts.size());
}

TEST(GriddedField, CountsOneCallPerQueryAndValidatesItsData)
{
    auto fu = [](double, double, double, double) { return 0.1; };
    GriddedCurrentField f(sampleRect(kX, kY, {0}, {0}, fu, fu));
    f.resetCallCount();
    f.velocity(1, 1, 0, 0);
    f.jacobian(1, 1, 0, 0);
    f.inWater(1, 1, 0);
    f.maxSpeed(Region{});
    EXPECT_EQ(f.callCount(), 2u);
    GriddedData d = sampleRect(kX, kY, {0}, {0}, fu, fu);
    d.u.pop_back();
    try
    {
        GriddedCurrentField g(d);
        FAIL();
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("velocity values"), std::string::npos) << e.what();
    }
    GriddedData e = sampleRect(kX, kY, {0}, {0}, fu, fu);
    e.x[3] = e.x[2];
    EXPECT_THROW(GriddedCurrentField{e}, Error);
    EXPECT_EQ(parseBeyondForecast("Hold"), BeyondForecast::HoldLast);
    EXPECT_EQ(parseBeyondForecast("refuse"), BeyondForecast::Refuse);
    EXPECT_THROW(parseBeyondForecast("extrapolate"), Error);
}

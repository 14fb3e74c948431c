// LocalProjection (PROJ aeqd on WGS84): round trip, exact distances from the reference point, the stated bound
// on planar-vs-geodesic distance over a 500 km region, and the east/north directions used to rotate currents.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LocalProjection.h"

using namespace ompl_glider;

TEST(LocalProjection, RoundTripIsExactToAMicrometre)
{
    for (auto [lon0, lat0] :
         {std::pair{-52.0, 47.5}, {170.0, -40.0}, {0.0, 0.0}, {-179.5, 60.0}, {179.9, -10.0}, {185.0, 20.0}})
    {
        const LocalProjection p(lon0, lat0);
        const Point2 o = p.forward(lon0, lat0);
        EXPECT_NEAR(o.x, 0.0, 1e-6);
        EXPECT_NEAR(o.y, 0.0, 1e-6);
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> U(-300e3, 300e3);
        for (int i = 0; i < 200; ++i)
        {
            const double px = U(rng), py = U(rng);
            const LonLat g = p.inverse(px, py);
            // every longitude out is in -180..180, whatever the reference (300 km from 179.9E is past the
            // antimeridian for half the points)
            EXPECT_GE(g.lon, -180.0);
            EXPECT_LT(g.lon, 180.0);
            const Point2 q = p.forward(g.lon, g.lat);
            EXPECT_NEAR(q.x, px, 1e-6);
            EXPECT_NEAR(q.y, py, 1e-6);
            // longitudes in another convention give the same point
            EXPECT_NEAR(p.forward(g.lon + 360.0, g.lat).x, px, 1e-6);
            EXPECT_NEAR(p.forward(g.lon - 720.0, g.lat).y, py, 1e-6);
        }
        // a position written in 0..360 and in -180..180 is the same point to the last bit
        for (double lon = std::round(lon0) - 2.0; lon <= std::round(lon0) + 2.0; lon += 0.25) // grid values
        {
            const double west = normalizeLongitude(lon), east = west < 0 ? west + 360.0 : west;
            const Point2 a = p.forward(west, lat0 + 0.5), b = p.forward(east, lat0 + 0.5);
            EXPECT_EQ(a.x, b.x) << lon;
            EXPECT_EQ(a.y, b.y) << lon;
        }
    }
    EXPECT_THROW(LocalProjection(0.0, 95.0), Error);
}

TEST(LocalProjection, NormalizeLongitudeIsExactAndHalfOpen)
{
    EXPECT_EQ(normalizeLongitude(185.0), -175.0);
    EXPECT_EQ(normalizeLongitude(180.0), -180.0);
    EXPECT_EQ(normalizeLongitude(-180.0), -180.0);
    EXPECT_EQ(normalizeLongitude(360.0), 0.0);
    EXPECT_EQ(normalizeLongitude(359.75), -0.25);
    EXPECT_EQ(normalizeLongitude(-190.0), 170.0);
    EXPECT_EQ(normalizeLongitude(540.0), -180.0);
    EXPECT_EQ(normalizeLongitude(-52.7), -52.7);
    // a grid longitude in 0..360 and the same in -180..180 are the same double; any other within a unit of the
    // last place of 360 (the rounding of l + 360 itself)
    for (double l = -179.75; l < 180.0; l += 0.25)
        EXPECT_EQ(normalizeLongitude(l + 360.0), normalizeLongitude(l)) << l;
    for (double l = -179.95; l < 180.0; l += 0.37)
        EXPECT_NEAR(normalizeLongitude(l + 360.0), l, 6e-14) << l;
    EXPECT_TRUE(std::isnan(normalizeLongitude(std::nan(""))));
}

TEST(LocalProjection, PlanarDistancesWithinTheStatedBoundOver500km)
{
    // Distances from the reference point are geodesic (equidistant); between two points within 250 km of it the
    // planar distance differs from the geodesic by less than d^2 / (6 R^2) ~ 2.6e-4 relative (bound checked: 5e-4).
    const LocalProjection p(-52.0, 47.5);
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> R(0, 250e3), A(0, 2 * M_PI);
    double worst = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const double r1 = R(rng), a1 = A(rng), r2 = R(rng), a2 = A(rng);
        const double x1 = r1 * std::cos(a1), y1 = r1 * std::sin(a1), x2 = r2 * std::cos(a2), y2 = r2 * std::sin(a2);
        const LonLat g1 = p.inverse(x1, y1), g2 = p.inverse(x2, y2);
        // from the reference point: exact
        EXPECT_NEAR(std::hypot(x1, y1), p.geodesicDistance(p.lon0(), p.lat0(), g1.lon, g1.lat), 1e-3);
        const double planar = std::hypot(x2 - x1, y2 - y1);
        if (planar < 1e3)
            continue;
        const double geo = p.geodesicDistance(g1.lon, g1.lat, g2.lon, g2.lat);
        worst = std::max(worst, std::abs(planar - geo) / geo);
    }
    EXPECT_LT(worst, 5e-4);
    EXPECT_GT(worst, 1e-5); // the plane is an approximation: the check is not vacuous
}

TEST(LocalProjection, ErrorBudgetOverA70DegreeTripAt40S)
{
    // The trip region of 35W..35E at 40S is centred on (0, 40S); start and goal lie 2969 km from the reference
    // point. Radial distances stay exact; distances across the radius are stretched by k = t / sin t, t = rho / R
    // (1.037 at 2969 km, 1 + rho^2 / (6 R^2)): the bound on any leg within rho of the reference point.
    const LocalProjection p(0.0, -40.0);
    const double R = 6371.0088e3;
    auto k = [&](double rho) { return (rho / R) / std::sin(rho / R); };
    const Point2 a = p.forward(-35.0, -40.0), b = p.forward(35.0, -40.0);
    EXPECT_NEAR(std::hypot(a.x, a.y), 2969.2e3, 0.1e3);
    // radial and tangential 10 km legs at the start
    const double r = std::hypot(a.x, a.y), ux = a.x / r, uy = a.y / r;
    auto geodesic = [&](double x0, double y0, double x1, double y1) {
        const LonLat g0 = p.inverse(x0, y0), g1 = p.inverse(x1, y1);
        return p.geodesicDistance(g0.lon, g0.lat, g1.lon, g1.lat);
    };
    EXPECT_NEAR(1e4 / geodesic(a.x - 5e3 * ux, a.y - 5e3 * uy, a.x + 5e3 * ux, a.y + 5e3 * uy), 1.0, 1e-4);
    const double tangential = 1e4 / geodesic(a.x + 5e3 * uy, a.y - 5e3 * ux, a.x - 5e3 * uy, a.y + 5e3 * ux);
    EXPECT_NEAR(tangential, k(r), 3e-3); // 1.0371 (the ellipsoid against the sphere's 1.0374)
    // the straight planar leg from start to goal: 0.16 % longer in the plane than the geodesic, and flown on the
    // ellipsoid (its points inverted) within 0.02 % of the geodesic
    const double planar = std::hypot(b.x - a.x, b.y - a.y), geo = p.geodesicDistance(-35, -40, 35, -40);
    EXPECT_GT(planar / geo - 1.0, 1e-3);
    EXPECT_LT(planar / geo - 1.0, 2e-3);
    double flown = 0.0;
    for (int i = 0; i < 500; ++i)
        flown += geodesic(a.x + (b.x - a.x) * i / 500.0, a.y + (b.y - a.y) * i / 500.0,
                          a.x + (b.x - a.x) * (i + 1) / 500.0, a.y + (b.y - a.y) * (i + 1) / 500.0);
    EXPECT_LT(flown / geo - 1.0, 2e-4);
    // random legs within 3000 km: |plane / geodesic - 1| below k(3000 km) - 1 = 3.8 %
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> Rr(0, 3000e3), A(0, 2 * M_PI), L(1e3, 500e3);
    double worst = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const double r1 = Rr(rng), a1 = A(rng), len = L(rng), dir = A(rng);
        const double x1 = r1 * std::cos(a1), y1 = r1 * std::sin(a1);
        const double x2 = x1 + len * std::cos(dir), y2 = y1 + len * std::sin(dir);
        if (std::hypot(x2, y2) > 3000e3)
            continue;
        worst = std::max(worst, std::abs(len / geodesic(x1, y1, x2, y2) - 1.0));
    }
    EXPECT_LT(worst, k(3000e3) - 1.0 + 1e-3);
    EXPECT_GT(worst, 0.01); // not vacuous: far from the reference point the plane does stretch
}

TEST(LocalProjection, EastAndNorthDirections)
{
    const LocalProjection p(10.0, 45.0);
    double ex, ey, nx, ny;
    p.eastDirection(10.0, 45.0, ex, ey);
    p.northDirection(10.0, 45.0, nx, ny);
    EXPECT_NEAR(ex, 1.0, 1e-9);
    EXPECT_NEAR(ey, 0.0, 1e-9);
    EXPECT_NEAR(nx, 0.0, 1e-9);
    EXPECT_NEAR(ny, 1.0, 1e-9);
    // 250 km east the meridians converge: north tilts towards the reference meridian (negative x) by about
    // dlon * sin(lat) (~2.2 degrees); east and north stay orthogonal to better than 1e-3.
    p.eastDirection(13.2, 45.0, ex, ey);
    p.northDirection(13.2, 45.0, nx, ny);
    const double tilt = std::atan2(-nx, ny) * 180.0 / M_PI;
    EXPECT_GT(tilt, 1.5);
    EXPECT_LT(tilt, 3.0);
    EXPECT_NEAR(ex * nx + ey * ny, 0.0, 1e-3);
    EXPECT_NEAR(std::hypot(ex, ey), 1.0, 1e-12);
}

// GeoBox: regions in either longitude convention (checked bound by bound, RFC 7946 bbox across the antimeridian)
// and the trip's region (the shorter way round, widened by a geodesic margin, stopping short of the poles).
#include <gtest/gtest.h>

#include <cmath>

#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GeoBox.h"

using namespace ompl_glider;

namespace
{
std::string faultBound(double a, double b, double c, double d)
{
    const auto f = regionFault(a, b, c, d);
    return f ? f->bound : "";
}
} // namespace

TEST(GeoBox, RegionFaultsNameTheBound)
{
    EXPECT_EQ(faultBound(-60, 30, -40, 45), "");
    EXPECT_EQ(faultBound(170, -10, -170, 10), ""); // across the antimeridian (RFC 7946 bbox)
    EXPECT_EQ(faultBound(350, 40, 10, 50), "");    // across Greenwich in 0..360
    EXPECT_EQ(faultBound(170, -10, 190, 10), "");  // unwrapped
    EXPECT_EQ(faultBound(std::nan(""), 30, -40, 45), "lon_min");
    EXPECT_EQ(faultBound(-60, 30, -40, INFINITY), "lat_max");
    EXPECT_EQ(faultBound(-200, 30, -40, 45), "lon_min");
    EXPECT_EQ(faultBound(-60, 30, 361, 45), "lon_max");
    EXPECT_EQ(faultBound(-60, -91, -40, 45), "lat_min");
    EXPECT_EQ(faultBound(-60, 30, -40, 95), "lat_max");
    EXPECT_EQ(faultBound(-60, 45, -40, 30), "lat_max");  // lat_min > lat_max
    EXPECT_EQ(faultBound(-60, 30, -40, 30), "lat_max");  // no height
    EXPECT_EQ(faultBound(-60, 30, -60, 45), "lon_max");  // no width
    EXPECT_EQ(faultBound(-180, 30, 180, 45), "lon_max"); // 360 wide
    EXPECT_EQ(faultBound(-170, 30, 300, 45), "lon_max"); // 470 wide
    EXPECT_NE(regionFault(-60, 30, -40, 95)->what.find("95"), std::string::npos);
    EXPECT_THROW(geoBox(-60, 30, -40, 95), Error);
}

TEST(GeoBox, EitherConventionGivesOneBox)
{
    const GeoBox a = geoBox(170, -10, -170, 10), b = geoBox(170, -10, 190, 10);
    for (const GeoBox &g : {a, b})
    {
        EXPECT_EQ(g.lonMin, 170.0);
        EXPECT_EQ(g.lonMax, 190.0);
        EXPECT_EQ(g.width(), 20.0);
    }
    EXPECT_EQ(faultBound(-190, -10, -170, 10), "lon_min"); // -190 is in neither convention
    const GeoBox g = geoBox(350, 40, 10, 50);              // 0..360 across Greenwich
    EXPECT_EQ(g.lonMin, -10.0);
    EXPECT_EQ(g.lonMax, 10.0);
    const GeoBox e = geoBox(190, 0, 200, 5); // 0..360, west of the antimeridian
    EXPECT_EQ(e.lonMin, -170.0);
    EXPECT_EQ(e.lonMax, -160.0);
    const GeoBox w = geoBox(10, 0, 350, 5); // 340 degrees wide, not across Greenwich
    EXPECT_EQ(w.width(), 340.0);
    // contains(): longitudes in any convention, edges included
    for (double lon : {170.0, 175.0, 180.0, -180.0, 185.0, -175.0, 190.0, -170.0, 530.0})
        EXPECT_TRUE(a.contains({lon, 0.0})) << lon;
    for (double lon : {169.9, -169.9, 0.0, 10.0})
        EXPECT_FALSE(a.contains({lon, 0.0})) << lon;
    EXPECT_FALSE(a.contains({175.0, 10.5}));
    EXPECT_TRUE(g.contains({359.0, 45.0}));
    EXPECT_TRUE(g.contains({-1.0, 45.0}));
    EXPECT_FALSE(g.contains({11.0, 45.0}));
    EXPECT_EQ(a.unwrap(-175.0), 185.0);
}

TEST(GeoBox, GreatCircleDistances)
{
    const double degree = kKmPerDegree;
    EXPECT_NEAR(greatCircleKm({0, 0}, {1, 0}), degree, 1e-6);
    EXPECT_NEAR(greatCircleKm({179.5, 0}, {-179.5, 0}), degree, 1e-6); // across the antimeridian
    EXPECT_NEAR(greatCircleKm({179.5, 0}, {180.5, 0}), degree, 1e-6);
    EXPECT_NEAR(greatCircleKm({10, 0}, {10, 90}), 90 * degree, 1e-6);
    // 70 degrees of longitude at 40S: cos(d) = sin^2(lat) + cos^2(lat) cos(70 deg)
    const double lat = 40.0 * M_PI / 180.0;
    const double d =
        std::acos(std::sin(lat) * std::sin(lat) + std::cos(lat) * std::cos(lat) * std::cos(70 * M_PI / 180));
    EXPECT_NEAR(greatCircleKm({-35, -40}, {35, -40}), d * 180 / M_PI * degree, 1e-6);
}

TEST(GeoBox, TripBoxTakesTheShorterWayRoundInEitherConvention)
{
    // across the antimeridian: 175E to 175W is 10 degrees wide, written in three ways
    const GeoBox a = tripBox({{175, 30}, {-175, 30.5}}, 0.0), b = tripBox({{175, 30}, {185, 30.5}}, 0.0),
                 c = tripBox({{-185, 30}, {-175, 30.5}}, 0.0);
    for (const GeoBox &g : {a, b, c})
    {
        EXPECT_EQ(g.lonMin, 175.0);
        EXPECT_EQ(g.lonMax, 185.0);
        EXPECT_EQ(g.latMin, 30.0);
        EXPECT_EQ(g.latMax, 30.5);
    }
    // across Greenwich in 0..360 and in -180..180; the order of the points does not matter
    const GeoBox g = tripBox({{355, 50}, {5, 51}}, 0.0), h = tripBox({{5, 51}, {-5, 50}}, 0.0);
    EXPECT_EQ(g.lonMin, -5.0);
    EXPECT_EQ(g.lonMax, 5.0);
    EXPECT_EQ(h.lonMin, -5.0);
    EXPECT_EQ(h.lonMax, 5.0);
    // 70 degrees wide (not 290)
    const GeoBox w = tripBox({{325, -40}, {35, -40}}, 0.0);
    EXPECT_EQ(w.lonMin, -35.0);
    EXPECT_EQ(w.lonMax, 35.0);
    // three points: the circle minus its largest gap
    const GeoBox t = tripBox({{170, 0}, {-170, 1}, {-100, 2}}, 0.0);
    EXPECT_EQ(t.lonMin, 170.0);
    EXPECT_EQ(t.lonMax, 260.0);
    EXPECT_EQ(t.latMax, 2.0);
}

TEST(GeoBox, MarginInKilometresAtTheHighestLatitude)
{
    // 1 degree of great circle of margin: 1 degree of latitude, 1 / cos(phi) degrees of longitude at the widened
    // box's highest |latitude| phi
    const GeoBox b = tripBox({{-35, -40}, {35, -40}}, kKmPerDegree);
    EXPECT_NEAR(b.latMin, -41.0, 1e-12);
    EXPECT_NEAR(b.latMax, -39.0, 1e-12);
    const double dLon = 1.0 / std::cos(41.0 * M_PI / 180.0);
    EXPECT_NEAR(b.lonMin, -35.0 - dLon, 1e-12);
    EXPECT_NEAR(b.lonMax, 35.0 + dLon, 1e-12);
    // the margin crosses the antimeridian: lonMin stays in -180..180, lonMax goes beyond 180
    const double m2 = 2.0 / std::cos(2.0 * M_PI / 180.0); // widened box: latitudes -2..2
    const GeoBox c = tripBox({{179, 0}, {179.5, 0}}, 2 * kKmPerDegree);
    EXPECT_NEAR(c.lonMin, 179.0 - m2, 1e-9);
    EXPECT_NEAR(c.lonMax, 179.5 + m2, 1e-9);
    EXPECT_GT(c.lonMax, 180.0);
    const GeoBox d = tripBox({{-179.5, 0}, {-179, 0}}, 2 * kKmPerDegree);
    EXPECT_NEAR(d.lonMin, 180.5 - m2, 1e-9);
    EXPECT_NEAR(d.lonMax, 181.0 + m2, 1e-9);
}

TEST(GeoBox, NearThePolesTheBoxStopsShortAndGoesAllRound)
{
    // a trip at 85N with a 1000 km margin: latitude stops at kMaxGridLatitude, and the longitude margin at 89.9N
    // goes all round: the whole circle centred on the trip
    const GeoBox b = tripBox({{10, 85}, {30, 85}}, 1000.0);
    EXPECT_EQ(b.latMax, kMaxGridLatitude);
    EXPECT_NEAR(b.latMin, 85.0 - 1000.0 / kKmPerDegree, 1e-9);
    EXPECT_EQ(b.width(), 360.0);
    EXPECT_NEAR(b.lonMin, 20.0 - 180.0, 1e-9);
    // a start within 0.1 degrees of a pole is refused with a message that says so
    try
    {
        tripBox({{0, 89.95}, {10, 88}}, 10.0);
        FAIL() << "no error";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("pole"), std::string::npos) << e.what();
    }
    EXPECT_THROW(tripBox({}, 1.0), Error);
    EXPECT_THROW(tripBox({{0, 0}}, -1.0), Error);
    EXPECT_THROW(tripBox({{0, 91}}, 1.0), Error);
}

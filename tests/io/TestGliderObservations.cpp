// A deployment's DAC from IOOS profile files written in the template's layout, and from a CSV: usable records in
// time order, bad ones rejected with the reason counted, the last fix, and clear errors where nothing is usable.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "IoosProfiles.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GliderObservations.h"
#include "ompl_glider/io/Time.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
fs::path freshDir(const std::string &name)
{
    const fs::path d = fs::path(::testing::TempDir()) / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string errorOf(const std::string &path)
{
    try
    {
        readGliderObservations(path);
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}
} // namespace

TEST(GliderObservations, IoosDeploymentFolder)
{
    const fs::path d = freshDir("ioos_deployment");
    const double t0 = parseIsoTime("2026-03-15T06:00:00Z");
    for (int k = 0; k < 6; ++k) // six good profiles, written out of order
    {
        const int i = (k * 5) % 6;
        ioos_test::writeProfile((d / ("ru29_" + std::to_string(i) + ".nc")).string(),
                                {t0 + 7200.0 * i, -52.5 + 0.02 * i, 47.95 + 0.01 * i, 0.1 * i, -0.05});
    }
    ioos_test::writeProfile((d / "ru29_6.nc").string(), {t0 + 7200.0 * 6, -52.38, 48.01, -999.0, -999.0});
    ioos_test::Profile bad{t0 + 7200.0 * 7, -52.36, 48.02, 0.2, 0.1};
    bad.qc = 4;
    ioos_test::writeProfile((d / "ru29_7.nc").string(), bad);
    ioos_test::writeProfile((d / "ru29_8.nc").string(), {t0 + 7200.0 * 8, -52.34, 48.03, 10.0, 0.0});
    ioos_test::Profile other{t0 + 7200.0 * 9, -60.0, 40.0, 0.1, 0.1};
    other.glider = "sg512";
    ioos_test::writeProfile((d / "sg512_0.nc").string(), other);
    ioos_test::writeProfile((d / "ru29_copy.nc").string(), {t0 + 7200.0 * 2, -52.46, 47.97, 0.2, -0.05});

    const GliderObservations o = readGliderObservations(d.string());
    EXPECT_EQ(o.files, 11u);
    EXPECT_EQ(o.platform, "ru29");
    ASSERT_EQ(o.dac.size(), 6u);
    for (std::size_t i = 0; i < o.dac.size(); ++i)
    {
        EXPECT_DOUBLE_EQ(o.dac[i].time, t0 + 7200.0 * i - 1800.0); // the dive's middle, in time order
        EXPECT_NEAR(o.dac[i].u, 0.1 * i, 1e-12);
        EXPECT_NEAR(o.dac[i].at.lon, -52.5 + 0.02 * i - 0.001, 1e-9);
    }
    EXPECT_EQ(o.rejected.at("fill value"), 1u);
    EXPECT_EQ(o.rejected.at("QC flag 4 (u_qc)"), 1u);
    EXPECT_EQ(o.rejected.at("faster than 3 m/s"), 1u);
    EXPECT_EQ(o.rejected.at("another glider ('sg512')"), 1u);
    EXPECT_EQ(o.rejected.at("repeated time"), 1u);
    // the last fix: the latest profile of this glider (the QC-rejected one still reports where it was)
    ASSERT_TRUE(o.lastFix.has_value());
    EXPECT_DOUBLE_EQ(o.lastFix->time, t0 + 7200.0 * 8);
    EXPECT_NEAR(o.lastFix->at.lat, 48.03, 1e-12);
    // a glob of the same files gives the same
    EXPECT_EQ(readGliderObservations((d / "ru29_*.nc").string()).dac.size(), 6u);
    EXPECT_NE(observationsText(o).find("6 DAC from 11 file(s) of glider 'ru29'"), std::string::npos);
}

TEST(GliderObservations, NothingUsableIsRefusedNamingTheFileAndVariable)
{
    const fs::path d = freshDir("ioos_bad");
    ioos_test::writeProfile((d / "a.nc").string(), {1.8e9, -52.0, 48.0, -999.0, -999.0});
    const std::string e = errorOf(d.string());
    EXPECT_NE(e.find("no usable depth-averaged current (variables u, v; rejected: 1 fill value)"), std::string::npos)
        << e;
    // a NetCDF file without the DAC variables
    int nc = 0;
    const std::string plain = (d / "plain.nc").string();
    ASSERT_EQ(nc_create(plain.c_str(), NC_CLOBBER, &nc), NC_NOERR);
    int id = 0;
    nc_def_var(nc, "time_uv", NC_DOUBLE, 0, nullptr, &id);
    nc_close(nc);
    const std::string e2 = errorOf(plain);
    EXPECT_NE(e2.find(plain), std::string::npos) << e2;
    EXPECT_NE(e2.find("variable 'lat_uv' is missing"), std::string::npos) << e2;
    EXPECT_NE(errorOf((d / "none_*.nc").string()).find("matches no file"), std::string::npos);
}

TEST(GliderObservations, CsvRowsFixesAndErrors)
{
    const fs::path d = freshDir("dac_csv");
    const std::string f = (d / "dac.csv").string();
    std::ofstream(f) << "time,lon,lat,u,v\n"
                        "2026-03-15T06:00:00Z,-52.7,47.9,0.10,-0.02\n"
                        "1773561600,307.5,48.0,0.12,-0.01\n"  // seconds since 1970, longitude 0..360
                        "2026-03-15T12:00:00Z,-52.4,48.1,,\n" // a fix without a DAC
                        "2026-03-15T09:00:00Z,-52.5,48.0,9.0,0.0\n";
    const GliderObservations o = readGliderObservations(f);
    ASSERT_EQ(o.dac.size(), 2u);
    EXPECT_LT(o.dac[0].time, o.dac[1].time);
    EXPECT_NEAR(o.dac[1].at.lon, -52.5, 1e-12);
    EXPECT_EQ(o.rejected.at("faster than 3 m/s"), 1u);
    ASSERT_TRUE(o.lastFix.has_value());
    EXPECT_DOUBLE_EQ(o.lastFix->time, parseIsoTime("2026-03-15T12:00:00Z"));
    std::ofstream(f) << "time,lon,lat,u,v\n2026-03-15T06:00:00Z,-52.7,north,0.1,0.1\n";
    EXPECT_NE(errorOf(f).find(f + ":2: column 'lat': expected a number, got 'north'"), std::string::npos) << errorOf(f);
    std::ofstream(f) << "when,lon,lat,u,v\n";
    EXPECT_NE(errorOf(f).find(f + ":1: the header must name the columns"), std::string::npos) << errorOf(f);
}

// A ';'-separated CSV (a spreadsheet's in a decimal-comma locale) reads as the ','-separated one; a decimal comma is
// named as such.
TEST(GliderObservations, SemicolonSeparatedCsvReadsAsTheCommaSeparatedOne)
{
    const fs::path d = freshDir("dac_semicolon");
    const std::string comma = (d / "comma.csv").string(), semi = (d / "semi.csv").string();
    std::ofstream(comma) << "time,lon,lat,u,v\n2026-03-15T06:00:00Z,-52.7,47.9,0.10,-0.02\n"
                            "2026-03-15T09:00:00Z,-52.5,48.0,0.12,-0.01\n2026-03-15T12:00:00Z,-52.4,48.1,,\n";
    std::ofstream(semi) << "time;lon;lat;u;v\n2026-03-15T06:00:00Z;-52.7;47.9;0.10;-0.02\n"
                           "2026-03-15T09:00:00Z;-52.5;48.0;0.12;-0.01\n2026-03-15T12:00:00Z;-52.4;48.1;;\n";
    const GliderObservations a = readGliderObservations(comma), b = readGliderObservations(semi);
    ASSERT_EQ(a.dac.size(), b.dac.size());
    for (std::size_t i = 0; i < a.dac.size(); ++i)
    {
        EXPECT_EQ(a.dac[i].time, b.dac[i].time);
        EXPECT_EQ(a.dac[i].u, b.dac[i].u);
        EXPECT_EQ(a.dac[i].at.lat, b.dac[i].at.lat);
    }
    EXPECT_EQ(a.fixes.size(), b.fixes.size());
    EXPECT_EQ(a.lastFix->time, b.lastFix->time);
    std::ofstream(semi) << "time;lon;lat;u;v\n2026-03-15T06:00:00Z;-52,7;47,9;0,10;-0,02\n";
    EXPECT_NE(errorOf(semi).find(semi + ":2: column 'lon': expected a number, got '-52,7' (a ';'-separated CSV with "
                                        "a decimal comma"),
              std::string::npos)
        << errorOf(semi);
    std::ofstream(semi) << "when;lon;lat;u;v\n";
    EXPECT_NE(errorOf(semi).find("(missing 'time' in this ';'-separated header)"), std::string::npos) << errorOf(semi);
}

// A deployment's DAC from IOOS profile files written in the template's layout, and from a CSV: usable records in
// time order, bad ones rejected with the reason counted, the last fix, and clear errors where nothing is usable.
#include <gtest/gtest.h>

#include <netcdf.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "IoosProfiles.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GliderObservations.h"
#include "ompl_glider/io/Time.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
fs::path freshObservationDir(const std::string &name)
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
    const fs::path d = freshObservationDir("ioos_deployment");
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
    EXPECT_EQ(o.rejected.at("faster than 3 m/s (u, v read in 'm s-1')"), 1u);
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
    const fs::path d = freshObservationDir("ioos_bad");
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
    const fs::path d = freshObservationDir("dac_csv");
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
    EXPECT_EQ(o.rejected.at("faster than 3 m/s (u, v read without units, as m/s)"), 1u);
    ASSERT_TRUE(o.lastFix.has_value());
    EXPECT_DOUBLE_EQ(o.lastFix->time, parseIsoTime("2026-03-15T12:00:00Z"));
    std::ofstream(f) << "time,lon,lat,u,v\n2026-03-15T06:00:00Z,-52.7,north,0.1,0.1\n";
    EXPECT_NE(errorOf(f).find(f + ":2: column 'lat': expected a number, got 'north'"), std::string::npos) << errorOf(f);
    std::ofstream(f) << "when,lon,lat,u,v\n";
    EXPECT_NE(errorOf(f).find(f + ":1: the header must name the columns"), std::string::npos) << errorOf(f);
}

// The DAC's units, as the file writes them (UDUNITS-2, as for the forecasts): profiles in cm s-1 or knots read as
// the same currents in m s-1; a unit that is no velocity is refused naming the file and variable; a CSV header gives
// the unit as "u (cm/s)"; the rejection of implausibly fast values names the unit read.
TEST(GliderObservations, VelocityUnitsAreConvertedOrRefused)
{
    const fs::path d = freshObservationDir("dac_units");
    const double t0 = parseIsoTime("2026-03-15T06:00:00Z");
    const double knot = 1852.0 / 3600.0;
    const struct
    {
        const char *units;
        double perMetre; // the file's value of 1 m/s
    } cases[] = {{"m s-1", 1.0}, {"cm s-1", 100.0}, {"cm/s", 100.0}, {"knots", 1.0 / knot}, {"mm s-1", 1000.0}};
    for (const auto &c : cases)
    {
        const fs::path f = d / (std::string("p_") + std::to_string(&c - cases) + ".nc");
        ioos_test::Profile p{t0, -52.5, 47.95, 0.25 * c.perMetre, -0.1 * c.perMetre};
        p.velocityUnits = c.units;
        ioos_test::writeProfile(f.string(), p);
        const GliderObservations o = readGliderObservations(f.string());
        ASSERT_EQ(o.dac.size(), 1u) << c.units;
        EXPECT_NEAR(o.dac[0].u, 0.25, 1e-12) << c.units;
        EXPECT_NEAR(o.dac[0].v, -0.1, 1e-12) << c.units;
    }
    // 10 knots is no glider's DAC: rejected, and the reason says what unit the file gave
    ioos_test::Profile fast{t0, -52.5, 47.95, 10.0, 0.0};
    fast.velocityUnits = "knots";
    ioos_test::writeProfile((d / "fast.nc").string(), fast);
    const std::string e = errorOf((d / "fast.nc").string());
    EXPECT_NE(e.find("faster than 3 m/s (u, v read in 'knots')"), std::string::npos) << e;
    // a temperature is no velocity
    ioos_test::Profile warm{t0, -52.5, 47.95, 12.0, 11.0};
    warm.velocityUnits = "degC";
    const std::string w = (d / "warm.nc").string();
    ioos_test::writeProfile(w, warm);
    EXPECT_NE(errorOf(w).find("NetCDF file '" + w + "': 'u' is in 'degC': units 'degC' are not a velocity"),
              std::string::npos)
        << errorOf(w);
    // a CSV with units in its header
    const std::string csv = (d / "dac.csv").string();
    std::ofstream(csv) << "time,lon,lat,u (cm/s),v (cm/s)\n2026-03-15T06:00:00Z,-52.7,47.9,25,-10\n";
    const GliderObservations o = readGliderObservations(csv);
    ASSERT_EQ(o.dac.size(), 1u);
    EXPECT_NEAR(o.dac[0].u, 0.25, 1e-12);
    EXPECT_NEAR(o.dac[0].v, -0.1, 1e-12);
    std::ofstream(csv) << "time,lon,lat,u (degC),v (degC)\n2026-03-15T06:00:00Z,-52.7,47.9,25,-10\n";
    EXPECT_NE(errorOf(csv).find(csv + ":1: 'u' is in 'degC': units 'degC' are not a velocity"), std::string::npos)
        << errorOf(csv);
    std::ofstream(csv) << "time,lon,lat,u (cm/s),v (m/s)\n2026-03-15T06:00:00Z,-52.7,47.9,25,-10\n";
    EXPECT_NE(errorOf(csv).find(csv + ":1: 'u' is in 'cm/s' and 'v' in 'm/s'"), std::string::npos) << errorOf(csv);
}

// A ';'-separated CSV (a spreadsheet's in a decimal-comma locale) reads as the ','-separated one; a decimal comma is
// named as such.
TEST(GliderObservations, SemicolonSeparatedCsvReadsAsTheCommaSeparatedOne)
{
    const fs::path d = freshObservationDir("dac_semicolon");
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

namespace
{
/// A file of several DAC (each variable a list, as a glider's trajectory file holds them), in m s-1.
void writeDacList(const std::string &path, const std::string &glider, const std::vector<double> &t,
                  const std::vector<double> &u, int qcBad = -1)
{
    int nc = 0, dim = 0;
    ASSERT_EQ(nc_create(path.c_str(), NC_CLOBBER | NC_NETCDF4, &nc), NC_NOERR);
    const std::size_t n = t.size();
    ASSERT_EQ(nc_def_dim(nc, "profile", n, &dim), NC_NOERR);
    const auto def = [&](const char *name, const char *units) {
        int id = 0;
        nc_def_var(nc, name, NC_DOUBLE, 1, &dim, &id);
        nc_put_att_text(nc, id, "units", std::strlen(units), units);
        return id;
    };
    const int vt = def("time_uv", "seconds since 1970-01-01T00:00:00Z"), vla = def("lat_uv", "degrees_north"),
              vlo = def("lon_uv", "degrees_east"), vu = def("u", "m s-1"), vv = def("v", "m s-1");
    int qc = 0, platform = 0;
    nc_def_var(nc, "u_qc", NC_BYTE, 1, &dim, &qc);
    nc_def_var(nc, "platform", NC_INT, 0, nullptr, &platform);
    nc_put_att_text(nc, platform, "id", glider.size(), glider.c_str());
    nc_enddef(nc);
    std::vector<double> lat(n, 48.0), lon(n), v(n, 0.0);
    std::vector<signed char> flags(n, 1);
    for (std::size_t i = 0; i < n; ++i)
        lon[i] = -52.5 + 0.01 * static_cast<double>(i);
    if (qcBad >= 0)
        flags[static_cast<std::size_t>(qcBad)] = 4;
    nc_put_var_double(nc, vt, t.data());
    nc_put_var_double(nc, vla, lat.data());
    nc_put_var_double(nc, vlo, lon.data());
    nc_put_var_double(nc, vu, u.data());
    nc_put_var_double(nc, vv, v.data());
    nc_put_var_schar(nc, qc, flags.data());
    nc_close(nc);
}
} // namespace

// A file holding several DAC gives them all (each with its own QC flag), not its first alone; files of two gliders in
// equal numbers are refused naming both, where one glider's files are the most they are read without the other's.
TEST(GliderObservations, FilesOfSeveralDacAndTiesBetweenGliders)
{
    const fs::path d = freshObservationDir("dac_lists");
    const double t0 = parseIsoTime("2026-03-15T06:00:00Z");
    writeDacList((d / "ru29_a.nc").string(), "ru29", {t0, t0 + 3600, t0 + 7200}, {0.1, 0.2, 0.3});
    writeDacList((d / "ru29_b.nc").string(), "ru29", {t0 + 10800, t0 + 14400, t0 + 18000}, {0.4, 0.5, 0.6}, 1);
    GliderObservations o = readGliderObservations(d.string());
    ASSERT_EQ(o.dac.size(), 5u); // six, one flagged bad
    EXPECT_EQ(o.rejected.at("QC flag 4 (u_qc)"), 1u);
    const double expected[] = {0.1, 0.2, 0.3, 0.4, 0.6};
    for (std::size_t i = 0; i < 5; ++i)
        EXPECT_DOUBLE_EQ(o.dac[i].u, expected[i]);
    EXPECT_DOUBLE_EQ(o.lastFix->time, t0 + 18000);
    // two files of another glider: as many as ru29's, a tie
    writeDacList((d / "sg512_a.nc").string(), "sg512", {t0 + 500}, {0.1});
    writeDacList((d / "sg512_b.nc").string(), "sg512", {t0 + 900}, {0.1});
    const std::string e = errorOf(d.string());
    EXPECT_NE(e.find("as many files of glider 'ru29' as of 'sg512' (2 each)"), std::string::npos) << e;
    // one more of ru29: ru29's deployment, sg512's files counted as rejected
    writeDacList((d / "ru29_c.nc").string(), "ru29", {t0 + 21600}, {0.7});
    o = readGliderObservations(d.string());
    EXPECT_EQ(o.platform, "ru29");
    EXPECT_EQ(o.dac.size(), 6u);
    EXPECT_EQ(o.rejected.at("another glider ('sg512')"), 2u);
}

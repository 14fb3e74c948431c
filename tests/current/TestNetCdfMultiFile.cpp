// A forecast in several files read as one (loadGriddedCurrents() with a list of files): the same field as the one
// combined file, whatever the files' time units and origins and the order they are given in; the later file wins
// where two overlap; only the files the trip needs are read; mismatched grids, calendars, undated files, gaps and
// glob patterns that match nothing are refused with messages that name the files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

#include "MultiFileForecast.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
/// The daily files named so that their alphabetical order is not their time order.
struct Files : MfFiles
{
    explicit Files(bool land = true)
        : MfFiles([](int d) { return std::string(1, char('d' - d)) + "_day" + std::to_string(d) + ".nc"; }, land)
    {
    }
};

std::string messageOf(const std::function<void()> &f)
{
    try
    {
        f();
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "(no error)";
}

GriddedCurrentOptions options()
{
    GriddedCurrentOptions o;
    o.lonMin = -52.9;
    o.lonMax = -52.1;
    o.latMin = 47.1;
    o.latMax = 47.9;
    return o;
}

/// The two fields give the same velocities (bit for bit) at sampled points and times.
void expectSameField(const GriddedCurrents &a, const GriddedCurrents &b, double t0, double t1)
{
    ASSERT_EQ(a.loadedShape, b.loadedShape);
    EXPECT_EQ(a.field->timeAxis().nodes(), b.field->timeAxis().nodes());
    EXPECT_EQ(a.landNodes, b.landNodes);
    int compared = 0;
    for (double t = t0; t <= t1; t += 1234.5)
        for (double lon = -52.95; lon <= -52.05; lon += 0.13)
            for (double lat = 47.05; lat <= 47.95; lat += 0.11)
            {
                const Point2 p = a.toLocal({lon, lat});
                const Point2 q = b.toLocal({lon, lat});
                ASSERT_EQ(p.x, q.x);
                ASSERT_EQ(p.y, q.y);
                const Velocity va = a.field->velocity(p.x, p.y, 0.0, t), vb = b.field->velocity(q.x, q.y, 0.0, t);
                ASSERT_EQ(va.u, vb.u) << "lon " << lon << " lat " << lat << " t " << t;
                ASSERT_EQ(va.v, vb.v) << "lon " << lon << " lat " << lat << " t " << t;
                ASSERT_EQ(a.field->inWater(p.x, p.y, 0.0), b.field->inWater(q.x, q.y, 0.0));
                ++compared;
            }
    EXPECT_GT(compared, 1000);
}
} // namespace

TEST(NetCdfMultiFile, DailyFilesGiveTheCombinedFileField)
{
    Files f;
    const GriddedCurrentOptions o = options();
    const GriddedCurrents one = loadGriddedCurrents(f.combined, o);
    // given in reverse time order: ordered by their first (dated) times
    const std::vector<std::string> reversed(f.days.rbegin(), f.days.rend());
    const GriddedCurrents many = loadGriddedCurrents(reversed, o);
    EXPECT_EQ(many.files, f.days);
    EXPECT_EQ(one.files, std::vector<std::string>{f.combined});
    EXPECT_TRUE(many.dated);
    EXPECT_FALSE(many.steady);
    EXPECT_EQ(many.originSeconds, one.originSeconds);
    EXPECT_EQ(many.forecastBegin, one.forecastBegin);
    EXPECT_EQ(many.forecastEnd, one.forecastEnd);
    EXPECT_EQ(many.forecastEnd, 93.0 * 3600.0);
    EXPECT_EQ(many.droppedRecords, 1u); // day 1's record at 2026-03-03T00:00, replaced by day 2's
    EXPECT_EQ(one.droppedRecords, 0u);
    EXPECT_EQ(many.isoTime(48.0 * 3600.0), "2026-03-03T00:00:00Z");
    EXPECT_EQ(many.fillLandNodes, one.fillLandNodes);
    EXPECT_EQ(many.zeroLandNodes, one.zeroLandNodes);
    EXPECT_EQ(many.zeroLandNodes, 0u); // the still node lies away from the fill-value land: calm water
    EXPECT_GT(many.fillLandNodes, 0u);
    expectSameField(one, many, 0.0, 93.0 * 3600.0);
    // the overlapping record: the later file's values (the true ones), not day 1's biased copy
    const Point2 p = many.toLocal({-52.5, 47.5});
    EXPECT_EQ(many.field->velocity(p.x, p.y, 0.0, 48.0 * 3600.0).u,
              one.field->velocity(p.x, p.y, 0.0, 48.0 * 3600.0).u);
}

TEST(NetCdfMultiFile, OnlyTheFilesOfTheTripAreRead)
{
    Files f;
    GriddedCurrentOptions o = options();
    o.departure = "2026-03-01T20:00:00Z";
    o.horizon = 20.0 * 3600.0; // to 2026-03-02T16:00; 2 records of margin: to 2026-03-03T00:00 (day 2's first)
    const GriddedCurrents one = loadGriddedCurrents(f.combined, o);
    const GriddedCurrents many = loadGriddedCurrents(f.days, o);
    EXPECT_EQ(many.files, (std::vector<std::string>{f.days[0], f.days[1], f.days[2]}));
    EXPECT_EQ(many.departureTime, 20.0 * 3600.0);
    EXPECT_EQ(many.departureTime, one.departureTime);
    EXPECT_EQ(many.loadedShape, one.loadedShape);
    EXPECT_EQ(many.loadedShape.front(), 13u); // 12:00 on day 0 to 00:00 on day 2
    expectSameField(one, many, 14.0 * 3600.0, 48.0 * 3600.0);
    // a departure in the gap between two files' records is a departure like any other
    o.departure = "2026-03-01T22:30:00Z";
    o.horizon = 2.0 * 3600.0;
    const GriddedCurrents small = loadGriddedCurrents(f.days, o);
    EXPECT_EQ(small.files, (std::vector<std::string>{f.days[0], f.days[1]}));
    // a departure outside the joined forecast: an error naming the files
    o.departure = "2026-03-05T00:00:00Z";
    const std::string msg = messageOf([&] { loadGriddedCurrents(f.days, o); });
    EXPECT_NE(msg.find("outside the forecast"), std::string::npos) << msg;
    EXPECT_NE(msg.find("4 files"), std::string::npos) << msg;
}

TEST(NetCdfMultiFile, ZeroVelocityLandIsDecidedOnAllTheTripsRecords)
{
    Files f(false); // no fill values: the zeros are the only land the files give
    // node (3, 2) is still throughout day 0's file, moving from day 1 on: water for a trip into day 1, as in the
    // combined file (not land because one file saw it still)
    GriddedCurrentOptions o = options();
    o.departure = "2026-03-01T15:00:00Z";
    o.horizon = 12.0 * 3600.0;
    GriddedCurrents one = loadGriddedCurrents(f.combined, o), many = loadGriddedCurrents(f.days, o);
    EXPECT_EQ(many.zeroLandNodes, 1u);
    EXPECT_EQ(many.zeroLandNodes, one.zeroLandNodes);
    EXPECT_EQ(many.files.size(), 2u);
    expectSameField(one, many, 9.0 * 3600.0, 33.0 * 3600.0);
    // a trip within day 0 (its margin record in day 1 does not count): land in both
    o.departure = "2026-03-01T06:00:00Z";
    o.horizon = 9.0 * 3600.0;
    one = loadGriddedCurrents(f.combined, o);
    many = loadGriddedCurrents(f.days, o);
    EXPECT_EQ(many.files.size(), 2u); // the stencil margin reaches 00:00 of day 1
    EXPECT_EQ(many.zeroLandNodes, 2u);
    EXPECT_EQ(many.zeroLandNodes, one.zeroLandNodes);
    expectSameField(one, many, 0.0, 24.0 * 3600.0);
}

TEST(NetCdfMultiFile, TimeAxisOfSeveralFiles)
{
    Files f;
    const ForecastTimeAxis one = readForecastTimeAxis(f.combined, GriddedCurrentOptions{});
    const ForecastTimeAxis many = readForecastTimeAxis(
        std::vector<std::string>{f.days[2], f.days[0], f.days[3], f.days[1]}, GriddedCurrentOptions{});
    EXPECT_TRUE(many.found && many.dated);
    EXPECT_FALSE(many.steady);
    EXPECT_EQ(many.originSeconds, one.originSeconds);
    EXPECT_EQ(many.size, one.size);
    EXPECT_EQ(many.span, one.span);
    EXPECT_EQ(many.calendar, one.calendar);
}

TEST(NetCdfMultiFile, MismatchedGridsNameBothFiles)
{
    Files f;
    MfFile shifted = mfDay(1);
    shifted.lonShift = 0.05;
    const std::string bad = f.dir.file("shifted_day1.nc");
    writeMfFile(bad, shifted);
    const std::string msg = messageOf([&] { loadGriddedCurrents({f.days[0], bad, f.days[2]}, options()); });
    EXPECT_NE(msg.find("'" + f.days[0] + "'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'" + bad + "'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("grids in the trip's region differ"), std::string::npos) << msg;
    EXPECT_NE(msg.find("longitude 'lon'"), std::string::npos) << msg;
}

TEST(NetCdfMultiFile, CalendarsMustAgree)
{
    Files f;
    MfFile noleap = mfDay(1);
    noleap.calendar = "noleap";
    const std::string bad = f.dir.file("noleap_day1.nc");
    writeMfFile(bad, noleap);
    const std::string msg = messageOf([&] { loadGriddedCurrents({f.days[0], bad}, options()); });
    EXPECT_NE(msg.find("calendars differ"), std::string::npos) << msg;
    EXPECT_NE(msg.find(bad), std::string::npos) << msg;
    EXPECT_NE(msg.find(f.days[0]), std::string::npos) << msg;
}

TEST(NetCdfMultiFile, UndatedFilesCannotBeJoined)
{
    Files f;
    MfFile undated = mfDay(1);
    undated.units = "hours";
    const std::string bad = f.dir.file("undated.nc");
    writeMfFile(bad, undated);
    for (const auto &list : {std::vector<std::string>{f.days[0], bad}, std::vector<std::string>{bad, f.days[0]}})
    {
        const std::string msg = messageOf([&] { loadGriddedCurrents(list, options()); });
        EXPECT_NE(msg.find("NetCDF file '" + bad + "'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("have no date"), std::string::npos) << msg;
        const std::string axis = messageOf([&] { readForecastTimeAxis(list, GriddedCurrentOptions{}); });
        EXPECT_NE(axis.find("have no date"), std::string::npos) << axis;
    }
}

TEST(NetCdfMultiFile, SameStartTwiceAndSteadyRecordAreRefused)
{
    Files f;
    std::string msg = messageOf([&] { loadGriddedCurrents({f.days[0], f.days[1], f.days[0]}, options()); });
    EXPECT_NE(msg.find("both begin at 2026-03-01T00:00:00Z"), std::string::npos) << msg;
    GriddedCurrentOptions o = options();
    o.steadyRecord = 0;
    msg = messageOf([&] { loadGriddedCurrents(f.days, o); });
    EXPECT_NE(msg.find("steadyRecord"), std::string::npos) << msg;
}

TEST(NetCdfMultiFile, GapInTheTripIsRefusedOutsideItIsNot)
{
    Files f;
    // day 1 missing: 21:00 on day 0, then 00:00 on day 2 (27 h, the step is 3 h)
    const std::vector<std::string> holed{f.days[0], f.days[2], f.days[3]};
    std::string msg = messageOf([&] { loadGriddedCurrents(holed, options()); });
    EXPECT_NE(msg.find("a gap of 27 h"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'" + f.days[0] + "' and '" + f.days[2] + "'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("2026-03-01T21:00:00Z"), std::string::npos) << msg;
    // a trip after the gap does not read the files before it
    GriddedCurrentOptions o = options();
    o.departure = "2026-03-03T12:00:00Z";
    o.horizon = 6.0 * 3600.0;
    const GriddedCurrents after = loadGriddedCurrents(holed, o);
    EXPECT_EQ(after.files, (std::vector<std::string>{f.days[2], f.days[3]}));
}

TEST(NetCdfMultiFile, GlobPatternsAndLists)
{
    Files f;
    const std::string dir = f.dir.file("");
    // a pattern: its matches (glob(3) sorts them by name; loading orders them by time)
    std::vector<std::string> got = expandForecastFiles({"?_day*.nc"}, dir);
    std::vector<std::string> sorted = f.days;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(got.size(), 4u);
    for (std::size_t k = 0; k < got.size(); ++k)
        EXPECT_EQ(std::filesystem::path(got[k]), std::filesystem::path(sorted[k]));
    const GriddedCurrents many = loadGriddedCurrents(got, options());
    for (std::size_t k = 0; k < 4; ++k)
        EXPECT_EQ(std::filesystem::path(many.files[k]), std::filesystem::path(f.days[k]));
    // a comma-separated list, plain names and patterns mixed
    got = forecastFileList("d_day0.nc, [bc]_day*.nc", dir);
    ASSERT_EQ(got.size(), 3u);
    EXPECT_EQ(std::filesystem::path(got[0]).filename(), "d_day0.nc");
    EXPECT_EQ(std::filesystem::path(got[1]).filename(), "b_day2.nc");
    // a pattern that matches nothing names the pattern
    const std::string msg = messageOf([&] { forecastFileList("d_day0.nc,hycom_*.nc", dir); });
    EXPECT_NE(msg.find("no file matches the pattern"), std::string::npos) << msg;
    EXPECT_NE(msg.find("hycom_*.nc'"), std::string::npos) << msg;
    EXPECT_NE(messageOf([&] { forecastFileList("a.nc,,b.nc", dir); }).find("empty name"), std::string::npos);
}

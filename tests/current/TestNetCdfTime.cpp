// CF time units and calendars (standard, proleptic_gregorian, julian, noleap, all_leap, 360_day) and ISO dates;
// the time axis of a forecast file found as the loader finds it (readForecastTimeAxis), whatever its name.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using glider_test::NcWriter;
using glider_test::TempDir;

namespace
{
double days(const std::string &a, const std::string &b, Calendar c)
{
    return (secondsSinceCalendarEpoch(parseDateTime(b), c) - secondsSinceCalendarEpoch(parseDateTime(a), c)) / 86400.0;
}
} // namespace

TEST(Time, CalendarsCountDaysTheirOwnWay)
{
    EXPECT_EQ(days("2000-02-01", "2000-03-01", Calendar::ProlepticGregorian), 29);
    EXPECT_EQ(days("2000-02-01", "2000-03-01", Calendar::Standard), 29);
    EXPECT_EQ(days("2000-02-01", "2000-03-01", Calendar::NoLeap), 28);
    EXPECT_EQ(days("2001-02-01", "2001-03-01", Calendar::AllLeap), 29);
    EXPECT_EQ(days("2000-02-01", "2000-03-01", Calendar::Day360), 30);
    EXPECT_EQ(days("1900-02-01", "1900-03-01", Calendar::ProlepticGregorian), 28);
    EXPECT_EQ(days("1900-02-01", "1900-03-01", Calendar::Julian), 29);
    EXPECT_EQ(days("1950-01-01", "2020-01-01", Calendar::NoLeap), 70 * 365);
    EXPECT_EQ(days("1950-01-01", "2020-01-01", Calendar::Day360), 70 * 360);
    EXPECT_EQ(days("1970-01-01", "2000-01-01", Calendar::Standard), 10957); // known Unix-day count
    // the Gregorian reform: 1582-10-04 (Julian) is followed by 1582-10-15
    EXPECT_EQ(days("1582-10-04", "1582-10-15", Calendar::Standard), 1);
    EXPECT_EQ(days("1582-10-04", "1582-10-15", Calendar::ProlepticGregorian), 11);
    EXPECT_THROW(secondsSinceCalendarEpoch(parseDateTime("2001-02-29"), Calendar::Standard), Error);
    EXPECT_THROW(secondsSinceCalendarEpoch(parseDateTime("2000-02-29"), Calendar::NoLeap), Error);
    EXPECT_NO_THROW(secondsSinceCalendarEpoch(parseDateTime("2001-02-30"), Calendar::Day360));
}

TEST(Time, DatesRoundTripInEveryCalendar)
{
    for (Calendar c : {Calendar::Standard, Calendar::ProlepticGregorian, Calendar::Julian, Calendar::NoLeap,
                       Calendar::AllLeap, Calendar::Day360})
        for (const char *s : {"1950-01-01T00:00:00Z", "2020-02-28T23:59:59Z", "2023-12-30T12:30:00Z",
                              "1600-03-01T06:00:00Z", "0800-07-15T01:02:03Z"})
        {
            const double t = secondsSinceCalendarEpoch(parseDateTime(s), c);
            EXPECT_EQ(formatDateTime(dateFromCalendarEpoch(t, c)), s);
        }
}

TEST(Time, ParsesUnitsAndIsoVariants)
{
    const CfTimeUnits h = parseCfTimeUnits("hours since 1950-1-1 0:0:0", "gregorian");
    EXPECT_EQ(h.secondsPerUnit, 3600.0);
    EXPECT_EQ(h.calendar, Calendar::Standard);
    EXPECT_EQ(formatDateTime(dateFromCalendarEpoch(h.reference + 36.5 * 3600, h.calendar)), "1950-01-02T12:30:00Z");
    EXPECT_EQ(parseCfTimeUnits("days since 2000-01-01", "360_day").calendar, Calendar::Day360);
    EXPECT_EQ(parseCfTimeUnits("seconds since 1970-01-01T00:00:00Z", "").secondsPerUnit, 1.0);
    EXPECT_EQ(parseCfTimeUnits("minutes since 1970-01-01 00:00", "proleptic_gregorian").secondsPerUnit, 60.0);
    // time zones are converted to UTC
    EXPECT_EQ(formatDateTime(parseDateTime("2020-06-01T02:00:00+03:00")), "2020-05-31T23:00:00Z");
    EXPECT_EQ(formatDateTime(parseDateTime("2020-06-01 10:00 UTC")), "2020-06-01T10:00:00Z");
    // an offset is less than a day: +24:00, +99:00 or 01:75 is refused, not a shift of days
    for (const char *bad : {"2026-06-01T00:00+24:00", "2026-06-01T00:00+99:00", "2026-06-01T00:00+01:75",
                            "2026-06-01T00:00-2400", "2026-06-01T00:00+0160"})
    {
        EXPECT_THROW(parseDateTime(bad), Error) << bad;
        EXPECT_THROW(parseIsoTime(bad), Error) << bad;
    }
    EXPECT_EQ(parseIsoTime("2026-06-01T00:00-23:59") - parseIsoTime("2026-06-01T00:00Z"), 23.0 * 3600 + 59 * 60);
    // a zone in a calendar without the Gregorian months: the offset is subtracted in that calendar's own days
    // (2026-02-30 exists in 360_day; an hour east of UTC it is 2026-02-29T23:00 there)
    EXPECT_EQ(secondsSinceCalendarEpoch("2026-02-30T00:00:00+01:00", Calendar::Day360),
              secondsSinceCalendarEpoch(parseDateTime("2026-02-29T23:00:00"), Calendar::Day360));
    EXPECT_EQ(formatDateTime(dateFromCalendarEpoch(
                  parseCfTimeUnits("days since 2026-02-30 00:00 +01:00", "360_day").reference, Calendar::Day360)),
              "2026-02-29T23:00:00Z");
    EXPECT_EQ(secondsSinceCalendarEpoch("2020-06-01T02:00:00+03:00", Calendar::Standard),
              secondsSinceCalendarEpoch(parseDateTime("2020-05-31T23:00:00"), Calendar::Standard));
    for (const char *bad :
         {"hours after 2000-01-01", "months since 2000-01-01", "fortnights since 2000-01-01", "days since yesterday"})
    {
        try
        {
            parseCfTimeUnits(bad, "standard");
            ADD_FAILURE() << bad;
        }
        catch (const Error &e)
        {
            EXPECT_FALSE(std::string(e.what()).empty());
        }
    }
    EXPECT_THROW(parseCfTimeUnits("days since 2000-01-01", "mayan"), Error);
}

namespace
{
/// A forecast u/v(time?, lat, lon) on a 3 x 4 geographic grid. The time axis (when timeName is not empty) has
/// the given attributes (empty values are left out) and values; an extra variable `decoy` named "time" on its
/// own dimension is written when withDecoy (a time variable the velocities are not on).
struct TimeAxisFile
{
    std::string timeName, units, calendar, standardName, axis;
    std::vector<double> times;
    bool withDecoy{false};
};

void writeTimeAxisFile(const std::string &path, const TimeAxisFile &spec)
{
    NcWriter w(path);
    std::vector<int> dims;
    int vt = -1, vd = -1;
    if (!spec.timeName.empty())
    {
        const int dt = w.dim(spec.timeName, spec.times.size());
        vt = w.var(spec.timeName, NC_DOUBLE, {dt});
        for (const auto &[att, value] :
             {std::make_pair("units", spec.units), std::make_pair("calendar", spec.calendar),
              std::make_pair("standard_name", spec.standardName), std::make_pair("axis", spec.axis)})
            if (!value.empty())
                w.text(vt, att, value);
        dims.push_back(dt);
    }
    if (spec.withDecoy)
    {
        vd = w.var("time", NC_DOUBLE, {w.dim("time", 2)});
        w.text(vd, "units", "days since 2000-01-01");
    }
    const int dy = w.dim("lat", 3), dx = w.dim("lon", 4);
    const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    dims.push_back(dy);
    dims.push_back(dx);
    const int u = w.var("uo", NC_FLOAT, dims), v = w.var("vo", NC_FLOAT, dims);
    w.text(u, "units", "m/s");
    w.text(v, "units", "m/s");
    w.enddef();
    if (vt >= 0)
        w.put(vt, spec.times);
    if (vd >= 0)
        w.put(vd, {0.0, 1.0});
    w.put(vy, {10.0, 10.5, 11.0});
    w.put(vx, {20.0, 20.5, 21.0, 21.5});
    const std::size_t n = 12 * (spec.timeName.empty() ? 1 : spec.times.size());
    w.put(u, std::vector<double>(n, 0.1));
    w.put(v, std::vector<double>(n, -0.2));
}

std::string timeErrorOf(const std::function<void()> &f)
{
    try
    {
        f();
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}
} // namespace

TEST(ForecastTimeAxis, FoundByStandardNameAxisOrUnitsWhateverItsName)
{
    TempDir tmp;
    // NEMO style: time_counter, standard_name time, axis T, seconds since 1950-01-01 in the noleap calendar.
    // First time 2020-01-01: 1949 + 70 years of 365 days after 0001-01-01 (the noleap epoch).
    const std::string nemo = tmp.file("nemo.nc");
    writeTimeAxisFile(nemo, {"time_counter",
                             "seconds since 1950-01-01 00:00:00",
                             "noleap",
                             "time",
                             "T",
                             {70 * 365 * 86400.0, 70 * 365 * 86400.0 + 21600, 70 * 365 * 86400.0 + 43200}});
    const ForecastTimeAxis a = readForecastTimeAxis(nemo);
    EXPECT_TRUE(a.found);
    EXPECT_TRUE(a.dated);
    EXPECT_EQ(a.variable, "time_counter");
    EXPECT_EQ(a.calendar, Calendar::NoLeap);
    EXPECT_EQ(a.originSeconds, (1949.0 * 365 + 70 * 365) * 86400.0);
    EXPECT_EQ(a.size, 3u);
    EXPECT_EQ(a.span, 43200.0);
    EXPECT_EQ(formatDateTime(dateFromCalendarEpoch(a.originSeconds, a.calendar)), "2020-01-01T00:00:00Z");
    // the loader reads the same axis
    const GriddedCurrents loaded = loadGriddedCurrents(nemo);
    EXPECT_EQ(loaded.calendar, a.calendar);
    EXPECT_EQ(loaded.originSeconds, a.originSeconds);
    EXPECT_EQ(loaded.forecastEnd, a.span);

    // TIME (upper case), only units "days since ..." and no calendar (standard). 1950-01-01 is day 2433283 of
    // the Julian day numbers, 0001-01-01 of the Julian calendar (the standard calendar's epoch) day 1721424:
    // 711859 days, plus the first value 0.5 days.
    const std::string upper = tmp.file("upper.nc");
    writeTimeAxisFile(upper, {"TIME", "days since 1950-01-01", "", "", "", {0.5, 1.5, 2.5, 3.5}});
    const ForecastTimeAxis b = readForecastTimeAxis(upper);
    EXPECT_TRUE(b.found);
    EXPECT_TRUE(b.dated);
    EXPECT_EQ(b.variable, "TIME");
    EXPECT_EQ(b.calendar, Calendar::Standard);
    EXPECT_EQ(b.originSeconds, (711859 + 0.5) * 86400.0);
    EXPECT_EQ(b.size, 4u);
    EXPECT_EQ(b.span, 3 * 86400.0);
    EXPECT_EQ(loadGriddedCurrents(upper).originSeconds, b.originSeconds);

    // a name in no list, found by its units alone; 360_day calendar: 1999 years of 360 days to 2000-01-01
    const std::string odd = tmp.file("odd.nc");
    writeTimeAxisFile(odd, {"forecast_instant", "hours since 2000-01-01", "360_day", "", "", {6.0, 12.0}});
    const ForecastTimeAxis c = readForecastTimeAxis(odd);
    EXPECT_EQ(c.variable, "forecast_instant");
    EXPECT_EQ(c.calendar, Calendar::Day360);
    EXPECT_EQ(c.originSeconds, 1999.0 * 360 * 86400 + 6 * 3600.0);
    EXPECT_EQ(c.span, 6 * 3600.0);

    // axis T without "since": found but undated (raw values)
    const std::string raw = tmp.file("raw.nc");
    writeTimeAxisFile(raw, {"step", "", "", "", "T", {0.0, 2.0, 5.0}});
    const ForecastTimeAxis d = readForecastTimeAxis(raw);
    EXPECT_TRUE(d.found);
    EXPECT_FALSE(d.dated);
    EXPECT_EQ(d.variable, "step");
    EXPECT_EQ(d.originSeconds, 0.0);
    EXPECT_EQ(d.size, 3u);
    EXPECT_EQ(d.span, 5.0);

    // the time variable named explicitly (with the velocity name)
    const ForecastTimeAxis e = readForecastTimeAxis(nemo, "time_counter", "uo");
    EXPECT_EQ(e.variable, "time_counter");
    EXPECT_EQ(e.originSeconds, a.originSeconds);
}

TEST(ForecastTimeAxis, SteadyFilesHaveNoTimeAxisAndErrorsNameTheFile)
{
    TempDir tmp;
    // no time dimension on the velocities, although a variable "time" exists: a steady field, as the loader sees it
    const std::string steady = tmp.file("steady.nc");
    writeTimeAxisFile(steady, {"", "", "", "", "", {}, true});
    const ForecastTimeAxis a = readForecastTimeAxis(steady);
    EXPECT_FALSE(a.found);
    EXPECT_FALSE(a.dated);
    EXPECT_EQ(a.variable, "");
    EXPECT_EQ(a.size, 0u);
    EXPECT_EQ(loadGriddedCurrents(steady).loadedShape[0], 1u);

    // not NetCDF
    const std::string text = tmp.file("text.nc");
    std::FILE *fp = std::fopen(text.c_str(), "w");
    ASSERT_NE(fp, nullptr);
    std::fputs("not netcdf\n", fp);
    std::fclose(fp);
    std::string m = timeErrorOf([&] { readForecastTimeAxis(text); });
    EXPECT_NE(m.find("'" + text + "'"), std::string::npos) << m;
    EXPECT_NE(m.find("cannot open"), std::string::npos) << m;

    // a time variable named but missing; a velocity named but missing
    const std::string nemo = tmp.file("nemo.nc");
    writeTimeAxisFile(nemo, {"time_counter", "days since 1950-01-01", "noleap", "time", "T", {0.0, 1.0}});
    m = timeErrorOf([&] { readForecastTimeAxis(nemo, "time"); });
    EXPECT_NE(m.find("'time'"), std::string::npos) << m;
    EXPECT_NE(m.find(nemo), std::string::npos) << m;
    m = timeErrorOf([&] { readForecastTimeAxis(nemo, "", "water_u"); });
    EXPECT_NE(m.find("'water_u'"), std::string::npos) << m;

    // units the loader does not accept
    const std::string months = tmp.file("months.nc");
    writeTimeAxisFile(months, {"time", "months since 2000-01-01", "", "", "", {0.0, 1.0}});
    m = timeErrorOf([&] { readForecastTimeAxis(months); });
    EXPECT_NE(m.find("time variable 'time'"), std::string::npos) << m;
    EXPECT_NE(m.find(months), std::string::npos) << m;
}

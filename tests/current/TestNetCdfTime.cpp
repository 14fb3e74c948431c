// CF time units and calendars (standard, proleptic_gregorian, julian, noleap, all_leap, 360_day) and ISO dates.
#include <gtest/gtest.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CfTime.h"

using namespace ompl_glider;

namespace
{
double days(const std::string &a, const std::string &b, Calendar c)
{
    return (secondsSinceCalendarEpoch(parseDateTime(b), c) - secondsSinceCalendarEpoch(parseDateTime(a), c)) / 86400.0;
}
}  // namespace

TEST(CfTime, CalendarsCountDaysTheirOwnWay)
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
    EXPECT_EQ(days("1970-01-01", "2000-01-01", Calendar::Standard), 10957);  // known Unix-day count
    // the Gregorian reform: 1582-10-04 (Julian) is followed by 1582-10-15
    EXPECT_EQ(days("1582-10-04", "1582-10-15", Calendar::Standard), 1);
    EXPECT_EQ(days("1582-10-04", "1582-10-15", Calendar::ProlepticGregorian), 11);
    EXPECT_THROW(secondsSinceCalendarEpoch(parseDateTime("2001-02-29"), Calendar::Standard), Error);
    EXPECT_THROW(secondsSinceCalendarEpoch(parseDateTime("2000-02-29"), Calendar::NoLeap), Error);
    EXPECT_NO_THROW(secondsSinceCalendarEpoch(parseDateTime("2001-02-30"), Calendar::Day360));
}

TEST(CfTime, DatesRoundTripInEveryCalendar)
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

TEST(CfTime, ParsesUnitsAndIsoVariants)
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
    for (const char *bad : {"hours after 2000-01-01", "months since 2000-01-01", "fortnights since 2000-01-01",
                            "days since yesterday"})
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

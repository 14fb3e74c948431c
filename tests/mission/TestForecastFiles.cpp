// A forecast in daily files planned as one (the command line's --currents LIST and a mission's current.file list or
// glob): the same route and travel time as the one combined file, through the one pipeline (forecastMission() /
// loadMission() -> MissionProblem -> runMission()); the files read are what the problem reports.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../current/MultiFileForecast.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
/// The daily files named as a pilot downloads them: hycom_20260301.nc ...
struct Files : MfFiles
{
    Files() : MfFiles([](int d) { return "hycom_2026030" + std::to_string(d + 1) + ".nc"; }) {}
};

ForecastInput trip()
{
    ForecastInput in;
    in.start = {-52.8, 47.2};
    in.goal = {-52.2, 47.8};
    in.speed = 0.5;
    in.departure = "2026-03-01T18:00:00Z";
    return in;
}

void expectSamePlan(const MissionResult &a, const MissionResult &b)
{
    ASSERT_TRUE(a.plan.solved) << a.plan.reason;
    ASSERT_TRUE(b.plan.solved) << b.plan.reason;
    EXPECT_NEAR(a.plan.travelTime, b.plan.travelTime, 1e-9 * a.plan.travelTime);
    EXPECT_EQ(a.plan.departure, b.plan.departure);
    ASSERT_EQ(a.plan.path.size(), b.plan.path.size());
    for (std::size_t k = 0; k < a.plan.path.size(); ++k)
    {
        EXPECT_NEAR(a.plan.path[k].x, b.plan.path[k].x, 1e-6);
        EXPECT_NEAR(a.plan.path[k].y, b.plan.path[k].y, 1e-6);
    }
}
} // namespace

TEST(ForecastFiles, DailyFilesPlanAsTheCombinedFile)
{
    Files f;
    ForecastInput one = trip();
    one.current.file = f.combined;
    ForecastInput many = trip();
    many.current.files = {f.days[3], f.days[1], f.days[0], f.days[2]}; // any order
    const MissionSpec s1 = forecastMission(one), s2 = forecastMission(many);
    EXPECT_EQ(s2.current.files, many.current.files);
    EXPECT_EQ(s1.departure.time, s2.departure.time);
    ASSERT_TRUE(s2.fileCalendar);
    EXPECT_EQ(s1.fileCalendar->originSeconds, s2.fileCalendar->originSeconds);
    const MissionProblem p1(s1), p2(s2);
    EXPECT_EQ(p1.forecastFiles(), std::vector<std::string>{f.combined});
    // the trip (about a day from 18:00 on day 1) reads days 1 to 3 at most; day 4 only when the horizon reaches it
    ASSERT_GE(p2.forecastFiles().size(), 2u);
    EXPECT_EQ(p2.forecastFiles().front(), f.days[0]);
    const MissionResult r1 = runMission(p1), r2 = runMission(p2);
    expectSamePlan(r1, r2);
    EXPECT_GT(r1.plan.travelTime, 3600.0);
}

TEST(ForecastFiles, MissionFileTakesAGlobOrAList)
{
    Files f;
    const std::string dir = std::filesystem::path(f.combined).parent_path().string();
    const std::string rest = "start: {lon: -52.8, lat: 47.2}\n"
                             "goal: {lon: -52.2, lat: 47.8}\n"
                             "departure: {time: \"2026-03-01T18:00:00Z\"}\n"
                             "vehicle: {speed: 0.5}\n"
                             "travel_time: {eps: 1.0}\n";
    const MissionSpec single =
        parseMission("name: one\ncurrent: {type: netcdf, file: combined.nc}\n" + rest, "one.yaml", dir);
    const MissionSpec glob =
        parseMission("name: glob\ncurrent: {type: netcdf, file: \"hycom_*.nc\"}\n" + rest, "glob.yaml", dir);
    const MissionSpec list = parseMission("name: list\ncurrent:\n  type: netcdf\n  file: [hycom_20260303.nc, "
                                          "hycom_20260301.nc, \"hycom_2026030[24].nc\"]\n" +
                                              rest,
                                          "list.yaml", dir);
    ASSERT_EQ(glob.current.files.size(), 4u);
    ASSERT_EQ(list.current.files.size(), 4u);
    EXPECT_EQ(std::filesystem::path(glob.current.files[0]).filename(), "hycom_20260301.nc");
    EXPECT_EQ(glob.departure.time, single.departure.time);
    EXPECT_EQ(list.departure.time, single.departure.time);
    const MissionResult r1 = runMission(MissionProblem(single));
    const MissionResult r2 = runMission(MissionProblem(glob));
    const MissionResult r3 = runMission(MissionProblem(list));
    expectSamePlan(r1, r2);
    expectSamePlan(r1, r3);
    // a pattern that matches nothing: the mission file's line and field, and the pattern
    try
    {
        parseMission("name: none\ncurrent: {type: netcdf, file: \"gofs_*.nc\"}\n" + rest, "none.yaml", dir);
        FAIL() << "no error";
    }
    catch (const Error &e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("none.yaml:2"), std::string::npos) << msg;
        EXPECT_NE(msg.find("current.file"), std::string::npos) << msg;
        EXPECT_NE(msg.find("gofs_*.nc"), std::string::npos) << msg;
    }
}

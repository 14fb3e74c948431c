// The gridded current kind by its name `gridded` and by its alias `netcdf` (the name it had before it read Zarr,
// GRIB and OPeNDAP too): the registry finds one kind under both, a mission file may spell either, and both plan the
// same route to the bit; the mission keeps the name it was given (summary.json and the report say what the file
// says).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

namespace
{
const std::string kGriddedKindExamples = std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/";

/// examples/labrador_forecast.yaml with its current's type spelled @p type, without its departure window and its
/// dive profile (one departure: a quick plan).
std::string griddedKindMission(const std::string &type)
{
    return "name: labrador_" + type +
           "\n"
           "projection: {lon0: -52.0, lat0: 48.2}\n"
           "current:\n"
           "  type: " +
           type +
           "\n"
           "  file: labrador_forecast.nc\n"
           "  variables: {u: u, v: v, lon: lon, lat: lat, depth: depth, time: time}\n"
           "  interpolation: {xy: bicubic, time: akima}\n"
           "region: {lon_min: -52.9, lon_max: -51.1, lat_min: 47.7, lat_max: 48.7}\n"
           "start: {lon: -52.7, lat: 47.9}\n"
           "goal: {lon: -51.5, lat: 48.45}\n"
           "departure: {time: \"2026-03-15T06:00:00Z\"}\n"
           "vehicle: {speed: 0.3}\n"
           "travel_time: {eps: 1.0}\n"
           "planner: {name: zastartve, grid_size: 4000, sectors: 3}\n";
}

void expectIdenticalPlans(const MissionResult &a, const MissionResult &b)
{
    ASSERT_TRUE(a.plan.solved) << a.plan.reason;
    ASSERT_TRUE(b.plan.solved) << b.plan.reason;
    EXPECT_EQ(a.plan.travelTime, b.plan.travelTime); // one source, one pipeline: to the bit
    EXPECT_EQ(a.plan.departure, b.plan.departure);
    ASSERT_EQ(a.plan.path.size(), b.plan.path.size());
    for (std::size_t k = 0; k < a.plan.path.size(); ++k)
    {
        EXPECT_EQ(a.plan.path[k].x, b.plan.path[k].x);
        EXPECT_EQ(a.plan.path[k].y, b.plan.path[k].y);
    }
}
} // namespace

TEST(GriddedKind, RegistryFindsOneKindByNameAndAlias)
{
    const CurrentFieldKind *gridded = findCurrentFieldKind("gridded");
    ASSERT_NE(gridded, nullptr);
    EXPECT_EQ(findCurrentFieldKind("netcdf"), gridded);
    EXPECT_EQ(gridded->name, "gridded");
    EXPECT_TRUE(gridded->gridded());
    EXPECT_TRUE(isGriddedKind("gridded"));
    EXPECT_TRUE(isGriddedKind("netcdf"));
    EXPECT_FALSE(isGriddedKind("meandering_jet"));
    EXPECT_FALSE(isGriddedKind("no_such_kind"));
    const std::vector<std::string> names = currentFieldKindNames();
    EXPECT_NE(std::find(names.begin(), names.end(), "gridded"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "netcdf"), names.end());
    // the lists name the kinds, not their aliases
    EXPECT_NE(currentFieldKindList().find("gridded"), std::string::npos);
    EXPECT_EQ(currentFieldKindList().find("netcdf"), std::string::npos);
    EXPECT_EQ(griddedKindList(), "gridded");
}

TEST(GriddedKind, AnAliasIsNoFreeName)
{
    EXPECT_EQ(currentFieldKindAliases(*findCurrentFieldKind("gridded")), std::vector<std::string>{"netcdf"});
    EXPECT_TRUE(currentFieldKindAliases(*findCurrentFieldKind("uniform")).empty());
    CurrentFieldKind k = *findCurrentFieldKind("gridded");
    k.name = "netcdf"; // the alias of the built-in kind: taken
    EXPECT_THROW(registerCurrentFieldKind(k), Error);
    EXPECT_THROW(addCurrentFieldKindAlias("netcdf", "uniform"), Error);  // taken
    EXPECT_THROW(addCurrentFieldKindAlias("gridded", "uniform"), Error); // a kind's name
    EXPECT_THROW(addCurrentFieldKindAlias("", "gridded"), Error);
    EXPECT_THROW(addCurrentFieldKindAlias("steady", "no_such_kind"), Error);
    EXPECT_EQ(findCurrentFieldKind("steady"), nullptr);
    // (no alias is added here: the registry is the process's, shared by the tests of this executable)
}

TEST(GriddedKind, MissionFilesSpellingEitherNamePlanTheSameRoute)
{
    const MissionSpec alias = parseMission(griddedKindMission("netcdf"), "alias.yaml", kGriddedKindExamples);
    const MissionSpec named = parseMission(griddedKindMission("gridded"), "named.yaml", kGriddedKindExamples);
    // each keeps the name it was given (the outputs of existing missions stay as they were)
    EXPECT_EQ(alias.current.type, "netcdf");
    EXPECT_EQ(named.current.type, "gridded");
    EXPECT_TRUE(alias.current.isForecast());
    EXPECT_TRUE(named.current.isForecast());
    EXPECT_EQ(alias.departure.time, named.departure.time);
    expectIdenticalPlans(runMission(MissionProblem(alias)), runMission(MissionProblem(named)));
}

TEST(GriddedKind, ForecastInputNamingEitherNamePlansTheSameRoute)
{
    // the command line's --currents (no kind named: recorded by the gridded reader's name) and a caller naming the kind
    ForecastInput in;
    in.current.file = kGriddedKindExamples + "labrador_forecast.nc";
    in.start = {-52.7, 47.9};
    in.goal = {-51.5, 48.45};
    in.speed = 0.3;
    in.departure = "2026-03-15T06:00:00Z";
    const MissionSpec cli = forecastMission(in);
    in.current.type = "gridded";
    const MissionSpec named = forecastMission(in);
    in.current.type = "netcdf";
    const MissionSpec alias = forecastMission(in);
    EXPECT_EQ(cli.current.type, "gridded");
    EXPECT_EQ(named.current.type, "gridded");
    EXPECT_EQ(alias.current.type, "netcdf");
    const MissionResult r = runMission(MissionProblem(cli));
    expectIdenticalPlans(r, runMission(MissionProblem(named)));
    expectIdenticalPlans(r, runMission(MissionProblem(alias)));
}

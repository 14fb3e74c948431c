// Tests of the NetCDF seafloor depth that limits the dives (bilinear on lon/lat or x/y axes, positive="up",
// fill values as land) and of its use by a mission.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/io/GriddedBathymetry.h"

using namespace ompl_glider;

namespace
{
double plane(double lon, double lat)
{
    return 100.0 + 50.0 * (lon + 53.0) + 200.0 * (lat - 47.0);
}

/// Writes a CDL with depth(lat, lon) = plane(lon, lat) (or -plane with positive = "up"), lat descending, and one
/// fill value at (lon -51, lat 49); converts it with ncgen. Returns the NetCDF path.
std::string makeFile(const std::string &name, bool elevation, double lonShift = 0.0)
{
    const std::string dir = ::testing::TempDir();
    std::ofstream f(dir + name + ".cdl");
    f << "netcdf " << name << " {\ndimensions:\n lat = 5 ;\n lon = 5 ;\nvariables:\n double lat(lat) ;\n"
      << "  lat:units = \"degrees_north\" ;\n double lon(lon) ;\n  lon:units = \"degrees_east\" ;\n"
      << " float depth(lat, lon) ;\n  depth:_FillValue = -32767.f ;\n";
    if (elevation)
        f << "  depth:positive = \"up\" ;\n";
    f << "data:\n lat = 49, 48.5, 48, 47.5, 47 ;\n lon = " << -53 + lonShift << ", " << -52.5 + lonShift << ", "
      << -52 + lonShift << ", " << -51.5 + lonShift << ", " << -51 + lonShift << " ;\n depth =";
    bool first = true;
    for (double lat : {49.0, 48.5, 48.0, 47.5, 47.0})
        for (double lon : {-53.0, -52.5, -52.0, -51.5, -51.0})
        {
            f << (first ? " " : ", ");
            first = false;
            if (lat == 49.0 && lon == -51.0)
                f << "_";
            else
                f << (elevation ? -plane(lon, lat) : plane(lon, lat));
        }
    f << " ;\n}\n";
    f.close();
    const std::string nc = dir + name + ".nc";
    const std::string cmd = "ncgen -o " + nc + " " + dir + name + ".cdl";
    if (std::system(cmd.c_str()) != 0)
        throw std::runtime_error("ncgen failed");
    return nc;
}
} // namespace

TEST(GriddedBathymetry, BilinearOnGeographicAxes)
{
    for (bool elevation : {false, true})
    {
        const std::string path = makeFile(elevation ? "mission_bathy_elev" : "mission_bathy_depth", elevation);
        // identity "projection" for the test
        const GriddedBathymetry b(path, "depth", [](double x, double y) { return LonLat{x, y}; });
        EXPECT_TRUE(b.geographic());
        for (double lon = -53.0; lon <= -51.6; lon += 0.17)
            for (double lat = 47.0; lat <= 48.5; lat += 0.13)
                EXPECT_NEAR(b.seafloorDepth(lon, lat), plane(lon, lat), 1e-3) << lon << " " << lat;
        // The fill value is land (0); it pulls the cell next to it towards 0.
        EXPECT_DOUBLE_EQ(b.atAxes(-51.0, 49.0), 0.0);
        EXPECT_LT(b.atAxes(-51.25, 48.75), plane(-51.25, 48.75));
        // Outside the grid: nearest edge.
        EXPECT_NEAR(b.atAxes(-54.0, 47.0), plane(-53.0, 47.0), 1e-3);
    }
}

TEST(GriddedBathymetry, EitherLongitudeConvention)
{
    // a 0..360 file (307..309E) queried with the -180..180 longitudes every projection gives, and a -180..180 file
    // queried in 0..360: the same depths
    const GriddedBathymetry east(makeFile("mission_bathy_360", false, 360.0), "depth", [](double x, double y) {
        return LonLat{x, y};
    });
    const GriddedBathymetry west(makeFile("mission_bathy_180", false, 0.0), "depth", [](double x, double y) {
        return LonLat{x + 360.0, y};
    });
    for (double lon = -53.0; lon <= -51.6; lon += 0.17)
        for (double lat = 47.0; lat <= 48.5; lat += 0.13)
        {
            EXPECT_NEAR(east.seafloorDepth(lon, lat), plane(lon, lat), 1e-3) << lon << " " << lat;
            EXPECT_NEAR(west.seafloorDepth(lon, lat), plane(lon, lat), 1e-3) << lon << " " << lat;
        }
}

TEST(GriddedBathymetry, ErrorsNameFileAndVariable)
{
    const std::string path = makeFile("mission_bathy_depth2", false);
    try
    {
        GriddedBathymetry b(path, "elevation", {});
        FAIL();
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("'elevation'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_THROW(GriddedBathymetry(path, "depth", {}), Error); // geographic axes need a projection
    EXPECT_THROW(GriddedBathymetry("/nonexistent.nc", "depth", {}), Error);
}

TEST(GriddedBathymetry, LimitsTheDivesOfAMission)
{
    const std::string path = makeFile("mission_bathy_depth3", false);
    const std::string text = "name: b\nprojection: {lon0: -52, lat0: 48}\nunits: {length_m: 1000}\n"
                             "current: {type: uniform, parameters: {u: 0.1, v: 0}}\n"
                             "region: {x_min: -60, x_max: 60, y_min: -60, y_max: 60}\n"
                             "start: {x: -40, y: 0}\ngoal: {x: 40, y: 0}\n"
                             "dive_profile: {z_min: 0, z_max: 1000, climb_to_max: 0, min_range: 100, clearance: 20,\n"
                             "  bathymetry: {type: netcdf, file: " +
                             path + ", variable: depth}}\n";
    const MissionProblem problem(parseMission(text, "b.yaml"));
    const auto dive = problem.diveProfiles(0.5);
    ASSERT_TRUE(dive);
    // Uniform current: the dive depth changes nothing but where the seafloor is too shallow.
    const double t = dive->travelTime(dive->profiles()[0], -40, 0, 40, 0, 0);
    EXPECT_NEAR(t, 80.0 / 0.6, 1e-9);
    // The seafloor at the goal's longitude is about 100 + 50 * 1.54 + 200 = 377 m: a 20 m clearance still leaves water.
    const LonLat g = problem.toGeographic({40, 0});
    const GriddedBathymetry b(path, "depth", [&](double x, double y) { return problem.toGeographic({x, y}); });
    EXPECT_NEAR(b.seafloorDepth(40, 0), plane(g.lon, g.lat), 0.5);
    const std::string bad = "name: b\nprojection: {lon0: -52, lat0: 48}\n"
                            "current: {type: uniform}\nregion: {x_min: -1, x_max: 1, y_min: -1, y_max: 1}\n"
                            "start: {x: 0, y: 0}\ngoal: {x: 1, y: 0}\n"
                            "dive_profile: {z_min: 0, z_max: 100, bathymetry: {type: netcdf, file: " +
                            path + ", variable: nope}}\n";
    try // the bathymetry is read with the mission's other inputs, once, when the problem is made
    {
        const MissionProblem p2(parseMission(bad, "bad.yaml"));
        FAIL();
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("dive_profile.bathymetry"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'nope'"), std::string::npos) << e.what();
    }
}

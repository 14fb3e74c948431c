// Coastlines from GIS files: a real GSHHG extract (examples/jamaica_coast.geojson, made by scripts/make_coastline.sh)
// as forbidden land and map outline; the same land written by GDAL as a Shapefile in Web Mercator and as KML, a
// shoreline written as a closed line, and bad files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include "../current/TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Coastline.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
const std::string kJamaica = std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/jamaica_coast.geojson";

/// Even-odd point-in-ring test on lon/lat (an independent reference for the planner's polygons).
bool inside(const std::vector<LonLat> &ring, double lon, double lat)
{
    bool in = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    {
        const LonLat &a = ring[i], &b = ring[j];
        if ((a.lat > lat) != (b.lat > lat) && lon < (b.lon - a.lon) * (lat - a.lat) / (b.lat - a.lat) + a.lon)
            in = !in;
    }
    return in;
}

double ringArea(const std::vector<LonLat> &r)
{
    double a = 0;
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
        a += (r[j].lon - r[i].lon) * (r[j].lat + r[i].lat);
    return std::abs(0.5 * a);
}

/// How many of @p land's outer rings hold (lon, lat) (each land point should be in exactly one).
int polygonsHolding(const std::vector<LandPolygon> &land, double lon, double lat)
{
    int n = 0;
    for (const LandPolygon &p : land)
        n += inside(p.outer, lon, lat);
    return n;
}

/// Every ~200 m of the path's legs lies outside @p ring (lon/lat, the independent point-in-polygon above).
void expectPathOutside(const MissionProblem &problem, const std::vector<TimedPoint> &path,
                       const std::vector<LonLat> &ring)
{
    for (std::size_t k = 0; k + 1 < path.size(); ++k)
    {
        const TimedPoint &a = path[k], &b = path[k + 1];
        const int n = std::max(2, int(std::hypot(b.x - a.x, b.y - a.y) / 200.0));
        for (int q = 0; q <= n; ++q)
        {
            const double f = double(q) / n;
            const LonLat g = problem.toGeographic({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)});
            ASSERT_FALSE(inside(ring, g.lon, g.lat)) << "leg " << k << " at " << g.lon << ", " << g.lat;
        }
    }
}

/// Writes the polygons to a GDAL vector file of the given driver, in the given EPSG code.
void writeWithGdal(const std::string &path, const char *driver, int epsg, const std::vector<LandPolygon> &land,
                   bool asLines = false)
{
    GDALAllRegister();
    GDALDriver *drv = GetGDALDriverManager()->GetDriverByName(driver);
    ASSERT_NE(drv, nullptr) << driver;
    std::unique_ptr<GDALDataset> ds(drv->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    ASSERT_NE(ds, nullptr) << path;
    OGRSpatialReference srs, wgs84;
    srs.importFromEPSG(epsg);
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    wgs84.importFromEPSG(4326);
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&wgs84, &srs));
    OGRLayer *layer = ds->CreateLayer("land", &srs, asLines ? wkbLineString : wkbPolygon, nullptr);
    ASSERT_NE(layer, nullptr);
    for (const LandPolygon &p : land)
    {
        OGRLinearRing r;
        for (const LonLat &g : p.outer)
            r.addPoint(g.lon, g.lat);
        r.closeRings();
        std::unique_ptr<OGRGeometry> geom;
        if (asLines)
        {
            auto *l = new OGRLineString;
            l->addSubLineString(&r);
            geom.reset(l);
        }
        else
        {
            auto *poly = new OGRPolygon;
            poly->addRing(&r);
            geom.reset(poly);
        }
        ASSERT_EQ(geom->transform(ct.get()), OGRERR_NONE);
        OGRFeature f(layer->GetLayerDefn());
        f.SetGeometry(geom.get());
        ASSERT_EQ(layer->CreateFeature(&f), OGRERR_NONE);
    }
}

/// A 0.1-degree file over lon -79.5..-75, lat 16.5..19.5 with no land and a westward current of 0.1 m/s.
void writeCaribbean(const std::string &path)
{
    NcWriter w(path);
    const std::size_t nx = 46, ny = 31;
    const int dt = w.dim("time", 2), dy = w.dim("lat", ny), dx = w.dim("lon", nx);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy}),
              vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vt, "units", "days since 2026-06-01");
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    const int vu = w.var("uo", NC_FLOAT, {dt, dy, dx}), vv = w.var("vo", NC_FLOAT, {dt, dy, dx});
    w.text(vu, "standard_name", "eastward_sea_water_velocity");
    w.text(vv, "standard_name", "northward_sea_water_velocity");
    w.text(vu, "units", "m s-1");
    w.text(vv, "units", "m s-1");
    w.enddef();
    w.put(vt, {0.0, 30.0});
    w.put(vy, linspace(16.5, 0.1, ny));
    w.put(vx, linspace(-79.5, 0.1, nx));
    w.put(vu, std::vector<double>(2 * nx * ny, -0.1));
    w.put(vv, std::vector<double>(2 * nx * ny, 0.01));
}
} // namespace

TEST(Coastline, GshhgExtractOfJamaicaIsOneLandPolygon)
{
    const auto land = readLandPolygons(kJamaica, geoBox(-80, 16, -75, 20));
    ASSERT_EQ(land.size(), 1u);
    // Jamaica: about 11,000 km^2, 1.0 square degree at 18N (1 deg^2 = 111 x 105.6 km^2); GSHHG's low resolution
    // keeps the outline within a few per cent
    EXPECT_NEAR(ringArea(land[0].outer), 0.94, 0.1);
    EXPECT_TRUE(inside(land[0].outer, -77.3, 18.1));  // the island's interior
    EXPECT_FALSE(inside(land[0].outer, -77.3, 17.5)); // south of it
    // a box that holds only the eastern half: clipped to it
    const auto east = readLandPolygons(kJamaica, geoBox(-77.0, 16, -75, 20));
    ASSERT_EQ(east.size(), 1u);
    for (const LonLat &g : east[0].outer)
        EXPECT_GE(g.lon, -77.0 - 1e-9);
    EXPECT_LT(ringArea(east[0].outer), ringArea(land[0].outer));
    // a box away from it: nothing
    EXPECT_TRUE(readLandPolygons(kJamaica, geoBox(-70, 10, -65, 12)).empty());
}

TEST(Coastline, ShapefileInWebMercatorKmlAndClosedShorelinesReadTheSame)
{
    TempDir dir;
    const auto land = readLandPolygons(kJamaica, geoBox(-80, 16, -75, 20));
    ASSERT_EQ(land.size(), 1u);
    const double area = ringArea(land[0].outer);
    const std::string shp = dir.file("jamaica_3857.shp"), kml = dir.file("jamaica.kml"),
                      lines = dir.file("shore.geojson");
    writeWithGdal(shp, "ESRI Shapefile", 3857, land);
    writeWithGdal(kml, "KML", 4326, land);
    writeWithGdal(lines, "GeoJSON", 4326, land, true);
    for (const std::string &f : {shp, kml, lines})
    {
        const auto again = readLandPolygons(f, geoBox(-80, 16, -75, 20));
        ASSERT_EQ(again.size(), 1u) << f;
        EXPECT_NEAR(ringArea(again[0].outer), area, 1e-6 * area) << f;
        EXPECT_TRUE(inside(again[0].outer, -77.3, 18.1)) << f;
    }
}

TEST(Coastline, ALayerIn0To360LongitudesGivesItsLandInMinus180To180)
{
    // a GeoJSON without CRS whose longitudes run 0..360 (as some Pacific extracts are written): an island at
    // 200..202E (158..160W) and one across the antimeridian at 179..181E
    TempDir dir;
    const std::string path = dir.file("pacific360.geojson");
    std::ofstream(path) << R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates":
        [[[200, 20], [202, 20], [202, 22], [200, 22], [200, 20]]]}},
      {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates":
        [[[179, 30], [181, 30], [181, 31], [179, 31], [179, 30]]]}}]})";
    const auto east = readLandPolygons(path, geoBox(-165, 15, -150, 25));
    ASSERT_EQ(east.size(), 1u);
    EXPECT_NEAR(ringArea(east[0].outer), 4.0, 1e-9);
    EXPECT_TRUE(inside(east[0].outer, -159.0, 21.0));
    for (const LonLat &p : east[0].outer)
        EXPECT_TRUE(p.lon >= -180 && p.lon <= 180) << p.lon;
    // the box split at the antimeridian (as MissionProblem asks for it): both halves of the second island
    const auto west = readLandPolygons(path, geoBox(175, 25, 180, 35)),
               across = readLandPolygons(path, geoBox(-180, 25, -175, 35));
    ASSERT_EQ(west.size(), 1u);
    ASSERT_EQ(across.size(), 1u);
    EXPECT_NEAR(ringArea(west[0].outer), 1.0, 1e-9);
    EXPECT_NEAR(ringArea(across[0].outer), 1.0, 1e-9);
    EXPECT_TRUE(inside(across[0].outer, -179.5, 30.5));
}

TEST(Coastline, BadFilesAreErrorsNamingTheFile)
{
    TempDir dir;
    const std::string open = dir.file("open.geojson"), point = dir.file("point.geojson"), junk = dir.file("junk.shp");
    std::ofstream(open) << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
                           R"("geometry":{"type":"LineString","coordinates":[[-77,18],[-76,18.5],[-75.5,18]]}}]})";
    std::ofstream(point) << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
                            R"("geometry":{"type":"Point","coordinates":[-77,18]}}]})";
    std::ofstream(junk) << "not a shapefile";
    for (const auto &[file, phrase] : std::vector<std::pair<std::string, std::string>>{
             {open, "open line"}, {point, "Point"}, {junk, "cannot open"}, {dir.file("missing.kml"), "cannot open"}})
    {
        try
        {
            readLandPolygons(file, geoBox(-80, 16, -75, 20));
            ADD_FAILURE() << file;
        }
        catch (const Error &e)
        {
            const std::string msg = e.what();
            EXPECT_NE(msg.find(file), std::string::npos) << msg;
            EXPECT_NE(msg.find(phrase), std::string::npos) << msg;
        }
    }
}

TEST(Coastline, RouteGoesAroundJamaicaAndAStartOnItIsBadInput)
{
    TempDir dir;
    const std::string nc = dir.file("caribbean.nc");
    writeCaribbean(nc);
    ForecastInput in;
    in.current.file = nc;
    in.start = {-78.8, 18.2}; // west of Jamaica
    in.goal = {-75.8, 18.1};  // east of it
    in.speed = 0.4;
    // without the coastline the file has no land: the straight leg crosses the island
    const MissionProblem bare(forecastMission(in));
    const MissionResult rb = runMission(bare);
    ASSERT_TRUE(rb.plan.solved);
    EXPECT_TRUE(std::isfinite(rb.plan.straightLineTime));

    MissionSpec spec = forecastMission(in);
    spec.forbidden.coastline = kJamaica;
    const MissionProblem problem(spec);
    ASSERT_EQ(problem.getPolygons().size(), 1u);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.status << " " << r.plan.reason;
    EXPECT_TRUE(std::isinf(r.plan.straightLineTime));
    EXPECT_GT(r.plan.travelTime, rb.plan.travelTime);
    // every ~200 m of the route lies outside the island (independent point-in-polygon on lon/lat)
    const auto land = readLandPolygons(kJamaica, geoBox(-80, 16, -75, 20));
    expectPathOutside(problem, r.plan.path, land[0].outer);
    // a start on the island is bad input
    MissionSpec onLand = spec;
    onLand.start.lonLat.lon = onLand.start.xy.x = -77.3;
    onLand.start.lonLat.lat = onLand.start.xy.y = 18.1;
    const MissionProblem p2(onLand);
    const PlannedPath pp = planRoute(p2, p2.getSpec().departure.time);
    EXPECT_FALSE(pp.solved);
    EXPECT_EQ(pp.badInput.field(), "start");
}

namespace
{
/// A GeoJSON of one feature with the given name and geometry (JSON text).
std::string oneFeature(const std::string &name, const std::string &geometry)
{
    return R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"name":")" + name +
           R"("},"geometry":)" + geometry + "}]}";
}

// an island of lon -77.5..-76.5, lat 17.8..18.6 with a lagoon whose corner touches the outer ring at its
// south-west vertex (valid for GEOS, as in GSHHG's intermediate data)
const char *kTouchingLagoon =
    R"({"type":"Polygon","coordinates":[[[-77.5,17.8],[-76.5,17.8],[-76.5,18.6],[-77.5,18.6],[-77.5,17.8]],)"
    R"([[-77.5,17.8],[-77.0,18.0],[-77.2,18.3],[-77.5,17.8]]]})";
} // namespace

TEST(Coastline, AHoleTouchingItsOuterRingAtAVertexIsTakenAsItIs)
{
    TempDir dir;
    const std::string coast = dir.file("lagoon.geojson"), nc = dir.file("caribbean.nc");
    std::ofstream(coast) << oneFeature("Isla Laguna", kTouchingLagoon);
    std::vector<std::string> repairs;
    const auto land = readLandPolygons(coast, geoBox(-80, 16, -75, 20), &repairs);
    ASSERT_EQ(land.size(), 1u);
    EXPECT_EQ(land[0].holes.size(), 1u);
    EXPECT_EQ(land[0].name, "Isla Laguna");
    EXPECT_TRUE(repairs.empty()) << repairs.front();
    // the planner takes it: land is forbidden, the lagoon is water
    writeCaribbean(nc);
    ForecastInput in;
    in.current.file = nc;
    in.start = {-78.8, 18.2};
    in.goal = {-75.8, 18.1};
    in.speed = 0.4;
    MissionSpec spec = forecastMission(in);
    spec.forbidden.coastline = coast;
    spec.forbidden.coastlineMark = {"--coastline", 0, Origin::Flag};
    const MissionProblem problem(spec);
    ASSERT_EQ(problem.getPolygons().size(), 1u);
    EXPECT_EQ(problem.getPolygons()[0].name, "Isla Laguna");
    const Point2 onLand = problem.toLocal({-76.8, 18.4}), inLagoon = problem.toLocal({-77.2, 18.1});
    EXPECT_FALSE(problem.getEnvironment()->pointFree(onLand.x, onLand.y, spec.departure.time));
    EXPECT_TRUE(problem.getEnvironment()->pointFree(inLagoon.x, inLagoon.y, spec.departure.time));
    EXPECT_EQ(problem.coastlineNote().find("repaired"), std::string::npos) << problem.coastlineNote();
}

TEST(Coastline, AnInvalidPolygonIsRepairedAndTheRepairIsReported)
{
    TempDir dir;
    const std::string coast = dir.file("bowtie.geojson");
    // a bow tie: its outer ring crosses itself at lon -77, lat 18.2
    std::ofstream(coast) << oneFeature(
        "Bow Tie",
        R"({"type":"Polygon","coordinates":[[[-77.5,17.8],[-76.5,18.6],[-76.5,17.8],[-77.5,18.6],[-77.5,17.8]]]})");
    std::vector<std::string> repairs;
    const auto land = readLandPolygons(coast, geoBox(-80, 16, -75, 20), &repairs);
    ASSERT_EQ(repairs.size(), 1u);
    EXPECT_NE(repairs[0].find("'Bow Tie'"), std::string::npos) << repairs[0];
    EXPECT_NE(repairs[0].find("Self-intersection"), std::string::npos) << repairs[0];
    EXPECT_NE(repairs[0].find("-77"), std::string::npos) << repairs[0]; // where, in lon/lat
    // both triangles are land after the repair
    ASSERT_EQ(land.size(), 2u);
    EXPECT_EQ(polygonsHolding(land, -77.4, 18.2), 1); // west
    EXPECT_EQ(polygonsHolding(land, -76.6, 18.2), 1); // east
}

TEST(Coastline, ShorelinesInAGeometryCollectionAreLandOrRefusedNeverDropped)
{
    // Jamaica's GSHHG shoreline written as a closed LineString inside a GeometryCollection (as coastline extracts
    // often write it), beside a small square island as a polygon
    TempDir dir;
    const auto jamaica = readLandPolygons(kJamaica, geoBox(-80, 16, -75, 20));
    ASSERT_EQ(jamaica.size(), 1u);
    std::string ring;
    for (std::size_t k = 0; k <= jamaica[0].outer.size(); ++k)
    {
        const LonLat &p = jamaica[0].outer[k % jamaica[0].outer.size()];
        ring += (k ? "," : "") + std::string("[") + std::to_string(p.lon) + "," + std::to_string(p.lat) + "]";
    }
    const std::string coast = dir.file("collection.geojson");
    std::ofstream(coast) << oneFeature(
        "Shores", R"({"type":"GeometryCollection","geometries":[{"type":"LineString","coordinates":[)" + ring +
                      R"(]},{"type":"Polygon","coordinates":[[[-79,16.5],[-78.8,16.5],[-78.8,16.7],[-79,16.7],)"
                      R"([-79,16.5]]]}]})");
    const auto land = readLandPolygons(coast, geoBox(-80, 16, -75, 20));
    ASSERT_EQ(land.size(), 2u);
    EXPECT_EQ(polygonsHolding(land, -77.3, 18.1), 1); // Jamaica, from the closed line
    EXPECT_EQ(polygonsHolding(land, -78.9, 16.6), 1); // the square
    // the route from west to east of the island goes around it: every ~200 m outside the GSHHG ring
    const std::string nc = dir.file("caribbean.nc");
    writeCaribbean(nc);
    ForecastInput in;
    in.current.file = nc;
    in.start = {-78.8, 18.2};
    in.goal = {-75.8, 18.1};
    in.speed = 0.4;
    MissionSpec spec = forecastMission(in);
    spec.forbidden.coastline = coast;
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.status << " " << r.plan.reason;
    EXPECT_TRUE(std::isinf(r.plan.straightLineTime));
    expectPathOutside(problem, r.plan.path, jamaica[0].outer);
    // an open line or a point in a collection is refused, naming the feature and the member
    for (const auto &[member, phrase] : std::vector<std::pair<std::string, std::string>>{
             {R"({"type":"LineString","coordinates":[[-77,18],[-76,18.5],[-75.5,18]]})", "open line from lon -77"},
             {R"({"type":"Point","coordinates":[-77,18]})", "a Point"}})
    {
        const std::string bad = dir.file("bad_collection.geojson");
        std::ofstream(bad) << oneFeature(
            "Mixed", R"({"type":"GeometryCollection","geometries":[{"type":"Polygon","coordinates":[[[-79,16.5],)"
                     R"([-78.8,16.5],[-78.8,16.7],[-79,16.7],[-79,16.5]]]},)" +
                         member + "]}");
        try
        {
            readLandPolygons(bad, geoBox(-80, 16, -75, 20));
            ADD_FAILURE() << member << " was dropped in silence";
        }
        catch (const Error &e)
        {
            const std::string msg = e.what();
            EXPECT_NE(msg.find("'Mixed', member 2 of its collection"), std::string::npos) << msg;
            EXPECT_NE(msg.find(phrase), std::string::npos) << msg;
        }
    }
}

TEST(Coastline, ErrorsNameTheCoastlineFileTheFeatureAndLonLat)
{
    TempDir dir;
    const std::string coast = dir.file("cape.geojson"), nc = dir.file("caribbean.nc");
    std::ofstream(coast) << oneFeature("Cape Open",
                                       R"({"type":"LineString","coordinates":[[-77,18],[-76,18.5],[-75.5,18]]})");
    writeCaribbean(nc);
    ForecastInput in;
    in.current.file = nc;
    in.start = {-78.8, 18.2};
    in.goal = {-75.8, 18.1};
    MissionSpec spec = forecastMission(in);
    spec.forbidden.coastline = coast;
    spec.forbidden.coastlineMark = {"--coastline", 0, Origin::Flag};
    try
    {
        const MissionProblem problem(spec);
        ADD_FAILURE() << "an open line was taken as land";
    }
    catch (const Error &e)
    {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind("--coastline: ", 0), 0u) << msg;
        EXPECT_NE(msg.find(coast), std::string::npos) << msg;
        EXPECT_NE(msg.find("'Cape Open'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("lon -77, lat 18"), std::string::npos) << msg;
        EXPECT_EQ(msg.find(nc), std::string::npos) << msg; // not the forecast's file
    }
}

TEST(Coastline, MissionPolygonsGeosCallsValidAreTakenOthersNamedWithTheReason)
{
    TempDir dir;
    const std::string nc = dir.file("caribbean.nc");
    writeCaribbean(nc);
    ForecastInput in;
    in.current.file = nc;
    in.start = {-78.8, 18.2};
    in.goal = {-75.8, 18.1};
    MissionSpec spec = forecastMission(in);
    ObstacleSpec o;
    o.polygon.name = "reef";
    o.polygon.geographic = true;
    o.polygon.points = {{-77.5, 17.8}, {-76.5, 17.8}, {-76.5, 18.6}, {-77.5, 18.6}};
    o.polygon.holes = {{{-77.5, 17.8}, {-77.0, 18.0}, {-77.2, 18.3}}}; // touches the outer ring at a vertex
    spec.forbidden.obstacles = {o};
    EXPECT_NO_THROW(MissionProblem{spec});
    spec.forbidden.obstacles[0].polygon.holes.clear();
    spec.forbidden.obstacles[0].polygon.points = {{-77.5, 17.8}, {-76.5, 18.6}, {-76.5, 17.8}, {-77.5, 18.6}};
    try
    {
        const MissionProblem problem(spec);
        ADD_FAILURE() << "a bow tie was taken";
    }
    catch (const Error &e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("'reef'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("Self-intersection"), std::string::npos) << msg;
        EXPECT_NE(msg.find("lon lat"), std::string::npos) << msg;
    }
}

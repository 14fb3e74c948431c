// Isochrones through the pipeline: a mission with the output format "isochrones" writes
// isochrones.geojson with one feature per time; in a uniform current every contour is the closed-form circle; on a
// NetCDF forecast (geographic) the coordinates are lon/lat inside the forecast's box and the times are dates.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
fs::path scratch(const std::string &name)
{
    const fs::path d = fs::temp_directory_path() / ("ompl_glider_iso_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

nlohmann::json readJson(const fs::path &p)
{
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}
} // namespace

TEST(Isochrones, UniformCurrentContoursAreTheReachableCircles)
{
    const fs::path dir = scratch("uniform");
    {
        std::ofstream m(dir / "m.yaml");
        m << "name: iso\n"
             "current: {type: uniform, parameters: {u: 0.1, v: 0.05}}\n"
             "region: {x_min: 0, x_max: 10, y_min: -4, y_max: 4}\n"
             "start: {x: 2, y: 0}\n"
             "goal: {x: 8, y: 1}\n"
             "vehicle: {speed: 0.5}\n"
             "planner: {name: zastartve, grid_size: 0.5}\n"
             "outputs: {directory: out, files: [summary, isochrones], isochrone_interval: 2}\n";
    }
    const MissionProblem problem(loadMission((dir / "m.yaml").string()));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved);
    ASSERT_TRUE(r.isochrones);
    writeOutputs(r, problem);
    const nlohmann::json j = readJson(dir / "out" / "isochrones.geojson");
    ASSERT_EQ(j["type"], "FeatureCollection");
    const auto &features = j["features"];
    // every 2 time units up to the arrival
    ASSERT_EQ(features.size(), static_cast<std::size_t>(std::floor(r.plan.travelTime / 2.0)));
    const double h = j["resolution"].get<double>();
    for (std::size_t k = 0; k < features.size(); ++k)
    {
        const double t = features[k]["properties"]["time"].get<double>();
        EXPECT_NEAR(t, 2.0 * (k + 1), 1e-9);
        EXPECT_TRUE(features[k]["properties"]["time_iso"].is_null()); // no dates in a dimensionless mission
        // Nested discs (|c| < V): the set reached by t is the disc of centre start + c t, radius V t.
        const double cx = 2 + 0.1 * t, cy = 0.05 * t, R = 0.5 * t;
        std::size_t points = 0;
        for (const auto &line : features[k]["geometry"]["coordinates"])
            for (const auto &p : line)
            {
                const double x = p[0].get<double>(), y = p[1].get<double>();
                if (x <= 1e-9 || x >= 10 - 1e-9 || y <= -4 + 1e-9 || y >= 4 - 1e-9)
                    continue; // where the disc meets the region's edge
                EXPECT_NEAR(std::hypot(x - cx, y - cy), R, 0.5 * h) << "t = " << t;
                ++points;
            }
        EXPECT_GT(points, 20u);
    }
    fs::remove_all(dir);
}

TEST(Isochrones, ForecastIsochronesAreGeographicAndDated)
{
    // The repository's Labrador shelf forecast (a NetCDF file in the layout of a regional model) with its islands.
    const fs::path dir = scratch("labrador");
    const std::string src = OMPL_GLIDER_SOURCE_DIR;
    MissionSpec spec = loadMission(src + "/examples/labrador_forecast.yaml");
    spec.outputs.directory = (dir / "out").string();
    spec.outputs.files = {OutputFormatId::Summary, OutputFormatId::Isochrones};
    spec.departure.window = false; // one departure (the window's start): the test is about the isochrones
    spec.departure.time = spec.departure.begin;
    // what the test is about needs no dive profiles and no bicubic/Akima interpolation (5x the work, 12x more
    // sanitized)
    spec.dive.enabled = false;
    spec.current.xyInterpolation = Interp2D::Bilinear;
    spec.current.timeInterpolation = Interp1D::Linear;
    spec.current.depthInterpolation = Interp1D::Linear;
    const MissionProblem problem(spec);
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.isochrones);
    writeOutputs(r, problem);
    const nlohmann::json j = readJson(dir / "out" / "isochrones.geojson");
    const auto &features = j["features"];
    ASSERT_EQ(features.size(), 8u);
    double last = -1e300;
    const LonLat s = problem.toGeographic(problem.getStart());
    for (const auto &f : features)
    {
        const double t = f["properties"]["time"].get<double>();
        EXPECT_GT(t, last);
        last = t;
        ASSERT_TRUE(f["properties"]["time_iso"].is_string());
        EXPECT_EQ(f["properties"]["time_iso"].get<std::string>().size(), 20u); // 2026-03-15T06:00:00Z
        for (const auto &line : f["geometry"]["coordinates"])
            for (const auto &p : line)
            {
                const double lon = p[0].get<double>(), lat = p[1].get<double>();
                EXPECT_GE(lon, -180.0);
                EXPECT_LE(lon, 180.0);
                // within a few degrees of the start: lon/lat, not metres
                EXPECT_LT(std::abs(lon - s.lon), 10.0);
                EXPECT_LT(std::abs(lat - s.lat), 10.0);
            }
    }
    fs::remove_all(dir);
}

// Eight threads plan at once, each on its own forecast, through every reader that calls a library that is not
// thread-safe: NetCDF datasets in memory, NetCDF files, Zarr stores (GDAL), OPeNDAP URLs (NetCDF-C's DAP client,
// from the tests' DAP2 server on 127.0.0.1), half of them with a coastline file (GDAL/OGR), each writing its outputs
// as the others plan. Each answer must be the one the same plan gives alone, to the bit (src/io/DatasetLock.h: one
// lock around every NetCDF-C call and GDAL dataset).
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include "../current/TestNetCdfUtil.h"
#include "../opendap/DapServer.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/output/RouteFiles.h"

extern char **environ;

namespace
{
using namespace ompl_glider;
using glider_test::linspace;
using glider_test::NcWriter;
using glider_test::TempDir;
namespace fs = std::filesystem;

const std::string kJamaicaCoast = std::string(OMPL_GLIDER_SOURCE_DIR) + "/examples/jamaica_coast.geojson";
constexpr std::size_t kSourceNx = 26, kNy = 16, kNt = 2;

/// The currents of forecast @p k (each thread its own): a westward stream with a meander, stronger for larger k.
std::vector<double> velocity(int k, bool east)
{
    std::vector<double> out;
    for (std::size_t t = 0; t < kNt; ++t)
        for (std::size_t j = 0; j < kNy; ++j)
            for (std::size_t i = 0; i < kSourceNx; ++i)
                out.push_back(east ? -0.05 - 0.02 * k + 0.04 * std::sin(0.5 * double(j) + double(t))
                                   : 0.03 * std::cos(0.4 * double(i)) + 0.005 * k);
    return out;
}

const std::vector<double> kTime{0.0, 30.0};
const std::vector<double> kLat = linspace(17.3, 0.08, kNy), kLon = linspace(-79.2, 0.08, kSourceNx);

/// Forecast @p k as a CDF-5 NetCDF file (a classic file: its bytes are also a dataset NetCDF-C opens in memory).
void writeNetCdf(const std::string &path, int k)
{
    NcWriter w(path, NC_CLOBBER | NC_64BIT_DATA);
    const int dt = w.dim("time", kNt), dy = w.dim("lat", kNy), dx = w.dim("lon", kSourceNx);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("lat", NC_DOUBLE, {dy}),
              vx = w.var("lon", NC_DOUBLE, {dx});
    w.text(vt, "units", "days since 2026-06-01");
    w.text(vy, "units", "degrees_north");
    w.text(vx, "units", "degrees_east");
    const int vu = w.var("uo", NC_DOUBLE, {dt, dy, dx}), vv = w.var("vo", NC_DOUBLE, {dt, dy, dx});
    w.text(vu, "standard_name", "eastward_sea_water_velocity");
    w.text(vv, "standard_name", "northward_sea_water_velocity");
    w.text(vu, "units", "m s-1");
    w.text(vv, "units", "m s-1");
    w.enddef();
    w.put(vt, kTime);
    w.put(vy, kLat);
    w.put(vx, kLon);
    w.put(vu, velocity(k, true));
    w.put(vv, velocity(k, false));
}

/// One array of a Zarr v2 store: a single uncompressed chunk of little-endian doubles.
void writeZarrArray(const fs::path &store, const std::string &name, const std::vector<std::string> &dims,
                    const std::vector<std::size_t> &shape, const std::vector<double> &values, const std::string &attrs)
{
    fs::create_directories(store / name);
    std::string s, d, key;
    for (std::size_t k = 0; k < shape.size(); ++k)
    {
        s += (k ? ", " : "") + std::to_string(shape[k]);
        d += std::string(k ? ", " : "") + "\"" + dims[k] + "\"";
        key += std::string(k ? "." : "") + "0";
    }
    std::ofstream(store / name / ".zarray") << "{\"zarr_format\": 2, \"shape\": [" << s << "], \"chunks\": [" << s
                                            << "], \"dtype\": \"<f8\", \"compressor\": null, \"fill_value\": null, "
                                               "\"order\": \"C\", \"filters\": null}";
    std::ofstream(store / name / ".zattrs") << "{\"_ARRAY_DIMENSIONS\": [" << d << "]" << attrs << "}";
    std::ofstream(store / name / key, std::ios::binary)
        .write(reinterpret_cast<const char *>(values.data()), static_cast<std::streamsize>(values.size() * 8));
}

/// Forecast @p k as a Zarr store (the same values as its NetCDF file).
void writeZarr(const fs::path &store, int k)
{
    fs::create_directories(store);
    std::ofstream(store / ".zgroup") << "{\"zarr_format\": 2}";
    writeZarrArray(store, "time", {"time"}, {kNt}, kTime, ", \"units\": \"days since 2026-06-01\"");
    writeZarrArray(store, "lat", {"lat"}, {kNy}, kLat, ", \"units\": \"degrees_north\"");
    writeZarrArray(store, "lon", {"lon"}, {kSourceNx}, kLon, ", \"units\": \"degrees_east\"");
    writeZarrArray(store, "uo", {"time", "lat", "lon"}, {kNt, kNy, kSourceNx}, velocity(k, true),
                   ", \"units\": \"m s-1\", \"standard_name\": \"eastward_sea_water_velocity\"");
    writeZarrArray(store, "vo", {"time", "lat", "lon"}, {kNt, kNy, kSourceNx}, velocity(k, false),
                   ", \"units\": \"m s-1\", \"standard_name\": \"northward_sea_water_velocity\"");
}

std::string slurp(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Answer
{
    double travelTime{0.0};
    std::string waypoints; ///< waypoints.csv as the output layer writes it
    std::string error;
};

/// Plans forecast source @p source (a file, a store, a URL, or "memory": @p bytes registered anew), with the
/// coastline for odd @p k, and writes the outputs into @p out.
Answer planOn(int k, const std::string &source, const std::string &bytes, const std::string &out)
{
    Answer a;
    try
    {
        ForecastInput in;
        in.current.file = source == "memory" ? registerMemoryDataset(bytes) : source;
        in.start = {-79.0, 17.6};
        in.goal = {-77.6, 17.5};
        in.speed = 0.4;
        MissionSpec spec = forecastMission(in);
        if (k % 2 == 1)
            spec.forbidden.coastline = kJamaicaCoast;
        spec.planner.globalCheck = false;
        spec.outputs.files = {OutputFormatId::Summary, OutputFormatId::Csv, OutputFormatId::GeoJson,
                              OutputFormatId::Path};
        const MissionProblem problem(spec);
        const MissionResult r = runMission(problem);
        if (!r.plan.solved)
            throw Error("no path: " + r.plan.reason);
        a.travelTime = r.plan.travelTime;
        a.waypoints = waypointsCsv(r);
        writeOutputFiles(out, outputFiles(r, problem));
        if (slurp(out + "/waypoints.csv") != a.waypoints)
            throw Error("waypoints.csv written is not the result's");
        if (isMemoryDataset(in.current.file))
            releaseMemoryDataset(in.current.file);
    }
    catch (const std::exception &e)
    {
        a.error = e.what();
    }
    return a;
}
} // namespace

TEST(ConcurrentSources, EightThreadsPlanOnMemoryFilesZarrAndUrlsAsEachAlone)
{
    TempDir dir;
    const std::string served = dir.file("served");
    fs::create_directories(served);
    dap_test::DapServer server(served); // starting while the forecasts are written
    constexpr int kThreads = 8;
    std::vector<std::string> alone(kThreads), together(kThreads), bytes(kThreads);
    for (int k = 0; k < kThreads; ++k)
    {
        const std::string nc = dir.file("f" + std::to_string(k) + ".nc");
        writeNetCdf(nc, k);
        bytes[k] = slurp(nc);
        switch (k % 4)
        {
        case 0: // NetCDF-C in memory
            alone[k] = together[k] = "memory";
            break;
        case 1: // a NetCDF file
            alone[k] = together[k] = nc;
            break;
        case 2: // a Zarr store through GDAL
            writeZarr(dir.file("f" + std::to_string(k) + ".zarr"), k);
            alone[k] = together[k] = dir.file("f" + std::to_string(k) + ".zarr");
            break;
        default: // a URL: two names, since the process keeps a URL's dataset and values once read
            fs::copy_file(nc, served + "/alone" + std::to_string(k) + ".nc");
            fs::copy_file(nc, served + "/together" + std::to_string(k) + ".nc");
            alone[k] = "alone" + std::to_string(k) + ".nc";
            together[k] = "together" + std::to_string(k) + ".nc";
        }
    }
    for (int k = 3; k < kThreads; k += 4)
        alone[k] = server.url(alone[k]), together[k] = server.url(together[k]);

    std::vector<Answer> first(kThreads), second(kThreads);
    for (int k = 0; k < kThreads; ++k)
    {
        first[k] = planOn(k, alone[k], bytes[k], dir.file("alone_out" + std::to_string(k)));
        ASSERT_TRUE(first[k].error.empty()) << alone[k] << ": " << first[k].error;
    }
    // the travel times differ between the forecasts: an answer read from another thread's dataset would show
    for (int k = 1; k < kThreads; ++k)
        EXPECT_NE(first[k].travelTime, first[k - 1].travelTime);

    std::mutex m;
    std::condition_variable go;
    int ready = 0;
    std::vector<std::thread> threads;
    for (int k = 0; k < kThreads; ++k)
        threads.emplace_back([&, k] {
            {
                std::unique_lock<std::mutex> lock(m);
                if (++ready == kThreads)
                    go.notify_all();
                go.wait(lock, [&] { return ready == kThreads; }); // all start at once
            }
            second[k] = planOn(k, together[k], bytes[k], dir.file("out" + std::to_string(k)));
        });
    for (std::thread &t : threads)
        t.join();
    for (int k = 0; k < kThreads; ++k)
    {
        ASSERT_TRUE(second[k].error.empty()) << together[k] << ": " << second[k].error;
        EXPECT_EQ(second[k].travelTime, first[k].travelTime) << together[k]; // to the bit
        EXPECT_EQ(second[k].waypoints, first[k].waypoints) << together[k];
    }
}

// A deployment's many DAC correcting the forecast (optimal interpolation, [BrethertonOI]): the time to build the
// corrected problem and plan on it, against the plan on the uncorrected forecast, as the DAC grow from 8 to 5000. The
// DAC come from ten gliders crossing the Labrador forecast's region over the day before the departure
// (examples/labrador_forecast.nc), each the forecast there plus a uniform error of (0.05, -0.03) m/s and 2 cm/s of
// noise; with --repeat N each reading is written N times a second apart (the same current measured again). Prints, for
// each count, the DAC the correction used (at most its 2000 most recent), the wall time of the correction and of the
// plan, their ratio to the uncorrected forecast's, the cost of one velocity (200000 random points over the box and
// three days), the travel time, and the largest eastward correction along the region's middle line (never above the
// innovations' range: the error plus its noise). The plans differ (the corrected current moves the route), so the
// plan times compare searches of different problems; the cost of a velocity compares the fields.
//
// Usage: bench_many_dac [--counts 0,8,200,1000,2000,5000] [--forecast examples/labrador_forecast.nc] [--repeat 1]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Observations.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
/// @p n DAC over the day before 2026-03-16T00:00Z, from ten gliders on straight tracks across the region, in a CSV;
/// with @p repeat > 1 each reading is written that many times (the same current measured again).
std::string writeDac(const fs::path &dir, int n, int repeat, const MissionProblem &forecast)
{
    const fs::path f = dir / ("dac_" + std::to_string(n) + "_" + std::to_string(repeat) + ".csv");
    std::ofstream out(f);
    out << "time,lon,lat,u,v\n";
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, 0.02);
    const double end = parseIsoTime("2026-03-16T00:00:00Z");
    const int gliders = 10, each = std::max(1, n / (gliders * repeat));
    for (int g = 0; g < gliders && n > 0; ++g)
        for (int k = 0; k < each; ++k)
        {
            const double s = each > 1 ? static_cast<double>(k) / (each - 1) : 1.0;
            const double lon = -52.8 + 1.6 * s, lat = 47.75 + 0.09 * g + 0.05 * s;
            const double t = end - 86400.0 * (1.0 - s) - 60.0 * g;
            // the forecast there (its local x/y is east/north to within the projection's small turn) plus the error
            const Point2 at = forecast.toLocal({lon, lat});
            const Velocity f = forecast.getField()->velocity(at.x, at.y, 0.0, t);
            const double u = f.u + 0.05 + noise(rng), v = f.v - 0.03 + noise(rng);
            for (int r = 0; r < repeat; ++r)
                out << formatIsoTime(t - r) << "," << lon << "," << lat << "," << u << "," << v << "\n";
        }
    out << formatIsoTime(end) << ",-52.7,47.9,,\n"; // the last fix: where the mission starts
    return f.string();
}
} // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    std::string countsText = "0,8,200,1000,2000,5000", forecast = "examples/labrador_forecast.nc";
    int repeat = 1;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string k = argv[i];
        if (k == "--counts")
            countsText = argv[i + 1];
        else if (k == "--forecast")
            forecast = argv[i + 1];
        else if (k == "--repeat")
            repeat = std::max(1, std::atoi(argv[i + 1]));
        else
        {
            std::fprintf(stderr, "usage: bench_many_dac [--counts 0,8,200,1000] [--forecast FILE.nc] [--repeat N]\n");
            return 2;
        }
    }
    if (!fs::exists(forecast))
    {
        std::fprintf(stderr, "bench_many_dac: no forecast '%s' (run from the source tree, or give --forecast)\n",
                     forecast.c_str());
        return 2;
    }
    std::vector<int> counts;
    std::stringstream in(countsText);
    for (std::string c; std::getline(in, c, ',');)
        counts.push_back(std::atoi(c.c_str()));
    const fs::path dir = fs::temp_directory_path() / "bench_many_dac";
    fs::create_directories(dir);
    const std::string base = "name: many_dac\ncurrent: {type: netcdf, file: '" + fs::absolute(forecast).string() +
                             "'}\nregion: {lon_min: -52.9, lon_max: -51.1, lat_min: 47.7, lat_max: 48.7}\n"
                             "goal: {lon: -51.5, lat: 48.45}\nvehicle: {speed: 0.3}\nplanner: {grid_size: 4000}\n";
    std::printf("%6s %6s %10s %10s %8s %10s %12s %12s\n", "DAC", "used", "correct s", "plan s", "ratio", "eval ns",
                "travel h", "max du m/s");
    double plain = 0.0;
    std::shared_ptr<const CurrentField> forecastField;
    std::unique_ptr<MissionProblem> plainProblem;
    for (const int n : counts)
    {
        if (n > 0 && !plainProblem)
        {
            std::fprintf(stderr, "bench_many_dac: the counts begin with 0 (the uncorrected forecast)\n");
            return 2;
        }
        const std::string yaml =
            n == 0 ? base + "start: {lon: -52.7, lat: 47.9}\ndeparture: {time: '2026-03-16T00:00:00Z'}\n"
                   : base + "observations: '" + writeDac(dir, n, repeat, *plainProblem) + "'\n";
        const auto t0 = std::chrono::steady_clock::now();
        const MissionProblem problem(parseMission(yaml, "many_dac.yaml"));
        const auto t1 = std::chrono::steady_clock::now();
        const MissionResult r = runMission(problem);
        const auto t2 = std::chrono::steady_clock::now();
        const double correct = std::chrono::duration<double>(t1 - t0).count();
        const double plan = std::chrono::duration<double>(t2 - t1).count();
        if (n == 0)
        {
            plain = correct + plan;
            forecastField = problem.getField();
            plainProblem = std::make_unique<MissionProblem>(parseMission(yaml, "many_dac.yaml"));
        }
        // the cost of one velocity: 200000 points over the box and the plan's span
        const Region box = problem.getBox();
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> ux(box.xMin, box.xMax), uy(box.yMin, box.yMax), ut(0.0, 1.0);
        const double from = problem.getSpec().departure.time, span = 3.0 * 86400.0;
        double sink = 0.0;
        const auto e0 = std::chrono::steady_clock::now();
        for (int i = 0; i < 200000; ++i)
            sink += problem.getField()->velocity(ux(rng), uy(rng), 0.0, from + span * ut(rng)).u;
        const double evalNs =
            std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - e0).count() / 200000.0;
        if (!std::isfinite(sink))
            std::printf("(a velocity not finite)\n");
        // the largest eastward correction along the region's middle line at the departure (the corrected field less
        // the forecast's)
        double largest = 0.0;
        if (forecastField && n > 0)
        {
            const double y = 0.5 * (box.yMin + box.yMax), t = r.plan.departure;
            for (int i = 0; i <= 200; ++i)
            {
                const double x = box.xMin + (box.xMax - box.xMin) * i / 200.0;
                const double du =
                    problem.getField()->velocity(x, y, 0.0, t).u - forecastField->velocity(x, y, 0.0, t).u;
                largest = std::max(largest, std::abs(du));
            }
        }
        const auto &o = problem.observations();
        std::printf("%6d %6zu %10.2f %10.2f %8.2f %10.0f %12.2f %12.3f\n", n, o ? o->correction.used : 0, correct, plan,
                    plain > 0.0 ? (correct + plan) / plain : NAN, evalNs,
                    r.plan.solved ? r.plan.travelTime / 3600.0 : NAN, largest);
    }
    return 0;
}

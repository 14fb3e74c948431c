// The comparison of [IsernObstacles] Tables I-III in shape, on our own scenarios: remaining distance to
// the goal after a 4-day mission of 8 h stints for direct to goal, CTS-A*, Optim and Init-Optim, relative to
// Init-Optim (mean and standard deviation over random start/goal pairs with islands near the route), and the
// computing time of each, at 0.4 and 0.2 m/s; on the meandering jet (10 km per length unit, 12500 s per time unit:
// V = 0.5 is 0.4 m/s) and on a NetCDF forecast written here (jet and eddies in m/s, islands as land cells).
// Every plan goes through the one pipeline (planRoute() on a MissionProblem, the planner by its registry name).
//
//   bench_stints [--pairs N] [--seed S] [--scenario jet|forecast|all] [--speeds 0.4,0.2] [--dir DIR]
//   bench_stints --conversion                 lattice paths flown as stints: loss against stint length
//   bench_stints --map FILE.png [--pair K]    the four methods' stint tracks on one map (jet, 0.4 m/s)
#include <netcdf.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/MissionMap.h"

using namespace ompl_glider;

namespace
{
const std::vector<std::string> kMethods = {"init_optim", "optim", "cts_astar", "direct"};
constexpr double kLengthUnit = 10000.0; // jet: metres per length unit
constexpr double kTimeUnit = 12500.0;   // jet: seconds per time unit (V = 0.5 -> 0.4 m/s)

struct Pair
{
    Point2 start, goal;
    std::vector<std::vector<std::pair<double, double>>> islands;
};

std::vector<std::pair<double, double>> box(double cx, double cy, double hx, double hy)
{
    return {{cx - hx, cy - hy}, {cx + hx, cy - hy}, {cx + hx, cy + hy}, {cx - hx, cy + hy}};
}

bool inside(const std::vector<std::pair<double, double>> &b, Point2 p, double margin)
{
    return p.x > b[0].first - margin && p.x < b[1].first + margin && p.y > b[0].second - margin &&
           p.y < b[2].second + margin;
}

/// Jet pairs: start in x 2..8, goal 20..28 units away (200-280 km: 4 days at 0.4 m/s cover 138 km in still water,
/// the jet adds up to 0.8 m/s) within 60 degrees of east, two islands of 15 x 10 km near the straight line (at 35 % and
/// 65 %, offset up to 10 km).
std::vector<Pair> jetPairs(int n, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::vector<Pair> pairs;
    while (static_cast<int>(pairs.size()) < n)
    {
        Pair p;
        p.start = {2.0 + 6.0 * U(rng), -5.0 + 10.0 * U(rng)};
        const double d = 20.0 + 8.0 * U(rng), a = (-60.0 + 120.0 * U(rng)) * M_PI / 180.0;
        p.goal = {p.start.x + d * std::cos(a), p.start.y + d * std::sin(a)};
        if (p.goal.y < -12.0 || p.goal.y > 12.0)
            continue;
        bool ok = true;
        for (double f : {0.35, 0.65})
        {
            const double off = -1.0 + 2.0 * U(rng);
            const double cx = p.start.x + f * (p.goal.x - p.start.x) - off * std::sin(a);
            const double cy = p.start.y + f * (p.goal.y - p.start.y) + off * std::cos(a);
            p.islands.push_back(box(cx, cy, 0.75, 0.5));
            ok = ok && !inside(p.islands.back(), p.start, 0.3) && !inside(p.islands.back(), p.goal, 0.3);
        }
        if (ok)
            pairs.push_back(p);
    }
    return pairs;
}

MissionSpec jetMission(const Pair &p, double speedMs)
{
    MissionSpec m;
    m.file = "<bench_stints>";
    m.name = "stints_jet";
    m.lengthUnitMetres = kLengthUnit;
    m.timeUnitSeconds = kTimeUnit;
    m.current.type = "meandering_jet";
    m.region.set = true;
    m.region.xy = {-5, 45, -15, 15};
    m.start.xy = p.start;
    m.goal.xy = p.goal;
    m.vehicle.speed = speedMs * kTimeUnit / kLengthUnit;
    m.travel.speed = m.vehicle.speed;
    for (std::size_t k = 0; k < p.islands.size(); ++k)
    {
        ObstacleSpec o;
        o.polygon.name = "island " + std::to_string(k + 1);
        o.polygon.points = p.islands[k];
        m.forbidden.obstacles.push_back(o);
    }
    m.stints.set = true;
    m.stints.duration = 8.0 * 3600.0 / kTimeUnit;
    m.stints.missionDuration = 4.0 * 86400.0 / kTimeUnit;
    m.stints.bearingStep = 20.0;
    m.outputs.files = {OutputFormatId::Summary};
    return m;
}

/// A 5-day hourly forecast on a 4 km Cartesian grid (x 0..400 km, y -160..160 km): the meandering jet in m/s (10 km
/// and 12500 s per unit) plus two eddies, and two islands (fill values) at (150, -10) km and (230, 35) km.
struct ForecastIslands
{
    std::vector<std::vector<std::pair<double, double>>> boxes;
};
ForecastIslands writeForecast(const std::string &path)
{
    const int nx = 101, ny = 81, nt = 121;
    const float fill = -999.0f;
    ForecastIslands isl;
    isl.boxes = {box(150e3, -10e3, 14e3, 10e3), box(230e3, 35e3, 12e3, 14e3)};
    const MeanderingJet jet;
    std::vector<double> xs(nx), ys(ny), ts(nt);
    for (int i = 0; i < nx; ++i)
        xs[i] = 4000.0 * i;
    for (int j = 0; j < ny; ++j)
        ys[j] = -160000.0 + 4000.0 * j;
    for (int k = 0; k < nt; ++k)
        ts[k] = 3600.0 * k;
    std::vector<float> u(static_cast<std::size_t>(nt) * ny * nx), v(u.size());
    for (int k = 0; k < nt; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const std::size_t idx = (static_cast<std::size_t>(k) * ny + j) * nx + i;
                bool land = false;
                for (const auto &b : isl.boxes)
                    land = land || inside(b, {xs[i], ys[j]}, 0.0);
                if (land)
                {
                    u[idx] = v[idx] = fill;
                    continue;
                }
                const Velocity c = jet.velocity(xs[i] / kLengthUnit, ys[j] / kLengthUnit, 0.0, ts[k] / kTimeUnit);
                double uu = 0.8 * c.u, vv = 0.8 * c.v;
                // two eddies (Gaussian vortices of 30 km radius, 0.3 m/s), drifting west at 2 km/h
                for (const auto &[ex, ey, s] :
                     {std::array<double, 3>{260e3, -70e3, 1.0}, std::array<double, 3>{120e3, 80e3, -1.0}})
                {
                    const double cx = ex - 0.55 * ts[k], dx = xs[i] - cx, dy = ys[j] - ey;
                    const double g = 0.3 * s * std::exp(-(dx * dx + dy * dy) / (2.0 * 30e3 * 30e3)) / 30e3 * 1.65;
                    uu += -g * dy;
                    vv += g * dx;
                }
                u[idx] = static_cast<float>(uu);
                v[idx] = static_cast<float>(vv);
            }
    int nc, dx, dy, dt, vx, vy, vt, vu, vv;
    auto ok = [](int s) {
        if (s != NC_NOERR)
        {
            std::fprintf(stderr, "netcdf: %s\n", nc_strerror(s));
            std::exit(2);
        }
    };
    ok(nc_create(path.c_str(), NC_CLOBBER | NC_64BIT_OFFSET, &nc));
    ok(nc_def_dim(nc, "time", nt, &dt));
    ok(nc_def_dim(nc, "y", ny, &dy));
    ok(nc_def_dim(nc, "x", nx, &dx));
    ok(nc_def_var(nc, "time", NC_DOUBLE, 1, &dt, &vt));
    ok(nc_def_var(nc, "y", NC_DOUBLE, 1, &dy, &vy));
    ok(nc_def_var(nc, "x", NC_DOUBLE, 1, &dx, &vx));
    const int dims[3] = {dt, dy, dx};
    ok(nc_def_var(nc, "u", NC_FLOAT, 3, dims, &vu));
    ok(nc_def_var(nc, "v", NC_FLOAT, 3, dims, &vv));
    auto text = [&](int var, const char *name, const char *value) {
        ok(nc_put_att_text(nc, var, name, std::strlen(value), value));
    };
    text(vt, "units", "seconds since 2026-04-01 00:00:00");
    text(vt, "standard_name", "time");
    text(vx, "units", "m");
    text(vx, "standard_name", "projection_x_coordinate");
    text(vy, "units", "m");
    text(vy, "standard_name", "projection_y_coordinate");
    text(vu, "units", "m/s");
    text(vu, "standard_name", "eastward_sea_water_velocity");
    text(vv, "units", "m/s");
    text(vv, "standard_name", "northward_sea_water_velocity");
    ok(nc_put_att_float(nc, vu, "_FillValue", NC_FLOAT, 1, &fill));
    ok(nc_put_att_float(nc, vv, "_FillValue", NC_FLOAT, 1, &fill));
    ok(nc_enddef(nc));
    ok(nc_put_var_double(nc, vt, ts.data()));
    ok(nc_put_var_double(nc, vy, ys.data()));
    ok(nc_put_var_double(nc, vx, xs.data()));
    ok(nc_put_var_float(nc, vu, u.data()));
    ok(nc_put_var_float(nc, vv, v.data()));
    ok(nc_close(nc));
    return isl;
}

/// Forecast pairs: start in x 20..80 km, y -100..100 km; goal 180..260 km away within 50 degrees of east, the
/// straight line passing within 25 km of an island's centre.
std::vector<Pair> forecastPairs(int n, unsigned seed, const ForecastIslands &isl)
{
    std::mt19937 rng(seed + 7);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::vector<Pair> pairs;
    while (static_cast<int>(pairs.size()) < n)
    {
        Pair p;
        p.start = {20e3 + 60e3 * U(rng), -100e3 + 200e3 * U(rng)};
        const double d = 180e3 + 80e3 * U(rng), a = (-50.0 + 100.0 * U(rng)) * M_PI / 180.0;
        p.goal = {p.start.x + d * std::cos(a), p.start.y + d * std::sin(a)};
        if (p.goal.x > 390e3 || std::abs(p.goal.y) > 150e3)
            continue;
        bool near = false, clear = true;
        for (const auto &b : isl.boxes)
        {
            const double cx = 0.5 * (b[0].first + b[1].first), cy = 0.5 * (b[0].second + b[2].second);
            const double ex = p.goal.x - p.start.x, ey = p.goal.y - p.start.y;
            const double q =
                std::clamp(((cx - p.start.x) * ex + (cy - p.start.y) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
            near = near || std::hypot(p.start.x + q * ex - cx, p.start.y + q * ey - cy) < 25e3;
            clear = clear && !inside(b, p.start, 8e3) && !inside(b, p.goal, 8e3);
        }
        if (near && clear)
            pairs.push_back(p);
    }
    return pairs;
}

MissionSpec forecastMission(const Pair &p, double speedMs, const std::string &file)
{
    MissionSpec m;
    m.file = "<bench_stints>";
    m.name = "stints_forecast";
    m.current.type = "netcdf";
    m.current.file = file;
    m.current.variables = {{"x", "x"}, {"y", "y"}};
    m.start.xy = p.start;
    m.goal.xy = p.goal;
    m.vehicle.speed = speedMs;
    m.travel.speed = speedMs;
    m.travel.eps = 1.0;
    m.stints.set = true;
    m.stints.duration = 8.0 * 3600.0;
    m.stints.missionDuration = 4.0 * 86400.0;
    m.stints.bearingStep = 20.0;
    m.outputs.files = {OutputFormatId::Summary};
    return m;
}

struct Stat
{
    std::vector<double> diff, time, remaining;
    int grounded{0}, better{0}; // stopped on land; pairs where the method leaves less than Init-Optim
};

double mean(const std::vector<double> &v)
{
    double s = 0;
    for (double x : v)
        s += x;
    return v.empty() ? NAN : s / v.size();
}
double stdev(const std::vector<double> &v)
{
    const double m = mean(v);
    double s = 0;
    for (double x : v)
        s += (x - m) * (x - m);
    return v.size() < 2 ? 0.0 : std::sqrt(s / (v.size() - 1));
}

void runScenario(const char *title, const std::vector<MissionSpec> &missions, double metresPerUnit)
{
    std::map<std::string, Stat> stats;
    for (std::size_t i = 0; i < missions.size(); ++i)
    {
        std::map<std::string, double> rem;
        for (const std::string &method : kMethods)
        {
            MissionSpec m = missions[i];
            m.planner.name = method;
            const MissionProblem problem(m);
            const PlannedPath p = planRoute(problem, m.departure.time);
            if (!p.solved || !p.stints)
            {
                std::fprintf(stderr, "pair %zu %s: no plan (%s)\n", i, method.c_str(), p.reason.c_str());
                continue;
            }
            const double km = p.stints->plan.remainingDistance * metresPerUnit / 1000.0;
            rem[method] = km;
            stats[method].time.push_back(p.planningSeconds);
            stats[method].remaining.push_back(km);
            stats[method].grounded += p.stints->plan.grounded ? 1 : 0;
        }
        for (const std::string &method : kMethods)
            if (rem.count(method) && rem.count("init_optim"))
            {
                stats[method].diff.push_back(rem[method] - rem["init_optim"]);
                stats[method].better += rem[method] < rem["init_optim"] - 1e-9 ? 1 : 0;
            }
        std::fprintf(stderr, "%s: pair %zu/%zu done\n", title, i + 1, missions.size());
    }
    std::printf("\n%s (%zu start/goal pairs)\n\n", title, missions.size());
    std::printf(
        "| method | remaining distance, km: mean (std) | difference to Init-Optim, km: mean (std) | "
        "pairs it beats Init-Optim | stopped on land | computing time, s: mean (std) |\n|---|---|---|---|---|---|\n");
    const char *names[] = {"Init-Optim", "Optim", "CTS-A*", "Direct to goal"};
    for (std::size_t k = 0; k < kMethods.size(); ++k)
    {
        const Stat &s = stats[kMethods[k]];
        std::printf("| %s | %.1f (%.1f) | %.1f (%.1f) | %d | %d | %.2f (%.2f) |\n", names[k], mean(s.remaining),
                    stdev(s.remaining), mean(s.diff), stdev(s.diff), s.better, s.grounded, mean(s.time), stdev(s.time));
    }
    std::fflush(stdout);
}

void conversion()
{
    const std::vector<std::array<double, 4>> rows = {{1.0, -3.0, 8.0, 3.0}, {1.0, 3.0, 9.0, -2.5},
                                                     {2.0, -3.5, 7.0, 3.5}, {0.5, -2.0, 9.5, 2.0},
                                                     {2.0, 3.5, 8.0, -3.5}, {0.5, 3.0, 5.0, -3.0}};
    std::printf("Lattice (ZA*TVE + smoothing + refinement) paths flown as stints, the unstarred jet problems of "
                "test_planner_vs_optimum (1 h = 0.288 time units)\n\n| stint length | mean loss | worst loss | "
                "stints (mean) | conversion time, s (mean) |\n|---|---|---|---|---|\n");
    for (double hours : {0.5, 1.0, 2.0, 4.0, 8.0})
    {
        std::vector<double> loss, count, secs;
        for (const auto &r : rows)
        {
            MissionSpec m = defaultGulfStreamMission();
            m.start.xy = {r[0], r[1]};
            m.goal.xy = {r[2], r[3]};
            m.stints.set = true;
            m.stints.duration = hours * 3600.0 / kTimeUnit;
            m.stints.missionDuration = 40.0;
            const MissionProblem problem(m);
            const PlannedPath p = planRoute(problem, 0.0);
            loss.push_back(p.stints ? p.stints->loss : INFINITY);
            count.push_back(p.stints ? p.stints->plan.bearings.size() : 0);
            secs.push_back(p.stints ? p.stints->seconds : NAN);
        }
        double worst = -INFINITY;
        for (double l : loss)
            worst = std::max(worst, l);
        std::printf("| %.1f h | %+.2f %% | %+.2f %% | %.1f | %.2f |\n", hours, 100.0 * mean(loss), 100.0 * worst,
                    mean(count), mean(secs));
    }
}

void drawMap(const std::string &file, int index, int pairs, unsigned seed)
{
    const Pair p = jetPairs(std::max(pairs, index + 1), seed)[index];
    const MissionSpec base = jetMission(p, 0.4);
    std::vector<std::pair<std::string, PlannedPath>> plans;
    MissionSpec first = base;
    first.planner.name = "init_optim";
    const MissionProblem problem(first);
    MissionResult r = runMission(problem);
    MapRenderer map = missionMap(r, problem);
    const char *names[] = {"optim", "cts_astar", "direct"};
    for (std::size_t k = 1; k < kMethods.size(); ++k)
    {
        MissionSpec m = base;
        m.planner.name = kMethods[k];
        const PlannedPath q = planRoute(MissionProblem(m), 0.0);
        char label[160];
        std::snprintf(label, sizeof label, "%s: %zu stints, %.1f km left%s", names[k - 1],
                      q.stints->plan.bearings.size(), q.stints->plan.remainingDistance * kLengthUnit / 1000.0,
                      q.stints->plan.grounded ? ", land" : "");
        map.addPath(MapRenderer::stintTrackStyle(label, q.stints->plan.track, static_cast<int>(k)));
    }
    map.writePng(file);
    std::printf("map of pair %d written to %s (Init-Optim remaining %.1f km)\n", index, file.c_str(),
                r.plan.stints->plan.remainingDistance * kLengthUnit / 1000.0);
}
} // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN); // one line per solve would drown the tables
    int pairs = 20, mapPair = 0;
    unsigned seed = 14;
    std::string scenario = "all", dir = ".", mapFile;
    std::vector<double> speeds = {0.4, 0.2};
    bool conv = false;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc)
            {
                std::fprintf(stderr, "%s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--pairs")
            pairs = std::stoi(next());
        else if (a == "--seed")
            seed = static_cast<unsigned>(std::stoul(next()));
        else if (a == "--scenario")
            scenario = next();
        else if (a == "--dir")
            dir = next();
        else if (a == "--speeds")
        {
            speeds.clear();
            std::string s = next();
            for (std::size_t p = 0; p < s.size();)
            {
                const std::size_t q = s.find(',', p);
                speeds.push_back(std::stod(s.substr(p, q - p)));
                p = q == std::string::npos ? s.size() : q + 1;
            }
        }
        else if (a == "--conversion")
            conv = true;
        else if (a == "--map")
            mapFile = next();
        else if (a == "--pair")
            mapPair = std::stoi(next());
        else
        {
            std::fprintf(stderr, "usage: bench_stints [--pairs N] [--seed S] [--scenario jet|forecast|all] "
                                 "[--speeds 0.4,0.2] [--dir DIR] | --conversion | --map FILE.png [--pair K]\n");
            return 2;
        }
    }
    if (conv)
    {
        conversion();
        return 0;
    }
    if (!mapFile.empty())
    {
        drawMap(mapFile, mapPair, pairs, seed);
        return 0;
    }
    if (scenario == "jet" || scenario == "all")
    {
        const std::vector<Pair> ps = jetPairs(pairs, seed);
        for (double v : speeds)
        {
            std::vector<MissionSpec> ms;
            for (const Pair &p : ps)
                ms.push_back(jetMission(p, v));
            char title[160];
            std::snprintf(title, sizeof title,
                          "Meandering jet with two islands near each route, V = %.1f m/s, 8 h stints, 4 days", v);
            runScenario(title, ms, kLengthUnit);
        }
    }
    if (scenario == "forecast" || scenario == "all")
    {
        const std::string file = dir + "/bench_stints_forecast.nc";
        const ForecastIslands isl = writeForecast(file);
        const std::vector<Pair> ps = forecastPairs(pairs, seed, isl);
        for (double v : speeds)
        {
            std::vector<MissionSpec> ms;
            for (const Pair &p : ps)
                ms.push_back(forecastMission(p, v, file));
            char title[160];
            std::snprintf(title, sizeof title,
                          "NetCDF forecast (jet and eddies, two islands), V = %.1f m/s, 8 h stints, 4 days", v);
            runScenario(title, ms, 1.0);
        }
    }
    return 0;
}

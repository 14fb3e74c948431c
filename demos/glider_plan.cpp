// glider_plan: plans the built-in Gulf Stream mission (meandering jet, 000 Sec. 6.1) with ZA*TVE, smoothing
// (000 Table 3) and waypoint refinement, prints the result and optionally writes summary.json, path.csv and a map;
// or runs a YAML mission file (--mission, issue 6), or plans on a NetCDF forecast (--currents, issue 5).
// The work is done by the library (mission/PlanRun.h, mission/MissionOutputs.h); this file only parses flags.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionOutputs.h"
#include "ompl_glider/mission/PlanRun.h"

namespace
{
constexpr int kUsageError = 2;

void usage(std::ostream &out)
{
    out << "Usage: glider_plan [options]                  built-in Gulf Stream mission\n"
           "       glider_plan --mission FILE.yaml [--out DIR] [--speeds LIST]\n"
           "       glider_plan --currents FILE.nc --start lon,lat --goal lon,lat [options]\n"
           "Plans a time-optimal glider route and prints travel time, path length, waypoints, CFC and CMC.\n"
           "Without --mission / --currents: the built-in Gulf Stream model (meandering jet, x in [0, 10],\n"
           "y in [-4, 4], V = 0.5, dimensionless units).\n"
           "\n"
           "Common options:\n"
           "  --start x,y        start (built-in default 1,-3; with --currents lon,lat for a geographic file)\n"
           "  --goal x,y         goal (built-in default 8,3; with --currents lon,lat for a geographic file)\n"
           "  --departure t      departure time: built-in a number (default 0); with --currents an ISO 8601 time\n"
           "                     (2026-03-15T06:00:00Z) or seconds after the first forecast time (default: the\n"
           "                     first forecast time)\n"
           "  --speed V          vehicle speed through water (built-in default 0.5; --currents: m/s, default 0.3)\n"
           "  --speeds LIST      speed sweep, e.g. 0.25,0.30,0.35: travel time and path length per speed\n"
           "                     (003 Table VI), also with --mission (overrides the mission's 'speeds')\n"
           "  --planner NAME     TVE | A*TVE | ZTVE | ZA*TVE (default) | RRTstar | InformedRRTstar | PRM | PRMstar | RRT\n"
           "  --grid-size g      lattice spacing for the TVE family (built-in default 0.4; --currents: metres,\n"
           "                     default half the smallest grid cell, kept within 1/200..1/25 of the start-goal\n"
           "                     distance, two significant digits)\n"
           "  --sectors n        lattice connectivity 1..5 (default 3)\n"
           "  --time-limit s     planner time limit in seconds (default 10; sampling planners use all of it)\n"
           "  --no-smooth        skip path smoothing (000 Table 3)\n"
           "  --no-refine        skip waypoint refinement\n"
           "  --out DIR          write the outputs into DIR: built-in and --currents: summary.json, path.csv,\n"
           "                     map.svg, map.png (--currents also waypoints.csv, path.geojson, goto_l10.ma);\n"
           "                     --mission: the mission's files (overrides outputs.directory)\n"
           "  --optimum          built-in only: also solve Zermelo's optimal-control problem (shooting) and compare\n"
           "  --verbose          show OMPL's log messages\n"
           "  --help             this text\n"
           "\n"
           "Mission file (issue 6; format: examples/MISSION_FORMAT.md):\n"
           "  --mission FILE     run a YAML mission end to end; only --out, --speeds and --verbose go with it\n"
           "\n"
           "NetCDF forecast (issue 5):\n"
           "  --currents FILE    plan on the u/v currents of a NetCDF file (CF names found automatically)\n"
           "  --u-var NAME       eastward velocity variable      --v-var NAME      northward velocity variable\n"
           "  --lon-var NAME     longitude (or x) variable       --lat-var NAME    latitude (or y) variable\n"
           "  --depth-var NAME   depth variable                  --time-var NAME   time variable\n"
           "  --xy-interp S      nearest | bilinear (default) | bicubic\n"
           "  --time-interp S    nearest | linear (default) | cubic | akima\n"
           "  --depth-interp S   nearest | linear (default) | cubic | akima\n"
           "  --beyond P         past the last forecast time: refuse (default; such trips are infeasible) |\n"
           "                     hold (hold the last field)\n"
           "  --depth z          depth in metres (positive down) at which the current is read (default 0; not\n"
           "                     below the file's deepest layer)\n"
           "  Only the trip's region is loaded: the start-goal box plus half its larger side on each side.\n"
           "  The path.csv columns are t,x,y,lon,lat (t seconds after the first forecast time, x/y metres in the\n"
           "  local projection).\n"
           "\n"
           "Exit status: 0 path found, 1 no path, 2 bad arguments or input (nothing written).\n";
}

struct UsageError
{
    std::string message;
};

double parseNumber(const std::string &flag, const std::string &text)
{
    std::size_t used = 0;
    double v = 0.0;
    try
    {
        v = std::stod(text, &used);
    }
    catch (const std::exception &)
    {
        used = 0;
    }
    if (used == 0 || used != text.size() || !std::isfinite(v))
        throw UsageError{flag + " expects a finite number, got '" + text + "'"};
    return v;
}

void parsePair(const std::string &flag, const std::string &text, double &x, double &y)
{
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos)
        throw UsageError{flag + " expects x,y (two numbers separated by a comma), got '" + text + "'"};
    x = parseNumber(flag, text.substr(0, comma));
    y = parseNumber(flag, text.substr(comma + 1));
}
}  // namespace

int main(int argc, char **argv)
{
    using namespace ompl_glider;
    PlanRequest req;
    req.problem = gulfStreamProblem();
    ForecastPlanRequest fc;
    std::string outDir, missionFile, departureText, speedText;
    std::optional<std::vector<double>> speeds;
    std::set<std::string> given;  // flags seen (for incompatible combinations)
    bool verbose = false;
    double sx = req.problem.startX, sy = req.problem.startY, gx = req.problem.goalX, gy = req.problem.goalY;
    try
    {
        // "--flag=value" is the same as "--flag value" (handy for values starting with '-': --start=-52.7,47.9).
        std::vector<std::string> args;
        for (int k = 1; k < argc; ++k)
        {
            const std::string a = argv[k];
            const std::size_t eq = a.find('=');
            if (a.rfind("--", 0) == 0 && eq != std::string::npos)
            {
                args.push_back(a.substr(0, eq));
                args.push_back(a.substr(eq + 1));
            }
            else
                args.push_back(a);
        }
        for (std::size_t i = 0; i < args.size(); ++i)
        {
            const std::string &a = args[i];
            auto value = [&]() -> const std::string & {
                if (i + 1 >= args.size())
                    throw UsageError{a + " needs a value"};
                return args[++i];
            };
            auto scheme = [&](const std::vector<std::string> &allowed) {
                const std::string &v = value();
                if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
                {
                    std::string list;
                    for (const auto &x : allowed)
                        list += (list.empty() ? "" : " | ") + x;
                    throw UsageError{a + " expects " + list + ", got '" + v + "'"};
                }
                return v;
            };
            if (a.rfind("--", 0) == 0)
                given.insert(a);
            if (a == "--help" || a == "-h")
            {
                usage(std::cout);
                return 0;
            }
            else if (a == "--start")
                parsePair(a, value(), sx, sy);
            else if (a == "--goal")
                parsePair(a, value(), gx, gy);
            else if (a == "--departure")
                departureText = value();
            else if (a == "--speed")
            {
                speedText = value();
                if (!(parseNumber(a, speedText) > 0.0))
                    throw UsageError{"--speed must be > 0"};
            }
            else if (a == "--speeds")
            {
                try
                {
                    speeds = parseSpeedList(value());
                }
                catch (const Error &e)
                {
                    throw UsageError{e.what()};
                }
            }
            else if (a == "--planner")
                req.planner = value();
            else if (a == "--grid-size")
            {
                req.gridSize = parseNumber(a, value());
                if (!(req.gridSize > 0.0))
                    throw UsageError{"--grid-size must be > 0"};
            }
            else if (a == "--sectors")
            {
                const double n = parseNumber(a, value());
                if (n != std::floor(n) || n < 1 || n > 5)
                    throw UsageError{"--sectors expects an integer in 1..5"};
                req.sectors = static_cast<unsigned>(n);
            }
            else if (a == "--time-limit")
            {
                req.timeLimit = parseNumber(a, value());
                if (!(req.timeLimit > 0.0))
                    throw UsageError{"--time-limit must be > 0"};
            }
            else if (a == "--no-smooth")
                req.smooth = false;
            else if (a == "--no-refine")
                req.refine = false;
            else if (a == "--out")
                outDir = value();
            else if (a == "--optimum")
                req.optimum = true;
            else if (a == "--verbose")
                verbose = true;
            else if (a == "--mission")
                missionFile = value();
            else if (a == "--currents")
                fc.file = value();
            else if (a == "--u-var" || a == "--v-var" || a == "--lon-var" || a == "--lat-var" || a == "--depth-var" ||
                     a == "--time-var")
            {
                const std::string role = a.substr(2, a.size() - 6);
                const std::string &v = value();
                if (v.empty())
                    throw UsageError{a + " needs a variable name"};
                fc.variables[role] = v;
            }
            else if (a == "--xy-interp")
                fc.xyInterpolation = scheme({"nearest", "bilinear", "bicubic"});
            else if (a == "--time-interp")
                fc.timeInterpolation = scheme({"nearest", "linear", "cubic", "akima"});
            else if (a == "--depth-interp")
                fc.depthInterpolation = scheme({"nearest", "linear", "cubic", "akima"});
            else if (a == "--beyond")
                fc.horizonPolicy = scheme({"hold", "refuse"}) == "hold" ? "hold_last" : "refuse";
            else if (a == "--depth")
            {
                fc.depth = parseNumber(a, value());
                if (fc.depth < 0.0)
                    throw UsageError{"--depth expects metres >= 0 (positive down)"};
            }
            else
                throw UsageError{"unknown option '" + a + "'"};
        }
        const auto &names = plannerNames();
        if (std::find(names.begin(), names.end(), req.planner) == names.end())
            throw UsageError{"unknown planner '" + req.planner + "' (see --help)"};

        // Incompatible combinations.
        const std::vector<std::string> netcdfFlags = {"--u-var",       "--v-var",       "--lon-var", "--lat-var",
                                                      "--depth-var",   "--time-var",    "--xy-interp",
                                                      "--time-interp", "--depth-interp", "--beyond", "--depth"};
        if (!missionFile.empty())
        {
            for (const std::string &f : given)
                if (f != "--mission" && f != "--out" && f != "--speeds" && f != "--verbose")
                    throw UsageError{"--mission takes its settings from the mission file: " + f +
                                     " cannot be combined with it (only --out, --speeds and --verbose can)"};
        }
        else if (!fc.file.empty())
        {
            if (req.optimum)
                throw UsageError{"--optimum works only for the built-in mission, not with --currents"};
        }
        else
        {
            for (const std::string &f : netcdfFlags)
                if (given.count(f))
                    throw UsageError{f + " needs --currents FILE"};
        }
    }
    catch (const UsageError &e)
    {
        std::cerr << "glider_plan: " << e.message << "\nTry 'glider_plan --help'.\n";
        return kUsageError;
    }

    if (!verbose)
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

    if (!missionFile.empty())
    {
        MissionCommandOptions o;
        o.speeds = speeds;
        if (!outDir.empty())
            o.outputDirectory = outDir;
        return runMissionFile(missionFile, o, std::cout, std::cerr);
    }

    if (!fc.file.empty())
    {
        fc.startSet = given.count("--start") > 0;
        fc.goalSet = given.count("--goal") > 0;
        fc.startA = sx;
        fc.startB = sy;
        fc.goalA = gx;
        fc.goalB = gy;
        fc.departure = departureText;
        if (!speedText.empty())
            fc.speed = std::stod(speedText);
        fc.planner = req.planner;
        fc.gridSize = given.count("--grid-size") ? req.gridSize : 0.0;
        fc.sectors = req.sectors;
        fc.smooth = req.smooth;
        fc.refine = req.refine;
        fc.timeLimit = req.timeLimit;
        return runForecastCommand(fc, speeds, outDir, true, std::cout, std::cerr);
    }

    // The built-in Gulf Stream mission.
    try
    {
        req.problem.startX = sx;
        req.problem.startY = sy;
        req.problem.goalX = gx;
        req.problem.goalY = gy;
        if (!departureText.empty())
            req.problem.t0 = parseNumber("--departure", departureText);
        if (!speedText.empty())
            req.problem.travel.speed = std::stod(speedText);
    }
    catch (const UsageError &e)
    {
        std::cerr << "glider_plan: " << e.message << "\nTry 'glider_plan --help'.\n";
        return kUsageError;
    }
    try
    {
        PlanRunResult result = runPlan(req);
        if (speeds)
            result.speedSweep = planSpeedSweep(req, *speeds);
        printPlanReport(std::cout, req, result);
        if (!outDir.empty())
        {
            for (const std::string &f : writePlanOutputs(req, result, outDir))
                std::cout << "wrote " << f << "\n";
        }
        return result.feasible ? 0 : 1;
    }
    catch (const Error &e)
    {
        std::cerr << "glider_plan: " << e.what() << "\n";
        return kUsageError;
    }
}

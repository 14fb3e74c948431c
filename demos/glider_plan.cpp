// glider_plan: plans the built-in Gulf Stream mission (meandering jet, 000 Sec. 6.1) with ZA*TVE, smoothing
// (000 Table 3) and waypoint refinement, prints the result and optionally writes summary.json, path.csv and a map.
// The work is done by the library (mission/PlanRun.h); this file only parses flags.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/PlanRun.h"

namespace
{
constexpr int kUsageError = 2;

void usage(std::ostream &out)
{
    out << "Usage: glider_plan [options]\n"
           "Plans a time-optimal glider route through the built-in Gulf Stream model (meandering jet,\n"
           "x in [0, 10], y in [-4, 4], V = 0.5) and prints travel time, path length, waypoints, CFC and CMC.\n"
           "\n"
           "Options:\n"
           "  --start x,y        start position (default 1,-3)\n"
           "  --goal x,y         goal position (default 8,3)\n"
           "  --departure t      departure time t0 (default 0)\n"
           "  --planner NAME     TVE | A*TVE | ZTVE | ZA*TVE (default) | RRTstar | InformedRRTstar | PRM | PRMstar | RRT\n"
           "  --grid-size g      lattice spacing for the TVE family (default 0.4)\n"
           "  --sectors n        lattice connectivity 1..5 (default 3)\n"
           "  --time-limit s     planner time limit in seconds (default 10; sampling planners use all of it)\n"
           "  --no-smooth        skip path smoothing (000 Table 3)\n"
           "  --no-refine        skip waypoint refinement\n"
           "  --out DIR          write DIR/summary.json, DIR/path.csv, DIR/map.svg and DIR/map.png\n"
           "  --optimum          also solve Zermelo's optimal-control problem (shooting) and compare\n"
           "  --verbose          show OMPL's log messages\n"
           "  --help             this text\n"
           "Exit status: 0 path found, 1 no path, 2 bad arguments or input.\n";
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
    std::string outDir;
    bool verbose = false;
    try
    {
        std::vector<std::string> args(argv + 1, argv + argc);
        for (std::size_t i = 0; i < args.size(); ++i)
        {
            const std::string &a = args[i];
            auto value = [&]() -> const std::string & {
                if (i + 1 >= args.size())
                    throw UsageError{a + " needs a value"};
                return args[++i];
            };
            if (a == "--help" || a == "-h")
            {
                usage(std::cout);
                return 0;
            }
            else if (a == "--start")
                parsePair(a, value(), req.problem.startX, req.problem.startY);
            else if (a == "--goal")
                parsePair(a, value(), req.problem.goalX, req.problem.goalY);
            else if (a == "--departure")
                req.problem.t0 = parseNumber(a, value());
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
            else
                throw UsageError{"unknown option '" + a + "'"};
        }
        const auto &names = plannerNames();
        if (std::find(names.begin(), names.end(), req.planner) == names.end())
            throw UsageError{"unknown planner '" + req.planner + "' (see --help)"};
    }
    catch (const UsageError &e)
    {
        std::cerr << "glider_plan: " << e.message << "\nTry 'glider_plan --help'.\n";
        return kUsageError;
    }

    if (!verbose)
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    try
    {
        const PlanRunResult result = runPlan(req);
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

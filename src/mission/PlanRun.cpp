#include "ompl_glider/mission/PlanRun.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/current/Interpolation.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/NetCdfCurrents.h"
#include "ompl_glider/mission/MissionOutputs.h"
#include "ompl_glider/mission/SlocumGoto.h"
#include "ompl_glider/planners/PathSmoother.h"
#include "ompl_glider/planners/WaypointRefiner.h"
#include "ompl_glider/planners/ZAStarTVE.h"
#include "ompl_glider/reference/ZermeloReference.h"

namespace ompl_glider
{
namespace
{
bool isLatticePlanner(const std::string &name)
{
    return name == "TVE" || name == "A*TVE" || name == "ZTVE" || name == "ZA*TVE";
}

std::string num(double v)
{
    if (!std::isfinite(v))
        return "null";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string jsonString(const std::string &s)
{
    std::string out = "\"";
    for (char c : s)
    {
        if (c == '"' || c == '\\')
            out += '\\';
        if (static_cast<unsigned char>(c) < 0x20)
        {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
            continue;
        }
        out += c;
    }
    return out + "\"";
}

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

void writeFile(const std::string &path, const std::string &text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out)
        throw Error("writePlanOutputs: cannot write '" + path + "'");
}
}  // namespace

const std::vector<std::string> &plannerNames()
{
    static const std::vector<std::string> names = {"TVE",           "A*TVE",           "ZTVE", "ZA*TVE", "RRTstar",
                                                   "InformedRRTstar", "PRM", "PRMstar", "RRT"};
    return names;
}

GliderProblem gulfStreamProblem()
{
    GliderProblem p;
    p.field = std::make_shared<MeanderingJet>();
    p.travel.speed = 0.5;
    p.xMin = 0.0;
    p.xMax = 10.0;
    p.yMin = -4.0;
    p.yMax = 4.0;
    p.t0 = 0.0;
    p.horizon = 60.0;
    p.startX = 1.0;
    p.startY = -3.0;
    p.goalX = 8.0;
    p.goalY = 3.0;
    return p;
}

PlanRunResult runPlan(const PlanRequest &req)
{
    const auto &names = plannerNames();
    if (std::find(names.begin(), names.end(), req.planner) == names.end())
    {
        std::string list;
        for (const auto &n : names)
            list += (list.empty() ? "" : ", ") + n;
        throw Error("unknown planner '" + req.planner + "' (expected one of " + list + ")");
    }
    if (!(req.timeLimit > 0.0))
        throw Error("planner time limit must be > 0 s");
    std::shared_ptr<GliderContext> ctx;
    ompl::geometric::SimpleSetupPtr ss = makeSimpleSetup(req.problem, &ctx);
    const ompl::base::SpaceInformationPtr &si = ss->getSpaceInformation();

    std::shared_ptr<ZAStarTVE> lattice;
    if (isLatticePlanner(req.planner))
    {
        lattice = std::make_shared<ZAStarTVE>(si, ctx, req.planner);
        lattice->setGridSize(req.gridSize);
        lattice->setSectors(req.sectors);
        ss->setPlanner(lattice);
    }
    else if (req.planner == "RRTstar")
        ss->setPlanner(std::make_shared<ompl::geometric::RRTstar>(si));
    else if (req.planner == "InformedRRTstar")
        ss->setPlanner(std::make_shared<ompl::geometric::InformedRRTstar>(si));
    else if (req.planner == "PRM")
        ss->setPlanner(std::make_shared<ompl::geometric::PRM>(si));
    else if (req.planner == "PRMstar")
        ss->setPlanner(std::make_shared<ompl::geometric::PRMstar>(si));
    else
        ss->setPlanner(std::make_shared<ompl::geometric::RRT>(si));

    PlanRunResult res;
    res.planner = req.planner;
    const double t0 = ctx->t0;
    res.straightLineTime = legTravelTime(*ctx, req.problem.startX, req.problem.startY, req.problem.goalX,
                                         req.problem.goalY, t0);

    const std::uint64_t cfc0 = ctx->travel->costFunctionCalls(), cmc0 = ctx->field->callCount();
    const auto tA = std::chrono::steady_clock::now();
    const ompl::base::PlannerStatus status = ss->solve(req.timeLimit);
    const auto tB = std::chrono::steady_clock::now();
    res.planningSeconds = seconds(tA, tB);
    res.status = status.asString();
    if (lattice)
    {
        res.costFunctionCalls = lattice->getCostFunctionCalls();
        res.currentModelCalls = lattice->getCurrentModelCalls();
    }
    else
    {
        res.costFunctionCalls = ctx->travel->costFunctionCalls() - cfc0;
        res.currentModelCalls = ctx->field->callCount() - cmc0;
    }
    if (!ss->haveSolutionPath())
        return res;
    ompl::geometric::PathGeometric path = ss->getSolutionPath();
    res.feasible = ss->haveExactSolutionPath();
    res.raw = waypointsFromPath(path);
    res.travelTimeRaw = res.feasible ? res.raw.back().t - t0 : std::numeric_limits<double>::infinity();

    const std::uint64_t cfc1 = ctx->travel->costFunctionCalls();
    const auto tC = std::chrono::steady_clock::now();
    if (res.feasible && req.smooth)
        PathSmoother(ctx).smooth(path);
    res.smoothed = waypointsFromPath(path);
    if (res.feasible && req.refine)
        WaypointRefiner(ctx).refine(path);
    res.refined = waypointsFromPath(path);
    res.postprocessSeconds = seconds(tC, std::chrono::steady_clock::now());
    res.postprocessCostFunctionCalls = ctx->travel->costFunctionCalls() - cfc1;

    res.path = res.refined;
    if (res.feasible)
    {
        res.travelTimeSmoothed = res.smoothed.back().t - t0;
        res.travelTime = res.path.back().t - t0;
        res.pathChecked = path.check();
    }
    res.pathLength = pathLength(res.path);
    if (req.optimum)
    {
        ZermeloParams zp;
        zp.speed = ctx->speed();
        zp.depth = req.problem.travel.depth;
        // Any flown path bounds the optimum; without one, the horizon does.
        zp.maxTime = std::min(req.problem.horizon, res.feasible ? 1.2 * res.travelTime : req.problem.horizon);
        const ZermeloReference ref(ctx->field, zp);
        const GliderProblem &p = req.problem;
        const ZermeloSolution sol = ref.solve(p.startX, p.startY, p.goalX, p.goalY, t0);
        if (sol.found)
        {
            res.optimumTime = sol.travelTime;
            for (const ZermeloState &z : ref.trajectory(p.startX, p.startY, sol.initialHeading, t0, sol.travelTime))
                res.optimumPath.push_back({z.x, z.y, z.t});
        }
    }
    return res;
}

std::string planSummaryJson(const PlanRequest &req, const PlanRunResult &r)
{
    std::ostringstream o;
    o << "{\n";
    o << "  \"feasible\": " << (r.feasible ? "true" : "false") << ",\n";
    o << "  \"status\": " << jsonString(r.status) << ",\n";
    o << "  \"planner\": " << jsonString(r.planner) << ",\n";
    o << "  \"field\": " << jsonString(req.problem.field ? req.problem.field->name() : "") << ",\n";
    o << "  \"start\": [" << num(req.problem.startX) << ", " << num(req.problem.startY) << "],\n";
    o << "  \"goal\": [" << num(req.problem.goalX) << ", " << num(req.problem.goalY) << "],\n";
    o << "  \"departure\": " << num(req.problem.t0) << ",\n";
    o << "  \"speed\": " << num(req.problem.travel.speed) << ",\n";
    o << "  \"grid_size\": " << num(req.gridSize) << ",\n";
    o << "  \"sectors\": " << req.sectors << ",\n";
    o << "  \"travel_time\": " << num(r.travelTime) << ",\n";
    o << "  \"travel_time_raw\": " << num(r.travelTimeRaw) << ",\n";
    o << "  \"travel_time_smoothed\": " << num(r.travelTimeSmoothed) << ",\n";
    o << "  \"straight_line_time\": " << num(r.straightLineTime) << ",\n";
    o << "  \"path_length\": " << num(r.pathLength) << ",\n";
    o << "  \"waypoints_raw\": " << r.raw.size() << ",\n";
    o << "  \"waypoints_smoothed\": " << r.smoothed.size() << ",\n";
    o << "  \"waypoints_refined\": " << r.refined.size() << ",\n";
    o << "  \"smoothing\": " << (req.smooth ? "true" : "false") << ",\n";
    o << "  \"refinement\": " << (req.refine ? "true" : "false") << ",\n";
    o << "  \"cost_function_calls\": " << r.costFunctionCalls << ",\n";
    o << "  \"current_model_calls\": " << r.currentModelCalls << ",\n";
    o << "  \"postprocess_cost_function_calls\": " << r.postprocessCostFunctionCalls << ",\n";
    o << "  \"planning_time_s\": " << num(r.planningSeconds) << ",\n";
    o << "  \"postprocess_time_s\": " << num(r.postprocessSeconds) << ",\n";
    if (req.optimum)
        o << "  \"optimal_control_time\": " << num(r.optimumTime) << ",\n";
    if (!r.speedSweep.empty())
    {
        o << "  \"speed_sweep\": [";
        for (std::size_t i = 0; i < r.speedSweep.size(); ++i)
        {
            const SpeedSweepRow &w = r.speedSweep[i];
            o << (i ? ",\n    " : "") << "{\"speed\": " << num(w.speed) << ", \"travel_time\": " << num(w.travelTime)
              << ", \"path_length\": " << num(w.pathLength) << ", \"straight_line_travel_time\": "
              << (std::isfinite(w.straightLineTime) ? num(w.straightLineTime) : std::string("\"impassable\""))
              << ", \"straight_line_length\": " << num(w.straightLineLength) << "}";
        }
        o << "],\n";
    }
    o << "  \"path_checked\": " << (r.pathChecked ? "true" : "false") << "\n";
    o << "}\n";
    return o.str();
}

std::string planPathCsv(const PlanRunResult &r)
{
    std::ostringstream o;
    o << "t,x,y\n";
    char buf[128];
    for (const TimedWaypoint &w : r.path)
    {
        std::snprintf(buf, sizeof buf, "%.10g,%.10g,%.10g\n", w.t, w.x, w.y);
        o << buf;
    }
    return o.str();
}

MapRenderer planMap(const PlanRequest &req, const PlanRunResult &r)
{
    const GliderProblem &p = req.problem;
    Region box;
    box.xMin = p.xMin;
    box.xMax = p.xMax;
    box.yMin = p.yMin;
    box.yMax = p.yMax;
    MapOptions mo;
    mo.title = !req.title.empty() ? req.title
                                  : std::string(p.field ? p.field->name() : "field") + " - " + r.planner +
                                        ", V = " + num(p.travel.speed) + ", departure t = " + num(p.t0);
    MapRenderer map(box, mo);
    if (p.field)
        map.setField(p.field, p.t0, p.travel.depth);
    for (const MapPolygon &poly : req.polygons)
        map.addPolygon(poly);
    auto fmtT = [](double t) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.2f", t);
        return std::string(buf);
    };
    if (!r.raw.empty())
    {
        const bool lattice = isLatticePlanner(r.planner);
        std::string rawLabel = r.planner + (lattice ? " lattice: " : " path: ") + std::to_string(r.raw.size()) + " wp";
        rawLabel += r.feasible ? ", T=" + fmtT(r.travelTimeRaw) : ", not at goal";
        const bool smoothedDiffers = r.smoothed.size() != r.raw.size() || r.travelTimeSmoothed < r.travelTimeRaw;
        const bool refinedDiffers = r.refined.size() != r.smoothed.size() || r.travelTime < r.travelTimeSmoothed;
        MapPath raw = MapRenderer::rawPathStyle(rawLabel, r.raw);
        if (!smoothedDiffers && !refinedDiffers)
            raw.timeTicks = true;
        map.addPath(raw);
        if (req.smooth && smoothedDiffers)
        {
            MapPath s = MapRenderer::smoothedPathStyle(
                "smoothed: " + std::to_string(r.smoothed.size()) + " wp, T=" + fmtT(r.travelTimeSmoothed),
                r.smoothed);
            s.timeTicks = !refinedDiffers || !req.refine;
            map.addPath(s);
        }
        if (req.refine && refinedDiffers)
            map.addPath(MapRenderer::refinedPathStyle(
                "refined: " + std::to_string(r.refined.size()) + " wp, T=" + fmtT(r.travelTime), r.refined));
    }
    if (!r.optimumPath.empty())
    {
        MapPath opt;
        opt.label = "optimal control: T=" + fmtT(r.optimumTime);
        opt.waypoints = r.optimumPath;
        opt.colour = {0.10, 0.35, 0.95, 1.0};
        opt.width = 1.6;
        opt.dashed = true;
        opt.waypointMarkers = false;
        map.addPath(opt);
    }
    map.setStartGoal(p.startX, p.startY, p.goalX, p.goalY);
    if (r.feasible)
    {
        map.addNote("travel time " + fmtT(r.travelTime));
        map.addNote("path length " + fmtT(r.pathLength));
        map.addNote("straight line: " +
                    (std::isfinite(r.straightLineTime) ? "T=" + fmtT(r.straightLineTime) : std::string("impassable")));
    }
    else
        map.addNote("no path found (" + r.status + ")");
    map.addNote("field shown at departure");
    return map;
}

std::vector<std::string> writePlanOutputs(const PlanRequest &req, const PlanRunResult &r,
                                          const std::string &directory)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (ec || !fs::is_directory(directory))
        throw Error("writePlanOutputs: cannot create output directory '" + directory + "'" +
                    (ec ? ": " + ec.message() : std::string()));
    const fs::path dir(directory);
    std::vector<std::string> files = {(dir / "summary.json").string(), (dir / "path.csv").string(),
                                      (dir / "map.svg").string(), (dir / "map.png").string()};
    writeFile(files[0], planSummaryJson(req, r));
    writeFile(files[1], planPathCsv(r));
    const MapRenderer map = planMap(req, r);
    map.writeSvg(files[2]);
    map.writePng(files[3]);
    return files;
}

void printPlanReport(std::ostream &out, const PlanRequest &req, const PlanRunResult &r)
{
    char buf[256];
    const GliderProblem &p = req.problem;
    std::snprintf(buf, sizeof buf, "Field: %s, V = %g, departure t0 = %g\n", p.field ? p.field->name().c_str() : "?",
                  p.travel.speed, p.t0);
    out << buf;
    std::snprintf(buf, sizeof buf, "Start (%g, %g) -> goal (%g, %g); planner %s", p.startX, p.startY, p.goalX,
                  p.goalY, r.planner.c_str());
    out << buf;
    if (isLatticePlanner(r.planner))
    {
        std::snprintf(buf, sizeof buf, " (grid %g, %u sectors)", req.gridSize, req.sectors);
        out << buf;
    }
    out << "\n";
    out << "Status: " << r.status << (r.feasible ? "" : " - no path to the goal") << "\n";
    if (r.feasible)
    {
        std::snprintf(buf, sizeof buf, "Travel time:        %.4f (raw %.4f, smoothed %.4f)\n", r.travelTime,
                      r.travelTimeRaw, r.travelTimeSmoothed);
        out << buf;
        std::snprintf(buf, sizeof buf, "Path length:        %.4f\n", r.pathLength);
        out << buf;
        if (std::isfinite(r.straightLineTime))
            std::snprintf(buf, sizeof buf, "Straight line:      %.4f\n", r.straightLineTime);
        else
            std::snprintf(buf, sizeof buf, "Straight line:      impassable\n");
        out << buf;
    }
    std::snprintf(buf, sizeof buf, "Waypoints:          raw %zu, smoothed %zu%s, refined %zu%s\n", r.raw.size(),
                  r.smoothed.size(), req.smooth ? "" : " (off)", r.refined.size(), req.refine ? "" : " (off)");
    out << buf;
    std::snprintf(buf, sizeof buf, "CFC (cost function calls): %llu; CMC (current model calls): %llu\n",
                  static_cast<unsigned long long>(r.costFunctionCalls),
                  static_cast<unsigned long long>(r.currentModelCalls));
    out << buf;
    std::snprintf(buf, sizeof buf, "Planning time:      %.3f s (post-processing %.3f s, %llu CFC)\n",
                  r.planningSeconds, r.postprocessSeconds,
                  static_cast<unsigned long long>(r.postprocessCostFunctionCalls));
    out << buf;
    if (req.optimum)
    {
        if (std::isfinite(r.optimumTime))
            std::snprintf(buf, sizeof buf, "Optimal control:    %.4f (final path %+.2f%%)\n", r.optimumTime,
                          100.0 * (r.travelTime / r.optimumTime - 1.0));
        else
            std::snprintf(buf, sizeof buf, "Optimal control:    no extremal through the goal found\n");
        out << buf;
    }
    if (!r.speedSweep.empty())
        out << "Speed sweep (003 Table VI):\n" << speedSweepTable(r.speedSweep);
    if (r.feasible)
    {
        out << "Waypoints (t, x, y):\n";
        for (const TimedWaypoint &w : r.path)
        {
            std::snprintf(buf, sizeof buf, "  %9.4f  %8.4f  %8.4f\n", w.t, w.x, w.y);
            out << buf;
        }
    }
}

std::vector<SpeedSweepRow> planSpeedSweep(const PlanRequest &request, const std::vector<double> &speeds)
{
    std::vector<SpeedSweepRow> rows;
    for (double v : speeds)
    {
        if (!(v > 0.0) || !std::isfinite(v))
            throw Error("speed sweep: speed " + num(v) + " is not > 0");
        PlanRequest r = request;
        r.problem.travel.speed = v;
        r.optimum = false;
        const PlanRunResult res = runPlan(r);
        SpeedSweepRow row;
        row.speed = v;
        row.solved = res.feasible;
        row.travelTime = res.travelTime;
        row.pathLength = res.pathLength;
        row.straightLineTime = res.straightLineTime;
        row.straightLineLength = std::hypot(r.problem.goalX - r.problem.startX, r.problem.goalY - r.problem.startY);
        rows.push_back(row);
    }
    return rows;
}

double defaultForecastGridSize(double minCellSize, double distance)
{
    double g = 0.5 * minCellSize;
    if (distance > 0.0)
        g = std::clamp(g, distance / 200.0, distance / 25.0);
    if (!(g > 0.0) || !std::isfinite(g))
        throw Error("cannot choose a grid size (cell size " + num(minCellSize) + ", start-goal distance " +
                    num(distance) + "): give --grid-size");
    const double scale = std::pow(10.0, std::floor(std::log10(g)) - 1.0);  // two significant digits
    return std::round(g / scale) * scale;
}

namespace
{
std::string lowerPlannerName(const std::string &name)
{
    if (name == "TVE")
        return "tve";
    if (name == "A*TVE")
        return "astartve";
    if (name == "ZTVE")
        return "ztve";
    if (name == "ZA*TVE")
        return "zastartve";
    return name;
}

std::string pointText(double a, double b)
{
    char buf[80];
    std::snprintf(buf, sizeof buf, "%.6g,%.6g", a, b);
    return buf;
}
}  // namespace

MissionSpec forecastMission(const ForecastPlanRequest &q)
{
    namespace fs = std::filesystem;
    const std::string &file = q.file;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw Error("--currents: cannot open '" + file + "' (no such file)");
    if (!q.startSet || !q.goalSet)
        throw Error(std::string("--currents needs --start and --goal (") +
                    "lon,lat for a geographic file, x,y for a Cartesian one)");
    if (!(q.speed > 0.0) || !std::isfinite(q.speed))
        throw Error("--speed must be > 0 (m/s)");
    if (!(q.depth >= 0.0))
        throw Error("--depth must be >= 0 (metres, positive down)");
    const auto &names = plannerNames();
    if (std::find(names.begin(), names.end(), q.planner) == names.end())
        throw Error("unknown planner '" + q.planner + "' (see --help)");

    MissionSpec m;
    m.file = file;
    m.directory = ".";
    m.name = fs::path(file).stem().string();
    m.current.type = "netcdf";
    m.current.file = file;
    m.current.variables = q.variables;
    m.current.xyInterpolation = q.xyInterpolation;
    m.current.depthInterpolation = q.depthInterpolation;
    m.current.timeInterpolation = q.timeInterpolation;
    m.current.horizonPolicy = q.horizonPolicy;
    m.current.mark.file = file;

    // Load once as the mission runner will (same names, schemes, depth range, default projection) to check the
    // request and convert the start, goal and departure.
    NetCdfCurrentOptions o = netCdfCurrentOptions(m.current);
    o.maxDepth = q.depth;
    o.departure = q.departure;
    // Load only the region of the trip (issue 5): the start-goal box plus half its larger side (at least 0.2
    // degrees or units) on each side; the whole file when the trip crosses the antimeridian.
    const double spanA = std::abs(q.goalA - q.startA), spanB = std::abs(q.goalB - q.startB);
    const double pad = std::max(0.5 * std::max(spanA, spanB), 0.2);
    const bool subset = spanA < 180.0;
    if (subset)
    {
        o.lonMin = std::min(q.startA, q.goalA) - pad;
        o.lonMax = std::max(q.startA, q.goalA) + pad;
        o.latMin = std::max(std::min(q.startB, q.goalB) - pad, -90.0);
        o.latMax = std::min(std::max(q.startB, q.goalB) + pad, 90.0);
    }
    NetCdfCurrents nc;
    try
    {
        nc = loadNetCdfCurrents(file, o);
    }
    catch (const Error &e)
    {
        // Name the command-line flags instead of the library's option fields.
        std::string what = e.what();
        for (const auto &[field, flag] : std::vector<std::pair<std::string, std::string>>{
                 {"NetCdfCurrentOptions::timeName/depthName/lonName/latName",
                  "--time-var/--depth-var/--lon-var/--lat-var"},
                 {"NetCdfCurrentOptions::lonName/latName", "--lon-var/--lat-var"},
                 {"NetCdfCurrentOptions::uName", "--u-var"},
                 {"NetCdfCurrentOptions::vName", "--v-var"},
                 {"NetCdfCurrentOptions::lonName", "--lon-var"},
                 {"NetCdfCurrentOptions::latName", "--lat-var"},
                 {"NetCdfCurrentOptions::depthName", "--depth-var"},
                 {"NetCdfCurrentOptions::timeName", "--time-var"},
                 {"NetCdfCurrentOptions::departure", "--departure"},
                 {"NetCdfCurrentOptions::maxDepth", "--depth"}})
            for (std::size_t at = what.find(field); at != std::string::npos; at = what.find(field, at))
                what.replace(at, field.size(), flag);
        if (!q.departure.empty() && what.find("depart") != std::string::npos && what.find("--departure") == std::string::npos)
            what = "--departure " + q.departure + ": " + what;
        else if (what.find("region ") != std::string::npos)
            what = "--start " + pointText(q.startA, q.startB) + " / --goal " + pointText(q.goalA, q.goalB) +
                   ": not on the grid: " + what;
        throw Error(what);
    }
    const GriddedCurrentField &g = *nc.field;
    // (Above the first layer is the surface layer's value, as forecasts put their first layer just below it.)
    if (g.nz() > 1 && q.depth > g.depthAxis().back())
        throw Error("--depth " + num(q.depth) + " m lies below the deepest layer of '" + file + "' (" +
                    num(g.depthAxis().back()) + " m)");
    const char *coords = nc.geographic ? "lon,lat" : "x,y";
    double sx, sy, gx, gy;
    nc.toLocal(q.startA, q.startB, sx, sy);
    nc.toLocal(q.goalA, q.goalB, gx, gy);
    const Region e = g.extent();
    for (const auto &[flag, a, b, x, y] :
         {std::tuple<const char *, double, double, double, double>{"--start", q.startA, q.startB, sx, sy},
          std::tuple<const char *, double, double, double, double>{"--goal", q.goalA, q.goalB, gx, gy}})
    {
        double fi, fj;
        if (!std::isfinite(x) || !std::isfinite(y) || !g.locate(x, y, fi, fj))
        {
            double lo0, la0, lo1, la1;
            nc.toGeographic(e.xMin, e.yMin, lo0, la0);
            nc.toGeographic(e.xMax, e.yMax, lo1, la1);
            throw Error(std::string(flag) + " " + pointText(a, b) + " (" + coords + ") lies outside the grid of '" +
                        file + "' (about " + coords + " " + pointText(lo0, la0) + " to " + pointText(lo1, la1) +
                        ")");
        }
        if (!g.inWater(x, y, q.depth))
            throw Error(std::string(flag) + " " + pointText(a, b) + " (" + coords + ") is on land in '" + file +
                        "' (u/v are fill values there at depth " + num(q.depth) + " m)");
    }
    const double tDep = nc.departureTime;
    if (tDep < nc.forecastBegin || tDep > nc.forecastEnd)
        throw Error("--departure " + q.departure + " is outside the forecast (" + nc.isoTime(nc.forecastBegin) +
                    " to " + nc.isoTime(nc.forecastEnd) + ")");
    if (tDep >= nc.forecastEnd && q.horizonPolicy == "refuse")
        throw Error("--departure " + (q.departure.empty() ? std::string("(default)") : q.departure) +
                    " is the last forecast time: no time is left to travel (use an earlier departure or --beyond hold)");

    if (nc.geographic)
    {
        if (subset && o.latMax - o.latMin < 120.0)
        {
            // The same subset for the mission's load, clipped to the grid loaded here, and the same local frame.
            double lo0, la0, lo1, la1, lo2, la2, lo3, la3;
            nc.toGeographic(e.xMin, e.yMin, lo0, la0);
            nc.toGeographic(e.xMax, e.yMax, lo1, la1);
            nc.toGeographic(e.xMin, e.yMax, lo2, la2);
            nc.toGeographic(e.xMax, e.yMin, lo3, la3);
            (void)lo2;
            (void)lo3;
            m.region.set = m.region.geographic = true;
            m.region.lonMin = std::max(o.lonMin, std::min(lo0, lo2));
            m.region.lonMax = std::min(o.lonMax, std::max(lo1, lo3));
            m.region.latMin = std::max(o.latMin, std::min(la0, la3));
            m.region.latMax = std::min(o.latMax, std::max(la1, la2));
            double lon0, lat0;
            nc.toGeographic(0.0, 0.0, lon0, lat0);
            m.projection.set = true;
            m.projection.lon0 = lon0;
            m.projection.lat0 = lat0;
            if (!(m.region.lonMin < m.region.lonMax && m.region.latMin < m.region.latMax))
                m.region.set = m.region.geographic = false;
        }
        m.start.geographic = m.goal.geographic = true;
        m.start.lon = q.startA;
        m.start.lat = q.startB;
        m.goal.lon = q.goalA;
        m.goal.lat = q.goalB;
    }
    else
    {
        m.start.x = q.startA;
        m.start.y = q.startB;
        m.goal.x = q.goalA;
        m.goal.y = q.goalB;
    }
    if (nc.dated)
    {
        MissionSpec::FileCalendar fc;
        fc.calendar = nc.calendar;
        fc.originSeconds = nc.originSeconds;
        m.fileCalendar = fc;
        m.epoch = fc.originSeconds - secondsSinceCalendarEpoch(DateTime{}, fc.calendar);
    }
    m.departure.time = tDep;
    m.vehicle.speed = q.speed;
    m.vehicle.depth = q.depth;
    m.travel.speed = q.speed;
    m.travel.depth = q.depth;
    m.travel.eps = 1.0;  // one second per integration step on trips of hours to days (as the example mission)
    m.planner.name = lowerPlannerName(q.planner);
    m.planner.gridSize =
        q.gridSize > 0.0 ? q.gridSize : defaultForecastGridSize(g.minCellSize(), std::hypot(gx - sx, gy - sy));
    m.planner.sectors = static_cast<int>(q.sectors);
    m.planner.smoothing = q.smooth;
    m.planner.refinement = q.refine;
    m.planner.timeLimit = q.timeLimit;
    m.outputs.files.clear();
    m.outputs.directory.clear();
    m.outputs.gotoNumber = 10;
    return m;
}

std::string forecastPathCsv(const MissionResult &r)
{
    std::ostringstream o;
    o << "t,x,y,lon,lat\n";
    char buf[200];
    for (const MissionWaypoint &w : r.waypoints)
    {
        if (w.geographic)
            std::snprintf(buf, sizeof buf, "%.10g,%.10g,%.10g,%.10g,%.10g\n", w.time, w.x, w.y, w.lon, w.lat);
        else
            std::snprintf(buf, sizeof buf, "%.10g,%.10g,%.10g,,\n", w.time, w.x, w.y);
        o << buf;
    }
    return o.str();
}

std::vector<std::string> writeForecastOutputs(const MissionResult &r, const MissionProblem &problem,
                                              const std::string &directory)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (ec || !fs::is_directory(directory))
        throw Error("cannot create output directory '" + directory + "'" + (ec ? ": " + ec.message() : std::string()));
    const fs::path dir(directory);
    std::vector<std::string> files;
    auto text = [&](const char *name, const std::string &content) {
        const std::string f = (dir / name).string();
        writeFile(f, content);
        files.push_back(f);
    };
    text("summary.json", summaryJson(r));
    if (r.plan.solved)
    {
        text("path.csv", forecastPathCsv(r));
        text("waypoints.csv", waypointsCsv(r));
        text("path.geojson", waypointsGeoJson(r));
        if (problem.geographic())
        {
            const std::string f = (dir / gotoFileName(r.spec.outputs.gotoNumber)).string();
            writeGotoFile(f, gotoList(r));
            files.push_back(f);
        }
    }
    const MapRenderer map = missionMap(r, problem);
    map.writeSvg((dir / "map.svg").string());
    map.writePng((dir / "map.png").string());
    files.push_back((dir / "map.svg").string());
    files.push_back((dir / "map.png").string());
    return files;
}

int runForecastCommand(const ForecastPlanRequest &request, const std::optional<std::vector<double>> &speeds,
                       const std::string &directory, bool progress, std::ostream &out, std::ostream &err)
{
    try
    {
        const MissionSpec spec = forecastMission(request);
        RunOptions o;
        o.writeOutputs = false;
        o.progress = progress;
        o.speeds = speeds;
        const MissionProblem problem(spec);  // loads the forecast once for the run and the map
        MissionResult r = runMission(problem, o);
        out << "forecast " << request.file << ": grid size " << num(spec.planner.gridSize) << " m"
            << (request.gridSize > 0.0 ? "" : " (default: half the smallest cell, within 1/200..1/25 of the "
                                              "start-goal distance)")
            << "\n";
        if (!directory.empty())
            r.files = writeForecastOutputs(r, problem, directory);
        printMissionReport(out, r);
        return r.plan.solved ? 0 : 1;
    }
    catch (const Error &e)
    {
        err << "glider_plan: " << e.what() << "\n";
        return 2;
    }
}
}  // namespace ompl_glider

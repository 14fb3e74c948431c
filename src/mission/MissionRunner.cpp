#include "ompl_glider/mission/MissionRunner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/DoubleGyre.h"
#include "ompl_glider/current/Interpolation.h"
#include "ompl_glider/current/LinearShear.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/NetCdfCurrents.h"
#include "ompl_glider/current/UniformCurrent.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/IceZone.h"
#include "ompl_glider/environment/StaticRegion.h"
#include "ompl_glider/environment/TimeWindowedZone.h"
#include "ompl_glider/mission/IsoTime.h"
#include "ompl_glider/mission/MissionOutputs.h"
#include "ompl_glider/mission/NetCdfBathymetry.h"
#include "ompl_glider/mission/PlanRun.h"
#include "ompl_glider/planners/PathSmoother.h"
#include "ompl_glider/planners/WaypointRefiner.h"

namespace ompl_glider
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

double seconds(std::chrono::steady_clock::time_point a)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

double param(const std::map<std::string, double> &p, const char *key, double dflt)
{
    const auto it = p.find(key);
    return it == p.end() ? dflt : it->second;
}

std::shared_ptr<const CurrentField> analyticField(const CurrentSpec &c)
{
    const auto &p = c.parameters;
    if (c.type == "meandering_jet")
    {
        MeanderingJetParams j;
        j.B0 = param(p, "B0", j.B0);
        j.epsilon = param(p, "epsilon", j.epsilon);
        j.omega = param(p, "omega", j.omega);
        j.theta = param(p, "theta", j.theta);
        j.k = param(p, "k", j.k);
        j.c = param(p, "c", j.c);
        return std::make_shared<MeanderingJet>(j);
    }
    if (c.type == "uniform")
        return std::make_shared<UniformCurrent>(param(p, "u", 0.0), param(p, "v", 0.0));
    if (c.type == "linear_shear")
        return std::make_shared<LinearShear>(param(p, "a", -1.0));
    if (c.type == "double_gyre")
        return std::make_shared<DoubleGyre>(param(p, "amplitude", 0.1), param(p, "length", 1.0));
    throw Error("current type '" + c.type + "' is not an analytic flow");
}

std::string where(const MissionSpec &m, const SourceMark &mark = {})
{
    if (!mark.file.empty() && mark.line > 0)
        return mark.file + ":" + std::to_string(mark.line) + ": ";
    return m.file + ": ";
}
}  // namespace

NetCdfCurrentOptions netCdfCurrentOptions(const CurrentSpec &c)
{
    NetCdfCurrentOptions o;
    auto var = [&](const char *role) {
        const auto it = c.variables.find(role);
        return it == c.variables.end() ? std::string() : it->second;
    };
    o.uName = var("u");
    o.vName = var("v");
    o.lonName = !var("lon").empty() ? var("lon") : var("x");
    o.latName = !var("lat").empty() ? var("lat") : var("y");
    o.depthName = var("depth");
    o.timeName = var("time");
    o.field.xy = parseInterp2D(c.xyInterpolation);
    o.field.depth = parseInterp1D(c.depthInterpolation);
    o.field.time = parseInterp1D(c.timeInterpolation);
    o.field.beyond = c.horizonPolicy == "hold_last" ? BeyondForecast::HoldLast : BeyondForecast::Refuse;
    o.field.name = "netcdf:" + c.file;
    return o;
}

MissionProblem::~MissionProblem() = default;

MissionProblem::MissionProblem(MissionSpec spec) : spec_(std::move(spec))
{
    MissionSpec &m = spec_;
    std::shared_ptr<const LocalProjection> projection;
    if (m.current.type == "netcdf")
    {
        NetCdfCurrentOptions o = netCdfCurrentOptions(m.current);
        if (m.region.set && m.region.geographic)
        {
            o.lonMin = m.region.lonMin;
            o.lonMax = m.region.lonMax;
            o.latMin = m.region.latMin;
            o.latMax = m.region.latMax;
        }
        o.maxDepth = m.dive.enabled ? m.dive.params.zMax : m.vehicle.depth;
        if (m.projection.set)
        {
            o.refLon = m.projection.lon0;
            o.refLat = m.projection.lat0;
        }
        NetCdfCurrents nc = loadNetCdfCurrents(m.current.file, o);
        field_ = nc.field;
        projection = nc.projection;
        projectionScale_ = 1.0;
    }
    else
    {
        field_ = analyticField(m.current);
        if (m.projection.set)
            projection = std::make_shared<LocalProjection>(m.projection.lon0, m.projection.lat0);
        projectionScale_ = m.lengthUnitMetres;
    }
    projection_ = projection;

    auto local = [&](bool geographic, double a, double b, double &x, double &y, const std::string &what) {
        if (!geographic)
        {
            x = a;
            y = b;
            return;
        }
        if (!projection_)
            throw Error(where(m) + what + ": lon/lat given but the forecast has no geographic coordinates");
        toLocal(a, b, x, y);
    };
    local(m.start.geographic, m.start.lon, m.start.lat, sx_, sy_, "start");
    if (!m.start.geographic)
        sx_ = m.start.x, sy_ = m.start.y;
    local(m.goal.geographic, m.goal.lon, m.goal.lat, gx_, gy_, "goal");
    if (!m.goal.geographic)
        gx_ = m.goal.x, gy_ = m.goal.y;

    // Planning box.
    if (m.region.set && !m.region.geographic)
    {
        box_.xMin = m.region.xMin;
        box_.xMax = m.region.xMax;
        box_.yMin = m.region.yMin;
        box_.yMax = m.region.yMax;
    }
    else if (m.region.set)
    {
        box_.xMin = box_.yMin = kInf;
        box_.xMax = box_.yMax = -kInf;
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
            {
                if (i != 0 && i != 8 && j != 0 && j != 8)
                    continue;
                double x, y;
                toLocal(m.region.lonMin + (m.region.lonMax - m.region.lonMin) * i / 8.0,
                        m.region.latMin + (m.region.latMax - m.region.latMin) * j / 8.0, x, y);
                box_.xMin = std::min(box_.xMin, x);
                box_.xMax = std::max(box_.xMax, x);
                box_.yMin = std::min(box_.yMin, y);
                box_.yMax = std::max(box_.yMax, y);
            }
    }
    else if (auto g = std::dynamic_pointer_cast<const GriddedCurrentField>(field_))
    {
        const Region e = g->extent();
        box_.xMin = e.xMin;
        box_.xMax = e.xMax;
        box_.yMin = e.yMin;
        box_.yMax = e.yMax;
    }
    else
        throw Error(where(m) + "field 'region': missing");
    box_.tMin = field_->timeBegin();
    box_.tMax = field_->timeEnd();
    box_.zMin = 0.0;
    box_.zMax = m.dive.enabled ? m.dive.params.zMax : m.vehicle.depth;
    for (const auto &[name, x, y] : {std::tuple<const char *, double, double>{"start", sx_, sy_},
                                     std::tuple<const char *, double, double>{"goal", gx_, gy_}})
        if (!(x >= box_.xMin && x <= box_.xMax && y >= box_.yMin && y <= box_.yMax))
            throw Error(where(m) + "field '" + name + "': lies outside the planning region (x " +
                        std::to_string(box_.xMin) + ".." + std::to_string(box_.xMax) + ", y " +
                        std::to_string(box_.yMin) + ".." + std::to_string(box_.yMax) + ")");

    // Forbidden regions.
    auto ring = [&](const std::vector<std::pair<double, double>> &pts, bool geographic, const std::string &what) {
        std::vector<Point2> out;
        for (const auto &p : pts)
        {
            Point2 q;
            local(geographic, p.first, p.second, q.x, q.y, what);
            out.push_back(q);
        }
        return out;
    };
    auto polygon = [&](const PolygonSpec &p, const std::string &kind) {
        try
        {
            std::vector<std::vector<Point2>> holes;
            for (const auto &h : p.holes)
                holes.push_back(ring(h, p.geographic, p.name));
            std::vector<Point2> outer = ring(p.points, p.geographic, p.name);
            MissionPolygon mp{p.name, kind, {}};
            for (const auto &q : outer)
                mp.points.push_back({q.x, q.y});
            polygons_.push_back(mp);
            return Polygon(outer, holes, p.name);
        }
        catch (const Error &e)
        {
            throw Error(where(m, p.mark) + "forbidden region '" + p.name + "': " + e.what());
        }
    };
    auto regions = std::make_shared<ForbiddenRegions>();
    for (const auto &o : m.forbidden.obstacles)
        regions->add(std::make_shared<StaticRegion>(o.polygon.name, polygon(o.polygon, o.kind), o.kind));
    for (const auto &t : m.forbidden.timeWindows)
    {
        std::vector<Interval> w;
        for (const auto &p : t.windows)
            w.push_back({p.first, p.second});
        try
        {
            regions->add(std::make_shared<TimeWindowedZone>(t.polygon.name, polygon(t.polygon, "closure"), w));
        }
        catch (const Error &e)
        {
            throw Error(where(m, t.polygon.mark) + e.what());
        }
    }
    for (const auto &i : m.forbidden.ice)
    {
        Polygon shape = polygon(i.polygon, "ice");
        try
        {
            if (i.carried)
            {
                // Advected over the mission's time span: from the earliest departure (or t_ref) to the latest
                // departure plus five straight-line crossings of the box at the vehicle speed, within the field's time.
                const Point2 ref = shape.outer().front();
                const double diag = std::hypot(box_.xMax - box_.xMin, box_.yMax - box_.yMin);
                const double firstDep = m.departure.window ? m.departure.begin : m.departure.time;
                const double lastDep = m.departure.window ? m.departure.end : m.departure.time;
                double t0 = std::min(i.tRef, firstDep), t1 = std::max(i.tRef, lastDep + 5.0 * diag / m.vehicle.speed);
                t0 = std::max(t0, field_->timeBegin());
                t1 = std::min(t1, field_->timeEnd());
                regions->add(std::make_shared<IceZone>(i.polygon.name, shape, i.tRef, *field_, ref, t0, std::max(t1, t0),
                                                       i.maxSubmergedTime));
            }
            else
                regions->add(
                    std::make_shared<IceZone>(i.polygon.name, shape, i.tRef, i.vx, i.vy, i.maxSubmergedTime));
        }
        catch (const Error &e)
        {
            throw Error(where(m, i.polygon.mark) + e.what());
        }
    }
    if (regions->size() > 0)
        environment_ = regions;
}

bool MissionProblem::geographic() const
{
    return static_cast<bool>(projection_);
}

void MissionProblem::toGeographic(double x, double y, double &lon, double &lat) const
{
    if (!projection_)
        throw Error(spec_.file + ": no projection: longitudes and latitudes are unknown");
    projection_->inverse(x * projectionScale_, y * projectionScale_, lon, lat);
}

void MissionProblem::toLocal(double lon, double lat, double &x, double &y) const
{
    if (!projection_)
        throw Error(spec_.file + ": no projection: longitudes and latitudes cannot be used");
    projection_->forward(lon, lat, x, y);
    x /= projectionScale_;
    y /= projectionScale_;
}

std::string MissionProblem::isoTime(double t) const
{
    if (!spec_.epoch || !std::isfinite(t))
        return "";
    return formatIsoTime(*spec_.epoch + t * spec_.timeUnitSeconds);
}

GliderProblem MissionProblem::gliderProblem(double tDep, double speed) const
{
    GliderProblem p;
    p.field = field_;
    p.travel = spec_.travel;
    p.travel.speed = speed;
    p.environment = environment_;
    p.xMin = box_.xMin;
    p.xMax = box_.xMax;
    p.yMin = box_.yMin;
    p.yMax = box_.yMax;
    p.t0 = tDep;
    const double dist = std::hypot(gx_ - sx_, gy_ - sy_);
    double horizon = spec_.planner.horizon;
    if (!(horizon > 0))
    {
        horizon = 50.0 * (std::hypot(box_.xMax - box_.xMin, box_.yMax - box_.yMin) + dist) / speed;
        if (std::isfinite(field_->timeEnd()))
            horizon = std::min(horizon, field_->timeEnd() - tDep);
    }
    p.horizon = horizon;
    p.startX = sx_;
    p.startY = sy_;
    p.goalX = gx_;
    p.goalY = gy_;
    p.goalTolerance = spec_.planner.goalTolerance >= 0
                          ? spec_.planner.goalTolerance
                          : 1e-6 * std::max(box_.xMax - box_.xMin, box_.yMax - box_.yMin);
    return p;
}

PlannedPath MissionProblem::plan(double tDep, const PlanOptions &o) const
{
    const auto start = std::chrono::steady_clock::now();
    PlannedPath r;
    r.departure = tDep;
    r.speed = std::isnan(o.speed) ? spec_.vehicle.speed : o.speed;
    const double grid = o.gridSize > 0 ? o.gridSize : spec_.planner.gridSize;
    const int sectors = o.sectors > 0 ? o.sectors : spec_.planner.sectors;
    const bool smoothing = o.smoothing.value_or(spec_.planner.smoothing);
    const bool refinement = o.refinement.value_or(spec_.planner.refinement);
    r.straightLineLength = std::hypot(gx_ - sx_, gy_ - sy_);
    const GliderProblem gp = gliderProblem(tDep, r.speed);
    if (!(gp.horizon > 0))
    {
        r.status = "departure after the end of the forecast";
        return r;
    }
    std::shared_ptr<const GliderContext> ctx = makeGliderContext(gp);
    r.straightLineTime = legTravelTime(*ctx, sx_, sy_, gx_, gy_, tDep);
    const std::string &name = spec_.planner.name;
    if (name != "tve" && name != "astartve" && name != "ztve" && name != "zastartve")
    {
        // An OMPL planner on the time-augmented space (PlanRun.h).
        PlanRequest req;
        req.problem = gp;
        req.planner = name;
        req.gridSize = grid;
        req.sectors = static_cast<unsigned>(sectors);
        req.smooth = smoothing;
        req.refine = refinement;
        req.timeLimit = spec_.planner.timeLimit > 0 ? spec_.planner.timeLimit : 10.0;
        const PlanRunResult res = runPlan(req);
        r.status = res.status;
        r.solved = res.feasible && !res.path.empty() && std::isfinite(res.travelTime);
        r.costFunctionCalls = res.costFunctionCalls + res.postprocessCostFunctionCalls;
        r.currentModelCalls = res.currentModelCalls;
        r.wallSeconds = seconds(start);
        if (r.solved)
        {
            r.raw = res.raw;  // the planner's own times (it may hold position)
            r.rawTravelTime = res.travelTimeRaw;
            r.rawPathLength = pathLength(r.raw);
            r.path = res.path;
            r.smoothedWaypoints = res.smoothed.empty() ? res.raw.size() : res.smoothed.size();
            r.travelTime = res.travelTime;
            r.pathLength = pathLength(r.path);
        }
        return r;
    }

    TveOptions to;
    to.heuristic = name == "astartve" || name == "zastartve";
    to.zermelo = name == "ztve" || name == "zastartve";
    const auto &pp = spec_.planner.parameters;
    if (pp.count("delta_phi_max_deg"))
        to.deltaPhiMax = pp.at("delta_phi_max_deg") * M_PI / 180.0;
    if (pp.count("zermelo_steps"))
        to.zermeloSteps = static_cast<unsigned>(std::max(1.0, pp.at("zermelo_steps")));
    if (pp.count("course_extrapolation"))
        to.courseExtrapolation = pp.at("course_extrapolation");
    const double limit = spec_.planner.timeLimit;
    auto terminate = [&]() { return limit > 0 && seconds(start) > limit; };

    const std::uint64_t cmc0 = field_->callCount();
    TveSearch search(ctx, grid, static_cast<unsigned>(sectors));
    const TveResult res = search.run(sx_, sy_, gx_, gy_, to, terminate);
    r.currentModelCalls = res.currentModelCalls;
    r.expansions = res.expansions;
    switch (res.outcome)
    {
        case TveOutcome::Exact:
            r.status = "exact";
            break;
        case TveOutcome::Exhausted:
            r.status = "no path on the lattice";
            break;
        case TveOutcome::Terminated:
            r.status = "time limit reached";
            break;
        case TveOutcome::InvalidStart:
            r.status = "invalid start: " + res.message;
            break;
        case TveOutcome::InvalidGoal:
            r.status = "invalid goal: " + res.message;
            break;
    }
    if (res.outcome != TveOutcome::Exact)
    {
        r.costFunctionCalls = ctx->travel->costFunctionCalls();
        r.wallSeconds = seconds(start);
        (void)cmc0;
        return r;
    }
    r.solved = true;
    r.raw = retimeWaypoints(*ctx, res.waypoints, tDep);
    r.rawTravelTime = r.raw.back().t - tDep;
    r.rawPathLength = pathLength(r.raw);
    r.path = r.raw;
    if (smoothing)
    {
        const SmoothingResult s = PathSmoother(ctx).smooth(r.path, tDep);
        r.path = s.waypoints;
    }
    r.smoothedWaypoints = r.path.size();
    if (refinement)
    {
        RefinerParams rp;
        if (pp.count("refiner_max_evaluations"))
            rp.maxEvaluations = static_cast<unsigned>(std::max(1.0, pp.at("refiner_max_evaluations")));
        r.path = WaypointRefiner(ctx, rp).refine(r.path, tDep).waypoints;
    }
    r.travelTime = r.path.back().t - tDep;
    r.pathLength = pathLength(r.path);
    r.costFunctionCalls = ctx->travel->costFunctionCalls();
    r.wallSeconds = seconds(start);
    return r;
}

TravelTimeOfDeparture MissionProblem::departureFunction(double gridSize, int sectors) const
{
    return [this, gridSize, sectors](double tDep) {
        PlanOptions o;
        o.gridSize = gridSize;
        o.sectors = sectors;
        o.smoothing = false;
        o.refinement = false;
        try
        {
            const PlannedPath p = plan(tDep, o);
            return p.solved ? p.rawTravelTime : kInf;
        }
        catch (const Error &)
        {
            return kInf;  // e.g. a departure outside the forecast: no trip from there
        }
    };
}

double MissionProblem::minTripDuration(double speed) const
{
    Region r = box_;
    return std::hypot(gx_ - sx_, gy_ - sy_) / (speed + field_->maxSpeed(r));
}

std::shared_ptr<const DiveProfileTravelTime> MissionProblem::diveProfiles(double speed) const
{
    if (!spec_.dive.enabled)
        return nullptr;
    std::shared_ptr<const Bathymetry> bathymetry;
    if (spec_.dive.bathymetryType == "constant")
    {
        const double d = spec_.dive.bathymetryDepth;
        bathymetry = std::make_shared<FunctionBathymetry>([d](double, double) { return d; });
    }
    else if (spec_.dive.bathymetryType == "netcdf")
    {
        std::function<void(double, double, double &, double &)> geo;
        if (projection_)
            geo = [this](double x, double y, double &lon, double &lat) { toGeographic(x, y, lon, lat); };
        try
        {
            bathymetry = std::make_shared<NetCdfBathymetry>(spec_.dive.bathymetryFile, spec_.dive.bathymetryVariable, geo);
        }
        catch (const Error &e)
        {
            throw Error(spec_.file + ": field 'dive_profile.bathymetry': " + e.what());
        }
    }
    TravelTimeParams t = spec_.travel;
    t.speed = speed;
    return std::make_shared<DiveProfileTravelTime>(field_, t, spec_.dive.params, bathymetry, spec_.dive.threads);
}

PilotWaypoints missionWaypoints(const MissionProblem &problem, const PlannedPath &plan)
{
    PilotWaypoints out;
    const auto dive = problem.diveProfiles(plan.speed);
    double t = plan.departure;
    for (std::size_t i = 0; i < plan.path.size(); ++i)
    {
        MissionWaypoint w;
        w.x = plan.path[i].x;
        w.y = plan.path[i].y;
        if (problem.geographic())
        {
            w.geographic = true;
            problem.toGeographic(w.x, w.y, w.lon, w.lat);
        }
        if (i == 0)
            w.time = plan.departure;
        else if (dive)
        {
            const DiveLegResult leg =
                dive->bestProfile(plan.path[i - 1].x, plan.path[i - 1].y, w.x, w.y, t);
            w.profile = leg.profile;
            if (leg.profile >= 0)
                w.dive = dive->profiles()[leg.profile];
            w.legTime = leg.travelTime;
            t += leg.travelTime;
            w.time = t;
        }
        else
        {
            w.time = plan.path[i].t;
            w.legTime = plan.path[i].t - plan.path[i - 1].t;
        }
        w.iso = problem.isoTime(w.time);
        out.waypoints.push_back(w);
    }
    out.travelTime = out.waypoints.empty() ? kInf : out.waypoints.back().time - plan.departure;
    return out;
}

std::vector<SpeedSweepRow> speedSweep(const MissionProblem &problem, double tDep, const std::vector<double> &speeds,
                                      bool progress)
{
    std::vector<SpeedSweepRow> rows;
    for (std::size_t i = 0; i < speeds.size(); ++i)
    {
        if (progress)
        {
            std::fprintf(stderr, "\rspeed sweep: %zu/%zu (V = %g)   ", i + 1, speeds.size(), speeds[i]);
            std::fflush(stderr);
        }
        PlanOptions o;
        o.speed = speeds[i];
        const PlannedPath p = problem.plan(tDep, o);
        rows.push_back({speeds[i], p.solved, p.travelTime, p.pathLength, p.straightLineTime, p.straightLineLength});
    }
    if (progress && !speeds.empty())
        std::fprintf(stderr, "\n");
    return rows;
}

namespace
{
MissionResult runProblem(const MissionProblem &problem, const RunOptions &options,
                         std::chrono::steady_clock::time_point start)
{
    MissionResult result;
    result.spec = problem.spec();
    if (options.outputDirectory)
        result.spec.outputs.directory = *options.outputDirectory;
    const MissionSpec &m = problem.spec();
    double tDep = m.departure.time;
    if (m.departure.window)
    {
        DepartureSearchParams p;
        p.windowBegin = m.departure.begin;
        p.windowEnd = m.departure.end;
        p.spacing = m.departure.spacing;
        p.tolerance = m.departure.tolerance;
        p.horizon = problem.field()->timeEnd();
        p.minTripDuration = problem.minTripDuration(m.vehicle.speed);
        p.threads = m.departure.threads;
        p.progress = options.progress;
        const TravelTimeOfDeparture fine = problem.departureFunction();
        TravelTimeOfDeparture coarse;
        if (m.departure.coarseGridSize > 0)
            coarse = problem.departureFunction(m.departure.coarseGridSize, m.departure.coarseSectors);
        result.departureSearch = optimalDepartureTime(fine, p, coarse);
        if (result.departureSearch->found)
            tDep = result.departureSearch->departure;
    }
    if (m.departure.window && !result.departureSearch->found)
    {
        result.plan.departure = m.departure.begin;
        result.plan.status = "no departure in the window has a path within the forecast";
    }
    else
    {
        result.plan = problem.plan(tDep);
        if (result.plan.solved)
        {
            PilotWaypoints w = missionWaypoints(problem, result.plan);
            result.waypoints = std::move(w.waypoints);
            result.diveProfiles = m.dive.enabled;
            if (m.dive.enabled)
                result.profileSet = makeDiveProfiles(m.dive.params);
            result.diveTravelTime = w.travelTime;
        }
        const std::vector<double> speeds = options.speeds ? *options.speeds : m.speeds;
        if (!speeds.empty())
            result.speedSweep = speedSweep(problem, tDep, speeds, options.progress);
    }
    result.wallSeconds = seconds(start);
    if (options.writeOutputs)
        result.files = writeMissionOutputs(result, problem);
    return result;
}
}  // namespace

MissionResult runMission(const MissionSpec &spec, const RunOptions &options)
{
    const auto start = std::chrono::steady_clock::now();
    MissionSpec s = spec;
    if (options.outputDirectory)
        s.outputs.directory = *options.outputDirectory;
    const MissionProblem problem(std::move(s));
    return runProblem(problem, options, start);
}

MissionResult runMission(const MissionProblem &problem, const RunOptions &options)
{
    return runProblem(problem, options, std::chrono::steady_clock::now());
}
}  // namespace ompl_glider

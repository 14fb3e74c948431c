// The Python module's run() and Result: runMission() with the GIL released, its MissionResult read back as numpy
// arrays and as the output layer's texts (summary.json, GeoJSON, execution.csv), and written by the output layer.
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>
#include <string>
#include <type_traits>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "Bindings.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/output/MapHtml.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/mission/Fleet.h"
#include "ompl_glider/mission/Observations.h"
#include "ompl_glider/output/ExecutionFiles.h"
#include "ompl_glider/output/FleetFiles.h"
#include "ompl_glider/output/OutputWriter.h"
#include "ompl_glider/output/Report.h"
#include "ompl_glider/output/ReachabilityFiles.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/output/SummaryJson.h"

namespace py = pybind11;
using namespace ompl_glider;

namespace ompl_glider_py
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

py::array_t<double> array(const std::vector<double> &v)
{
    return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

/// x, y, t of timed points (and lon, lat where the problem is geographic, else NaN).
py::dict points(const PyResult &r, const std::vector<TimedPoint> &pts)
{
    std::vector<double> x, y, t, lon, lat;
    const bool geo = r.problem->isGeographic();
    for (const TimedPoint &p : pts)
    {
        x.push_back(p.x);
        y.push_back(p.y);
        t.push_back(p.t);
        const LonLat g = geo ? r.problem->toGeographic({p.x, p.y}) : LonLat{kNaN, kNaN};
        lon.push_back(g.lon);
        lat.push_back(g.lat);
    }
    py::dict d;
    d["x"] = array(x);
    d["y"] = array(y);
    d["t"] = array(t);
    d["lon"] = array(lon);
    d["lat"] = array(lat);
    return d;
}

/// The waypoints as columns: the numbers as the result holds them, and the leg and stop of each as the output
/// layer writes them in waypoints.csv (stopName(): "start", a via point's name, the goal's; "" between them and
/// in a mission of one leg); "heading" is the TRUE heading held from the waypoint (trueHeadings()).
py::dict waypoints(const PyResult &r)
{
    std::vector<double> x, y, lon, lat, t, heading, duration, leg;
    std::vector<std::string> iso, stop;
    // the held headings as TRUE bearings (clockwise from true north), as waypoints.csv's heading_true_deg
    const std::vector<double> trueHeading = trueHeadings(r.result, r.problem.get());
    py::array_t<long long> legIndex(static_cast<py::ssize_t>(r.result.waypoints.size()));
    for (std::size_t i = 0; i < r.result.waypoints.size(); ++i)
    {
        const MissionWaypoint &w = r.result.waypoints[i];
        legIndex.mutable_at(static_cast<py::ssize_t>(i)) = w.missionLeg;
        stop.push_back(stopName(r.result, i));
        x.push_back(w.position.x);
        y.push_back(w.position.y);
        lon.push_back(w.geographic ? w.lonLat.lon : kNaN);
        lat.push_back(w.geographic ? w.lonLat.lat : kNaN);
        t.push_back(w.time);
        heading.push_back(trueHeading[i]);
        duration.push_back(w.headingDuration);
        leg.push_back(w.legTime);
        iso.push_back(w.iso);
    }
    py::dict d;
    d["x"] = array(x);
    d["y"] = array(y);
    d["lon"] = array(lon);
    d["lat"] = array(lat);
    d["t"] = array(t);
    d["heading"] = array(heading);
    d["heading_duration"] = array(duration);
    d["leg_time"] = array(leg);
    d["time_iso"] = iso;
    d["leg"] = legIndex;
    d["stop"] = stop;
    return d;
}

/// Polylines as a list of (n, 2) arrays: (x, y) of planning-frame points, (lon, lat) of geographic ones.
template <typename P> py::list polylines(const std::vector<std::vector<P>> &lines)
{
    py::list out;
    for (const auto &line : lines)
    {
        py::array_t<double> a({static_cast<py::ssize_t>(line.size()), py::ssize_t{2}});
        auto v = a.mutable_unchecked<2>();
        for (std::size_t k = 0; k < line.size(); ++k)
        {
            if constexpr (std::is_same_v<P, LonLat>)
                v(k, 0) = line[k].lon, v(k, 1) = line[k].lat;
            else
                v(k, 0) = line[k].x, v(k, 1) = line[k].y;
        }
        out.append(a);
    }
    return out;
}

py::object isochrones(const PyResult &r)
{
    if (!r.result.isochrones)
        return py::none();
    py::list out;
    for (const Isochrone &c : r.result.isochrones->contours)
    {
        py::dict d;
        d["time"] = c.time;
        d["time_iso"] = c.iso;
        d["lines"] = polylines(c.lines);
        d["lonlat"] = polylines(c.lonLat);
        out.append(d);
    }
    return std::move(out);
}

/// What the glider's DAC did to the forecast (Result.correction()): the scales as used and where each came from, the
/// likelihood gained, the innovations' bias and tides, an ensemble's member weights; None without observations.
py::object correction(const PyResult &r)
{
#if OMPL_GLIDER_WITH_NETCDF
    const auto &o = r.problem->observations();
    if (!o)
        return py::none();
    const CorrectionSummary &c = o->correction;
    py::dict d;
    d["used"] = c.used;
    d["length_scale"] = c.params.lengthScale;
    d["time_scale"] = c.params.timeScale;
    d["error_ratio"] = c.params.errorRatio;
    d["length_scale_source"] = c.lengthSource;
    d["time_scale_source"] = c.timeSource;
    d["error_ratio_source"] = c.ratioSource;
    d["dac_estimated_from"] = c.learnedFrom;
    d["log_likelihood_gain"] = c.likelihoodGain;
    d["bias"] = c.mean.active() ? py::object(py::make_tuple(c.mean.bias.u, c.mean.bias.v)) : py::object(py::none());
    py::list tides;
    for (const InnovationMean::Constituent &k : c.mean.tides)
        tides.append(py::dict(py::arg("name") = k.name, py::arg("u_amplitude") = k.amplitude(true),
                              py::arg("u_phase") = k.phase(true), py::arg("v_amplitude") = k.amplitude(false),
                              py::arg("v_phase") = k.phase(false), py::arg("omega") = k.omega));
    d["tides"] = tides;
    std::vector<double> w, rms, a;
    for (const MemberScore &m : o->members)
        w.push_back(m.weight), rms.push_back(m.rmsInnovation), a.push_back(m.coefficient);
    d["member_weights"] = array(w);
    d["member_rms_innovation"] = array(rms);
    d["member_coefficients"] = array(a);
    return std::move(d);
#else
    (void)r;
    return py::none();
#endif
}

py::object arrivalField(const PyResult &r)
{
    if (!r.result.isochrones || r.result.isochrones->arrival.empty())
        return py::none();
    const IsochroneSet &s = *r.result.isochrones;
    std::vector<double> x(s.nx), y(s.ny);
    for (int i = 0; i < s.nx; ++i)
        x[i] = s.x0 + i * s.h;
    for (int j = 0; j < s.ny; ++j)
        y[j] = s.y0 + j * s.h;
    py::array_t<double> t({static_cast<py::ssize_t>(s.ny), static_cast<py::ssize_t>(s.nx)}, s.arrival.data());
    py::dict d;
    d["x"] = array(x);
    d["y"] = array(y);
    d["arrival"] = t;
    return std::move(d);
}

/// The probability of reach (plan(reachability=True), ReachProbability.h) as numpy arrays; None without it.
py::object reachability(const PyResult &r)
{
    if (!r.result.reachability)
        return py::none();
    const ReachProbability &p = *r.result.reachability;
    const auto ny = static_cast<py::ssize_t>(p.ny), nx = static_cast<py::ssize_t>(p.nx);
    std::vector<double> x(p.nx), y(p.ny), goalTravel;
    for (int i = 0; i < p.nx; ++i)
        x[i] = p.x0 + i * p.h;
    for (int j = 0; j < p.ny; ++j)
        y[j] = p.y0 + j * p.h;
    py::array_t<float> prob({static_cast<py::ssize_t>(p.probability.size()), ny, nx});
    auto P = prob.mutable_unchecked<3>();
    for (std::size_t f = 0; f < p.probability.size(); ++f)
        for (py::ssize_t n = 0; n < ny * nx; ++n)
            P(f, n / nx, n % nx) = p.probability[f][static_cast<std::size_t>(n)];
    py::array_t<double> arrival({static_cast<py::ssize_t>(p.memberArrival.size()), ny, nx});
    auto A = arrival.mutable_unchecked<3>();
    for (std::size_t k = 0; k < p.memberArrival.size(); ++k)
        for (py::ssize_t n = 0; n < ny * nx; ++n)
            A(k, n / nx, n % nx) = p.memberArrival[k][static_cast<std::size_t>(n)];
    for (const double t : p.goalTimes)
        goalTravel.push_back(t - p.departure);
    py::dict quantiles, arrivals, isos;
    for (const ReachQuantile &q : p.quantiles)
    {
        quantiles[py::float_(q.q)] = q.reached ? py::object(py::float_(q.travelTime)) : py::object(py::none());
        arrivals[py::float_(q.q)] = q.reached ? py::object(py::float_(q.arrival)) : py::object(py::none());
        isos[py::float_(q.q)] = q.iso.empty() ? py::object(py::none()) : py::object(py::str(q.iso));
    }
    py::list contours;
    for (const ReachContour &c : p.contours)
        contours.append(py::dict(py::arg("time") = c.time, py::arg("time_iso") = c.iso, py::arg("level") = c.level,
                                 py::arg("lines") = polylines(c.lines)));
    py::dict d;
    d["members"] = p.members;
    d["weights"] = array(p.weights);
    d["resolution"] = p.resolution;
    d["x"] = array(x);
    d["y"] = array(y);
    if (!p.lon.empty())
    {
        d["lon"] = py::array_t<double>({ny, nx}, p.lon.data());
        d["lat"] = py::array_t<double>({ny, nx}, p.lat.data());
    }
    else
    {
        d["lon"] = py::none();
        d["lat"] = py::none();
    }
    d["departure"] = p.departure;
    d["horizon"] = p.horizon - p.departure;
    d["times"] = array(p.times);
    d["time_iso"] = p.iso;
    d["levels"] = array(p.levels);
    d["probability"] = prob;
    d["member_arrival"] = arrival;
    d["goal_times"] = array(p.goalTimes);
    d["goal_travel_times"] = array(goalTravel);
    d["goal_probability"] = p.goalProbability;
    d["quantiles"] = quantiles;
    d["quantile_arrivals"] = arrivals;
    d["quantile_iso"] = isos;
    d["contours"] = contours;
    d["stopped"] = p.stopped;
    d["seconds"] = p.seconds;
    return std::move(d);
}

/// The current on an n x n grid over the planning box at time t (NaN: the departure), for maps.
py::dict currentGrid(const PyResult &r, int n, double t)
{
    if (n < 2 || n > 2000)
        throw Error("current_grid(): n must be in 2..2000, got " + std::to_string(n));
    if (std::isnan(t))
        t = r.result.plan.departure;
    const Region &box = r.problem->getBox();
    const double z = r.result.spec.vehicle.depth;
    py::array_t<double> x({n, n}), y({n, n}), u({n, n}), v({n, n}), lon({n, n}), lat({n, n});
    auto X = x.mutable_unchecked<2>(), Y = y.mutable_unchecked<2>(), U = u.mutable_unchecked<2>(),
         V = v.mutable_unchecked<2>(), Lo = lon.mutable_unchecked<2>(), La = lat.mutable_unchecked<2>();
    const bool geo = r.problem->isGeographic();
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            const double px = box.xMin + (box.xMax - box.xMin) * i / (n - 1);
            const double py_ = box.yMin + (box.yMax - box.yMin) * j / (n - 1);
            const Velocity c = r.problem->getField()->velocity(px, py_, z, t);
            X(j, i) = px, Y(j, i) = py_, U(j, i) = c.u, V(j, i) = c.v;
            const LonLat g = geo ? r.problem->toGeographic({px, py_}) : LonLat{kNaN, kNaN};
            Lo(j, i) = g.lon, La(j, i) = g.lat;
        }
    py::dict d;
    d["x"] = x, d["y"] = y, d["u"] = u, d["v"] = v, d["lon"] = lon, d["lat"] = lat, d["t"] = t;
    return d;
}

py::list polygons(const PyResult &r)
{
    py::list out;
    for (const MissionPolygon &p : r.problem->getPolygons())
    {
        py::array_t<double> a({static_cast<py::ssize_t>(p.points.size()), py::ssize_t{2}});
        auto v = a.mutable_unchecked<2>();
        for (std::size_t k = 0; k < p.points.size(); ++k)
            v(k, 0) = p.points[k].x, v(k, 1) = p.points[k].y;
        py::dict d;
        d["name"] = p.name;
        d["kind"] = regionKindName(p.kind);
        d["points"] = a;
        out.append(d);
    }
    return out;
}

/// The progress sink of a run for the Python callback @p progress (none: no sink): called with the GIL held from
/// whichever thread reports; the first exception it raises is kept in @p raised (guarded by @p guard) and raised
/// after the run.
ProgressSink progressSink(const py::object &progress, std::optional<py::error_already_set> &raised, std::mutex &guard)
{
    if (progress.is_none())
        return {};
    PyObject *callback = progress.ptr(); // kept alive by the caller's reference
    return [callback, &raised, &guard](const std::string &line, bool done) {
        const py::gil_scoped_acquire gil;
        const std::lock_guard<std::mutex> lock(guard);
        if (raised)
            return;
        try
        {
            const py::handle function(callback);
            function(line, done);
        }
        catch (py::error_already_set &e)
        {
            raised = std::move(e);
        }
    };
}

/// runMission() on @p spec, the GIL released; progress lines go to @p progress (called with the GIL held; an
/// exception it raises is raised after the run). Bad input is raised as Error with glider_plan's message.
std::shared_ptr<PyResult> run(const MissionSpec &spec, const py::object &progress,
                              std::optional<std::vector<double>> speeds, bool optimum)
{
    auto out = std::make_shared<PyResult>();
    std::optional<py::error_already_set> raised;
    std::mutex guard;
    RunOptions options;
    options.speeds = std::move(speeds);
    options.optimum = optimum;
    options.progress = progressSink(progress, raised, guard);
    runStoppable([&] {
        out->problem = std::make_shared<const MissionProblem>(spec);
        out->result = runMission(*out->problem, options);
    });
    options.progress = nullptr;
    if (raised)
        throw *raised;
    const PlannedPath &p = out->result.plan;
    if (!p.solved && p.badInput.any())
        throw Error(out->problem->getSpec().place(p.badInput.field()) + ": " + p.reason);
    return out;
}

/// runFleet() (the library's fleet runner, as glider_plan --mission runs a fleet) on @p spec, the GIL released: each
/// glider's result by name in the fleet's order, and when @p directory is given the command line's fleet files
/// (a folder per glider, fleet.csv, summary.json, all or nothing) with the paths written.
std::pair<std::vector<std::pair<std::string, std::shared_ptr<PyResult>>>, std::vector<std::string>> runFleetPy(
    const MissionSpec &spec, const py::object &progress, const std::string &directory)
{
    std::optional<py::error_already_set> raised;
    std::mutex guard;
    RunOptions options;
    options.progress = progressSink(progress, raised, guard);
    std::map<std::string, std::shared_ptr<PyResult>> byName;
    std::vector<FleetGlider> gliders;
    std::vector<std::string> written;
    runStoppable([&] {
        const auto start = std::chrono::steady_clock::now();
        const FleetKeep keep = [&](const MissionResult &result, const MissionProblem &problem) {
            auto r = std::make_shared<PyResult>();
            r->problem = std::make_shared<const MissionProblem>(problem);
            r->result = result;
            {
                const std::lock_guard<std::mutex> lock(guard);
                byName[result.spec.name] = r;
            }
            return directory.empty() ? std::string() : renderOutputFiles(result, problem);
        };
        gliders = runFleet(spec, options, keep);
        for (const FleetGlider &g : gliders)
            if (!g.row.badInput.empty())
                throw Error("glider '" + g.row.name + "': " + g.row.badInput + ": " + g.row.reason);
        if (!directory.empty() && !stopRequested()) // Ctrl-C: nothing written (writeOutputFiles checks too)
        {
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            written = writeOutputFiles(directory, fleetOutputFiles(spec, gliders, wall));
        }
    });
    options.progress = nullptr;
    if (raised)
        throw *raised;
    std::vector<std::pair<std::string, std::shared_ptr<PyResult>>> out;
    for (const FleetGlider &g : gliders)
        out.emplace_back(g.row.name, byName.at(g.row.name));
    return {out, written};
}

std::vector<std::string> write(const PyResult &r, const std::string &directory)
{
    const py::gil_scoped_release release;
    checkOutputDirectory(directory);
    return writeOutputFiles(directory, outputFiles(r.result, *r.problem));
}
} // namespace

// KeyboardInterrupt is raised by Python's handler on the main thread (this one); it is raised here once the work
// has returned, within a moment instead of when the work would have finished
void runStoppable(const std::function<void()> &work)
{
    std::exception_ptr failed;
    std::atomic<bool> done{false};
    std::optional<py::error_already_set> interrupted;
    {
        const py::gil_scoped_release release;
        std::thread worker([&] {
            try
            {
                work();
            }
            catch (...)
            {
                failed = std::current_exception();
            }
            done.store(true);
        });
        while (!done.load())
        {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            if (interrupted)
                continue;
            const py::gil_scoped_acquire gil;
            if (PyErr_CheckSignals() != 0)
            {
                interrupted.emplace(); // the KeyboardInterrupt (or the handler's exception), kept for after the run
                requestStop();
            }
        }
        worker.join();
    }
    if (interrupted)
    {
        clearStop();
        throw *interrupted;
    }
    if (failed)
        std::rethrow_exception(failed);
}

void bindResult(py::module_ &m)
{
    using R = PyResult;
    py::class_<R, std::shared_ptr<R>>(m, "Result", "The result of one run (MissionResult and its problem).")
        .def_property_readonly("solved", [](const R &r) { return r.result.plan.solved; })
        .def_property_readonly("status", [](const R &r) { return statusText(r.result.plan.status); })
        .def_property_readonly("reason", [](const R &r) { return r.result.plan.reason; })
        .def_property_readonly("no_path_cause", [](const R &r) { return causeName(r.result.plan.noPath.cause); })
        .def_property_readonly("planner", [](const R &r) { return r.result.plan.planner; })
        .def_property_readonly("switched_from", [](const R &r) { return r.result.plan.switchedFrom; })
        .def_property_readonly("travel_time", [](const R &r) { return r.result.plan.travelTime; })
        .def_property_readonly("departure", [](const R &r) { return r.result.plan.departure; })
        .def_property_readonly("speed", [](const R &r) { return r.result.plan.speed; })
        .def_property_readonly("path_length", [](const R &r) { return r.result.plan.pathLength; })
        .def_property_readonly("hold_time", [](const R &r) { return r.result.plan.holdTime; })
        .def_property_readonly("straight_line_time", [](const R &r) { return r.result.plan.straightLineTime; })
        .def_property_readonly("planning_seconds", [](const R &r) { return r.result.plan.planningSeconds; })
        .def_property_readonly("wall_seconds", [](const R &r) { return r.result.wallSeconds; })
        .def_property_readonly("cost_function_calls", [](const R &r) { return r.result.plan.totalCostFunctionCalls(); })
        .def_property_readonly("current_model_calls", [](const R &r) { return r.result.plan.currentModelCalls; })
        .def_property_readonly("geographic", [](const R &r) { return r.problem->isGeographic(); })
        .def_property_readonly("mission", [](const R &r) { return r.problem->getSpec(); })
        .def_property_readonly("box",
                               [](const R &r) {
                                   const Region &b = r.problem->getBox();
                                   return py::make_tuple(b.xMin, b.yMin, b.xMax, b.yMax);
                               })
        .def_property_readonly(
            "start", [](const R &r) { return py::make_tuple(r.problem->getStart().x, r.problem->getStart().y); })
        .def_property_readonly(
            "goal", [](const R &r) { return py::make_tuple(r.problem->getGoal().x, r.problem->getGoal().y); })
        .def("waypoints", &waypoints)
        .def("waypoints_csv", [](const R &r) { return waypointsCsv(r.result, r.problem.get()); })
        .def("path", [](const R &r) { return points(r, r.result.plan.path); })
        .def("track", [](const R &r) { return points(r, r.result.plan.track); })
        .def("polygons", &polygons)
        .def("isochrones", &isochrones)
        .def("arrival_field", &arrivalField)
        .def("reachability", &reachability)
        .def("reachability_geojson", [](const R &r) { return reachabilityGeoJson(r.result); })
        .def("current_grid", &currentGrid, py::arg("n") = 25, py::arg("t") = kNaN)
        .def("summary_json", [](const R &r) { return summaryJson(r.result, *r.problem, {}); })
        .def("correction", &correction)
#if OMPL_GLIDER_WITH_MAP
        .def("map_html", [](const R &r) { return mapHtml(r.result, *r.problem); })
#endif
        .def("route_geojson", [](const R &r) { return routeGeoJson(r.result, r.problem.get()); })
        .def("isochrones_geojson", [](const R &r) { return isochronesGeoJson(r.result); })
        .def("report",
             [](const R &r) {
                 std::ostringstream s;
                 printReport(s, r.result, r.problem.get());
                 return s.str();
             })
        .def("execution_csv",
             [](const R &r) {
                 return r.result.execution ? executionCsv(*r.result.execution, *r.problem) : std::string();
             })
        .def("speed_sweep",
             [](const R &r) {
                 std::vector<double> s, t, l;
                 for (const SpeedSweepRow &row : r.result.speedSweep)
                     s.push_back(row.speed), t.push_back(row.travelTime), l.push_back(row.pathLength);
                 py::dict d;
                 d["speed"] = array(s), d["travel_time"] = array(t), d["path_length"] = array(l);
                 return d;
             })
        .def("ensemble",
             [](const R &r) -> py::object {
                 if (!r.result.plan.ensemble)
                     return py::none();
                 const EnsemblePlan &e = *r.result.plan.ensemble;
                 py::dict d;
                 d["chosen"] = e.chosen;
                 d["objective_value"] = e.objectiveValue;
                 d["member_travel_times"] = array(e.memberTravelTimes);
                 py::list c;
                 for (const EnsemblePlan::Candidate &k : e.candidates)
                     c.append(py::dict(py::arg("name") = k.name, py::arg("solved") = k.solved,
                                       py::arg("objective_value") = k.objectiveValue,
                                       py::arg("member_travel_times") = array(k.memberTravelTimes)));
                 d["candidates"] = c;
                 return std::move(d);
             })
        .def("write", &write, py::arg("directory"));
    m.def("run", &run, py::arg("mission"), py::arg("progress") = py::none(), py::arg("speeds") = py::none(),
          py::arg("optimum") = false, "runMission() on a mission (the GIL released).");
    m.def("run_fleet", &runFleetPy, py::arg("mission"), py::arg("progress") = py::none(),
          py::arg("directory") = std::string(),
          "runFleet() on a mission with a fleet (the GIL released): [(name, result)], and the files written to "
          "directory (none when empty).");
}
} // namespace ompl_glider_py

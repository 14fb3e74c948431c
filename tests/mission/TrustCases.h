#pragma once
// Random problems for the trust property ("on any problem the default is the best route there is"): flows, speeds,
// start/goal pairs and departures drawn from a seed, each planned by the default pipeline and measured against the
// independent extremal sweep (ExtremalSweep.h). Shared by the property test and bench_trust.

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ExtremalSweep.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"

namespace trust
{
using namespace ompl_glider;

/// A flow of the trials: its mission (region, current), the speeds tried and the RK4 step of the reference.
struct Flow
{
    std::string name;
    MissionSpec mission;
    std::vector<double> departures;
    double referenceStep{0.01}; ///< the sweep's RK4 step (field time units)
};

inline MissionSpec analytic(const std::string &type, const std::map<std::string, double> &params, Box box)
{
    MissionSpec m = defaultGulfStreamMission();
    m.current.type = type;
    m.current.parameters = params;
    m.region.set = true;
    m.region.xy = box;
    m.departure.time = 0.0;
    return m;
}

/// The four flows of the issue: the meandering jet (the built-in mission), a steady double gyre, a Rankine vortex in
/// a stream and a linear shear.
inline std::vector<Flow> flows()
{
    std::vector<Flow> f;
    f.push_back({"jet", defaultGulfStreamMission(), {0.0, 2.0, 5.0}, 0.01});
    f.push_back({"double gyre",
                 analytic("double_gyre", {{"amplitude", 0.8}, {"length", 5.0}}, Box{0.0, 10.0, 0.0, 5.0}),
                 {0.0},
                 0.01});
    f.push_back({"Rankine vortex",
                 analytic("rankine_vortex", {{"x0", 5.0}, {"y0", 0.0}, {"radius", 1.5}, {"vmax", 0.8}, {"u", 0.15}},
                          Box{0.0, 10.0, -4.0, 4.0}),
                 {0.0},
                 0.01});
    f.push_back({"shear", analytic("linear_shear", {{"a", -0.2}}, Box{0.0, 10.0, -4.0, 4.0}), {0.0}, 0.01});
    return f;
}

/// The tolerance of the default against the best extremal at speed V (the figures).
inline double tolerance(double speed)
{
    return speed >= 0.3 - 1e-12 ? 0.005 : speed >= 0.15 - 1e-12 ? 0.01 : 0.015;
}

/// One trial: a problem and how the default fared against the reference.
struct Trial
{
    std::string flow;
    double speed{0}, departure{0};
    Point2 start, goal;
    bool defaultSolved{false};
    double defaultTime{std::numeric_limits<double>::infinity()};
    std::string winner;         ///< the global check's winner
    bool referenceFound{false}; ///< the sweep found an extremal through the goal
    double referenceTime{std::numeric_limits<double>::infinity()};
    double seconds{0.0}; ///< wall time of the default plan
    double ratio() const { return defaultTime / referenceTime; }
};

/// @p count random pairs in @p flow at @p speed: start and goal inside the region 0.5 from its edges, at least a
/// quarter of its larger side apart; a departure drawn from the flow's list. With @p eastward the goal lies east of
/// the start (along the jet's core: at V = 0.15 most other goals lie where the jet carries the glider off).
inline std::vector<Trial> draw(const Flow &flow, double speed, int count, std::mt19937 &rng, bool eastward = false)
{
    const Box b = flow.mission.region.xy;
    std::uniform_real_distribution<double> ux(b.xMin + 0.5, b.xMax - 0.5), uy(b.yMin + 0.5, b.yMax - 0.5);
    std::uniform_int_distribution<std::size_t> ud(0, flow.departures.size() - 1);
    const double minD = 0.25 * std::max(b.xMax - b.xMin, b.yMax - b.yMin);
    std::vector<Trial> out;
    while (static_cast<int>(out.size()) < count)
    {
        Trial t;
        t.flow = flow.name;
        t.speed = speed;
        t.start = {ux(rng), uy(rng)};
        t.goal = {ux(rng), uy(rng)};
        t.departure = flow.departures[ud(rng)];
        if (eastward && t.goal.x < t.start.x)
            std::swap(t.start, t.goal);
        if (std::hypot(t.goal.x - t.start.x, t.goal.y - t.start.y) >= minD)
            out.push_back(t);
    }
    return out;
}

/// The independent sweep's setup for @p problem: the field's velocity at depth 0, the speed, the planning box, the
/// longest extremal @p maxTime and a fixed RK4 step of about @p step; finer windows where the sweep finds none.
inline extremal_sweep::Setup sweepSetup(const MissionProblem &problem, double departure, double speed, double maxTime,
                                        double step)
{
    const GliderProblem gp = problem.gliderProblem(departure, speed);
    extremal_sweep::Setup s;
    const std::shared_ptr<const CurrentField> field = problem.getField();
    s.current = [field](double x, double y, double tt, double &u, double &v) {
        const Velocity c = field->velocity(x, y, 0.0, tt);
        u = c.u;
        v = c.v;
    };
    s.speed = speed;
    s.xMin = gp.xMin;
    s.xMax = gp.xMax;
    s.yMin = gp.yMin;
    s.yMax = gp.yMax;
    s.maxTime = maxTime;
    s.steps = std::max(400, static_cast<int>(std::ceil(maxTime / step)));
    s.zoom = 3; // where the sweep finds none, three windows down about its nearest miss
    return s;
}

/// Plans the trial with the default pipeline and sweeps the reference up to the default's time (or the planning
/// window when the default has no route).
inline void run(const Flow &flow, Trial &t)
{
    MissionSpec m = flow.mission;
    m.start.xy = t.start;
    m.goal.xy = t.goal;
    m.vehicle.speed = m.travel.speed = t.speed;
    m.departure.time = t.departure;
    const MissionProblem problem(m);
    const auto a = std::chrono::steady_clock::now();
    const PlannedPath p = planRoute(problem, t.departure);
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
    t.defaultSolved = p.solved;
    t.defaultTime = p.solved ? p.travelTime : std::numeric_limits<double>::infinity();
    t.winner = p.globalCheck ? p.globalCheck->winner : std::string();
    // a quarter past the default's time: the neighbours of an extremal through the goal pass it later
    const double horizon = problem.gliderProblem(t.departure, t.speed).horizon;
    const extremal_sweep::Setup s = sweepSetup(
        problem, t.departure, t.speed, p.solved ? std::min(1.25 * p.travelTime, horizon) : horizon, flow.referenceStep);
    const extremal_sweep::Best best = extremal_sweep::fastest(s, t.start.x, t.start.y, t.departure, t.goal.x, t.goal.y);
    t.referenceFound = best.found;
    t.referenceTime = best.time;
}
} // namespace trust

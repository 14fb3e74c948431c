#include "ompl_glider/output/Report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "ompl_glider/Config.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/mission/EnsembleDraw.h"
#include "ompl_glider/output/RouteFiles.h"
#include "ompl_glider/registry/PlannerRegistry.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif
#include "../io/NumberText.h"

namespace ompl_glider
{
namespace
{
/// Empty for NaN, "inf" for either infinity, else text::csvNumber().
std::string reportNumber(double v)
{
    return std::isinf(v) ? "inf" : text::csvNumber(v);
}

/// printf into a string (the report's lines are short).
template <class... A> std::string format(const char *fmt, A... args)
{
    char buf[512];
    std::snprintf(buf, sizeof buf, fmt, args...);
    return buf;
}

/// A length for people: km with physical length units ("109.479 km"), else the field's number ("%.4f").
std::string lengthText(const MissionSpec &m, double d)
{
    return m.physicalUnits().length ? format("%.3f km", d * m.metresPerUnit() / 1000.0) : format("%.4f", d);
}

/// Where a bearing is measured from: true north (lon/lat and the problem), the planning frame's grid north (lon/lat
/// without it), or nothing to say (a Cartesian mission).
const char *northOf(const MissionResult &r, const MissionProblem *problem)
{
    const bool geographic = !r.waypoints.empty() && r.waypoints.front().geographic;
    return !geographic ? "" : problem ? " true" : " grid";
}

void printWaypoints(std::ostream &out, const MissionResult &r, const MissionProblem *problem)
{
    // a heading route (or a mission's legs of held headings): the heading held from each waypoint and for how long
    bool headings = false;
    for (const MissionWaypoint &w : r.waypoints)
        headings = headings || std::isfinite(w.heading);
    const std::string north = northOf(r, problem);
    std::vector<double> bearing; // as the pilot files write them: from true north where the problem says where it is
    for (const MissionWaypoint &w : r.waypoints)
        bearing.push_back(w.heading);
    if (headings && north == " true")
        bearing = trueHeadings(r, problem);
    out << format("%4s %12s %12s %11s %10s %14s %22s %16s", "#", "x", "y", "lon", "lat", "arrival", "arrival (UTC)",
                  "dive profile");
    out << (headings ? format(" %11s %12s\n", ("heading" + north).c_str(), "held for") : std::string("\n"));
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        const MissionWaypoint &w = r.waypoints[i];
        std::string prof;
        if (r.diveProfiles && i > 0 && w.profile >= 0)
            prof = reportNumber(w.dive.climbTo) + "-" + reportNumber(w.dive.diveTo);
        out << format("%4zu %12.6g %12.6g %11s %10s %14s %22s %16s", i, w.position.x, w.position.y,
                      w.geographic ? format("%.6f", w.lonLat.lon).c_str() : "",
                      w.geographic ? format("%.6f", w.lonLat.lat).c_str() : "", reportNumber(w.time).c_str(),
                      w.iso.c_str(), prof.c_str());
        if (headings && std::isfinite(w.heading))
            out << format(" %11s %12s\n", format("%.1f deg", bearing[i]).c_str(),
                          (r.spec.physicalUnits().time
                               ? format("%.2f h", w.headingDuration * r.spec.timeUnitSeconds / 3600.0)
                               : reportNumber(w.headingDuration))
                              .c_str());
        else
            out << "\n";
    }
}

/// A mission of several legs: the order of the via points (and the free-order search), then one line per leg.
void printLegs(std::ostream &out, const MissionResult &r)
{
    if (r.legs.empty())
        return;
    const MissionSpec &m = r.spec;
    // durations in the table: hours where the unit is known (a column's width), else the field's number
    const auto span = [&](double t) {
        return m.physicalUnits().time ? format("%.2f h", t * m.timeUnitSeconds / 3600.0) : format("%.6g", t);
    };
    std::string order;
    for (const std::size_t i : r.order)
        order += (order.empty() ? "" : " -> ") + m.waypoints[i].name;
    out << "Via points:         " << m.waypoints.size() << ", visited " << order << " (order "
        << visitOrderName(m.order) << ")\n";
    if (r.orderSearch)
    {
        const OrderSearch &s = *r.orderSearch;
        out << "Order search:       " << s.ordersEvaluated << " of " << s.ordersTotal << " orders planned to the goal ("
            << s.legsPlanned << " legs planned); the given order "
            << (std::isfinite(s.givenTime) ? span(s.givenTime) : std::string("has no route"))
            << (std::isfinite(s.chosenTime)
                    ? format(", the chosen one %s (%.2f%% faster)", span(s.chosenTime).c_str(), 100.0 * s.gain)
                    : std::string(", no order has a route"))
            << (s.stopped.empty() ? std::string()
                                  : "; the search stopped at " + s.stopped +
                                        ": the chosen order is the fastest of those planned, not proven the fastest")
            << "\n";
    }
    out << format("%4s  %-28s %22s %22s %14s %10s  %-10s %s\n", "leg", "from -> to", "departure", "arrival",
                  "travel time", "stay", "planner", "status (global check)");
    for (const PlannedLeg &l : r.legs)
    {
        const PlannedPath &p = l.plan;
        // the date of a waypoint of the whole route where the mission has dates, else the field time
        const auto when = [&](std::size_t i, double t) {
            return i < r.waypoints.size() && !r.waypoints[i].iso.empty() ? r.waypoints[i].iso : format("%.6g", t);
        };
        std::string check = p.globalCheck ? " (winner " + p.globalCheck->winner + ")" : "";
        out << format("%4zu  %-28s %22s %22s %14s %10s  %-10s %s%s\n", l.index + 1, (l.from + " -> " + l.to).c_str(),
                      when(p.solved ? l.firstPoint : r.waypoints.size(), p.departure).c_str(),
                      p.solved ? when(l.lastPoint, l.arrival()).c_str() : "-",
                      p.solved ? span(p.travelTime).c_str() : "-", l.stay > 0.0 ? span(l.stay).c_str() : "",
                      p.planner.c_str(), statusText(p.status).c_str(), check.c_str());
        if (!p.solved)
            out << "      " << p.reason << "\n";
    }
}

/// A plan's route kind: "held headings (63 segments)" or "straight legs (12 legs)".
std::string routeKind(const PlannedPath &p)
{
    if (p.headingRoute())
        return format("held headings (%zu segments)", p.headings->segments.size());
    return format("straight legs (%zu legs)", p.path.empty() ? std::size_t{0} : p.path.size() - 1);
}

/// The route's kind (of each leg in a mission of several legs): held headings or straight legs, and the switch to
/// another planner.
void printRouteModel(std::ostream &out, const MissionResult &r)
{
    const PlannedPath &p = r.plan;
    const MissionSpec &m = r.spec;
    // a duration as a pilot reads it (days and hours, the seconds beside them) where the mission has a time unit
    const auto span = [&](double t) {
        return m.physicalUnits().time ? text::durationText(t * m.timeUnitSeconds) : format("%.6f", t);
    };
    if (!p.switchedFrom.empty())
        out << "Switched:           " << p.switchReason << "; planned with " << p.planner << "\n";
    if (!p.solved)
        return;
    if (r.legs.empty())
        out << "Route:              " << routeKind(p) << "\n";
    for (const PlannedLeg &l : r.legs) // each leg as it is flown (and written in the pilot files)
        out << (l.index == 0 ? "Route:              " : "                    ") << "leg " << l.index + 1 << " ("
            << l.from << " -> " << l.to << "): " << routeKind(l.plan) << "\n";
    if (p.solved && p.reflown && std::isfinite(p.plannerTravelTime))
        out << "Re-flight:          " << span(p.reflownTravelTime)
            << " (the planner's own legs: " << span(p.plannerTravelTime)
            << format(", %+.2e relative)\n", (p.plannerTravelTime - p.reflownTravelTime) / p.reflownTravelTime);
    else if (p.solved && p.reflown)
        out << "Re-flight:          " << span(p.reflownTravelTime)
            << ", ends " +
                   (m.physicalUnits().length ? format("%.3g m", p.reflownEndDistance * m.metresPerUnit())
                                             : format("%.3g", p.reflownEndDistance)) +
                   " from the goal\n";
    if (p.solved && !p.reflightNote.empty())
        out << "Re-flight note:     " << p.reflightNote << "\n";
}

/// The runs that were never flown (no plan on the forecast): "2 of 3 runs not flown: <reason> (runs 1, 2)", one
/// reason at a time.
void printRunsNotFlown(std::ostream &out, const ExecutionResult &e)
{
    std::vector<std::pair<std::string, std::string>> reasons; // reason, the runs
    std::size_t notFlown = 0;
    for (const ExecutionRun &run : e.runs)
    {
        if (run.planned)
            continue;
        ++notFlown;
        const std::string why = run.reason.empty() ? "no plan on the forecast" : run.reason;
        auto it = std::find_if(reasons.begin(), reasons.end(), [&](const auto &x) { return x.first == why; });
        const std::string name = run.index == 0 ? "the mission's own" : std::to_string(run.index);
        if (it == reasons.end())
            reasons.push_back({why, name});
        else
            it->second += ", " + name;
    }
    if (notFlown == 0)
        return;
    out << format("  %zu of %zu runs not flown (no plan on the forecast):\n", notFlown, e.runs.size());
    for (const auto &[why, runs] : reasons)
        out << "    " << why << " (run" << (runs.find(',') == std::string::npos ? " " : "s ") << runs << ")\n";
}

/// Why the runs flown did not count as reached: the mission's own run in full, the batch's counted by kind.
void printNotReached(std::ostream &out, const ExecutionResult &e)
{
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const std::string name = controlStrategyName(e.strategies[k]);
        const ExecutionRun &own = e.runs.front();
        if (own.planned && !own.flown[k].reached)
            out << "  not reached       " << name << (e.runs.size() > 1 ? " (the mission's own run)" : "") << ": "
                << own.flown[k].notReachedWhy << "\n";
        std::size_t grounded = 0, station = 0, late = 0, time = 0;
        for (std::size_t i = 1; i < e.runs.size(); ++i)
        {
            const ExecutionRun &run = e.runs[i];
            if (!run.planned || run.flown[k].reached)
                continue;
            const FlownTrack &f = run.flown[k];
            (f.grounded                           ? grounded
             : f.stationsReached < e.stops.size() ? station
             : f.windowsMissed > 0                ? late
                                                  : time)++;
        }
        std::string kinds;
        for (const auto &[n, what] :
             {std::pair<std::size_t, const char *>{time, "not within the radius by the run's end"},
              {station, "a station not reached"},
              {late, "a station reached after its window"},
              {grounded, "grounded"}})
            if (n > 0)
                kinds += format("%s%zu %s", kinds.empty() ? "" : ", ", n, what);
        if (!kinds.empty())
            out << "  not reached       " << name << " (the batch): " << kinds << "\n";
    }
}

/// The execution's strategies over its runs: reached, grounded, the median distance to the goal at the planned
/// arrival and at the end of the run and, where the truth is not the forecast, the arrival over the oracle's
/// (ExecutionResult::oracle); then why runs were not reached or not flown.
void printExecutionTable(std::ostream &out, const ExecutionResult &e, const MissionSpec &m)
{
    out << format("  %-22s %9s %8s %16s %16s", "strategy", "reached", "grounded", "distance to goal", "");
    out << (e.oracle ? "  over oracle\n" : "\n");
    out << format("  %-22s %9s %8s %16s %16s", "", "", "", "at planned arr.", "at the end");
    out << (e.oracle ? "  median / q3 (runs)\n" : "\n");
    for (std::size_t k = 0; k < e.spread.size(); ++k)
    {
        const StrategySpread &s = e.spread[k];
        std::vector<double> ends; // the distance to the goal where each flight ended
        for (const ExecutionRun &run : e.runs)
            if (run.planned && !run.flown[k].track.empty())
                ends.push_back(
                    std::hypot(run.flown[k].track.back().x - run.goal.x, run.flown[k].track.back().y - run.goal.y));
        const MeasureSpread end = measureSpread(ends);
        const std::string reached = format("%zu / %zu", s.reached, s.runs);
        const std::string distance = s.finalDistance.count ? lengthText(m, s.finalDistance.median) : "-";
        out << format("  %-22s %9s %8zu %16s %16s", s.strategy.c_str(), reached.c_str(), s.grounded, distance.c_str(),
                      end.count ? lengthText(m, end.median).c_str() : "-");
        if (e.oracle)
            out << (s.overOracle.count
                        ? format("  %.3f / %.3f (%zu)", s.overOracle.median, s.overOracle.q3, s.overOracle.count)
                        : std::string("  - (0)"));
        out << "\n";
    }
    if (e.runs.size() > 1)
        out << "  (medians over the runs flown; distances to each run's goal)\n";
    if (e.oracle)
    {
        std::size_t reached = 0;
        for (const ExecutionRun &run : e.runs)
            reached += std::isfinite(run.oracleArrival) ? 1 : 0;
        out << format("  oracle (planned and flown on the truth) reached %zu / %zu runs (%.1f s)\n", reached,
                      e.runs.size(), e.oracleSeconds);
    }
    printNotReached(out, e);
    printRunsNotFlown(out, e);
}

/// The global check of the route class: the candidates and which one won, by how much.
void printGlobalCheck(std::ostream &out, const PlannedPath &p, const MissionSpec &m)
{
    if (!p.globalCheck)
        return;
    const GlobalCheck &g = *p.globalCheck;
    const auto span = [&](double t) {
        return m.physicalUnits().time ? text::durationText(t * m.timeUnitSeconds) : format("%.4f", t);
    };
    out << "Global check:       " << g.headings << " extremals shot from the start, "
        << (g.extremalFound ? "the fastest through the goal " + span(g.extremalTime)
                            : std::string("none through the goal"))
        << format(" (%.2f s)\n", g.seconds);
    if (g.timedOut)
        out << format("  time limit        the check's %g s ended its scans before they were done\n", g.timeLimit);
    if (g.finerHeadings > 0)
        out << "  finer scans       " << g.finerHeadings << " headings in narrowing windows"
            << (std::isfinite(g.levelSetTime) ? "; the level set's first arrival " + span(g.levelSetTime)
                : g.levelSetBudgetSpent       ? format("; the level set's budget of %llu node updates spent before "
                                                             "its front reached the goal",
                                                       static_cast<unsigned long long>(g.levelSetBudget))
                                              : std::string())
            << "\n";
    for (const RouteCandidate &c : g.candidates)
        out << "  candidate         " << c.name << ": " << (c.solved ? span(c.travelTime) : "no route (" + c.why + ")")
            << (c.name == g.winner ? "  <- the route" : "") << "\n";
    if (!g.winner.empty() && g.winner != g.candidates.front().name)
        out << format("  the planner's route was in another route class: %.2f%% faster now\n", 100.0 * g.gain);
}

/// An ensemble's plan: robust over every member, or the one most likely to arrive (in how many members, which not).
void printEnsemblePlan(std::ostream &out, const PlannedPath &p, const MissionSpec &m)
{
    if (!p.ensemble || !p.solved)
        return;
    const EnsemblePlan &e = *p.ensemble;
    const auto span = [&](double t) {
        return m.physicalUnits().time ? text::durationText(t * m.timeUnitSeconds) : format("%.4f", t);
    };
    std::size_t arriving = 0;
    std::string missing;
    for (std::size_t k = 0; k < e.memberTravelTimes.size(); ++k)
        if (std::isfinite(e.memberTravelTimes[k]))
            ++arriving;
        else
            missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    const std::size_t n = e.memberTravelTimes.size();
    const std::string on = e.chosen == "mean" ? "the members' mean" : e.chosen;
    if (arriving == n)
        out << "Ensemble:           robust: arrives in every one of the " << n << " members, planned on " << on << "; "
            << ensembleObjectiveName(e.objective) << " " << span(e.objectiveValue) << "\n";
    else
        out << "Ensemble:           arrives in " << arriving << " of " << n
            << " members, p = " << format("%.2f", e.arrivalProbability)
            << " (no candidate arrives in every member: the plan most "
            << "likely to arrive, planned on " << on << "); not in member" << (n - arriving > 1 ? "s " : " ") << missing
            << "; " << ensembleObjectiveName(e.objective) << " over those it reaches " << span(e.objectiveValue)
            << "\n";
}
} // namespace

std::string speedSweepTable(const std::vector<SpeedSweepRow> &rows)
{
    std::string s = format("%8s %14s %12s %18s %14s\n", "speed", "travel time", "path length", "straight-line time",
                           "straight length");
    for (const auto &r : rows)
    {
        const std::string tt = r.solved ? reportNumber(r.travelTime) : "no path";
        const std::string st = std::isfinite(r.straightLineTime) ? reportNumber(r.straightLineTime) : "impassable";
        s += format("%8.4g %14s %12.6g %18s %14.6g\n", r.speed, tt.c_str(), r.pathLength, st.c_str(),
                    r.straightLineLength);
    }
    return s;
}

/// The probability of reach over the ensemble's members ([SubramaniStochastic]): how it was computed, the goal's
/// probability by the horizon and its arrival quantiles after the departure.
void printReachability(std::ostream &out, const MissionResult &r)
{
    if (!r.reachability)
        return;
    const ReachProbability &p = *r.reachability;
    const MissionSpec &m = r.spec;
    const auto span = [&m](double t) {
        return m.physicalUnits().time ? text::durationText(t * m.timeUnitSeconds) : reportNumber(t);
    };
    out << "Reachability:       " << p.members << (p.members == 1 ? " member" : " members") << ", cell "
        << reportNumber(p.resolution) << ", horizon " << span(p.horizon - p.departure) << ", " << p.times.size()
        << " frames, " << format("%.1f s", p.seconds) << (p.stopped ? " (stopped)" : "") << "\n";
    std::string q;
    for (const ReachQuantile &x : p.quantiles)
        q += format(", %g %%: ", 100.0 * x.q) + (x.reached ? span(x.travelTime) : std::string("not by the horizon"));
    out << "Goal by horizon:    p = " << reportNumber(p.goalProbability) << q << "\n";
}

namespace
{
/// The report's head: the mission, its current and planner, the departure (and its search), the status.
void printMissionHeader(std::ostream &out, const MissionResult &r)
{
    const PlannedPath &p = r.plan;
    const MissionSpec &m = r.spec;
    out << "Mission:            " << m.name << " (" << m.file << "), current " << m.current.type;
    if (m.current.isForecast() && !m.current.file.empty()) // a Zarr store, a GRIB file, an OPeNDAP dataset...
        out << " (" << forecastSourceKind(m.current.file) << (m.current.files.size() > 1 ? "s" : "") << ")";
    out << "\n";
    if (!m.current.members.empty()) // an ensemble: how many members, and how they were drawn
        out << "Current:            " << ensembleDescription(m.current) << "\n";
    out << "Planner:            " << p.planner;
    const PlannerEntry *entry = findPlanner(p.planner.empty() ? m.planner.name : p.planner);
    if (m.planner.gridSize > 0 && entry && entry->lattice()) // grid and sectors are the lattice's
        out << " (grid "
            << (m.physicalUnits().length ? lengthText(m, m.planner.gridSize) : format("%g", m.planner.gridSize))
            << format(", %d sectors)", m.planner.sectors);
    out << ", V = " << reportNumber(p.speed) << "\n";
    if (r.departureSearch)
    {
        const DepartureSearchResult &d = *r.departureSearch;
        out << format("Departure search:   [%g, %g], %zu fine + %zu coarse searches in %.3f s, best %s\n",
                      m.departure.begin, d.windowEnd, d.fineEvaluations, d.coarseEvaluations, d.wallSeconds,
                      d.found ? reportNumber(d.departure).c_str() : "none");
    }
    const std::string iso = r.waypoints.empty() ? r.departureIso : r.waypoints.front().iso;
    out << "Departure:          " << reportNumber(p.departure) << (iso.empty() ? "" : " (" + iso + ")") << "\n";
#if OMPL_GLIDER_WITH_NETCDF
    if (const std::string resumed = resumeNote(m); !resumed.empty())
        out << "Resumed:            " << resumed << "\n";
#endif
    out << "Status:             " << statusText(p.status) << (p.solved ? "" : "\nReason:             " + p.reason)
        << "\n";
}

/// Where the route comes closest to land, how close, and the keep-off distance beside it.
void printClosestLand(std::ostream &out, const MissionResult &r)
{
    const MissionSpec &m = r.spec;
    if (!std::isfinite(r.closestLand.distance))
        return;
    const double mpu = m.metresPerUnit();
    const std::string d = m.physicalUnits().length ? format("%.3f km", r.closestLand.distance * mpu / 1000.0)
                                                   : reportNumber(r.closestLand.distance);
    out << "Closest to land:    " << d;
    if (r.closestLandLonLat)
        out << format(" at %.5f, %.5f", r.closestLandLonLat->lon, r.closestLandLonLat->lat);
    else
        out << " at (" << reportNumber(r.closestLand.where.x) << ", " << reportNumber(r.closestLand.where.y) << ")";
    if (const double keepOff = m.safety.keepOff; keepOff > 0.0)
        out << " (keep-off "
            << (m.physicalUnits().length ? format("%.3f km", keepOff * mpu / 1000.0) : reportNumber(keepOff)) << ")";
    out << "\n";
}

/// A route's travel time, arrival and hold, length, closeness to land, straight line and waypoints.
void printSolvedRoute(std::ostream &out, const MissionResult &r)
{
    const PlannedPath &p = r.plan;
    const MissionSpec &m = r.spec;
    if (m.physicalUnits().time) // days and hours, the seconds beside them
        out << "Travel time:        " << text::durationText(p.travelTime * m.timeUnitSeconds)
            << format(" (raw %.4f, smoothed %.4f)\n", p.rawTravelTime, p.smoothedTravelTime);
    else
        out << format("Travel time:        %.4f (raw %.4f, smoothed %.4f)\n", p.travelTime, p.rawTravelTime,
                      p.smoothedTravelTime);
    if (m.goalWindow.set || p.holdTime > 0.0)
    {
        const std::string at = r.waypoints.empty() ? "" : r.waypoints.back().iso;
        out << "Arrival at goal:    " << reportNumber(p.path.back().t) << (at.empty() ? "" : " (" + at + ")");
        if (m.goalWindow.set)
            out << " in the window [" << reportNumber(m.goalWindow.begin) << ", " << reportNumber(m.goalWindow.end)
                << "]";
        out << "\n";
        out << "Holding:            "
            << (m.physicalUnits().time ? text::durationText(p.holdTime * m.timeUnitSeconds) : reportNumber(p.holdTime))
            << (p.arrivalTiming.empty() ? std::string() : " (" + p.arrivalTiming + ")") << "\n";
    }
    if (r.diveProfiles)
        out << "With dive profiles: "
            << (std::isfinite(r.diveTravelTime) ? reportNumber(r.diveTravelTime) : "impassable") << "\n";
    out << "Path length:        " << lengthText(m, p.pathLength) << " (straight " << lengthText(m, p.straightLineLength)
        << ")\n";
    printClosestLand(out, r);
    out << "Straight line:      "
        << (!std::isfinite(p.straightLineTime) ? std::string("impassable")
            : m.physicalUnits().time           ? text::durationText(p.straightLineTime * m.timeUnitSeconds)
                                               : format("%.4f", p.straightLineTime))
        << "\n";
    out << format("Waypoints:          raw %zu, smoothed %zu%s, refined %zu%s\n", p.raw.size(), p.smoothed.size(),
                  m.planner.smoothing ? "" : " (off)", p.path.size(), m.planner.refinement ? "" : " (off)");
}

/// The constant-bearing stints ([IsernObstacles]) the glider flies, and their bearings.
void printStints(std::ostream &out, const MissionResult &r, const MissionProblem *problem)
{
    const StintOutcome &st = *r.plan.stints;
    out << format("Stints:             %zu of %g (%s), remaining distance %.4f%s%s\n", st.plan.bearings.size(),
                  st.settings.duration,
                  st.converted ? "the path converted" : stintObjectiveName(st.settings.objective).c_str(),
                  st.plan.remainingDistance, st.plan.reached ? ", goal reached" : "",
                  st.plan.grounded ? ", stopped on land" : "");
    if (st.converted)
        out << format("As stints:          arrival after %.4f against the path's %.4f (%+.2f%%)\n", st.stintTravelTime,
                      st.pathTravelTime, 100.0 * st.loss);
    const std::string north = northOf(r, problem);
    std::string b;
    for (double x : north == " true" ? trueStintBearings(r, problem) : st.plan.bearings)
        b += (b.empty() ? "" : " ") + format("%.1f", x);
    out << format("%-20s", ("Bearings (deg" + north + "):").c_str()) << b << "\n";
}
} // namespace

void printReport(std::ostream &out, const MissionResult &r, const MissionProblem *problem)
{
    const PlannedPath &p = r.plan;
    const MissionSpec &m = r.spec;
    printMissionHeader(out, r);
    printEnsemblePlan(out, p, m);
    printRouteModel(out, r);
    printGlobalCheck(out, p, m);
    if (!r.safetyNote.empty())
        out << "Depth limit:        " << r.safetyNote << "\n";
    for (const std::string &note : r.forecastNotes)
        out << "Forecast:           " << note << "\n";
    const std::vector<std::string> correction = correctionLines(r);
    for (std::size_t i = 0; i < correction.size(); ++i)
        out << (i == 0 ? "Correction:         " : "                    ") << correction[i] << "\n";
    if (!r.coastlineNote.empty())
        out << "Coastline:          " << r.coastlineNote << "\n";
    if (p.solved)
        printSolvedRoute(out, r);
    out << format("CFC (cost function calls): %llu (+%llu smoothing and refinement); CMC (current model calls): %llu\n",
                  static_cast<unsigned long long>(p.searchCostFunctionCalls),
                  static_cast<unsigned long long>(p.postprocessCostFunctionCalls),
                  static_cast<unsigned long long>(p.currentModelCalls));
    out << format("Planning time:      %.3f s (post-processing %.3f s; whole run %.3f s)\n", p.planningSeconds,
                  p.postprocessSeconds, r.wallSeconds);
    if (r.optimum)
    {
        if (r.optimum->found)
            out << format("Optimal control:    %.4f (final path %+.2f%%)\n", r.optimum->travelTime,
                          100.0 * (p.travelTime / r.optimum->travelTime - 1.0));
        else
            out << "Optimal control:    no extremal through the goal found\n";
    }
    if (p.solved && p.stints)
        printStints(out, r, problem);
    if (r.execution)
    {
        const ExecutionResult &e = *r.execution;
        out << "Execution:          truth " << e.truth << ", " << e.runs.size() << " run(s) x " << e.strategies.size()
            << " strategies, surfacing every "
            << (m.physicalUnits().time ? text::durationText(e.surfacingInterval * m.timeUnitSeconds)
                                       : reportNumber(e.surfacingInterval))
            << " (" << e.surfacingIntervalSource << ")\n";
        for (const std::string &note : e.notes)
            out << "Execution note:     " << note << "\n";
        printExecutionTable(out, e, m);
    }
    printReachability(out, r);
    printLegs(out, r);
    if (p.solved)
        printWaypoints(out, r, problem);
    if (!r.speedSweep.empty())
        out << "Speed sweep:\n" << speedSweepTable(r.speedSweep);
}
} // namespace ompl_glider

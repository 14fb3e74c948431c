#include "ompl_glider/output/SummaryJson.h"

#include <cctype>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "../io/NumberText.h"
#include "JsonValues.h"
#include "ompl_glider/Exception.h"
#include "SummaryParts.h"
#include "ompl_glider/output/RouteFiles.h"

namespace ompl_glider
{
namespace
{
using json = nlohmann::ordered_json;
using output_json::jnum;
using output_json::jtext;

/// "nan", "-nan", "inf" or "-inf" as a word of @p s (as "%g" prints a non-finite number).
bool holdsNonFiniteNumber(const std::string &s)
{
    auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (const char *token : {"nan", "inf"})
        for (std::size_t at = s.find(token); at != std::string::npos; at = s.find(token, at + 1))
            if ((at == 0 || !word(s[at - 1])) && (at + 3 == s.size() || !word(s[at + 3])))
                return true;
    return false;
}

/// Refuses a non-finite number anywhere in the summary, and one printed into a generated text (a reason, a
/// time), naming the field; a missing value is written as null on purpose (jnum()).
void checkFinite(const json &j, const std::string &field)
{
    static const std::set<std::string> generated = {"reason",    "grounded_why",  "switch_reason", "note",
                                                    "timing",    "switched_from", "iso",           "arrival_iso",
                                                    "begin_iso", "end_iso"};
    auto fail = [&field](const std::string &what) {
        throw Error("summary.json: field '" + field + "' holds a non-finite number (" + what +
                    "); nothing was written");
    };
    if (j.is_number_float() && !std::isfinite(j.get<double>()))
        fail(text::number(j.get<double>()));
    if (j.is_string())
    {
        const std::string key = field.substr(field.find_last_of('.') + 1);
        if (generated.count(key) && holdsNonFiniteNumber(j.get<std::string>()))
            fail("'" + j.get<std::string>() + "'");
    }
    if (j.is_object())
        for (auto it = j.begin(); it != j.end(); ++it)
            checkFinite(it.value(), field.empty() ? it.key() : field + "." + it.key());
    if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i)
            checkFinite(j[i], field + "[" + std::to_string(i) + "]");
}

json position(const MissionProblem &problem, Point2 p)
{
    json j = {{"x", p.x}, {"y", p.y}, {"lon", nullptr}, {"lat", nullptr}};
    if (problem.isGeographic())
    {
        const LonLat g = problem.toGeographic(p);
        j["lon"] = g.lon;
        j["lat"] = g.lat;
    }
    return j;
}

json spreadJson(const MeasureSpread &s)
{
    return {{"count", s.count}, {"min", jnum(s.min)}, {"q1", jnum(s.q1)},    {"median", jnum(s.median)},
            {"q3", jnum(s.q3)}, {"max", jnum(s.max)}, {"mean", jnum(s.mean)}};
}

/// The execution: one object per strategy (keyed by its name) with the mission's own run, its spread over every
/// run flown (the batch), and the settings.
json executionJson(const ExecutionResult &e, const MissionProblem &problem)
{
    json j;
    j["truth"] = e.truth;
    j["surfacing_interval"] = e.surfacingInterval;
    j["surfacing_interval_source"] = e.surfacingIntervalSource;
    j["notes"] = e.notes;
    j["step"] = e.step;
    const ExecutionRun &own = e.runs.front();
    j["radius"] = own.radius;
    j["runs"] = e.runs.size();
    std::size_t planned = 0;
    for (const ExecutionRun &run : e.runs)
        planned += run.planned ? 1 : 0;
    j["runs_planned"] = planned;
    j["model_difference"] = {{"rms", e.rmsDifference},
                             {"max_point_rms", e.maxPointRmsDifference},
                             {"from", e.differenceBegin},
                             {"to", e.differenceEnd}};
    j["threads"] = e.threads;
    j["wall_time_s"] = e.wallSeconds;
    if (e.oracle) // each pair planned on the truth and flown in it: the yardstick of `over_oracle`
    {
        std::size_t reached = 0;
        for (const ExecutionRun &run : e.runs)
            reached += std::isfinite(run.oracleArrival) ? 1 : 0;
        j["oracle"] = {{"arrival_time", jnum(own.oracleArrival)},
                       {"arrival_iso",
                        std::isfinite(own.oracleArrival) ? jtext(problem.isoTime(own.oracleArrival)) : json(nullptr)},
                       {"runs_reached", reached},
                       {"wall_time_s", e.oracleSeconds}};
    }
    else
        j["oracle"] = nullptr; // the truth is the forecast: nothing to measure against
    j["planned"] = own.planned;
    j["reason"] = jtext(own.reason);
    for (std::size_t k = 0; k < e.strategies.size(); ++k)
    {
        const StrategySpread &s = e.spread[k];
        json o;
        if (own.planned)
        {
            const FlownTrack &f = own.flown[k];
            o["final_distance"] = jnum(f.finalDistance);
            o["arrival_time"] = jnum(f.arrivalTime);
            o["arrival_iso"] = std::isfinite(f.arrivalTime) ? jtext(problem.isoTime(f.arrivalTime)) : json(nullptr);
            o["planned_arrival"] = f.plannedArrival;
            o["reached"] = f.reached;
            o["grounded"] = f.grounded;
            o["grounded_why"] = jtext(f.groundedWhy);
            o["not_reached_why"] = jtext(f.notReachedWhy); // null where it reached
            o["made_good_speed"] = f.madeGoodSpeed;
            o["surfacings"] = f.fixes.empty() ? 0 : f.fixes.size() - 1;
            if (e.strategies[k] == ControlStrategy::Replan || e.strategies[k] == ControlStrategy::ReplanObserved)
                o["replans"] = f.replans;
            if (!e.stops.empty()) // a mission of several legs: its stations reached (in their windows)
            {
                o["stations_reached"] = f.stationsReached;
                o["windows_missed"] = f.windowsMissed;
            }
        }
        else
            for (const char *key : {"final_distance", "arrival_time", "reached", "grounded"})
                o[key] = nullptr;
        o["batch"] = {{"runs", s.runs},
                      {"reached", s.reached},
                      {"grounded", s.grounded},
                      {"final_distance", spreadJson(s.finalDistance)},
                      {"arrival_delay", spreadJson(s.arrivalDelay)},
                      {"made_good_speed", spreadJson(s.madeGoodSpeed)},
                      {"over_oracle", e.oracle ? spreadJson(s.overOracle) : json(nullptr)}};
        j[s.strategy] = o;
    }
    return j;
}

json plannerJson(const MissionSpec &m, const PlannedPath &p)
{
    json params = json::object();
    for (const auto &[k, v] : m.planner.parameters)
        params[k] = v;
    return {{"name", p.planner.empty() ? m.planner.name : p.planner},
            {"grid_size", m.planner.gridSize},
            {"sectors", m.planner.sectors},
            {"smoothing", m.planner.smoothing},
            {"refinement", m.planner.refinement},
            {"time_limit_s", m.planner.timeLimit},
            {"parameters", params}};
}

/// A heading route's segments as flown, from the waypoints (each begun where the one before ended): bearing,
/// duration (also in hours with physical time units) and where and when it is begun; null for straight legs.
/// "headings", "straight_legs", or "mixed" for a mission whose legs are flown some as straight legs, some as held
/// headings.
const char *routeModel(const MissionResult &r)
{
    if (r.plan.headingRoute())
        return "headings";
    for (const PlannedLeg &l : r.legs)
        if (l.plan.headingRoute())
            return "mixed";
    return "straight_legs";
}

json headingsJson(const MissionResult &r, const MissionProblem &problem)
{
    // a heading route's segments, or those of a mission's legs flown as held headings
    bool any = false;
    for (const MissionWaypoint &w : r.waypoints)
        any = any || std::isfinite(w.heading);
    if (!r.plan.headingRoute() && !any)
        return nullptr;
    json a = json::array();
    const std::vector<double> heading = trueHeadings(r, &problem); // true bearings
    for (std::size_t i = 0; i < r.waypoints.size(); ++i)
    {
        const MissionWaypoint &w = r.waypoints[i];
        if (!std::isfinite(w.heading))
            continue;
        json start = position(problem, w.position);
        start["time"] = w.time;
        start["iso"] = jtext(w.iso);
        json seg = {{"bearing_true_deg", heading[i]}, {"duration", w.headingDuration}};
        if (r.spec.physicalUnits().time)
            seg["duration_h"] = w.headingDuration * r.spec.timeUnitSeconds / 3600.0;
        seg["start"] = start;
        if (!r.legs.empty() && i + 1 < r.waypoints.size())
            seg["leg"] = r.waypoints[i + 1].missionLeg; // the leg of the segment's end (a via point closes its leg)
        a.push_back(seg);
    }
    return a;
}

/// A stint plan's bearings as TRUE bearings, each the one whose flight ends at its next surfacing; null without stints.
json stintBearingsJson(const MissionResult &r, const MissionProblem &problem)
{
    const PlannedPath &p = r.plan;
    if (!p.stints)
        return nullptr;
    return trueStintBearings(r, &problem);
}

json departureSearchJson(const MissionSpec &m, const DepartureSearchResult &d)
{
    auto samples = [](const std::vector<DepartureSample> &v) {
        json a = json::array();
        for (const DepartureSample &s : v)
            a.push_back({{"departure", s.tDep}, {"travel_time", jnum(s.travelTime)}});
        return a;
    };
    return {{"found", d.found},
            {"departure", jnum(d.departure)},
            {"travel_time", jnum(d.travelTime)},
            {"window", {m.departure.begin, jnum(d.windowEnd)}},
            {"bracket", {jnum(d.bracketLo), jnum(d.bracketHi)}},
            {"fine_searches", d.fineEvaluations},
            {"coarse_searches", d.coarseEvaluations},
            {"wall_time_s", d.wallSeconds},
            {"supporting_points", samples(d.supportingPoints)},
            {"refinements", samples(d.refinements)}};
}
/// The safety margins (keep-off distance, depth limit) and the route's closest approach to land.
void safetyJson(const MissionResult &r, json &j)
{
    const MissionSpec &m = r.spec;
    const double mpu = m.metresPerUnit();
    const bool metres = m.physicalUnits().length;
    const LandApproach &c = r.closestLand;
    j["safety"] = {{"keep_off", m.safety.keepOff},
                   {"keep_off_m", metres ? json(m.safety.keepOff * mpu) : json(nullptr)},
                   {"min_depth_m", m.safety.minDepth},
                   {"depth_limit", jtext(r.safetyNote)},
                   {"coastline", jtext(r.coastlineNote)}};
    j["closest_land"] = std::isfinite(c.distance)
                            ? json{{"distance", c.distance},
                                   {"distance_m", metres ? json(c.distance * mpu) : json(nullptr)},
                                   {"x", c.where.x},
                                   {"y", c.where.y},
                                   {"lon", r.closestLandLonLat ? json(r.closestLandLonLat->lon) : json(nullptr)},
                                   {"lat", r.closestLandLonLat ? json(r.closestLandLonLat->lat) : json(nullptr)}}
                            : json(nullptr);
    j["closest_land_m"] = std::isfinite(c.distance) && metres ? json(c.distance * mpu) : json(nullptr);
}

/// The global check of the route class (GlobalCheck): its candidates and the winner; null when it did not run.
json globalCheckJson(const PlannedPath &p)
{
    if (!p.globalCheck)
        return nullptr;
    const GlobalCheck &g = *p.globalCheck;
    json candidates = json::array();
    for (const RouteCandidate &c : g.candidates)
        candidates.push_back({{"name", c.name},
                              {"solved", c.solved},
                              {"travel_time", c.solved ? jnum(c.travelTime) : json(nullptr)},
                              {"why", jtext(c.why)}});
    return {{"headings", g.headings},
            {"finer_headings", g.finerHeadings},
            {"timed_out", g.timedOut},
            {"level_set_travel_time", std::isfinite(g.levelSetTime) ? jnum(g.levelSetTime) : json(nullptr)},
            {"level_set_budget", g.levelSetBudget},
            {"level_set_updates", g.levelSetUpdates},
            {"level_set_budget_spent", g.levelSetBudgetSpent},
            {"extremal_found", g.extremalFound},
            {"extremal_travel_time", g.extremalFound ? jnum(g.extremalTime) : json(nullptr)},
            {"candidates", candidates},
            {"winner", jtext(g.winner)},
            {"gain", jnum(g.gain)},
            {"current_model_calls", g.currentModelCalls},
            {"wall_time_s", g.seconds}};
}

/// The dive profiles generated for the mission and how one is chosen per leg.
json diveProfilesJson(const MissionResult &r)
{
    json profiles = json::array();
    for (const DiveProfile &d : r.profileSet)
        profiles.push_back({{"climb_to", d.climbTo}, {"dive_to", d.diveTo}});
    return {{"selection", toString(r.spec.dive.params.selection)}, {"profiles", profiles}};
}

/// A mission of several legs: each leg's ends, times, planner, status and global check; the via points; the order.
void legsJson(const MissionResult &r, const MissionProblem &problem, json &j)
{
    const MissionSpec &m = r.spec;
    if (m.waypoints.empty())
        return;
    json via = json::array();
    for (std::size_t i = 0; i < m.waypoints.size(); ++i)
    {
        const ViaPointSpec &v = m.waypoints[i];
        via.push_back({{"name", v.name},
                       {"position", position(problem, problem.getViaPoints()[i])},
                       {"radius", jnum(v.radius)},
                       {"stay", v.stay},
                       {"arrive_begin", v.arrive.set ? jnum(v.arrive.begin) : json(nullptr)},
                       {"arrive_end", v.arrive.set ? jnum(v.arrive.end) : json(nullptr)}});
    }
    j["via_points"] = via;
    json order = json::array();
    for (const std::size_t i : r.order)
        order.push_back(m.waypoints[i].name);
    j["order"] = {{"mode", visitOrderName(m.order)}, {"visited", order}};
    if (r.orderSearch)
    {
        const OrderSearch &s = *r.orderSearch;
        json chosen = json::array();
        for (const std::size_t i : s.chosen)
            chosen.push_back(m.waypoints[i].name);
        j["order"]["search"] = {{"orders_total", s.ordersTotal},
                                {"orders_evaluated", s.ordersEvaluated},
                                {"legs_planned", s.legsPlanned},
                                {"given_travel_time", jnum(s.givenTime)},
                                {"chosen_travel_time", jnum(s.chosenTime)},
                                {"chosen", chosen},
                                {"gain", jnum(s.gain)},
                                {"complete", s.stopped.empty()},
                                {"stopped", s.stopped.empty() ? json(nullptr) : json(s.stopped)}};
    }
    json legs = json::array();
    for (const PlannedLeg &l : r.legs)
    {
        const PlannedPath &p = l.plan;
        const double arrival = l.arrival();
        json g = globalCheckJson(p);
        legs.push_back({{"leg", l.index + 1},
                        {"from", l.from},
                        {"to", l.to},
                        {"departure", p.departure},
                        {"departure_iso", jtext(problem.isoTime(p.departure))},
                        {"arrival", jnum(arrival)},
                        {"arrival_iso", p.solved ? jtext(problem.isoTime(arrival)) : json(nullptr)},
                        {"travel_time", jnum(p.travelTime)},
                        {"stay", l.stay},
                        {"path_length", p.solved ? json(p.pathLength) : json(nullptr)},
                        {"planner", p.planner},
                        {"status", statusText(p.status)},
                        {"solved", p.solved},
                        {"reason", jtext(p.reason)},
                        {"no_path_cause", jtext(causeName(p.noPath.cause))},
                        {"route_model", p.headingRoute() ? "headings" : "straight_legs"},
                        {"hold_time", p.holdTime},
                        {"arrival_timing", jtext(p.arrivalTiming)},
                        {"global_check", g.is_null() ? json(nullptr)
                                                     : json{{"winner", g["winner"]},
                                                            {"gain", g["gain"]},
                                                            {"extremal_found", g["extremal_found"]},
                                                            {"headings", g["headings"]}}},
                        {"first_waypoint", l.firstPoint},
                        {"last_waypoint", l.lastPoint}});
    }
    j["legs"] = legs;
}

/// How the plan ended: solved, its status, why there is no path (words and cause) and the switch to another planner.
void outcomeJson(const PlannedPath &p, json &j)
{
    j["solved"] = p.solved;
    j["status"] = statusText(p.status);
    j["reason"] = jtext(p.reason);
    j["no_path_cause"] = jtext(causeName(p.noPath.cause));
    j["no_path_leg"] = p.noPath.leg > 0 ? json(p.noPath.leg) : json(nullptr);
    j["switched_from"] = jtext(p.switchedFrom);
    j["switch_reason"] = jtext(p.switchReason);
    j["switch_cause"] = jtext(causeName(p.switchCause));
}
/// What was computed after the plan: the execution, the probability of reach.
void afterPlanJson(const MissionResult &r, const MissionProblem &problem, json &j)
{
    if (r.execution)
        j["execution"] = executionJson(*r.execution, problem);
    if (r.reachability)
        j["reachability"] = summary_detail::reachabilityJson(r);
}
} // namespace

namespace
{
/// summary.json's "ensemble": the members, the objective, the chosen candidate, its arrival in each member.
json ensembleJson(const PlannedPath &p, const MissionProblem &problem)
{
    const EnsemblePlan &e = *p.ensemble;
    auto times = [](const std::vector<double> &v) {
        json a = json::array();
        for (double x : v)
            a.push_back(jnum(x));
        return a;
    };
    json members = json::array();
    for (const auto &f : problem.getMembers())
        members.push_back(f->name());
    json cands = json::array();
    for (const EnsemblePlan::Candidate &c : e.candidates)
        cands.push_back({{"name", c.name},
                         {"solved", c.solved},
                         {"objective_value", jnum(c.objectiveValue)},
                         {"member_travel_times", times(c.memberTravelTimes)}});
    const MeasureSpread spread = measureSpread(e.memberTravelTimes);
    json arriving = json::array(), notArriving = json::array(); // members by index, as member_travel_times
    for (std::size_t k = 0; k < e.memberTravelTimes.size(); ++k)
        (std::isfinite(e.memberTravelTimes[k]) ? arriving : notArriving).push_back(k);
    return {{"members", members},
            {"objective", ensembleObjectiveName(e.objective)},
            {"quantile", e.objective == EnsembleObjective::Quantile ? json(e.quantile) : json(nullptr)},
            {"chosen", e.chosen},
            {"objective_value", jnum(e.objectiveValue)},
            {"member_travel_times", times(e.memberTravelTimes)},
            {"arrival_probability", p.solved ? json(e.arrivalProbability) : json(nullptr)},
            {"members_arriving", arriving},
            {"members_not_arriving", notArriving},
            {"spread", {{"min", jnum(spread.min)}, {"mean", jnum(spread.mean)}, {"max", jnum(spread.max)}}},
            {"candidates", cands}};
}

/// The route's times: the departure and arrival, the holds and the goal window, the travel times, the path's length
/// and the straight line's.
void timingJson(const MissionResult &r, const MissionProblem &problem, json &j)
{
    const PlannedPath &p = r.plan;
    const MissionSpec &m = r.spec;
    j["departure"] = {{"time", p.departure},
                      {"iso", r.waypoints.empty() ? jtext(r.departureIso) : jtext(r.waypoints.front().iso)}};
    j["arrival"] = {{"time", r.waypoints.empty() ? json(nullptr) : jnum(r.waypoints.back().time)},
                    {"iso", r.waypoints.empty() ? json(nullptr) : jtext(r.waypoints.back().iso)}};
    // goals in time: the time at the goal in the window, the holds, the window
    j["arrival_time"] = r.waypoints.empty() ? json(nullptr) : jnum(r.waypoints.back().time);
    j["hold_time"] = p.solved ? jnum(p.holdTime) : json(nullptr);
    if (m.goalWindow.set)
        j["goal_window"] = {{"begin", m.goalWindow.begin},
                            {"end", m.goalWindow.end},
                            {"begin_iso", jtext(problem.isoTime(m.goalWindow.begin))},
                            {"end_iso", jtext(problem.isoTime(m.goalWindow.end))},
                            {"timing", jtext(p.arrivalTiming)}};
    // no travel time without a path (a robust plan's best candidate, impassable in some member, is not one)
    j["travel_time"] = p.solved ? jnum(p.travelTime) : json(nullptr);
    j["travel_time_raw"] = p.solved ? jnum(p.rawTravelTime) : json(nullptr);
    j["travel_time_smoothed"] = p.solved ? jnum(p.smoothedTravelTime) : json(nullptr);
    if (p.ensemble) // the share of the members in which the route arrives (1: robust over every member)
        j["arrival_probability"] = p.solved ? json(p.ensemble->arrivalProbability) : json(0.0);
    if (r.diveProfiles)
        j["travel_time_dive_profiles"] = jnum(r.diveTravelTime);
    j["path_length"] = p.solved ? json(p.pathLength) : json(nullptr);
    j["path_length_raw"] = p.solved ? json(p.rawPathLength) : json(nullptr);
    j["straight_line"] = {{"travel_time", jnum(p.straightLineTime)},
                          {"passable", std::isfinite(p.straightLineTime)},
                          {"length", p.straightLineLength}};
}

/// Honest times: the accurate Dormand-Prince re-flight of the reported route (null where it was not re-flown).
json reflightJson(const PlannedPath &p)
{
    if (!p.reflown)
        return nullptr;
    return {{"method", "Dormand-Prince 5(4), rtol 1e-10"},
            {"travel_time", jnum(p.reflownTravelTime)},
            {"relative_difference", p.reflownTravelTime > 0.0
                                        ? jnum((p.travelTime - p.reflownTravelTime) / p.reflownTravelTime)
                                        : json(nullptr)},
            {"end_distance_to_goal", jnum(p.reflownEndDistance)},
            {"planner_travel_time", jnum(p.plannerTravelTime)},
            {"note", jtext(p.reflightNote)},
            {"fallback", p.reflightFallback == ReflightFallback::EarlierStage ? json("earlier_stage")
                         : p.reflightFallback == ReflightFallback::Reaimed    ? json("reaimed")
                                                                              : json(nullptr)}};
}

/// The constant-bearing stints ([IsernObstacles]): how they were planned and what they reach.
json stintsJson(const StintOutcome &s)
{
    return {{"converted", s.converted},
            {"duration", s.settings.duration},
            {"mission_duration", s.settings.missionDuration},
            {"objective", stintObjectiveName(s.settings.objective)},
            {"radius", s.settings.radius},
            {"count", s.plan.bearings.size()},
            {"reached", s.plan.reached},
            {"arrival_time", jnum(s.plan.arrivalTime)},
            {"grounded", s.plan.grounded},
            {"grounded_why", jtext(s.plan.groundedWhy)},
            {"path_travel_time", jnum(s.pathTravelTime)},
            {"stint_travel_time", jnum(s.stintTravelTime)},
            {"loss", jnum(s.loss)}};
}

/// The speed sweep: a row per speed, its travel time and path length beside the straight line's.
json speedSweepJson(const std::vector<SpeedSweepRow> &sweep)
{
    json rows = json::array();
    for (const SpeedSweepRow &w : sweep)
        rows.push_back({{"speed", w.speed},
                        {"solved", w.solved},
                        {"travel_time", jnum(w.travelTime)},
                        {"path_length", w.solved ? json(w.pathLength) : json(nullptr)},
                        {"straight_line_travel_time", jnum(w.straightLineTime)},
                        {"straight_line_length", w.straightLineLength}});
    return rows;
}
} // namespace

std::string summaryJson(const MissionResult &r, const MissionProblem &problem, const std::vector<std::string> &files)
{
    const PlannedPath &p = r.plan;
    const MissionSpec &m = r.spec;
    json j;
    j["schema"] = kSummarySchema;
    j["mission"] = m.name;
    j["source"] = m.file;
    j["current"] = m.current.type;
    j["current_ensemble"] = summary_detail::currentEnsembleJson(m.current);
    summary_detail::forecastJson(problem, j);
    j["forecast_run"] = summary_detail::forecastRunJson(problem, p);
    j["forecast_notes"] = json::array();
    for (const std::string &note : r.forecastNotes)
        j["forecast_notes"].push_back(jtext(note));
    outcomeJson(p, j);
    j["planner"] = plannerJson(m, p);
    j["units"] = {{"length_m", m.lengthUnitMetres}, {"time_s", m.timeUnitSeconds}};
    j["speed"] = p.speed;
    j["start"] = position(problem, problem.getStart());
    j["goal"] = position(problem, problem.getGoal());
    timingJson(r, problem, j);
    safetyJson(r, j);
    j["waypoints"] = {{"raw", p.raw.size()}, {"smoothed", p.smoothed.size()}, {"final", p.path.size()}};
    j["cost_function_calls"] = {{"search", p.searchCostFunctionCalls},
                                {"postprocess", p.postprocessCostFunctionCalls},
                                {"total", p.totalCostFunctionCalls()}};
    j["current_model_calls"] = p.currentModelCalls;
    j["expanded_vertices"] = p.expandedVertices;
    j["wall_time_s"] = {
        {"planning", p.planningSeconds}, {"postprocess", p.postprocessSeconds}, {"total", r.wallSeconds}};
    j["path_checked"] = p.pathChecked;
    // heading routes: what the glider holds (the switch from a planner without a path: outcomeJson())
    j["route_model"] = routeModel(r);
    j["headings"] = headingsJson(r, problem);
    // the global check of the route class: extremals shot from the start beside the planner's route
    j["global_check"] = globalCheckJson(p);
    // honest times: the accurate Dormand-Prince re-flight of the reported route
    j["reflight"] = reflightJson(p);
    // constant-bearing stints ([IsernObstacles]): null without a stints section
    j["remaining_distance"] = p.stints ? jnum(p.stints->plan.remainingDistance) : json(nullptr);
    j["bearings"] = stintBearingsJson(r, problem);
    j["bearing_reference"] = "true north"; // every bearing written (headings, bearings): clockwise from true north
    if (p.stints)
        j["stints"] = stintsJson(*p.stints);
    if (r.optimum)
        j["optimal_control"] = {{"found", r.optimum->found},
                                {"travel_time", jnum(r.optimum->travelTime)},
                                {"ratio", jnum(p.travelTime / r.optimum->travelTime)}};
    if (r.diveProfiles)
        j["dive_profiles"] = diveProfilesJson(r);
    if (r.departureSearch)
        j["departure_search"] = departureSearchJson(m, *r.departureSearch);
    if (!r.speedSweep.empty())
        j["speed_sweep"] = speedSweepJson(r.speedSweep);
    if (p.ensemble)
        j["ensemble"] = ensembleJson(p, problem);
    afterPlanJson(r, problem, j);
    legsJson(r, problem, j);
    j["observations"] = summary_detail::observationsJson(problem);
    j["files"] = files;
    checkFinite(j, "");
    return output_json::utf8Dump(j, 2) + "\n";
}
} // namespace ompl_glider

/// @file SummaryInputs.cpp
/// @brief summary.json's account of what went in: the forecast's files and remote sources (what came from the
/// network, what from the cache), the current's ensemble, and the glider's observations with what the correction
/// learned from them. The rest of summary.json: SummaryJson.cpp.
#include <cmath>

#include "ompl_glider/Config.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/io/FileList.h"
#include "ompl_glider/io/RemoteSource.h"
#include "SummaryParts.h"

namespace ompl_glider
{
namespace summary_detail
{
namespace
{
using output_json::jnum;
using output_json::jtext;

/// The forecast's remote sources (OPeNDAP datasets, Zarr stores, GRIB files over HTTP): what came from the network,
/// what from the cache.
json forecastSourcesJson(const MissionProblem &problem)
{
    json out = json::array();
    for (const RemoteFetch &f : problem.remoteSources())
        out.push_back({{"source", f.source},
                       {"kind", remoteKindName(f.kind)},
                       {"cache_file", f.cacheFile},
                       {"bytes_fetched", f.bytesFetched},
                       {"bytes_from_cache", f.bytesFromCache},
                       {"requests", f.requests},
                       {"network", f.opened},
                       {"cache_problem", jtext(f.cacheProblem)},
                       {"cache_ignored", jtext(f.cacheIgnored)}});
    return out;
}

#if OMPL_GLIDER_WITH_NETCDF
/// The learned correction judged on DAC not used to fit it (null: not judged).
json heldOutJson(const HeldOutCheck &h)
{
    const auto error = [](double e) { return std::isfinite(e) ? json(e) : json(nullptr); };
    if (h.fitted == 0)
        return nullptr;
    return {{"fitted", h.fitted},
            {"scored", h.scored},
            {"prior_error", error(h.priorError)},
            {"mean_error", error(h.meanError)},
            {"scales_error", error(h.scalesError)},
            {"learned_error", error(h.learnedError)},
            {"scales_kept", h.scalesKept},
            {"mean_kept", h.meanKept}};
}

/// What the correction learned from the DAC: each scale's source, the likelihood gained, the innovations' mean (bias,
/// tides) and an ensemble's member weights.
json learnedJson(const ObservationReport &o)
{
    const CorrectionSummary &c = o.correction;
    json tides = json::array();
    for (const InnovationMean::Constituent &k : c.mean.tides)
        tides.push_back({{"name", k.name},
                         {"u_amplitude", k.amplitude(true)},
                         {"u_phase_deg", k.phase(true) * 180.0 / 3.14159265358979323846},
                         {"v_amplitude", k.amplitude(false)},
                         {"v_phase_deg", k.phase(false) * 180.0 / 3.14159265358979323846}});
    json members = json::array();
    for (const MemberScore &s : o.members)
        members.push_back({{"weight", s.weight}, {"rms_innovation", s.rmsInnovation}, {"coefficient", s.coefficient}});
    return {{"length_scale_source", c.lengthSource},
            {"time_scale_source", c.timeSource},
            {"error_ratio_source", c.ratioSource},
            {"dac_estimated_from", c.learnedFrom},
            {"log_likelihood_gain", c.likelihoodGain},
            {"held_out", heldOutJson(c.heldOut)},
            {"bias", c.mean.active() ? json{{"u", c.mean.bias.u}, {"v", c.mean.bias.v}} : json(nullptr)},
            {"tides", tides},
            {"tides_time_origin", c.mean.active() ? json(c.mean.tRef) : json(nullptr)},
            {"members", members}};
}
#endif
} // namespace

/// The current's ensemble (null without one): each member's parameters (an analytic flow's, its kind's defaults
/// filled in: what the member flew) or files, and for members drawn from one source (CurrentSpec::drawn) the seed
/// and each parameter's relative spread, member 0 being the control run.
json currentEnsembleJson(const CurrentSpec &c)
{
    if (c.members.empty())
        return nullptr;
    json members = json::array();
    for (const CurrentSpec &member : c.members)
    {
        const CurrentFieldKind *kind = findCurrentFieldKind(member.type);
        json o = json::object();
        if (kind && !kind->gridded())
            for (const auto &[name, value] : kind->parameters)
                o[name] = member.parameters.count(name) ? member.parameters.at(name) : value;
        else
            o["files"] = member.forecastFiles();
        members.push_back(o);
    }
    json j = {{"type", c.type}, {"count", c.members.size()}, {"drawn", c.drawn.has_value()}};
    j["seed"] = c.drawn ? json(c.drawn->seed) : json(nullptr);
    j["spread"] = json::object();
    if (c.drawn)
        for (const auto &[name, spread] : c.drawn->spread)
            j["spread"][name] = spread;
    j["members"] = members;
    return j;
}

/// The forecast's files: what they are (a Zarr store, a GRIB file, an OPeNDAP dataset, NetCDF files; null for an
/// analytic flow), their names and what came from the network.
void forecastJson(const MissionProblem &problem, json &j)
{
    const MissionSpec &m = problem.getSpec();
    j["current_source"] =
        m.current.isForecast() && !m.current.file.empty() ? json(forecastSourceKind(m.current.file)) : json(nullptr);
    json forecastFiles = json::array();
    for (const std::string &f : problem.forecastFiles())
        forecastFiles.push_back(withoutCredentials(f)); // a URL's user:password never reaches an output
    j["forecast_files"] = forecastFiles;
    j["forecast_sources"] = forecastSourcesJson(problem);
}

json forecastRunJson(const MissionProblem &problem, const PlannedPath &plan)
{
    if (!problem.runs())
        return nullptr;
    const MissionSpec &m = problem.getSpec();
    const ForecastRun &run = (*problem.runs())[problem.runIndex()];
    const bool arrived = plan.solved && !plan.path.empty();
    return {{"file", withoutCredentials(run.file)},
            {"run", problem.runIndex() + 1},
            {"runs", problem.runs()->size()},
            {"reference_time", m.isoTime(run.reference)},
            {"reference_from", run.referenceFrom},
            {"available_since", m.isoTime(run.available)},
            {"run_delay_hours", m.current.runDelay / 3600.0},
            {"lead_time_at_arrival_hours",
             arrived ? jnum((plan.path.back().t - run.reference) * m.timeUnitSeconds / 3600.0) : json(nullptr)}};
}

/// The glider's observations: what was read, rejected and used, and the correction's size (null without them).
json observationsJson(const MissionProblem &problem)
{
#if OMPL_GLIDER_WITH_NETCDF
    const auto &o = problem.observations();
    if (!o)
        return nullptr;
    json rejected = json::object();
    for (const auto &[why, n] : o->rejected)
        rejected[why] = n;
    if (o->future > 0)
        rejected["after the departure"] = o->future;
    if (o->correction.outsideForecast > 0)
        rejected["outside the forecast"] = o->correction.outsideForecast;
    if (o->far > 0)
        rejected["far from the mission"] = o->far;
    if (o->correction.older > 0)
        rejected["older than the most recent kept"] = o->correction.older;
    json notes = json::object();
    for (const auto &[what, n] : o->notes)
        notes[what] = n;
    json fix = nullptr;
    if (o->lastFix)
        fix = {{"lon", o->lastFix->at.lon}, {"lat", o->lastFix->at.lat}, {"time_iso", formatIsoTime(o->lastFix->time)}};
    // the mission resumed at the last fix: what it replaced and which stations it dropped
    json resumed = nullptr;
    const MissionSpec &m = problem.getSpec();
    if (m.observations && m.observations->resumed)
    {
        const MissionResume &r = *m.observations->resumed;
        json dropped = json::array();
        for (const DroppedStation &d : r.dropped)
            dropped.push_back({{"name", d.name},
                               {"why", d.windowClosed.empty() ? "reached" : "reached after its window closed"},
                               {"reached_iso", d.reachedIso},
                               {"distance_m", d.distance},
                               {"lon", d.at.lon},
                               {"lat", d.at.lat},
                               {"radius_m", d.radius},
                               {"stay_left", d.stayLeft},
                               {"window_opens", jtext(d.windowOpens)},
                               {"window_closed", jtext(d.windowClosed)}});
        json left = nullptr;
        if (r.leftStay)
            left = {{"name", r.leftStay->name},          {"reached_iso", r.leftStay->reachedIso},
                    {"left_iso", r.leftStay->leftIso},   {"held", r.leftStay->held},
                    {"stay_left", r.leftStay->stayLeft}, {"distance_m", r.leftStay->distance},
                    {"radius_m", r.leftStay->radius}};
        resumed = {{"fix", {{"lon", r.fix.lon}, {"lat", r.fix.lat}, {"time_iso", r.fixIso}}},
                   {"replaced_start", jtext(r.replacedStart)},
                   {"replaced_departure", jtext(r.replacedDeparture)},
                   {"dropped", dropped},
                   {"stay_ends", jtext(r.stayEnds)},
                   {"departure_during_stay", jtext(r.departureDuringStay)},
                   {"left_stay", left},
                   {"warnings", resumeWarnings(m)},
                   {"stale_fix_warning", jtext(r.staleFix)}};
    }
    return {{"source", o->source},
            {"files", o->files},
            {"platform", jtext(o->platform)},
            {"used", o->correction.used},
            {"rejected", rejected},
            {"notes", notes},
            {"rms_innovation_before", jnum(o->correction.rmsBefore)},
            {"rms_innovation_after", jnum(o->correction.rmsAfter)},
            {"mean_innovation", {{"u", o->correction.meanInnovation.u}, {"v", o->correction.meanInnovation.v}}},
            {"length_scale", o->params.lengthScale},
            {"time_scale", o->params.timeScale},
            {"error_ratio", o->params.errorRatio},
            {"compared_with", o->comparedWith},
            {"deepest_dive_m", jnum(o->deepestDive)},
            {"learned", learnedJson(*o)},
            {"last_fix", fix},
            {"resumed", resumed}};
#else
    (void)problem;
    return nullptr;
#endif
}
} // namespace summary_detail
} // namespace ompl_glider

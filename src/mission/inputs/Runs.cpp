// A forecast given as runs (current.runs; ProblemInputs.h): each run's reference time and availability on the
// mission's clock, the run planned on (the newest available at the departure, read as that file alone would be),
// and the others read when an execution first asks for them.
#include "InputsInternal.h"
#include "../../io/NumberText.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/ForecastRuns.h"
#include "ompl_glider/current/ShiftedTimeField.h"
#include "ompl_glider/io/Time.h"

namespace ompl_glider::inputs_detail
{
namespace
{
/// The mission @p m with run @p run (its file or files, and its index in a file of several runs) as its one forecast.
MissionSpec withRun(const MissionSpec &m, const ForecastRun &run)
{
    MissionSpec out = m;
    out.current.file = run.file;
    out.current.runIndex = run.runIndex;
    out.current.files = run.files;
    out.current.runs.clear();
    return out;
}

/// Each run's times on the mission's clock (m.fileCalendar: the earliest run's first time): forecastRunSources()
/// (a file of several runs is each of its runs, a run in several files one run).
std::vector<ForecastRun> readRuns(const MissionSpec &m, const CurrentFieldKind &kind)
{
    const double origin = m.fileCalendar ? m.fileCalendar->originSeconds : 0.0;
    std::vector<ForecastRun> out;
    ForecastRun first;
    first.file = m.current.runs.front();
    for (const RunSource &s : forecastRunSources(*kind.source, forecastRequest(withRun(m, first)), m.current.runs))
    {
        const ForecastTimeAxis &axis = s.axis;
        if (!axis.dated || !m.fileCalendar || axis.calendar != m.fileCalendar->calendar)
            throw Error("forecast run '" + s.files.front() +
                        "': its time axis is not dated on the first run's calendar");
        ForecastRun r;
        r.file = s.files.front();
        if (s.files.size() > 1)
            r.files = s.files;
        r.runIndex = s.runIndex;
        r.begin = axis.originSeconds - origin;
        r.end = r.begin + axis.span;
        r.reference = axis.referenceSeconds - origin;
        r.available = r.reference + m.current.runDelay;
        r.referenceFrom = axis.referenceFrom;
        out.push_back(r);
    }
    return out;
}
} // namespace

void loadRuns(ProblemInputs &in, const CurrentFieldKind &kind)
{
    const MissionSpec &m = in.spec;
    std::vector<ForecastRun> list = readRuns(m, kind);
    // the others are read (every record, on the mission's clock, as a truth is) when an execution first asks for
    // them; one at a time (a gridded source is read from one thread at a time)
    auto source = std::make_shared<ProblemInputs>();
    source->spec = m;
    auto gate = std::make_shared<std::mutex>();
    ForecastRuns::Loader load = [source, gate](const ForecastRun &r) {
        std::lock_guard<std::mutex> hold(*gate);
        CurrentSpec run = withRun(source->spec, r).current;
        run.mark = {};
        return loadSource(*source, run, "current.runs");
    };
    auto runs = std::make_shared<ForecastRuns>(std::move(list), std::move(load));
    const double departure = m.departure.window ? m.departure.begin : m.departure.time;
    const std::optional<std::size_t> k = runs->newestAt(departure);
    if (!k)
    {
        const ForecastRun &first = (*runs)[0];
        throw Error(sourcePlace(m, m.current.mark) + "field 'current.runs': no run is available at the departure " +
                    m.isoTime(departure) + ": the first, '" + first.file + "' (reference time " +
                    m.isoTime(first.reference) + "), is available from " + m.isoTime(first.available) +
                    " (its reference time + current.run_delay)");
    }
    const ForecastRun &run = (*runs)[*k];
    // the run read as the mission given that file alone reads it: its own clock (field time 0 its first time),
    // the departure on that clock, then shifted back onto the mission's
    MissionSpec alone = withRun(m, run);
    alone.departure.time -= run.begin;
    alone.departure.begin -= run.begin;
    alone.departure.end -= run.begin;
    LoadedForecast forecast;
    try
    {
        forecast = kind.source->load(forecastRequest(alone));
    }
    catch (const Error &e)
    {
        if (m.current.mark.line > 0)
            throw Error(sourcePlace(m, m.current.mark) + e.what());
        throw;
    }
    checkDepthAxis(m, forecast);
    const double shift = m.fileCalendar->originSeconds - forecast.originSeconds;
    in.field = shift == 0.0 ? forecast.field : std::make_shared<ShiftedTimeField>(forecast.field, shift);
    keepForecast(in, forecast);
    source->frame.projection = forecast.projection;
    in.runs = runs;
    in.run = *k;
}

void estimateRunSpread(ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    const auto &strategies = m.execution.strategies;
    const bool measured = std::find(strategies.begin(), strategies.end(), "dac") != strategies.end() ||
                          std::find(strategies.begin(), strategies.end(), "replan_observed") != strategies.end();
    if (!in.runs || in.runs->size() < 2 ||
        !((m.observations && m.observations->hasFiles()) || (m.execution.enabled && measured)))
        return;
    const RunSpread s = runSpread(*in.runs, in.frame.box, m.vehicle.depth);
    in.runSpread = s;
    if (s.pairs == 0)
    {
        in.forecastNotes.push_back("no two forecast runs overlap: the correction's priors are its defaults");
        return;
    }
    const auto km = [](double v) { return std::isfinite(v) ? text::number(v / 1000.0, 3) + " km" : "unresolved"; };
    in.forecastNotes.push_back("the runs' differences where they overlap (" + std::to_string(s.pairs) +
                               " pairs, the NMC method): error " + text::number(s.sigma, 3) +
                               " m/s per component, length scale " + km(s.lengthScale) + ", time scale " +
                               (std::isfinite(s.timeScale) ? m.durationText(s.timeScale) : std::string("unresolved")) +
                               ": the priors of the correction by the DAC where the mission gives none");
}
} // namespace ompl_glider::inputs_detail

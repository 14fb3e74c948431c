/// @file Observations.cpp
/// @brief A glider's measurements in a mission (Observations.h): the start at the last fix, and the forecast
/// corrected by its depth-averaged currents (MissionProblem::applyObservations()).

#include "ompl_glider/mission/Observations.h"

#include <cmath>

#include "../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"

namespace ompl_glider
{
void startAtLastFix(MissionSpec &m, const SourceMark &mark, bool keepDeparture)
{
    const GliderObservations o = readGliderObservations(m.observations->path);
    if (!o.lastFix)
        throw Error("the observations '" + m.observations->path + "' report no position to start from");
    m.start.geographic = true;
    m.start.lonLat = o.lastFix->at;
    m.marks["start"] = mark;
    if (!keepDeparture)
    {
        try
        {
            m.departure.time = m.timeOf(formatIsoTime(o.lastFix->time));
        }
        catch (const Error &e)
        {
            throw Error(std::string("the last fix's time: ") + e.what());
        }
        m.departure.window = false;
        m.marks["departure.time"] = mark;
    }
}

void MissionProblem::applyObservations()
{
    if (!spec_.observations || !spec_.observations->hasFiles())
        return;
    const ObservationsSpec &s = *spec_.observations;
    const std::string at = spec_.place("observations");
    if (!isGeographic())
        throw Error(at + ": a glider's observations are in lon/lat: the mission needs a geographic forecast or a "
                         "'projection'");
    GliderObservations o;
    try
    {
        o = readGliderObservations(s.path);
    }
    catch (const Error &e)
    {
        throw Error(at + ": " + e.what());
    }
    ObservationReport report;
    report.source = o.source;
    report.files = o.files;
    report.platform = o.platform;
    report.rejected = o.rejected;
    report.lastFix = o.lastFix;
    const MissionSpec &m = spec_;
    const double departure = m.departure.window ? m.departure.begin : m.departure.time;
    // velocities in field units (a forecast's m/s; an analytic flow's units per time unit)
    const double scale = m.metresPerUnit() / (m.current.isForecast() ? 1.0 : m.timeUnitSeconds);
    std::vector<DacObservation> dac;
    for (const DacRecord &r : o.dac)
    {
        double t = 0.0;
        try
        {
            t = m.timeOf(formatIsoTime(r.time));
        }
        catch (const Error &e)
        {
            throw Error(at + ": '" + r.file + "': " + e.what());
        }
        if (t > departure)
        {
            ++report.future; // measured after the plan departs: not known when it is made
            continue;
        }
        // east/north turned into the planning frame's x/y there, as the forecast's velocities are
        double ex = 1.0, ey = 0.0, nx = 0.0, ny = 1.0;
        if (projection_)
        {
            projection_->eastDirection(r.at.lon, r.at.lat, ex, ey);
            projection_->northDirection(r.at.lon, r.at.lat, nx, ny);
        }
        const Velocity c{(r.u * ex + r.v * nx) / scale, (r.u * ey + r.v * ny) / scale};
        dac.push_back({t, toLocal(r.at), c, std::nullopt});
    }
    const CorrectionParams p = correctionParams();
    if (!(p.timeScale > 0.0) || !std::isfinite(p.timeScale))
        throw Error(at + ": give observations.time_scale (no default time scale for this field)");
    auto corrected = std::make_shared<CorrectedField>(field_, dac, p);
    report.correction = corrected->summary();
    report.params = p;
    if (report.correction.used == 0)
    {
        std::string why = std::to_string(report.future) + " after the departure, " +
                          std::to_string(report.correction.outsideForecast) + " outside the forecast";
        throw Error(at + ": none of the " + std::to_string(o.dac.size()) +
                    " depth-averaged currents can correct the forecast (" + why + ")");
    }
    field_ = corrected;
    observations_ = std::make_shared<ObservationReport>(std::move(report));
}

std::string observationNote(const MissionProblem &problem)
{
    const auto &r = problem.observations();
    if (!r)
        return "";
    const MissionSpec &m = problem.getSpec();
    const bool ms = m.current.isForecast();
    std::string rejected;
    for (const auto &[why, n] : r->rejected)
        rejected += ", " + std::to_string(n) + " " + why;
    if (r->future > 0)
        rejected += ", " + std::to_string(r->future) + " after the departure";
    if (r->correction.outsideForecast > 0)
        rejected += ", " + std::to_string(r->correction.outsideForecast) + " outside the forecast";
    if (r->correction.older > 0)
        rejected += ", " + std::to_string(r->correction.older) + " older than the most recent kept";
    return "glider observations '" + r->source + "'" + (r->platform.empty() ? "" : " (" + r->platform + ")") + ": " +
           std::to_string(r->correction.used) + " DAC used" +
           (rejected.empty() ? "" : "; rejected" + rejected.substr(1)) + "; RMS innovation " +
           text::number(r->correction.rmsBefore, 3) + (ms ? " m/s" : "") + " before, " +
           text::number(r->correction.rmsAfter, 3) + (ms ? " m/s" : "") + " after the correction";
}
} // namespace ompl_glider

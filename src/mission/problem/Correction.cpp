/// @file Correction.cpp
/// @brief The forecast corrected by a glider's depth-averaged currents (MissionProblem::applyObservations()), and
/// what the correction says (Observations.h); reading the observations and resuming at the last fix are
/// src/mission/inputs/'s.

#include "ompl_glider/mission/Observations.h"

#include <algorithm>
#include <cmath>

#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"

namespace ompl_glider
{
CorrectionParams MissionProblem::correctionParams() const
{
    const MissionSpec &m = spec_;
    const ObservationsSpec s = m.observations.value_or(ObservationsSpec{});
    const CorrectionParams forecast; // a forecast's defaults (metres, seconds), stated once in CorrectedField.h
    CorrectionParams p;
    const double side = std::max(frame_.box.xMax - frame_.box.xMin, frame_.box.yMax - frame_.box.yMin);
    p.lengthScale = std::isfinite(s.lengthScale) ? s.lengthScale
                    : m.current.isForecast()     ? forecast.lengthScale
                                                 : 0.1 * side;
    const double span = field_->timeEnd() - field_->timeBegin();
    p.timeScale = std::isfinite(s.timeScale) ? s.timeScale
                  : m.hasTimeUnit()          ? forecast.timeScale / (m.current.isForecast() ? 1.0 : m.timeUnitSeconds)
                  : std::isfinite(span)      ? 0.1 * span
                                             : side / m.vehicle.speed;
    p.errorRatio = std::isfinite(s.errorRatio) ? s.errorRatio : forecast.errorRatio;
    // with forecast runs, the priors of the scales not given from the runs' differences ([ParrishDerberNMC])
    if (runSpread_ && runSpread_->pairs > 0)
    {
        const bool length = !std::isfinite(s.lengthScale) && std::isfinite(runSpread_->lengthScale);
        const bool time = !std::isfinite(s.timeScale) && std::isfinite(runSpread_->timeScale);
        if (length)
            p.lengthScale = runSpread_->lengthScale;
        if (time)
            p.timeScale = runSpread_->timeScale;
        if (length || time)
            p.priorSource = "from the forecast runs' differences (NMC, " + std::to_string(runSpread_->pairs) +
                            " pairs" +
                            (length && time ? ""
                             : length       ? "; the length scale"
                                            : "; the time scale") +
                            ")";
    }
    // what is given is kept; the rest are priors the DAC may improve on ([RasmussenGP] Sec. 5.4.1)
    p.learn = s.learn;
    p.lengthGiven = std::isfinite(s.lengthScale);
    p.timeGiven = std::isfinite(s.timeScale);
    p.ratioGiven = std::isfinite(s.errorRatio);
    // a DAC is good to about 1 cm/s (its error is never estimated below that); in field units
    const double seconds = !m.hasTimeUnit() ? 0.0 : m.current.isForecast() ? 1.0 : m.timeUnitSeconds;
    const double metresPerSecond = m.physicalUnits().length && seconds > 0.0 ? m.metresPerUnit() / seconds : 0.0;
    p.dacError = metresPerSecond > 0.0 ? 0.01 / metresPerSecond : 0.03 * m.vehicle.speed;
    p.secondsPerTimeUnit = seconds;
    if (m.dive.enabled)
    {
        p.depthTop = m.dive.params.zMin;
        p.depthBottom = m.dive.params.zMax;
    }
    else
        p.depthTop = p.depthBottom = m.vehicle.depth;
    return p;
}

#if OMPL_GLIDER_WITH_NETCDF
namespace
{
/// "farther than 200 km from the mission's area (10 length scales)"
std::string farText(const MissionSpec &m, double distance)
{
    return "farther than " +
           (m.physicalUnits().length ? text::number(distance * m.metresPerUnit() / 1000.0, 4) + " km"
                                     : text::number(distance, 4)) +
           " from the mission's area (10 length scales)";
}

/// The planning frame's vector @p d in east and north components at the mean position of @p dac (the frame's axes
/// there, LocalProjection's east and north directions); as it is without a projection.
Velocity eastNorth(Velocity d, const std::vector<DacRecord> &dac, const LocalProjection *projection)
{
    if (!projection || dac.empty())
        return d;
    double lon = 0.0, lat = 0.0, ex = 1.0, ey = 0.0, nx = 0.0, ny = 1.0;
    for (const DacRecord &r : dac)
    {
        lon += std::remainder(r.at.lon - dac.front().at.lon, 360.0); // across the antimeridian too
        lat += r.at.lat;
    }
    lon = dac.front().at.lon + lon / static_cast<double>(dac.size());
    lat /= static_cast<double>(dac.size());
    projection->eastDirection(lon, lat, ex, ey);
    projection->northDirection(lon, lat, nx, ny);
    // d = E east + N north
    const double det = ex * ny - ey * nx;
    return {(d.u * ny - d.v * nx) / det, (ex * d.v - ey * d.u) / det};
}

/// "12.5 m" of a depth
std::string metresText(double z)
{
    return text::number(z, 4) + " m";
}

/// What the DAC @p dac were compared with (ObservationReport::comparedWith): a DAC is the current averaged over a
/// dive, which the surface current of a forecast is not.
std::string comparedWith(const MissionSpec &m, const CorrectionParams &p, const std::vector<DacObservation> &dac,
                         double deepest)
{
    if (m.current.depthAverage)
        return "the forecast's " + text::number(m.current.depthAverage->first, 4) + "-" +
               metresText(m.current.depthAverage->second) + " average (current.depth_average)";
    std::size_t own = 0;
    for (const DacObservation &o : dac)
        own += std::isfinite(o.depthBottom) ? 1 : 0;
    if (p.depthBottom > p.depthTop)
        return std::string(own > 0
                               ? "the forecast averaged over each dive's own depths (" + std::to_string(own) + " of " +
                                     std::to_string(dac.size()) + " DAC, within the dive profile's), " + "else over "
                               : "the forecast averaged over ") +
               "the dive profile's " + text::number(p.depthTop, 4) + "-" + metresText(p.depthBottom);
    if (!m.current.isForecast())
        return "the flow at the glider's depth (" + metresText(p.depthTop) + ")";
    std::string s = p.depthTop > 0.0 ? "the forecast's current at " + metresText(p.depthTop) : "the surface current";
    s += " (a DAC is an average over the dive";
    if (std::isfinite(deepest))
        s += ", down to " + metresText(deepest) + " here: give the depth average 0-" +
             text::number(std::round(deepest), 6) + " m (" + m.term("current.depth_average") +
             ") to compare like with like";
    else
        s += ": give a depth average (" + m.term("current.depth_average") +
             ") or a dive profile to compare like with like";
    return s + ")";
}
} // namespace

std::vector<GliderFix> surfacingFixes(const ObservationReport &o, bool *dacOnly)
{
    const auto isDacPosition = [&](const GliderFix &f) {
        return std::any_of(o.dac.begin(), o.dac.end(), [&](const DacRecord &d) {
            return d.time == f.time && d.at.lon == f.at.lon && d.at.lat == f.at.lat;
        });
    };
    std::vector<GliderFix> fixes;
    for (const GliderFix &f : o.fixes)
        if (!isDacPosition(f))
            fixes.push_back(f);
    if (dacOnly)
        *dacOnly = fixes.empty();
    return fixes.empty() ? o.fixes : fixes;
}

void MissionProblem::applyObservations(const GliderObservations &o)
{
    const std::string at = spec_.place("observations");
    ObservationReport report;
    report.source = o.source;
    report.files = o.files;
    report.platform = o.platform;
    report.rejected = o.rejected;
    report.notes = o.notes;
    report.lastFix = o.lastFix;
    report.fixes = o.fixes;
    report.dac = o.dac;
    const MissionSpec &m = spec_;
    const double departure = m.departure.window ? m.departure.begin : m.departure.time;
    // velocities in field units (a forecast's m/s; an analytic flow's units per time unit)
    const double scale = m.metresPerUnit() / (m.current.isForecast() ? 1.0 : m.timeUnitSeconds);
    const CorrectionParams p = correctionParams();
    if (!(p.timeScale > 0.0) || !std::isfinite(p.timeScale))
        throw Error(at + ": give observations.time_scale (no default time scale for this field)");
    // a DAC farther from the mission's area than 10 length scales (the given or the prior one) says nothing of its
    // currents: left out before anything is learned, and counted as such
    report.farDistance = 10.0 * p.lengthScale;
    std::vector<DacObservation> dac;
    // a forecast loaded to the dive profile's depth holds the layers a dive's own depth range needs (a depth-averaged
    // forecast holds none, a surface one only the surface)
    const bool ownDepths = m.dive.enabled && !m.current.depthAverage && p.depthBottom > p.depthTop;
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
        if (frame_.projection)
        {
            frame_.projection->eastDirection(r.at.lon, r.at.lat, ex, ey);
            frame_.projection->northDirection(r.at.lon, r.at.lat, nx, ny);
        }
        const Velocity c{(r.u * ex + r.v * nx) / scale, (r.u * ey + r.v * ny) / scale};
        const Point2 q = toLocal(r.at);
        const double dx = std::max({frame_.box.xMin - q.x, 0.0, q.x - frame_.box.xMax});
        const double dy = std::max({frame_.box.yMin - q.y, 0.0, q.y - frame_.box.yMax});
        if (std::hypot(dx, dy) > report.farDistance)
        {
            ++report.far;
            continue;
        }
        dac.push_back({t, q, c, std::nullopt});
        if (std::isfinite(r.depthMax))
        {
            report.deepestDive =
                std::isfinite(report.deepestDive) ? std::max(report.deepestDive, r.depthMax) : r.depthMax;
            if (ownDepths) // the forecast holds the dive profile's layers: each dive's own range, within them
            {
                dac.back().depthTop = std::clamp(std::isfinite(r.depthMin) ? r.depthMin : 0.0, 0.0, p.depthBottom);
                dac.back().depthBottom = std::clamp(r.depthMax, dac.back().depthTop, p.depthBottom);
            }
        }
    }
    report.comparedWith = comparedWith(m, p, dac, report.deepestDive);
    // the forecast the DAC make: corrected; an ensemble's members weighed by them and updated, then corrected
    const LearnedForecast learned = learnForecast(field_, members_, dac, p);
    report.correction = learned.correction;
    report.meanInnovationEastNorth = eastNorth(report.correction.meanInnovation, o.dac, frame_.projection.get());
    report.params = learned.correction.params;
    report.members = learned.members;
    if (report.correction.used == 0)
    {
        std::string why = std::to_string(report.future) + " after the departure, " +
                          std::to_string(report.correction.outsideForecast) + " outside the forecast";
        if (report.far > 0)
            why += ", " + std::to_string(report.far) + " " + farText(m, report.farDistance);
        throw Error(at + ": none of the " + std::to_string(o.dac.size()) +
                    " depth-averaged currents can correct the forecast (" + why + ")");
    }
    field_ = learned.field;
    // the members have spoken through the DAC: the plan is made on the forecast they make (not judged member by
    // member); the members as read are kept with their weights for the probability of reach
    if (learned.members.size() == members_.size())
        weighedMembers_ = members_;
    members_.clear();
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
    if (r->far > 0)
        rejected += ", " + std::to_string(r->far) + " " + farText(m, r->farDistance);
    if (r->correction.older > 0)
        rejected += ", " + std::to_string(r->correction.older) + " older than the most recent kept";
    return "glider observations '" + r->source + "'" + (r->platform.empty() ? "" : " (" + r->platform + ")") + ": " +
           std::to_string(r->correction.used) + " DAC used" +
           (rejected.empty() ? "" : "; rejected" + rejected.substr(1)) + "; RMS innovation " +
           text::number(r->correction.rmsBefore, 3) + (ms ? " m/s" : "") + " before, " +
           text::number(r->correction.rmsAfter, 3) + (ms ? " m/s" : "") + " after the correction";
}

std::string correctionNote(const MissionProblem &problem)
{
    const auto &r = problem.observations();
    if (!r)
        return "";
    const MissionSpec &m = problem.getSpec();
    const CorrectionSummary &c = r->correction;
    const bool km = m.physicalUnits().length, time = m.hasTimeUnit();
    const double seconds = !time ? 0.0 : m.current.isForecast() ? 1.0 : m.timeUnitSeconds;
    const double ms = km && seconds > 0.0 ? m.metresPerUnit() / seconds : 0.0; // metres per second per field unit
    const auto speed = [&](double v) { return ms > 0.0 ? text::number(v * ms, 3) + " m/s" : text::number(v, 3); };
    std::string out = "L " +
                      (km ? text::number(c.params.lengthScale * m.metresPerUnit() / 1000.0, 4) + " km"
                          : text::number(c.params.lengthScale, 4)) +
                      " (" + c.lengthSource + "), T " + m.durationText(c.params.timeScale) + " (" + c.timeSource +
                      "), ratio " + text::number(c.params.errorRatio, 3) + " (" + c.ratioSource + ")";
    if (c.learnedFrom > 0)
    {
        out += "; ln likelihood +" + text::number(c.likelihoodGain, 4) + " over the priors";
        const HeldOutCheck &h = c.heldOut;
        const std::string scores = " (held-out RMS error " +
                                   speed(h.scalesKept ? (h.meanKept ? h.learnedError : h.scalesError) : h.meanError) +
                                   " against the priors' " + speed(h.priorError) + "; fitted on the first " +
                                   std::to_string(h.fitted) + " DAC, scored on the next " + std::to_string(h.scored) +
                                   ")";
        if (h.scored == 0)
            out += "; the priors stand: too few DAC to judge the estimate on DAC not used to fit it";
        else if (h.scalesKept)
            out += std::string("; learned scales ") + (h.meanKept ? "and mean " : "") + "kept" +
                   (h.meanKept ? "" : ", the mean dropped") + scores;
        else if (h.meanKept)
            out += "; the prior scales stand, the learned mean kept" + scores;
        else
            out += "; the priors stand: the learned scales and mean predicted the held-out DAC no better (" +
                   speed(std::min({h.learnedError, h.scalesError, h.meanError})) + " against " + speed(h.priorError) +
                   "; fitted on the first " + std::to_string(h.fitted) + " DAC, scored on the next " +
                   std::to_string(h.scored) + ")";
    }
    if (c.mean.active())
    {
        out += "; bias (" + speed(c.mean.bias.u) + ", " + speed(c.mean.bias.v) + ")";
        for (const InnovationMean::Constituent &k : c.mean.tides)
            out += ", " + k.name + " " + speed(std::hypot(k.amplitude(true), k.amplitude(false)));
    }
    if (!r->members.empty())
    {
        // the members that agree best with the glider, as the pilots trust the model that does
        std::vector<std::size_t> order(r->members.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return r->members[a].weight > r->members[b].weight; });
        out += "; members by weight:";
        for (std::size_t k = 0; k < std::min<std::size_t>(3, order.size()); ++k)
            out += std::string(k ? "," : "") + " #" + std::to_string(order[k]) + " " +
                   text::number(r->members[order[k]].weight, 3) + " (RMS " + speed(r->members[order[k]].rmsInnovation) +
                   ")";
    }
    return out;
}
#else
void MissionProblem::applyObservations(const GliderObservations &)
{
    throw Error(spec_.place("observations") + ": this build reads no glider files (it has no NetCDF)");
}
#endif
} // namespace ompl_glider

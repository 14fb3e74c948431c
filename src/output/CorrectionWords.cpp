/// @file CorrectionWords.cpp
/// @brief The correction the glider's DAC made to the forecast, in a pilot's words (correctionLines(), Report.h): what
/// was used, what the glider measured against the forecast (speed and direction, m/s and kn), and how far and how
/// long ahead the plan uses it. The statisticians' figures (RMS innovations, likelihood, bias, tides, member weights)
/// are summary.json's (SummaryInputs.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ompl_glider/Config.h"
#include "ompl_glider/output/Report.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/mission/Observations.h"
#endif

namespace ompl_glider
{
#if OMPL_GLIDER_WITH_NETCDF
namespace
{
template <class... A> std::string words(const char *fmt, A... args)
{
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, args...);
    return buf;
}

/// The mission's units for the words: metres per length unit (0: none), seconds per field time unit (0: none), and
/// m/s per unit of the field's velocity (0: the field's numbers have no physical unit).
struct Units
{
    double metres{0.0}, seconds{0.0}, speed{0.0};
    explicit Units(const MissionSpec &m)
    {
        metres = m.physicalUnits().length ? m.metresPerUnit() : 0.0;
        seconds = m.hasTimeUnit() ? m.timeUnitSeconds : 0.0;
        // a forecast's velocities are m/s whatever its time unit; an analytic flow's are length units per time unit
        const double velocitySeconds = !m.hasTimeUnit() ? 0.0 : m.current.isForecast() ? 1.0 : m.timeUnitSeconds;
        speed = metres > 0.0 && velocitySeconds > 0.0 ? metres / velocitySeconds : 0.0;
    }
    /// "0.17 m/s (0.33 kn)", or the field's number
    std::string speedText(double v) const
    {
        return speed > 0.0 ? words("%.2f m/s (%.2f kn)", v * speed, v * speed * 3600.0 / 1852.0) : words("%.3g", v);
    }
    /// "18 km", or the field's number
    std::string lengthText(double d) const
    {
        return metres > 0.0 ? words(d * metres >= 10000.0 ? "%.0f km" : "%.1f km", d * metres / 1000.0)
                            : words("%.3g", d);
    }
    /// "3.6 h", "1.6 d", or the field's number
    std::string durationText(double t) const
    {
        if (seconds <= 0.0)
            return words("%.3g", t);
        const double h = t * seconds / 3600.0;
        return h >= 48.0 ? words("%.1f d", h / 24.0) : words("%.1f h", h);
    }
};

/// The direction a vector points to on a 16-point compass: "east", "south-west", "north-north-east".
std::string compassPoint(double east, double north)
{
    static const char *names[16] = {"north", "north-north-east", "north-east", "east-north-east",
                                    "east",  "east-south-east",  "south-east", "south-south-east",
                                    "south", "south-south-west", "south-west", "west-south-west",
                                    "west",  "west-north-west",  "north-west", "north-north-west"};
    double deg = std::atan2(east, north) * 180.0 / 3.14159265358979323846;
    deg = deg < 0.0 ? deg + 360.0 : deg;
    return names[static_cast<int>(std::floor(deg / 22.5 + 0.5)) % 16];
}

/// "8 DAC used (2026-03-14T00:40:00Z to 2026-03-14T10:10:00Z); rejected 2 after the departure"
/// "; 1 DAC placed at the surfacing's fix (...)": what the reader says of what it kept
std::string notesText(const ObservationReport &o)
{
    std::string s;
    for (const auto &[what, n] : o.notes)
        s += "; " + std::to_string(n) + " " + what;
    return s;
}

std::string usedLine(const ObservationReport &o, const MissionSpec &m, const Units &u)
{
    const CorrectionSummary &c = o.correction;
    std::string rejected;
    for (const auto &[why, n] : o.rejected)
        rejected += ", " + std::to_string(n) + " " + why;
    if (o.future > 0)
        rejected += ", " + std::to_string(o.future) + " after the departure";
    if (c.outsideForecast > 0)
        rejected += ", " + std::to_string(c.outsideForecast) + " outside the forecast";
    if (o.far > 0)
        rejected += ", " + std::to_string(o.far) + " farther than " + u.lengthText(o.farDistance) + " from the area";
    if (c.older > 0)
        rejected += ", " + std::to_string(c.older) + " older than the most recent kept";
    const std::string from = m.isoTime(c.firstUsed), to = m.isoTime(c.lastUsed);
    return "glider observations '" + o.source + "'" + (o.platform.empty() ? "" : " (" + o.platform + ")") + ": " +
           std::to_string(c.used) + " DAC used" +
           (from.empty() || c.used == 0 ? ""
            : c.used == 1               ? " (" + from + ")"
                                        : " (" + from + " to " + to + ")") +
           (rejected.empty() ? "" : "; rejected" + rejected.substr(1)) + notesText(o);
}

/// "the glider measured 0.17 m/s (0.33 kn) less eastward and 0.05 m/s (0.10 kn) more northward current than
/// forecast: in all 0.18 m/s (0.35 kn) towards the west-north-west (the mean over its 8 DAC)"
std::string measuredLine(const ObservationReport &o, const Units &u)
{
    const CorrectionSummary &c = o.correction;
    const Velocity d = o.meanInnovationEastNorth; // east and north: from true north, as every bearing written
    const double size = std::hypot(d.u, d.v);
    const std::string over = words("the mean over its %zu DAC", c.used);
    // below half a centimetre per second (or a field's millionth) the difference is no news to a pilot
    if (u.speed > 0.0 ? size * u.speed < 0.005 : size < 1e-6)
        return "the glider measured the current as forecast (" + over + " differs by less than " +
               (u.speed > 0.0 ? std::string("0.005 m/s") : std::string("1e-6")) + ")";
    const auto part = [&](double v, const char *way) {
        return u.speedText(std::abs(v)) + (v < 0.0 ? " less " : " more ") + way;
    };
    // the components a pilot reads (one tenth of the whole or more), and the whole where both are
    const bool east = std::abs(d.u) >= 0.1 * size, north = std::abs(d.v) >= 0.1 * size;
    const std::string parts = east && north ? part(d.u, "eastward") + " and " + part(d.v, "northward")
                              : east        ? part(d.u, "eastward")
                                            : part(d.v, "northward");
    return "the glider measured " + parts + " current than forecast" +
           (east && north ? ": in all " + u.speedText(size) + " towards the " + compassPoint(d.u, d.v) : "") + " (" +
           over + ")";
}

/// "the plan uses that within about 18 km of the dives and for about 3.6 h after them (the correction's length and
/// time scales: estimated from 8 DAC)"
std::string reachLine(const CorrectionSummary &c, const Units &u)
{
    const std::string sources =
        c.lengthSource == c.timeSource ? c.lengthSource : "length " + c.lengthSource + ", time " + c.timeSource;
    std::string line = "the plan uses that within about " + u.lengthText(c.params.lengthScale) +
                       " of the dives and for about " + u.durationText(c.params.timeScale) +
                       " after them (the correction's length and time scales: " + sources + ")";
    if (c.mean.active())
        line += "; the mean difference is carried farther, fading over about " + u.lengthText(c.mean.lengthScale) +
                " and " + u.durationText(c.mean.timeScale) + " beyond them" +
                (c.mean.tides.empty() ? "" : ", with the tides it resolved");
    return line;
}
} // namespace

std::vector<std::string> correctionLines(const MissionResult &r)
{
    std::vector<std::string> lines;
    if (!r.observations)
        return lines;
    const ObservationReport &o = *r.observations;
    const Units u(r.spec);
    lines.push_back(usedLine(o, r.spec, u));
    if (o.correction.used == 0)
        return lines;
    lines.push_back(measuredLine(o, u));
    // what the DAC were compared with: a DAC is an average over the dive, the forecast's surface current is not
    if (!o.comparedWith.empty())
        lines.push_back("the DAC were compared with " + o.comparedWith);
    lines.push_back(reachLine(o.correction, u));
    if (!o.members.empty())
    {
        // the members that agree best with the glider, as the pilots trust the model that does
        std::vector<std::size_t> order(o.members.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return o.members[a].weight > o.members[b].weight; });
        std::string best;
        for (std::size_t k = 0; k < std::min<std::size_t>(3, order.size()); ++k)
            best += words("%s #%zu (%.0f %%)", k ? "," : "", order[k], 100.0 * o.members[order[k]].weight);
        lines.push_back(words("the forecast's %zu members weighed by the DAC; the closest to them:", o.members.size()) +
                        best);
    }
    return lines;
}
#else
std::vector<std::string> correctionLines(const MissionResult &)
{
    return {};
}
#endif
} // namespace ompl_glider

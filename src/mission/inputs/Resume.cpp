/// @file Resume.cpp
/// @brief A mission resumed at the glider's last fix (Observations.h: resumeAtLastFix(), resumeNote()): the start and
/// departure replaced, the stations the glider's history shows finished dropped, a stay under way held first, a stay
/// left unfinished returned to.

#include "ompl_glider/mission/Observations.h"
#include "InputsInternal.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GeoBox.h"
#include "ompl_glider/io/Time.h"

namespace ompl_glider
{
#if OMPL_GLIDER_WITH_NETCDF
std::shared_ptr<const GliderObservations> readObservationsAt(const std::string &path, const std::string &cache)
{
    return std::make_shared<const GliderObservations>(readGliderObservations(path, {cache}));
}

void keepObservations(ObservationsSpec &s, std::shared_ptr<const GliderObservations> read)
{
    s.read = std::move(read);
    s.readFrom = s.path + "\n" + s.cache;
}

void markLastFixGuess(MissionSpec &m, const SourceMark &mark, bool departure)
{
    m.marks["start"] = SourceMark{mark.file, mark.line, Origin::Observations};
    if (departure)
        m.marks["departure.time"] = SourceMark{mark.file, mark.line, Origin::Observations};
}

void startAtLastFix(MissionSpec &m, const SourceMark &mark, bool keepDeparture)
{
    const std::shared_ptr<const GliderObservations> read =
        readObservationsAt(m.observations->path, m.observations->cache);
    keepObservations(*m.observations, read); // read once: the mission's inputs take them from here
    const std::optional<GliderFix> &fix = read->lastFix;
    if (!fix)
        throw Error("the observations '" + m.observations->path + "' report no position to start from");
    m.start.geographic = true;
    m.start.lonLat = fix->at;
    if (!keepDeparture)
    {
        try
        {
            m.departure.time = m.timeOf(formatIsoTime(fix->time));
        }
        catch (const Error &e)
        {
            throw Error(std::string("the last fix's time: ") + e.what());
        }
        m.departure.window = false;
    }
    markLastFixGuess(m, mark, !keepDeparture);
}

namespace
{
/// Given by a flag, a keyword or the calling program (not a mission file's, nor the observations' first guess).
bool givenByCaller(const MissionSpec &m, const std::string &field)
{
    const auto it = m.marks.find(field);
    return it != m.marks.end() && (it->second.origin == Origin::Flag || it->second.origin == Origin::Keyword ||
                                   it->second.origin == Origin::Program);
}

/// A field time as a pilot reads it: its date where the mission has dates.
std::string whenText(const MissionSpec &m, double t)
{
    try
    {
        if (const std::string iso = m.isoTime(t); !iso.empty())
            return iso;
    }
    catch (const Error &)
    {
    }
    return text::number(t, 10);
}

/// "3.0 h", "2 d 4.5 h" of @p seconds
std::string durationWords(double seconds)
{
    const double hours = seconds / 3600.0;
    if (hours < 24.0)
        return text::number(std::round(hours * 10.0) / 10.0, 6) + " h";
    const double days = std::floor(hours / 24.0);
    return text::number(days, 6) + " d " + text::number(std::round((hours - 24.0 * days) * 10.0) / 10.0, 6) + " h";
}

/// A stay's length in field time units as a pilot reads it ("4 h"; a number where the mission has no time unit).
std::string stayWords(const MissionSpec &m, double t)
{
    if (!m.hasTimeUnit())
        return text::number(t, 6) + " time units";
    return durationWords(t * (m.current.isForecast() ? 1.0 : m.timeUnitSeconds));
}

/// "500 m", "3.4 km"
std::string metresWords(double d)
{
    return d < 1000.0 ? text::number(std::round(d), 6) + " m" : text::number(std::round(d / 100.0) / 10.0, 6) + " km";
}

/// The visit of one station, followed fix by fix: its stay counts the time between fixes within its radius from its
/// window's opening on.
struct Visit
{
    std::size_t k{0};       ///< the via point
    double stay{0.0};       ///< its stay (field time units)
    double opens{0.0};      ///< the stay counts from here: the window's opening, or the arrival
    double held{0.0};       ///< the stay counted so far
    double inside{0.0};     ///< the last fix within the radius since the glider came (NaN: it left since)
    std::string leftIso;    ///< the fix outside the radius that ended the last run within it
    DroppedStation station; ///< as it is dropped
};

enum class VisitStep
{
    Void,  ///< the glider left before the window opened: no visit
    Going, ///< under way (or away, the stay unfinished)
    Done   ///< the stay is over: the station is finished
};

/// The visit @p v at a fix at field time @p t, within the radius or not.
VisitStep follow(Visit &v, double t, bool within, const std::string &iso)
{
    if (within)
    {
        if (std::isfinite(v.inside)) // within since the last fix: that time is held (from the window's opening)
            v.held += std::max(0.0, t - std::max(v.inside, v.opens));
        v.inside = t; // (back after leaving: the time away is not held)
        return t >= v.opens && v.held >= v.stay ? VisitStep::Done : VisitStep::Going;
    }
    if (!std::isnan(v.inside))
    {
        if (v.inside < v.opens)
            return VisitStep::Void; // not seen there once the window opened
        if (v.inside + (v.stay - v.held) <= t)
        {
            v.held = v.stay; // gone after the stay's end: nothing says it left earlier
            return VisitStep::Done;
        }
        v.inside = std::numeric_limits<double>::quiet_NaN(); // left before the stay was over
        v.leftIso = iso;
    }
    return VisitStep::Going;
}

/// The stations the fixes show reached: the finished ones dropped in the order reached, and the visit not over at the
/// last fix.
struct History
{
    std::vector<bool> reached;
    std::vector<DroppedStation> dropped;
    std::optional<Visit> open;
};

/// The glider's fixes @p o from @p deployed to the last fix, against @p m's via points; @p fieldTime turns a fix's
/// Unix time into field time.
template <typename FieldTime>
History stationHistory(const MissionSpec &m, const GliderObservations &o, double deployed, const FieldTime &fieldTime)
{
    History h;
    h.reached.assign(m.waypoints.size(), false);
    std::size_t next = 0; // the order given: the next station to reach
    const auto radiusOf = [&](const ViaPointSpec &v) {
        return std::isfinite(v.radius) ? v.radius * m.metresPerUnit() : m.outputs.gotoWptDist;
    };
    for (const GliderFix &f : o.fixes)
    {
        if (f.time > o.lastFix->time)
            break;
        const double t = fieldTime(f.time, "a fix's time");
        if (t < deployed)
            continue;
        const std::string iso = formatIsoTime(f.time);
        if (h.open)
        {
            Visit &v = *h.open;
            const ViaPointSpec &w = m.waypoints[v.k];
            const VisitStep step = follow(v, t, 1000.0 * greatCircleKm(f.at, w.position.lonLat) <= radiusOf(w), iso);
            if (step == VisitStep::Going)
                continue;
            if (step == VisitStep::Done)
            {
                h.reached[v.k] = true;
                h.dropped.push_back(v.station);
                if (m.order == VisitOrder::Given)
                    ++next;
            }
            h.open.reset(); // done, or no visit: this fix may reach another station
        }
        for (std::size_t k = 0; k < m.waypoints.size(); ++k)
        {
            if (h.reached[k] || (m.order == VisitOrder::Given && k != next))
                continue;
            const ViaPointSpec &w = m.waypoints[k];
            if (!w.position.geographic)
                continue;
            const double d = 1000.0 * greatCircleKm(f.at, w.position.lonLat);
            if (d > radiusOf(w))
                continue;
            Visit v;
            v.k = k;
            v.stay = w.stay;
            v.opens = w.arrive.set ? std::max(t, w.arrive.begin) : t;
            v.inside = t;
            v.station.name = w.name;
            v.station.reachedIso = iso;
            v.station.distance = d;
            v.station.at = w.position.lonLat;
            v.station.radius = radiusOf(w);
            if (w.arrive.set && t > w.arrive.end)
                v.station.windowClosed = whenText(m, w.arrive.end);
            if (follow(v, t, true, iso) == VisitStep::Done)
            {
                h.reached[k] = true;
                h.dropped.push_back(v.station);
                if (m.order == VisitOrder::Given)
                    ++next;
                continue; // (a station without a stay: the same fix may reach the next one)
            }
            h.open = std::move(v);
            break;
        }
    }
    return h;
}

/// The fixes count from the mission's own departure (the deployment's), also where a caller's departure replaced it;
/// from the first one where the mission gives none (the last fix's first guess, a caller's departure alone).
double deploymentOf(const MissionSpec &m)
{
    if (!std::isnan(m.departure.replaced))
        return m.departure.replaced;
    const auto d = m.marks.find("departure.time");
    if (givenByCaller(m, "departure.time") || (d != m.marks.end() && d->second.origin == Origin::Observations))
        return -std::numeric_limits<double>::infinity();
    return m.departure.window ? m.departure.begin : m.departure.time;
}
} // namespace

std::shared_ptr<const GliderObservations> resumeAtLastFix(MissionSpec &m)
{
    if (!m.observations || !m.observations->hasFiles() || m.observations->resumed || !m.fleet.empty())
        return nullptr;
    if (givenByCaller(m, "start"))
        return nullptr; // the caller says where the glider is: the observations only correct the forecast
    const std::shared_ptr<const GliderObservations> read = inputs_detail::observationsOf(m);
    const GliderObservations &o = *read;
    if (!o.lastFix)
        throw Error("the observations '" + m.observations->path + "' report no position to start from");
    MissionResume r;
    r.fix = o.lastFix->at;
    r.fixIso = formatIsoTime(o.lastFix->time);
    const auto fieldTime = [&](double unixSeconds, const char *what) {
        try
        {
            return m.timeOf(formatIsoTime(unixSeconds));
        }
        catch (const Error &e)
        {
            throw Error(std::string(what) + ": " + e.what());
        }
    };
    const double fixTime = fieldTime(o.lastFix->time, "the last fix's time");
    // a newer surfacing without a valid fix: the glider was elsewhere by then (a surfacing lasts minutes)
    if (std::isfinite(o.newestSurfacing) && o.newestSurfacing > o.lastFix->time + 600.0)
        r.staleFix = "the newest surfacing (" + formatIsoTime(o.newestSurfacing) + ") gave no valid fix: the plan " +
                     "departs from the last valid one, " + durationWords(o.newestSurfacing - o.lastFix->time) +
                     " older; the glider has moved since (give the start where it is, or wait for a fix)";
    const auto mark = m.marks.find("start");
    const bool startIsTheFix = m.start.geographic && m.start.lonLat.lon == o.lastFix->at.lon &&
                               m.start.lonLat.lat == o.lastFix->at.lat; // the loader's first guess
    if ((mark == m.marks.end() || mark->second.origin != Origin::Observations) && !startIsTheFix)
        r.replacedStart = m.start.geographic
                              ? text::number(m.start.lonLat.lon, 8) + ", " + text::number(m.start.lonLat.lat, 8)
                              : text::number(m.start.xy.x, 8) + ", " + text::number(m.start.xy.y, 8);
    // the stations reached, in the order listed (any order when the order is free), judged on the glider's history
    // from the deployment to the last fix, whatever departure the plan is made for
    History h = stationHistory(m, o, deploymentOf(m), fieldTime);
    r.dropped = std::move(h.dropped);
    double departure = fixTime; // the plan departs from the last fix, after a stay under way there
    if (h.open && !std::isnan(h.open->inside))
    {
        // the glider is at the station at the last fix: it holds there (until the window opens), then its stay
        Visit &v = *h.open;
        const double ends = std::max(v.inside, v.opens) + (v.stay - v.held);
        if (v.inside < v.opens)
            v.station.windowOpens = whenText(m, v.opens);
        v.station.stayLeft = std::max(0.0, ends - fixTime);
        if (v.station.stayLeft > 0.0)
        {
            r.stayEnds = whenText(m, ends);
            departure = ends;
        }
        r.dropped.push_back(v.station);
        h.reached[v.k] = true;
    }
    else if (h.open)
    {
        // the glider left the station before its stay was over: it goes back to hold what is left (its window met)
        const Visit &v = *h.open;
        m.waypoints[v.k].stay = v.stay - v.held;
        m.waypoints[v.k].arrive = {};
        LeftStay s;
        s.name = v.station.name;
        s.reachedIso = v.station.reachedIso;
        s.leftIso = v.leftIso;
        s.held = v.held;
        s.stayLeft = v.stay - v.held;
        s.distance = 1000.0 * greatCircleKm(o.lastFix->at, v.station.at);
        s.radius = v.station.radius;
        r.leftStay = s;
    }
    std::vector<ViaPointSpec> left;
    for (std::size_t k = 0; k < m.waypoints.size(); ++k)
        if (!h.reached[k])
            left.push_back(m.waypoints[k]);
    if (left.empty() && m.goal.geographic)
    {
        const double radius = m.execution.radius > 0.0 ? m.execution.radius * m.metresPerUnit() : m.outputs.gotoWptDist;
        const double d = 1000.0 * greatCircleKm(o.lastFix->at, m.goal.lonLat);
        if (d <= radius)
            throw Error("the last fix (" + r.fixIso + ", " + text::number(d, 3) + " m from the goal) is at the goal" +
                        (m.waypoints.empty() ? std::string() : " and every via point was reached") +
                        ": nothing is left to plan");
    }
    if (givenByCaller(m, "departure.time"))
    {
        if (m.departure.time < fixTime)
            throw Error("the departure " + whenText(m, m.departure.time) + " is before the last fix (" + r.fixIso +
                        "): the glider was elsewhere then; give a later departure, or none to depart at the last fix");
        if (m.departure.time < departure) // during the stay under way: the stay is finished first
        {
            r.departureDuringStay = whenText(m, m.departure.time);
            m.departure.time = departure;
        }
    }
    else
    {
        const auto d = m.marks.find("departure.time");
        if (d == m.marks.end() || d->second.origin != Origin::Observations)
            r.replacedDeparture = whenText(m, m.departure.window ? m.departure.begin : m.departure.time);
        m.departure.time = departure;
        m.departure.window = false;
        m.marks["departure.time"] =
            SourceMark{m.observations->mark.file, m.observations->mark.line, Origin::Observations};
    }
    m.start.geographic = true;
    m.start.lonLat = o.lastFix->at;
    m.marks["start"] = SourceMark{m.observations->mark.file, m.observations->mark.line, Origin::Observations};
    m.waypoints = std::move(left);
    m.observations->resumed = std::move(r);
    return read;
}

std::vector<std::string> resumeWarnings(const MissionSpec &m)
{
    std::vector<std::string> out;
    if (!m.observations || !m.observations->resumed)
        return out;
    const MissionResume &r = *m.observations->resumed;
    for (const DroppedStation &d : r.dropped)
        if (!d.windowClosed.empty())
            out.push_back(d.name + " was reached after its window closed (reached " + d.reachedIso +
                          ", the window closed " + d.windowClosed + "): dropped as visited, its window missed");
    if (r.leftStay)
    {
        const LeftStay &s = *r.leftStay;
        out.push_back("the glider left " + s.name + "'s " + metresWords(s.radius) +
                      " radius before its stay was over (outside at " + s.leftIso + ", " + metresWords(s.distance) +
                      " from it at the last fix; " + stayWords(m, s.held) + " of the stay held since " + s.reachedIso +
                      "): the plan returns to " + s.name + " to hold the remaining " + stayWords(m, s.stayLeft));
    }
    if (!r.staleFix.empty())
        out.push_back(r.staleFix);
    return out;
}

std::string resumeNote(const MissionSpec &m)
{
    if (!m.observations || !m.observations->resumed)
        return "";
    const MissionResume &r = *m.observations->resumed;
    std::string s =
        "from the last fix " + text::number(r.fix.lon, 8) + ", " + text::number(r.fix.lat, 8) + " at " + r.fixIso;
    if (!r.replacedStart.empty())
        s += " (replacing the mission's start " + r.replacedStart + ", the deployment's" +
             (r.replacedDeparture.empty() ? std::string() : ", and its departure " + r.replacedDeparture) + ")";
    else if (!r.replacedDeparture.empty())
        s += " (replacing the mission's departure " + r.replacedDeparture +
             ": the glider was elsewhere then, the plan departs from where and when it was last seen)";
    if (r.dropped.empty())
        s += "; no station reached yet";
    else
    {
        s += "; stations reached and dropped:";
        for (std::size_t i = 0; i < r.dropped.size(); ++i)
            s += std::string(i ? "," : "") + " " + r.dropped[i].name + " (" + r.dropped[i].reachedIso + ", " +
                 text::number(r.dropped[i].distance, 3) + " m from it" +
                 (r.dropped[i].windowClosed.empty() ? "" : ", after its window closed") + ")";
    }
    if (!r.stayEnds.empty())
    {
        const DroppedStation &d = r.dropped.back();
        s += "; the stay at " + d.name + " is under way" +
             (d.windowOpens.empty() ? std::string()
                                    : " (reached before its window opened: the glider holds there until it opens, " +
                                          d.windowOpens + ", then stays)") +
             ": the plan departs at its end, " + r.stayEnds;
        if (!r.departureDuringStay.empty())
            s += " (not at the departure given, " + r.departureDuringStay + ", during the stay)";
    }
    for (const std::string &w : resumeWarnings(m))
        s += "; WARNING: " + w;
    return s;
}

std::shared_ptr<const GliderObservations> inputs_detail::observationsOf(const MissionSpec &m)
{
    if (!m.observations || !m.observations->hasFiles())
        return nullptr;
    const ObservationsSpec &s = *m.observations;
    if (s.read && s.readFrom == s.path + "\n" + s.cache)
        return s.read;
    return readObservationsAt(s.path, s.cache);
}
#else
std::shared_ptr<const GliderObservations> inputs_detail::observationsOf(const MissionSpec &m)
{
    if (m.observations && m.observations->hasFiles())
        throw Error(m.place("observations") + ": this build reads no glider files (it has no NetCDF)");
    return nullptr;
}
#endif

void inputs_detail::checkLastFixInForecast(const ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    if (!m.observations || !m.observations->resumed)
        return;
    const MissionResume &r = *m.observations->resumed;
    const double fix = m.timeOf(r.fixIso), end = in.field->timeEnd();
    if (std::isfinite(end) && fix > end)
    {
        const std::string endText = m.isoTime(end).empty() ? text::number(end, 10) : m.isoTime(end);
        throw Error(m.place("observations") + ": the glider's last fix (" + r.fixIso +
                    ") is after the forecast's end (" + endText +
                    "): the forecast says nothing of the currents from there on; give a forecast that covers the "
                    "time from the last fix on");
    }
}
} // namespace ompl_glider

// The mission's current field (ProblemInputs.h): the forecast or analytic flow planned on, the members of an
// ensemble and the truth an execution flies in, each loaded from its source once.
#include "InputsInternal.h"
#include "../../io/NumberText.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/EnsembleField.h"
#include "ompl_glider/current/LocalProjection.h"
#include "ompl_glider/current/ShiftedTimeField.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider::inputs_detail
{
void loadField(ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    const CurrentFieldKind *kind = findCurrentFieldKind(m.current.type);
    if (!kind)
        throw Error(sourcePlace(m, m.current.mark) + "field 'current.type': unknown '" + m.current.type +
                    "' (expected one of " + currentFieldKindList() + ")");
    if (!kind->gridded())
    {
        in.field = makeAnalyticField(m.current.type, m.current.parameters);
        if (m.projection.set)
            in.frame.projection = std::make_shared<LocalProjection>(m.projection.lon0, m.projection.lat0);
        in.frame.projectionScale = m.lengthUnitMetres;
        return;
    }
    if (!m.current.runs.empty())
        return loadRuns(in, *kind);
    LoadedForecast forecast;
    try
    {
        forecast = kind->source->load(forecastRequest(m));
    }
    catch (const Error &e)
    {
        // a mission file's current section (the command line's forecastMission() words its own messages)
        if (m.current.mark.line > 0)
            throw Error(sourcePlace(m, m.current.mark) + e.what());
        throw;
    }
    checkDepthAxis(m, forecast);
    keepForecast(in, forecast);
    in.field = forecast.field;
}

void keepForecast(ProblemInputs &in, const LoadedForecast &forecast)
{
    in.frame.projection = forecast.projection;
    in.frame.projectionScale = 1.0;
    in.frame.xyScale = forecast.projection ? 1.0 : forecast.xyMetres;
    in.forecastFiles = forecast.files;
    in.forecastNotes = forecast.notes;
    in.remoteSources = remoteFetchesOf(forecast.files);
    in.wind = forecast.wind;
}

std::shared_ptr<const CurrentField> loadSource(const ProblemInputs &in, const CurrentSpec &t, const std::string &field)
{
    const MissionSpec &m = in.spec;
    const std::shared_ptr<const LocalProjection> &projection = in.frame.projection;
    // a command-line flag gave the source (--truth): name the flag, else the mission file's line and field
    const std::string at =
        t.mark.namesItself() ? t.mark.file + ": " : sourcePlace(m, t.mark) + "field '" + field + "': ";
    const CurrentFieldKind *kind = findCurrentFieldKind(t.type);
    if (!kind)
        throw Error(at + "unknown type '" + t.type + "' (expected one of " + currentFieldKindList() + ")");
    if (!kind->gridded())
        return makeAnalyticField(t.type, t.parameters);
    // Read like the forecast (same region and projection centre), every record of the region: its time axis may
    // start at another date, so the trip's records are not known in its own time.
    MissionSpec tm = m;
    tm.current = t;
    ForecastRequest o = forecastRequest(tm);
    o.optionNames = forecastFieldNames(field); // the source's settings are this section's
    o.departure.clear();
    o.horizon = std::numeric_limits<double>::infinity();
    if (projection)
    {
        o.refLon = projection->lon0();
        o.refLat = projection->lat0();
    }
    LoadedForecast f;
    try
    {
        f = kind->source->load(o);
    }
    catch (const Error &e)
    {
        throw Error(at + e.what());
    }
    if (!f.projection != !projection)
        throw Error(at + (projection ? "it has no longitude/latitude but the forecast has"
                                     : "it has longitude/latitude but the forecast is Cartesian"));
    // Field time 0 of each file is its first time: shifted so that both are asked at the same date.
    double shift = 0.0;
    if (m.fileCalendar && f.dated && !f.steady)
    {
        if (f.calendar != m.fileCalendar->calendar)
            throw Error(at + "its calendar (" + calendarName(f.calendar) + ") differs from the forecast's (" +
                        calendarName(m.fileCalendar->calendar) + ")");
        shift = m.fileCalendar->originSeconds - f.originSeconds;
    }
    else if (m.fileCalendar && !f.dated && !f.steady)
        throw Error(at + "its time axis has no dates ('<unit> since <date>') but the forecast's has: the two cannot "
                         "be aligned");
    return shift == 0.0 ? f.field : std::make_shared<ShiftedTimeField>(f.field, shift);
}

void loadMembers(ProblemInputs &in)
{
    const std::vector<CurrentSpec> &members = in.spec.current.members;
    if (members.empty())
        return;
    in.members.push_back(in.field); // the first member, read as the forecast
    for (std::size_t i = 1; i < members.size(); ++i)
        in.members.push_back(loadSource(in, members[i], "current.ensemble[" + std::to_string(i) + "]"));
    checkCommonTime(in);
    in.field = std::make_shared<EnsembleMeanField>(in.members);
}

void loadTruth(ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    if (m.execution.enabled && m.execution.truth)
        in.truth = loadSource(in, *m.execution.truth, "execution.truth");
}
} // namespace ompl_glider::inputs_detail

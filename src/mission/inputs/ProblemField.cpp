// The mission's current field (MissionProblem.h, "the field"): the forecast or analytic flow planned on, the
// members of an ensemble and the truth an execution flies in, each loaded from its source once.
#include "ompl_glider/mission/MissionProblem.h"
#include "../problem/ProblemParts.h"
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

namespace ompl_glider
{
void MissionProblem::buildField()
{
    const MissionSpec &m = spec_;
    const CurrentFieldKind *kind = findCurrentFieldKind(m.current.type);
    if (!kind)
        throw Error(sourcePlace(m, m.current.mark) + "field 'current.type': unknown '" + m.current.type +
                    "' (expected one of " + currentFieldKindList() + ")");
    if (!kind->gridded())
    {
        field_ = makeAnalyticField(m.current.type, m.current.parameters);
        if (m.projection.set)
            projection_ = std::make_shared<LocalProjection>(m.projection.lon0, m.projection.lat0);
        projectionScale_ = m.lengthUnitMetres;
        return;
    }
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
    checkDepthAxis(forecast);
    field_ = forecast.field;
    projection_ = forecast.projection;
    projectionScale_ = 1.0;
    xyScale_ = forecast.projection ? 1.0 : forecast.xyMetres;
    forecastFiles_ = forecast.files;
    forecastNotes_ = forecast.notes;
    remoteSources_ = remoteFetchesOf(forecast.files);
    if (forecast.wind)
        fieldWord_ = "wind";
}

std::shared_ptr<const CurrentField> MissionProblem::loadSource(const CurrentSpec &t, const std::string &field) const
{
    const MissionSpec &m = spec_;
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
    if (projection_)
    {
        o.refLon = projection_->lon0();
        o.refLat = projection_->lat0();
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
    if (!f.projection != !projection_)
        throw Error(at + (projection_ ? "it has no longitude/latitude but the forecast has"
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

void MissionProblem::buildMembers()
{
    const std::vector<CurrentSpec> &members = spec_.current.members;
    if (members.empty())
        return;
    members_.push_back(field_); // the first member, read as the forecast
    for (std::size_t i = 1; i < members.size(); ++i)
        members_.push_back(loadSource(members[i], "current.ensemble[" + std::to_string(i) + "]"));
    checkCommonTime();
    field_ = std::make_shared<EnsembleMeanField>(members_);
}

void MissionProblem::buildTruth()
{
    const MissionSpec &m = spec_;
    if (m.execution.enabled && m.execution.truth)
        truth_ = loadSource(*m.execution.truth, "execution.truth");
}

} // namespace ompl_glider

// The mission's words for places and times (MissionSpec.h): "FILE:LINE: ", ISO dates and durations in field time.
#include "ompl_glider/mission/MissionSpec.h"

#include <cmath>
#include <string>

#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Time.h"

namespace ompl_glider
{
std::string sourcePlace(const MissionSpec &m, const SourceMark &mark)
{
    if (!mark.file.empty() && mark.line > 0)
        return mark.file + ":" + std::to_string(mark.line) + ": ";
    return m.file + ": ";
}

std::string MissionSpec::isoTime(double t) const
{
    if (!epoch || !std::isfinite(t))
        return "";
    const double s = (fileCalendar ? fileCalendar->originSeconds : *epoch) + t * timeUnitSeconds;
    if (fileCalendar) // a dated forecast's own calendar: a climatology's year 0, a noleap or 360_day year
        return formatCalendarTime(s, fileCalendar->calendar);
    if (!isoYearInRange(s))
        throw Error(place("epoch") + ": t = " + text::number(t) +
                    " falls outside the years 0000-9999, which "
                    "ISO 8601 dates are written in (choose an earlier epoch or a shorter horizon)");
    return formatIsoTime(s);
}

std::string MissionSpec::durationText(double d) const
{
    return physicalUnits().time ? text::durationText(d * timeUnitSeconds) : text::number(d);
}
} // namespace ompl_glider

// Checks of the current sources a mission reads (MissionProblem::checkDepthAxis(), checkCommonTime(),
// checkAnalyticFields()): what the files or the formulas cannot give is refused, never planned on in silence.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "../../io/NumberText.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "InputsInternal.h"

namespace ompl_glider
{
namespace
{
/// The widest planning region (planning length units): a billion kilometres in metres; wider is a typing error and
/// overflows the planner's arithmetic.
constexpr double kMaxRegionSpan = 1e12;

/// An analytic field whose parameters overflow its formulas (a meandering jet with B0 = 1e300) gives NaN or
/// infinity: refused, naming where the parameters were given. Sampled on 9 x 9 points of the box at three times.
void checkFiniteField(const CurrentField &f, const Region &box, double t0, const std::string &at)
{
    for (const double t : {t0, t0 + 1.0, t0 + 10.0})
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
            {
                const double x = box.xMin + (box.xMax - box.xMin) * (i / 8.0);
                const double y = box.yMin + (box.yMax - box.yMin) * (j / 8.0);
                const Velocity v = f.velocity(x, y, 0.0, t); // CMC are counted as differences: no effect
                if (!std::isfinite(v.u) || !std::isfinite(v.v))
                    throw Error(at + "the current is not a finite number at (" + text::number(x, 6) + ", " +
                                text::number(y, 6) + ") at t = " + text::number(t, 6) +
                                ": its parameters overflow the field's formulas");
            }
}
} // namespace

namespace inputs_detail
{
void checkAnalyticFields(const ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    const Region &box = in.frame.box;
    // a region too wide for the planner's numbers (x_max: 1e308) is the region's fault, not the field's
    const double span = std::max(box.xMax - box.xMin, box.yMax - box.yMin);
    if (!(span <= kMaxRegionSpan))
        throw Error(m.place("region") + ": the region spans " + text::number(span) + " units; at most " +
                    text::number(kMaxRegionSpan) + " (give its bounds in the mission's length unit)");
    auto check = [&](const std::shared_ptr<const CurrentField> &f, const CurrentSpec &c, const std::string &field) {
        const CurrentFieldKind *kind = findCurrentFieldKind(c.type);
        if (!f || !kind || kind->gridded())
            return;
        const std::string at =
            c.mark.namesItself() ? c.mark.file + ": " : sourcePlace(m, c.mark) + "field '" + field + "': ";
        checkFiniteField(*f, box, m.departure.time, at);
    };
    if (in.members.empty())
        check(in.field, m.current, "current.parameters");
    for (std::size_t i = 0; i < in.members.size(); ++i)
        check(in.members[i], i == 0 ? m.current : m.current.members[i],
              i == 0 ? std::string("current.parameters") : "current.ensemble[" + std::to_string(i) + "].parameters");
    if (in.truth && m.execution.truth)
        check(in.truth, *m.execution.truth, "execution.truth.parameters");
}

void checkDepthAxis(const MissionSpec &m, const LoadedForecast &nc)
{
    if (nc.depthLevels || !(m.vehicle.depth > 0.0) || m.dive.enabled)
        return;
    // the glider's depth asked for currents that the file does not hold: never planned at the surface in silence
    const auto it = m.marks.find("vehicle.depth");
    const std::string at = it == m.marks.end()    ? m.place("vehicle.depth") + ": "
                           : it->second.line == 0 ? it->second.file + ": "
                                                  : sourcePlace(m, it->second) + "field 'vehicle.depth': ";
    throw Error(at + "the glider's depth of " + text::number(m.vehicle.depth) + " m: the forecast's '" + nc.uVariable +
                "' has no depth dimension, so its currents are of one level (the surface's, or a "
                "depth average), not of " +
                text::number(m.vehicle.depth) +
                " m; plan at depth 0 on it, or on a "
                "forecast with depth levels");
}

void checkCommonTime(const ProblemInputs &in)
{
    const MissionSpec &m = in.spec;
    const std::vector<CurrentSpec> &members = m.current.members;
    const std::vector<std::shared_ptr<const CurrentField>> &fields = in.members;
    // the ensemble is planned where every member holds currents: members without a common time are refused, each
    // named with its span
    double begin = -std::numeric_limits<double>::infinity(), end = std::numeric_limits<double>::infinity();
    for (const auto &f : fields)
    {
        begin = std::max(begin, f->timeBegin());
        end = std::min(end, f->timeEnd());
    }
    if (!(begin < end))
    {
        const auto when = [&m](double t) {
            if (!std::isfinite(t))
                return std::string(t > 0 ? "on" : "ever");
            const std::string iso = m.isoTime(t);
            return iso.empty() ? text::number(t) : iso;
        };
        std::string spans;
        for (std::size_t i = 0; i < fields.size(); ++i)
        {
            const CurrentSpec &c = members[i];
            const std::string name = c.file.empty() ? c.type : "'" + c.file + "'";
            spans += (i ? ", " : "") + std::string("[") + std::to_string(i) + "] " + name + " from " +
                     when(fields[i]->timeBegin()) + " to " + when(fields[i]->timeEnd());
        }
        throw Error(sourcePlace(m, m.current.mark) +
                    "field 'current.ensemble': the members hold currents at "
                    "no common time (" +
                    spans +
                    "); an ensemble is planned where all of them do: give members that "
                    "cover the trip's days");
    }
}
} // namespace inputs_detail
} // namespace ompl_glider

// Checks of the current sources a mission reads (MissionProblem::checkDepthAxis(), checkCommonTime()): what the
// files cannot give is refused, never planned on in silence.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "../io/NumberText.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionProblem.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "ompl_glider/current/NetCdfCurrents.h"
#endif

namespace ompl_glider
{
namespace
{
/// "FILE:LINE: " of a mark from a file, else "MISSION_FILE: " (as MissionProblem.cpp's messages).
std::string where(const MissionSpec &m, const SourceMark &mark)
{
    if (!mark.file.empty() && mark.line > 0)
        return mark.file + ":" + std::to_string(mark.line) + ": ";
    return m.file + ": ";
}
}  // namespace

#if OMPL_GLIDER_WITH_NETCDF
void MissionProblem::checkDepthAxis(const NetCdfCurrents &nc) const
{
    const MissionSpec &m = spec_;
    if (nc.depthAxis || !(m.vehicle.depth > 0.0) || m.dive.enabled)
        return;
    // the glider's depth asked for currents that the file does not hold: never planned at the surface in silence
    const auto it = m.marks.find("vehicle.depth");
    const std::string at = it == m.marks.end() ? m.place("vehicle.depth") + ": "
                           : it->second.line == 0 ? it->second.file + ": "
                                                  : where(m, it->second) + "field 'vehicle.depth': ";
    throw Error(at + "the glider's depth of " + text::number(m.vehicle.depth) + " m: the forecast's '" +
                nc.uVariable + "' has no depth dimension, so its currents are of one level (the surface's, or a "
                "depth average), not of " + text::number(m.vehicle.depth) + " m; plan at depth 0 on it, or on a "
                "forecast with depth levels");
}
#endif

void MissionProblem::checkCommonTime() const
{
    const std::vector<CurrentSpec> &members = spec_.current.members;
    // the ensemble is planned where every member holds currents: members without a common time are refused, each
    // named with its span
    double begin = -std::numeric_limits<double>::infinity(), end = std::numeric_limits<double>::infinity();
    for (const auto &f : members_)
    {
        begin = std::max(begin, f->timeBegin());
        end = std::min(end, f->timeEnd());
    }
    if (!(begin < end))
    {
        const auto when = [this](double t) {
            if (!std::isfinite(t))
                return std::string(t > 0 ? "on" : "ever");
            const std::string iso = isoTime(t);
            return iso.empty() ? text::number(t) : iso;
        };
        std::string spans;
        for (std::size_t i = 0; i < members_.size(); ++i)
        {
            const CurrentSpec &c = members[i];
            const std::string name = c.file.empty() ? c.type : "'" + c.file + "'";
            spans += (i ? ", " : "") + std::string("[") + std::to_string(i) + "] " + name + " from " +
                     when(members_[i]->timeBegin()) + " to " + when(members_[i]->timeEnd());
        }
        throw Error(where(spec_, spec_.current.mark) + "field 'current.ensemble': the members hold currents at no "
                    "common time (" + spans + "); an ensemble is planned where all of them do: give members that "
                    "cover the trip's days");
    }
}
}  // namespace ompl_glider

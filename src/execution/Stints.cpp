/// @file Stints.cpp
/// @brief The stint settings' checks and the objective's names (execution/Stints.h).

#include "ompl_glider/execution/Stints.h"

#include <algorithm>
#include <cmath>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
std::string stintObjectiveName(StintObjective o)
{
    return o == StintObjective::RemainingDistance ? "remaining_distance" : "earliest_arrival";
}

StintObjective parseStintObjective(const std::string &name)
{
    for (StintObjective o : {StintObjective::RemainingDistance, StintObjective::EarliestArrival})
        if (stintObjectiveName(o) == name)
            return o;
    throw Error("unknown stint objective '" + name + "' (remaining_distance, earliest_arrival)");
}

std::size_t StintSettings::stintCount() const
{
    const double n = std::ceil(missionDuration / duration - 1e-9);
    return static_cast<std::size_t>(std::max(1.0, n));
}

void StintSettings::check() const
{
    auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
    if (!positive(duration))
        throw Error("stints.duration: must be positive and finite");
    if (!positive(missionDuration))
        throw Error("stints.mission_duration: must be positive and finite");
    if (missionDuration / duration > 100000.0)
        throw Error("stints.mission_duration: more than 100000 stints of stints.duration");
    if (!(bearingStep > 0.0 && bearingStep <= 180.0))
        throw Error("stints.bearing_step: must be in (0, 180] degrees");
    if (!(radius >= 0.0) || !std::isfinite(radius))
        throw Error("stints.radius: must be >= 0 and finite");
    if (objective == StintObjective::EarliestArrival && !(radius > 0.0))
        throw Error("stints.radius: the earliest_arrival objective needs a radius > 0");
    if (!(step >= 0.0) || !std::isfinite(step) || (step > 0.0 && duration / step > 1e6))
        throw Error("stints.step: must be >= 0 and finite, at most 10^6 steps per stint");
}

} // namespace ompl_glider

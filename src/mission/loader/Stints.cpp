// The `stints` section: constant-bearing stints between surfacings ([IsernObstacles]).
#include "MissionReader.h"

namespace ompl_glider::mission_loader
{
void readStints(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "stints";
    r.checkMap(n, f, {"duration", "mission_duration", "bearing_step", "objective", "radius", "step"});
    StintSpec &s = m.stints;
    s.set = true;
    for (const char *key : {"duration", "mission_duration"})
        if (!n[key])
            r.fail(n, f + "." + key,
                   std::string("missing: the ") +
                       (std::string(key) == "duration" ? "time between two surfacings" : "length of the mission") +
                       " in the mission's time unit");
    s.duration = r.positive(n["duration"], f + ".duration");
    s.missionDuration = r.positive(n["mission_duration"], f + ".mission_duration");
    if (s.missionDuration / s.duration > 100000.0)
        r.fail(n["mission_duration"], f + ".mission_duration",
               "gives more than 100000 stints of stints.duration: use longer stints or a shorter mission");
    if (n["bearing_step"])
    {
        s.bearingStep = r.positive(n["bearing_step"], f + ".bearing_step");
        if (s.bearingStep > 180.0)
            r.fail(n["bearing_step"], f + ".bearing_step",
                   "expected degrees in (0, 180], got " + n["bearing_step"].Scalar());
    }
    if (n["objective"])
        s.objective =
            parseStintObjective(r.oneOf(n["objective"], f + ".objective", {"remaining_distance", "earliest_arrival"}));
    if (n["radius"])
        s.radius = r.nonNegative(n["radius"], f + ".radius");
    if (s.objective == StintObjective::EarliestArrival && !(s.radius > 0.0))
        r.fail(n["radius"] ? n["radius"] : n["objective"], f + ".radius",
               "the earliest_arrival objective needs a goal radius > 0");
    if (n["step"])
    {
        s.step = r.positive(n["step"], f + ".step");
        if (s.duration / s.step > 1e6)
            r.fail(n["step"], f + ".step", "gives more than 10^6 integration steps per stint");
    }
}
} // namespace ompl_glider::mission_loader

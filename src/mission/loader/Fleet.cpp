// The mission's `fleet` section: a list of gliders, each with a name, a start, a goal and optionally its own speed
// and departure time (mission/Fleet.h plans them).
#include <cctype>
#include <set>

#include "MissionReader.h"

namespace ompl_glider::mission_loader
{
namespace
{
/// A glider's name names its folder under the output directory: a plain name, not one of the fleet's own files.
bool folderName(const std::string &name)
{
    if (name.empty() || name.size() > 64 || name[0] == '.' || name == "summary.json" || name == "fleet.csv")
        return false;
    for (const char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
            return false;
    return true;
}
} // namespace

void readFleet(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    if (!n.IsSequence() || n.size() == 0)
        r.fail(n, "fleet", "expected a list of gliders, each {name, start, goal} (speed and departure optional)");
    r.mark(n, "fleet");
    // the fleet's work, estimated before any plan: a folder of files per glider and one plan each (each plan's own
    // work is checked as a single mission's)
    constexpr std::size_t kMaxFleetGliders = 50000;
    if (n.size() > kMaxFleetGliders)
        r.fail(n, "fleet",
               "a fleet of " + std::to_string(n.size()) + " gliders, more than the limit of " +
                   std::to_string(kMaxFleetGliders) +
                   " (a plan and a folder of files each): split it into missions "
                   "of fewer gliders");
    std::set<std::string> names;
    for (std::size_t i = 0; i < n.size(); ++i)
    {
        const YAML::Node &g = n[i];
        const std::string f = "fleet[" + std::to_string(i) + "]";
        r.checkMap(g, f, {"name", "start", "goal", "speed", "departure", "waypoints", "order"});
        FleetGliderSpec glider;
        glider.line = r.line(g);
        for (const char *key : {"name", "start", "goal"})
            if (!g[key])
                r.fail(g, f + "." + key, "missing: every glider of the fleet has a name, a start and a goal");
        glider.name = r.text(g["name"], f + ".name");
        if (!folderName(glider.name))
            r.fail(g["name"], f + ".name",
                   "'" + glider.name +
                       "' is not a folder name (letters, digits, '_', '-', '.'; not starting with "
                       "'.'; at most 64 characters; not summary.json or fleet.csv)");
        if (!names.insert(glider.name).second)
            r.fail(g["name"], f + ".name", "'" + glider.name + "' names another glider of the fleet too");
        readPoint(r, g["start"], f + ".start", glider.start, m);
        readPoint(r, g["goal"], f + ".goal", glider.goal, m);
        if (g["speed"])
            glider.speed = r.positive(g["speed"], f + ".speed");
        if (g["departure"])
            glider.departure = r.time(g["departure"], f + ".departure", m);
        if (g["waypoints"])
            readViaPoints(r, g["waypoints"], f + ".waypoints", glider.waypoints, m);
        if (g["order"])
            glider.order = readVisitOrder(r, g["order"], f + ".order", glider.waypoints.size());
        for (const PointSpec *p : {&glider.start, &glider.goal})
            if (!p->geographic && m.region.set && !m.region.geographic &&
                (p->xy.x < m.region.xy.xMin || p->xy.x > m.region.xy.xMax || p->xy.y < m.region.xy.yMin ||
                 p->xy.y > m.region.xy.yMax))
            {
                const char *key = p == &glider.start ? "start" : "goal";
                r.fail(g[key], f + "." + key, "lies outside the region");
            }
        m.fleet.push_back(std::move(glider));
    }
}
} // namespace ompl_glider::mission_loader

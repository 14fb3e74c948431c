// The mission's `waypoints` list (via points between start and goal) and `order`: read and checked field by field.
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "MissionReader.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Length.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/Time.h"

namespace ompl_glider
{
const char *visitOrderName(VisitOrder o)
{
    return o == VisitOrder::Free ? "free" : "given";
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string viaPointKey(const std::string &name)
{
    std::string key = name;
    for (char &c : key)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return key;
}

bool plainViaPointName(const std::string &name)
{
    if (name.empty() || name.size() > 16 || !std::isalpha(static_cast<unsigned char>(name[0])))
        return false;
    for (const char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
            return false;
    return true;
}

VisitOrder parseVisitOrder(const std::string &name)
{
    static const std::map<std::string, VisitOrder> orders = {{"given", VisitOrder::Given}, {"free", VisitOrder::Free}};
    if (const auto it = orders.find(name); it != orders.end())
        return it->second;
    throw Error("unknown order '" + name + "' (expected given or free)");
}

namespace mission_loader
{

void readViaPoints(const Reader &r, const YAML::Node &n, const std::string &field, std::vector<ViaPointSpec> &out,
                   const MissionSpec &m)
{
    if (n.IsSequence() && n.size() == 0)
        r.fail(n, field, "the list is empty: give at least one via point, or leave '" + field + "' out");
    if (!n.IsSequence())
        r.fail(n, field,
               "expected a list of via points, each {name, lon, lat} or {name, x, y} (radius, arrive, "
               "stay optional)");
    r.mark(n, field);
    constexpr std::size_t kMaxViaPoints = 1000;
    if (n.size() > kMaxViaPoints)
        r.fail(n, field,
               std::to_string(n.size()) + " via points, more than the limit of " + std::to_string(kMaxViaPoints) +
                   " (a planned leg each)");
    std::set<std::string> names{"start", "goal"};
    out.clear();
    for (std::size_t i = 0; i < n.size(); ++i)
    {
        const YAML::Node &w = n[i];
        const std::string f = field + "[" + std::to_string(i) + "]";
        if (!w.IsMap())
            r.fail(w, f, "expected a via point {name, lon, lat} or {name, x, y}");
        ViaPointSpec v;
        v.line = r.line(w);
        readPoint(r, w, f, v.position, m, {"name", "radius", "arrive", "stay"});
        v.name = w["name"] ? r.text(w["name"], f + ".name") : "WP" + std::to_string(i + 1);
        if (!plainViaPointName(v.name))
            r.fail(w["name"], f + ".name",
                   "'" + v.name +
                       "' is not a plain name (a letter, then letters, digits, '_' or '-'; at most 16 "
                       "characters: it is written into the Seaglider targets file)");
        if (const std::string key = viaPointKey(v.name); !names.insert(key).second)
            r.fail(w["name"] ? w["name"] : w, f + ".name",
                   "'" + v.name + "' names " +
                       (key == "start" || key == "goal" ? "the mission's " + key : "another via point") +
                       " too (names are compared without case): give every via point its own name");
        if (w["radius"])
            v.radius = r.setting(w["radius"], f + ".radius", m);
        if (w["stay"])
            v.stay = r.setting(w["stay"], f + ".stay", m);
        if (w["arrive"])
        {
            const YAML::Node &a = w["arrive"];
            const std::string g = f + ".arrive";
            r.checkMap(a, g, {"begin", "end"});
            if (!a["begin"] && !a["end"])
                r.fail(a, g, "give begin, end or both (the earliest and the latest accepted arrival)");
            v.arrive.set = true;
            // an end not given is open (infinite): any arrival after the begin, or before the end, is accepted
            v.arrive.begin = a["begin"] ? r.time(a["begin"], g + ".begin", m) : -kInfinity;
            v.arrive.end = a["end"] ? r.time(a["end"], g + ".end", m) : kInfinity;
            if (!(v.arrive.end >= v.arrive.begin))
                r.fail(a["end"], g + ".end", "the window ends before it begins");
            const double departure = m.departure.window ? m.departure.begin : m.departure.time;
            if (a["end"] && v.arrive.end < departure)
                r.fail(a["end"], g + ".end", "the window ends before the departure: no plan can arrive in it");
        }
        if (!v.position.geographic && m.region.set && !m.region.geographic &&
            (v.position.xy.x < m.region.xy.xMin || v.position.xy.x > m.region.xy.xMax ||
             v.position.xy.y < m.region.xy.yMin || v.position.xy.y > m.region.xy.yMax))
            r.fail(w, f, "lies outside the region");
        out.push_back(std::move(v));
    }
}

VisitOrder readVisitOrder(const Reader &r, const YAML::Node &n, const std::string &field, std::size_t count)
{
    const VisitOrder o = r.oneOf(n, field, {"given", "free"}) == "free" ? VisitOrder::Free : VisitOrder::Given;
    if (o == VisitOrder::Free && count > kMaxFreeOrderViaPoints)
        r.fail(n, field,
               "free order over " + std::to_string(count) + " via points: at most " +
                   std::to_string(kMaxFreeOrderViaPoints) +
                   " (the search is exponential in their number); give the order, or split the mission");
    return o;
}
} // namespace mission_loader
} // namespace ompl_glider

// The `reachability` section: the probability of reach over the ensemble's members (output format "reachability").
#include <algorithm>
#include <cmath>

#include "MissionReader.h"
#include "../../io/NumberText.h"
#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider::mission_loader
{
namespace
{
/// A list of probabilities, each in (0, 1), ascending and without repeats once read.
std::vector<double> probabilities(const Reader &r, const YAML::Node &n, const std::string &field)
{
    if (!n.IsSequence() || n.size() == 0)
        r.fail(n, field, "expected a non-empty list of numbers in (0, 1), such as [0.5, 0.9]");
    std::vector<double> out;
    for (std::size_t i = 0; i < n.size(); ++i)
    {
        const std::string f = field + "[" + std::to_string(i) + "]";
        const double v = r.number(n[i], f);
        if (!(v > 0.0 && v < 1.0))
            r.fail(n[i], f, "expected a number in (0, 1) (exclusive), got " + text::number(v));
        out.push_back(v);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}
} // namespace

void readReachability(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "reachability";
    r.checkMap(n, f, {"horizon", "interval", "levels", "quantiles", "resolution", "member_arrival"});
    ReachabilitySpec &s = m.reachability;
    if (n["horizon"])
        s.horizon = r.setting(n["horizon"], f + ".horizon", m);
    if (n["interval"])
        s.interval = r.setting(n["interval"], f + ".interval", m);
    if (n["resolution"])
        s.resolution = r.setting(n["resolution"], f + ".resolution", m);
    if (n["levels"])
        s.levels = probabilities(r, n["levels"], f + ".levels");
    if (n["quantiles"])
        s.quantiles = probabilities(r, n["quantiles"], f + ".quantiles");
    if (n["member_arrival"])
        s.memberArrival = r.boolean(n["member_arrival"], f + ".member_arrival");
}
} // namespace ompl_glider::mission_loader

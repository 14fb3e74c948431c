// An ensemble of an analytic flow drawn from one set of parameters (mission/EnsembleDraw.h): the members drawn, and
// the mission file's short form `current: {type, parameters, members, spread, seed}` read and expanded into them.
#include "ompl_glider/mission/EnsembleDraw.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "MissionReader.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"

namespace ompl_glider
{
std::vector<CurrentSpec> drawEnsembleMembers(const CurrentSpec &control, unsigned count,
                                             const CurrentSpec::EnsembleDraw &draw)
{
    const CurrentFieldKind *kind = findCurrentFieldKind(control.type);
    if (!kind || kind->gridded())
        throw Error("an ensemble is drawn from the parameters of an analytic flow, not of '" + control.type + "'");
    if (count < 2)
        throw Error("an ensemble has 2 or more members, got " + std::to_string(count));
    CurrentSpec base = control;
    base.members.clear();
    base.drawn.reset();
    for (const auto &[name, s] : draw.spread)
    {
        if (!hasParameter(*kind, name))
            throw Error("'" + name + "' is not a parameter of " + control.type + " (" + parameterNameList(*kind) + ")");
        if (!(s >= 0.0 && s < 1.0))
            throw Error("the spread of '" + name + "' must lie in [0, 1), got " + std::to_string(s));
        if (!base.parameters.count(name)) // perturbed about the value the flow would take
            for (const auto &[key, value] : kind->parameters)
                if (key == name)
                    base.parameters[name] = value;
    }
    std::vector<CurrentSpec> members{base}; // the control run, as forecast centres issue it
    std::mt19937 rng(draw.seed);
    for (unsigned i = 1; i < count; ++i)
    {
        CurrentSpec member = base;
        for (const auto &[name, s] : draw.spread)
        {
            // mt19937's outputs are fixed by the standard; the mapping to (-1, 1) is ours, so a seed draws the same
            // members everywhere
            const double u = -1.0 + 2.0 * (static_cast<double>(rng()) + 0.5) / 4294967296.0;
            member.parameters[name] = base.parameters[name] * (1.0 + s * u);
        }
        members.push_back(member);
    }
    return members;
}

std::string ensembleDescription(const CurrentSpec &c)
{
    if (c.members.empty())
        return "";
    std::string s = c.type + " ensemble of " + std::to_string(c.members.size()) + " members (";
    if (!c.drawn)
        return s + "listed)";
    s += "control + " + std::to_string(c.members.size() - 1) + " drawn, spread";
    bool first = true;
    for (const auto &[name, spread] : c.drawn->spread)
    {
        char pct[32];
        std::snprintf(pct, sizeof pct, "%g", 100.0 * spread);
        s += (first ? " " : ", ") + name + " " + pct + " %";
        first = false;
    }
    return s + ", seed " + std::to_string(c.drawn->seed) + ")";
}
} // namespace ompl_glider

namespace ompl_glider::mission_loader
{
bool isDrawnEnsemble(const YAML::Node &n)
{
    return n.IsMap() && (n["members"] || n["spread"] || n["seed"]);
}

void readDrawnEnsemble(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    // the key a refusal of the whole form names: the first of the form's keys given
    std::string key = "members";
    for (const char *k : {"members", "spread", "seed"})
        if (n[k])
        {
            key = k;
            break;
        }
    if (n["ensemble"])
        r.fail(n[key], "current." + key,
               "an ensemble is either listed (ensemble: [...]) or drawn from one source (members: N, spread: {...}), "
               "not both");
    if (!n["members"])
        r.fail(n[key], "current." + key, "only with members: N (an ensemble of N members drawn from these parameters)");
    const YAML::Node &type = n["type"];
    const CurrentFieldKind *named = type && type.IsScalar() ? findCurrentFieldKind(type.Scalar()) : nullptr;
    if (named && named->gridded())
    {
        const std::string at = n["spread"] ? "spread" : "members";
        r.fail(n[at], "current." + at,
               "an ensemble is drawn from the parameters of an analytic flow; a forecast's members are its files "
               "(current: {ensemble: [{type: " +
                   type.Scalar() + ", file: ...}, ...]})");
    }
    readCurrentSource(r, n, "current", m.current, {"members", "spread", "seed"});
    const unsigned count = static_cast<unsigned>(r.integer(n["members"], "current.members", 2, 1000));
    const YAML::Node &spread = n["spread"];
    if (!spread)
        r.fail(n["members"], "current.spread",
               "missing: the relative spread of each parameter drawn (spread: {name: 0.25, ...}); without one every "
               "member is the control run");
    const CurrentFieldKind &kind = *findCurrentFieldKind(m.current.type);
    std::set<std::string> names;
    for (const auto &[name, value] : kind.parameters)
        names.insert(name);
    r.checkMap(spread, "current.spread", names);
    if (spread.size() == 0)
        r.fail(spread, "current.spread", "empty: give the relative spread of each parameter drawn (name: 0.25)");
    CurrentSpec::EnsembleDraw draw;
    for (auto it = spread.begin(); it != spread.end(); ++it)
    {
        const std::string name = it->first.Scalar(), field = "current.spread." + name;
        const double s = r.finite(it->second, field);
        if (!(s >= 0.0 && s < 1.0))
            r.fail(it->second, field,
                   "expected a relative spread in [0, 1) (0.25: each member's value within 25 % of the given one)");
        draw.spread[name] = s;
    }
    if (n["seed"])
        draw.seed = static_cast<unsigned>(r.integer(n["seed"], "current.seed", 0, 4294967295L));
    std::vector<CurrentSpec> members;
    try
    {
        members = drawEnsembleMembers(m.current, count, draw);
    }
    catch (const Error &e)
    {
        r.fail(n, "current", e.what());
    }
    for (CurrentSpec &c : members)
        c.mark = {r.file(), r.line(n)};
    // as a listed ensemble: the first member is also the current's own spec (names, messages)
    m.current = members.front();
    m.current.members = members;
    m.current.drawn = draw;
}
} // namespace ompl_glider::mission_loader

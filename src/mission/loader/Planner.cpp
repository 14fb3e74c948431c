// The `planner` section: a planner of the registry by name, its lattice, limits and parameters.
#include "MissionReader.h"
#include "ompl_glider/registry/PlannerRegistry.h"

namespace ompl_glider::mission_loader
{
void readPlanner(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "planner";
    r.checkMap(n, f,
               {"name", "grid_size", "sectors", "smoothing", "refinement", "time_limit", "horizon", "goal_tolerance",
                "parameters", "objective", "quantile", "global_check"});
    PlannerSpec &p = m.planner;
    if (n["objective"])
    {
        p.objective =
            parseEnsembleObjective(r.oneOf(n["objective"], f + ".objective", {"expected", "worst", "quantile"}));
        if (m.current.members.empty())
            r.fail(n["objective"], f + ".objective",
                   "an objective over members needs an ensemble current (current: {ensemble: [...]})");
    }
    if (n["quantile"])
    {
        p.quantile = r.number(n["quantile"], f + ".quantile");
        if (!(p.quantile > 0.0 && p.quantile <= 1.0))
            r.fail(n["quantile"], f + ".quantile", "expected a number in (0, 1]");
        if (p.objective != EnsembleObjective::Quantile)
            r.fail(n["quantile"], f + ".quantile", "only with objective: quantile");
    }
    if (n["name"])
    {
        const std::string name = r.text(n["name"], f + ".name");
        const PlannerEntry *entry = findPlanner(name);
        if (!entry)
            r.fail(n["name"], f + ".name",
                   "unknown planner '" + name + "' (expected one of " + plannerNameList() + ")");
        p.name = entry->name;
    }
    if (n["grid_size"])
        p.gridSize = r.setting(n["grid_size"], f + ".grid_size", m);
    if (n["sectors"])
        p.sectors = static_cast<int>(r.setting(n["sectors"], f + ".sectors", m));
    if (n["smoothing"])
        p.smoothing = r.boolean(n["smoothing"], f + ".smoothing");
    if (n["refinement"])
        p.refinement = r.boolean(n["refinement"], f + ".refinement");
    if (n["global_check"])
        p.globalCheck = r.boolean(n["global_check"], f + ".global_check");
    if (n["time_limit"])
        p.timeLimit = r.setting(n["time_limit"], f + ".time_limit", m);
    if (n["horizon"])
        p.horizon = r.setting(n["horizon"], f + ".horizon", m);
    if (n["goal_tolerance"])
        p.goalTolerance = r.setting(n["goal_tolerance"], f + ".goal_tolerance", m);
    if (n["parameters"])
    {
        // Names and values are checked against the planner's declared parameters before planning (Planning.cpp).
        const YAML::Node &params = n["parameters"];
        if (!params.IsMap())
            r.fail(params, f + ".parameters", "expected a map of planner parameter names to values");
        for (auto it = params.begin(); it != params.end(); ++it)
        {
            const std::string key = it->first.Scalar();
            const std::string field = f + ".parameters." + key;
            if (!it->second.IsScalar())
                r.fail(it->second, field, "expected a value (number or boolean)");
            if (p.parameters.count(key))
                r.fail(it->first, field, "given twice");
            p.parameters[key] = it->second.Scalar();
            p.parameterMarks[key] = {r.file(), r.line(it->first)};
        }
    }
}
} // namespace ompl_glider::mission_loader

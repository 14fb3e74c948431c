// The `execution` section: the plan flown in another ocean, per strategy, once or in a batch.
#include <algorithm>
#include <set>

#include "MissionReader.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/execution/Execution.h"

namespace ompl_glider
{
const char *acrossRunsName(AcrossRuns a)
{
    return a == AcrossRuns::Reset ? "reset" : "carry";
}

AcrossRuns parseAcrossRuns(const std::string &name)
{
    for (AcrossRuns a : {AcrossRuns::Carry, AcrossRuns::Reset})
        if (name == acrossRunsName(a))
            return a;
    throw Error("unknown choice '" + name + "' (expected carry or reset)");
}
} // namespace ompl_glider

namespace ompl_glider::mission_loader
{
void readExecution(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "execution";
    r.checkMap(n, f,
               {"truth", "surfacing_interval", "strategies", "radius", "replan_every", "duration", "batch", "dac_noise",
                "across_runs"});
    ExecutionSpec &e = m.execution;
    e.enabled = true;
    e.mark = {r.file(), r.line(n)};
    if (n["truth"])
    {
        const YAML::Node &t = n["truth"];
        if (t.IsScalar() && t.Scalar() == kTruthIsForecast)
            e.truth.reset();
        else
        {
            if (!t.IsMap())
                r.fail(t, f + ".truth", "expected 'forecast' or a current source (type: ..., as in 'current')");
            CurrentSpec c;
            readCurrentSource(r, t, f + ".truth", c);
            c.mark = {r.file(), r.line(t)};
            const bool gridded = c.isForecast(), forecastGridded = m.current.isForecast();
            if (gridded != forecastGridded)
                r.fail(t["type"], f + ".truth.type",
                       forecastGridded ? "the forecast is a NetCDF file: the truth must be one too (same frame)"
                                       : "the forecast is an analytic flow: the truth must be one too (same units)");
            e.truth = c;
        }
    }
    if (n["surfacing_interval"])
        e.surfacingInterval = r.setting(n["surfacing_interval"], f + ".surfacing_interval", m);
    if (n["duration"])
        e.duration = duration(r, n["duration"], f + ".duration", m);
    if (n["strategies"])
    {
        const YAML::Node &l = n["strategies"];
        std::set<std::string> names;
        for (ControlStrategy s : controlStrategies())
            names.insert(controlStrategyName(s));
        if (!l.IsSequence() || l.size() == 0)
            r.fail(l, f + ".strategies", "expected a list such as [current_sensitive, current_blind, greedy, replan]");
        e.strategies.clear();
        for (std::size_t i = 0; i < l.size(); ++i)
        {
            const std::string field = f + ".strategies[" + std::to_string(i) + "]";
            const std::string s = r.oneOf(l[i], field, names);
            if (std::find(e.strategies.begin(), e.strategies.end(), s) != e.strategies.end())
                r.fail(l[i], field, "'" + s + "' is listed twice");
            e.strategies.push_back(s);
        }
    }
    if (n["radius"])
        e.radius = r.setting(n["radius"], f + ".radius", m);
    if (n["replan_every"])
        e.replanEvery = static_cast<unsigned>(r.integer(n["replan_every"], f + ".replan_every", 1, 100000));
    if (n["dac_noise"])
    {
        e.dacNoise = r.nonNegative(n["dac_noise"], f + ".dac_noise");
        if (std::find(e.strategies.begin(), e.strategies.end(), "dac") == e.strategies.end() &&
            std::find(e.strategies.begin(), e.strategies.end(), "replan_observed") == e.strategies.end())
            r.fail(n["dac_noise"], f + ".dac_noise",
                   "no strategy measures a DAC, so the noise on it would change nothing: add dac or replan_observed "
                   "to execution.strategies, or leave dac_noise out");
    }
    if (n["across_runs"])
    {
        if (m.current.runs.empty())
            r.fail(n["across_runs"], f + ".across_runs",
                   "given without forecast runs (current.runs): there is no new run to carry the learning across");
        e.acrossRuns = parseAcrossRuns(r.oneOf(n["across_runs"], f + ".across_runs", {"carry", "reset"}));
    }
    if (n["batch"])
    {
        const YAML::Node &b = n["batch"];
        r.checkMap(b, f + ".batch", {"pairs", "seed", "min_distance", "threads"});
        if (b["pairs"])
            e.pairs = static_cast<unsigned>(r.setting(b["pairs"], f + ".batch.pairs", m));
        if (b["seed"])
            e.seed = static_cast<unsigned>(r.setting(b["seed"], f + ".batch.seed", m));
        if (b["min_distance"])
            e.minDistance = r.positive(b["min_distance"], f + ".batch.min_distance");
        readThreads(r, b, f + ".batch", e.threads);
    }
}
} // namespace ompl_glider::mission_loader

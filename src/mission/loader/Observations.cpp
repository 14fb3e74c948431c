// The `observations` section: the glider's files (IOOS profile files, Slocum dba or binary files, a CSV or an ERDDAP
// URL) and the
// correction's parameters ([BrethertonOI]; their ranges: mission/SettingRanges.h).
#include <optional>

#include "MissionReader.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider::mission_loader
{
void readObservations(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "observations";
    ObservationsSpec o;
    o.mark = {r.file(), r.line(n)};
    std::optional<YAML::Node> file; // none: only the correction's parameters
    if (!n.IsMap())
        file = n;
    if (n.IsMap())
    {
        r.checkMap(n, f, {"file", "cache", "length_scale", "time_scale", "error_ratio", "learn"});
        if (!n["file"] && !n["length_scale"] && !n["time_scale"] && !n["error_ratio"] && !n["learn"])
            r.fail(n, f + ".file",
                   "missing: the glider's files (IOOS profile files or Slocum dba or binary files: a file, folder or "
                   "pattern; a "
                   "CSV; or an ERDDAP URL), or the "
                   "correction's parameters alone (for an execution's replan_observed)");
        if (n["file"])
            file = n["file"];
        if (n["cache"]) // a Slocum's cache files (the sensor lists of its binary files), besides theirs and cache/
            o.cache = joinPath(r.dir(), r.text(n["cache"], f + ".cache"));
        if (n["length_scale"])
            o.lengthScale = r.setting(n["length_scale"], f + ".length_scale", m);
        if (n["time_scale"])
            o.timeScale = r.setting(n["time_scale"], f + ".time_scale", m);
        if (n["error_ratio"])
            o.errorRatio = r.setting(n["error_ratio"], f + ".error_ratio", m);
        if (n["learn"])
            o.learn = r.boolean(n["learn"], f + ".learn");
    }
    if (file)
    {
        const std::string given = r.text(*file, n.IsMap() ? f + ".file" : f);
        o.path = isRemoteSource(given) ? given : joinPath(r.dir(), given); // a URL, or a file, folder or pattern
    }
    m.observations = std::move(o);
}
} // namespace ompl_glider::mission_loader

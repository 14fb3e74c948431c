// The `safety` section: the keep-off distance from land, the depth limit and the bathymetry it reads, and whether a
// start or goal on land moves to the nearest water (ranges: mission/SettingRanges.h).
#include "MissionReader.h"

namespace ompl_glider::mission_loader
{
void readSafety(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "safety";
    r.checkMap(n, f, {"keep_off", "bathymetry", "bathymetry_variable", "min_depth", "snap_to_water"});
    if (n["keep_off"])
    {
        m.safety.keepOff = r.setting(n["keep_off"], f + ".keep_off", m);
        m.marks[f + ".keep_off"] = {r.file(), r.line(n["keep_off"])};
    }
    if (n["min_depth"])
    {
        m.safety.minDepth = r.setting(n["min_depth"], f + ".min_depth", m);
        m.marks[f + ".min_depth"] = {r.file(), r.line(n["min_depth"])};
    }
    if (n["bathymetry"])
    {
        m.safety.bathymetry = joinPath(r.dir(), r.text(n["bathymetry"], f + ".bathymetry"));
        m.marks[f + ".bathymetry"] = {r.file(), r.line(n["bathymetry"])};
        if (!fileExists(m.safety.bathymetry))
            r.fail(n["bathymetry"], f + ".bathymetry", "cannot open '" + m.safety.bathymetry + "'");
    }
    if (n["bathymetry_variable"])
        m.safety.bathymetryVariable = r.text(n["bathymetry_variable"], f + ".bathymetry_variable");
    if (n["snap_to_water"])
    {
        m.safety.snapToWater = r.boolean(n["snap_to_water"], f + ".snap_to_water");
        m.marks[f + ".snap_to_water"] = {r.file(), r.line(n["snap_to_water"])};
    }
    if (n["min_depth"] && m.safety.bathymetry.empty() && !m.current.isForecast())
        r.fail(n["min_depth"], f + ".min_depth",
               "needs safety.bathymetry (a NetCDF file of seafloor depth or elevation)");
    if (n["bathymetry_variable"] && !n["bathymetry"] && !m.current.isForecast())
        r.fail(n["bathymetry_variable"], f + ".bathymetry_variable", "needs safety.bathymetry");
}
} // namespace ompl_glider::mission_loader

// The `dive_profile` section: the glider's saw-tooth dives, the depth range it flies and the seafloor.
#include "MissionReader.h"
#include "ompl_glider/Exception.h"

namespace ompl_glider::mission_loader
{
void readDive(const Reader &r, const YAML::Node &n, MissionSpec &m)
{
    const std::string f = "dive_profile";
    r.checkMap(n, f,
               {"z_min", "z_max", "climb_to_max", "min_range", "climb_to_levels", "dive_to_levels", "step", "selection",
                "max_time_factor", "max_time", "clearance", "threads", "bathymetry"});
    DiveSpec &d = m.dive;
    d.enabled = true;
    DiveProfileParams &p = d.params;
    for (const char *key : {"z_min", "z_max"})
        if (!n[key])
            r.fail(n, f + "." + key, "missing");
    p.zMin = r.nonNegative(n["z_min"], f + ".z_min");
    p.zMax = r.positive(n["z_max"], f + ".z_max");
    p.climbToMax = n["climb_to_max"] ? r.nonNegative(n["climb_to_max"], f + ".climb_to_max") : p.zMin;
    p.minRange = n["min_range"] ? r.nonNegative(n["min_range"], f + ".min_range") : 0.0;
    if (n["climb_to_levels"])
        p.climbToLevels = static_cast<int>(r.integer(n["climb_to_levels"], f + ".climb_to_levels", 1, 100));
    if (n["dive_to_levels"])
        p.diveToLevels = static_cast<int>(r.integer(n["dive_to_levels"], f + ".dive_to_levels", 1, 100));
    if (n["step"])
        p.step = r.positive(n["step"], f + ".step");
    if (n["selection"])
        p.selection = diveProfileSelectionFromString(
            r.oneOf(n["selection"], f + ".selection", {"fastest", "deepest_under_limit"}));
    if (n["max_time_factor"])
        p.maxTimeFactor = r.finite(n["max_time_factor"], f + ".max_time_factor");
    if (n["max_time"])
        p.maxTime = r.positive(n["max_time"], f + ".max_time");
    if (n["clearance"])
        p.clearance = r.nonNegative(n["clearance"], f + ".clearance");
    readThreads(r, n, f, d.threads);
    try
    {
        makeDiveProfiles(p);
    }
    catch (const Error &e)
    {
        r.fail(n, f, e.what());
    }
    if (n["bathymetry"])
    {
        const YAML::Node &b = n["bathymetry"];
        const std::string g = f + ".bathymetry";
        r.checkMap(b, g, {"type", "depth", "file", "variable"});
        if (!b["type"])
            r.fail(b, g + ".type", "missing (constant or netcdf)");
        d.bathymetry = r.oneOf(b["type"], g + ".type", {"constant", "netcdf"}) == "constant"
                           ? DiveSpec::Bathymetry::Constant
                           : DiveSpec::Bathymetry::File;
        if (d.bathymetry == DiveSpec::Bathymetry::Constant)
        {
            if (!b["depth"])
                r.fail(b, g + ".depth", "missing: the seafloor depth");
            d.bathymetryDepth = r.positive(b["depth"], g + ".depth");
        }
        else
        {
            if (!b["file"])
                r.fail(b, g + ".file", "missing: the NetCDF file with the seafloor depth");
            d.bathymetryFile = joinPath(r.dir(), r.text(b["file"], g + ".file"));
            if (!fileExists(d.bathymetryFile))
                r.fail(b["file"], g + ".file", "cannot open '" + d.bathymetryFile + "'");
            if (b["variable"])
                d.bathymetryVariable = r.text(b["variable"], g + ".variable");
        }
    }
}
} // namespace ompl_glider::mission_loader

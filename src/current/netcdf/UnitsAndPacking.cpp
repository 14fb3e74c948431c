// Units (velocities to m/s, Cartesian axes to metres) and packing (scale_factor / add_offset, fill values and
// valid ranges compared on the packed value).
#include <cctype>
#include <cmath>

#include "NetCdfInternal.h"

namespace ompl_glider
{
namespace netcdf_detail
{
std::optional<double> velocityScale(const std::string &units)
{
    std::string s;
    for (char c : lower(units))
        if (!std::isspace(static_cast<unsigned char>(c)))
            s += c;
    if (inList(s, {"m/s", "ms-1", "m.s-1", "ms^-1", "m.s^-1", "m*s-1", "m/sec", "meter/second", "meters/second",
                   "metre/second", "metres/second", "meterspersecond", "metrespersecond", "meter/sec", "meters/sec",
                   "mps"}))
        return 1.0;
    if (inList(s, {"cm/s", "cms-1", "cm.s-1", "cms^-1", "cm.s^-1", "cm*s-1", "cm/sec", "centimeter/second",
                   "centimeters/second", "centimetre/second", "centimetres/second", "centimeterspersecond"}))
        return 0.01;
    if (inList(s, {"knots", "knot", "kt", "kts", "kn"}))
        return 1852.0 / 3600.0;
    return std::nullopt;
}

double velocityScaleOf(const NcFile &f, const Layout &l, const NetCdfCurrentOptions &opt)
{
    const std::string uu = opt.velocityUnits.empty() ? unitsOf(f, l.uVar) : opt.velocityUnits;
    const std::string vu = opt.velocityUnits.empty() ? unitsOf(f, l.vVar) : opt.velocityUnits;
    auto su = velocityScale(uu), sv = velocityScale(vu);
    const bool dimensionless = !l.geographic && (uu.empty() || uu == "1") && (vu.empty() || vu == "1");
    if (dimensionless)
        return 1.0;
    if (!su)
        throw f.error("variable '" + l.uName + "': units '" + uu +
                      "' not understood; expected m/s (m s-1), cm/s (cm s-1) or knots");
    if (!sv)
        throw f.error("variable '" + l.vName + "': units '" + vu +
                      "' not understood; expected m/s (m s-1), cm/s (cm s-1) or knots");
    if (*su != *sv)
        throw f.error("variables '" + l.uName + "' and '" + l.vName + "' have different units");
    return *su;
}

double axisScale(const NcFile &f, int var)
{
    const std::string u = lower(unitsOf(f, var));
    if (u == "km" || u == "kilometer" || u == "kilometers" || u == "kilometre" || u == "kilometres")
        return 1000.0;
    return 1.0;
}

bool Packing::isFill(double raw) const
{
    if (std::isnan(raw))
        return true;
    for (double f : fills)
        if (raw == f)
            return true;
    return raw < validMin || raw > validMax;
}

namespace
{
/// The netCDF default fill value of a variable's type (used when _FillValue is absent).
std::optional<double> defaultFill(nc_type type)
{
    switch (type)
    {
        case NC_SHORT:
            return NC_FILL_SHORT;
        case NC_INT:
            return NC_FILL_INT;
        case NC_FLOAT:
            return static_cast<double>(NC_FILL_FLOAT);
        case NC_DOUBLE:
            return NC_FILL_DOUBLE;
        default:
            return std::nullopt;
    }
}
}  // namespace

Packing packingOf(const NcFile &f, int var)
{
    Packing p;
    const std::string name = f.varName(var);
    const auto sf = f.attDoubles(var, "scale_factor"), ao = f.attDoubles(var, "add_offset");
    if (!sf.empty())
        p.scale = sf[0];
    if (!ao.empty())
        p.offset = ao[0];
    if (!std::isfinite(p.scale) || p.scale == 0.0 || !std::isfinite(p.offset))
        throw f.error("variable '" + name + "': scale_factor/add_offset must be finite and scale_factor non-zero");
    const auto fv = f.attDoubles(var, "_FillValue");
    if (!fv.empty())
        p.fills.push_back(fv[0]);
    else if (auto d = defaultFill(f.varType(var)))
        p.fills.push_back(*d);
    for (double m : f.attDoubles(var, "missing_value"))
        p.fills.push_back(m);
    const auto vr = f.attDoubles(var, "valid_range");
    if (vr.size() >= 2)
    {
        p.validMin = vr[0];
        p.validMax = vr[1];
    }
    const auto vmin = f.attDoubles(var, "valid_min"), vmax = f.attDoubles(var, "valid_max");
    if (!vmin.empty())
        p.validMin = vmin[0];
    if (!vmax.empty())
        p.validMax = vmax[0];
    return p;
}
}  // namespace netcdf_detail
}  // namespace ompl_glider

// Units (velocities to m/s, Cartesian axes to metres, both with UDUNITS-2: UnitConversion.h) and packing (scale_factor
// / add_offset, fill values and valid ranges compared on the packed value).
#include <cctype>
#include <algorithm>
#include <cmath>
#include <vector>

#include "GriddedInternal.h"
#include "../../io/NumberText.h"
#include "ompl_glider/io/UnitConversion.h"

namespace ompl_glider
{
namespace gridded_detail
{
LinearConversion velocityConversionOf(const GriddedDataset &f, const Layout &l, const GriddedCurrentOptions &opt)
{
    const bool given = !opt.velocityUnits.empty();
    const std::string uu = given ? opt.velocityUnits : unitsOf(f, l.uVar);
    const std::string vu = given ? opt.velocityUnits : unitsOf(f, l.vVar);
    const auto noUnits = [](const std::string &u) { return trim(u).empty() || trim(u) == "1"; };
    if (!l.geographic && noUnits(uu) && noUnits(vu))
        return {}; // dimensionless velocities of a Cartesian file (the analytic flows sampled to a grid)
    const auto conversion = [&](const std::string &units, const std::string &var) {
        if (!given && trim(units).empty())
            throw f.error("variable '" + var +
                          "' has no units attribute; expected a velocity (m/s, cm/s, knots): "
                          "give the units with GriddedCurrentOptions::velocityUnits");
        try
        {
            return velocityToMetresPerSecond(units);
        }
        catch (const Error &e)
        {
            if (given)
                throw f.error("GriddedCurrentOptions::velocityUnits (for variables '" + l.uName + "' and '" + l.vName +
                              "'): " + e.what());
            throw f.error("variable '" + var + "': " + e.what() +
                          "; give the right units with GriddedCurrentOptions::velocityUnits");
        }
    };
    const LinearConversion cu = conversion(uu, l.uName), cv = conversion(vu, l.vName);
    if (cu.factor != cv.factor || cu.offset != cv.offset)
        throw f.error("variables '" + l.uName + "' and '" + l.vName + "' have different units ('" + uu + "' and '" +
                      vu + "')");
    return cu;
}

namespace
{
/// The smallest magnitude of a fill value models write (-999): a node this fast is a fill value not declared.
constexpr double kFillSize = 999.0;
/// A fast node is continuous with its neighbours when one of them is at least this fraction of its speed.
constexpr double kContinuity = 0.1;
/// Fast nodes are few when at most this fraction of a record's water nodes (else the units are off across the field).
constexpr double kFewFraction = 0.01;

/// The fast nodes of one record and layer-stack that read as a flow's (beside a vortex's core, say), not garbage:
/// finite, below a fill value's size, each with a neighbour (of the 8 around it, same layer and record, in water)
/// at least a tenth as fast, and at most 1 % of the record's water nodes (at least 8). Empty @p fast: nothing to say.
bool fastNodesAreFlow(const GriddedData &g, std::size_t first, std::size_t perTime,
                      const std::vector<std::size_t> &fast)
{
    const std::size_t nh = g.nx * g.ny;
    std::size_t waterNodes = 0;
    for (std::size_t n = 0; n < perTime; ++n)
        waterNodes += g.water.empty() || g.water[n];
    if (static_cast<double>(fast.size()) > std::max(8.0, kFewFraction * static_cast<double>(waterNodes)))
        return false;
    const auto speed = [&](std::size_t idx) { return std::hypot(double(g.u[idx]), double(g.v[idx])); };
    for (const std::size_t idx : fast)
    {
        const double s = speed(idx);
        if (!std::isfinite(s) || s >= kFillSize)
            return false;
        const std::size_t n = idx - first, layer = n / nh, q = n % nh, j = q / g.nx, i = q % g.nx;
        bool continuous = false;
        for (int dj = -1; dj <= 1 && !continuous; ++dj)
            for (int di = -1; di <= 1 && !continuous; ++di)
            {
                const long ii = long(i) + di, jj = long(j) + dj;
                if ((di == 0 && dj == 0) || ii < 0 || jj < 0 || ii >= long(g.nx) || jj >= long(g.ny))
                    continue;
                const std::size_t m = layer * nh + std::size_t(jj) * g.nx + std::size_t(ii);
                continuous = (g.water.empty() || g.water[m]) && speed(first + m) >= kContinuity * s;
            }
        if (!continuous)
            return false;
    }
    return true;
}
} // namespace

void checkVelocityMagnitudes(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h,
                             const AxisSelection &t, const GriddedCurrentOptions &opt, const GriddedData &g)
{
    const auto noUnits = [](const std::string &u) { return trim(u).empty() || trim(u) == "1"; };
    const bool physical =
        !opt.velocityUnits.empty() || l.geographic || !noUnits(unitsOf(f, l.uVar)) || !noUnits(unitsOf(f, l.vVar));
    const bool raised = opt.maxSpeed > 0.0 && std::isfinite(opt.maxSpeed);
    const double limit = raised ? opt.maxSpeed : physical ? 300.0 : 1e6;
    const std::size_t nh = g.nx * g.ny, perTime = g.water.empty() ? nh * g.depth.size() : g.water.size();
    if (nh == 0 || perTime == 0)
        return;
    for (std::size_t first = 0; first + perTime <= g.u.size(); first += perTime)
    {
        std::vector<std::size_t> fast;
        for (std::size_t n = 0; n < perTime; ++n)
        {
            const std::size_t idx = first + n;
            if ((g.water.empty() || g.water[n]) && !(std::abs(g.u[idx]) <= limit && std::abs(g.v[idx]) <= limit))
                fast.push_back(idx);
        }
        // With the bound as given, a few fast nodes continuous with the flow around them are the flow's (a node
        // beside a vortex's core); fill values' sizes, lone spikes and a whole field off by orders are refused.
        if (fast.empty() || (!raised && physical && fastNodesAreFlow(g, first, perTime, fast)))
            continue;
        const std::size_t idx = fast.front();
        const std::size_t n = idx % perTime;
        const bool badU = !(std::abs(g.u[idx]) <= limit);
        const std::size_t it = idx / perTime, q = n % nh, j = q / g.nx, i = q % g.nx;
        std::string at;
        if (q < h.nodeLon.size() && q < h.nodeLat.size())
            at = text::number(h.nodeLon[q]) + (l.geographic ? ", lat " : ", y ") + text::number(h.nodeLat[q]);
        else if (i < h.lon1D.size() && j < h.lat1D.size())
            at = text::number(h.lon1D[i]) + (l.geographic ? ", lat " : ", y ") + text::number(h.lat1D[j]);
        if (!at.empty())
            at = (l.geographic ? ", lon " : ", x ") + at;
        const std::string name = badU ? l.uName : l.vName;
        const double value = badU ? g.u[idx] : g.v[idx];
        std::string record;
        if (l.dimT >= 0 && it < t.idx.size())
            record = ", record " + std::to_string(t.idx[it]) + " of '" + f.dimName(l.dims[std::size_t(l.dimT)]) + "'";
        const std::string count =
            fast.size() > 1 ? " (" + std::to_string(fast.size()) + " such nodes in this record)" : "";
        throw f.error("variable '" + name + "' holds " + text::number(value, 7) + (physical ? " m/s" : "") +
                      " at (j, i) = (" + std::to_string(j < h.yIdx.size() ? h.yIdx[j] : j) + ", " +
                      std::to_string(i < h.xIdx.size() ? h.xIdx[i] : i) + ")" + at + record + count + ": faster than " +
                      (raised ? "the bound given" : "any current or wind") + " (more than " + text::number(limit) +
                      (physical ? " m/s" : "") + "), and not a fill value (_FillValue, " +
                      "missing_value, valid_range): a fill value not declared, or wrong units or scale_factor? If " +
                      "the speeds are real, raise the bound with GriddedCurrentOptions::maxSpeed");
    }
}

LinearConversion axisConversion(const GriddedDataset &f, int var)
{
    const std::string units = trim(unitsOf(f, var));
    // No units, UDUNITS-2's dimensionless ones ("1", "count", angles such as degrees_east, read as x/y in
    // CoordinateMode::Cartesian), and a few words UDUNITS-2 does not know that say the same: the values as they are.
    if (units.empty() ||
        inList(lower(units), {"none", "nondimensional", "dimensionless", "-", "index", "grid_index"}) ||
        isDimensionless(units))
        return {};
    try
    {
        return lengthToMetres(units);
    }
    catch (const Error &e)
    {
        throw f.error("coordinate '" + f.varName(var) + "': " + e.what() +
                      "; Cartesian axes are read in a length unit (m, km) or without units");
    }
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
std::optional<double> defaultFill(ValueType type)
{
    switch (type)
    {
    case ValueType::Short:
        return NC_FILL_SHORT;
    case ValueType::Int:
        return NC_FILL_INT;
    case ValueType::Float:
        return static_cast<double>(NC_FILL_FLOAT);
    case ValueType::Double:
        return NC_FILL_DOUBLE;
    default:
        return std::nullopt;
    }
}
} // namespace

Packing packingOf(const GriddedDataset &f, int var)
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

void unpackCoordinates(const GriddedDataset &f, int var, std::vector<double> &values)
{
    const Packing p = packingOf(f, var);
    if (p.scale == 1.0 && p.offset == 0.0)
        return;
    for (double &v : values)
        v = v * p.scale + p.offset;
}
} // namespace gridded_detail
} // namespace ompl_glider

// Reading the velocities and the land: u and v over the hyperslab plan, unpacked to m/s; a node (per depth layer)
// is land where u or v is a fill value (or outside the valid range, or NaN) in a record of the trip, where a
// land/sea mask variable says land, where a tracer is missing (TracerLand.cpp), and (GriddedCurrentOptions::
// zeroVelocityLand) where u = v = 0 exactly in every record of the trip next to that land. The rules are
// documented at loadGriddedCurrents() (GriddedCurrents.h).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
/// Unpacks raw u/v (internal order t, z, y, x) into g.u / g.v and marks land in g.water (per z, y, x), deciding on
/// the trip's records only (t.inTrip()). Fill values become velocity 0 (a fill in a margin record only reaches
/// the field through cubic/Akima time stencils, as a zero).
void unpackAndMask(const std::vector<double> &ru, const std::vector<double> &rv, const Packing &pu, const Packing &pv,
                   const LinearConversion &vel, bool zeroIsLand, const AxisSelection &t, GriddedData &g,
                   GriddedCurrents &out)
{
    const std::size_t total = ru.size(), perTime = g.depth.size() * g.nx * g.ny;
    g.u.assign(total, 0.0f);
    g.v.assign(total, 0.0f);
    g.water.assign(perTime, 1);
    std::vector<std::uint8_t> allZero(perTime, 1);
    for (std::size_t it = 0; it < g.time.size(); ++it)
        for (std::size_t n = 0; n < perTime; ++n)
        {
            const std::size_t idx = it * perTime + n;
            if (pu.isFill(ru[idx]) || pv.isFill(rv[idx]))
            {
                if (t.inTrip(it))
                    g.water[n] = 0;
                continue;
            }
            const double u = vel(ru[idx] * pu.scale + pu.offset);
            const double v = vel(rv[idx] * pv.scale + pv.offset);
            if ((u != 0.0 || v != 0.0) && t.inTrip(it))
                allZero[n] = 0;
            g.u[idx] = static_cast<float>(u);
            g.v[idx] = static_cast<float>(v);
        }
    // The zero rule is for model output: a field that is zero at every water node is still water, not all land,
    // and packed data seen in one record only can round a calm node to zero
    std::size_t tripRecords = 0;
    for (std::size_t it = 0; it < g.time.size(); ++it)
        tripRecords += t.inTrip(it);
    const bool packed = pu.scale != 1.0 || pu.offset != 0.0 || pv.scale != 1.0 || pv.offset != 0.0;
    std::size_t zeros = 0, wet = 0;
    for (std::size_t n = 0; n < perTime; ++n)
        if (g.water[n])
        {
            ++wet;
            zeros += allZero[n];
        }
    const bool applyZero = zeroIsLand && zeros < wet && !(packed && tripRecords < 2);
    for (std::size_t n = 0; n < perTime; ++n)
    {
        if (!g.water[n])
            ++out.fillLandNodes;
        else if (applyZero && allZero[n])
        {
            g.water[n] = 0;
            ++out.zeroLandNodes;
        }
    }
}

ZeroLandRule zeroLandRule(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, bool otherLand,
                          bool cornerGrid)
{
    ZeroLandRule r;
    r.everyStillNode = !otherLand || cornerGrid;
    const std::size_t nx = f.dimLen(l.dims[std::size_t(l.dimX)]), ny = f.dimLen(l.dims[std::size_t(l.dimY)]);
    // an edge is open unless it is the file's own (the loaded nodes are a contiguous block, or a run of columns
    // across a periodic grid's seam, whose end columns are then not the file's first or last)
    auto open = [](std::size_t idx, std::size_t n) { return idx != 0 && idx + 1 != n; };
    r.openEdge[0] = open(h.xIdx.front(), nx);
    r.openEdge[1] = open(h.xIdx.back(), nx);
    r.openEdge[2] = open(h.yIdx.front(), ny);
    r.openEdge[3] = open(h.yIdx.back(), ny);
    return r;
}

std::size_t zeroVelocityLand(GriddedData &g, const AxisSelection &t, bool packed, const ZeroLandRule &rule)
{
    const std::size_t perTime = g.water.size(), nx = g.nx, ny = g.ny, nh = nx * ny;
    std::vector<std::uint8_t> still(perTime, 1);
    std::size_t tripRecords = 0;
    for (std::size_t it = 0; it < g.time.size(); ++it)
    {
        if (!t.inTrip(it))
            continue;
        ++tripRecords;
        for (std::size_t n = 0; n < perTime; ++n)
            if (g.u[it * perTime + n] != 0.0f || g.v[it * perTime + n] != 0.0f)
                still[n] = 0;
    }
    std::size_t zeros = 0, wet = 0;
    for (std::size_t n = 0; n < perTime; ++n)
    {
        still[n] = still[n] && g.water[n];
        wet += g.water[n];
        zeros += still[n];
    }
    if (zeros == 0 || !(zeros < wet) || (packed && tripRecords < 2))
        return 0;
    std::vector<std::uint8_t> land(perTime, 0);
    if (rule.everyStillNode)
        land = still;
    else
    {
        // per layer, the blocks of still nodes (8-connected): land when one of them touches land or an open edge
        std::vector<std::size_t> block, stack;
        std::vector<std::uint8_t> seen(perTime, 0);
        for (std::size_t n0 = 0; n0 < perTime; ++n0)
        {
            if (!still[n0] || seen[n0])
                continue;
            const std::size_t layer = n0 / nh * nh;
            block.clear();
            stack.assign(1, n0);
            seen[n0] = 1;
            bool coast = false;
            while (!stack.empty())
            {
                const std::size_t n = stack.back();
                stack.pop_back();
                block.push_back(n);
                const std::size_t j = (n - layer) / nx, i = (n - layer) % nx;
                coast = coast || (i == 0 && rule.openEdge[0]) || (i + 1 == nx && rule.openEdge[1]) ||
                        (j == 0 && rule.openEdge[2]) || (j + 1 == ny && rule.openEdge[3]);
                for (std::size_t jj = j > 0 ? j - 1 : 0; jj <= std::min(ny - 1, j + 1); ++jj)
                    for (std::size_t ii = i > 0 ? i - 1 : 0; ii <= std::min(nx - 1, i + 1); ++ii)
                    {
                        const std::size_t m = layer + jj * nx + ii;
                        if (!g.water[m])
                            coast = true;
                        else if (still[m] && !seen[m])
                        {
                            seen[m] = 1;
                            stack.push_back(m);
                        }
                    }
            }
            if (coast)
                for (std::size_t n : block)
                    land[n] = 1;
        }
    }
    std::size_t made = 0;
    for (std::size_t n = 0; n < perTime; ++n)
        if (land[n])
        {
            g.water[n] = 0;
            ++made;
        }
    return made;
}

void zeroLandVelocities(GriddedData &g)
{
    const std::size_t perTime = g.water.size();
    for (std::size_t idx = 0; idx < g.u.size(); ++idx)
        if (!g.water[idx % perTime])
            g.u[idx] = g.v[idx] = 0.0f;
}

void GridFit::setHorizontal(const std::vector<std::size_t> &yIdx, const std::vector<std::size_t> &xIdx)
{
    for (std::size_t d = 0; d < role.size(); ++d)
        if (role[d] == Role::Y)
            reads[d] = makeDimRead(yIdx);
        else if (role[d] == Role::X)
            reads[d] = makeDimRead(xIdx);
}

std::optional<GridFit> fitToGrid(const GriddedDataset &f, const Layout &l, int var, const HorizontalSubset &h,
                                 const AxisSelection &z, const AxisSelection &t, std::string &why)
{
    const std::vector<int> md = f.varDims(var);
    if (md.size() < 2)
    {
        why = "it has " + std::to_string(md.size()) + " dimension(s), at least 2 (y, x) are needed";
        return std::nullopt;
    }
    const int uy = l.dims[l.dimY], ux = l.dims[l.dimX];
    GridFit m;
    m.reads.resize(md.size());
    std::vector<Role> &role = m.role;
    role.assign(md.size(), Role::None);
    for (std::size_t d = 0; d < md.size(); ++d)
        for (std::size_t e = 0; e < l.dims.size(); ++e)
            if (md[d] == l.dims[e])
                role[d] = l.role[e];
    // the last two dimensions stand for u's y and x when their lengths agree (a variable on dimensions of its own)
    const std::size_t a = md.size() - 2, b = md.size() - 1;
    if (role[a] == Role::None && role[b] == Role::None && f.dimLen(md[a]) == f.dimLen(uy) &&
        f.dimLen(md[b]) == f.dimLen(ux))
    {
        role[a] = Role::Y;
        role[b] = Role::X;
    }
    if (std::count(role.begin(), role.end(), Role::Y) != 1 || std::count(role.begin(), role.end(), Role::X) != 1)
    {
        why = "its dimensions (";
        for (std::size_t d = 0; d < md.size(); ++d)
            why += (d ? ", " : "") + f.dimName(md[d]) + " = " + std::to_string(f.dimLen(md[d]));
        why += ") are not the horizontal grid of '" + l.uName + "' (" + f.dimName(uy) + " = " +
               std::to_string(f.dimLen(uy)) + ", " + f.dimName(ux) + " = " + std::to_string(f.dimLen(ux)) + ")";
        return std::nullopt;
    }
    const std::size_t nx = h.xIdx.size(), nh = nx * h.yIdx.size();
    for (std::size_t d = 0; d < md.size(); ++d)
    {
        m.hasTime = m.hasTime || role[d] == Role::Time;
        m.hasDepth = m.hasDepth || role[d] == Role::Depth;
        if (role[d] == Role::None && f.dimLen(md[d]) != 1)
        {
            why = "its dimension " + f.dimName(md[d]) + " (" + std::to_string(f.dimLen(md[d])) +
                  ") is not a dimension of '" + l.uName + "'";
            return std::nullopt;
        }
    }
    const std::size_t nz = m.hasDepth ? z.idx.size() : 1;
    m.stride.assign(md.size(), 0);
    for (std::size_t d = 0; d < md.size(); ++d)
        switch (role[d])
        {
        case Role::Time:
            m.reads[d] = makeDimRead(t.idx);
            m.stride[d] = nz * nh;
            break;
        case Role::Depth:
            m.reads[d] = makeDimRead(z.idx);
            m.stride[d] = nh;
            break;
        case Role::Y:
            m.stride[d] = nx;
            break;
        case Role::X:
            m.stride[d] = 1;
            break;
        case Role::Run:
            m.reads[d] = makeDimRead({l.run});
            break;
        case Role::None:
            m.reads[d] = makeDimRead({0});
            break;
        }
    m.setHorizontal(h.yIdx, h.xIdx);
    return m;
}

namespace
{

/// How the values of a mask variable are read.
enum class MaskRule
{
    WaterIfHalf, ///< >= 0.5 is water (ROMS mask_rho, NEMO tmask, CF sea_binary_mask)
    LandIfHalf,  ///< >= 0.5 is land (CF land_binary_mask, ERA5 lsm, WRF LANDMASK)
    Flags,       ///< CF flag_values / flag_meanings
    LevelCount   ///< POP KMT: number of ocean levels
};

/// A mask variable, its rule, and where its dimensions sit in the loaded arrays.
struct Mask
{
    int var{-1};
    MaskRule rule{MaskRule::WaterIfHalf};
    std::set<double> waterFlags; ///< Flags: the values meaning water
};

/// The CF standard names of a binary mask, and how each is read.
const std::map<std::string, MaskRule> kBinaryMasks = {{"sea_binary_mask", MaskRule::WaterIfHalf},
                                                      {"land_binary_mask", MaskRule::LandIfHalf}};
/// The words of a flag's meaning that say water, and those that say something else (ice, land, a lake...).
const std::set<std::string> kWaterWords = {"sea", "water", "ocean"};
const std::set<std::string> kOtherWords = {"ice", "land", "shelf", "lake", "glacier", "river"};

std::string lowerName(const GriddedDataset &f, int var)
{
    return lower(f.varName(var));
}

/// The rule of a mask variable from its attributes and name.
Mask maskOf(const GriddedDataset &f, int var)
{
    Mask m;
    m.var = var;
    const std::string name = lowerName(f, var), sn = stdName(f, var);
    const auto meanings = f.attText(var, "flag_meanings");
    const auto values = f.attDoubles(var, "flag_values");
    if (meanings && !values.empty())
    {
        std::istringstream is(lower(*meanings));
        std::string word;
        std::size_t k = 0;
        for (; is >> word && k < values.size(); ++k)
        {
            // the words of a meaning: "sea", "open_water", "sea_ice", "ice_shelf", "land"
            bool water = false, other = false;
            std::istringstream ws(word);
            std::string part;
            while (std::getline(ws, part, '_'))
            {
                water = water || kWaterWords.count(part);
                other = other || kOtherWords.count(part);
            }
            if (water && !other)
                m.waterFlags.insert(values[k]);
        }
        m.rule = MaskRule::Flags;
        return m;
    }
    static const std::set<std::string> levelCounts = {"kmt", "kmu"}; // POP's ocean levels at T and U points
    if (const auto binary = kBinaryMasks.find(sn); binary != kBinaryMasks.end())
        m.rule = binary->second;
    else if (name.find("land") != std::string::npos || name.find("lsm") != std::string::npos)
        m.rule = MaskRule::LandIfHalf;
    else if (levelCounts.count(name))
        m.rule = MaskRule::LevelCount;
    return m;
}

const char *const kMaskNames[] = {"mask_rho",      "mask",    "tmask",    "landmask", "land_mask", "lsm",
                                  "land_sea_mask", "seamask", "sea_mask", "kmu",      "kmt"};

/// The mask variable: the given one (which must fit), else the first candidate that fits; -1 for none.
int findMask(const GriddedDataset &f, const Layout &l, const GriddedCurrentOptions &opt, const HorizontalSubset &h,
             const AxisSelection &z, const AxisSelection &t, std::optional<GridFit> &dims)
{
    std::string why;
    if (lower(opt.maskName) == "none")
        return -1;
    if (!opt.maskName.empty())
    {
        const auto v = f.findVar(opt.maskName);
        if (!v)
            throw f.error("no mask variable '" + opt.maskName +
                              "' (given as the land/sea mask: GriddedCurrentOptions::maskName)",
                          "GriddedCurrentOptions::maskName");
        dims = fitToGrid(f, l, *v, h, z, t, why);
        if (!dims)
            throw f.error("mask variable '" + opt.maskName +
                              "' (GriddedCurrentOptions::maskName) does not fit the velocities: " + why,
                          "GriddedCurrentOptions::maskName");
        return *v;
    }
    std::vector<int> order;
    for (int var = 0; var < f.nvars(); ++var)
    {
        const std::string sn = stdName(f, var);
        const auto meanings = f.attText(var, "flag_meanings");
        // flag meanings that name both land and water (not a quality flag such as "land_contaminated")
        bool landWord = false, waterWord = false;
        if (meanings)
        {
            std::istringstream is(lower(*meanings));
            std::string word;
            while (is >> word)
            {
                landWord = landWord || word == "land";
                waterWord = waterWord || kWaterWords.count(word) || word == "open_water";
            }
        }
        if ((landWord && waterWord) || kBinaryMasks.count(sn))
            order.push_back(var);
    }
    for (const char *name : kMaskNames)
        for (int var = 0; var < f.nvars(); ++var)
            if (lowerName(f, var) == name)
                order.push_back(var);
    for (int var : order)
        if (var != l.uVar && var != l.vVar && (dims = fitToGrid(f, l, var, h, z, t, why)))
            return var;
    return -1;
}
} // namespace

void readVelocities(const GriddedDataset &f, const Layout &l, const HyperslabPlan &plan, const AxisSelection &t,
                    const LinearConversion &vel, const GriddedCurrentOptions &opt, GriddedData &g, GriddedCurrents &out)
{
    const std::size_t total = g.time.size() * g.depth.size() * g.ny * g.nx;
    std::vector<double> ru(total), rv(total);
    readScatter(f, l.uVar, plan.reads, plan.stride, ru);
    readScatter(f, l.vVar, plan.reads, plan.stride, rv);
    const Packing pu = packingOf(f, l.uVar), pv = packingOf(f, l.vVar);
    unpackAndMask(ru, rv, pu, pv, vel, opt.zeroVelocityLand, t, g, out);
}

void applyLandMask(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const AxisSelection &z,
                   const AxisSelection &t, const GriddedCurrentOptions &opt, GriddedData &g, GriddedCurrents &out)
{
    std::optional<GridFit> dims;
    const int var = findMask(f, l, opt, h, z, t, dims);
    if (var >= 0)
    {
        const Mask m = maskOf(f, var);
        out.maskVariable = f.varName(var);
        const std::size_t nh = g.nx * g.ny, nzLoaded = g.depth.size();
        const std::size_t nt = dims->hasTime ? t.idx.size() : 1, nz = dims->hasDepth ? nzLoaded : 1;
        std::vector<double> raw(nt * nz * nh);
        readScatter(f, var, dims->reads, dims->stride, raw);
        const Packing p = packingOf(f, var);
        for (std::size_t it = 0; it < nt; ++it)
            for (std::size_t kz = 0; kz < nz && (!dims->hasTime || t.inTrip(it)); ++kz)
                for (std::size_t n = 0; n < nh; ++n)
                {
                    const double r = raw[(it * nz + kz) * nh + n];
                    const double v = r * p.scale + p.offset;
                    // the layers this mask value speaks for: its own, or all of them for a 2-D mask
                    for (std::size_t k = dims->hasDepth ? kz : 0; k < (dims->hasDepth ? kz + 1 : nzLoaded); ++k)
                    {
                        bool water = false;
                        if (!p.isFill(r))
                            switch (m.rule)
                            {
                            case MaskRule::WaterIfHalf:
                                water = v >= 0.5;
                                break;
                            case MaskRule::LandIfHalf:
                                water = v < 0.5;
                                break;
                            case MaskRule::Flags:
                                water = m.waterFlags.count(v) > 0;
                                break;
                            case MaskRule::LevelCount:
                                water = double(z.idx[k]) < v;
                                break;
                            }
                        std::uint8_t &w = g.water[k * nh + n];
                        if (w && !water)
                        {
                            w = 0;
                            ++out.maskLandNodes;
                        }
                    }
                }
    }
    out.landNodes = static_cast<std::size_t>(std::count(g.water.begin(), g.water.end(), 0));
}
void averageOverDepth(double top, double bottom, GriddedData &g)
{
    const std::vector<double> &d = g.depth;
    const std::size_t nz = d.size(), nh = g.nx * g.ny, nt = g.time.size();
    std::vector<double> w(nz, 0.0);
    if (nz == 1 || top == bottom)
    {
        // one layer, or a single depth: linear interpolation (clamped)
        const double z = std::clamp(top, d.front(), d.back());
        std::size_t k = 0;
        while (k + 2 < nz && d[k + 1] < z)
            ++k;
        const double a = nz == 1 ? 0.0 : (z - d[k]) / (d[k + 1] - d[k]);
        w[k] += 1.0 - a;
        if (nz > 1)
            w[k + 1] += a;
    }
    else
    {
        // integral of the piecewise-linear profile, extended as constants above d[0] and below d[nz-1]
        if (top < d.front())
            w.front() += std::min(bottom, d.front()) - top;
        if (bottom > d.back())
            w.back() += bottom - std::max(top, d.back());
        for (std::size_t k = 0; k + 1 < nz; ++k)
        {
            const double p = std::max(top, d[k]), q = std::min(bottom, d[k + 1]);
            if (!(q > p))
                continue;
            const double h = d[k + 1] - d[k], ap = (p - d[k]) / h, aq = (q - d[k]) / h;
            w[k] += 0.5 * (q - p) * ((1.0 - ap) + (1.0 - aq));
            w[k + 1] += 0.5 * (q - p) * (ap + aq);
        }
        for (double &x : w)
            x /= bottom - top;
    }
    std::vector<double> u(nt * nh, 0.0), v(nt * nh, 0.0);
    std::vector<std::uint8_t> water(nh, 1);
    for (std::size_t k = 0; k < nz; ++k)
    {
        if (w[k] == 0.0)
            continue;
        for (std::size_t n = 0; n < nh; ++n)
            water[n] = water[n] && g.water[k * nh + n];
        for (std::size_t it = 0; it < nt; ++it)
            for (std::size_t n = 0; n < nh; ++n)
            {
                u[it * nh + n] += w[k] * g.u[(it * nz + k) * nh + n];
                v[it * nh + n] += w[k] * g.v[(it * nz + k) * nh + n];
            }
    }
    for (std::size_t it = 0; it < nt; ++it)
        for (std::size_t n = 0; n < nh; ++n)
            if (!water[n])
                u[it * nh + n] = v[it * nh + n] = 0.0;
    g.u.assign(u.begin(), u.end());
    g.v.assign(v.begin(), v.end());
    g.water = std::move(water);
    g.depth = {top};
}
} // namespace gridded_detail
} // namespace ompl_glider

// Terrain-following (ROMS s-coordinate) levels turned into depth levels in metres: the depth of each s-level at
// each node from the CF formula of its standard_name (ocean_s_coordinate_g1 / _g2, formula_terms; ROMS names as a
// fallback), then every column interpolated linearly in depth onto fixed depth levels. A depth level below the
// sea floor of its column is land there; one above the top s-level takes the top level's current.
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
namespace
{
/// The formula of an s-coordinate, from its standard_name.
enum class SForm
{
    None,
    G1, ///< ocean_s_coordinate_g1 (ROMS Vtransform = 1)
    G2  ///< ocean_s_coordinate_g2 (ROMS Vtransform = 2)
};

SForm formOf(const GriddedDataset &f, int zv)
{
    const std::string sn = stdName(f, zv);
    if (sn == "ocean_s_coordinate_g1")
        return SForm::G1;
    if (sn == "ocean_s_coordinate_g2")
        return SForm::G2;
    return SForm::None;
}

/// formula_terms "s: s_rho C: Cs_r eta: zeta depth: h depth_c: hc" as a map term -> variable name.
std::map<std::string, std::string> formulaTerms(const GriddedDataset &f, int zv)
{
    std::map<std::string, std::string> terms;
    std::istringstream is(f.attText(zv, "formula_terms").value_or(""));
    std::string key, value;
    while (is >> key >> value)
        if (!key.empty() && key.back() == ':')
            terms[key.substr(0, key.size() - 1)] = value;
    return terms;
}

/// The variable of a formula term: formula_terms' name, else the ROMS name; nullopt when neither exists.
std::optional<int> termVar(const GriddedDataset &f, const std::map<std::string, std::string> &terms,
                           const std::string &term, const char *romsName)
{
    const auto it = terms.find(term);
    if (it != terms.end())
    {
        if (auto v = f.findVar(it->second))
            return v;
        throw f.error("formula_terms of the s-coordinate name '" + it->second + "' for " + term +
                      ", and the file has no such variable");
    }
    return f.findVar(romsName);
}

/// The fixed depth levels (m) the columns are interpolated onto: a standard set, the requested depths, down to the
/// first at or below `deepest`, plus 2 more for the cubic/Akima depth stencils.
std::vector<double> depthLevels(double deepest, const std::vector<double> &requested)
{
    std::set<double> lv = {0,   2,   5,   10,  15,  20,  30,   40,   50,   75,   100,  125,  150,  200,  250, 300,
                           400, 500, 600, 700, 800, 900, 1000, 1200, 1500, 2000, 2500, 3000, 4000, 5000, 6000};
    for (double d : requested)
        if (std::isfinite(d) && d >= 0)
            lv.insert(d);
    std::vector<double> out;
    std::size_t extra = 0;
    for (double d : lv)
    {
        out.push_back(d);
        if (std::isfinite(deepest) && d >= deepest && ++extra > 2)
            break;
    }
    return out;
}
} // namespace

bool isSigmaCoordinate(const GriddedDataset &f, int zv)
{
    const std::string sn = stdName(f, zv);
    return sn.rfind("ocean_s", 0) == 0 || sn.rfind("ocean_sigma", 0) == 0 || sn.rfind("ocean_double_sigma", 0) == 0;
}

void remapSigmaToDepths(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const AxisSelection &z,
                        const AxisSelection &t, double deepest, const std::vector<double> &requested, GriddedData &g)
{
    const int zv = l.coordVar[std::size_t(l.dimZ)];
    const std::string zn = f.varName(zv);
    const SForm form = formOf(f, zv);
    if (form == SForm::None)
        throw f.error("depth '" + zn + "' is a terrain-following coordinate (standard_name " + stdName(f, zv) +
                      "); only ocean_s_coordinate_g1 and _g2 (ROMS) are converted to depths: interpolate the file to "
                      "z levels first");
    const auto terms = formulaTerms(f, zv);
    const auto cVar = termVar(f, terms, "C", "Cs_r"), hVar = termVar(f, terms, "depth", "h");
    const auto hcVar = termVar(f, terms, "depth_c", "hc"), etaVar = termVar(f, terms, "eta", "zeta");
    if (!cVar || !hVar || !hcVar)
        throw f.error("depth '" + zn + "' (" + stdName(f, zv) +
                      ") needs its stretching curve C (Cs_r), the bathymetry "
                      "depth (h) and the critical depth depth_c (hc); missing: " +
                      std::string(!cVar ? "C " : "") + (!hVar ? "depth " : "") + (!hcVar ? "depth_c" : ""));
    // s and C per loaded level, hc, h per node, eta per record and node (0 without it)
    const std::vector<double> sAll = f.readAll1D(zv), cAll = f.readAll1D(*cVar), hcAll = f.readAll1D(*hcVar);
    if (cAll.size() != sAll.size() || hcAll.size() != 1 || !std::isfinite(hcAll[0]) || hcAll[0] < 0)
        throw f.error("s-coordinate '" + zn + "': expected C ('" + f.varName(*cVar) +
                      "') with one value per level and "
                      "one finite depth_c >= 0 ('" +
                      f.varName(*hcVar) + "')");
    const double hc = hcAll[0];
    const std::size_t nx = h.xIdx.size(), nh = nx * h.yIdx.size(), nzS = z.idx.size(), nt = t.idx.size();
    const std::vector<int> grid = {l.dims[std::size_t(l.dimY)], l.dims[std::size_t(l.dimX)]};
    if (f.varDims(*hVar) != grid)
        throw f.error("bathymetry depth '" + f.varName(*hVar) + "' of the s-coordinate '" + zn +
                      "' is not on the grid of the velocities");
    std::vector<double> depth(nh);
    readScatter(f, *hVar, {makeDimRead(h.yIdx), makeDimRead(h.xIdx)}, {nx, 1}, depth);
    const Packing hp = packingOf(f, *hVar);
    for (double &d : depth)
        d = hp.isFill(d) ? kNaN : d * hp.scale + hp.offset;
    std::vector<double> eta(nt * nh, 0.0);
    if (etaVar && f.varDims(*etaVar).size() == 3 && l.dimT >= 0 &&
        f.varDims(*etaVar)[0] == l.dims[std::size_t(l.dimT)] &&
        std::equal(grid.begin(), grid.end(), f.varDims(*etaVar).begin() + 1))
    {
        readScatter(f, *etaVar, {makeDimRead(t.idx), makeDimRead(h.yIdx), makeDimRead(h.xIdx)}, {nh, nx, 1}, eta);
        const Packing ep = packingOf(f, *etaVar);
        for (double &e : eta)
            e = ep.isFill(e) ? 0.0 : e * ep.scale + ep.offset;
    }
    const std::vector<double> levels = depthLevels(deepest, requested);
    const std::size_t nzD = levels.size();
    std::vector<float> u(nt * nzD * nh, 0.0f), v(nt * nzD * nh, 0.0f);
    std::vector<std::uint8_t> water(nzD * nh, 1);
    std::vector<double> zk(nzS);
    for (std::size_t n = 0; n < nh; ++n)
    {
        // a column is water at a depth level when its floor lies below it and the s-levels around it are water
        const double hn = depth[n];
        bool columnWet = std::isfinite(hn) && hn > 0;
        for (std::size_t k = 0; k < nzS; ++k)
            columnWet = columnWet && g.water[k * nh + n];
        for (std::size_t it = 0; it < nt; ++it)
        {
            const double e = eta[it * nh + n];
            for (std::size_t k = 0; k < nzS && columnWet; ++k)
            {
                const double s = sAll[z.idx[k]], c = cAll[z.idx[k]];
                if (form == SForm::G1)
                {
                    const double S = hc * s + (hn - hc) * c; // [CF] ocean_s_coordinate_g1
                    zk[k] = S + e * (1.0 + S / hn);
                }
                else
                {
                    const double S = (hc * s + hn * c) / (hc + hn); // [CF] ocean_s_coordinate_g2
                    zk[k] = e + (e + hn) * S;
                }
            }
            // z levels ascending with k when s is (ROMS: bottom first)
            const bool up = zk.back() > zk.front();
            const std::size_t top = up ? nzS - 1 : 0, bottom = up ? 0 : nzS - 1;
            for (std::size_t q = 0; q < nzD; ++q)
            {
                const double zt = -levels[q];
                std::uint8_t &w = water[q * nh + n];
                if (!columnWet || zt < -hn)
                {
                    w = 0;
                    continue;
                }
                // the bracketing pair of s-levels
                std::size_t lo = 0, hi = 0;
                double a = 0.0;
                if (nzS == 1 || zt >= zk[top])
                    lo = hi = top;
                else if (zt <= zk[bottom])
                    lo = hi = bottom;
                else
                    for (std::size_t k = 0; k + 1 < nzS; ++k)
                    {
                        const double z0 = zk[k], z1 = zk[k + 1];
                        if ((zt - z0) * (zt - z1) <= 0.0 && z0 != z1)
                        {
                            lo = k;
                            hi = k + 1;
                            a = (zt - z0) / (z1 - z0);
                            break;
                        }
                    }
                const std::size_t out = (it * nzD + q) * nh + n;
                const std::size_t i0 = (it * nzS + lo) * nh + n, i1 = (it * nzS + hi) * nh + n;
                u[out] = static_cast<float>((1.0 - a) * g.u[i0] + a * g.u[i1]);
                v[out] = static_cast<float>((1.0 - a) * g.v[i0] + a * g.v[i1]);
            }
        }
    }
    g.u = std::move(u);
    g.v = std::move(v);
    g.water = std::move(water);
    g.depth = levels;
}
} // namespace gridded_detail
} // namespace ompl_glider

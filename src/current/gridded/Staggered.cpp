// Velocities that are not eastward/northward on one set of points: an Arakawa C grid (ROMS: u and v on the faces
// of the cells, read at their own points and averaged onto the cell centres) and grid-relative components rotated
// by the grid's angle (ROMS angle, POP ANGLE on a B grid).
#include <cmath>
#include <optional>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// The file indices first - 1, first, ..., last of a contiguous ascending list (the faces around its points).
std::vector<std::size_t> withFaceBefore(const GriddedDataset &f, const std::vector<std::size_t> &idx,
                                        const std::string &what)
{
    for (std::size_t k = 1; k < idx.size(); ++k)
        if (idx[k] != idx[k - 1] + 1)
            throw f.error("the " + what + " of the staggered grid's region are not one contiguous block");
    if (idx.empty() || idx.front() == 0)
        throw f.error("the " + what + " of the staggered grid's region reach its edge (no face before the first)");
    std::vector<std::size_t> out{idx.front() - 1};
    out.insert(out.end(), idx.begin(), idx.end());
    return out;
}

/// The reads of a velocity variable on its own dimensions: time and depth as in plan, rows yIdx, columns xIdx;
/// internal order (t, z, y, x) with ny x nx horizontal points.
std::vector<double> readComponent(const GriddedDataset &f, int var, const Layout &l, const AxisSelection &z,
                                  const AxisSelection &t, const std::vector<std::size_t> &yIdx,
                                  const std::vector<std::size_t> &xIdx)
{
    const std::size_t nx = xIdx.size(), nh = nx * yIdx.size(), nz = z.idx.size();
    std::vector<DimRead> reads(l.dims.size());
    std::vector<std::size_t> stride(l.dims.size(), 0);
    for (std::size_t d = 0; d < l.dims.size(); ++d)
        switch (l.role[d])
        {
        case Role::Time:
            reads[d] = makeDimRead(t.idx);
            stride[d] = nz * nh;
            break;
        case Role::Depth:
            reads[d] = makeDimRead(z.idx);
            stride[d] = nh;
            break;
        case Role::Y:
            reads[d] = makeDimRead(yIdx);
            stride[d] = nx;
            break;
        case Role::X:
            reads[d] = makeDimRead(xIdx);
            stride[d] = 1;
            break;
        case Role::Run:
            reads[d] = makeDimRead({l.run});
            break;
        case Role::None:
            reads[d] = makeDimRead({0});
            break;
        }
    std::vector<double> out(t.idx.size() * nz * nh);
    readScatter(f, var, reads, stride, out);
    return out;
}

/// The face mask mask_u / mask_v (>= 0.5 water) on the component's own 2-D dimensions, read at rows x cols;
/// nullopt when the file has none of that shape.
std::optional<std::vector<double>> faceMask(const GriddedDataset &f, const char *name, const std::vector<int> &compDims,
                                            const std::vector<std::size_t> &yIdx, const std::vector<std::size_t> &xIdx)
{
    const auto v = f.findVar(name);
    const std::vector<int> want(compDims.end() - 2, compDims.end());
    if (!v || f.varDims(*v) != want)
        return std::nullopt;
    std::vector<double> m(yIdx.size() * xIdx.size());
    readScatter(f, *v, {makeDimRead(yIdx), makeDimRead(xIdx)}, {xIdx.size(), 1}, m);
    const Packing p = packingOf(f, *v);
    for (double &x : m)
        x = p.isFill(x) ? 0.0 : x * p.scale + p.offset;
    return m;
}
} // namespace

void readStaggeredVelocities(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h,
                             const AxisSelection &z, const AxisSelection &t, const LinearConversion &vel,
                             const GriddedCurrentOptions &opt, GriddedData &g, GriddedCurrents &out)
{
    const std::size_t nx = h.xIdx.size(), ny = h.yIdx.size(), nh = nx * ny;
    const std::size_t layers = t.idx.size() * z.idx.size();
    // u at the faces west and east of each rho column (xi_u = i - 1 and i), v south and north (eta_v = j - 1, j)
    const std::vector<std::size_t> uCols = withFaceBefore(f, h.xIdx, "columns");
    const std::vector<std::size_t> vRows = withFaceBefore(f, h.yIdx, "rows");
    const std::vector<double> ru = readComponent(f, l.uVar, l, z, t, h.yIdx, uCols);
    const std::vector<double> rv = readComponent(f, l.vVar, l, z, t, vRows, h.xIdx);
    const Packing pu = packingOf(f, l.uVar), pv = packingOf(f, l.vVar);
    const auto mu = faceMask(f, "mask_u", l.uDims, h.yIdx, uCols);
    const auto mv = faceMask(f, "mask_v", l.vDims, vRows, h.xIdx);
    // the mean of the two faces of each component, in m/s; NaN (a fill value) when both are fill values
    std::vector<double> au(layers * nh), av(layers * nh);
    auto face = [&](double raw, const Packing &p, bool masked, bool &fill) {
        if (masked)
            return 0.0;
        if (p.isFill(raw))
        {
            fill = true;
            return 0.0;
        }
        return vel(raw * p.scale + p.offset);
    };
    for (std::size_t q = 0; q < layers; ++q)
        for (std::size_t j = 0; j < ny; ++j)
            for (std::size_t i = 0; i < nx; ++i)
            {
                const std::size_t n = j * nx + i, wu = j * (nx + 1) + i, wv = j * nx + i;
                bool f0 = false, f1 = false, g0 = false, g1 = false;
                const double u0 = face(ru[q * ny * (nx + 1) + wu], pu, mu && (*mu)[wu] < 0.5, f0);
                const double u1 = face(ru[q * ny * (nx + 1) + wu + 1], pu, mu && (*mu)[wu + 1] < 0.5, f1);
                const double v0 = face(rv[q * (ny + 1) * nx + wv], pv, mv && (*mv)[wv] < 0.5, g0);
                const double v1 = face(rv[q * (ny + 1) * nx + wv + nx], pv, mv && (*mv)[wv + nx] < 0.5, g1);
                au[q * nh + n] = f0 && f1 ? kNaN : 0.5 * (u0 + u1);
                av[q * nh + n] = g0 && g1 ? kNaN : 0.5 * (v0 + v1);
            }
    // packed values seen in one record only can round a calm point to zero: no zero rule then (as readVelocities)
    std::size_t tripRecords = 0;
    for (std::size_t it = 0; it < t.idx.size(); ++it)
        tripRecords += t.inTrip(it);
    const bool packed = pu.scale != 1.0 || pu.offset != 0.0 || pv.scale != 1.0 || pv.offset != 0.0;
    unpackAndMask(au, av, Packing{}, Packing{}, LinearConversion{},
                  opt.zeroVelocityLand && !(packed && tripRecords < 2), t, g, out);
}

namespace
{
/// The angle derived from the loaded nodes' coordinates (Layout::deriveAngle), per node; empty when the grid is not
/// rotated. @throws Error naming the node when the angle is ambiguous.
std::vector<double> derivedAngle(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h,
                                 GriddedCurrents &out)
{
    const std::size_t nx = h.xIdx.size(), ny = h.yIdx.size();
    const DerivedGridAngle a = deriveGridAngle(h.nodeLon, h.nodeLat, nx, ny, l.geographic);
    if (!a.fault.empty() && (a.rotated || a.radians.empty()))
    {
        const std::size_t n = a.faultJ * nx + a.faultI;
        throw f.error("variables '" + l.uName + "'/'" + l.vName +
                      "' have no grid angle variable and do not say they "
                      "are eastward/northward (standard_name eastward_*), and the rotated curvilinear grid '" +
                      l.xName + "'/'" + l.yName + "' gives no clear angle: at (j, i) = (" +
                      std::to_string(h.yIdx[a.faultJ]) + ", " + std::to_string(h.xIdx[a.faultI]) + "), " + l.xName +
                      " " + text::number(h.nodeLon[n]) + ", " + l.yName + " " + text::number(h.nodeLat[n]) + ", " +
                      a.fault +
                      "; name the angle variable (GriddedCurrentOptions::angleName), or give "
                      "GriddedCurrentOptions::angleName 'none' if the velocities are eastward/northward");
    }
    if (!a.rotated)
        return {};
    out.gridAngle = gridAngleNote(a, "'" + l.xName + "'/'" + l.yName + "'");
    return a.radians;
}

/// The angle of the variable Layout::angleVar, per loaded node, in radians.
std::vector<double> angleOfVariable(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h,
                                    GriddedCurrents &out)
{
    const std::size_t nx = h.xIdx.size(), nh = nx * h.yIdx.size();
    std::vector<double> a(nh);
    readScatter(f, l.angleVar, {makeDimRead(h.yIdx), makeDimRead(h.xIdx)}, {nx, 1}, a);
    const Packing p = packingOf(f, l.angleVar);
    for (std::size_t n = 0; n < nh; ++n)
    {
        if (p.isFill(a[n]) || !std::isfinite(a[n]))
            throw f.error("grid angle variable '" + f.varName(l.angleVar) +
                          "' holds a fill value or a non-finite "
                          "number at (j, i) = (" +
                          std::to_string(h.yIdx[n / nx]) + ", " + std::to_string(h.xIdx[n % nx]) +
                          "); expected an angle at every velocity point");
        a[n] = (a[n] * p.scale + p.offset) * l.angleToRadians;
    }
    out.gridAngle = "variable '" + f.varName(l.angleVar) + "'";
    return a;
}
} // namespace

void rotateGridToEastNorth(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, GriddedData &g,
                           GriddedCurrents &out)
{
    if (l.angleVar < 0 && !l.deriveAngle)
        return;
    const std::vector<double> a = l.angleVar >= 0 ? angleOfVariable(f, l, h, out) : derivedAngle(f, l, h, out);
    if (a.empty())
        return;
    const std::size_t nh = a.size();
    std::vector<double> cosA(nh), sinA(nh);
    for (std::size_t n = 0; n < nh; ++n)
    {
        cosA[n] = std::cos(a[n]);
        sinA[n] = std::sin(a[n]);
    }
    // once per node, for every time and depth
    for (std::size_t idx = 0; idx < g.u.size(); ++idx)
    {
        const double c = cosA[idx % nh], s = sinA[idx % nh];
        const double u = g.u[idx], v = g.v[idx];
        g.u[idx] = static_cast<float>(u * c - v * s);
        g.v[idx] = static_cast<float>(u * s + v * c);
    }
}
} // namespace gridded_detail
} // namespace ompl_glider

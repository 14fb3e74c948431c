// Reading the velocities: u and v over the hyperslab plan, unpacked to m/s; a node where u or v is a fill value
// (or outside the valid range, or NaN) at any loaded time is land at that depth.
#include "NetCdfInternal.h"

namespace ompl_glider
{
namespace netcdf_detail
{
namespace
{
/// Unpacks raw u/v (internal order t, z, y, x) into g.u / g.v and marks land in g.water (per z, y, x). Land
/// nodes keep velocity 0 at every time.
void unpackAndMask(const std::vector<double> &ru, const std::vector<double> &rv, const Packing &pu,
                   const Packing &pv, const LinearConversion &vel, GriddedData &g)
{
    const std::size_t total = ru.size(), perTime = g.depth.size() * g.nx * g.ny;
    g.u.resize(total);
    g.v.resize(total);
    g.water.assign(perTime, 1);
    for (std::size_t it = 0; it < g.time.size(); ++it)
        for (std::size_t n = 0; n < perTime; ++n)
        {
            const std::size_t idx = it * perTime + n;
            if (pu.isFill(ru[idx]) || pv.isFill(rv[idx]))
            {
                g.water[n] = 0;
                continue;
            }
            g.u[idx] = static_cast<float>(vel(ru[idx] * pu.scale + pu.offset));
            g.v[idx] = static_cast<float>(vel(rv[idx] * pv.scale + pv.offset));
        }
}
}  // namespace

void readVelocities(const NcFile &f, const Layout &l, const HyperslabPlan &plan, const LinearConversion &vel,
                    GriddedData &g)
{
    const std::size_t total = g.time.size() * g.depth.size() * g.ny * g.nx;
    std::vector<double> ru(total), rv(total);
    readScatter(f, l.uVar, plan.reads, plan.stride, ru);
    readScatter(f, l.vVar, plan.reads, plan.stride, rv);
    const Packing pu = packingOf(f, l.uVar), pv = packingOf(f, l.vVar);
    unpackAndMask(ru, rv, pu, pv, vel, g);
}
}  // namespace netcdf_detail
}  // namespace ompl_glider

// Hyperslab reads: the file indices chosen along each dimension become contiguous runs; each combination of
// runs is one nc_get_vara read, scattered into the internal (t, z, y, x) order.
#include <algorithm>

#include "GriddedInternal.h"
#include "ompl_glider/ResourceLimits.h"

namespace ompl_glider
{
namespace gridded_detail
{
DimRead makeDimRead(const std::vector<std::size_t> &fileIdx)
{
    std::vector<std::pair<std::size_t, std::size_t>> order; // (file index, internal pos)
    for (std::size_t p = 0; p < fileIdx.size(); ++p)
        order.emplace_back(fileIdx[p], p);
    std::sort(order.begin(), order.end());
    DimRead d;
    for (std::size_t k = 0; k < order.size(); ++k)
    {
        if (k == 0 || order[k].first != order[k - 1].first + 1)
        {
            d.runs.emplace_back(order[k].first, 0);
            d.pos.emplace_back();
        }
        d.runs.back().second++;
        d.pos.back().push_back(order[k].second);
    }
    return d;
}

namespace
{
/// Scatters one hyperslab (runs runIdx of each dimension, row-major values buf) into out.
void scatterBlock(const std::vector<DimRead> &dims, const std::vector<std::size_t> &stride,
                  const std::vector<std::size_t> &runIdx, const std::vector<std::size_t> &count,
                  const std::vector<double> &buf, std::vector<double> &out)
{
    const std::size_t nd = dims.size();
    std::vector<std::size_t> c(nd, 0); // odometer over the hyperslab in row-major order
    for (std::size_t e = 0; e < buf.size(); ++e)
    {
        std::size_t off = 0;
        for (std::size_t d = 0; d < nd; ++d)
            off += dims[d].pos[runIdx[d]][c[d]] * stride[d];
        out[off] = buf[e];
        for (std::size_t d = nd; d-- > 0;)
        {
            if (++c[d] < count[d])
                break;
            c[d] = 0;
        }
    }
}

/// Next combination of runs (odometer, last dimension fastest); false after the last one.
bool nextRuns(const std::vector<DimRead> &dims, std::vector<std::size_t> &runIdx)
{
    for (std::size_t d = dims.size(); d-- > 0;)
    {
        if (++runIdx[d] < dims[d].runs.size())
            return true;
        runIdx[d] = 0;
    }
    return false;
}
} // namespace

void readScatter(const GriddedDataset &f, int var, const std::vector<DimRead> &dims,
                 const std::vector<std::size_t> &stride, std::vector<double> &out)
{
    const std::size_t nd = dims.size();
    std::vector<std::size_t> runIdx(nd, 0);
    std::vector<double> buf;
    do
    {
        std::vector<std::size_t> start(nd), count(nd);
        std::size_t n = 1;
        for (std::size_t d = 0; d < nd; ++d)
        {
            start[d] = dims[d].runs[runIdx[d]].first;
            count[d] = dims[d].runs[runIdx[d]].second;
            n *= count[d];
        }
        buf.resize(n);
        if (n > 0)
            f.readBlock(var, start, count, buf.data());
        scatterBlock(dims, stride, runIdx, count, buf, out);
    } while (nextRuns(dims, runIdx));
}

double tripBytes(std::size_t ni, std::size_t nj, std::size_t nt, std::size_t nz)
{
    const double nodes = double(ni) * double(nj), values = nodes * double(nt) * double(nz);
    // per value of u and of v: 4 (loaded float) + 4 (the field's copy) + 8 (stencil max/min) + 4 (their scratch
    // copy) bytes while the field is built, more than the reading's 8 (raw double) + 4 (a read buffer of doubles
    // for one variable at a time); per node: 4 coordinate arrays of doubles, the field's cell index (16 bytes), a
    // land mask per depth twice (the loaded one and the field's)
    const double perValue = 2.0 * (4.0 + 4.0 + 8.0 + 4.0);
    const double perNode = 4.0 * sizeof(double) + 16.0 + 2.0 * double(nz);
    return values * perValue + nodes * perNode;
}

void checkTripMemory(const GriddedDataset &f, std::size_t ni, std::size_t nj, std::size_t nt, std::size_t nz)
{
    checkMemory(tripBytes(ni, nj, nt, nz),
                "NetCDF file '" + f.path() + "': the trip's region (" + std::to_string(ni) + " x " +
                    std::to_string(nj) + " nodes, " + std::to_string(nt) + " times, " + std::to_string(nz) + " depths)",
                "restrict the region or the time window, or use a coarser file");
}

HyperslabPlan planHyperslab(const GriddedDataset &f, const Layout &l, const HorizontalSubset &h, const AxisSelection &z,
                            const AxisSelection &t)
{
    const std::size_t nd = l.dims.size(), nx = h.xIdx.size(), nh = nx * h.yIdx.size(), nz = z.idx.size();
    HyperslabPlan p;
    p.reads.resize(nd);
    p.stride.assign(nd, 0);
    for (std::size_t d = 0; d < nd; ++d)
    {
        p.fileValues *= f.dimLen(l.dims[d]);
        switch (l.role[d])
        {
        case Role::Time:
            p.reads[d] = makeDimRead(t.idx);
            p.stride[d] = nz * nh;
            break;
        case Role::Depth:
            p.reads[d] = makeDimRead(z.idx);
            p.stride[d] = nh;
            break;
        case Role::Y:
            p.reads[d] = makeDimRead(h.yIdx);
            p.stride[d] = nx;
            break;
        case Role::X:
            p.reads[d] = makeDimRead(h.xIdx);
            p.stride[d] = 1;
            break;
        case Role::Run:
            p.reads[d] = makeDimRead({l.run});
            p.stride[d] = 0;
            break;
        case Role::None:
            p.reads[d] = makeDimRead({0});
            p.stride[d] = 0;
            break;
        }
    }
    return p;
}
} // namespace gridded_detail
} // namespace ompl_glider

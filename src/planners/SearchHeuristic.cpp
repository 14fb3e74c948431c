/// @file SearchHeuristic.cpp
/// @brief LatticeHeuristic (detail/SearchHeuristic.h): lower bounds of edge times from per-cell velocity boxes, the
/// optimistic backward search that makes them an A* heuristic, and its refinement over arrival windows; the boxes
/// themselves (currentBounds(), CellBoxCache) in VelocityBounds.cpp.

#include "detail/SearchHeuristic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
unsigned LatticeHeuristic::autoCellFactor(const Lattice &lattice)
{
    const double cells = static_cast<double>(lattice.nx()) * static_cast<double>(lattice.ny());
    return static_cast<unsigned>(std::max(1.0, std::ceil(std::sqrt(cells / 65536.0))));
}

VelocityBox LatticeHeuristic::box(long I, long J, double ta, double tb, const Region &region, unsigned slices) const
{
    if (cache_ && std::isfinite(ta) && std::isfinite(tb) && tb - ta <= 1e6)
    {
        VelocityBox b = cache_->box(I, J, ta, tb, stop_);
        const double M = vCap_ - V_;
        b = {std::max(b.uMin, -M), std::min(b.uMax, M), std::max(b.vMin, -M), std::min(b.vMax, M)};
        return b;
    }
    return currentBounds(field_, region, slices);
}

LatticeHeuristic::LatticeHeuristic(const Lattice &lattice, const CurrentField &field, double speed, double depth,
                                   double tBegin, double tEnd, unsigned cellFactor, CellBoxCache *cache,
                                   std::function<bool()> stop)
    : lat_(lattice), field_(field), depth_(depth), V_(speed), tBegin_(tBegin), tEnd_(tEnd),
      n_(static_cast<int>(lattice.sectors())), stop_(std::move(stop))
{
    if (!(speed > 0.0) || !std::isfinite(speed))
        throw Error("LatticeHeuristic: the vehicle speed must be finite and > 0");
    const long nx = lattice.nx(), ny = lattice.ny();
    if (cellFactor == 0)
        cellFactor = autoCellFactor(lattice);
    f_ = cellFactor;
    if (cache && cache->matches(&field, lattice, depth, f_, cache->origin(), cache->dt()))
        cache_ = cache;
    const long f = static_cast<long>(f_);
    NX_ = std::max(0L, nx - 1) / f + 1;
    NY_ = std::max(0L, ny - 1) / f + 1;
    const double g = lattice.gridSize();

    Region whole;
    whole.xMin = lattice.xMin();
    whole.yMin = lattice.yMin();
    whole.xMax = lattice.xMin() + g * static_cast<double>(nx - 1);
    whole.yMax = lattice.yMin() + g * static_cast<double>(ny - 1);
    whole.zMin = whole.zMax = depth;
    whole.tMin = tBegin;
    whole.tMax = tEnd;
    const double M = field.maxSpeed(whole);
    vCap_ = speed + M;
    if (!std::isfinite(vCap_))
        throw Error("LatticeHeuristic: the field has no finite bound of the current speed");

    // Time slices of the interval bound: about one per unit of the jet's time scale, at most 64.
    const unsigned slices =
        std::isfinite(tEnd - tBegin) ? static_cast<unsigned>(std::clamp(std::ceil(tEnd - tBegin), 1.0, 64.0)) : 1u;
    boxes_.assign(static_cast<std::size_t>(NX_ * NY_), VelocityBox{-M, M, -M, M});
    for (long J = 0; J < NY_ && hasLocalBounds(field) && !stopped(); ++J)
        for (long I = 0; I < NX_; ++I)
        {
            Region r = whole;
            r.xMin = lattice.xMin() + g * static_cast<double>(I * f);
            r.xMax = lattice.xMin() + g * static_cast<double>((I + 1) * f);
            r.yMin = lattice.yMin() + g * static_cast<double>(J * f);
            r.yMax = lattice.yMin() + g * static_cast<double>((J + 1) * f);
            const VelocityBox b = box(I, J, tBegin, tEnd, r, slices);
            boxes_[static_cast<std::size_t>(I + J * NX_)] = b;
            if (b.uMin > -M || b.uMax < M || b.vMin > -M || b.vMax < M)
                informative_ = true;
        }

    empty_.assign(boxes_.size(), 0);
    buildTable();
}

void LatticeHeuristic::buildTable()
{
    const Lattice &lattice = lat_;
    const long nx = lattice.nx(), ny = lattice.ny();
    const long f = static_cast<long>(f_);
    const double g = lattice.gridSize();
    const std::vector<LatticeOffset> &offs = lattice.offsets();
    const std::size_t K = offs.size();
    const int w = 2 * n_ + 1;
    offsetIndex_.assign(static_cast<std::size_t>(w * w), -1);
    len_.resize(K);
    for (std::size_t k = 0; k < K; ++k)
    {
        offsetIndex_[static_cast<std::size_t>((offs[k].dx + n_) + (offs[k].dy + n_) * w)] = static_cast<int>(k);
        len_[k] = g * std::hypot(static_cast<double>(offs[k].dx), static_cast<double>(offs[k].dy));
    }
    // Per coarse cell and offset: the largest speed bound over the coarse cells an edge leaving a vertex of the
    // cell along the offset can touch (the cells of its bounding box).
    invSpeed_.assign(static_cast<std::size_t>(NX_ * NY_) * K, 0.0);
    auto cellRange = [&](long C, int d, long nv, long ncells, long &lo, long &hi) {
        if (d == 0)
        {
            lo = hi = C; // the edge runs along a vertex line inside the closed cell
            return;
        }
        // lattice cells (spanning vertex lines c .. c + 1) crossed by edges from vertex lines C f .. C f + f - 1
        long a = C * f + std::min(0, d), b = C * f + f - 1 + std::max(0, d) - 1;
        a = std::clamp(a, 0L, std::max(0L, nv - 2));
        b = std::clamp(b, 0L, std::max(0L, nv - 2));
        lo = std::min(a / f, ncells - 1);
        hi = std::min(b / f, ncells - 1);
    };
    for (long J = 0; J < NY_; ++J)
        for (long I = 0; I < NX_; ++I)
            for (std::size_t k = 0; k < K; ++k)
            {
                long i0, i1, j0, j1;
                cellRange(I, offs[k].dx, nx, NX_, i0, i1);
                cellRange(J, offs[k].dy, ny, NY_, j0, j1);
                const double L = len_[k] / g;
                const double ex = offs[k].dx / L, ey = offs[k].dy / L;
                double s = 0.0;
                for (long jj = j0; jj <= j1; ++jj)
                    for (long ii = i0; ii <= i1; ++ii)
                        if (!empty_[static_cast<std::size_t>(ii + jj * NX_)])
                            s = std::max(s, speedBound(boxes_[static_cast<std::size_t>(ii + jj * NX_)], ex, ey));
                invSpeed_[static_cast<std::size_t>(I + J * NX_) * K + k] = s > 0.0 ? 1.0 / s : kInf;
            }
}

double LatticeHeuristic::speedBound(const VelocityBox &b, double ex, double ey) const
{
    const double ceMax = std::max(ex * b.uMin, ex * b.uMax) + std::max(ey * b.vMin, ey * b.vMax);
    // c.n with n = (-ey, ex)
    const double cnLo = std::min(-ey * b.uMin, -ey * b.uMax) + std::min(ex * b.vMin, ex * b.vMax);
    const double cnHi = std::max(-ey * b.uMin, -ey * b.uMax) + std::max(ex * b.vMin, ex * b.vMax);
    const double cnMin = (cnLo <= 0.0 && cnHi >= 0.0) ? 0.0 : std::min(std::abs(cnLo), std::abs(cnHi));
    if (cnMin >= V_)
        return 0.0; // |c.n| >= V everywhere: the leg cannot be held ([EichhornRAS] Eq. 5)
    const double s = std::min(ceMax + std::sqrt(V_ * V_ - cnMin * cnMin), vCap_);
    return s > 0.0 ? s * (1.0 + 1e-12) : 0.0;
}

double LatticeHeuristic::genericBound(double x1, double y1, double x2, double y2) const
{
    const double len = std::hypot(x2 - x1, y2 - y1);
    if (!(len > 0.0))
        return 0.0;
    const double g = lat_.gridSize();
    const double ex = (x2 - x1) / len, ey = (y2 - y1) / len;
    auto cellIdx = [&](double c, double origin, long ncells) {
        const double fc = std::floor((c - origin) / (g * f_));
        return static_cast<long>(std::clamp(fc, 0.0, static_cast<double>(ncells - 1)));
    };
    // the cells covering the segment's bounding box (and the neighbours of cells whose boundary it touches)
    const long i0 = std::max(0L, cellIdx(std::min(x1, x2), lat_.xMin(), NX_) - 1);
    const long i1 = std::min(NX_ - 1, cellIdx(std::max(x1, x2), lat_.xMin(), NX_) + 1);
    const long j0 = std::max(0L, cellIdx(std::min(y1, y2), lat_.yMin(), NY_) - 1);
    const long j1 = std::min(NY_ - 1, cellIdx(std::max(y1, y2), lat_.yMin(), NY_) + 1);
    double s = 0.0;
    for (long j = j0; j <= j1; ++j)
        for (long i = i0; i <= i1; ++i)
            if (!empty_[static_cast<std::size_t>(i + j * NX_)])
                s = std::max(s, speedBound(boxes_[static_cast<std::size_t>(i + j * NX_)], ex, ey));
    return s > 0.0 ? len / s : kInf;
}

double LatticeHeuristic::edgeLowerBound(Lattice::VertexId u, Lattice::VertexId v) const
{
    const std::size_t G = lat_.numGridVertices();
    if (u < G && v < G)
    {
        const long iu = lat_.columnOf(u), ju = lat_.rowOf(u);
        const long dx = lat_.columnOf(v) - iu, dy = lat_.rowOf(v) - ju;
        const int w = 2 * n_ + 1;
        if (std::labs(dx) <= n_ && std::labs(dy) <= n_)
        {
            const int k = offsetIndex_[static_cast<std::size_t>((dx + n_) + (dy + n_) * w)];
            if (k >= 0)
            {
                const std::size_t C = static_cast<std::size_t>(cellOfColumn(iu) + cellOfRow(ju) * NX_);
                const double inv = invSpeed_[C * len_.size() + static_cast<std::size_t>(k)];
                return std::isfinite(inv) ? len_[static_cast<std::size_t>(k)] * inv : kInf;
            }
        }
    }
    return genericBound(lat_.x(u), lat_.y(u), lat_.x(v), lat_.y(v));
}

bool LatticeHeuristic::hasLocalBounds(const CurrentField &field)
{
    return dynamic_cast<const MeanderingJet *>(&field) != nullptr || field.hasVelocityBounds();
}

bool LatticeHeuristic::hasSlicedBounds(const CurrentField &field)
{
    return dynamic_cast<const MeanderingJet *>(&field) != nullptr;
}

long LatticeHeuristic::cellOfVertex(Lattice::VertexId v) const
{
    if (v < lat_.numGridVertices())
        return cellOfColumn(lat_.columnOf(v)) + cellOfRow(lat_.rowOf(v)) * NX_;
    const double g = lat_.gridSize() * f_;
    const long I = std::clamp(static_cast<long>(std::floor((lat_.x(v) - lat_.xMin()) / g)), 0L, NX_ - 1);
    const long J = std::clamp(static_cast<long>(std::floor((lat_.y(v) - lat_.yMin()) / g)), 0L, NY_ - 1);
    return I + J * NX_;
}

std::vector<double> LatticeHeuristic::staticSearch(bool forward,
                                                   const std::function<bool(Lattice::VertexId)> &inWater) const
{
    std::vector<double> d(lat_.numVertices(), kInf);
    const Lattice::VertexId src = forward ? lat_.start() : lat_.goal();
    if (src == Lattice::kNone)
        return d;
    std::priority_queue<QEntry, std::vector<QEntry>, std::greater<QEntry>> q;
    d[src] = 0.0;
    q.push({0.0, src});
    while (!q.empty())
    {
        const QEntry e = q.top();
        q.pop();
        if (e.d > d[e.v])
            continue;
        auto visit = [&](Lattice::VertexId y) {
            if (inWater && !inWater(y))
                return;
            const double w = forward ? edgeLowerBound(e.v, y) : edgeLowerBound(y, e.v);
            if (e.d + w < d[y])
            {
                d[y] = e.d + w;
                q.push({d[y], y});
            }
        };
        if (forward)
            lat_.forEachSuccessor(e.v, visit);
        else
            lat_.forEachPredecessor(e.v, visit);
    }
    return d;
}

void LatticeHeuristic::refineWindows(unsigned rounds, const std::function<bool(Lattice::VertexId)> &inWater)
{
    if (!std::isfinite(tEnd_) || lat_.start() == Lattice::kNone || lat_.goal() == Lattice::kNone)
        return;
    const std::size_t C = boxes_.size();
    const long rc = n_ / static_cast<long>(f_) + 1;
    const double g = lat_.gridSize();
    const long f = static_cast<long>(f_);
    for (unsigned r = 0; r < rounds && !stopped(); ++r)
    {
        const std::vector<double> a = staticSearch(true, inWater);
        std::vector<double> h = staticSearch(false, inWater);
        if (lat_.start() == lat_.startExtra())
            lat_.forEachSuccessor(lat_.start(), [&](Lattice::VertexId y) {
                h[lat_.start()] = std::min(h[lat_.start()], edgeLowerBound(lat_.start(), y) + h[y]);
            });
        std::vector<double> minA(C, kInf), minH(C, kInf);
        for (Lattice::VertexId v = 0; v < lat_.numVertices(); ++v)
        {
            if (!(a[v] < kInf) || !(h[v] < kInf))
                continue; // on no path from the start to the goal
            if ((v == lat_.startExtra() && v != lat_.start()) || (v == lat_.goalExtra() && v != lat_.goal()))
                continue; // unused extra vertex
            if (tBegin_ + a[v] + h[v] > tEnd_)
                continue; // no path through v arrives by the deadline
            const std::size_t c = static_cast<std::size_t>(cellOfVertex(v));
            minA[c] = std::min(minA[c], a[v]);
            minH[c] = std::min(minH[c], h[v]);
        }
        for (long J = 0; J < NY_; ++J)
            for (long I = 0; I < NX_; ++I)
            {
                double lo = kInf, hiH = kInf;
                for (long jj = std::max(0L, J - rc); jj <= std::min(NY_ - 1, J + rc); ++jj)
                    for (long ii = std::max(0L, I - rc); ii <= std::min(NX_ - 1, I + rc); ++ii)
                    {
                        lo = std::min(lo, minA[static_cast<std::size_t>(ii + jj * NX_)]);
                        hiH = std::min(hiH, minH[static_cast<std::size_t>(ii + jj * NX_)]);
                    }
                const std::size_t c = static_cast<std::size_t>(I + J * NX_);
                const double t1 = tBegin_ + lo, t2 = tEnd_ - hiH;
                if (!(t1 <= t2))
                {
                    empty_[c] = 1;
                    continue;
                }
                Region reg;
                reg.xMin = lat_.xMin() + g * static_cast<double>(I * f);
                reg.xMax = lat_.xMin() + g * static_cast<double>((I + 1) * f);
                reg.yMin = lat_.yMin() + g * static_cast<double>(J * f);
                reg.yMax = lat_.yMin() + g * static_cast<double>((J + 1) * f);
                reg.zMin = reg.zMax = depth_;
                reg.tMin = t1;
                reg.tMax = t2;
                const VelocityBox b =
                    box(I, J, t1, t2, reg, static_cast<unsigned>(std::clamp(std::ceil(t2 - t1), 1.0, 64.0)));
                // never wider than the previous round's box (both bound the same currents)
                VelocityBox &old = boxes_[c];
                old = {std::max(old.uMin, b.uMin), std::min(old.uMax, b.uMax), std::max(old.vMin, b.vMin),
                       std::min(old.vMax, b.vMax)};
                if (old.uMin > old.uMax || old.vMin > old.vMax)
                    empty_[c] = 1;
            }
        buildTable();
    }
    labels_.reset(lat_, Label{});
    queue_ = {};
    settled_ = 0;
}

void LatticeHeuristic::reset(std::function<bool(Lattice::VertexId)> inWater)
{
    inWater_ = std::move(inWater);
    labels_.reset(lat_, Label{});
    queue_ = {};
    settled_ = 0;
    const Lattice::VertexId g = lat_.goal();
    if (g == Lattice::kNone)
        return;
    labels_.ref(g) = {0.0, false};
    queue_.push({0.0, g});
}

double LatticeHeuristic::operator()(Lattice::VertexId v)
{
    if (v == lat_.startExtra() && v != lat_.goal())
        return 0.0;
    {
        const Label &l = labels_.get(v);
        if (l.settled)
            return l.d;
    }
    for (unsigned pops = 1; !queue_.empty(); ++pops)
    {
        if (pops % 4096 == 0 && stopped())
            return 0.0; // a lower bound; the search that asked is stopping
        const QEntry e = queue_.top();
        queue_.pop();
        Label &lab = labels_.ref(e.v);
        if (lab.settled || e.d > lab.d)
            continue;
        lab.settled = true;
        ++settled_;
        const Lattice::VertexId x = e.v;
        lat_.forEachPredecessor(x, [&](Lattice::VertexId u) {
            const double w = edgeLowerBound(u, x);
            if (!std::isfinite(w))
                return;
            const double nd = e.d + w;
            Label &lu = labels_.ref(u);
            if (lu.settled || !(nd < lu.d))
                return;
            const bool first = lu.d == kInf;
            lu.d = nd;
            if (first && inWater_ && !inWater_(u))
            {
                lu.d = kInf; // land: never enters the search
                lu.settled = true;
                return;
            }
            queue_.push({nd, u});
        });
        if (x == v)
            return e.d;
    }
    return kInf;
}
} // namespace ompl_glider

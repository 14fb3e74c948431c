/// @file VelocityBounds.cpp
/// @brief Bounds of the current over boxes of space and time for the lattice search's heuristic
/// (detail/SearchHeuristic.h): currentBounds() (interval arithmetic on the meandering jet's closed form, else the
/// field's own bounds) and the per-cell boxes of CellBoxCache. LatticeHeuristic, which uses them, is in
/// SearchHeuristic.cpp.

#include "detail/SearchHeuristic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

/// A closed interval [lo, hi] (interval arithmetic: every operation encloses all values of the operation on members
/// of its operands; rounding is covered by the relative margin applied to the final box).
struct Iv
{
    double lo, hi;
};
Iv add(Iv a, Iv b)
{
    return {a.lo + b.lo, a.hi + b.hi};
}
Iv sub(Iv a, Iv b)
{
    return {a.lo - b.hi, a.hi - b.lo};
}
Iv mul(Iv a, Iv b)
{
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
Iv scale(double k, Iv a)
{
    return k >= 0 ? Iv{k * a.lo, k * a.hi} : Iv{k * a.hi, k * a.lo};
}
/// a / b for b > 0.
Iv divPos(Iv a, Iv b)
{
    return mul(a, Iv{1.0 / b.hi, 1.0 / b.lo});
}
Iv sq(Iv a)
{
    if (a.lo >= 0)
        return {a.lo * a.lo, a.hi * a.hi};
    if (a.hi <= 0)
        return {a.hi * a.hi, a.lo * a.lo};
    return {0.0, std::max(a.lo * a.lo, a.hi * a.hi)};
}
/// sin over [a.lo, a.hi].
Iv sinI(Iv a)
{
    if (!(a.hi - a.lo < 2.0 * kPi) || !std::isfinite(a.lo) || !std::isfinite(a.hi))
        return {-1.0, 1.0};
    double lo = std::min(std::sin(a.lo), std::sin(a.hi)), hi = std::max(std::sin(a.lo), std::sin(a.hi));
    // a maximum pi/2 + 2 pi m inside?
    if (std::ceil((a.lo - kPi / 2) / (2 * kPi)) <= std::floor((a.hi - kPi / 2) / (2 * kPi)))
        hi = 1.0;
    if (std::ceil((a.lo + kPi / 2) / (2 * kPi)) <= std::floor((a.hi + kPi / 2) / (2 * kPi)))
        lo = -1.0;
    return {lo, hi};
}
Iv cosI(Iv a)
{
    return sinI({a.lo + kPi / 2, a.hi + kPi / 2});
}

/// Encloses (u, v) of the meandering jet ([EichhornRAS] Eq. 7-9, as MeanderingJet evaluates it) over X x Y x T.
VelocityBox jetBox(const MeanderingJetParams &p, Iv X, Iv Y, Iv T)
{
    const Iv B = add({p.B0, p.B0}, scale(p.epsilon, cosI(add(scale(p.omega, T), {p.theta, p.theta}))));
    const Iv th = scale(p.k, sub(X, scale(p.c, T)));
    const Iv sn = sinI(th), cs = cosI(th);
    const Iv N = sub(Y, mul(B, cs));
    const Iv B2 = sq(B);
    const Iv D = [&] {
        const Iv q = add({1.0, 1.0}, scale(p.k * p.k, mul(B2, sq(sn))));
        return Iv{std::sqrt(std::max(1.0, q.lo)), std::sqrt(std::max(1.0, q.hi))};
    }();
    const Iv s = divPos(N, D);
    // g = sech^2(s), decreasing in |s|
    const double sAbsMin = (s.lo <= 0 && s.hi >= 0) ? 0.0 : std::min(std::abs(s.lo), std::abs(s.hi));
    const double sAbsMax = std::max(std::abs(s.lo), std::abs(s.hi));
    auto sech2 = [](double x) {
        const double c = std::cosh(std::min(x, 300.0));
        return 1.0 / (c * c);
    };
    const Iv g{sech2(sAbsMax), sech2(sAbsMin)};
    const Iv u = divPos(g, D);
    const double k3 = p.k * p.k * p.k;
    const Iv Dx = divPos(scale(k3, mul(B2, mul(sn, cs))), D);
    const Iv sx = sub(divPos(scale(p.k, mul(B, sn)), D), divPos(mul(N, Dx), sq(D)));
    const Iv v = scale(-1.0, mul(g, sx));
    return {u.lo, u.hi, v.lo, v.hi};
}
} // namespace

VelocityBox currentBounds(const CurrentField &field, const Region &region, unsigned timeSlices)
{
    constexpr int kSub = 2; // 2 x 2 sub-boxes (4 x 4 and quarter time slices: 3.7x instead of 3.3x fewer CFC than
                            // TVE on bench_search's random pairs, at 7x the wall time)
    const double M = field.maxSpeed(region);
    VelocityBox box{-M, M, -M, M};
    if (const auto *jet = dynamic_cast<const MeanderingJet *>(&field))
    {
        const bool finiteT = std::isfinite(region.tMin) && std::isfinite(region.tMax);
        const unsigned nt = finiteT ? std::max(1u, timeSlices) : 1u;
        VelocityBox b{kInf, -kInf, kInf, -kInf};
        for (unsigned it = 0; it < nt; ++it)
        {
            const Iv T = finiteT ? Iv{region.tMin + (region.tMax - region.tMin) * it / nt,
                                      region.tMin + (region.tMax - region.tMin) * (it + 1) / nt}
                                 : Iv{-kInf, kInf};
            for (int a = 0; a < kSub; ++a)
                for (int c = 0; c < kSub; ++c)
                {
                    const double wx = (region.xMax - region.xMin) / kSub, wy = (region.yMax - region.yMin) / kSub;
                    const Iv X{region.xMin + a * wx, a + 1 == kSub ? region.xMax : region.xMin + (a + 1) * wx};
                    const Iv Y{region.yMin + c * wy, c + 1 == kSub ? region.yMax : region.yMin + (c + 1) * wy};
                    VelocityBox e = jetBox(jet->params(), X, Y, T);
                    if (!finiteT)
                        e = VelocityBox{-M, M, -M, M};
                    b.uMin = std::min(b.uMin, e.uMin);
                    b.uMax = std::max(b.uMax, e.uMax);
                    b.vMin = std::min(b.vMin, e.vMin);
                    b.vMax = std::max(b.vMax, e.vMax);
                }
        }
        // a small margin for rounding in the interval operations and in the field's own evaluation
        const double m = 1e-9 * (1.0 + M);
        if (std::isfinite(b.uMin) && std::isfinite(b.uMax) && std::isfinite(b.vMin) && std::isfinite(b.vMax))
            box = {b.uMin - m, b.uMax + m, b.vMin - m, b.vMax + m};
    }
    else
    {
        VelocityBox b;
        if (field.velocityBounds(region, b.uMin, b.uMax, b.vMin, b.vMax))
            box = b; // the field's own local bounds (a gridded field's node extremes)
    }
    box.uMin = std::max(box.uMin, -M);
    box.vMin = std::max(box.vMin, -M);
    box.uMax = std::min(box.uMax, M);
    box.vMax = std::min(box.vMax, M);
    return box;
}

CellBoxCache::CellBoxCache(std::shared_ptr<const CurrentField> field, const Lattice &lattice, double depth,
                           unsigned cellFactor, double origin, double dt)
    : field_(std::move(field)), xMin_(lattice.xMin()), yMin_(lattice.yMin()), g_(lattice.gridSize()), nx_(lattice.nx()),
      ny_(lattice.ny()), depth_(depth), origin_(origin), dt_(dt), f_(std::max(1u, cellFactor))
{
    const long f = static_cast<long>(f_);
    NX_ = std::max(0L, nx_ - 1) / f + 1;
    NY_ = std::max(0L, ny_ - 1) / f + 1;
}

bool CellBoxCache::matches(const CurrentField *field, const Lattice &lattice, double depth, unsigned cellFactor,
                           double origin, double dt) const
{
    return field == field_.get() && lattice.xMin() == xMin_ && lattice.yMin() == yMin_ && lattice.gridSize() == g_ &&
           lattice.nx() == nx_ && lattice.ny() == ny_ && depth == depth_ && std::max(1u, cellFactor) == f_ &&
           origin == origin_ && dt == dt_;
}

std::shared_ptr<CellBoxCache> CellBoxCache::shared(const std::shared_ptr<const CurrentField> &field,
                                                   const Lattice &lattice, double depth, unsigned cellFactor,
                                                   double origin, double dt)
{
    static std::mutex m;
    static std::vector<std::shared_ptr<CellBoxCache>> caches;
    const std::lock_guard<std::mutex> lock(m);
    for (const auto &c : caches)
        if (c->matches(field.get(), lattice, depth, cellFactor, origin, dt))
            return c;
    if (caches.size() >= 16)
        caches.erase(caches.begin());
    caches.push_back(std::make_shared<CellBoxCache>(field, lattice, depth, cellFactor, origin, dt));
    return caches.back();
}

VelocityBox CellBoxCache::box(long I, long J, double ta, double tb, const std::function<bool()> &stop)
{
    const std::lock_guard<std::mutex> lock(mutex_);
    const long k0 = static_cast<long>(std::floor((ta - origin_) / dt_));
    const long k1 = std::max(k0, static_cast<long>(std::ceil((tb - origin_) / dt_)) - 1);
    VelocityBox out{kInf, -kInf, kInf, -kInf};
    const double g = g_;
    const long f = static_cast<long>(f_);
    for (long k = k0; k <= k1; ++k)
    {
        if (slices_.find(k) == slices_.end() && stop && stop())
            return {-kInf, kInf, -kInf, kInf};
        auto [it, inserted] = slices_.try_emplace(k);
        if (inserted)
        {
            it->second.resize(static_cast<std::size_t>(NX_ * NY_));
            for (long jj = 0; jj < NY_; ++jj)
                for (long ii = 0; ii < NX_; ++ii)
                {
                    Region r;
                    r.xMin = xMin_ + g * static_cast<double>(ii * f);
                    r.xMax = xMin_ + g * static_cast<double>((ii + 1) * f);
                    r.yMin = yMin_ + g * static_cast<double>(jj * f);
                    r.yMax = yMin_ + g * static_cast<double>((jj + 1) * f);
                    r.zMin = r.zMax = depth_;
                    r.tMin = origin_ + dt_ * static_cast<double>(k);
                    r.tMax = origin_ + dt_ * static_cast<double>(k + 1);
                    it->second[static_cast<std::size_t>(ii + jj * NX_)] = currentBounds(*field_, r, 1);
                }
        }
        const VelocityBox &b = it->second[static_cast<std::size_t>(I + J * NX_)];
        out = {std::min(out.uMin, b.uMin), std::max(out.uMax, b.uMax), std::min(out.vMin, b.vMin),
               std::max(out.vMax, b.vMax)};
    }
    return out;
}
} // namespace ompl_glider

#include "detail/Lattice.h"
#include "ompl_glider/ompl/Sectors.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <sstream>
#include <string>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
std::string formatPoint(double x, double y)
{
    std::ostringstream os;
    os << "(" << x << ", " << y << ")";
    return os.str();
}

Lattice::Lattice(double xMin, double xMax, double yMin, double yMax, double gridSize, unsigned sectors)
    : xMin_(xMin), xMax_(xMax), yMin_(yMin), yMax_(yMax), g_(gridSize), sectors_(sectors)
{
    if (!std::isfinite(xMin) || !std::isfinite(xMax) || !std::isfinite(yMin) || !std::isfinite(yMax) ||
        !(xMax > xMin) || !(yMax > yMin))
        throw Error("Lattice: bounds must be finite with xMin < xMax and yMin < yMax (got x [" + std::to_string(xMin) +
                    ", " + std::to_string(xMax) + "], y [" + std::to_string(yMin) + ", " + std::to_string(yMax) + "])");
    if (!(gridSize > 0.0) || !std::isfinite(gridSize))
        throw Error("Lattice: grid_size must be a finite number > 0 (got " + std::to_string(gridSize) + ")");
    if (sectors < kMinSectors || sectors > kMaxSectors)
        throw Error("Lattice: sectors must be in " + std::to_string(kMinSectors) + ".." + std::to_string(kMaxSectors) +
                    " (got " + std::to_string(sectors) + ")");
    const double cx = std::floor((xMax - xMin) / gridSize + 1e-9) + 1.0;
    const double cy = std::floor((yMax - yMin) / gridSize + 1e-9) + 1.0;
    if (cx * cy > 2147483648.0)
        throw Error("Lattice: grid_size " + std::to_string(gridSize) + " gives more than 2^31 vertices");
    nx_ = static_cast<long>(cx);
    ny_ = static_cast<long>(cy);
    offsets_ = offsets(sectors);
    angles_.reserve(offsets_.size());
    for (const LatticeOffset &o : offsets_)
        angles_.push_back(std::atan2(static_cast<double>(o.dy), static_cast<double>(o.dx)));
}

std::vector<LatticeOffset> Lattice::offsets(unsigned sectors)
{
    std::vector<LatticeOffset> out;
    const int n = static_cast<int>(sectors);
    for (int dy = -n; dy <= n; ++dy)
        for (int dx = -n; dx <= n; ++dx)
            if ((dx != 0 || dy != 0) && std::gcd(std::abs(dx), std::abs(dy)) == 1)
                out.push_back({dx, dy});
    std::sort(out.begin(), out.end(), [](const LatticeOffset &a, const LatticeOffset &b) {
        return std::atan2(a.dy, a.dx) < std::atan2(b.dy, b.dx);
    });
    return out;
}

bool Lattice::inNeighbourhood(long dx, long dy) const
{
    const long ax = std::labs(dx), ay = std::labs(dy);
    if (ax == 0 && ay == 0)
        return true;
    return std::max(ax, ay) <= static_cast<long>(sectors_) && std::gcd(ax, ay) == 1;
}

Lattice::VertexId Lattice::join(double x, double y, long &ai, long &aj, bool &inside) const
{
    inside = false;
    if (!std::isfinite(x) || !std::isfinite(y))
        return kNone;
    const double fi = (x - xMin_) / g_, fj = (y - yMin_) / g_;
    const double tol = 1e-9;
    if (fi < -tol || fj < -tol || x > xMax_ + tol * g_ || y > yMax_ + tol * g_)
        return kNone;
    inside = true;
    ai = std::clamp(std::lround(fi), 0L, nx_ - 1);
    aj = std::clamp(std::lround(fj), 0L, ny_ - 1);
    if (std::abs(fi - static_cast<double>(ai)) <= tol && std::abs(fj - static_cast<double>(aj)) <= tol)
        return gridVertex(ai, aj);
    return kNone;
}

Lattice::VertexId Lattice::setStart(double x, double y)
{
    bool inside = false;
    const VertexId v = join(x, y, startAnchorI_, startAnchorJ_, inside);
    if (!inside)
        return start_ = kNone;
    startIsExtra_ = v == kNone;
    startX_ = x;
    startY_ = y;
    return start_ = startIsExtra_ ? startExtra() : v;
}

Lattice::VertexId Lattice::setGoal(double x, double y)
{
    bool inside = false;
    const VertexId v = join(x, y, goalAnchorI_, goalAnchorJ_, inside);
    if (!inside)
    {
        goalIsExtra_ = false;
        return goal_ = kNone;
    }
    goalIsExtra_ = v == kNone;
    goalX_ = x;
    goalY_ = y;
    return goal_ = goalIsExtra_ ? goalExtra() : v;
}

double Lattice::x(VertexId v) const
{
    if (v == startExtra())
        return startX_;
    if (v == goalExtra())
        return goalX_;
    return xMin_ + g_ * static_cast<double>(column(v));
}

double Lattice::y(VertexId v) const
{
    if (v == startExtra())
        return startY_;
    if (v == goalExtra())
        return goalY_;
    return yMin_ + g_ * static_cast<double>(row(v));
}
} // namespace ompl_glider

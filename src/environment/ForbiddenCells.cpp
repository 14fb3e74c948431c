// A union of forbidden grid cells (see ForbiddenCells.h).
#include "ompl_glider/environment/ForbiddenCells.h"

#include <algorithm>
#include <cmath>

#include "SegmentIndex.h"
#include "ompl_glider/Exception.h"

namespace ompl_glider
{
using environment_detail::SegmentIndex;

ForbiddenCells::ForbiddenCells(std::string name, std::string kind, std::size_t nx, std::size_t ny,
                               std::vector<Point2> nodes, const std::vector<std::uint8_t> &forbidden)
    : ForbiddenRegion(std::move(name), std::move(kind)), nx_(nx), nodes_(std::move(nodes))
{
    if (nx < 2 || ny < 2 || nodes_.size() != nx * ny || forbidden.size() != (nx - 1) * (ny - 1))
        throw Error("ForbiddenCells '" + this->name() + "': the node and cell arrays do not fit " + std::to_string(nx) +
                    " x " + std::to_string(ny) + " nodes");
    const std::size_t cx = nx - 1, cy = ny - 1;
    auto finite = [&](std::size_t n) { return std::isfinite(nodes_[n].x) && std::isfinite(nodes_[n].y); };
    auto usable = [&](std::size_t i, std::size_t j) {
        return finite(j * nx + i) && finite(j * nx + i + 1) && finite((j + 1) * nx + i) && finite((j + 1) * nx + i + 1);
    };
    auto bad = [&](std::size_t i, std::size_t j) { return forbidden[j * cx + i] != 0 && usable(i, j); };
    std::vector<Segment2> edges;
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL, size = 0.0;
    for (std::size_t j = 0; j < cy; ++j)
        for (std::size_t i = 0; i < cx; ++i)
        {
            if (!bad(i, j))
                continue;
            cells_.push_back(static_cast<std::uint32_t>(j * cx + i));
            const std::size_t n[4] = {j * nx + i, j * nx + i + 1, (j + 1) * nx + i + 1, (j + 1) * nx + i};
            for (std::size_t c : n)
            {
                x0 = std::min(x0, nodes_[c].x);
                x1 = std::max(x1, nodes_[c].x);
                y0 = std::min(y0, nodes_[c].y);
                y1 = std::max(y1, nodes_[c].y);
            }
            size += std::hypot(nodes_[n[1]].x - nodes_[n[0]].x, nodes_[n[1]].y - nodes_[n[0]].y);
            // the cell's sides that border a cell which is not forbidden (or the outside)
            if (j == 0 || !bad(i, j - 1))
                edges.push_back({nodes_[n[0]], nodes_[n[1]]});
            if (i + 1 == cx || !bad(i + 1, j))
                edges.push_back({nodes_[n[1]], nodes_[n[2]]});
            if (j + 1 == cy || !bad(i, j + 1))
                edges.push_back({nodes_[n[2]], nodes_[n[3]]});
            if (i == 0 || !bad(i - 1, j))
                edges.push_back({nodes_[n[3]], nodes_[n[0]]});
        }
    edges_ = std::make_unique<SegmentIndex>(std::move(edges));
    if (cells_.empty())
        return;
    // the cells in square buckets about one cell wide (at most 2^22)
    x0_ = x0;
    y0_ = y0;
    side_ = std::max({size / double(cells_.size()), 1e-9 * std::hypot(x1 - x0, y1 - y0), 1e-300});
    for (;;)
    {
        bnx_ = static_cast<std::size_t>((x1 - x0) / side_) + 1;
        bny_ = static_cast<std::size_t>((y1 - y0) / side_) + 1;
        if (bnx_ * bny_ <= (std::size_t(1) << 22))
            break;
        side_ *= 2.0;
    }
    auto each = [&](std::uint32_t c, auto &&f) {
        const std::size_t i = c % cx, j = c / cx;
        const std::size_t n[4] = {j * nx + i, j * nx + i + 1, (j + 1) * nx + i + 1, (j + 1) * nx + i};
        double a0 = HUGE_VAL, a1 = -HUGE_VAL, b0 = HUGE_VAL, b1 = -HUGE_VAL;
        for (std::size_t q : n)
        {
            a0 = std::min(a0, nodes_[q].x);
            a1 = std::max(a1, nodes_[q].x);
            b0 = std::min(b0, nodes_[q].y);
            b1 = std::max(b1, nodes_[q].y);
        }
        const auto col = [&](double x) {
            return std::min(bnx_ - 1, static_cast<std::size_t>(std::max(0.0, (x - x0_) / side_)));
        };
        const auto row = [&](double y) {
            return std::min(bny_ - 1, static_cast<std::size_t>(std::max(0.0, (y - y0_) / side_)));
        };
        for (std::size_t r = row(b0); r <= row(b1); ++r)
            for (std::size_t q = col(a0); q <= col(a1); ++q)
                f(r * bnx_ + q);
    };
    start_.assign(bnx_ * bny_ + 1, 0);
    for (std::uint32_t c : cells_)
        each(c, [&](std::size_t b) { ++start_[b + 1]; });
    for (std::size_t b = 0; b + 1 < start_.size(); ++b)
        start_[b + 1] += start_[b];
    ids_.assign(start_.back(), 0);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t c : cells_)
        each(c, [&](std::size_t b) { ids_[fill[b]++] = c; });
}

ForbiddenCells::~ForbiddenCells() = default;

const std::vector<Segment2> &ForbiddenCells::boundary() const
{
    return edges_->segments();
}

bool ForbiddenCells::inCell(std::uint32_t c, double x, double y) const
{
    const std::size_t cx = nx_ - 1, i = c % cx, j = c / cx;
    const Point2 q[4] = {nodes_[j * nx_ + i], nodes_[j * nx_ + i + 1], nodes_[(j + 1) * nx_ + i + 1],
                         nodes_[(j + 1) * nx_ + i]};
    bool in = false;
    for (int k = 0; k < 4; ++k)
    {
        const Point2 a = q[k], b = q[(k + 1) % 4];
        if (environment_detail::pointSegmentDistance({x, y}, a, b) == 0.0)
            return true; // closed: the boundary belongs to the cell
        if ((a.y > y) != (b.y > y) && x < a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y))
            in = !in;
    }
    return in;
}

bool ForbiddenCells::pointFree(double x, double y, double) const
{
    if (!std::isfinite(x) || !std::isfinite(y))
        return false;
    if (cells_.empty())
        return true;
    const double qx = (x - x0_) / side_, qy = (y - y0_) / side_;
    if (qx < 0.0 || qy < 0.0 || qx >= double(bnx_) || qy >= double(bny_))
        return true;
    const std::size_t b = static_cast<std::size_t>(qy) * bnx_ + static_cast<std::size_t>(qx);
    for (std::uint32_t k = start_[b]; k < start_[b + 1]; ++k)
        if (inCell(ids_[k], x, y))
            return false;
    return true;
}

bool ForbiddenCells::legFree(double x1, double y1, double t1, double x2, double y2, double t2) const
{
    if (!std::isfinite(t1) || !std::isfinite(t2) || !pointFree(x1, y1, t1) || !pointFree(x2, y2, t2))
        return false;
    return edges_->within({x1, y1}, {x2, y2}, 0.0) > 0.0;
}
} // namespace ompl_glider

/// @file GriddedLocator.cpp
/// @brief Locating a point in the grid of GriddedCurrentField: the bucket index of curvilinear grids, the inverse
/// bilinear map of a cell, locate(), and the horizontal stencils of a query (horizontal()).

#include "ompl_glider/current/GriddedCurrentField.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include "../core/Numbers.h"

namespace ompl_glider
{
namespace
{

/// The bilinear map (a, b) -> p00 + a e + b f + a b g of the curvilinear cell (ci, cj) with corners p00, p10 = p00 +
/// e, p01 = p00 + f and p11 = p00 + e + f + g.
struct CellMap
{
    double x00, y00, ex, ey, fx, fy, gx, gy;

    CellMap(const std::vector<double> &nodeX, const std::vector<double> &nodeY, std::size_t nx, std::size_t ci,
            std::size_t cj)
    {
        const std::size_t n00 = cj * nx + ci, n10 = n00 + 1, n01 = n00 + nx, n11 = n01 + 1;
        x00 = nodeX[n00];
        y00 = nodeY[n00];
        ex = nodeX[n10] - x00;
        ey = nodeY[n10] - y00;
        fx = nodeX[n01] - x00;
        fy = nodeY[n01] - y00;
        gx = nodeX[n11] - nodeX[n10] - nodeX[n01] + x00;
        gy = nodeY[n11] - nodeY[n10] - nodeY[n01] + y00;
    }

    /// Jacobian d(x, y)/d(a, b) = [j11 j12; j21 j22] at (a, b); returns its determinant.
    double jacobian(double a, double b, double &j11, double &j12, double &j21, double &j22) const
    {
        j11 = ex + b * gx;
        j12 = fx + a * gx;
        j21 = ey + b * gy;
        j22 = fy + a * gy;
        return j11 * j22 - j12 * j21;
    }
};
} // namespace

void GriddedCurrentField::buildLocator()
{
    const std::size_t cx = nx_ - 1, cy = ny_ - 1, nc = cx * cy;
    const double w = std::max(xMax_ - xMin_, 1e-300), h = std::max(yMax_ - yMin_, 1e-300);
    double s = std::sqrt(w * h / double(nc));
    bnx_ = static_cast<std::size_t>(std::ceil(w / s)) + 1;
    bny_ = static_cast<std::size_t>(std::ceil(h / s)) + 1;
    while (bnx_ * bny_ > 4 * nc + 16)
    {
        s *= 1.5;
        bnx_ = static_cast<std::size_t>(std::ceil(w / s)) + 1;
        bny_ = static_cast<std::size_t>(std::ceil(h / s)) + 1;
    }
    bx0_ = xMin_;
    by0_ = yMin_;
    bInv_ = 1.0 / s;
    bucket_.assign(bnx_ * bny_, -1);
    std::deque<std::size_t> queue;
    for (std::size_t j = 0; j < cy; ++j)
        for (std::size_t i = 0; i < cx; ++i)
        {
            const std::size_t n[4] = {j * nx_ + i, j * nx_ + i + 1, (j + 1) * nx_ + i, (j + 1) * nx_ + i + 1};
            double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
            for (std::size_t q : n)
            {
                x0 = std::min(x0, nodeX_[q]);
                x1 = std::max(x1, nodeX_[q]);
                y0 = std::min(y0, nodeY_[q]);
                y1 = std::max(y1, nodeY_[q]);
            }
            const std::size_t bi0 = static_cast<std::size_t>((x0 - bx0_) * bInv_);
            const std::size_t bi1 = std::min(bnx_ - 1, static_cast<std::size_t>((x1 - bx0_) * bInv_));
            const std::size_t bj0 = static_cast<std::size_t>((y0 - by0_) * bInv_);
            const std::size_t bj1 = std::min(bny_ - 1, static_cast<std::size_t>((y1 - by0_) * bInv_));
            for (std::size_t bj = bj0; bj <= bj1; ++bj)
                for (std::size_t bi = bi0; bi <= bi1; ++bi)
                    if (bucket_[bj * bnx_ + bi] < 0)
                    {
                        bucket_[bj * bnx_ + bi] = static_cast<std::int32_t>(j * cx + i);
                        queue.push_back(bj * bnx_ + bi);
                    }
        }
    // Empty buckets (outside the mesh) get a neighbour's cell so that the walk starts nearby.
    while (!queue.empty())
    {
        const std::size_t b = queue.front();
        queue.pop_front();
        const std::size_t bi = b % bnx_, bj = b / bnx_;
        const std::size_t nb[4] = {bi > 0 ? b - 1 : b, bi + 1 < bnx_ ? b + 1 : b, bj > 0 ? b - bnx_ : b,
                                   bj + 1 < bny_ ? b + bnx_ : b};
        for (std::size_t q : nb)
            if (bucket_[q] < 0)
            {
                bucket_[q] = bucket_[b];
                queue.push_back(q);
            }
    }
}

bool GriddedCurrentField::cellInside(std::size_t ci, std::size_t cj, double px, double py, double &a, double &b) const
{
    const CellMap c(nodeX_, nodeY_, nx_, ci, cj);
    a = 0.5;
    b = 0.5;
    for (int iter = 0; iter < 16; ++iter)
    {
        const double rx = c.x00 + a * c.ex + b * c.fx + a * b * c.gx - px;
        const double ry = c.y00 + a * c.ey + b * c.fy + a * b * c.gy - py;
        double j11, j12, j21, j22;
        const double det = c.jacobian(a, b, j11, j12, j21, j22);
        if (!(std::abs(det) > 0.0))
            return false;
        const double inv = 1.0 / det;
        const double da = (j22 * rx - j12 * ry) * inv, db = (-j21 * rx + j11 * ry) * inv;
        a -= da;
        b -= db;
        if (!std::isfinite(a) || !std::isfinite(b))
            return false;
        if (std::abs(da) + std::abs(db) < 1e-7) // quadratic convergence: the error left is ~1e-14
            break;
    }
    return true;
}

bool GriddedCurrentField::locate(double x, double y, double &fi, double &fj) const
{
    if (!curvilinear_)
    {
        const bool inside = x >= xMin_ && x <= xMax_ && y >= yMin_ && y <= yMax_;
        auto frac = [](const Axis &ax, double q) {
            q = std::clamp(q, ax.front(), ax.back());
            const std::size_t k = ax.interval(q);
            return double(k) + (q - ax[k]) / (ax[k + 1] - ax[k]);
        };
        fi = frac(x_, x);
        fj = frac(y_, y);
        return inside;
    }
    const std::size_t cx = nx_ - 1, cy = ny_ - 1;
    // Consecutive queries of one thread are usually in the same or a neighbouring cell (the travel-time code
    // walks along legs): start from the last cell found by this thread in this field when it is close.
    struct Hint
    {
        std::uint64_t field{0};
        std::size_t ci{0}, cj{0};
    };
    thread_local Hint hint;
    constexpr double tol = 1e-10;
    double a = 0.5, b = 0.5;
    std::size_t ci, cj;
    if (hint.field == id_ && hint.ci < cx && hint.cj < cy && cellInside(hint.ci, hint.cj, x, y, a, b) && a > -2.0 &&
        a < 3.0 && b > -2.0 && b < 3.0)
    {
        ci = hint.ci;
        cj = hint.cj;
    }
    else
    {
        const double qx = std::clamp((x - bx0_) * bInv_, 0.0, double(bnx_ - 1));
        const double qy = std::clamp((y - by0_) * bInv_, 0.0, double(bny_ - 1));
        const std::int32_t start = bucket_[static_cast<std::size_t>(qy) * bnx_ + static_cast<std::size_t>(qx)];
        ci = static_cast<std::size_t>(start) % cx;
        cj = static_cast<std::size_t>(start) / cx;
        if (!cellInside(ci, cj, x, y, a, b))
            a = b = std::numeric_limits<double>::quiet_NaN();
    }
    const std::size_t maxSteps = 2 * (nx_ + ny_) + 8;
    for (std::size_t step = 0; step < maxSteps; ++step)
    {
        if (step > 0 && !cellInside(ci, cj, x, y, a, b))
            break;
        if (std::isnan(a))
            break;
        const int di = a < -tol ? -1 : (a > 1 + tol ? 1 : 0);
        const int dj = b < -tol ? -1 : (b > 1 + tol ? 1 : 0);
        if (di == 0 && dj == 0)
        {
            // on (within tol of) an edge shared with the next cell, the next cell: the answer is the same whichever
            // cell the walk started from (the thread's hint), so results do not depend on the order of queries
            double a2 = a, b2 = b;
            const std::size_t ui = a > 1.0 - tol && ci + 1 < cx ? ci + 1 : ci;
            const std::size_t uj = b > 1.0 - tol && cj + 1 < cy ? cj + 1 : cj;
            if ((ui != ci || uj != cj) && cellInside(ui, uj, x, y, a2, b2) && a2 >= -tol && a2 <= 1.0 + tol &&
                b2 >= -tol && b2 <= 1.0 + tol)
            {
                ci = ui;
                cj = uj;
                a = a2;
                b = b2;
            }
            fi = double(ci) + std::clamp(a, 0.0, 1.0);
            fj = double(cj) + std::clamp(b, 0.0, 1.0);
            hint = {id_, ci, cj};
            return true;
        }
        const std::size_t ni = di < 0 ? (ci > 0 ? ci - 1 : ci) : (di > 0 ? std::min(ci + 1, cx - 1) : ci);
        const std::size_t nj = dj < 0 ? (cj > 0 ? cj - 1 : cj) : (dj > 0 ? std::min(cj + 1, cy - 1) : cj);
        if (ni == ci && nj == cj)
            break; // wants to leave the mesh: outside
        ci = ni;
        cj = nj;
    }
    fi = double(ci) + (std::isfinite(a) ? std::clamp(a, 0.0, 1.0) : 0.5);
    fj = double(cj) + (std::isfinite(b) ? std::clamp(b, 0.0, 1.0) : 0.5);
    return false;
}

GriddedCurrentField::Horizontal GriddedCurrentField::horizontal(double x, double y, bool derivative) const
{
    Horizontal h;
    const Interp1D s = axisScheme(options_.xy);
    if (!curvilinear_)
    {
        h.sx = makeStencil(x_, s, x, derivative);
        h.sy = makeStencil(y_, s, y, derivative);
        return h;
    }
    double fi, fj;
    locate(x, y, fi, fj);
    h.sx = makeStencil(x_, s, fi, derivative);
    h.sy = makeStencil(y_, s, fj, derivative);
    if (!derivative)
        return h;
    // d(x, y)/d(fi, fj) of the cell's bilinear map at (a, b), inverted
    const std::size_t ci = std::min(static_cast<std::size_t>(fi), nx_ - 2);
    const std::size_t cj = std::min(static_cast<std::size_t>(fj), ny_ - 2);
    double j11, j12, j21, j22;
    const CellMap cell(nodeX_, nodeY_, nx_, ci, cj);
    const double det = cell.jacobian(fi - double(ci), fj - double(cj), j11, j12, j21, j22);
    if (std::abs(det) > 0.0)
    {
        h.m[0] = j22 / det;  // dfi/dx
        h.m[1] = -j12 / det; // dfi/dy
        h.m[2] = -j21 / det; // dfj/dx
        h.m[3] = j11 / det;  // dfj/dy
    }
    else
        h.m[0] = h.m[1] = h.m[2] = h.m[3] = 0.0;
    return h;
}
} // namespace ompl_glider

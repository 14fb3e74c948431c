#pragma once
/// @file detail/Lattice.h (an internal of the lattice search, installed because TveSearch.h needs it; not API)
/// @brief Implicit rectangular lattice with n-sector connectivity ([EichhornRAS] Sec. 2.1, Fig. 1).

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ompl_glider
{
/// @brief A position as "(x, y)" (default stream precision), for the lattice searches' messages about start and goal.
std::string formatPoint(double x, double y);

/// @brief An integer grid offset (dx, dy) of a lattice edge.
struct LatticeOffset
{
    int dx{0}; ///< columns
    int dy{0}; ///< rows
};

/// @brief A rectangular lattice over [xMin, xMax] x [yMin, yMax] with spacing gridSize and n-sector connectivity.
///
/// Grid vertex (i, j) sits at (xMin + i g, yMin + j g), i = 0..nx-1, j = 0..ny-1, with
/// nx = floor((xMax - xMin) / g) + 1 (the last column may lie short of xMax when the width is not a multiple of g).
/// Its successors are the grid vertices at every offset (dx, dy) with max(|dx|, |dy|) <= n and gcd(|dx|, |dy|) = 1
/// (8, 16, 32, 48, 80 neighbours for n = 1..5; [EichhornRAS] Fig. 1(a)-(c)). Nothing is stored per edge: successors are
/// generated on demand, so a lattice of 10^6 vertices costs only its few scalars until a search visits it.
///
/// Exact start and goal positions are joined to the lattice as two extra vertices (ids numGridVertices() and
/// numGridVertices() + 1). A position within 1e-9 g of a grid vertex is not an extra vertex: it is that grid vertex.
/// Otherwise let a be the grid vertex nearest to the position (its "anchor") and A = {a} u {a + o : o offset} the
/// anchor's neighbourhood (inside the grid). The start vertex has an edge to every vertex of A(start); every grid
/// vertex of A(goal) has an edge to the goal vertex; and the start has a direct edge to the goal when the two anchors
/// are equal or one offset apart. So the extra vertices have the same edge slopes as the grid around them, only
/// shifted by less than half a cell.
class Lattice
{
public:
    /// @brief Vertex index: grid vertices first (i + j nx), then the extra start and goal vertices.
    using VertexId = std::size_t;
    /// @brief "No vertex".
    static constexpr VertexId kNone = std::numeric_limits<VertexId>::max();

    /// @brief Builds the lattice. Throws ompl_glider::Error for non-finite or empty bounds, gridSize <= 0,
    /// sectors outside 1..5, or more than 2^31 vertices.
    Lattice(double xMin, double xMax, double yMin, double yMax, double gridSize, unsigned sectors);

    /// @brief The offsets of n-sector connectivity: max(|dx|, |dy|) <= n, gcd(|dx|, |dy|) = 1, sorted by angle.
    /// @note [EichhornRAS] Fig. 1.
    static std::vector<LatticeOffset> offsets(unsigned sectors);

    /// @brief Offsets in use (sorted by angle atan2(dy, dx) in (-pi, pi]).
    const std::vector<LatticeOffset> &offsets() const { return offsets_; }
    /// @brief Direction atan2(dy, dx) of offsets()[k].
    const std::vector<double> &offsetAngles() const { return angles_; }

    /// @brief Joins the exact start position; returns its vertex (a grid vertex when it coincides with one,
    /// else the extra start vertex) or kNone when the position lies outside the bounds.
    VertexId setStart(double x, double y);
    /// @brief Joins the exact goal position; returns its vertex (as setStart) or kNone when outside the bounds.
    VertexId setGoal(double x, double y);

    /// @brief Calls f(v) for every successor v of u (grid neighbours inside the bounds, plus the extra goal
    /// vertex when u is in the goal's anchor neighbourhood). The goal vertex has no successors.
    template <typename F> void forEachSuccessor(VertexId u, F &&f) const
    {
        if (u == goalExtra() || u >= numVertices())
            return;
        if (u == startExtra())
        {
            if (!startIsExtra_)
                return;
            visitNeighbourhood(startAnchorI_, startAnchorJ_, true, f);
            // (a grid goal inside A(start) was visited above)
            if (goalIsExtra_ && inNeighbourhood(goalAnchorI_ - startAnchorI_, goalAnchorJ_ - startAnchorJ_))
                f(goalExtra());
            return;
        }
        const long i = column(u), j = row(u);
        visitNeighbourhood(i, j, false, f);
        if (goalIsExtra_ && inNeighbourhood(goalAnchorI_ - i, goalAnchorJ_ - j))
            f(goalExtra());
    }

    /// @brief Position of vertex v.
    double x(VertexId v) const;
    /// @brief Position of vertex v.
    double y(VertexId v) const;

    /// @brief Grid columns.
    long nx() const { return nx_; }
    /// @brief Grid rows.
    long ny() const { return ny_; }
    /// @brief Grid spacing.
    double gridSize() const { return g_; }
    /// @brief Sectors n of the connectivity.
    unsigned sectors() const { return sectors_; }
    /// @brief Number of grid vertices nx ny.
    std::size_t numGridVertices() const { return static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_); }
    /// @brief Number of vertex ids (grid vertices + the two extra vertices).
    std::size_t numVertices() const { return numGridVertices() + 2; }
    /// @brief Id of the extra start vertex (used only when the start is not on a grid vertex).
    VertexId startExtra() const { return numGridVertices(); }
    /// @brief Id of the extra goal vertex (used only when the goal is not on a grid vertex).
    VertexId goalExtra() const { return numGridVertices() + 1; }
    /// @brief The start vertex set by setStart() (kNone before).
    VertexId start() const { return start_; }
    /// @brief The goal vertex set by setGoal() (kNone before).
    VertexId goal() const { return goal_; }
    /// @brief Grid vertex (i, j), or kNone outside the grid.
    VertexId gridVertex(long i, long j) const
    {
        return (i < 0 || j < 0 || i >= nx_ || j >= ny_) ? kNone : static_cast<VertexId>(i + j * nx_);
    }
    /// @brief True when (dx, dy) is (0, 0) or a connectivity offset.
    bool inNeighbourhood(long dx, long dy) const;

    /// @brief Calls f(u) for every vertex u that has v among its successors, except the extra start vertex (for
    /// backward searches from the goal): the grid neighbours of a grid vertex (the offsets are symmetric), and the
    /// grid vertices of the goal's anchor neighbourhood for the extra goal vertex.
    template <typename F> void forEachPredecessor(VertexId v, F &&f) const
    {
        if (v == goalExtra())
        {
            if (goalIsExtra_)
                visitNeighbourhood(goalAnchorI_, goalAnchorJ_, true, f);
            return;
        }
        if (v >= numGridVertices())
            return;
        visitNeighbourhood(column(v), row(v), false, f);
    }
    /// @brief Column i of a grid vertex.
    long columnOf(VertexId v) const { return column(v); }
    /// @brief Row j of a grid vertex.
    long rowOf(VertexId v) const { return row(v); }
    /// @brief Lower x bound (x of column 0).
    double xMin() const { return xMin_; }
    /// @brief Lower y bound (y of row 0).
    double yMin() const { return yMin_; }

private:
    long column(VertexId v) const { return static_cast<long>(v % static_cast<VertexId>(nx_)); }
    long row(VertexId v) const { return static_cast<long>(v / static_cast<VertexId>(nx_)); }
    template <typename F> void visitNeighbourhood(long i, long j, bool includeSelf, F &f) const
    {
        if (includeSelf)
            f(gridVertex(i, j));
        for (const LatticeOffset &o : offsets_)
        {
            const long a = i + o.dx, b = j + o.dy;
            if (a >= 0 && b >= 0 && a < nx_ && b < ny_)
                f(static_cast<VertexId>(a + b * nx_));
        }
    }
    /// Returns the grid vertex at (x, y) when within 1e-9 g, kNone otherwise; sets the anchor (nearest vertex).
    VertexId join(double x, double y, long &ai, long &aj, bool &inside) const;

    double xMin_, xMax_, yMin_, yMax_, g_;
    long nx_, ny_;
    unsigned sectors_;
    std::vector<LatticeOffset> offsets_;
    std::vector<double> angles_;
    VertexId start_{kNone}, goal_{kNone};
    bool startIsExtra_{false}, goalIsExtra_{false};
    long startAnchorI_{0}, startAnchorJ_{0}, goalAnchorI_{0}, goalAnchorJ_{0};
    double startX_{0}, startY_{0}, goalX_{0}, goalY_{0};
};
} // namespace ompl_glider

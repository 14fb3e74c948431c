// Lattice: n-sector offsets (counts, gcd and bound properties), implicit successors, joining exact start/goal
// positions, bad parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

#include "ompl_glider/Exception.h"
#include "planners/detail/Lattice.h" // internal to the library (src/)

using namespace ompl_glider;

namespace
{
std::vector<Lattice::VertexId> successors(const Lattice &l, Lattice::VertexId u)
{
    std::vector<Lattice::VertexId> out;
    l.forEachSuccessor(u, [&](Lattice::VertexId v) { out.push_back(v); });
    return out;
}
} // namespace

TEST(Lattice, OffsetCountsMatchSectors)
{
    // [EichhornRAS] Fig. 1: 1-sector 8, 2-sector 16, 3-sector 32 neighbours.
    EXPECT_EQ(Lattice::offsets(1).size(), 8u);
    EXPECT_EQ(Lattice::offsets(2).size(), 16u);
    EXPECT_EQ(Lattice::offsets(3).size(), 32u);
    // Independent count for n = 4, 5: coprime pairs in the square.
    for (unsigned n = 1; n <= 5; ++n)
    {
        std::size_t count = 0;
        for (int a = -int(n); a <= int(n); ++a)
            for (int b = -int(n); b <= int(n); ++b)
                if ((a || b) && std::gcd(std::abs(a), std::abs(b)) == 1)
                    ++count;
        EXPECT_EQ(Lattice::offsets(n).size(), count) << "n = " << n;
    }
}

TEST(Lattice, OffsetsAreCoprimeBoundedDistinctAndSymmetric)
{
    for (unsigned n = 1; n <= 5; ++n)
    {
        const auto off = Lattice::offsets(n);
        std::set<std::pair<int, int>> seen;
        std::set<long> angles; // no two offsets with the same direction
        for (const auto &o : off)
        {
            EXPECT_FALSE(o.dx == 0 && o.dy == 0);
            EXPECT_LE(std::max(std::abs(o.dx), std::abs(o.dy)), int(n));
            EXPECT_EQ(std::gcd(std::abs(o.dx), std::abs(o.dy)), 1);
            EXPECT_TRUE(seen.insert({o.dx, o.dy}).second);
            EXPECT_TRUE(angles.insert(std::lround(std::atan2(o.dy, o.dx) * 1e9)).second);
        }
        for (const auto &o : off)
            EXPECT_TRUE(seen.count({-o.dx, -o.dy})) << "offset set must be symmetric";
        for (std::size_t i = 1; i < off.size(); ++i)
            EXPECT_LT(std::atan2(off[i - 1].dy, off[i - 1].dx), std::atan2(off[i].dy, off[i].dx));
    }
}

TEST(Lattice, GridShapeAndPositions)
{
    Lattice l(0.0, 10.0, -4.0, 4.0, 0.4, 3);
    EXPECT_EQ(l.nx(), 26);
    EXPECT_EQ(l.ny(), 21);
    EXPECT_EQ(l.numGridVertices(), 546u);
    const auto v = l.gridVertex(5, 7);
    EXPECT_NEAR(l.x(v), 2.0, 1e-12);
    EXPECT_NEAR(l.y(v), -4.0 + 2.8, 1e-12);
    EXPECT_EQ(l.gridVertex(26, 0), Lattice::kNone);
    EXPECT_EQ(l.gridVertex(0, -1), Lattice::kNone);
}

TEST(Lattice, InteriorVertexHasAllNeighboursCornerFewer)
{
    Lattice l(0.0, 10.0, -4.0, 4.0, 0.4, 3);
    const auto u = l.gridVertex(10, 10);
    const auto s = successors(l, u);
    EXPECT_EQ(s.size(), 32u);
    for (auto v : s)
    {
        const double dx = std::round((l.x(v) - l.x(u)) / 0.4), dy = std::round((l.y(v) - l.y(u)) / 0.4);
        EXPECT_TRUE(l.inNeighbourhood(long(dx), long(dy)));
        EXPECT_FALSE(dx == 0 && dy == 0);
    }
    // Corner (0, 0): only offsets with dx >= 0 and dy >= 0: (1,0),(0,1),(1,1),(1,2),(2,1),(1,3),(3,1),(2,3),(3,2).
    EXPECT_EQ(successors(l, l.gridVertex(0, 0)).size(), 9u);
}

TEST(Lattice, StartOnGridVertexIsThatVertex)
{
    Lattice l(0.0, 10.0, -4.0, 4.0, 0.4, 2);
    EXPECT_EQ(l.setStart(2.0, 0.0), l.gridVertex(5, 10));
    EXPECT_EQ(l.setGoal(8.0, 2.0), l.gridVertex(20, 15));
}

TEST(Lattice, ExtraStartJoinsAnchorNeighbourhood)
{
    Lattice l(0.0, 10.0, -4.0, 4.0, 0.4, 1);
    const auto s = l.setStart(2.05, 0.13); // anchor (5, 10) at (2.0, 0.0)
    ASSERT_EQ(s, l.startExtra());
    EXPECT_DOUBLE_EQ(l.x(s), 2.05);
    EXPECT_DOUBLE_EQ(l.y(s), 0.13);
    const auto succ = successors(l, s);
    std::set<Lattice::VertexId> got(succ.begin(), succ.end());
    std::set<Lattice::VertexId> want;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            want.insert(l.gridVertex(5 + dx, 10 + dy));
    EXPECT_EQ(got, want);
}

TEST(Lattice, ExtraGoalReachedFromItsAnchorNeighbourhoodOnly)
{
    Lattice l(0.0, 10.0, -4.0, 4.0, 0.4, 2);
    const auto g = l.setGoal(6.1, 1.3); // anchor (15, 13) at (6.0, 1.2)
    ASSERT_EQ(g, l.goalExtra());
    std::size_t into = 0;
    for (Lattice::VertexId u = 0; u < l.numGridVertices(); ++u)
        for (auto v : successors(l, u))
            if (v == g)
            {
                ++into;
                const long dx = std::lround((l.x(u) - 6.0) / 0.4), dy = std::lround((l.y(u) - 1.2) / 0.4);
                EXPECT_TRUE(l.inNeighbourhood(dx, dy));
            }
    EXPECT_EQ(into, 17u); // the anchor + its 16 neighbours
    EXPECT_TRUE(successors(l, g).empty());
}

TEST(Lattice, StartAndGoalInSameNeighbourhoodAreJoinedDirectly)
{
    Lattice l(0.0, 10.0, -4.0, 4.0, 0.4, 1);
    l.setGoal(2.3, 0.1);                   // anchor (6, 10)
    const auto s = l.setStart(2.05, 0.13); // anchor (5, 10)
    const auto succ = successors(l, s);
    EXPECT_NE(std::find(succ.begin(), succ.end(), l.goalExtra()), succ.end());
}

TEST(Lattice, OutsideBoundsIsRejected)
{
    Lattice l(0.0, 10.0, -4.0, 4.0, 0.4, 3);
    EXPECT_EQ(l.setStart(-0.1, 0.0), Lattice::kNone);
    EXPECT_EQ(l.setGoal(5.0, 4.5), Lattice::kNone);
    EXPECT_NE(l.setGoal(10.0, 4.0), Lattice::kNone);
}

TEST(Lattice, BadParametersThrow)
{
    EXPECT_THROW(Lattice(0, 10, -4, 4, 0.0, 3), Error);
    EXPECT_THROW(Lattice(0, 10, -4, 4, 0.4, 0), Error);
    EXPECT_THROW(Lattice(0, 10, -4, 4, 0.4, 6), Error);
    EXPECT_THROW(Lattice(10, 0, -4, 4, 0.4, 3), Error);
    EXPECT_THROW(Lattice(0, std::nan(""), -4, 4, 0.4, 3), Error);
}

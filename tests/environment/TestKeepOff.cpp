// Tests of the keep-off zone (the band within a distance of land's boundary) and of forbidden grid cells (the
// shallow water of a depth limit): exact distances, legs that pass just inside or just outside the distance.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ompl_glider/environment/ForbiddenCells.h"
#include "ompl_glider/environment/ForbiddenRegions.h"
#include "ompl_glider/environment/KeepOffZone.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/environment/Polygon.h"

using namespace ompl_glider;

namespace
{
/// The edges of the unit square [0, 1] x [0, 1] (an island).
std::vector<Segment2> square()
{
    return Polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}).edges();
}
} // namespace

TEST(KeepOffZone, ExactDistancesToTheBoundary)
{
    const KeepOffZone z(square(), 0.5);
    EXPECT_DOUBLE_EQ(z.distanceTo(2.0, 0.5), 1.0);               // east of the east side
    EXPECT_DOUBLE_EQ(z.distanceTo(4.0, 5.0), 5.0);               // from the corner (1, 1): 3-4-5
    EXPECT_NEAR(z.distanceTo(0.5, 0.9), 0.1, 1e-15);             // inside: to the north side
    EXPECT_NEAR(z.legDistance(-1.0, 1.3, 3.0, 1.3), 0.3, 1e-15); // a leg passing north of the island
    EXPECT_EQ(z.legDistance(-1.0, 0.5, 3.0, 0.5), 0.0);          // a leg across it
    const KeepOffZone none({}, 1.0);
    EXPECT_TRUE(none.empty());
    EXPECT_TRUE(std::isinf(none.distanceTo(0, 0)));
    EXPECT_TRUE(none.legFree(0, 0, 0, 5, 5, 1));
}

TEST(KeepOffZone, LegsJustInsideAndJustOutsideTheDistance)
{
    const KeepOffZone z(square(), 0.5);
    // a leg along y = 1.5 + e: the island's north side is 0.5 + e away
    EXPECT_TRUE(z.legFree(-3.0, 1.5 + 1e-9, 0.0, 4.0, 1.5 + 1e-9, 1.0));
    EXPECT_FALSE(z.legFree(-3.0, 1.5 - 1e-9, 0.0, 4.0, 1.5 - 1e-9, 1.0));
    // its ends are far from the island: sampling the ends alone would miss it
    EXPECT_TRUE(z.pointFree(-3.0, 1.5 - 1e-9, 0.0));
    EXPECT_TRUE(z.pointFree(4.0, 1.5 - 1e-9, 0.0));
    // a diagonal leg past the corner (1, 1): its distance is that of the corner to the line
    const double c = 1.0 + 0.25 * std::sqrt(2.0); // the line x + y = 2c passes 0.5 from (1, 1)
    EXPECT_TRUE(z.legFree(c + 2.0 + 1e-9, c - 2.0 + 1e-9, 0.0, c - 2.0 + 1e-9, c + 2.0 + 1e-9, 1.0));
    EXPECT_FALSE(z.legFree(c + 2.0 - 1e-6, c - 2.0 - 1e-6, 0.0, c - 2.0 - 1e-6, c + 2.0 - 1e-6, 1.0));
    EXPECT_FALSE(z.pointFree(1.2, 1.2, 0.0));
    EXPECT_NE(z.whyBlocked(1.2, 1.2, 0.0).find("keep-off"), std::string::npos);
    EXPECT_TRUE(z.isStatic());
}

TEST(KeepOffZone, ClosestApproachOfARoute)
{
    const KeepOffZone z(square(), 0.0);
    const std::vector<TimedPoint> route{{-2.0, 2.0, 0.0}, {0.5, 1.25, 1.0}, {3.0, 1.25, 2.0}};
    const LandApproach c = closestApproach(z, route);
    EXPECT_NEAR(c.distance, 0.25, 1e-12);
    EXPECT_NEAR(c.where.y, 1.25, 1e-9);
    EXPECT_GE(c.where.x, 0.5 - 1e-9);
    EXPECT_LE(c.where.x, 1.0 + 1e-9);
}

TEST(KeepOffZone, MakesTheCompositeStaticAndRefusesNegativeDistances)
{
    ForbiddenRegions r;
    r.add(std::make_shared<KeepOffZone>(square(), 0.2));
    EXPECT_TRUE(r.isStatic());
    EXPECT_FALSE(r.pointFree(1.1, 0.5, 0.0));
    EXPECT_TRUE(r.pointFree(1.3, 0.5, 0.0));
    EXPECT_THROW(KeepOffZone(square(), -1.0), Error);
    EXPECT_THROW(KeepOffZone(square(), NAN), Error);
}

TEST(ForbiddenCells, PointsAndLegsAgainstTheUnionOfCells)
{
    // 4 x 3 nodes on a slanted grid; cells (1, 0) and (2, 1) forbidden (they share the node (2, 1) only)
    const std::size_t nx = 4, ny = 3;
    std::vector<Point2> nodes;
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
            nodes.push_back({double(i) + 0.2 * double(j), double(j)});
    std::vector<std::uint8_t> bad(6, 0);
    bad[0 * 3 + 1] = 1;
    bad[1 * 3 + 2] = 1;
    const ForbiddenCells c("depth < 50 m", "shallow water", nx, ny, nodes, bad);
    EXPECT_EQ(c.cellCount(), 2u);
    EXPECT_EQ(c.boundary().size(), 8u);
    EXPECT_FALSE(c.pointFree(1.6, 0.5, 0.0));  // inside cell (1, 0)
    EXPECT_TRUE(c.pointFree(0.6, 0.5, 0.0));   // inside cell (0, 0)
    EXPECT_FALSE(c.pointFree(1.0, 0.0, 0.0));  // on its boundary: closed
    EXPECT_TRUE(c.pointFree(10.0, 10.0, 0.0)); // outside the grid
    // a leg between two free cells that clips the corner of a forbidden one
    EXPECT_FALSE(c.legFree(0.5, 0.5, 0.0, 1.3, -0.1, 1.0));
    // a leg through free cells only, passing close to the forbidden ones
    EXPECT_TRUE(c.legFree(0.3, 0.5, 0.0, 0.3 + 0.2 * 1.4, 1.9, 1.0));
    // a leg across the shared corner node (2.2, 1)
    EXPECT_FALSE(c.legFree(1.7, 1.5, 0.0, 2.7, 0.5, 1.0));
    EXPECT_THROW(ForbiddenCells("x", "y", nx, ny, nodes, std::vector<std::uint8_t>(5, 0)), Error);
}

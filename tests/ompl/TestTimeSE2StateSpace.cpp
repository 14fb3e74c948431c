#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <ompl/base/ProjectionEvaluator.h>
#include <ompl/base/ScopedState.h>
#include <ompl/util/RandomNumbers.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/ompl/TimeSE2StateSpace.h"

namespace ob = ompl::base;
using ompl_glider::TimeSE2StateSpace;

namespace
{
std::shared_ptr<TimeSE2StateSpace> makeSpace()
{
    ob::RealVectorBounds b(2);
    b.setLow(0, 0.0);
    b.setHigh(0, 10.0);
    b.setLow(1, -4.0);
    b.setHigh(1, 4.0);
    return std::make_shared<TimeSE2StateSpace>(b, 0.0, 60.0);
}
} // namespace

TEST(TimeSE2StateSpace, SanityChecksAllFlags)
{
    ompl::RNG::setSeed(1);
    auto space = makeSpace();
    space->setup();
    // Default flags: every check (the distance is a metric), tolerances zero = DBL_EPS and eps = FLT_EPS.
    // No flag is relaxed: the distance is a weighted sum of metrics, interpolation is linear in x, y, t and
    // geodesic in yaw (so the midpoint splits the distance exactly), sampling stays in bounds.
    EXPECT_NO_THROW(space->sanityChecks());
    space->setTimeWeight(1.5);
    EXPECT_NO_THROW(space->sanityChecks());
    // Explicit flag set: nothing relaxed.
    const unsigned int all = ~0u;
    EXPECT_NO_THROW(space->sanityChecks(std::numeric_limits<double>::epsilon(), 1e-6, all));
}

TEST(TimeSE2StateSpace, TypedAccessAndBounds)
{
    auto space = makeSpace();
    EXPECT_TRUE(space->isLocked());
    EXPECT_EQ(space->getDimension(), 4u);
    EXPECT_DOUBLE_EQ(space->tMin(), 0.0);
    EXPECT_DOUBLE_EQ(space->tMax(), 60.0);
    EXPECT_DOUBLE_EQ(space->getTimeBounds().low[0], 0.0);
    EXPECT_DOUBLE_EQ(space->getXYBounds().high[1], 4.0);
    ob::ScopedState<TimeSE2StateSpace> s(space);
    s->setXYT(1.0, 2.0, 3.0);
    s->setYaw(0.5);
    EXPECT_DOUBLE_EQ(s->getX(), 1.0);
    EXPECT_DOUBLE_EQ(s->getY(), 2.0);
    EXPECT_DOUBLE_EQ(s->getTime(), 3.0);
    EXPECT_DOUBLE_EQ(s->getYaw(), 0.5);
    s->setX(4.0);
    s->setY(-1.0);
    s->setTime(7.0);
    EXPECT_DOUBLE_EQ(s->getX(), 4.0);
    EXPECT_DOUBLE_EQ(s->getY(), -1.0);
    EXPECT_DOUBLE_EQ(s->getTime(), 7.0);
    EXPECT_TRUE(space->satisfiesBounds(s.get()));
    s->setTime(61.0);
    EXPECT_FALSE(space->satisfiesBounds(s.get()));
    s->setTime(-0.1);
    EXPECT_FALSE(space->satisfiesBounds(s.get()));
    s->setTime(5.0);
    s->setX(10.5);
    EXPECT_FALSE(space->satisfiesBounds(s.get()));
    space->enforceBounds(s.get());
    EXPECT_DOUBLE_EQ(s->getX(), 10.0);
}

TEST(TimeSE2StateSpace, DistanceIsWeightedSum)
{
    auto space = makeSpace();
    ob::ScopedState<TimeSE2StateSpace> a(space), b(space);
    a->setXYT(0.0, 0.0, 1.0);
    a->setYaw(0.0);
    b->setXYT(3.0, 4.0, 3.0);
    b->setYaw(1.0);
    // d = |dxy| + yawWeight |dyaw| + timeWeight |dt| with defaults 0.01 and 1.
    EXPECT_DOUBLE_EQ(space->getYawWeight(), 0.01);
    EXPECT_DOUBLE_EQ(space->getTimeWeight(), 1.0);
    EXPECT_NEAR(space->distance(a.get(), b.get()), 5.0 + 0.01 * 1.0 + 1.0 * 2.0, 1e-12);
    space->setTimeWeight(1.5);
    space->setYawWeight(0.1);
    EXPECT_NEAR(space->distance(a.get(), b.get()), 5.0 + 0.1 + 1.5 * 2.0, 1e-12);
    // yaw wraps: distance of headings 3 and -3 is 2 pi - 6.
    a->setYaw(3.0);
    b->setYaw(-3.0);
    EXPECT_NEAR(space->distance(a.get(), b.get()), 5.0 + 0.1 * (2 * M_PI - 6.0) + 3.0, 1e-12);
    EXPECT_DOUBLE_EQ(TimeSE2StateSpace::xyDistance(a.get(), b.get()), 5.0);
    EXPECT_THROW(space->setTimeWeight(0.0), ompl_glider::Error);
    EXPECT_THROW(space->setYawWeight(-1.0), ompl_glider::Error);
    // Maximum extent: diagonal 10x8 box + pi yaw + 60 time units.
    EXPECT_NEAR(space->getMaximumExtent(), std::hypot(10.0, 8.0) + 0.1 * M_PI + 1.5 * 60.0, 1e-9);
}

TEST(TimeSE2StateSpace, InterpolationIsLinearInXYT)
{
    auto space = makeSpace();
    ob::ScopedState<TimeSE2StateSpace> a(space), b(space), m(space);
    a->setXYT(1.0, -2.0, 4.0);
    a->setYaw(3.0);
    b->setXYT(5.0, 2.0, 12.0);
    b->setYaw(-3.0);
    space->interpolate(a.get(), b.get(), 0.25, m.get());
    EXPECT_NEAR(m->getX(), 2.0, 1e-12);
    EXPECT_NEAR(m->getY(), -1.0, 1e-12);
    EXPECT_NEAR(m->getTime(), 6.0, 1e-12);
    // shortest arc from 3 to -3 passes through pi
    double expectYaw = 3.0 + 0.25 * (2 * M_PI - 6.0);
    EXPECT_NEAR(m->getYaw(), expectYaw, 1e-12);
    // distances split in proportion (triangle equality along the motion)
    EXPECT_NEAR(space->distance(a.get(), m.get()), 0.25 * space->distance(a.get(), b.get()), 1e-12);
}

TEST(TimeSE2StateSpace, CloneAndSerialization)
{
    auto space = makeSpace();
    ob::ScopedState<TimeSE2StateSpace> a(space);
    a->setXYT(2.5, 1.5, 33.0);
    a->setYaw(-1.2);
    ob::State *c = space->cloneState(a.get());
    EXPECT_TRUE(space->equalStates(a.get(), c));
    EXPECT_DOUBLE_EQ(c->as<TimeSE2StateSpace::StateType>()->getTime(), 33.0);
    space->freeState(c);

    std::vector<char> buf(space->getSerializationLength());
    EXPECT_EQ(buf.size(), 4 * sizeof(double));
    space->serialize(buf.data(), a.get());
    ob::ScopedState<TimeSE2StateSpace> b(space);
    b->setXYT(0, 0, 0);
    space->deserialize(b.get(), buf.data());
    EXPECT_TRUE(space->equalStates(a.get(), b.get()));
    EXPECT_DOUBLE_EQ(b->getX(), 2.5);
    EXPECT_DOUBLE_EQ(b->getYaw(), -1.2);
}

TEST(TimeSE2StateSpace, RejectsBadBounds)
{
    ob::RealVectorBounds b(2);
    b.setLow(0.0);
    b.setHigh(1.0);
    EXPECT_THROW(TimeSE2StateSpace(b, 5.0, 5.0), ompl_glider::Error);
    EXPECT_THROW(TimeSE2StateSpace(b, 0.0, std::numeric_limits<double>::infinity()), ompl_glider::Error);
    ob::RealVectorBounds b3(3);
    b3.setLow(0.0);
    b3.setHigh(1.0);
    EXPECT_THROW(TimeSE2StateSpace(b3, 0.0, 1.0), ompl_glider::Error);
    b.setHigh(1, -1.0);
    EXPECT_THROW(TimeSE2StateSpace(b, 0.0, 1.0), ompl_glider::Error);
}

TEST(TimeSE2StateSpace, DefaultProjectionIsXYT)
{
    auto space = makeSpace();
    space->setup();
    auto proj = space->getDefaultProjection();
    ASSERT_TRUE(proj);
    EXPECT_EQ(proj->getDimension(), 3u);
    ob::ScopedState<TimeSE2StateSpace> s(space);
    s->setXYT(1.5, -2.5, 42.0);
    s->setYaw(0.3);
    Eigen::VectorXd v(3);
    proj->project(s.get(), v);
    EXPECT_DOUBLE_EQ(v[0], 1.5);
    EXPECT_DOUBLE_EQ(v[1], -2.5);
    EXPECT_DOUBLE_EQ(v[2], 42.0);
    EXPECT_NEAR(proj->getCellSizes()[2], 3.0, 1e-12);
}

TEST(TimeSE2StateSpace, SampledStatesRespectBounds)
{
    auto space = makeSpace();
    auto sampler = space->allocStateSampler();
    ob::ScopedState<TimeSE2StateSpace> s(space);
    for (int i = 0; i < 1000; ++i)
    {
        sampler->sampleUniform(s.get());
        ASSERT_TRUE(space->satisfiesBounds(s.get()));
        ASSERT_GE(s->getTime(), 0.0);
        ASSERT_LE(s->getTime(), 60.0);
    }
}

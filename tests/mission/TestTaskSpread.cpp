// The many-plan modes through a TaskSpreader (TaskSpread.h) without MPI: a spreader of "two processes" that runs
// the tasks here in reverse order and hands back only their bytes must give the threaded run's results bit for bit
// (tests/mpi/ runs the same missions under mpirun).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ReverseSpreader.h"
#include "ompl_glider/TaskSpread.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;

namespace
{
using test::ReverseSpreader;

MissionResult runWith(const std::string &mission, std::shared_ptr<TaskSpreader> spreader)
{
    MissionSpec spec = loadMission(std::string(OMPL_GLIDER_SOURCE_DIR) + "/tests/mpi/" + mission);
    const MissionProblem problem(spec);
    setTaskSpreader(std::move(spreader));
    MissionResult r;
    try
    {
        r = runMission(problem);
    }
    catch (...)
    {
        setTaskSpreader(nullptr);
        throw;
    }
    setTaskSpreader(nullptr);
    return r;
}

void expectSamePoints(const std::vector<TimedPoint> &a, const std::vector<TimedPoint> &b)
{
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        EXPECT_EQ(a[i].x, b[i].x) << i;
        EXPECT_EQ(a[i].y, b[i].y) << i;
        EXPECT_EQ(a[i].t, b[i].t) << i;
    }
}
} // namespace

TEST(TaskSpread, BytesRoundTrip)
{
    ByteWriter w;
    w.put(std::nextafter(1.0, 2.0));
    w.put(std::string("a;b\nc"));
    w.put(std::vector<double>{-0.0, 1e-310, INFINITY});
    w.put(true);
    const std::string bytes = w.take();
    ByteReader r(bytes);
    EXPECT_EQ(r.value<double>(), std::nextafter(1.0, 2.0));
    EXPECT_EQ(r.value<std::string>(), "a;b\nc");
    std::vector<double> v;
    r.get(v);
    ASSERT_EQ(v.size(), 3u);
    EXPECT_TRUE(std::signbit(v[0]));
    EXPECT_EQ(v[1], 1e-310);
    EXPECT_TRUE(std::isinf(v[2]));
    EXPECT_TRUE(r.value<bool>());
    EXPECT_TRUE(r.atEnd());
    EXPECT_THROW(r.value<int>(), std::runtime_error);
}

TEST(TaskSpread, NoSpreaderMeansOneProcess)
{
    EXPECT_EQ(activeTaskSpreader(), nullptr);
    EXPECT_EQ(taskRank(), 0);
    EXPECT_EQ(taskProcesses(), 1);
}

TEST(TaskSpread, EnsembleCandidatesEqualThreaded)
{
    const MissionResult one = runWith("ensemble.yaml", nullptr);
    auto spread = std::make_shared<ReverseSpreader>();
    const MissionResult two = runWith("ensemble.yaml", spread);
    ASSERT_EQ(spread->runs, std::vector<std::string>{"ensemble candidate x5"});
    ASSERT_TRUE(one.plan.solved);
    ASSERT_TRUE(one.plan.ensemble && two.plan.ensemble);
    EXPECT_EQ(one.plan.ensemble->chosen, two.plan.ensemble->chosen);
    EXPECT_EQ(one.plan.travelTime, two.plan.travelTime);
    expectSamePoints(one.plan.path, two.plan.path);
    ASSERT_EQ(one.plan.ensemble->candidates.size(), two.plan.ensemble->candidates.size());
    for (std::size_t c = 0; c < one.plan.ensemble->candidates.size(); ++c)
        EXPECT_EQ(one.plan.ensemble->candidates[c].memberTravelTimes,
                  two.plan.ensemble->candidates[c].memberTravelTimes)
            << c;
    EXPECT_EQ(one.plan.searchCostFunctionCalls, two.plan.searchCostFunctionCalls);
}

TEST(TaskSpread, ExecutionBatchEqualsThreaded)
{
    const MissionResult one = runWith("execution.yaml", nullptr);
    auto spread = std::make_shared<ReverseSpreader>();
    const MissionResult two = runWith("execution.yaml", spread);
    ASSERT_EQ(spread->runs, std::vector<std::string>{"execution run x6"});
    ASSERT_TRUE(one.execution && two.execution);
    ASSERT_EQ(one.execution->runs.size(), 6u);
    ASSERT_EQ(two.execution->runs.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i)
    {
        const ExecutionRun &a = one.execution->runs[i], &b = two.execution->runs[i];
        EXPECT_EQ(a.planned, b.planned) << i;
        expectSamePoints(a.plan, b.plan);
        ASSERT_EQ(a.flown.size(), b.flown.size());
        for (std::size_t k = 0; k < a.flown.size(); ++k)
        {
            expectSamePoints(a.flown[k].track, b.flown[k].track);
            EXPECT_EQ(a.flown[k].finalDistance, b.flown[k].finalDistance);
            EXPECT_EQ(a.flown[k].reached, b.flown[k].reached);
            EXPECT_EQ(a.flown[k].headings, b.flown[k].headings);
        }
        // the oracle travels with its run (both NaN where it did not reach)
        EXPECT_EQ(std::isnan(a.oracleArrival), std::isnan(b.oracleArrival)) << i;
        if (!std::isnan(a.oracleArrival))
        {
            EXPECT_EQ(a.oracleArrival, b.oracleArrival) << i;
        }
        EXPECT_GT(b.oracleSeconds, 0.0) << i;
    }
    ASSERT_TRUE(two.execution->oracle);
    for (std::size_t k = 0; k < one.execution->spread.size(); ++k)
    {
        EXPECT_EQ(one.execution->spread[k].finalDistance.median, two.execution->spread[k].finalDistance.median);
        EXPECT_GT(two.execution->spread[k].overOracle.count, 0u);
        EXPECT_EQ(one.execution->spread[k].overOracle.median, two.execution->spread[k].overOracle.median);
    }
}

TEST(TaskSpread, DepartureSearchAndSpeedSweepEqualThreaded)
{
    const MissionResult one = runWith("sweep_departure.yaml", nullptr);
    auto spread = std::make_shared<ReverseSpreader>();
    const MissionResult two = runWith("sweep_departure.yaml", spread);
    ASSERT_EQ(spread->runs, (std::vector<std::string>{"departure evaluation x7", "speed sweep speed x6"}));
    ASSERT_TRUE(one.departureSearch && two.departureSearch);
    const DepartureSearchResult &a = *one.departureSearch, &b = *two.departureSearch;
    ASSERT_EQ(a.supportingPoints.size(), b.supportingPoints.size());
    for (std::size_t i = 0; i < a.supportingPoints.size(); ++i)
        EXPECT_EQ(a.supportingPoints[i].travelTime, b.supportingPoints[i].travelTime) << i;
    ASSERT_EQ(a.refinements.size(), b.refinements.size());
    EXPECT_EQ(a.departure, b.departure);
    EXPECT_EQ(one.plan.travelTime, two.plan.travelTime);
    ASSERT_EQ(one.speedSweep.size(), 6u);
    ASSERT_EQ(two.speedSweep.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i)
    {
        EXPECT_EQ(one.speedSweep[i].speed, two.speedSweep[i].speed);
        EXPECT_EQ(one.speedSweep[i].solved, two.speedSweep[i].solved);
        EXPECT_EQ(one.speedSweep[i].travelTime, two.speedSweep[i].travelTime) << i;
        EXPECT_EQ(one.speedSweep[i].pathLength, two.speedSweep[i].pathLength) << i;
    }
    EXPECT_TRUE(one.speedSweep[0].solved);
}

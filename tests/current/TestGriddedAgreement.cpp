// Agreement of the gridded model with the analytic field it samples : the meandering jet
// ([EichhornRAS] Sec. 6.1) sampled to a Cartesian NetCDF grid (spacing 0.1, time step 0.25, its own dimensionless
// units), loaded with bilinear/linear interpolation, gives travel times within 1 % of the analytic field along fixed
// multi-leg paths, and ZA*TVE (grid 0.4, 3 sectors, region x [0, 10], y [-4, 4], V = 0.5) plans routes whose
// travel times agree within 1 % with planning on the analytic field, same start and goal.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/Console.h>

#include "TestNetCdfUtil.h"
#include "ompl_glider/cost/TravelTimeCalculator.h"
#include "ompl_glider/current/MeanderingJet.h"
#include "ompl_glider/current/GriddedCurrents.h"
#include "ompl_glider/ompl/GliderSetup.h"
#include "planners/TveSearch.h" // internal to the library (src/)
#include "ompl_glider/planners/ZAStarTVE.h"

using namespace ompl_glider;
namespace ob = ompl::base;

namespace
{
struct Pt
{
    double x, y;
};

/// The jet sampled once for the whole suite.
class JetGrid : public ::testing::Test
{
protected:
    static void SetUpTestSuite()
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
        dir_ = new glider_test::TempDir();
        path_ = dir_->file("jet.nc");
        const auto xs = glider_test::linspace(-0.5, 0.1, 111); // -0.5 .. 10.5
        const auto ys = glider_test::linspace(-4.5, 0.1, 91);  // -4.5 .. 4.5
        const auto ts = glider_test::linspace(0.0, 0.25, 257); // 0 .. 64
        const MeanderingJet jet;
        {
            glider_test::NcWriter w(path_);
            const int dt = w.dim("time", ts.size()), dy = w.dim("y", ys.size()), dx = w.dim("x", xs.size());
            const int vt = w.var("time", NC_DOUBLE, {dt}), vy = w.var("y", NC_DOUBLE, {dy}),
                      vx = w.var("x", NC_DOUBLE, {dx});
            w.text(vt, "units", "1");
            w.text(vx, "units", "1");
            w.text(vy, "units", "1");
            const int u = w.var("u", NC_FLOAT, {dt, dy, dx}), v = w.var("v", NC_FLOAT, {dt, dy, dx});
            w.text(u, "standard_name", "sea_water_x_velocity");
            w.text(v, "standard_name", "sea_water_y_velocity");
            w.enddef();
            w.put(vt, ts);
            w.put(vy, ys);
            w.put(vx, xs);
            std::vector<double> pu, pv;
            pu.reserve(ts.size() * ys.size() * xs.size());
            pv.reserve(pu.capacity());
            for (double t : ts)
                for (double y : ys)
                    for (double x : xs)
                    {
                        const Velocity c = jet.velocity(x, y, 0, t);
                        pu.push_back(c.u);
                        pv.push_back(c.v);
                    }
            w.put(u, pu);
            w.put(v, pv);
        }
        GriddedCurrentOptions o;
        o.coordinates = CoordinateMode::Cartesian;
        o.field.xy = Interp2D::Bilinear;
        o.field.time = Interp1D::Linear;
        gridded_ = new GriddedCurrents(loadGriddedCurrents(path_, o));
    }
    static void TearDownTestSuite()
    {
        delete gridded_;
        delete dir_;
    }

    static glider_test::TempDir *dir_;
    static std::string path_;
    static GriddedCurrents *gridded_;
};
glider_test::TempDir *JetGrid::dir_ = nullptr;
std::string JetGrid::path_;
GriddedCurrents *JetGrid::gridded_ = nullptr;

double pathTime(const TravelTimeCalculator &calc, const std::vector<Pt> &path, double t0)
{
    double t = t0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
    {
        const double dt = calc.travelTime(path[i].x, path[i].y, path[i + 1].x, path[i + 1].y, t);
        if (!std::isfinite(dt))
            return dt;
        t += dt;
    }
    return t - t0;
}
} // namespace

TEST_F(JetGrid, LoadedAsACartesianFieldInTheJetsUnits)
{
    const GriddedCurrentField &f = *gridded_->field;
    EXPECT_FALSE(gridded_->geographic);
    EXPECT_FALSE(gridded_->dated);
    EXPECT_FALSE(f.curvilinear());
    EXPECT_EQ(gridded_->loadedShape, (std::vector<std::size_t>{257, 1, 91, 111}));
    EXPECT_EQ(f.timeBegin(), 0.0);
    EXPECT_EQ(f.timeEnd(), 64.0);
    const MeanderingJet jet;
    // exact at nodes, close between them
    for (double t : {0.0, 7.25, 30.0})
    {
        const Velocity a = f.velocity(2.3, -0.7, 0, t), b = jet.velocity(2.3, -0.7, 0, t);
        EXPECT_NEAR(a.u, b.u, 1e-6);
        EXPECT_NEAR(a.v, b.v, 1e-6);
    }
    double worst = 0;
    for (double x = 0.03; x < 10; x += 0.37)
        for (double y = -3.97; y < 4; y += 0.29)
        {
            const Velocity a = f.velocity(x, y, 0, 11.1), b = jet.velocity(x, y, 0, 11.1);
            worst = std::max(worst, std::hypot(a.u - b.u, a.v - b.v));
        }
    EXPECT_LT(worst, 0.02); // bilinear error ~ h^2/8 |c''| with h = 0.1
    EXPECT_GE(f.maxSpeed(Region{}), 0.99);
    EXPECT_LE(f.maxSpeed(Region{}), jet.maxSpeed(Region{}));
}

TEST_F(JetGrid, TravelTimesAlongFixedMultiLegPathsAgreeWithinOnePercent)
{
    // Fixed paths: the routes ZA*TVE finds on the analytic jet (they cross it, the hard case: a leg is only
    // feasible within about 30 degrees of the jet's direction) and four routes in the weak flow away from it.
    // Each is flown on both fields from the same departure time with the same travel-time code.
    TravelTimeParams p; // V = 0.5, eps = 1e-3
    const auto jet = std::make_shared<MeanderingJet>();
    const TravelTimeCalculator analytic(jet, p);
    const TravelTimeCalculator gridded(gridded_->field, p);
    std::vector<std::pair<std::vector<Pt>, double>> paths;
    struct Pair
    {
        double sx, sy, gx, gy, t0;
    };
    for (const Pair &q :
         {Pair{0.4, -3.2, 7.6, 1.2, 0.0}, Pair{2.0, -2.4, 7.6, 1.2, 5.0}, Pair{9.6, -3.2, 1.2, 2.8, 0.0},
          Pair{1.0, 3.1, 8.3, -2.7, 12.5}, Pair{4.8, -0.4, 7.6, 1.2, 3.0}})
    {
        GliderProblem gp;
        gp.field = jet;
        gp.start.x = q.sx;
        gp.start.y = q.sy;
        gp.goal.x = q.gx;
        gp.goal.y = q.gy;
        gp.t0 = q.t0;
        const TveResult r = TveSearch(makeGliderContext(gp), 0.4, 3).run(q.sx, q.sy, q.t0, q.gx, q.gy, TveOptions{});
        ASSERT_EQ(r.outcome, TveOutcome::Exact);
        std::vector<Pt> path;
        for (const TimedPoint &w : r.waypoints)
            path.push_back({w.x, w.y});
        ASSERT_GE(path.size(), 4u);
        paths.emplace_back(path, q.t0);
    }
    paths.push_back({{{0.5, -3.5}, {3.0, -3.6}, {6.0, -3.4}, {9.5, -3.5}}, 0.0});
    paths.push_back({{{9.5, -3.5}, {6.0, -3.4}, {3.0, -3.6}, {0.5, -3.5}}, 5.0});
    paths.push_back({{{0.5, 3.5}, {3.0, 3.6}, {6.0, 3.4}, {9.5, 3.5}}, 12.5});
    paths.push_back({{{9.0, 2.5}, {7.0, 3.0}, {4.0, 3.2}, {1.0, 2.8}}, 0.0});
    for (const auto &[path, t0] : paths)
    {
        const double ta = pathTime(analytic, path, t0), tg = pathTime(gridded, path, t0);
        ASSERT_TRUE(std::isfinite(ta));
        ASSERT_TRUE(std::isfinite(tg)) << "path from (" << path[0].x << ", " << path[0].y << ") at " << t0;
        EXPECT_NEAR(tg / ta, 1.0, 0.01) << "path from (" << path[0].x << ", " << path[0].y << ") at " << t0
                                        << ": analytic " << ta << ", gridded " << tg;
        std::printf("fixed path from (%.2f, %.2f), %zu legs, t0 %.1f: analytic %.4f gridded %.4f ratio %.5f\n",
                    path[0].x, path[0].y, path.size() - 1, t0, ta, tg, tg / ta);
    }
}

TEST_F(JetGrid, ZAStarTvePlansAgreeWithinOnePercent)
{
    struct Pair
    {
        double sx, sy, gx, gy;
    };
    const Pair pairs[] = {{0.4, -3.2, 7.6, 1.2}, {3.2, -1.6, 7.6, 1.2}, {9.6, -3.2, 1.2, 2.8}, {1.0, 3.1, 8.3, -2.7}};
    for (const Pair &q : pairs)
    {
        double times[2];
        for (int k = 0; k < 2; ++k)
        {
            GliderProblem p; // region x [0, 10], y [-4, 4], V = 0.5, t0 = 0, horizon 60
            if (k == 0)
                p.field = std::make_shared<MeanderingJet>();
            else
                p.field = gridded_->field;
            p.start.x = q.sx;
            p.start.y = q.sy;
            p.goal.x = q.gx;
            p.goal.y = q.gy;
            std::shared_ptr<GliderContext> ctx;
            auto ss = makeSimpleSetup(p, &ctx);
            auto planner = std::make_shared<ZAStarTVE>(ss->getSpaceInformation(), ctx, "ZA*TVE");
            planner->setGridSize(0.4);
            planner->setSectors(3);
            ss->setPlanner(planner);
            ss->setup();
            const ob::PlannerStatus st = ss->solve(ob::timedPlannerTerminationCondition(60.0));
            ASSERT_EQ(st, ob::PlannerStatus::EXACT_SOLUTION) << (k ? "gridded" : "analytic");
            times[k] = planner->getTravelTime();
        }
        EXPECT_NEAR(times[1] / times[0], 1.0, 0.01) << "(" << q.sx << ", " << q.sy << ") -> (" << q.gx << ", " << q.gy
                                                    << "): analytic " << times[0] << ", gridded " << times[1];
        std::printf("ZA*TVE (%.1f, %.1f) -> (%.1f, %.1f): analytic %.4f gridded %.4f ratio %.5f\n", q.sx, q.sy, q.gx,
                    q.gy, times[0], times[1], times[1] / times[0]);
    }
}

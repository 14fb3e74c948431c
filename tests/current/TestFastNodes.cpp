// Velocities faster than any current or wind (300 m/s) are refused on reading where they are garbage (a fill value
// not declared, a lone spike, units off across the field) and read where they are the flow's: a Cartesian benchmark
// file of a vortex in a 2 km box ([ThompsonICRA]-style scaling: vehicle 10 m/s), whose node beside the core is
// faster than 300 m/s and continuous with its neighbours, loads and plans as the analytic vortex does; the bound
// can be raised (GriddedCurrentOptions::maxSpeed, current.max_speed), and one set lower refuses the node, named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"

using namespace glider_test;
using namespace ompl_glider;

namespace
{
// The vortex: a Rankine core of radius 1.6 m and 400 m/s at its edge, centred off the nodes (1.2, 0.8), so that the
// node at the origin (1.44 m from the centre) holds 360 m/s and its neighbours 70-80 m/s.
constexpr double kX0 = 1.2, kY0 = 0.8, kRadius = 1.6, kVmax = 400.0;
constexpr std::size_t kN = 201; // nodes each way, 10 m apart over [-1000, 1000] m

void vortexAt(double x, double y, double &u, double &v)
{
    const double dx = x - kX0, dy = y - kY0, r2 = dx * dx + dy * dy;
    const double k = r2 <= kRadius * kRadius ? kVmax / kRadius : kVmax * kRadius / r2;
    u = -k * dy;
    v = k * dx;
}

/// A steady Cartesian file (x, y in metres, u, v in m s-1) of @p field at the nodes, each node's (u, v) passed
/// through @p edit (i, j, u, v) before writing.
void writeField(const std::string &path, const std::function<void(std::size_t, std::size_t, double &, double &)> &edit)
{
    NcWriter w(path);
    const int dy = w.dim("y", kN), dx = w.dim("x", kN);
    const int vy = w.var("y", NC_DOUBLE, {dy}), vx = w.var("x", NC_DOUBLE, {dx});
    w.text(vy, "units", "m");
    w.text(vx, "units", "m");
    const int u = w.var("u", NC_FLOAT, {dy, dx}), v = w.var("v", NC_FLOAT, {dy, dx});
    w.text(u, "units", "m s-1");
    w.text(v, "units", "m s-1");
    w.enddef();
    const std::vector<double> axis = linspace(-1000.0, 10.0, kN);
    w.put(vy, axis);
    w.put(vx, axis);
    std::vector<double> us(kN * kN), vs(kN * kN);
    for (std::size_t j = 0; j < kN; ++j)
        for (std::size_t i = 0; i < kN; ++i)
        {
            double a, b;
            vortexAt(axis[i], axis[j], a, b);
            edit(i, j, a, b);
            us[j * kN + i] = a;
            vs[j * kN + i] = b;
        }
    w.put(u, us);
    w.put(v, vs);
}

std::string refusal(const std::string &path, const GriddedCurrentOptions &o = {})
{
    try
    {
        (void)loadGriddedCurrents(path, o);
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

const auto kAsIs = [](std::size_t, std::size_t, double &, double &) {};
constexpr std::size_t kCore = 100; // the node at the origin
} // namespace

TEST(FastNodes, AVortexCoreNodeIsTheFlowAndPlansAsTheAnalyticVortex)
{
    TempDir dir;
    const std::string file = dir.file("vortex.nc");
    writeField(file, kAsIs);
    const GriddedCurrents nc = loadGriddedCurrents(file);
    // the node beside the core holds its 360 m/s, as written
    const Velocity c = nc.field->velocity(0.0, 0.0, 0.0, 0.0);
    double u, v;
    vortexAt(0.0, 0.0, u, v);
    EXPECT_NEAR(c.u, u, 1e-3 * std::abs(u));
    EXPECT_NEAR(c.v, v, 1e-3 * std::abs(u));
    EXPECT_GT(std::hypot(c.u, c.v), 300.0);

    // A trip past the vortex at 10 m/s, planned on the file and on the analytic vortex (metres and seconds)
    const std::string trip = "start: {x: -800, y: -300}\ngoal: {x: 800, y: 350}\nvehicle: {speed: 10}\n"
                             "planner: {name: zastartve, grid_size: 20}\n";
    const MissionSpec onFile = parseMission("current: {type: netcdf, file: " + file + "}\n" + trip, "vortex.yaml");
    const MissionSpec analytic =
        parseMission("units: {length_m: 1, time_s: 1}\nregion: {x_min: -1000, x_max: 1000, y_min: -1000, y_max: 1000}\n"
                     "current: {type: rankine_vortex, parameters: {x0: 1.2, y0: 0.8, radius: 1.6, vmax: 400}}\n" +
                         trip,
                     "analytic.yaml");
    const MissionResult a = runMission(MissionProblem(onFile)), b = runMission(MissionProblem(analytic));
    ASSERT_TRUE(a.plan.solved) << a.plan.reason;
    ASSERT_TRUE(b.plan.solved) << b.plan.reason;
    std::printf("vortex file: %.3f s, analytic vortex: %.3f s\n", a.plan.travelTime, b.plan.travelTime);
    EXPECT_NEAR(a.plan.travelTime, b.plan.travelTime, 1e-3 * b.plan.travelTime);
}

TEST(FastNodes, GarbageIsStillRefusedAndTheMessageNamesTheBound)
{
    TempDir dir;
    // a lone spike of 473 m/s where the flow around it is slow (far from the core): not continuous
    const std::string spike = dir.file("spike.nc");
    writeField(spike, [](std::size_t i, std::size_t j, double &u, double &) {
        if (i == 158 && j == 30)
            u = -473.867;
    });
    std::string e = refusal(spike);
    EXPECT_NE(e.find("variable 'u' holds -473.867 m/s at (j, i) = (30, 158)"), std::string::npos) << e;
    EXPECT_NE(e.find("GriddedCurrentOptions::maxSpeed"), std::string::npos) << e;

    // a fill value not declared (-999) next to the core: a fill value's size, refused however its neighbours run
    const std::string fill = dir.file("fill.nc");
    writeField(fill, [](std::size_t i, std::size_t j, double &u, double &v) {
        if (i == kCore && j == kCore)
            u = v = -999.0;
    });
    e = refusal(fill);
    EXPECT_NE(e.find("variable 'u' holds -999 m/s at (j, i) = (100, 100)"), std::string::npos) << e;

    // the whole field in mm/s written as m/s: continuous everywhere, but fast across the field
    const std::string mm = dir.file("mm.nc");
    writeField(mm, [](std::size_t, std::size_t, double &u, double &v) {
        u *= 1000.0;
        v *= 1000.0;
    });
    e = refusal(mm);
    EXPECT_NE(e.find("such nodes in this record"), std::string::npos) << e;
    EXPECT_NE(e.find("more than 300 m/s"), std::string::npos) << e;

    // the vortex with the bound set below its core: refused at the core, the message saying the bound was given
    const std::string vortex = dir.file("vortex.nc");
    writeField(vortex, kAsIs);
    GriddedCurrentOptions low;
    low.maxSpeed = 200.0;
    e = refusal(vortex, low);
    EXPECT_NE(e.find("faster than the bound given (more than 200 m/s)"), std::string::npos) << e;
    // ... and raised above it: the mm/s field read as it is (the pilot says such speeds are real)
    GriddedCurrentOptions high;
    high.maxSpeed = 1e6;
    EXPECT_EQ(refusal(mm, high), "");
}

TEST(FastNodes, TheMissionsBoundIsCurrentMaxSpeedWithUnits)
{
    TempDir dir;
    const std::string file = dir.file("vortex.nc");
    writeField(file, kAsIs);
    const std::string trip = "start: {x: -800, y: -300}\ngoal: {x: 800, y: 350}\nvehicle: {speed: 10}\n";
    // 200 kn is 102.9 m/s: the core's 360 m/s is refused, naming the mission's setting
    try
    {
        (void)MissionProblem(
            parseMission("current: {type: netcdf, file: " + file + ", max_speed: 200 kn}\n" + trip, "m.yaml"));
        ADD_FAILURE() << "a bound of 200 kn accepted a node of 360 m/s";
    }
    catch (const Error &e)
    {
        const std::string w = e.what();
        EXPECT_NE(w.find("more than 102.888"), std::string::npos) << w;
        EXPECT_NE(w.find("current.max_speed"), std::string::npos) << w;
    }
    // not a speed: refused at its line
    try
    {
        (void)parseMission("current: {type: netcdf, file: " + file + ", max_speed: 3 km}\n" + trip, "m.yaml");
        ADD_FAILURE() << "a max_speed of 3 km accepted";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("m.yaml:1: field 'current.max_speed': expected a speed > 0"),
                  std::string::npos)
            << e.what();
    }
}

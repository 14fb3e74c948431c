// The glider's measurements in a mission: the forecast corrected by its DAC, the plan from the last fix. A truth that
// is the forecast plus a uniform current: the corrected current at the glider is the truth's, and a plan on it, flown
// in the truth, arrives within 1 % of the plan made on the truth itself. DAC equal to the forecast change (almost)
// nothing.
#include <gtest/gtest.h>

#include <netcdf.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Overrides.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Observations.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/Report.h"
#include "../io/RealtimeDeployment.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
fs::path dir()
{
    const fs::path d = fs::path(::testing::TempDir()) / "observations_missions";
    fs::create_directories(d);
    return d;
}

/// A current on a lon/lat grid over 5 days, hourly, as a CF file: u = @p u + @p shear z (z the depth, m) and @p v, the
/// same everywhere and always; with @p depths a depth axis of those layers (double values), else a 2-D field (floats,
/// as many forecasts store them).
std::string gridForecast(const std::string &name, double u, double v, const std::vector<double> &depths = {},
                         double shear = 0.0)
{
    const std::string path = (dir() / name).string();
    int nc = 0, dt = 0, dz = 0, dy = 0, dx = 0, vt = 0, vz = 0, vy = 0, vx = 0, vu = 0, vv = 0;
    EXPECT_EQ(nc_create(path.c_str(), NC_CLOBBER, &nc), NC_NOERR);
    const int nt = 121, ny = 21, nx = 41, nz = depths.empty() ? 1 : static_cast<int>(depths.size());
    nc_def_dim(nc, "time", nt, &dt);
    if (!depths.empty())
        nc_def_dim(nc, "depth", nz, &dz);
    nc_def_dim(nc, "lat", ny, &dy);
    nc_def_dim(nc, "lon", nx, &dx);
    nc_def_var(nc, "time", NC_DOUBLE, 1, &dt, &vt);
    if (!depths.empty())
        nc_def_var(nc, "depth", NC_DOUBLE, 1, &dz, &vz);
    nc_def_var(nc, "lat", NC_DOUBLE, 1, &dy, &vy);
    nc_def_var(nc, "lon", NC_DOUBLE, 1, &dx, &vx);
    const std::vector<int> dims = depths.empty() ? std::vector<int>{dt, dy, dx} : std::vector<int>{dt, dz, dy, dx};
    const nc_type type = depths.empty() ? NC_FLOAT : NC_DOUBLE;
    nc_def_var(nc, "u", type, static_cast<int>(dims.size()), dims.data(), &vu);
    nc_def_var(nc, "v", type, static_cast<int>(dims.size()), dims.data(), &vv);
    const auto text = [&](int var, const char *k, const std::string &s) {
        nc_put_att_text(nc, var, k, s.size(), s.c_str());
    };
    text(vt, "units", "hours since 2026-03-15 00:00:00");
    text(vt, "standard_name", "time");
    if (!depths.empty())
    {
        text(vz, "units", "m");
        text(vz, "positive", "down");
        text(vz, "standard_name", "depth");
    }
    text(vy, "units", "degrees_north");
    text(vx, "units", "degrees_east");
    text(vu, "units", "m/s");
    text(vu, "standard_name", "eastward_sea_water_velocity");
    text(vv, "units", "m/s");
    text(vv, "standard_name", "northward_sea_water_velocity");
    nc_enddef(nc);
    std::vector<double> t(nt), y(ny), x(nx);
    for (int i = 0; i < nt; ++i)
        t[i] = i;
    for (int j = 0; j < ny; ++j)
        y[j] = 47.5 + 0.05 * j;
    for (int i = 0; i < nx; ++i)
        x[i] = -53.0 + 0.05 * i;
    nc_put_var_double(nc, vt, t.data());
    if (!depths.empty())
        nc_put_var_double(nc, vz, depths.data());
    nc_put_var_double(nc, vy, y.data());
    nc_put_var_double(nc, vx, x.data());
    const std::size_t layer = static_cast<std::size_t>(ny) * nx;
    std::vector<double> U(static_cast<std::size_t>(nt) * nz * layer), V(U.size(), v);
    for (std::size_t k = 0; k < U.size(); ++k)
        U[k] = u + shear * (depths.empty() ? 0.0 : depths[(k / layer) % static_cast<std::size_t>(nz)]);
    if (depths.empty()) // floats: the file's values are the floats of u and v
    {
        const std::vector<float> Uf(U.begin(), U.end()), Vf(V.begin(), V.end());
        nc_put_var_float(nc, vu, Uf.data());
        nc_put_var_float(nc, vv, Vf.data());
    }
    else
    {
        nc_put_var_double(nc, vu, U.data());
        nc_put_var_double(nc, vv, V.data());
    }
    nc_close(nc);
    return path;
}

/// A uniform current (u, v) on a lon/lat grid over 5 days, hourly, as a CF file (floats).
std::string uniformForecast(const std::string &name, double u, double v)
{
    return gridForecast(name, u, v);
}

/// Eight DAC of (u, v) over the 12 h before 2026-03-16T00:00Z along lat 48.0 from lon -52.30 to -52.09 (the last fix);
/// with @p count, that many every 1.5 h, 0.03 deg of longitude apart, ending there.
std::string dacCsv(const std::string &name, double u, double v, int count = 8)
{
    const std::string path = (dir() / name).string();
    std::ofstream f(path);
    f << "time,lon,lat,u,v\n";
    const double end = parseIsoTime("2026-03-16T00:00:00Z");
    for (int k = 0; k < count; ++k)
        f << formatIsoTime(end - 1.5 * 3600.0 * (count - k)) << "," << -52.09 - 0.03 * (count - 1 - k) << ",48.0,"
          << std::setprecision(17) << u << "," << v << std::setprecision(6) << "\n";
    f << formatIsoTime(end) << ",-52.09,48.0,,\n"; // the last fix
    return path;
}

MissionSpec missionOn(const std::string &forecast, const std::string &extra,
                      const std::string &goal = "goal: {lon: -51.95, lat: 48.08}\n")
{
    return parseMission("name: obs\ncurrent: {type: netcdf, file: '" + forecast + "'}\n" + goal +
                            "vehicle: {speed: 0.3}\nplanner: {grid_size: 500}\n" + extra,
                        "obs.yaml");
}
} // namespace

TEST(Observations, ReplanFromTheLastFixOnTheCorrectedForecastFliesAsThePlanOnTheTruth)
{
    const std::string forecast = uniformForecast("forecast.nc", 0.1, 0.0);
    const std::string truth = uniformForecast("truth.nc", 0.2, 0.05);
    const std::string dac = dacCsv("dac.csv", 0.2, 0.05);
    const MissionSpec corrected = missionOn(forecast, "observations: '" + dac + "'\n");
    // no start: the last fix, at its time
    ASSERT_TRUE(corrected.start.geographic);
    EXPECT_DOUBLE_EQ(corrected.start.lonLat.lon, -52.09);
    EXPECT_DOUBLE_EQ(corrected.departure.time, 24 * 3600.0);
    const MissionProblem pc(corrected);
    ASSERT_TRUE(pc.observations());
    EXPECT_EQ(pc.observations()->correction.used, 8u);
    EXPECT_NEAR(pc.observations()->correction.rmsBefore, std::hypot(0.1, 0.05), 1e-6 + 1e-7 * 8); // float file
    EXPECT_LT(pc.observations()->correction.rmsAfter, 0.1 * pc.observations()->correction.rmsBefore);
    const MissionSpec onTruth = missionOn(truth, "start: {lon: -52.09, lat: 48.0}\ndeparture: {time: 86400}\n");
    const MissionProblem pt(onTruth);
    // at the glider the corrected forecast is the truth but for the interpolation's shrinkage towards the forecast
    const Point2 fix = pc.getStart();
    const Velocity c = pc.getField()->velocity(fix.x, fix.y, 0.0, corrected.departure.time);
    const Velocity w = pt.getField()->velocity(fix.x, fix.y, 0.0, corrected.departure.time);
    EXPECT_LT(std::hypot(c.u - w.u, c.v - w.v), 0.01);
    const MissionResult best = runMission(pt);
    const MissionResult plan = runMission(pc);
    ASSERT_TRUE(best.plan.solved && plan.plan.solved);
    // the corrected plan flown in the truth, leg by leg
    const std::vector<TimedPoint> flown = retimePath(pt, pt.getField(), 0.3, plan.plan.path);
    ASSERT_FALSE(flown.empty());
    const double t = flown.back().t - flown.front().t;
    EXPECT_LT(std::abs(t / best.plan.travelTime - 1.0), 0.01) << t << " against " << best.plan.travelTime;
    // while the forecast's own plan, flown in the truth, is further off
    const MissionResult blind = runMission(MissionProblem(missionOn(forecast, "start: {lon: -52.09, lat: 48.0}\n"
                                                                              "departure: {time: 86400}\n")));
    const std::vector<TimedPoint> blindFlown = retimePath(pt, pt.getField(), 0.3, blind.plan.path);
    ASSERT_FALSE(blindFlown.empty());
    EXPECT_GT(std::abs(blind.plan.travelTime / best.plan.travelTime - 1.0), 0.05);
}

TEST(Observations, ADayOfDacShowingOneErrorCorrectsThePlanWithTheDefaultSettings)
{
    // the truth is the forecast plus a uniform (0.15, -0.05) m/s; sixteen DAC over a day along 25 km of track all show
    // that error; the goal is 20 km ahead. With the default scales as fixed values (L 20 km, T 1 d) the correction
    // fades before the goal and the plan's predicted arrival is off by more than 5 % (7.7 %); learned from the DAC (the
    // default) the plan predicts its arrival within 3 % of the plan made on the truth, and flown in the truth arrives
    // within 1 % of it.
    const std::string forecast = uniformForecast("learn_forecast.nc", 0.05, 0.02);
    const std::string truth = uniformForecast("learn_truth.nc", 0.20, -0.03);
    const std::string dac = dacCsv("learn_dac.csv", 0.20, -0.03, 16);
    const std::string goal = "goal: {lon: -51.82, lat: 48.0}\n";
    const MissionProblem learned(missionOn(forecast, "observations: '" + dac + "'\n", goal));
    const MissionProblem fixed(missionOn(forecast, "observations: {file: '" + dac + "', learn: false}\n", goal));
    const MissionProblem onTruth(missionOn(truth, "start: {lon: -52.09, lat: 48.0}\ndeparture: {time: 86400}\n", goal));
    ASSERT_TRUE(learned.observations());
    const CorrectionSummary &c = learned.observations()->correction;
    // (the forecast is read over the mission's region: the westernmost DAC lie outside it)
    EXPECT_GE(c.used, 12u);
    EXPECT_EQ(c.learnedFrom, c.used);
    EXPECT_EQ(c.lengthSource, "estimated from " + std::to_string(c.used) + " DAC");
    ASSERT_TRUE(c.mean.active());
    // a uniform error: the scales and mean learned from the earlier DAC predict the later ones better than the
    // priors (judged on DAC not used to fit them), and the report says they were kept
    EXPECT_GT(c.heldOut.scored, 0u);
    EXPECT_EQ(c.heldOut.fitted + c.heldOut.scored, c.learnedFrom);
    EXPECT_TRUE(c.heldOut.scalesKept && c.heldOut.meanKept);
    EXPECT_LT(c.heldOut.learnedError, c.heldOut.priorError);
    EXPECT_NE(correctionNote(learned).find("learned scales and mean kept (held-out RMS error"), std::string::npos)
        << correctionNote(learned);
    const MissionResult best = runMission(onTruth), withLearning = runMission(learned), withPriors = runMission(fixed);
    ASSERT_TRUE(best.plan.solved && withLearning.plan.solved && withPriors.plan.solved);
    EXPECT_LT(std::abs(withLearning.plan.travelTime / best.plan.travelTime - 1.0), 0.03)
        << withLearning.plan.travelTime << " against " << best.plan.travelTime;
    EXPECT_GT(std::abs(withPriors.plan.travelTime / best.plan.travelTime - 1.0), 0.05)
        << withPriors.plan.travelTime << " against " << best.plan.travelTime;
    const std::vector<TimedPoint> flown = retimePath(onTruth, onTruth.getField(), 0.3, withLearning.plan.path);
    ASSERT_FALSE(flown.empty());
    EXPECT_LT(std::abs((flown.back().t - flown.front().t) / best.plan.travelTime - 1.0), 0.01);
}

TEST(Observations, DacEqualToTheForecastChangeAlmostNothing)
{
    const std::string forecast = uniformForecast("same.nc", 0.1, 0.0);
    const std::string dac = dacCsv("same.csv", static_cast<double>(0.1f), 0.0); // the file's float, as a CSV has it
    const std::string start = "start: {lon: -52.09, lat: 48.0}\ndeparture: {time: 86400}\n";
    const MissionResult with = runMission(MissionProblem(missionOn(forecast, start + "observations: '" + dac + "'\n")));
    const MissionResult without = runMission(MissionProblem(missionOn(forecast, start)));
    ASSERT_TRUE(with.plan.solved);
    // DAC in east/north against a forecast turned into the plane at its nodes: equal but for the rounding of the
    // turn (bit-identity holds where the DAC is measured in the plane: CorrectedField.NoInnovationChangesNothing...)
    EXPECT_NEAR(with.plan.travelTime, without.plan.travelTime, 1e-6 * without.plan.travelTime);
}

TEST(Observations, BadObservationsNameTheField)
{
    const std::string forecast = uniformForecast("bad.nc", 0.1, 0.0);
    try
    {
        missionOn(forecast, "observations: {file: '/nonexistent/ru29'}\n");
        FAIL() << "accepted a missing deployment";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("obs.yaml:6: field 'observations'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no such file or folder"), std::string::npos) << e.what();
    }
    EXPECT_THROW(missionOn(forecast, "observations: {file: x.csv, error_ratio: 0}\n"), Error);
    // DAC all after the departure: nothing to correct with, said so (a start given by the caller: the mission is
    // not resumed at the last fix, the observations only correct the forecast)
    const std::string dac = dacCsv("late.csv", 0.2, 0.0);
    try
    {
        MissionSpec m = missionOn(forecast, "departure: {time: 3600}\nobservations: '" + dac + "'\n");
        MissionOverrides o;
        o.start = Given<Point2>{{-52.09, 48.0}, "--start"};
        o.departure = Given<std::string>{"3600", "--departure"};
        applyOverrides(o, m);
        MissionProblem p(m);
        FAIL() << "accepted observations from the future";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("8 after the departure"), std::string::npos) << e.what();
    }
}

// DAC far from the mission (here 1700 km east, of another glider's ocean) say nothing of its currents: counted apart
// as such, never reported as used.
TEST(Observations, DacFarFromTheMissionAreCountedApartNotUsed)
{
    const std::string forecast = uniformForecast("far_forecast.nc", 0.1, 0.0);
    const std::string dac = dacCsv("far_dac.csv", 0.2, 0.05);
    {
        std::ofstream f(dac, std::ios::app);
        for (int k = 0; k < 3; ++k)
            f << formatIsoTime(parseIsoTime("2026-03-15T20:00:00Z") + 600.0 * k) << ",-30.0," << 48.0 + 0.1 * k
              << ",0.2,0.05\n";
    }
    const MissionProblem p(missionOn(forecast, "observations: '" + dac + "'\n"));
    ASSERT_TRUE(p.observations());
    EXPECT_EQ(p.observations()->far, 3u);
    EXPECT_EQ(p.observations()->correction.used, 8u);
    EXPECT_EQ(p.observations()->correction.outsideForecast, 0u);
    const std::string note = observationNote(p);
    EXPECT_NE(note.find("8 DAC used"), std::string::npos) << note;
    EXPECT_NE(note.find("3 farther than 200 km from the mission's area"), std::string::npos) << note;
}

namespace
{
/// A current sheared in depth, the same everywhere and always: u = 0.3 - 0.002 z m/s on layers 0, 100, 200 m (linear:
/// its mean over 0-180 m is its value at 90 m, 0.12 m/s), v = 0, as a CF file with a depth axis.
std::string shearedForecast(const std::string &name)
{
    return gridForecast(name, 0.3, 0.0, {0.0, 100.0, 200.0}, -0.002);
}
} // namespace

// A DAC is the current averaged over the dive: compared with the surface current of a sheared forecast it shows an
// error the forecast does not have (0.18 m/s here), and the report says so with the remedy; compared with the depth
// average it measured (current.depth_average) it shows none.
TEST(Observations, DacAreComparedWithTheDepthAverageTheMissionSays)
{
    const std::string forecast = shearedForecast("sheared.nc");
    const std::string dac = dacCsv("sheared_dac.csv", 0.12, 0.0); // exactly the 0-180 m mean
    const std::string start = "start: {lon: -52.09, lat: 48.0}\ndeparture: {time: 86400}\n";
    const std::string obs = "observations: {file: '" + dac + "', learn: false}\n";
    const MissionProblem surface(missionOn(forecast, start + obs));
    ASSERT_TRUE(surface.observations());
    EXPECT_NEAR(surface.observations()->correction.rmsBefore, 0.18, 1e-6);
    EXPECT_NE(surface.observations()->comparedWith.find("the surface current"), std::string::npos)
        << surface.observations()->comparedWith;
    EXPECT_NE(surface.observations()->comparedWith.find("current.depth_average"), std::string::npos);
    const MissionProblem averaged(parseMission("name: obs\ncurrent: {type: netcdf, file: '" + forecast +
                                                   "', depth_average: [0, 180]}\ngoal: {lon: -51.95, lat: 48.08}\n"
                                                   "vehicle: {speed: 0.3}\nplanner: {grid_size: 500}\n" +
                                                   start + obs,
                                               "obs.yaml"));
    ASSERT_TRUE(averaged.observations());
    EXPECT_NEAR(averaged.observations()->correction.rmsBefore, 0.0, 1e-6);
    EXPECT_NE(averaged.observations()->comparedWith.find("0-180 m average"), std::string::npos)
        << averaged.observations()->comparedWith;
}

// The glider surfaced after its last valid fix without a valid one (the placeholder 69696969): the plan departs from
// the last valid fix, and the report warns how much older it is than the newest surfacing.
TEST(Observations, AStartFromAFixOlderThanTheNewestSurfacingIsWarned)
{
    const std::string forecast = uniformForecast("stale.nc", 0.1, 0.0);
    const fs::path folder = dir() / "stale_dba";
    fs::create_directories(folder);
    const double t0 = parseIsoTime("2026-03-15T12:00:00Z"), nan = std::nan("");
    std::string text = realtime_test::dbaHeader("ru29-2026-074-0-0");
    text += realtime_test::dbaRow(t0, 48.0, -52.30, 0, nan, nan, 0.5);
    text += realtime_test::dbaRow(t0 + 3600, nan, nan, nan, nan, nan, 100.0);
    text += realtime_test::dbaRow(t0 + 7200, 48.0, -52.25, 0, nan, nan, 0.5); // the last valid fix
    text += realtime_test::dbaRow(t0 + 7260, nan, nan, nan, 0.1, 0.0, 0.5);
    text += realtime_test::dbaRow(t0 + 10800, nan, nan, nan, nan, nan, 100.0);
    text += realtime_test::dbaRow(t0 + 14400, 69696969.0, 69696969.0, 0, nan, nan, 0.5); // surfaced, no fix
    std::ofstream((folder / "ru29-2026-074-0-0.dba").string()) << text;
    const MissionProblem p(
        missionOn(forecast, "start: {lon: -52.5, lat: 48.0}\nobservations: '" + folder.string() + "'\n"));
    const MissionSpec &m = p.getSpec();
    ASSERT_TRUE(m.observations && m.observations->resumed);
    EXPECT_EQ(m.isoTime(m.departure.time), "2026-03-15T14:00:00Z"); // the last valid fix
    const std::string &warning = m.observations->resumed->staleFix;
    EXPECT_NE(warning.find("2026-03-15T16:00:00Z"), std::string::npos) << warning;
    EXPECT_NE(warning.find("2 h older"), std::string::npos) << warning;
    EXPECT_NE(resumeNote(m).find("WARNING: " + warning), std::string::npos);
    // a deployment whose newest surfacing gave its fix: no warning
    std::string fine = realtime_test::dbaHeader("ru29-2026-074-0-0");
    fine += realtime_test::dbaRow(t0, 48.0, -52.30, 0, nan, nan, 0.5);
    fine += realtime_test::dbaRow(t0 + 60, nan, nan, nan, 0.1, 0.0, 0.5); // no fix before its dive: at the surfacing
    fine += realtime_test::dbaRow(t0 + 3600, nan, nan, nan, nan, nan, 100.0);
    fine += realtime_test::dbaRow(t0 + 7200, 48.0, -52.25, 0, nan, nan, 0.5);
    fine += realtime_test::dbaRow(t0 + 7260, nan, nan, nan, 0.1, 0.0, 0.5);
    std::ofstream((folder / "ru29-2026-074-0-0.dba").string()) << fine;
    const MissionProblem q(
        missionOn(forecast, "start: {lon: -52.5, lat: 48.0}\nobservations: '" + folder.string() + "'\n"));
    EXPECT_TRUE(q.getSpec().observations->resumed->staleFix.empty()) << q.getSpec().observations->resumed->staleFix;
    // the reader's note of the DAC placed at its surfacing reaches the report's correction lines
    const MissionResult r = runMission(q);
    const std::vector<std::string> lines = correctionLines(r);
    ASSERT_FALSE(lines.empty());
    EXPECT_NE(lines.front().find("1 DAC placed at the surfacing's fix"), std::string::npos) << lines.front();
}

// The report's words of what the glider measured are from true north: a uniform error of the forecast of (0.1, 0.1)
// m/s east and north, measured where the planning frame's grid north is 4-5 degrees off true north (its projection
// centred 6 degrees of longitude away), is (0.1, 0.1) east and north again, not the frame's rotated components.
TEST(Observations, TheMeasuredDifferenceIsSaidEastAndNorth)
{
    const std::string forecast = uniformForecast("en.nc", 0.1, 0.0);
    const std::string dac = dacCsv("en.csv", 0.2, 0.1);
    const MissionProblem p(missionOn(forecast, "projection: {lon0: -46.0, lat0: 48.0}\n"
                                               "start: {lon: -52.09, lat: 48.0}\ndeparture: {time: 86400}\n"
                                               "observations: {file: '" +
                                                   dac + "', learn: false}\n"));
    ASSERT_TRUE(p.observations());
    const ObservationReport &o = *p.observations();
    EXPECT_NEAR(o.meanInnovationEastNorth.u, 0.1, 1e-6);
    EXPECT_NEAR(o.meanInnovationEastNorth.v, 0.1, 1e-6);
    // in the frame the same difference is turned by the meridians' convergence there
    const double turn = std::atan2(o.correction.meanInnovation.u, o.correction.meanInnovation.v) * 180.0 / M_PI - 45.0;
    EXPECT_GT(std::abs(turn), 3.0) << turn;
    // (its length alike but for the frame's east and north at the grid's nodes, where the forecast was turned)
    EXPECT_NEAR(std::hypot(o.correction.meanInnovation.u, o.correction.meanInnovation.v), std::hypot(0.1, 0.1), 1e-5);
}

// With a dive profile the forecast holds the layers down to its z_max: each DAC is compared with the forecast
// averaged over its own dive's depths (a dba file's m_depth over the segment, 0-180 m: 0.12 m/s), not over the
// profile's 0-200 m (0.10 m/s).
TEST(Observations, WithADiveProfileEachDacIsComparedOverItsOwnDive)
{
    const std::string forecast = shearedForecast("sheared_dive.nc");
    const fs::path folder = dir() / "own_dive_dba";
    fs::create_directories(folder);
    const double t0 = parseIsoTime("2026-03-15T12:00:00Z"), nan = std::nan("");
    std::string text = realtime_test::dbaHeader("ru29-2026-074-0-0");
    text += realtime_test::dbaRow(t0, 48.0, -52.30, 0, nan, nan, 0.0);
    text += realtime_test::dbaRow(t0 + 3600, nan, nan, nan, nan, nan, 180.0);
    text += realtime_test::dbaRow(t0 + 7200, 48.0, -52.25, 0, nan, nan, 0.0);
    text += realtime_test::dbaRow(t0 + 7260, nan, nan, nan, 0.12, 0.0, 0.0);
    std::ofstream((folder / "ru29-2026-074-0-0.dba").string()) << text;
    const MissionProblem p(missionOn(forecast, "start: {lon: -52.5, lat: 48.0}\ndive_profile: {z_min: 0, z_max: 200}\n"
                                               "observations: {file: '" +
                                                   folder.string() + "', learn: false}\n"));
    ASSERT_TRUE(p.observations());
    const ObservationReport &o = *p.observations();
    ASSERT_EQ(o.dac.size(), 1u);
    EXPECT_EQ(o.dac[0].depthMax, 180.0);
    EXPECT_NEAR(o.correction.rmsBefore, 0.0, 1e-6);
    EXPECT_EQ(o.deepestDive, 180.0);
    EXPECT_NE(o.comparedWith.find("each dive's own depths (1 of 1 DAC"), std::string::npos) << o.comparedWith;
}

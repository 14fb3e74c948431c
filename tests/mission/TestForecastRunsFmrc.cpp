// Forecast runs in one file of several runs, as a THREDDS FMRC serves them over OPeNDAP (the velocities on a run
// dimension whose coordinate is the runs' reference times, time a 2-D time(run, time)): given as `current.runs` it
// is each of its runs, and every departure is planned as on the same runs given one file each (to 1e-9); each run's
// reference time is its value of the run coordinate; a run shorter than the others (its row of time ending in fill
// values) keeps only its own times; the file given as `current.file` is an error that says to give it as runs.
// Served over OPeNDAP (the tests' DAP2 server), the URL is the same runs; an execution through them flies as through
// the run files. Also a folder of daily HYCOM-named run files whose reference time is HYCOM's `tau` (hours since the
// analysis), HYCOM's one file per time step as one run in several files, and a THREDDS best time series (a
// forecast_reference_time along time) read as one forecast.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../opendap/DapServer.h"
#include "RunFiles.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/ForecastRuns.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionExecution.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
/// Five daily runs of @p lengths records each, one file a run and all in one file of several runs.
struct FmrcAndFiles
{
    TempDir dir;
    std::vector<std::string> files;
    std::string fmrc;
    explicit FmrcAndFiles(const std::vector<std::size_t> &lengths = std::vector<std::size_t>(5, kRunTimes),
                          const FmrcLayout &layout = {})
    {
        for (std::size_t r = 0; r < lengths.size(); ++r)
        {
            files.push_back(dir.file("run_2026030" + std::to_string(1 + r) + ".nc"));
            writeRun(files.back(), int(r), RunReference::Variable, lengths[r]);
        }
        fmrc = dir.file("fmrc_TwoD.nc");
        writeFmrc(fmrc, lengths, layout);
    }
    std::string mission(const std::string &name, const std::string &current, const std::string &departure) const
    {
        const std::string path = dir.file(name + ".yaml");
        std::ofstream(path)
            << "name: " << name << "\ncurrent:\n  type: netcdf\n"
            << current << "  horizon: hold_last\n"
            << "start: {lon: -52.85, lat: 47.15}\ngoal: {lon: -52.1, lat: 47.85}\n"
            << "departure: {time: \"" << departure << "\"}\n"
            << "vehicle: {speed: 0.5}\nplanner: {name: zastartve, grid_size: 4000, sectors: 3, global_check: false}\n";
        return path;
    }
    std::string onFiles() const { return "  runs: \"" + dir.file("run_*.nc") + "\"\n"; }
    std::string onFmrc() const { return "  runs: \"" + fmrc + "\"\n"; }
};

void expectSameFmrcPlan(const MissionResult &a, const MissionResult &b)
{
    ASSERT_TRUE(a.plan.solved) << a.plan.reason;
    ASSERT_TRUE(b.plan.solved) << b.plan.reason;
    EXPECT_NEAR(a.plan.travelTime, b.plan.travelTime, 1e-9);
    EXPECT_NEAR(a.plan.rawTravelTime, b.plan.rawTravelTime, 1e-9);
    ASSERT_EQ(a.plan.path.size(), b.plan.path.size());
    for (std::size_t k = 0; k < a.plan.path.size(); ++k)
    {
        EXPECT_NEAR(a.plan.path[k].x, b.plan.path[k].x, 1e-9); // metres
        EXPECT_NEAR(a.plan.path[k].y, b.plan.path[k].y, 1e-9);
        EXPECT_NEAR(a.plan.path[k].t, b.plan.path[k].t, 1e-9); // seconds
    }
}

/// The runs of @p a and @p b are the same runs: times, reference times, availability and currents.
void expectSameFmrcRuns(const ForecastRuns &a, const ForecastRuns &b)
{
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k)
    {
        SCOPED_TRACE(k);
        EXPECT_EQ(a[k].begin, b[k].begin);
        EXPECT_EQ(a[k].end, b[k].end);
        EXPECT_EQ(a[k].reference, b[k].reference);
        EXPECT_EQ(a[k].available, b[k].available);
        for (double dt : {0.0, 5.0, 23.0})
        {
            const double t = std::min(a[k].begin + dt * 3600.0, a[k].end);
            const Velocity va = a.field(k)->velocity(1500.0, -2500.0, 0.0, t),
                           vb = b.field(k)->velocity(1500.0, -2500.0, 0.0, t);
            EXPECT_EQ(va.u, vb.u);
            EXPECT_EQ(va.v, vb.v);
        }
    }
}
} // namespace

TEST(ForecastRunsFmrc, EveryDepartureIsPlannedAsOnTheRunFiles)
{
    const FmrcAndFiles runs;
    const char *departures[] = {"2026-03-01T12:00:00Z", "2026-03-02T11:59:00Z", "2026-03-03T12:00:00Z",
                                "2026-03-04T20:00:00Z", "2026-03-05T13:00:00Z"};
    const std::size_t expected[] = {0, 0, 2, 3, 4};
    for (std::size_t c = 0; c < 5; ++c)
    {
        SCOPED_TRACE(departures[c]);
        const MissionProblem onFmrc(loadMission(runs.mission("fmrc", runs.onFmrc(), departures[c])));
        const MissionProblem onFiles(loadMission(runs.mission("files", runs.onFiles(), departures[c])));
        ASSERT_TRUE(onFmrc.runs());
        ASSERT_TRUE(onFiles.runs());
        EXPECT_EQ(onFmrc.runs()->size(), 5u);
        EXPECT_EQ(onFmrc.runIndex(), expected[c]);
        EXPECT_EQ(onFiles.runIndex(), expected[c]);
        const MissionResult a = runMission(onFmrc), b = runMission(onFiles);
        expectSameFmrcPlan(a, b);
        ASSERT_FALSE(a.forecastNotes.empty());
        const std::string &note = a.forecastNotes.front();
        EXPECT_NE(note.find("run " + std::to_string(expected[c] + 1) + " of 5"), std::string::npos) << note;
        EXPECT_NE(note.find("variable 'run', run " + std::to_string(expected[c] + 1) + " of 5"), std::string::npos)
            << note;
    }
}

TEST(ForecastRunsFmrc, ReferenceTimesAreTheRunCoordinate)
{
    const FmrcAndFiles runs;
    const MissionProblem p(loadMission(runs.mission("fmrc", runs.onFmrc(), "2026-03-01T12:00:00Z")));
    const MissionProblem q(loadMission(runs.mission("files", runs.onFiles(), "2026-03-01T12:00:00Z")));
    ASSERT_TRUE(p.runs());
    const ForecastRuns &r = *p.runs();
    const MissionSpec &m = p.getSpec();
    for (std::size_t k = 0; k < r.size(); ++k)
    {
        SCOPED_TRACE(k);
        EXPECT_EQ(r[k].file, runs.fmrc);
        ASSERT_TRUE(r[k].runIndex);
        EXPECT_EQ(*r[k].runIndex, k);
        EXPECT_EQ(m.isoTime(r[k].reference), "2026-03-0" + std::to_string(k + 1) + "T00:00:00Z");
        EXPECT_EQ(m.isoTime(r[k].begin), "2026-03-0" + std::to_string(k + 1) + "T00:00:00Z");
        EXPECT_DOUBLE_EQ(r[k].end - r[k].begin, 72.0 * 3600.0);
        EXPECT_EQ(r[k].referenceFrom, "variable 'run', run " + std::to_string(k + 1) + " of 5");
    }
    expectSameFmrcRuns(r, *q.runs());
}

TEST(ForecastRunsFmrc, ARunShorterThanTheOthersKeepsItsOwnTimes)
{
    // THREDDS 5 names (reftime, time1) and a depth: u(reftime, time1, depth, lat, lon); run 2 has 2 days, run 4 one
    const std::vector<std::size_t> lengths{25, 25, 17, 25, 9};
    FmrcLayout layout;
    layout.run = "reftime";
    layout.time = "time1";
    layout.depth = true;
    const FmrcAndFiles runs(lengths, layout);
    for (const char *departure : {"2026-03-03T13:00:00Z", "2026-03-05T12:30:00Z"})
    {
        SCOPED_TRACE(departure);
        const MissionProblem p(loadMission(runs.mission("fmrc", runs.onFmrc(), departure)));
        const MissionProblem q(loadMission(runs.mission("files", runs.onFiles(), departure)));
        ASSERT_TRUE(p.runs());
        const ForecastRuns &r = *p.runs();
        for (std::size_t k = 0; k < r.size(); ++k)
            EXPECT_DOUBLE_EQ(r[k].end - r[k].begin, 3.0 * 3600.0 * double(lengths[k] - 1)) << k;
        EXPECT_EQ(r[4].referenceFrom, "variable 'reftime', run 5 of 5");
        expectSameFmrcRuns(r, *q.runs());
        expectSameFmrcPlan(runMission(p), runMission(q));
    }
}

TEST(ForecastRunsFmrc, AnExecutionThroughTheFmrcsRunsFliesAsThroughTheRunFiles)
{
    // flown in a truth of 6 days (the first run's flow carried on), replanning every 3 h and when a run arrives: the
    // same flights
    const FmrcAndFiles runs;
    const std::string truth = runs.dir.file("truth.nc");
    writeRun(truth, 0, RunReference::None, 2 * kRunTimes - 1);
    const std::string execution = "  run_delay: 12 h\nexecution: {truth: {type: netcdf, file: \"" + truth +
                                  "\", horizon: hold_last}, strategies: [current_sensitive, replan], "
                                  "surfacing_interval: 1 h, replan_every: 3, duration: 3 d}\n";
    const auto with = [&](const std::string &current) {
        const std::string name = current == runs.onFmrc() ? "fmrc_exec" : "files_exec";
        const std::string path = runs.mission(name, current, "2026-03-02T12:00:00Z");
        std::string text;
        {
            std::ifstream in(path);
            text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
        const std::size_t at = text.find("start:");
        std::ofstream(path) << text.substr(0, at) << execution << text.substr(at);
        return runMission(MissionProblem(loadMission(path)));
    };
    const MissionResult a = with(runs.onFmrc()), b = with(runs.onFiles());
    ASSERT_TRUE(a.execution && b.execution);
    ASSERT_EQ(a.execution->runs.size(), b.execution->runs.size());
    const ExecutionRun &ra = a.execution->runs.front(), &rb = b.execution->runs.front();
    ASSERT_EQ(ra.flown.size(), 2u);
    ASSERT_EQ(rb.flown.size(), 2u);
    for (std::size_t s = 0; s < ra.flown.size(); ++s)
    {
        SCOPED_TRACE(s);
        const FlownTrack &fa = ra.flown[s], &fb = rb.flown[s];
        EXPECT_EQ(fa.replans, fb.replans);
        EXPECT_EQ(fa.reached, fb.reached);
        ASSERT_EQ(fa.fixes.size(), fb.fixes.size());
        for (std::size_t k = 0; k < fa.fixes.size(); ++k)
        {
            EXPECT_NEAR(fa.fixes[k].x, fb.fixes[k].x, 1e-9);
            EXPECT_NEAR(fa.fixes[k].y, fb.fixes[k].y, 1e-9);
            EXPECT_NEAR(fa.fixes[k].t, fb.fixes[k].t, 1e-9);
        }
    }
    EXPECT_GT(ra.flown[1].replans, 0u);
}

TEST(ForecastRunsFmrc, AnFmrcServedOverOpendapIsTheSameRuns)
{
    const FmrcAndFiles runs({25, 25, 25, 17, 9});
    const std::string served = runs.dir.file("served");
    std::filesystem::create_directories(served);
    dap_test::DapServer server(served);
    std::filesystem::copy_file(runs.fmrc, served + "/fmrc_TwoD.nc");
    const std::string url = server.url("fmrc_TwoD.nc");
    const char *departure = "2026-03-04T20:00:00Z";
    const MissionProblem onUrl(loadMission(runs.mission("url", "  runs: \"" + url + "\"\n", departure)));
    const MissionProblem onFile(loadMission(runs.mission("fmrc", runs.onFmrc(), departure)));
    ASSERT_TRUE(onUrl.runs());
    EXPECT_EQ(onUrl.runIndex(), 3u);
    EXPECT_EQ((*onUrl.runs())[3].file, url);
    expectSameFmrcRuns(*onUrl.runs(), *onFile.runs());
    expectSameFmrcPlan(runMission(onUrl), runMission(onFile));
}

TEST(ForecastRunsFmrc, TheCommandLinesRunsReadTheFmrc)
{
    // glider_plan --currents FMRC --runs and Field.netcdf(FMRC, runs=True): forecastMission() on the run's clock
    const FmrcAndFiles runs;
    const ForecastInput in = runsInput("2026-03-03T13:00:00Z");
    ForecastInput onFmrc = in, onFiles = in;
    onFmrc.current.runs = {runs.fmrc};
    onFiles.current.runs = runs.files;
    MissionSpec a = forecastMission(onFmrc), b = forecastMission(onFiles);
    for (MissionSpec *m : {&a, &b})
        m->planner.globalCheck = false; // (its wall-clock limit is not reproducible)
    EXPECT_EQ(a.current.file, runs.fmrc);
    ASSERT_TRUE(a.current.runIndex);
    EXPECT_EQ(*a.current.runIndex, 2u);
    EXPECT_EQ(a.departure.time, b.departure.time);
    const MissionProblem pa(a), pb(b);
    ASSERT_TRUE(pa.runs());
    EXPECT_EQ(pa.runIndex(), 2u);
    expectSameFmrcPlan(runMission(pa), runMission(pb));
    // the file of several runs given as one forecast: an error that says to read it as runs
    ForecastInput plain = in;
    plain.current.file = runs.fmrc;
    try
    {
        (void)MissionProblem(forecastMission(plain));
        FAIL() << "expected an error";
    }
    catch (const Error &e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("5 forecast runs"), std::string::npos) << what;
        EXPECT_NE(what.find("current.runs"), std::string::npos) << what;
    }
}

TEST(ForecastRunsFmrc, GivenAsFileItIsAnErrorSayingRuns)
{
    const FmrcAndFiles runs;
    try
    {
        (void)loadMission(runs.mission("plain", "  file: \"" + runs.fmrc + "\"\n", "2026-03-02T12:00:00Z"));
        FAIL() << "expected an error";
    }
    catch (const Error &e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("current.file"), std::string::npos) << what;
        EXPECT_NE(what.find("holds 5 forecast runs"), std::string::npos) << what;
        EXPECT_NE(what.find("'runs:'"), std::string::npos) << what;
    }
}

namespace
{
/// A HYCOM (GOFS 3.1 / ESPC) run file: water_u/water_v(time, depth, lat, lon), time in hours since 2000-01-01, and
/// `tau` the hours since the analysis (the run's reference time, 12Z on day 1 + r): records k0 .. k0 + nt - 1 of the
/// run's 17, 3-hourly from 12 h after its analysis (HYCOM writes one file per time step: nt = 1).
void writeHycomRun(const std::string &path, int r, std::size_t k0 = 0, std::size_t nt = 17)
{
    NcWriter w(path, NC_CLOBBER);
    const int dt = w.dim("time", nt), dz = w.dim("depth", 1), dy = w.dim("lat", kRunNy), dx = w.dim("lon", kRunNx);
    const int vt = w.var("time", NC_DOUBLE, {dt}), vtau = w.var("tau", NC_DOUBLE, {dt}),
              vz = w.var("depth", NC_DOUBLE, {dz}), vy = w.var("lat", NC_DOUBLE, {dy}),
              vx = w.var("lon", NC_DOUBLE, {dx});
    const int vu = w.var("water_u", NC_FLOAT, {dt, dz, dy, dx}), vv = w.var("water_v", NC_FLOAT, {dt, dz, dy, dx});
    w.text(vt, "units", "hours since 2000-01-01 00:00:00");
    w.text(vt, "time_origin", "2000-01-01 00:00:00");
    w.text(vtau, "long_name", "Tau");
    w.text(vtau, "units", "hours since analysis");
    w.text(vtau, "time_origin", "2026-03-0" + std::to_string(1 + r) + " 12:00:00");
    w.text(vz, "units", "m");
    w.text(vz, "positive", "down");
    describeLatLonVelocity(w, vy, vx, vu, vv, "m/s");
    w.enddef();
    // 2026-03-01T00:00Z is 26 years (7 leap days) after 2000-01-01: 9556 days
    const double analysis = (9556.0 + r) * 24.0 + 12.0;
    std::vector<double> tau = linspace(12.0 + 3.0 * double(k0), 3.0, nt), time;
    for (double h : tau)
        time.push_back(analysis + h);
    std::vector<double> u, v;
    runFlow(r, k0 + nt, u, v);
    const std::size_t skip = k0 * kRunNy * kRunNx;
    u.erase(u.begin(), u.begin() + std::ptrdiff_t(skip));
    v.erase(v.begin(), v.begin() + std::ptrdiff_t(skip));
    w.put(vt, time);
    w.put(vtau, tau);
    w.put(vz, {0.0});
    w.put(vy, runLats());
    w.put(vx, runLons());
    w.put(vu, u);
    w.put(vv, v);
}

/// A mission on the runs @p glob, departing 2026-03-03T06Z.
std::string hycomMission(const TempDir &dir, const std::string &name, const std::string &glob)
{
    const std::string path = dir.file(name + ".yaml");
    std::ofstream(path) << "name: hycom\ncurrent:\n  type: netcdf\n  runs: \"" << dir.file(glob)
                        << "\"\n  horizon: hold_last\n"
                        << "start: {lon: -52.85, lat: 47.15}\ngoal: {lon: -52.1, lat: 47.85}\n"
                        << "departure: {time: \"2026-03-03T06:00:00Z\"}\nvehicle: {speed: 0.5}\n"
                        << "planner: {name: zastartve, grid_size: 4000, sectors: 3, global_check: false}\n";
    return path;
}
} // namespace

TEST(ForecastRunsFmrc, AFolderOfHycomRunsTakesTheReferenceFromTau)
{
    TempDir dir;
    for (int r = 0; r < 4; ++r)
        writeHycomRun(dir.file("hycom_glby_930_2026030" + std::to_string(1 + r) + "12_t012_uv3z.nc"), r);
    const MissionProblem p(loadMission(hycomMission(dir, "hycom", "hycom_glby_930_*.nc")));
    ASSERT_TRUE(p.runs());
    const ForecastRuns &r = *p.runs();
    const MissionSpec &m = p.getSpec();
    ASSERT_EQ(r.size(), 4u);
    for (std::size_t k = 0; k < r.size(); ++k)
    {
        SCOPED_TRACE(k);
        EXPECT_EQ(m.isoTime(r[k].reference), "2026-03-0" + std::to_string(k + 1) + "T12:00:00Z");
        EXPECT_EQ(r[k].begin - r[k].reference, 12.0 * 3600.0); // the first record 12 h after the analysis
        EXPECT_NE(r[k].referenceFrom.find("'tau'"), std::string::npos) << r[k].referenceFrom;
    }
    // available 12 h after its analysis: at 2026-03-03T06Z the newest is run 2 (analysis 2026-03-02T12Z)
    EXPECT_EQ(p.runIndex(), 1u);
    const MissionResult res = runMission(p);
    ASSERT_TRUE(res.plan.solved) << res.plan.reason;
}

TEST(ForecastRunsFmrc, HycomsOneFilePerTimeStepIsOneRunInSeveralFiles)
{
    // HYCOM's files as they come: one per time step (t012, t015, ...), each with the run's analysis in tau; the files
    // of one analysis are one run, planned as on that run in one file
    TempDir dir;
    for (int r = 0; r < 4; ++r)
    {
        const std::string day = "2026030" + std::to_string(1 + r) + "12";
        writeHycomRun(dir.file("one_" + day + ".nc"), r);
        for (std::size_t k = 0; k < 17; ++k)
        {
            const std::string lead = std::to_string(1000 + 12 + 3 * k).substr(1);
            writeHycomRun(dir.file("hycom_glby_930_" + day + "_t" + lead + "_uv3z.nc"), r, k, 1);
        }
    }
    const MissionProblem steps(loadMission(hycomMission(dir, "steps", "hycom_glby_930_*.nc")));
    const MissionProblem whole(loadMission(hycomMission(dir, "whole", "one_*.nc")));
    ASSERT_TRUE(steps.runs());
    const ForecastRuns &r = *steps.runs();
    ASSERT_EQ(r.size(), 4u);
    const MissionSpec &m = steps.getSpec();
    for (std::size_t k = 0; k < r.size(); ++k)
    {
        SCOPED_TRACE(k);
        EXPECT_EQ(r[k].files.size(), 17u);
        EXPECT_EQ(m.isoTime(r[k].reference), "2026-03-0" + std::to_string(k + 1) + "T12:00:00Z");
        EXPECT_NE(r[k].referenceFrom.find("one run in 17 files"), std::string::npos) << r[k].referenceFrom;
    }
    EXPECT_EQ(steps.runIndex(), 1u);
    expectSameFmrcRuns(r, *whole.runs());
    expectSameFmrcPlan(runMission(steps), runMission(whole));
    // the command line's and Python's runs alike: the run planned on is its 17 files
    const ForecastInput in = runsInput("2026-03-03T06:00:00Z");
    ForecastInput onSteps = in, onWhole = in;
    for (const ForecastRun &run : r.runs())
        onSteps.current.runs.insert(onSteps.current.runs.end(), run.files.begin(), run.files.end());
    for (int k = 0; k < 4; ++k)
        onWhole.current.runs.push_back(dir.file("one_2026030" + std::to_string(1 + k) + "12.nc"));
    MissionSpec a = forecastMission(onSteps), b = forecastMission(onWhole);
    EXPECT_EQ(a.current.files.size(), 17u);
    EXPECT_EQ(a.departure.time, b.departure.time);
    for (MissionSpec *spec : {&a, &b})
        spec->planner.globalCheck = false;
    expectSameFmrcPlan(runMission(MissionProblem(a)), runMission(MissionProblem(b)));
}

TEST(ForecastRunsFmrc, ABestTimeSeriesIsOneForecastCompleteWhenItsNewestRunIs)
{
    // a THREDDS FMRC's best time series: 1-D time, each record from its own run (reftime(time), standard_name
    // forecast_reference_time): one forecast as a file; as a run, available when its newest run is
    TempDir dir;
    const std::string best = dir.file("best.nc");
    {
        NcWriter w(best, NC_CLOBBER);
        const int dt = w.dim("time", kRunTimes), dy = w.dim("lat", kRunNy), dx = w.dim("lon", kRunNx);
        const int vt = w.var("time", NC_DOUBLE, {dt}), vr = w.var("reftime", NC_DOUBLE, {dt}),
                  vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx});
        const int vu = w.var("uo", NC_FLOAT, {dt, dy, dx}), vv = w.var("vo", NC_FLOAT, {dt, dy, dx});
        for (int v : {vt, vr})
            w.text(v, "units", "hours since 2026-03-01 00:00:00");
        w.text(vr, "standard_name", "forecast_reference_time");
        describeLatLonVelocity(w, vy, vx, vu, vv);
        w.enddef();
        std::vector<double> hours = linspace(0.0, 3.0, kRunTimes), refs, u, v;
        for (double h : hours)
            refs.push_back(std::min(48.0, 24.0 * std::floor(h / 24.0))); // the last day from the run of day 3
        runFlow(0, kRunTimes, u, v);
        w.put(vt, hours);
        w.put(vr, refs);
        w.put(vy, runLats());
        w.put(vx, runLons());
        w.put(vu, u);
        w.put(vv, v);
    }
    const auto mission = [&](const std::string &name, const std::string &key) {
        const std::string path = dir.file(name + ".yaml");
        std::ofstream(path) << "name: best\ncurrent:\n  type: netcdf\n  " << key << ": \"" << best
                            << "\"\n  horizon: hold_last\nstart: {lon: -52.85, lat: 47.15}\n"
                            << "goal: {lon: -52.1, lat: 47.85}\ndeparture: {time: \"2026-03-03T13:00:00Z\"}\n"
                            << "vehicle: {speed: 0.5}\n"
                            << "planner: {name: zastartve, grid_size: 4000, sectors: 3, global_check: false}\n";
        return path;
    };
    const MissionProblem asFile(loadMission(mission("file", "file")));
    EXPECT_TRUE(runMission(asFile).plan.solved);
    const MissionProblem asRun(loadMission(mission("run", "runs")));
    ASSERT_TRUE(asRun.runs());
    const ForecastRun &run = (*asRun.runs())[0];
    EXPECT_EQ(asRun.getSpec().isoTime(run.reference), "2026-03-03T00:00:00Z");
    EXPECT_EQ(run.referenceFrom, "variable 'reftime' (the newest of its values along time)");
}

// A forecast given as runs (current.runs): the plan is made on the newest run available at the departure, to 1e-9
// of the same mission given that run's file alone, and names it; each run's reference time comes from CF
// forecast_reference_time (a variable, else a global attribute, else the first time); no run available is an error
// naming the first run's availability. The runs are written here with NetCDF-C, as a model writes them: daily, each
// in hours since its own reference time, each a differently perturbed flow.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "RunFiles.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/ForecastRuns.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Overrides.h"
#include "ompl_glider/mission/Planning.h"

using namespace ompl_glider;
using namespace glider_test;

namespace
{
/// Five daily runs, named as Copernicus names them (their names do not sort as their reference times do: the runs
/// are ordered by reference time, not by name).
struct Runs
{
    TempDir dir;
    std::vector<std::string> files;
    Runs()
    {
        const RunReference refs[5] = {RunReference::Variable, RunReference::Attribute, RunReference::Variable,
                                      RunReference::None, RunReference::Variable};
        for (int r = 0; r < 5; ++r)
        {
            files.push_back(
                dir.file("glo_anfc_R2026030" + std::to_string(1 + r) + "_v" + std::to_string(5 - r) + ".nc"));
            writeRun(files.back(), r, refs[r]);
        }
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
};

void expectSameRunPlan(const MissionResult &a, const MissionResult &b)
{
    ASSERT_TRUE(a.plan.solved) << a.plan.reason;
    ASSERT_TRUE(b.plan.solved) << b.plan.reason;
    // the mission's clock is the run's planned on (its first time, as the file alone is read): the same arithmetic
    EXPECT_NEAR(a.plan.travelTime, b.plan.travelTime, 1e-9 * a.plan.travelTime);
    ASSERT_EQ(a.plan.path.size(), b.plan.path.size());
    for (std::size_t k = 0; k < a.plan.path.size(); ++k)
    {
        EXPECT_NEAR(a.plan.path[k].x, b.plan.path[k].x, 1e-6); // metres
        EXPECT_NEAR(a.plan.path[k].y, b.plan.path[k].y, 1e-6);
    }
    EXPECT_NEAR(a.plan.rawTravelTime, b.plan.rawTravelTime, 1e-9 * a.plan.rawTravelTime);
}
} // namespace

TEST(ForecastRuns, PlansOnTheNewestRunAvailableAtTheDepartureAsOnThatFileAlone)
{
    const Runs runs;
    // run k (reference 2026-03-(1+k)) is available from 12:00 that day: at each departure, the newest one
    const struct
    {
        const char *departure;
        std::size_t run;
    } cases[] = {{"2026-03-01T12:00:00Z", 0},
                 {"2026-03-02T11:59:00Z", 0},
                 {"2026-03-03T12:00:00Z", 2},
                 {"2026-03-04T20:00:00Z", 3},
                 {"2026-03-05T13:00:00Z", 4}};
    for (const auto &c : cases)
    {
        SCOPED_TRACE(c.departure);
        const MissionProblem onRuns(
            loadMission(runs.mission("runs", "  runs: \"" + runs.dir.file("glo_anfc_*.nc") + "\"\n", c.departure)));
        ASSERT_TRUE(onRuns.runs());
        EXPECT_EQ(onRuns.runs()->size(), 5u);
        EXPECT_EQ(onRuns.runIndex(), c.run);
        EXPECT_EQ((*onRuns.runs())[c.run].file, runs.files[c.run]);
        const MissionProblem alone(
            loadMission(runs.mission("alone", "  file: " + runs.files[c.run] + "\n", c.departure)));
        EXPECT_FALSE(alone.runs());
        const MissionResult a = runMission(onRuns), b = runMission(alone);
        expectSameRunPlan(a, b);
        // named in the notes: the run, its reference time, when it became available, the lead time at arrival
        ASSERT_FALSE(a.forecastNotes.empty());
        const std::string &note = a.forecastNotes.front();
        EXPECT_NE(note.find("run " + std::to_string(c.run + 1) + " of 5"), std::string::npos) << note;
        EXPECT_NE(note.find("available since 2026-03-0" + std::to_string(c.run + 1) + "T12:00:00Z"), std::string::npos)
            << note;
        EXPECT_NE(note.find("lead time at arrival"), std::string::npos) << note;
    }
}

TEST(ForecastRuns, ReferenceTimesFromVariableAttributeOrFirstTime)
{
    const Runs runs;
    const MissionProblem p(loadMission(runs.mission(
        "runs", "  runs: \"" + runs.dir.file("glo_anfc_*.nc") + "\"\n  run_delay: 6 h\n", "2026-03-01T06:00:00Z")));
    ASSERT_TRUE(p.runs());
    const ForecastRuns &r = *p.runs();
    const MissionSpec &m = p.getSpec();
    for (std::size_t k = 0; k < r.size(); ++k)
    {
        SCOPED_TRACE(k);
        EXPECT_EQ(r[k].file, runs.files[k]); // ordered by reference time, not by name
        EXPECT_EQ(m.isoTime(r[k].reference), "2026-03-0" + std::to_string(k + 1) + "T00:00:00Z");
        EXPECT_DOUBLE_EQ(r[k].available - r[k].reference, 6.0 * 3600.0);
        EXPECT_DOUBLE_EQ(r[k].end - r[k].begin, 72.0 * 3600.0);
    }
    EXPECT_NE(r[0].referenceFrom.find("variable"), std::string::npos);
    EXPECT_NE(r[1].referenceFrom.find("attribute"), std::string::npos);
    EXPECT_NE(r[3].referenceFrom.find("first time"), std::string::npos);
    // the live stream: the newest run's current at each time
    const RunStreamField live(p.runs());
    for (double hours : {7.0, 30.0, 55.0, 80.0, 120.0})
    {
        const double t = hours * 3600.0;
        const std::size_t k = r.runAt(t);
        EXPECT_EQ(live.runFor(t), k);
        const Velocity a = live.velocity(1000.0, -2000.0, 0.0, t), b = r.field(k)->velocity(1000.0, -2000.0, 0.0, t);
        EXPECT_EQ(a.u, b.u);
        EXPECT_EQ(a.v, b.v);
    }
    // a new run after t0 is announced for replanning when it is newer than the one then
    const std::vector<double> after = r.arrivalsAfter(7.0 * 3600.0);
    ASSERT_EQ(after.size(), 4u);
    EXPECT_DOUBLE_EQ(after.front(), r[1].available);
}

TEST(ForecastRuns, NoRunAvailableAtTheDepartureIsAnErrorNamingTheFirst)
{
    const Runs runs;
    try
    {
        const MissionProblem p(loadMission(
            runs.mission("early", "  runs: \"" + runs.dir.file("glo_anfc_*.nc") + "\"\n", "2026-03-01T06:00:00Z")));
        FAIL() << "expected an error";
    }
    catch (const Error &e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("current.runs"), std::string::npos) << what;
        EXPECT_NE(what.find("available from 2026-03-01T12:00:00Z"), std::string::npos) << what;
    }
}

namespace
{
/// Run k of a stream whose consecutive runs differ by 2 A cos(kx x) cos(w t) in u (the sign alternates): the
/// differences' scales are known, 1 / kx and 1 / w for a Gaussian fit of cos.
class AlternatingRun : public CurrentField
{
public:
    AlternatingRun(double sign, double a, double kx, double w) : sign_(sign), a_(a), kx_(kx), w_(w) {}
    double maxSpeed(const Region &) const override { return 0.1 + a_; }
    std::string name() const override { return "alternating run"; }

protected:
    Velocity evaluate(double x, double, double, double t) const override
    {
        return {0.1 + sign_ * a_ * std::cos(kx_ * x) * std::cos(w_ * t), 0.05};
    }
    Jacobian evaluateJacobian(double, double, double, double) const override { return {}; }

private:
    double sign_, a_, kx_, w_;
};
} // namespace

TEST(ForecastRuns, TheRunsSpreadGivesTheScalesOfTheirDifferences)
{
    const double a = 0.2, kx = 1.0 / 30000.0, w = 1.0 / (2.0 * 86400.0);
    std::vector<ForecastRun> list;
    for (int k = 0; k < 6; ++k)
    {
        ForecastRun r;
        r.file = "run" + std::to_string(k);
        r.reference = r.begin = 86400.0 * k;
        r.end = r.begin + 10.0 * 86400.0;
        r.available = r.reference + 43200.0;
        list.push_back(r);
    }
    const ForecastRuns runs(list, [&](const ForecastRun &r) -> std::shared_ptr<const CurrentField> {
        const double sign = (r.file.back() - '0') % 2 == 0 ? 1.0 : -1.0;
        return std::make_shared<AlternatingRun>(sign, a, kx, w);
    });
    Region box;
    box.xMin = 0.0;
    box.xMax = 2.0 * 2.0 * M_PI / kx; // two wavelengths: each snapshot's mean about 0
    box.yMin = 0.0;
    box.yMax = 300000.0;
    const RunSpread s = runSpread(runs, box, 0.0);
    EXPECT_EQ(s.pairs, 5u);
    EXPECT_EQ(s.samples, 5u * 17u * 24u * 24u);
    // the differences 2 a cos cos in u only: their mean square per component a^2 / 2, halved for two runs' errors
    EXPECT_NEAR(s.sigma, 0.5 * a, 0.1 * a);
    // a Gaussian fitted to cos(k r) over its resolved lags (0.05 < c < 0.98): a little below 1 / k
    EXPECT_GT(s.lengthScale, 0.75 / kx);
    EXPECT_LT(s.lengthScale, 1.05 / kx);
    EXPECT_GT(s.timeScale, 0.6 / w);
    EXPECT_LT(s.timeScale, 1.1 / w);
    // runs that do not differ resolve no scale and show no error
    const ForecastRuns same(list, [&](const ForecastRun &) -> std::shared_ptr<const CurrentField> {
        return std::make_shared<AlternatingRun>(1.0, a, kx, w);
    });
    const RunSpread z = runSpread(same, box, 0.0);
    EXPECT_EQ(z.sigma, 0.0);
    EXPECT_TRUE(std::isnan(z.lengthScale));
    EXPECT_TRUE(std::isnan(z.timeScale));
}

TEST(ForecastRuns, TheCommandLinesRunsPlanOnTheNewestRunToTheBit)
{
    // glider_plan --currents FILES --runs and Field.netcdf(runs=True): forecastMission() on the run's own clock
    const Runs runs;
    const ForecastInput in = runsInput("2026-03-03T13:00:00Z");
    ForecastInput onRuns = in, alone = in;
    onRuns.current.runs = runs.files;
    alone.current.file = runs.files[2];
    MissionSpec a = forecastMission(onRuns), b = forecastMission(alone);
    for (MissionSpec *m : {&a, &b})
        m->planner.globalCheck = false; // (its wall-clock limit is not reproducible)
    EXPECT_EQ(a.current.file, runs.files[2]);
    EXPECT_EQ(a.departure.time, b.departure.time);
    const MissionProblem pa(a), pb(b);
    ASSERT_TRUE(pa.runs());
    EXPECT_EQ(pa.runIndex(), 2u);
    const MissionResult ra = runMission(pa), rb = runMission(pb);
    ASSERT_TRUE(ra.plan.solved) << ra.plan.reason;
    EXPECT_EQ(ra.plan.travelTime, rb.plan.travelTime);
    ASSERT_EQ(ra.plan.path.size(), rb.plan.path.size());
    for (std::size_t k = 0; k < ra.plan.path.size(); ++k)
    {
        EXPECT_EQ(ra.plan.path[k].x, rb.plan.path[k].x);
        EXPECT_EQ(ra.plan.path[k].t, rb.plan.path[k].t);
    }
    // without a departure: when the first run becomes available
    ForecastInput first = onRuns;
    first.departure.clear();
    const MissionSpec f = forecastMission(first);
    EXPECT_EQ(f.isoTime(f.departure.time), "2026-03-01T12:00:00Z");
    EXPECT_EQ(f.current.file, runs.files[0]);
    // a departure before any run is available: an error naming the first run's availability
    first.departure = "2026-03-01T06:00:00Z";
    try
    {
        (void)forecastMission(first);
        FAIL() << "expected an error";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("available from 2026-03-01T12:00:00Z"), std::string::npos) << e.what();
    }
}

TEST(ForecastRuns, AcrossRunsIsSetByTheFlagAndRefusedWithoutRuns)
{
    // --across-runs and plan(across_runs=): the one override set, checked as the mission file's key is
    const Runs runs;
    const ForecastInput in = runsInput("2026-03-03T13:00:00Z");
    ForecastInput onRuns = in, alone = in;
    onRuns.current.runs = runs.files;
    alone.current.file = runs.files[2];
    MissionSpec a = forecastMission(onRuns), b = forecastMission(alone);
    EXPECT_EQ(a.execution.acrossRuns, AcrossRuns::Carry); // the default
    MissionOverrides o;
    o.acrossRuns = Given<std::string>{"reset", "--across-runs"};
    applyOverrides(o, a);
    EXPECT_EQ(a.execution.acrossRuns, AcrossRuns::Reset);
    EXPECT_TRUE(a.execution.enabled); // any execution setting flies the plan
    const auto refused = [](MissionSpec &m, const MissionOverrides &given, const std::string &expected) {
        const MissionSpec before = m;
        try
        {
            applyOverrides(given, m);
            ADD_FAILURE() << "expected an error";
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
        EXPECT_EQ(m.execution.enabled, before.execution.enabled); // all or nothing
        EXPECT_EQ(m.execution.acrossRuns, before.execution.acrossRuns);
    };
    refused(b, o, "--across-runs: given without forecast runs");
    o.acrossRuns = Given<std::string>{"keep", "--across-runs"};
    refused(a, o, "--across-runs: unknown choice 'keep' (expected carry or reset)");
}

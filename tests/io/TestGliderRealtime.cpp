// A glider's real-time sources through readGliderObservations(): an ERDDAP tabledap answer (.csvp, .csv, .ncCF)
// served by a loopback HTTP server of the test, and Slocum dba files, each of one deployment, give to the bit the DAC,
// the fixes and the last fix its IOOS profile files give; servers down, slow, answering HTML or ERDDAP's error, and
// bad dba files are refused naming the URL, or the file and line.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "LoopbackHttp.h"
#include "RealtimeDeployment.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/GliderObservations.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/Time.h"
#include "ompl_glider/mission/MissionSpec.h"

using namespace ompl_glider;
using namespace realtime_test;
namespace fs = std::filesystem;

namespace
{

std::string realtimeErrorOf(const std::string &source)
{
    try
    {
        readGliderObservations(source);
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

const char *kColumns = "time,latitude,longitude,profile_id,time_uv,lat_uv,lon_uv,u,v,u_qc,v_qc";

/// The same DAC, fixes and last fix, to the bit.
void expectSame(const GliderObservations &a, const GliderObservations &b)
{
    ASSERT_EQ(a.dac.size(), b.dac.size());
    for (std::size_t i = 0; i < a.dac.size(); ++i)
    {
        EXPECT_EQ(a.dac[i].time, b.dac[i].time) << i;
        EXPECT_EQ(a.dac[i].at.lon, b.dac[i].at.lon) << i;
        EXPECT_EQ(a.dac[i].at.lat, b.dac[i].at.lat) << i;
        EXPECT_EQ(a.dac[i].u, b.dac[i].u) << i;
        EXPECT_EQ(a.dac[i].v, b.dac[i].v) << i;
    }
    ASSERT_EQ(a.fixes.size(), b.fixes.size());
    for (std::size_t i = 0; i < a.fixes.size(); ++i)
    {
        EXPECT_EQ(a.fixes[i].time, b.fixes[i].time) << i;
        EXPECT_EQ(a.fixes[i].at.lon, b.fixes[i].at.lon) << i;
        EXPECT_EQ(a.fixes[i].at.lat, b.fixes[i].at.lat) << i;
    }
    ASSERT_TRUE(a.lastFix && b.lastFix);
    EXPECT_EQ(a.lastFix->time, b.lastFix->time);
    EXPECT_EQ(a.lastFix->at.lon, b.lastFix->at.lon);
    EXPECT_EQ(a.lastFix->at.lat, b.lastFix->at.lat);
    EXPECT_EQ(a.platform, b.platform);
}

/// The same DAC (to the bit), last fix and glider.
void expectSameDac(const GliderObservations &a, const GliderObservations &b)
{
    ASSERT_EQ(a.dac.size(), b.dac.size());
    for (std::size_t i = 0; i < a.dac.size(); ++i)
    {
        EXPECT_EQ(a.dac[i].time, b.dac[i].time) << i;
        EXPECT_EQ(a.dac[i].at.lon, b.dac[i].at.lon) << i;
        EXPECT_EQ(a.dac[i].at.lat, b.dac[i].at.lat) << i;
        EXPECT_EQ(a.dac[i].u, b.dac[i].u) << i;
        EXPECT_EQ(a.dac[i].v, b.dac[i].v) << i;
    }
    ASSERT_TRUE(a.lastFix && b.lastFix);
    EXPECT_EQ(a.lastFix->time, b.lastFix->time);
    EXPECT_EQ(a.lastFix->at.lon, b.lastFix->at.lon);
    EXPECT_EQ(a.lastFix->at.lat, b.lastFix->at.lat);
    EXPECT_EQ(a.platform, b.platform);
}

/// An ERDDAP of the deployment: /erddap/tabledap/<dataset>.<csvp|csv|ncCF>?<columns>&time>=<date>, the answer built
/// from the surfacings the constraint selects; "-flat" datasets answer .ncCF in the flat layout.
class Erddap
{
public:
    explicit Erddap(const fs::path &scratch)
        : server_([this, scratch](const loopback_test::Request &r) { return answer(r, scratch); })
    {
    }
    std::string url(const std::string &dataset, const std::string &type, bool constrained = true) const
    {
        return server_.url("/erddap/tabledap/" + dataset + type + "?" + kColumns +
                           (constrained ? std::string("&time%3E=") + kSince : std::string()));
    }
    const loopback_test::Server &server() const { return server_; }

private:
    static loopback_test::Response answer(const loopback_test::Request &r, const fs::path &scratch)
    {
        double from = -INFINITY;
        const std::size_t at = r.query.find("&time>=");
        if (at != std::string::npos)
            from = parseIsoTime(r.query.substr(at + 7, r.query.find('&', at + 1) - at - 7));
        const std::vector<Surfacing> d = since(deployment(), from);
        const auto ends = [&](const std::string &e) {
            return r.path.size() > e.size() && r.path.compare(r.path.size() - e.size(), e.size(), e) == 0;
        };
        if (ends(".csvp"))
            return {200, csvAnswer(d, true), "text/csv"};
        if (ends(".csv"))
            return {200, csvAnswer(d, false), "text/csv"};
        if (ends(".ncCF"))
            return {200, ncCfAnswer(d, r.path.find("-flat") != std::string::npos, scratch), "application/x-netcdf"};
        return {404, "Error {\n    code=404;\n    message=\"Not Found: no such file type\";\n}\n"};
    }
    loopback_test::Server server_;
};

/// Each case with a request time limit of 1 s (the loopback server answers in milliseconds, the slow one in 5 s; the
/// limit is the process's from its first NetCDF access on, so every case sets the same) and no retries (a failing
/// server answers at once); the retries restored after it.
class GliderRealtime : public ::testing::Test
{
protected:
    void SetUp() override { setRemoteAccess(access(0)); }
    void TearDown() override { setRemoteAccess(access(RemoteAccess{}.retries)); }
    static RemoteAccess access(int retries)
    {
        RemoteAccess a;
        a.requestTimeout = 1.0;
        a.retries = retries;
        return a;
    }
    /// The deployment's surfacings of the constrained URLs as IOOS profile files, read.
    GliderObservations ioos()
    {
        const fs::path d = freshDir("realtime_ioos");
        writeIoos(d, since(deployment(), parseIsoTime(kSince)));
        return readGliderObservations(d.string());
    }
};
} // namespace

TEST_F(GliderRealtime, TheIoosFilesOfTheDeploymentAreAsBuilt)
{
    // the reference the other sources are compared with: 4 DAC (the fill and the flagged surfacing rejected), the 6
    // profiles' fixes and the 4 DAC's positions, the last fix the sixth profile's
    const GliderObservations o = ioos();
    ASSERT_EQ(o.dac.size(), 4u);
    EXPECT_EQ(o.fixes.size(), 10u);
    EXPECT_EQ(o.rejected, (std::map<std::string, std::size_t>{{"QC flag 4 (u_qc)", 1}, {"fill value", 1}}));
    ASSERT_TRUE(o.lastFix);
    EXPECT_EQ(o.lastFix->time, t0() + 37800.0);
    EXPECT_EQ(o.lastFix->at.lon, -52.375);
    EXPECT_EQ(o.lastFix->at.lat, 48.046875);
    EXPECT_EQ(o.dac[0].at.lon, -52.625);
    EXPECT_EQ(o.dac[3].time, t0() + 36000.0);
}

TEST_F(GliderRealtime, ErddapCsvpAndCsvAreTheIoosFiles)
{
    const GliderObservations reference = ioos();
    const Erddap erddap(freshDir("realtime_csv") / "answer.nc");
    for (const char *type : {".csvp", ".csv"})
    {
        SCOPED_TRACE(type);
        const std::string url = erddap.url("ru29-20260315T0000", type);
        const GliderObservations o = readGliderObservations(url);
        expectSame(o, reference);
        // a profile's repeated rows are no rejection: the same reasons counted as the files'
        EXPECT_EQ(o.rejected, reference.rejected);
        EXPECT_EQ(o.source, url);
        EXPECT_EQ(o.files, 1u);
        EXPECT_EQ(o.dac[0].file, url);
    }
    // the server was asked the constraint (without it, the evening before comes too)
    const auto asked = erddap.server().received();
    ASSERT_FALSE(asked.empty());
    EXPECT_NE(asked.back().query.find(std::string("time>=") + kSince), std::string::npos) << asked.back().query;
    const GliderObservations all = readGliderObservations(erddap.url("ru29-20260315T0000", ".csvp", false));
    EXPECT_EQ(all.dac.size(), reference.dac.size() + 1);
}

TEST_F(GliderRealtime, ErddapNcCfRaggedAndFlatAreTheIoosFiles)
{
    const GliderObservations reference = ioos();
    const Erddap erddap(freshDir("realtime_nccf") / "answer.nc");
    // the ragged answer (profile_id numbers, -999 as a value) and the flat one (profile_id text, three rows a profile,
    // -999 the declared fill value); "-delayed" and "-flat" left out of the glider's name
    for (const char *dataset : {"ru29-20260315T0000", "ru29-flat-20260315T0000-delayed"})
    {
        SCOPED_TRACE(dataset);
        const GliderObservations o = readGliderObservations(erddap.url(dataset, ".ncCF"));
        if (std::string(dataset).find("flat") == std::string::npos)
            expectSame(o, reference);
        else
        {
            GliderObservations renamed = o;
            EXPECT_EQ(o.platform, "ru29-flat");
            renamed.platform = reference.platform;
            expectSame(renamed, reference);
        }
        EXPECT_EQ(o.rejected, reference.rejected);
    }
}

TEST_F(GliderRealtime, DbaFilesPlaceEachDacOverItsDiveAsTheIoosFiles)
{
    // the dba files hold the fixes before and after each dive, then the DAC: each DAC placed at the segment's mean
    // time and position is the IOOS file's (time_uv, lon_uv, lat_uv), to the bit
    const GliderObservations reference = ioos();
    const fs::path d = freshDir("realtime_dba");
    const std::vector<Surfacing> surfacings = since(deployment(), parseIsoTime(kSince));
    writeDba(d, surfacings);
    for (const std::string &source : {d.string(), (d / "*.dba").string()})
    {
        const GliderObservations o = readGliderObservations(source);
        expectSameDac(o, reference);
        EXPECT_EQ(o.files, 2u);
        // the placeholder fix, the status-2 fix, a DAC with one component, a DAC without a fix before it
        EXPECT_EQ(o.rejected, (std::map<std::string, std::size_t>{{"GPS status 2 (m_gps_status)", 1},
                                                                  {"fill value", 1},
                                                                  {"no GPS fix (69696969)", 1},
                                                                  {"no GPS fix in the 30 min before it", 1}}));
        EXPECT_TRUE(o.notes.empty()); // every DAC has its dive's start
        // each DAC's segment: the fix before the dive and the first fix after it (not the second, 15 s later); the
        // depths over it: the surface's 0.125 to the dive's deepest
        const std::size_t good[] = {0, 1, 2, 5};
        ASSERT_EQ(o.dac.size(), 4u);
        for (std::size_t i = 0; i < 4; ++i)
        {
            const Surfacing &s = surfacings[good[i]];
            EXPECT_EQ(o.dac[i].segmentStart, s.timeUv - 1800.0) << i;
            EXPECT_EQ(o.dac[i].segmentEnd, s.time) << i;
            EXPECT_EQ(o.dac[i].depthMin, 0.125) << i;
            EXPECT_EQ(o.dac[i].depthMax, diveDepth(good[i])) << i;
        }
        // the valid fixes: before and after each dive (the fill's and the flagged one's after rejected), the good
        // surfacings' second fixes but the last's
        EXPECT_EQ(o.fixes.size(), 6u + 4u + 3u);
        // the newest surfacing: the last fix (valid)
        EXPECT_EQ(o.newestSurfacing, o.lastFix->time);
    }
    // one file alone: the third surfacing's DAC (first in the second file) has its fix in the other file
    const GliderObservations second = readGliderObservations((d / "ru29-2026-074-0-1.dba").string());
    ASSERT_EQ(second.dac.size(), 1u); // the sixth's: the third's lost its fix, the fourth's and fifth's rejected
    EXPECT_EQ(second.rejected.at("no GPS fix in the 30 min before it"), 2u);
}

TEST_F(GliderRealtime, DbaDacWithoutAFixBeforeItsDiveIsPlacedAtTheSurfacingAndCounted)
{
    const fs::path d = freshDir("realtime_dba_first");
    const double t = t0();
    // the first surfacing of the files (no fix before its dive), a second fix without a dive between, its DAC; the
    // newest fix rejected (69696969): the newest surfacing is later than the last fix
    std::ofstream(d / "ru29-2026-074-0-0.dba")
        << dbaHeader("ru29-2026-074-0-0") << dbaRow(t, 47.875, -52.625, 0.0, NAN, NAN, 0.25)
        << dbaRow(t + 60, 47.890625, -52.625, NAN, NAN, NAN, 0.25) << dbaRow(t + 90, NAN, NAN, NAN, 0.2, -0.1, 0.25)
        << dbaRow(t + 3600, NAN, NAN, NAN, NAN, NAN, 80.0)
        << dbaRow(t + 7200, 69696969.0, 69696969.0, NAN, NAN, NAN, 0.25);
    const GliderObservations o = readGliderObservations(d.string());
    ASSERT_EQ(o.dac.size(), 1u);
    EXPECT_EQ(o.dac[0].time, t + 60); // the latest fix at or before it, as without the dive's start
    EXPECT_EQ(o.dac[0].at.lat, 47.890625);
    EXPECT_TRUE(std::isnan(o.dac[0].segmentStart));
    EXPECT_EQ(o.dac[0].segmentEnd, t); // the surfacing's first fix
    EXPECT_TRUE(std::isnan(o.dac[0].depthMin));
    EXPECT_EQ(o.notes, (std::map<std::string, std::size_t>{
                           {"DAC placed at the surfacing's fix (no fix before the dive: its start unknown)", 1}}));
    EXPECT_NE(observationsText(o).find("; 1 DAC placed at the surfacing's fix (no fix before the dive"),
              std::string::npos)
        << observationsText(o);
    EXPECT_EQ(o.lastFix->time, t + 60);
    EXPECT_EQ(o.newestSurfacing, t + 7200);
}

TEST_F(GliderRealtime, DbaSurfacingsWithoutDepthsAreSplitByTheirGaps)
{
    // without m_depth between them, fixes more than 15 min apart are two surfacings: the DAC averages the dive
    // between the last fix of the first and the first fix of the second
    const fs::path d = freshDir("realtime_dba_gaps");
    const double t = t0();
    std::ofstream(d / "ru29-2026-074-0-0.dba")
        << dbaHeader("ru29-2026-074-0-0") << dbaRow(t, 47.875, -52.625, 0.0, NAN, NAN, NAN)
        << dbaRow(t + 600, 47.875, -52.5, 0.0, NAN, NAN, NAN) // 10 min later: the same surfacing
        << dbaRow(t + 600 + 7200, 48.0, -52.5, 0.0, NAN, NAN, NAN)
        << dbaRow(t + 600 + 7300, 48.0, -52.375, 0.0, NAN, NAN, NAN)
        << dbaRow(t + 600 + 7330, NAN, NAN, NAN, 0.1, 0.2, NAN);
    const GliderObservations o = readGliderObservations(d.string());
    ASSERT_EQ(o.dac.size(), 1u);
    EXPECT_EQ(o.dac[0].segmentStart, t + 600);
    EXPECT_EQ(o.dac[0].segmentEnd, t + 7800);
    EXPECT_EQ(o.dac[0].time, t + 4200);
    EXPECT_EQ(o.dac[0].at.lon, -52.5);
    EXPECT_EQ(o.dac[0].at.lat, 47.9375);
    EXPECT_TRUE(std::isnan(o.dac[0].depthMax)); // no depth reported
}

TEST_F(GliderRealtime, ErddapServerDownIsRefusedNamingTheUrl)
{
    const std::string url = "http://127.0.0.1:" + std::to_string(loopback_test::closedPort()) +
                            "/erddap/tabledap/ru29-20260315T0000.csvp?" + kColumns;
    const std::string e = realtimeErrorOf(url);
    EXPECT_NE(e.find("cannot fetch '" + url + "'"), std::string::npos) << e;
    EXPECT_NE(e.find("0 retries"), std::string::npos) << e;
}

TEST_F(GliderRealtime, ErddapTooSlowIsRefusedAtTheTimeLimit)
{
    const loopback_test::Server slow([](const loopback_test::Request &) {
        loopback_test::Response r{200, csvAnswer(deployment(), true)};
        r.delaySeconds = 5.0;
        return r;
    });
    const std::string url = slow.url("/erddap/tabledap/ru29-20260315T0000.csvp");
    const auto begin = std::chrono::steady_clock::now();
    const std::string e = realtimeErrorOf(url);
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    EXPECT_NE(e.find("cannot fetch '" + url + "'"), std::string::npos) << e;
    EXPECT_NE(e.find("request time limit 1 s"), std::string::npos) << e;
    EXPECT_LT(took, 3.0);
}

TEST_F(GliderRealtime, ErddapErrorPagesAndHtmlAreRefusedWithTheServersWords)
{
    const loopback_test::Server server([](const loopback_test::Request &r) -> loopback_test::Response {
        if (r.path.find("nomatch") != std::string::npos)
            return {404, "Error {\n    code=404;\n    message=\"Not Found: Your query produced no matching results. "
                         "(nRows = 0)\";\n}\n"};
        if (r.path.find("badvar") != std::string::npos)
            return {
                400,
                "Error {\n    code=400;\n    message=\"Bad Request: Query error: Unrecognized variable=\\\"uu\\\"\";"
                "\n}\n"};
        if (r.path.find("broken") != std::string::npos)
            return {500, "<html><head><title>500 Internal Server Error</title></head><body>oops</body></html>",
                    "text/html"};
        return {200, "<!DOCTYPE html>\n<html><head><title>Sign in to the portal</title></head></html>", "text/html"};
    });
    const auto check = [&](const std::string &dataset, const std::string &words) {
        const std::string url = server.url("/erddap/tabledap/" + dataset + ".csvp?time,u&time>=2026-03-15T00:00:00Z");
        const std::string e = realtimeErrorOf(url);
        EXPECT_NE(e.find("ERDDAP '" + url + "'"), std::string::npos) << e;
        EXPECT_NE(e.find(words), std::string::npos) << e;
    };
    check("nomatch", "HTTP 404: Not Found: Your query produced no matching results. (nRows = 0)");
    check("badvar", "HTTP 400: Bad Request: Query error: Unrecognized variable=\"uu\"");
    check("broken", "HTTP 500: an HTML page ('500 Internal Server Error')");
    check("portal", "the answer is an HTML page ('Sign in to the portal'), not ERDDAP data");
    // .ncCF: an HTML page where NetCDF was expected
    const std::string url = server.url("/erddap/tabledap/portal.ncCF");
    EXPECT_NE(realtimeErrorOf(url).find("ERDDAP '" + url + "': the answer is an HTML page"), std::string::npos)
        << realtimeErrorOf(url);
    // a URL of another file type
    const std::string json = server.url("/erddap/tabledap/ru29.json?time");
    EXPECT_NE(realtimeErrorOf(json).find("ERDDAP '" + json +
                                         "': not an ERDDAP tabledap answer this reader knows (the file "
                                         "type '.json'; expected .csvp, .csv or .ncCF"),
              std::string::npos)
        << realtimeErrorOf(json);
}

TEST_F(GliderRealtime, ErddapAnswersWithoutTheColumnsAreRefusedNamingThem)
{
    const fs::path scratch = freshDir("realtime_columns") / "answer.nc";
    const loopback_test::Server server([&](const loopback_test::Request &r) -> loopback_test::Response {
        if (r.path.find("cut.ncCF") != std::string::npos) // the answer cut short (a dropped connection)
        {
            const std::string whole = ncCfAnswer(deployment(), false, scratch);
            return {200, whole.substr(0, whole.size() - 100)};
        }
        if (r.path.find(".ncCF") != std::string::npos)
            return {200, ncCfAnswer(deployment(), false, scratch, {"v", "lat_uv"})};
        if (r.path.find("good") != std::string::npos) // the same answer in m s-1
            return {200, csvAnswer(deployment(), true)};
        if (r.path.find("cms") != std::string::npos || r.path.find("degc") != std::string::npos) // cm/s, degC
        {
            std::string body = csvAnswer(deployment(), true);
            const std::string unit = r.path.find("cms") != std::string::npos ? "cm s-1" : "degC";
            for (const char *k : {"u (m s-1)", "v (m s-1)"})
                body.replace(body.find(k), std::strlen(k), std::string(k).replace(3, 5, unit));
            return {200, body};
        }
        if (r.path.find("notanumber") != std::string::npos)
            return {200, "time (UTC),latitude (degrees_north),longitude (degrees_east),time_uv (UTC),lat_uv,lon_uv,"
                         "u (m s-1),v (m s-1)\n2026-03-15T06:00:00Z,48,-52,2026-03-15T05:30:00Z,48,-52,east,0.1\n"};
        return {200, "time (UTC),latitude (degrees_north),longitude (degrees_east),profile_id\n"
                     "2026-03-15T06:00:00Z,48.0,-52.0,1\n"};
    });
    const std::string csvp = server.url("/erddap/tabledap/ru29.csvp?time,latitude,longitude,profile_id");
    EXPECT_NE(realtimeErrorOf(csvp).find("ERDDAP '" + csvp +
                                         "': the answer has no column 'time_uv', 'lat_uv', 'lon_uv', "
                                         "'u', 'v'"),
              std::string::npos)
        << realtimeErrorOf(csvp);
    const std::string nccf = server.url("/erddap/tabledap/ru29.ncCF?time");
    EXPECT_NE(realtimeErrorOf(nccf).find("ERDDAP '" + nccf + "': the answer has no variable 'lat_uv', 'v'"),
              std::string::npos)
        << realtimeErrorOf(nccf);
    const std::string cut = server.url("/erddap/tabledap/cut.ncCF");
    EXPECT_NE(realtimeErrorOf(cut).find("ERDDAP '" + cut + "': the .ncCF answer is cut short or corrupt"),
              std::string::npos)
        << realtimeErrorOf(cut);
    // the same numbers in cm s-1: a hundredth of the DAC in m s-1; in degC: refused
    const std::string cms = server.url("/erddap/tabledap/cms.csvp");
    const GliderObservations inCm = readGliderObservations(cms);
    const GliderObservations inM = readGliderObservations(server.url("/erddap/tabledap/good.csvp"));
    ASSERT_EQ(inCm.dac.size(), inM.dac.size());
    for (std::size_t i = 0; i < inM.dac.size(); ++i)
        EXPECT_NEAR(inCm.dac[i].u, inM.dac[i].u / 100.0, 1e-15);
    const std::string degc = server.url("/erddap/tabledap/degc.csvp");
    EXPECT_NE(realtimeErrorOf(degc).find("ERDDAP '" + degc + "': 'u' is in 'degC': units 'degC' are not a velocity"),
              std::string::npos)
        << realtimeErrorOf(degc);
    const std::string nan = server.url("/erddap/tabledap/notanumber.csvp");
    EXPECT_NE(realtimeErrorOf(nan).find("ERDDAP '" + nan + "': answer line 2: 'u': expected a number, got 'east'"),
              std::string::npos)
        << realtimeErrorOf(nan);
}

TEST_F(GliderRealtime, BadDbaFilesAreRefusedNamingFileAndLine)
{
    const fs::path d = freshDir("realtime_dba_bad");
    const std::string f = (d / "ru29-2026-074-0-0.dba").string();
    const std::string header = dbaHeader("ru29-2026-074-0-0");
    const std::string row = dbaRow(t0(), 47.875, -52.625, 0.0, NAN, NAN, 0.1);
    const auto check = [&](const std::string &text, const std::string &words) {
        std::ofstream(f) << text;
        const std::string e = realtimeErrorOf(f);
        EXPECT_NE(e.find(f + ":" + words), std::string::npos) << e;
    };
    // the header's 14 lines, then the file ends: no label lines
    check(header.substr(0, header.find("m_present_time")), "15: the file ends before its label lines (3: sensor "
                                                           "names, units, bytes per value)");
    check(header + row + "1773554460 NaN NaN 0 0.1\n", "19: 5 values, the label line (15) names 7 sensors");
    check(header + row + "1773554460 NaN NaN 0 abc 0.1 2\n", "19: sensor 'm_water_vx': 'abc' is not a number");
    check(
        dbaHeader("ru29-2026-074-0-0", "m_present_time m_gps_lat m_gps_lon m_depth", "timestamp lat lon m", "8 8 8 4") +
            "1773554400 4752.5 -5237.5 3\n",
        "15: no sensor 'm_water_vx'");
    check(dbaHeader("ru29-2026-074-0-0", "m_present_time m_lat m_lon m_water_vx m_water_vy",
                    "timestamp lat lon m/s m/s", "8 8 8 4 4"),
          "15: no sensor 'm_gps_lat'");
    check(dbaHeader("ru29-2026-074-0-0", kSensors, "timestamp lat lon enum degC degC m"),
          "16: 'm_water_vx' is in 'degC': units 'degC' are not a velocity");
    check("the_label: x\n" + header.substr(header.find('\n') + 1), "1: not a Slocum dba file");
    check(header.substr(0, header.find("num_ascii_tags")) + "all_sensors 0\n",
          "3: the header has no num_ascii_tags line");
    // a folder of dba files without any DAC: nothing usable, the sensors named
    std::ofstream(f) << header << row;
    EXPECT_NE(realtimeErrorOf(d.string()).find("no usable depth-averaged current (sensors m_water_vx, m_water_vy)"),
              std::string::npos)
        << realtimeErrorOf(d.string());
}

TEST_F(GliderRealtime, DbaRejectsPlaceholdersHalfFixesAndOtherGliders)
{
    const fs::path d = freshDir("realtime_dba_rejects");
    const double t = t0();
    std::ofstream(d / "ru29-2026-074-0-0.dba")
        << dbaHeader("ru29-2026-074-0-0") << dbaRow(t, 47.875, -52.625, 0.0, NAN, NAN, 0.1)
        << dbaRow(t + 30, NAN, NAN, NAN, 0.2, -0.1, 0.1)              // the DAC of the fix above
        << dbaRow(t + 60, 69696969.0, 69696969.0, NAN, NAN, NAN, 0.1) // no fix
        << dbaRow(t + 90, 47.890625, NAN, NAN, NAN, NAN, 0.1)         // half a fix
        << dbaRow(t + 120, NAN, NAN, 1.0, NAN, NAN, 0.1)              // the status turns bad...
        << dbaRow(t + 150, 47.90625, -52.59375, NAN, NAN, NAN, 0.1)   // ...and stays bad for this fix
        << dbaRow(t + 7200, NAN, NAN, NAN, 0.3, NAN, 0.1)             // a DAC with one component
        << dbaRow(t + 9000, NAN, NAN, NAN, 5.0, 0.0, 0.1);            // no fix in the 30 min before it
    std::ofstream(d / "sg512-2026-074-0-0.dba")
        << dbaHeader("sg512-2026-074-0-0") << dbaRow(t, 40.0, -60.0, 0.0, 0.1, 0.1, 0.1);
    std::ofstream(d / "ru29-2026-074-0-1.dba")
        << dbaHeader("ru29-2026-074-0-1") << dbaRow(t + 9600, 47.9375, -52.5625, 0.0, NAN, NAN, 0.1)
        << dbaRow(t + 9630, NAN, NAN, NAN, 3.5, 0.0, 0.1);
    const GliderObservations o = readGliderObservations(d.string());
    EXPECT_EQ(o.platform, "ru29");
    EXPECT_EQ(o.files, 3u);
    ASSERT_EQ(o.dac.size(), 1u);
    EXPECT_EQ(o.dac[0].time, t);
    EXPECT_EQ(o.dac[0].at.lat, 47.875);
    EXPECT_EQ(o.dac[0].at.lon, -52.625);
    EXPECT_EQ(o.dac[0].u, 0.2);
    EXPECT_EQ(o.fixes.size(), 2u); // the good fixes only
    ASSERT_TRUE(o.lastFix);
    EXPECT_EQ(o.lastFix->time, t + 9600);
    EXPECT_EQ(o.rejected, (std::map<std::string, std::size_t>{{"GPS status 1 (m_gps_status)", 1},
                                                              {"another glider ('sg512')", 1},
                                                              {"faster than 3 m/s (u, v read in 'm/s')", 1},
                                                              {"fill value", 1},
                                                              {"no GPS fix (69696969)", 1},
                                                              {"no GPS fix (m_gps_lat or m_gps_lon NaN)", 1},
                                                              {"no GPS fix in the 30 min before it", 1}}));
}

TEST_F(GliderRealtime, DbaFilesAreFoundByNameOrFirstLineAndNotMixedWithNetCdf)
{
    const fs::path d = freshDir("realtime_dba_find");
    writeDba(d, since(deployment(), parseIsoTime(kSince)));
    // a dba file under another name: known by its first line
    fs::rename(d / "ru29-2026-074-0-1.dba", d / "ru29-2026-074-0-1.asc");
    const GliderObservations one = readGliderObservations((d / "ru29-2026-074-0-1.asc").string());
    EXPECT_EQ(one.dac.size(), 1u);
    EXPECT_EQ(one.platform, "ru29");
    // a pattern matching a dba file and a NetCDF file, a folder holding both: refused
    writeIoos(d, {deployment()[1]});
    EXPECT_NE(realtimeErrorOf((d / "ru29*").string()).find("matches both Slocum dba files and others"),
              std::string::npos)
        << realtimeErrorOf((d / "ru29*").string());
    EXPECT_NE(realtimeErrorOf(d.string()).find("the folder holds both NetCDF (.nc) and Slocum dba (.dba) files"),
              std::string::npos)
        << realtimeErrorOf(d.string());
}

TEST_F(GliderRealtime, MissionFileKeepsAnErddapUrlAsGiven)
{
    // a mission file's observations: a URL is not a path beside the mission file
    const std::string url = "https://gliders.ioos.us/erddap/tabledap/ru29-20260315T0000.csvp?time,u";
    const MissionSpec m =
        parseMission(std::string("name: obs\ncurrent: {type: netcdf, file: '") + OMPL_GLIDER_SOURCE_DIR +
                         "/examples/labrador_forecast.nc'}\n"
                         "start: {lon: -52.3, lat: 48.0}\ngoal: {lon: -52.2, lat: 48.1}\n"
                         "observations: '" +
                         url + "'\n",
                     "/missions/obs.yaml", "/missions");
    ASSERT_TRUE(m.observations);
    EXPECT_EQ(m.observations->path, url);
    const MissionSpec file =
        parseMission(std::string("name: obs\ncurrent: {type: netcdf, file: '") + OMPL_GLIDER_SOURCE_DIR +
                         "/examples/labrador_forecast.nc'}\n"
                         "start: {lon: -52.3, lat: 48.0}\ngoal: {lon: -52.2, lat: 48.1}\n"
                         "observations: deployment\n",
                     "/missions/obs.yaml", "/missions");
    EXPECT_EQ(file.observations->path, "/missions/deployment");
}

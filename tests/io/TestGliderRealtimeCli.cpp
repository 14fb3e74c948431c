// glider_plan --observations with a glider's real-time sources: a folder of Slocum dba files and an ERDDAP URL (a
// loopback server of the test) plan from the deployment's last fix, and the very route its IOOS profile files give
// (the same DAC correct the forecast); an ERDDAP error is bad input (exit 2) naming the URL and ERDDAP's message.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <filesystem>
#include <string>

#include "LoopbackHttp.h"
#include "../opendap/DapServer.h"
#include "RealtimeDeployment.h"
#include "ompl_glider/io/Time.h"

using namespace realtime_test;
namespace fs = std::filesystem;

namespace
{

struct PlanRun
{
    int status{-1};
    std::string out; // stdout and stderr
};

/// glider_plan on the example forecast from the last fix of @p observations to a goal 4 km away (no refinement nor
/// global check: a short plan).
PlanRun run(const std::string &arguments)
{
    const std::string command = std::string("'") + GLIDER_PLAN_EXE + "' " + arguments + " 2>&1";
    PlanRun r;
    FILE *p = ::popen(command.c_str(), "r");
    if (!p)
        return r;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;)
        r.out.append(buf, n);
    const int status = ::pclose(p);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

PlanRun plan(const std::string &observations)
{
    return run(std::string("--currents '") + OMPL_GLIDER_SOURCE_DIR +
               "/examples/labrador_forecast.nc' --observations '" + observations +
               "' --goal=-52.33,48.07 --speed 0.3 --no-refine --no-global-check");
}

/// The route's table (the lines from its header "   #" on): positions and arrival times.
std::string table(const std::string &out)
{
    const std::size_t at = out.find("\n   #");
    return at == std::string::npos ? "" : out.substr(at);
}

/// A run from the deployment's last fix (t0 + 10.5 h at -52.375, 48.046875) with its 4 usable DAC.
void expectFromTheLastFix(const PlanRun &r)
{
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("(" + iso(t0() + 37800.0) + ")"), std::string::npos) << r.out; // the departure
    EXPECT_NE(r.out.find("(ru29): 4 DAC used"), std::string::npos) << r.out;
    const std::string t = table(r.out);
    const std::size_t row0 = t.find("\n   0 ");
    ASSERT_NE(row0, std::string::npos) << r.out;
    EXPECT_NE(t.substr(row0, t.find('\n', row0 + 1) - row0).find("-52.375000  48.046875"), std::string::npos) << t;
}

/// The deployment's ERDDAP answer (.csvp) to a request with a `time>=` constraint.
loopback_test::Response erddapAnswer(const loopback_test::Request &q)
{
    const std::size_t at = q.query.find("&time>=");
    const double from = at == std::string::npos ? -1e300 : ompl_glider::parseIsoTime(q.query.substr(at + 7));
    return loopback_test::Response{200, csvAnswer(since(deployment(), from), true), "text/csv"};
}

/// The deployment's tabledap URL at @p server, constrained to kSince on.
std::string deploymentUrl(const loopback_test::Server &server)
{
    return server.url("/erddap/tabledap/ru29-20260315T0000.csvp?time,latitude,longitude,profile_id,time_uv,lat_uv,"
                      "lon_uv,u,v,u_qc,v_qc&time%3E=" +
                      std::string(kSince));
}

std::string ioosRoute()
{
    const fs::path d = freshDir("realtime_cli_ioos");
    writeIoos(d, since(deployment(), ompl_glider::parseIsoTime(kSince)));
    const PlanRun r = plan(d.string());
    EXPECT_EQ(r.status, 0) << r.out;
    return table(r.out);
}
} // namespace

TEST(GliderRealtimeCli, DbaFolderPlansFromTheLastFixAsTheIoosFiles)
{
    const fs::path d = freshDir("realtime_cli_dba");
    writeDba(d, since(deployment(), ompl_glider::parseIsoTime(kSince)));
    const PlanRun r = plan(d.string());
    expectFromTheLastFix(r);
    EXPECT_EQ(table(r.out), ioosRoute());
}

TEST(GliderRealtimeCli, ErddapUrlPlansFromTheLastFixAsTheIoosFiles)
{
    const loopback_test::Server server(erddapAnswer);
    const std::string url = deploymentUrl(server);
    const PlanRun r = plan(url);
    expectFromTheLastFix(r);
    EXPECT_EQ(table(r.out), ioosRoute());
    EXPECT_GE(server.requests(), 1);
}

TEST(GliderRealtimeCli, ErddapErrorIsBadInputNamingTheUrl)
{
    const loopback_test::Server server([](const loopback_test::Request &) {
        return loopback_test::Response{404, "Error {\n    code=404;\n    message=\"Not Found: Your query produced no "
                                            "matching results. (nRows = 0)\";\n}\n"};
    });
    const std::string url = server.url("/erddap/tabledap/ru29-20260315T0000.csvp?time,u&time%3E=2027-01-01T00:00:00Z");
    const PlanRun r = plan(url);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find("ERDDAP '" + url +
                         "': the server answered HTTP 404: Not Found: Your query produced no "
                         "matching results. (nRows = 0)"),
              std::string::npos)
        << r.out;
}

/// Each input of a plan is read once: the ERDDAP URL of the glider's observations (the start's first guess, the
/// resume and the correction take it from one read) and the forecast at a URL (no request made twice), from the
/// command line's flags and from a mission file alike.
TEST(GliderRealtimeCli, EachInputIsReadOncePerPlan)
{
    const loopback_test::Server erddap(erddapAnswer);
    const std::string observations = deploymentUrl(erddap);
    const fs::path dir = freshDir("read_once");
    fs::create_directories(dir / "served");
    fs::copy_file(fs::path(OMPL_GLIDER_SOURCE_DIR) / "examples/labrador_forecast.nc", dir / "served/labrador.nc");
    const fs::path log = dir / "dap.log";
    dap_test::DapServer dap((dir / "served").string(), log.string());
    const std::string forecast = dap.url("labrador.nc");
    std::ofstream(dir / "mission.yaml") << "current:\n  type: gridded\n  file: " << forecast
                                        << "\ngoal: {lon: -52.33, lat: 48.07}\nvehicle: {speed: 0.3}\n"
                                           "observations: {file: \""
                                        << observations << "\"}\nplanner: {global_check: false}\n";
    // each run: the requests the DAP server logged (path and query), and the ERDDAP's
    std::size_t logged = 0;
    for (const std::string &how : {"--currents '" + forecast + "' --observations '" + observations +
                                       "' --goal=-52.33,48.07 --speed 0.3 --no-refine --no-global-check",
                                   "--mission '" + (dir / "mission.yaml").string() + "' --no-refine"})
    {
        const std::size_t asked = erddap.requests();
        const PlanRun r = run(how);
        ASSERT_EQ(r.status, 0) << how << "\n" << r.out;
        EXPECT_NE(r.out.find("(ru29): 4 DAC used"), std::string::npos) << r.out; // resumed and corrected
        EXPECT_EQ(erddap.requests() - asked, 1) << how;                          // the glider's observations read once
        std::ifstream in(log);
        std::vector<std::string> lines;
        for (std::string line; std::getline(in, line);)
            lines.push_back(line);
        // each request (path and query) of this run, how often; the opens of the dataset (its attributes, .das: the
        // DAP2 client of NetCDF-C asks its description, .dds, twice at each open)
        std::map<std::string, int> times;
        std::size_t opens = 0;
        for (std::size_t k = logged; k < lines.size(); ++k)
        {
            const std::size_t p = lines[k].find("\"path\": ");
            const std::size_t q = lines[k].find(", \"variables\"");
            const std::string request = lines[k].substr(p, q == std::string::npos ? std::string::npos : q - p);
            if (request.find(".dds\"") == std::string::npos)
                ++times[request];
            opens += request.find(".das\"") != std::string::npos ? 1 : 0;
        }
        EXPECT_GT(lines.size(), logged) << how << ": the forecast was not read at its URL";
        logged = lines.size();
        for (const auto &[request, n] : times)
            EXPECT_EQ(n, 1) << how << ": " << request << " asked " << n << " times";
        EXPECT_EQ(opens, 1u) << how << ": the forecast opened " << opens << " times";
    }
}

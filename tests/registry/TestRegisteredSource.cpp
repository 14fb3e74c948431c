// A gridded current source that exists only in this test, registered at run time (registerCurrentFieldKind()),
// following the recipe of docs/ARCHITECTURE.md: it reads a forecast from a CSV file of grid nodes (x, y in metres,
// u, v in m/s; a node without u and v is land). A mission file names it by its kind, `current.type: csv_grid`,
// and it plans through runMission() and the output layer, as the command line's forecast missions
// (forecastMission()) do, without any edit to mission/. Travel times are checked against the closed form of a
// uniform current.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <ompl/util/Console.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/current/CurrentFieldRegistry.h"
#include "ompl_glider/current/ForecastSource.h"
#include "ompl_glider/current/GriddedCurrentField.h"
#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionProblem.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"

using namespace ompl_glider;
namespace fs = std::filesystem;

namespace
{
/// The nodes of a CSV grid file, checked: a regular grid of x and y, each row "x,y,u,v" (u and v empty: land).
struct CsvGrid
{
    std::vector<double> x, y;
    std::map<std::pair<double, double>, std::pair<double, double>> water; // (x, y) -> (u, v)
};

CsvGrid readCsvGrid(const std::string &path)
{
    std::ifstream in(path);
    if (!in)
        throw Error("'" + path + "': cannot open the grid file");
    CsvGrid g;
    std::string line;
    std::getline(in, line);
    if (line != "x,y,u,v")
        throw Error("'" + path + "':1: expected the header 'x,y,u,v', found '" + line + "'");
    std::vector<std::pair<double, double>> nodes;
    for (int number = 2; std::getline(in, line); ++number)
    {
        std::vector<std::string> cells;
        std::stringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');)
            cells.push_back(cell);
        if (line.back() == ',')
            cells.emplace_back();
        const auto value = [&](std::size_t k) {
            std::size_t used = 0;
            double v = 0.0;
            try
            {
                v = std::stod(cells[k], &used);
            }
            catch (const std::exception &)
            {
                used = 0;
            }
            if (used != cells[k].size() || cells[k].empty() || !std::isfinite(v))
                throw Error("'" + path + "':" + std::to_string(number) + ": column " + std::to_string(k + 1) + ": '" +
                            cells[k] + "' is not a number");
            return v;
        };
        if (cells.size() != 4)
            throw Error("'" + path + "':" + std::to_string(number) + ": expected 4 columns x,y,u,v, found " +
                        std::to_string(cells.size()));
        const std::pair<double, double> node{value(0), value(1)};
        nodes.push_back(node);
        if (!cells[2].empty() || !cells[3].empty())
            g.water[node] = {value(2), value(3)};
    }
    for (const auto &[a, b] : nodes)
    {
        g.x.push_back(a);
        g.y.push_back(b);
    }
    for (std::vector<double> *axis : {&g.x, &g.y})
    {
        std::sort(axis->begin(), axis->end());
        axis->erase(std::unique(axis->begin(), axis->end()), axis->end());
    }
    if (g.x.size() < 2 || g.y.size() < 2 || nodes.size() != g.x.size() * g.y.size())
        throw Error("'" + path + "': the nodes do not form a regular grid (" + std::to_string(nodes.size()) +
                    " rows for " + std::to_string(g.x.size()) + " x " + std::to_string(g.y.size()) + " axes)");
    return g;
}

/// The recipe's source: steady, Cartesian (metres), land where a node has no velocity.
class CsvGridSource final : public GriddedSource
{
public:
    bool geographic(const ForecastRequest &) const override { return false; }
    ForecastExtent extent(const ForecastRequest &r) const override
    {
        const CsvGrid g = readCsvGrid(r.files.at(0));
        ForecastExtent e;
        e.lonMin = g.x.front();
        e.lonMax = g.x.back();
        e.latMin = g.y.front();
        e.latMax = g.y.back();
        e.xName = "x";
        e.yName = "y";
        return e;
    }
    ForecastTimeAxis timeAxis(const ForecastRequest &) const override
    {
        ForecastTimeAxis a;
        a.steady = true; // no time axis: the same currents at every time
        return a;
    }
    LoadedForecast load(const ForecastRequest &r) const override
    {
        if (r.files.size() != 1)
            throw Error("csv_grid: one grid file, not " + std::to_string(r.files.size()));
        const CsvGrid g = readCsvGrid(r.files.front());
        GriddedData d;
        d.nx = g.x.size();
        d.ny = g.y.size();
        d.x = g.x;
        d.y = g.y;
        d.u.assign(d.nx * d.ny, 0.0f);
        d.v.assign(d.nx * d.ny, 0.0f);
        d.water.assign(d.nx * d.ny, 0);
        for (std::size_t j = 0; j < d.ny; ++j)
            for (std::size_t i = 0; i < d.nx; ++i)
                if (const auto it = g.water.find({g.x[i], g.y[j]}); it != g.water.end())
                {
                    d.u[j * d.nx + i] = static_cast<float>(it->second.first);
                    d.v[j * d.nx + i] = static_cast<float>(it->second.second);
                    d.water[j * d.nx + i] = 1;
                }
        GriddedFieldOptions o;
        o.xy = r.xy;
        o.name = r.name.empty() ? "csv_grid:" + r.files.front() : r.name;
        LoadedForecast f;
        f.field = std::make_shared<GriddedCurrentField>(std::move(d), o);
        f.steady = true;
        f.files = r.files;
        f.lonMin = g.x.front();
        f.lonMax = g.x.back();
        f.latMin = g.y.front();
        f.latMax = g.y.back();
        f.uVariable = "u";
        f.notes.push_back(std::to_string(g.water.size()) + " water nodes read from the CSV grid");
        f.landCauses.push_back("rows of '" + r.files.front() + "' without u and v");
        return f;
    }
};

void registerSourceOnce()
{
    if (findCurrentFieldKind("csv_grid"))
        return;
    CurrentFieldKind k;
    k.name = "csv_grid";
    k.description = "a steady forecast from a CSV file of grid nodes x,y,u,v (registered by a test)";
    k.source = std::make_shared<CsvGridSource>();
    registerCurrentFieldKind(k);
}

constexpr double kU = 0.1, kV = 0.05, kSpeed = 0.3;

/// A 21 x 21 grid over [0, 20 km]^2 of the uniform current (kU, kV); nodes in @p land (i, j) hold no velocity.
std::string writeGrid(const std::string &name, const std::vector<std::pair<int, int>> &land = {})
{
    const fs::path dir = fs::temp_directory_path() / "ompl_glider_registered_source";
    fs::create_directories(dir);
    const fs::path file = dir / name;
    std::ofstream out(file);
    out << "x,y,u,v\n";
    for (int j = 0; j <= 20; ++j)
        for (int i = 0; i <= 20; ++i)
        {
            out << i * 1000 << "," << j * 1000 << ",";
            if (std::find(land.begin(), land.end(), std::make_pair(i, j)) == land.end())
                out << kU << "," << kV;
            else
                out << ",";
            out << "\n";
        }
    return file.string();
}

/// The closed form: on a uniform current c the fastest route is the straight leg, flown at the ground speed
/// c.d + sqrt(V^2 - |c|^2 + (c.d)^2) along its direction d (c as the grid stores it: in single precision).
double straightTime(Point2 a, Point2 b)
{
    const double u = static_cast<float>(kU), v = static_cast<float>(kV);
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const double along = (u * (b.x - a.x) + v * (b.y - a.y)) / len;
    return len / (along + std::sqrt(kSpeed * kSpeed - u * u - v * v + along * along));
}

std::string sourceMission(const std::string &grid, const std::string &extra = "")
{
    return "name: csv\ncurrent: {type: csv_grid, file: " + grid +
           "}\nstart: {x: 2000, y: 3000}\ngoal: {x: 17000, y: 12000}\nvehicle: {speed: 0.3}\n" + extra;
}

std::string readText(const fs::path &p)
{
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
} // namespace

TEST(RegisteredSource, PlansThroughTheWholePipelineLikeTheBuiltInOne)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    registerSourceOnce();
    ASSERT_NE(findCurrentFieldKind("csv_grid"), nullptr);
    EXPECT_TRUE(findCurrentFieldKind("csv_grid")->gridded());
    EXPECT_NE(griddedKindList().find("csv_grid"), std::string::npos);

    const fs::path out = fs::temp_directory_path() / "ompl_glider_registered_source" / "out";
    fs::remove_all(out);
    const std::string grid = writeGrid("uniform.csv");
    const MissionSpec spec = parseMission(
        sourceMission(grid, "outputs: {directory: " + out.string() + ", files: [summary, csv]}\n"), "c.yaml");
    EXPECT_TRUE(spec.current.isForecast());
    const MissionProblem problem(spec);
    ASSERT_NE(problem.getField()->grid(), nullptr);
    EXPECT_EQ(problem.forecastFiles(), std::vector<std::string>{grid});
    ASSERT_EQ(problem.forecastNotes().size(), 1u);
    EXPECT_EQ(problem.forecastNotes().front(), "441 water nodes read from the CSV grid");

    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const double exact = straightTime({2000, 3000}, {17000, 12000});
    EXPECT_NEAR(r.plan.travelTime, exact, 1e-6 * exact) << r.plan.travelTime - exact;
    EXPECT_GE(r.plan.travelTime, exact * (1.0 - 1e-9)); // nothing flies faster than the optimum
    ASSERT_FALSE(writeOutputs(r, problem).empty());
    const std::string json = readText(out / "summary.json");
    EXPECT_NE(json.find("csv_grid"), std::string::npos);
    EXPECT_NE(json.find("441 water nodes"), std::string::npos);
    EXPECT_TRUE(fs::exists(out / "waypoints.csv"));
    fs::remove_all(out);
}

TEST(RegisteredSource, TheCommandLinesForecastMissionTakesItByName)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    registerSourceOnce();
    ForecastInput q;
    q.current.type = "csv_grid";
    q.current.file = writeGrid("uniform_cli.csv");
    q.start = {2000, 3000};
    q.goal = {17000, 12000};
    q.speed = kSpeed;
    const MissionSpec m = forecastMission(q);
    EXPECT_EQ(m.current.type, "csv_grid");
    const MissionResult r = runMission(MissionProblem(m));
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    const double exact = straightTime({2000, 3000}, {17000, 12000});
    EXPECT_NEAR(r.plan.travelTime, exact, 1e-4 * exact);

    // outside the source's extent, on its land: refused, naming the flag and what the source says makes land
    q.goal = {25000, 12000};
    try
    {
        forecastMission(q);
        FAIL() << "a goal outside the grid must be refused";
    }
    catch (const Error &e)
    {
        EXPECT_NE(std::string(e.what()).find("goal 25000,12000 (x,y) lies outside the grid"), std::string::npos)
            << e.what();
    }
    q.current.file = writeGrid("land_cli.csv", {{16, 11}, {17, 11}, {16, 12}, {17, 12}});
    q.goal = {17000, 12000};
    try
    {
        forecastMission(q);
        FAIL() << "a goal on land must be refused";
    }
    catch (const Error &e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("goal 17000,12000 (x,y) is on land"), std::string::npos) << what;
        EXPECT_NE(what.find("rows of '" + q.current.file + "' without u and v"), std::string::npos) << what;
        EXPECT_NE(what.find("the nearest water is"), std::string::npos) << what;
    }
}

TEST(RegisteredSource, LandAcrossTheWayIsGoneAroundAndTheSourcesErrorsNameTheMissionLine)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    registerSourceOnce();
    // a wall of land across the straight leg, open to the north
    std::vector<std::pair<int, int>> wall;
    for (int j = 0; j <= 13; ++j)
        wall.emplace_back(10, j);
    const MissionProblem problem(parseMission(sourceMission(writeGrid("wall.csv", wall)), "c.yaml"));
    const MissionResult r = runMission(problem);
    ASSERT_TRUE(r.plan.solved) << r.plan.reason;
    EXPECT_GT(r.plan.travelTime, straightTime({2000, 3000}, {17000, 12000}) * 1.01);
    // the route stays in the source's water, checked at 200 points of each leg
    const auto &path = r.plan.path;
    for (std::size_t k = 1; k < path.size(); ++k)
        for (int s = 0; s <= 200; ++s)
        {
            const double a = s / 200.0;
            const double x = path[k - 1].x + a * (path[k].x - path[k - 1].x);
            const double y = path[k - 1].y + a * (path[k].y - path[k - 1].y);
            ASSERT_TRUE(problem.getField()->inWater(x, y, 0.0)) << "leg " << k << " at " << x << "," << y;
        }
    // the same route never crosses the wall's column above its top
    bool north = false;
    for (const auto &p : path)
        north = north || (std::abs(p.x - 10000.0) < 1500.0 && p.y > 13000.0);
    EXPECT_TRUE(north);

    // a malformed row: the source's message, on the mission's line of the current section
    const std::string bad = writeGrid("bad.csv");
    {
        std::ofstream out(bad, std::ios::app);
        out << "21000,0,0.1,fast\n";
    }
    try
    {
        MissionProblem p(parseMission(sourceMission(bad), "c.yaml"));
        FAIL() << "a malformed row must be refused";
    }
    catch (const Error &e)
    {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("c.yaml:2: ", 0), 0u) << what;
        EXPECT_NE(what.find("'" + bad + "':443: column 4: 'fast' is not a number"), std::string::npos) << what;
    }
}

TEST(RegisteredSource, RegistrationRefusesWhatIsNotAKind)
{
    registerSourceOnce();
    CurrentFieldKind twin = *findCurrentFieldKind("csv_grid");
    EXPECT_THROW(registerCurrentFieldKind(twin), Error); // the name is taken
    twin.name = "csv_grid_2";
    twin.make = [](const std::map<std::string, double> &) { return std::shared_ptr<const CurrentField>(); };
    EXPECT_THROW(registerCurrentFieldKind(twin), Error); // both a make function and a source
    twin.make = nullptr;
    twin.source = nullptr;
    EXPECT_THROW(registerCurrentFieldKind(twin), Error); // neither
    EXPECT_EQ(findCurrentFieldKind("csv_grid_2"), nullptr);
    // an analytic call of a gridded kind is refused
    EXPECT_THROW(makeAnalyticField("csv_grid"), Error);
}

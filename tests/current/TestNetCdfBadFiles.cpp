// Forecast files the reader must refuse with a one-line Error naming the file and the variable instead of
// crashing or loading a wrong field: empty dimensions (an UNLIMITED lat or time without records), axes that are
// not strictly monotonic (lat, lon, Cartesian x/y, time, depth, 2-D curvilinear lat/lon), axes holding fill
// values or non-finite numbers, and a trip region larger than the memory limit. Longitudes written across a seam
// (0..360 or -180..180) stay allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>

#include "TestNetCdfUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using glider_test::NcWriter;
using glider_test::TempDir;

namespace
{
/// A small forecast u(time, [depth,] lat, lon) = 0.1 m/s eastward, v = 0, with knobs for what goes wrong.
struct Forecast
{
    std::vector<double> lat{47.0, 47.2, 47.4, 47.6}, lon{-53.0, -52.8, -52.6, -52.4}, time{0, 24, 48};
    std::vector<double> depth;     ///< empty: no depth axis
    bool cartesian{false};         ///< axes x/y in m (and u/v in m/s) instead of lat/lon
    bool latUnlimited{false};      ///< lat an UNLIMITED dimension (its length is that of lat)
    bool timeUnlimited{false};     ///< time an UNLIMITED dimension
    bool writeLat{true};           ///< false: lat never written (reads as the netCDF-4 default fill)
    std::optional<double> latFill; ///< a _FillValue attribute of lat
};

/// nc_put_vara of all values of var (record variables included: nc_put_var writes no records).
void putAll(int id, int var, const std::vector<std::size_t> &count, const std::vector<double> &values)
{
    if (values.empty())
        return;
    const std::vector<std::size_t> start(count.size(), 0);
    NCW_CHECK(nc_put_vara_double(id, var, start.data(), count.data(), values.data()));
}

/// Defines the 1-D axis var of dimension dim with units (and a standard_name when not empty).
int axis(NcWriter &w, const std::string &name, int dim, const std::string &units)
{
    const int v = w.var(name, NC_DOUBLE, {dim});
    w.text(v, "units", units);
    return v;
}

void writeForecast(const std::string &path, const Forecast &s)
{
    NcWriter w(path);
    const std::string yn = s.cartesian ? "y" : "lat", xn = s.cartesian ? "x" : "lon";
    const int dt = w.dim("time", s.timeUnlimited ? NC_UNLIMITED : s.time.size());
    const int dz = s.depth.empty() ? -1 : w.dim("depth", s.depth.size());
    const int dy = w.dim(yn, s.latUnlimited ? NC_UNLIMITED : s.lat.size()), dx = w.dim(xn, s.lon.size());
    const int vt = axis(w, "time", dt, "hours since 2026-03-15 00:00:00");
    const int vz = s.depth.empty() ? -1 : axis(w, "depth", dz, "m");
    const int vy = axis(w, yn, dy, s.cartesian ? "m" : "degrees_north");
    const int vx = axis(w, xn, dx, s.cartesian ? "m" : "degrees_east");
    if (s.latFill)
        w.fill(vy, NC_DOUBLE, *s.latFill);
    std::vector<int> dims{dt, dy, dx};
    std::vector<std::size_t> count{s.time.size(), s.lat.size(), s.lon.size()};
    if (dz >= 0)
    {
        dims.insert(dims.begin() + 1, dz);
        count.insert(count.begin() + 1, s.depth.size());
    }
    const int u = w.var("u", NC_FLOAT, dims), v = w.var("v", NC_FLOAT, dims);
    w.text(u, "units", "m/s");
    w.text(v, "units", "m/s");
    w.text(u, "standard_name", "eastward_sea_water_velocity");
    w.text(v, "standard_name", "northward_sea_water_velocity");
    w.enddef();
    putAll(w.id(), vt, {s.time.size()}, s.time);
    if (vz >= 0)
        putAll(w.id(), vz, {s.depth.size()}, s.depth);
    if (s.writeLat)
        putAll(w.id(), vy, {s.lat.size()}, s.lat);
    putAll(w.id(), vx, {s.lon.size()}, s.lon);
    std::size_t n = 1;
    for (std::size_t c : count)
        n *= c;
    putAll(w.id(), u, count, std::vector<double>(n, 0.1));
    putAll(w.id(), v, count, std::vector<double>(n, 0.0));
}

/// The message of the Error f throws ("" when it throws none).
std::string errorOf(const std::function<void()> &f)
{
    try
    {
        f();
    }
    catch (const Error &e)
    {
        return e.what();
    }
    return "";
}

/// The message of loading a file written from s (options o).
std::string loadError(const TempDir &tmp, const std::string &name, const Forecast &s,
                      const GriddedCurrentOptions &o = {})
{
    const std::string path = tmp.file(name);
    writeForecast(path, s);
    return errorOf([&] { loadGriddedCurrents(path, o); });
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)
} // namespace

TEST(NetCdfBadFiles, ZeroLengthLatitudeNamesTheAxis)
{
    TempDir tmp;
    Forecast s;
    s.lat.clear();
    s.latUnlimited = true;
    const std::string m = loadError(tmp, "nolat.nc", s);
    EXPECT_HAS(m, "nolat.nc");
    EXPECT_HAS(m, "'lat' has no values");
    EXPECT_HAS(m, "length 0");
}

TEST(NetCdfBadFiles, TimeWithoutRecordsNamesTheTimeVariable)
{
    TempDir tmp;
    Forecast s;
    s.time.clear();
    s.timeUnlimited = true;
    const std::string path = tmp.file("norecords.nc");
    writeForecast(path, s);
    std::string m = errorOf([&] { loadGriddedCurrents(path); });
    EXPECT_HAS(m, "norecords.nc");
    EXPECT_HAS(m, "time variable 'time' has no values");
    // the time axis alone, as the mission loader reads it
    m = errorOf([&] { readForecastTimeAxis(path); });
    EXPECT_HAS(m, "time variable 'time' has no values");
}

TEST(NetCdfBadFiles, AxesThatAreNotStrictlyMonotonicNameTheAxis)
{
    TempDir tmp;
    Forecast s;
    s.lat = {47.0, 47.2, 47.2, 47.6};
    std::string m = loadError(tmp, "lat.nc", s);
    EXPECT_HAS(m, "lat.nc");
    EXPECT_HAS(m, "coordinate 'lat' is not strictly monotonic: 47.2 at index 1, then 47.2 at index 2");

    s = Forecast();
    s.lon = {-53.0, -52.8, -52.9, -52.4};
    m = loadError(tmp, "lon.nc", s);
    EXPECT_HAS(m, "coordinate 'lon' is not strictly monotonic: -52.8 at index 1, then -52.9 at index 2");

    s = Forecast();
    s.cartesian = true;
    s.lat = {0, 1000, 2000, 3000};
    s.lon = {0, 1000, 1000, 3000};
    GriddedCurrentOptions cart;
    cart.coordinates = CoordinateMode::Cartesian;
    m = loadError(tmp, "x.nc", s, cart);
    EXPECT_HAS(m, "coordinate 'x' is not strictly monotonic");
    s.lon = {0, 1000, 2000, 3000};
    s.lat = {3000, 2000, 2500, 0};
    m = loadError(tmp, "y.nc", s, cart);
    EXPECT_HAS(m, "coordinate 'y' is not strictly monotonic: 2000 at index 1, then 2500 at index 2");

    s = Forecast();
    s.time = {0, 24, 24};
    m = loadError(tmp, "time.nc", s);
    EXPECT_HAS(m, "time variable 'time' is not strictly monotonic: 24 at index 1, then 24 at index 2");

    s = Forecast();
    s.depth = {0, 10, 10};
    m = loadError(tmp, "depth.nc", s);
    EXPECT_HAS(m, "depth 'depth' has the depth 10 m twice");
}

TEST(NetCdfBadFiles, DescendingAxesAndLongitudesAcrossASeamStayAllowed)
{
    TempDir tmp;
    Forecast s;
    s.lat = {47.6, 47.4, 47.2, 47.0};
    s.lon = {179.6, 179.8, 180.0, -179.8, -179.6}; // -180..180 written across the antimeridian
    const std::string path = tmp.file("seam.nc");
    writeForecast(path, s);
    const GriddedCurrents nc = loadGriddedCurrents(path);
    ASSERT_TRUE(nc.field);
    EXPECT_EQ(nc.loadedShape[3], 5u);
    // eastward 0.1 m/s everywhere, also across the seam
    const Point2 p = nc.toLocal({-179.9, 47.3});
    const Velocity c = nc.field->velocity(p.x, p.y, 0.0, 0.0);
    EXPECT_NEAR(std::hypot(c.u, c.v), 0.1, 1e-4);
    // a region across the seam given as lonMin > lonMax
    GriddedCurrentOptions o;
    o.lonMin = 179.7;
    o.lonMax = -179.7;
    o.latMin = 47.1;
    o.latMax = 47.5;
    o.marginNodes = 0;
    EXPECT_NO_THROW(loadGriddedCurrents(path, o));
    // 0..360 written across 0 (350, 0, 10)
    s.lon = {359.6, 359.8, 0.0, 0.2, 0.4};
    writeForecast(path, s);
    EXPECT_NO_THROW(loadGriddedCurrents(path));
    // but not twice around
    s.lon = {0.0, 180.0, 359.0, 170.0, 350.0};
    writeForecast(path, s);
    EXPECT_HAS(errorOf([&] { loadGriddedCurrents(path); }), "coordinate 'lon' is not strictly monotonic");
}

TEST(NetCdfBadFiles, AxesWithFillValuesOrNonFiniteNumbersNameTheAxis)
{
    TempDir tmp;
    Forecast s;
    s.writeLat = false; // never written: reads as the default fill 9.97e36
    std::string m = loadError(tmp, "unwritten.nc", s);
    EXPECT_HAS(m, "unwritten.nc");
    EXPECT_HAS(m, "coordinate 'lat' holds fill values or non-finite numbers (9.969209968e+36 at index 0)");
    EXPECT_EQ(m.find("outside"), std::string::npos) << m;

    s = Forecast();
    s.lat = {47.0, -999.0, 47.4, 47.6};
    s.latFill = -999.0;
    m = loadError(tmp, "fill.nc", s);
    EXPECT_HAS(m, "coordinate 'lat' holds fill values or non-finite numbers (-999 at index 1)");

    s = Forecast();
    s.lon = {-53.0, NAN, -52.6, -52.4};
    m = loadError(tmp, "nan.nc", s);
    EXPECT_HAS(m, "coordinate 'lon' holds fill values or non-finite numbers");

    s = Forecast();
    s.time = {0, INFINITY, 48};
    m = loadError(tmp, "time.nc", s);
    EXPECT_HAS(m, "time variable 'time' holds fill values or non-finite numbers (inf at index 1)");

    s = Forecast();
    s.depth = {0, NAN};
    m = loadError(tmp, "depth.nc", s);
    EXPECT_HAS(m, "depth 'depth' holds fill values or non-finite numbers");
}

namespace
{
/// A curvilinear grid nav_lat/nav_lon(y, x) of 4 x 5 nodes with u, v on (time, y, x); edit changes the
/// coordinates (index j * 5 + i) before they are written.
std::string writeCurvilinear(const TempDir &tmp, const std::string &name,
                             const std::function<void(std::vector<double> &, std::vector<double> &)> &edit)
{
    const std::string path = tmp.file(name);
    const std::size_t nj = 4, ni = 5;
    std::vector<double> la, lo;
    for (std::size_t j = 0; j < nj; ++j)
        for (std::size_t i = 0; i < ni; ++i)
        {
            la.push_back(47.0 + 0.2 * double(j) + 0.05 * double(i));
            lo.push_back(-53.0 + 0.2 * double(i) - 0.05 * double(j));
        }
    edit(la, lo);
    NcWriter w(path);
    const int dt = w.dim("time", 1), dy = w.dim("y", nj), dx = w.dim("x", ni);
    const int vt = axis(w, "time", dt, "hours since 2026-03-15");
    const int vla = w.var("nav_lat", NC_DOUBLE, {dy, dx}), vlo = w.var("nav_lon", NC_DOUBLE, {dy, dx});
    w.text(vla, "units", "degrees_north");
    w.text(vlo, "units", "degrees_east");
    const int u = w.var("u", NC_FLOAT, {dt, dy, dx}), v = w.var("v", NC_FLOAT, {dt, dy, dx});
    for (int var : {u, v})
    {
        w.text(var, "units", "m/s");
        w.text(var, "coordinates", "nav_lon nav_lat");
    }
    w.enddef();
    w.put(vt, {0.0});
    w.put(vla, la);
    w.put(vlo, lo);
    w.put(u, std::vector<double>(nj * ni, 0.1));
    w.put(v, std::vector<double>(nj * ni, 0.0));
    return path;
}
} // namespace

TEST(NetCdfBadFiles, CurvilinearCoordinatesMustBeFiniteAndUnfolded)
{
    TempDir tmp;
    // the grid as written loads
    EXPECT_NO_THROW(loadGriddedCurrents(writeCurvilinear(tmp, "ok.nc", [](auto &, auto &) {})));

    // a fill value in nav_lat
    std::string m = errorOf([&] {
        loadGriddedCurrents(writeCurvilinear(tmp, "fill.nc", [](auto &la, auto &) { la[7] = NC_FILL_DOUBLE; }));
    });
    EXPECT_HAS(m, "coordinate 'nav_lat' holds fill values or non-finite numbers (9.969209968e+36 at (j, i) = (1, 2))");

    // row 2 repeats row 1: neighbouring nodes coincide
    m = errorOf([&] {
        loadGriddedCurrents(writeCurvilinear(tmp, "repeat.nc", [](auto &la, auto &lo) {
            for (std::size_t i = 0; i < 5; ++i)
            {
                la[10 + i] = la[5 + i];
                lo[10 + i] = lo[5 + i];
            }
        }));
    });
    EXPECT_HAS(m, "curvilinear coordinates 'nav_lon'/'nav_lat' are not strictly monotonic");
    EXPECT_HAS(m, "coincide");

    // column 3 moved west of column 2: the grid folds
    m = errorOf([&] {
        loadGriddedCurrents(writeCurvilinear(tmp, "fold.nc", [](auto &, auto &lo) {
            for (std::size_t j = 0; j < 4; ++j)
                lo[j * 5 + 3] = lo[j * 5 + 2] - 0.1;
        }));
    });
    EXPECT_HAS(m, "curvilinear coordinates 'nav_lon'/'nav_lat' are not strictly monotonic");
    EXPECT_HAS(m, "folded");
}

namespace
{
/// Sets an environment variable for its lifetime (each test runs in its own process under ctest).
class ScopedEnv
{
public:
    ScopedEnv(const char *name, const char *value) : name_(name)
    {
        if (const char *old = std::getenv(name))
            old_ = old;
        ::setenv(name, value, 1);
    }
    ~ScopedEnv()
    {
        if (old_)
            ::setenv(name_, old_->c_str(), 1);
        else
            ::unsetenv(name_);
    }

private:
    const char *name_;
    std::optional<std::string> old_;
};
} // namespace

TEST(NetCdfBadFiles, TripRegionLargerThanTheMemoryLimitIsRefusedBeforeReading)
{
    TempDir tmp;
    Forecast s;
    s.depth = {0, 10};
    const std::string path = tmp.file("small.nc");
    writeForecast(path, s);
    EXPECT_NO_THROW(loadGriddedCurrents(path));
    ScopedEnv limit("OMPL_GLIDER_MEMORY_LIMIT", "2K");
    const std::string m = errorOf([&] { loadGriddedCurrents(path); });
    EXPECT_HAS(m, "NetCDF file '" + path + "': the trip's region (4 x 4 nodes, 3 times, 2 depths) needs about");
    EXPECT_HAS(m, "restrict the region or the time window, or use a coarser file");
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

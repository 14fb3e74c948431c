#pragma once
// Helpers of the gridded/NetCDF tests: a per-test temporary directory, a tiny NetCDF-C writer, the options of a
// region and the expected current in a loaded field's plane.
#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "ompl_glider/current/GriddedCurrents.h"

namespace glider_test
{
/// A fresh directory under the test temp dir, named after the running test, removed at scope exit.
class TempDir
{
public:
    TempDir()
    {
        const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name =
            std::string("ompl_glider_") + (info ? info->test_suite_name() : "x") + "_" + (info ? info->name() : "y");
        // unique per process and instance: ctest runs the tests of one executable in parallel processes
        static int counter = 0;
        name += "_" + std::to_string(static_cast<long>(::getpid())) + "_" + std::to_string(counter++);
        for (char &c : name)
            if (c == '/')
                c = '_';
        path_ = std::filesystem::path(::testing::TempDir()) / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir()
    {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    std::string file(const std::string &name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

#define NCW_CHECK(expr)                                                                                                \
    do                                                                                                                 \
    {                                                                                                                  \
        const int st_ = (expr);                                                                                        \
        if (st_ != NC_NOERR)                                                                                           \
            throw std::runtime_error(std::string(#expr) + ": " + nc_strerror(st_));                                    \
    } while (0)

/// Minimal NetCDF writer: define dims/vars/atts, then enddef(), then put().
class NcWriter
{
public:
    explicit NcWriter(const std::string &path, int mode = NC_CLOBBER | NC_NETCDF4)
    {
        NCW_CHECK(nc_create(path.c_str(), mode, &id_));
    }
    ~NcWriter() { nc_close(id_); }
    int dim(const std::string &name, std::size_t len)
    {
        int d;
        NCW_CHECK(nc_def_dim(id_, name.c_str(), len, &d));
        return d;
    }
    int var(const std::string &name, nc_type type, const std::vector<int> &dims)
    {
        int v;
        NCW_CHECK(nc_def_var(id_, name.c_str(), type, int(dims.size()), dims.data(), &v));
        return v;
    }
    void text(int var, const std::string &name, const std::string &value)
    {
        NCW_CHECK(nc_put_att_text(id_, var, name.c_str(), value.size(), value.c_str()));
    }
    void num(int var, const std::string &name, nc_type type, const std::vector<double> &values)
    {
        NCW_CHECK(nc_put_att_double(id_, var, name.c_str(), type, values.size(), values.data()));
    }
    /// _FillValue must be set before enddef for netCDF-4 files.
    void fill(int var, nc_type type, double value) { num(var, "_FillValue", type, {value}); }
    void enddef() { NCW_CHECK(nc_enddef(id_)); }
    void put(int var, const std::vector<double> &values) { NCW_CHECK(nc_put_var_double(id_, var, values.data())); }
    int id() const { return id_; }

private:
    int id_{-1};
};

/// Options that load the region lon [lonMin, lonMax] x lat [latMin, latMax] (lonMax < lonMin across 180).
inline ompl_glider::GriddedCurrentOptions regionOptions(double lonMin, double lonMax, double latMin, double latMax)
{
    ompl_glider::GriddedCurrentOptions o;
    o.lonMin = lonMin;
    o.lonMax = lonMax;
    o.latMin = latMin;
    o.latMax = latMax;
    return o;
}

/// The eastward/northward current (ue, vn) at (lon, lat) as the loaded field holds it in its plane: turned by the
/// projection's east and north directions there.
inline ompl_glider::Velocity inPlane(const ompl_glider::GriddedCurrents &nc, double lon, double lat, double ue,
                                     double vn)
{
    double ex, ey, nx, ny;
    nc.projection->eastDirection(lon, lat, ex, ey);
    nc.projection->northDirection(lon, lat, nx, ny);
    return {ue * ex + vn * nx, ue * ey + vn * ny};
}

/// Regularly spaced values a, a+h, ... (n values).
inline std::vector<double> linspace(double a, double h, std::size_t n)
{
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = a + h * double(i);
    return v;
}
} // namespace glider_test

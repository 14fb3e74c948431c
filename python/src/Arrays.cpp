// Currents given as numpy arrays: a CF NetCDF dataset built in memory (nc_create_mem) and registered with the
// library (io/MemoryDataset.h), so that they reach the pipeline the way every forecast does (the NetCDF reader's
// checks, land from NaN, units, interpolation), not by a second path, and without a file on disk. Its NetCDF-C
// calls hold the library's one lock of NetCDF-C (src/io/DatasetLock.h), as every other NetCDF-C call does.
#include <netcdf.h>
#include <netcdf_mem.h>

#include <cstdlib>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "Bindings.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "io/DatasetLock.h"

namespace py = pybind11;
using ompl_glider::Error;
using ompl_glider::gridded_detail::DatasetLock;

namespace ompl_glider_py
{
namespace
{
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
constexpr double kFill = 1e20;

class Writer
{
public:
    /// A dataset in memory (CDF-5: 64-bit sizes, no HDF5 image needed)
    explicit Writer(const std::string &name) : path_(name)
    {
        check(nc_create_mem(name.c_str(), NC_64BIT_DATA, 1 << 16, &id_));
    }
    ~Writer()
    {
        if (id_ >= 0)
            nc_close(id_);
    }
    void check(int status) const
    {
        if (status != NC_NOERR)
            throw Error(path_ + ": writing the currents: " + nc_strerror(status));
    }
    int dim(const char *name, std::size_t n)
    {
        int d = 0;
        check(nc_def_dim(id_, name, n, &d));
        return d;
    }
    int var(const char *name, const std::vector<int> &dims, const std::string &units, const std::string &standard)
    {
        int v = 0;
        check(nc_def_var(id_, name, NC_DOUBLE, static_cast<int>(dims.size()), dims.data(), &v));
        text(v, "units", units);
        if (!standard.empty())
            text(v, "standard_name", standard);
        return v;
    }
    void text(int var, const char *name, const std::string &value)
    {
        check(nc_put_att_text(id_, var, name, value.size(), value.c_str()));
    }
    void fill(int var) { check(nc_put_att_double(id_, var, "_FillValue", NC_DOUBLE, 1, &kFill)); }
    void put(int var, const double *data) { check(nc_put_var_double(id_, var, data)); }
    void enddef() { check(nc_enddef(id_)); }
    /// Closes the dataset and registers its bytes: the name the reader opens it by.
    std::string close()
    {
        NC_memio io{};
        const int st = nc_close_memio(id_, &io);
        id_ = -1;
        check(st);
        std::string bytes(static_cast<const char *>(io.memory), io.size);
        std::free(io.memory);
        return ompl_glider::registerMemoryDataset(std::move(bytes));
    }

private:
    std::string path_;
    int id_{-1};
};

std::vector<double> values(const Array &a, const char *name, std::size_t n)
{
    if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n)
        throw Error(std::string("currents from arrays: '") + name + "' must be 1-D with " + std::to_string(n) +
                    " values (the matching axis of u and v), got shape " +
                    py::str(py::tuple(py::cast(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()))))
                        .cast<std::string>());
    std::vector<double> v(a.data(), a.data() + n);
    for (double x : v)
        if (!std::isfinite(x))
            throw Error(std::string("currents from arrays: '") + name + "' holds a value that is not finite");
    return v;
}

/// Builds u and v ((time, y, x) or steady (y, x); NaN: land) on the axes x (lon) and y (lat) and the times t
/// (in @p timeUnits; none for a steady field) as a CF NetCDF dataset in memory; returns its name ("memory:N").
std::string memoryForecast(const Array &u, const Array &v, const Array &x, const Array &y,
                           const std::optional<Array> &t, bool geographic, const std::string &timeUnits,
                           const std::string &velocityUnits)
{
    const py::ssize_t nd = u.ndim();
    if ((nd != 2 && nd != 3) || v.ndim() != nd)
        throw Error("currents from arrays: u and v must both be (time, y, x) or (y, x) arrays");
    for (py::ssize_t k = 0; k < nd; ++k)
        if (u.shape(k) != v.shape(k))
            throw Error("currents from arrays: u and v must have the same shape");
    if ((nd == 3) != t.has_value())
        throw Error(nd == 3 ? "currents from arrays: (time, y, x) arrays need the times t"
                            : "currents from arrays: (y, x) arrays are a steady field and take no times");
    const std::size_t nx = u.shape(nd - 1), ny = u.shape(nd - 2), nt = nd == 3 ? u.shape(0) : 0;
    const std::vector<double> xs = values(x, geographic ? "lon" : "x", nx),
                              ys = values(y, geographic ? "lat" : "y", ny);
    const std::vector<double> ts = t ? values(*t, "t", nt) : std::vector<double>{};
    if (t && timeUnits.empty())
        throw Error("currents from arrays: time_units must say what t is, e.g. 'seconds since 2026-03-15 00:00:00'");
    std::vector<double> uu(u.data(), u.data() + u.size()), vv(v.data(), v.data() + v.size());
    for (std::size_t k = 0; k < uu.size(); ++k)
        if (std::isnan(uu[k]) || std::isnan(vv[k]))
            uu[k] = vv[k] = kFill;
        else if (!std::isfinite(uu[k]) || !std::isfinite(vv[k]))
            throw Error("currents from arrays: u and v must be finite or NaN (land)");

    // NetCDF-C is not thread-safe: the dataset is written under the library's one lock of it (io/DatasetLock.h), with
    // the GIL released first (the lock is never taken while the GIL is held: a thread holding it may wait for the GIL)
    const py::gil_scoped_release release;
    const DatasetLock lock;
    Writer w("currents_from_arrays");
    std::vector<int> dims;
    int tv = -1;
    if (t)
    {
        dims.push_back(w.dim("time", nt));
        tv = w.var("time", {dims.back()}, timeUnits, "time");
    }
    const int yd = w.dim(geographic ? "lat" : "y", ny), xd = w.dim(geographic ? "lon" : "x", nx);
    const int yv =
        geographic ? w.var("lat", {yd}, "degrees_north", "latitude") : w.var("y", {yd}, "m", "projection_y_coordinate");
    const int xv =
        geographic ? w.var("lon", {xd}, "degrees_east", "longitude") : w.var("x", {xd}, "m", "projection_x_coordinate");
    dims.push_back(yd);
    dims.push_back(xd);
    const int uv = w.var("u", dims, velocityUnits, "eastward_sea_water_velocity");
    const int vv_ = w.var("v", dims, velocityUnits, "northward_sea_water_velocity");
    w.fill(uv);
    w.fill(vv_);
    w.enddef();
    if (t)
        w.put(tv, ts.data());
    w.put(yv, ys.data());
    w.put(xv, xs.data());
    w.put(uv, uu.data());
    w.put(vv_, vv.data());
    return w.close();
}
} // namespace

void bindArrays(py::module_ &m)
{
    m.def("memory_forecast", &memoryForecast, py::arg("u"), py::arg("v"), py::arg("x"), py::arg("y"),
          py::arg("t") = py::none(), py::arg("geographic") = true, py::arg("time_units") = "",
          py::arg("velocity_units") = "m s-1",
          "Builds numpy currents as a CF NetCDF dataset in memory that the forecast reader reads; its name.");
    m.def("release_memory_dataset", &ompl_glider::releaseMemoryDataset, py::arg("name"),
          "Forgets a dataset of memory_forecast().");
}
} // namespace ompl_glider_py

// read_observations(): a glider's fixes and DAC as the planner reads them (readGliderObservations(), the one reader
// of every source: IOOS profile files, CSV, ERDDAP URLs, Slocum dba and binary files), as numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "Bindings.h"
#include "ompl_glider/io/GliderObservations.h"

namespace py = pybind11;

namespace ompl_glider_py
{
namespace
{
py::array_t<double> columnArray(const std::vector<double> &v)
{
    return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

py::dict observationsDict(const ompl_glider::GliderObservations &o)
{
    std::vector<double> ft, flon, flat;
    for (const ompl_glider::GliderFix &f : o.fixes)
    {
        ft.push_back(f.time);
        flon.push_back(f.at.lon);
        flat.push_back(f.at.lat);
    }
    std::vector<double> t, lon, lat, u, v, start, end, zmin, zmax;
    for (const ompl_glider::DacRecord &d : o.dac)
    {
        t.push_back(d.time);
        lon.push_back(d.at.lon);
        lat.push_back(d.at.lat);
        u.push_back(d.u);
        v.push_back(d.v);
        start.push_back(d.segmentStart);
        end.push_back(d.segmentEnd);
        zmin.push_back(d.depthMin);
        zmax.push_back(d.depthMax);
    }
    py::dict fixes, dac, out;
    fixes["time"] = columnArray(ft);
    fixes["lon"] = columnArray(flon);
    fixes["lat"] = columnArray(flat);
    dac["time"] = columnArray(t);
    dac["lon"] = columnArray(lon);
    dac["lat"] = columnArray(lat);
    dac["u"] = columnArray(u);
    dac["v"] = columnArray(v);
    dac["segment_start"] = columnArray(start);
    dac["segment_end"] = columnArray(end);
    dac["depth_min"] = columnArray(zmin);
    dac["depth_max"] = columnArray(zmax);
    out["fixes"] = fixes;
    out["dac"] = dac;
    out["rejected"] = py::cast(o.rejected);
    out["notes"] = py::cast(o.notes);
    out["platform"] = o.platform;
    out["files"] = o.files;
    out["newest_surfacing"] = o.newestSurfacing;
    return out;
}
} // namespace

void bindObservations(py::module_ &m)
{
    m.def(
        "read_observations",
        [](const std::string &source, const std::string &cache) {
            ompl_glider::ObservationReadOptions options;
            options.cache = cache;
            ompl_glider::GliderObservations o;
            {
                py::gil_scoped_release release;
                o = ompl_glider::readGliderObservations(source, options);
            }
            return observationsDict(o);
        },
        py::arg("source"), py::arg("cache") = "",
        "The fixes and DAC the planner reads from source (readGliderObservations()).");
}
} // namespace ompl_glider_py

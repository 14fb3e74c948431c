// ompl_glider._core: the C++ side of the Python module ompl_glider (python/ompl_glider/__init__.py is the API).
#include <pybind11/pybind11.h>

#include <ompl/util/Console.h>

#include "Bindings.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/RemoteSource.h"

namespace py = pybind11;

PYBIND11_MODULE(_core, m)
{
    m.doc() = "ompl_glider's C++ pipeline (MissionSpec -> runMission() -> the output layer); use the package "
              "ompl_glider, not this module";
    // errors of the library: the same messages as glider_plan's, as ompl_glider.Error (a ValueError)
    py::register_exception<ompl_glider::Error>(m, "Error", PyExc_ValueError);
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN); // as glider_plan without --verbose
    m.def(
        "set_verbose", [](bool on) { ompl::msg::setLogLevel(on ? ompl::msg::LOG_INFO : ompl::msg::LOG_WARN); },
        py::arg("on"), "Shows OMPL's log messages (as glider_plan --verbose).");
    m.def(
        "set_remote_access",
        [](const std::string &cache, double requestTimeout, int retries) {
            ompl_glider::RemoteAccess a;
            a.cacheDir = cache;
            a.requestTimeout = requestTimeout;
            a.retries = retries;
            ompl_glider::setRemoteAccess(a);
        },
        py::arg("cache"), py::arg("request_timeout"), py::arg("retries"),
        "How OPeNDAP URLs are fetched (glider_plan's --cache, --request-timeout, --retries).");
    ompl_glider_py::bindMission(m);
    ompl_glider_py::bindResult(m);
    ompl_glider_py::bindArrays(m);
    ompl_glider_py::bindObservations(m);
}

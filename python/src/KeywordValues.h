#pragma once
// The keyword arguments of plan() read in the Python module (Mission.cpp): each value checked for what its keyword
// takes (a bool is no number, a number no bool, a number finite, a text not empty), an Error naming the keyword, what
// it expects and what it got otherwise; where a keyword's value came from (SourceMark).
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "ompl_glider/Exception.h"
#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider_py
{
namespace py = pybind11;
using ompl_glider::Error;
using ompl_glider::Origin;
using ompl_glider::SourceMark;

/// Where a keyword's value came from, for MissionSpec::place() (a keyword's mark names itself).
inline SourceMark keyword(const std::string &name)
{
    return SourceMark{"plan(): keyword '" + name + "'", 0, Origin::Keyword};
}

/// "str 'fast'": the Python type and a short repr of a value, for messages.
inline std::string describe(const py::handle &v)
{
    std::string r = py::repr(v).cast<std::string>();
    if (r.size() > 60)
        r = r.substr(0, 57) + "...";
    return std::string(Py_TYPE(v.ptr())->tp_name) + " " + r;
}

inline bool isBool(const py::handle &v)
{
    return py::isinstance<py::bool_>(v) || std::string(Py_TYPE(v.ptr())->tp_name) == "numpy.bool_";
}

/// What keeps @p v, or an item of it at any depth (of a tuple, a list, a dict's values), from being the numbers a
/// keyword takes: a bool (True is no 1.0) or a number that is not finite (NaN would read as "not given"); "" when
/// nothing does. Texts are left to the keyword's own reading.
inline std::string badNumber(const py::handle &v, const std::string &item = "")
{
    const std::string what = item.empty() ? "it" : "item " + item;
    if (isBool(v))
        return what + " is a bool";
    if (py::isinstance<py::str>(v) || py::isinstance<py::bytes>(v))
        return "";
    if (py::isinstance<py::dict>(v))
    {
        for (const auto &kv : py::reinterpret_borrow<py::dict>(v))
            if (std::string bad = badNumber(kv.second, item + "[" + py::repr(kv.first).cast<std::string>() + "]");
                !bad.empty())
                return bad;
        return "";
    }
    if (py::isinstance<py::tuple>(v) || py::isinstance<py::list>(v))
    {
        std::size_t k = 0;
        for (const py::handle x : v)
            if (std::string bad = badNumber(x, item + "[" + std::to_string(k++) + "]"); !bad.empty())
                return bad;
        return "";
    }
    if (PyFloat_Check(v.ptr()) || (PyNumber_Check(v.ptr()) && !PyLong_Check(v.ptr()) && py::hasattr(v, "dtype")))
    {
        const double x = PyFloat_AsDouble(v.ptr());
        if (PyErr_Occurred())
            PyErr_Clear();
        else if (!std::isfinite(x))
            return what + " is not finite";
    }
    return "";
}

/// The value of keyword @p name as a T, or an Error naming the keyword, what it expects and what it got: a bool is
/// no number, and a number no bool (smoothing=1 is refused, as smoothing="no" is), also as an item of a pair or a
/// list (via=[(True, False)]); a number is finite (radius=nan is refused, not read as "not given"); a text is not
/// empty (observations="" is refused, not read as "none").
template <class T> T value(const py::handle &v, const std::string &name, const char *expected)
{
    bool ok = std::is_same_v<T, bool> ? isBool(v) : !isBool(v);
    std::string why;
    if constexpr (!std::is_same_v<T, bool> && !std::is_same_v<T, std::string> && !std::is_base_of_v<py::handle, T>)
        if (ok && !(why = badNumber(v)).empty())
            ok = false;
    if (ok)
        try
        {
            T out = v.cast<T>();
            if constexpr (std::is_same_v<T, std::string>)
                if (out.empty())
                    throw Error("plan(): keyword '" + name + "': expected " + expected + ", got an empty text");
            return out;
        }
        catch (const py::cast_error &)
        {
            ok = false;
        }
    throw Error("plan(): keyword '" + name + "': expected " + expected + ", got " + describe(v) +
                (why.empty() ? std::string() : " (" + why + ")"));
}

inline void checkFinite(const std::string &name, double v, bool positive)
{
    if (!std::isfinite(v) || (positive && !(v > 0.0)))
    {
        char got[32];
        std::snprintf(got, sizeof got, "%.10g", v); // as the library's messages write numbers
        throw Error("plan(): keyword '" + name + "' expects a finite number" + (positive ? " > 0" : "") + ", got " +
                    got);
    }
}
} // namespace ompl_glider_py

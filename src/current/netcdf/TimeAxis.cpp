// The CF time axis ("<unit> since <date>" with its calendar), the forecast times a mission needs, and
// readNetCdfTimeAxis(), which finds the axis exactly as the loader does.
#include <algorithm>
#include <cmath>

#include "NetCdfInternal.h"

namespace ompl_glider
{
namespace netcdf_detail
{
namespace
{
/// The first index k with v[k] <= v[k - 1]; v.size() when v is strictly increasing.
std::size_t firstNotIncreasing(const std::vector<double> &v)
{
    for (std::size_t k = 1; k < v.size(); ++k)
        if (!(v[k] > v[k - 1]))
            return k;
    return v.size();
}
}  // namespace

TimeValues readTimeValues(const NcFile &f, int tv, bool allowUndated)
{
    TimeValues out;
    out.name = f.varName(tv);
    const std::string &tn = out.name;
    const std::vector<double> raw = f.readAll1D(tv);
    if (raw.empty())
        throw f.error("time variable '" + tn + "' has no values");
    checkAxisValues(f, tv, raw, "time variable");
    const std::size_t bad = firstNotIncreasing(raw);
    if (bad < raw.size())
        throw f.error("time variable '" + tn + "' is not strictly monotonic: " + numText(raw[bad - 1]) +
                      " at index " + std::to_string(bad - 1) + ", then " + numText(raw[bad]) + " at index " +
                      std::to_string(bad) + "; expected increasing times");
    const std::string units = unitsOf(f, tv);
    const std::string cal = f.attText(tv, "calendar").value_or("standard");
    std::vector<double> &ts = out.times;
    ts.resize(raw.size());
    if (lower(units).find(" since ") != std::string::npos)
    {
        CfTimeUnits cu;
        try
        {
            cu = parseCfTimeUnits(units, cal);
        }
        catch (const Error &e)
        {
            throw f.error("time variable '" + tn + "': " + e.what());
        }
        out.dated = true;
        out.calendar = cu.calendar;
        out.originSeconds = cu.reference + raw.at(0) * cu.secondsPerUnit;
        for (std::size_t k = 0; k < raw.size(); ++k)
            ts[k] = (raw[k] - raw[0]) * cu.secondsPerUnit;
    }
    else if (allowUndated)
        ts = raw;
    else
        throw f.error("time variable '" + tn + "': units '" + units +
                      "', expected '<seconds|minutes|hours|days> since <date>'");
    for (std::size_t j = 0; j < ts.size(); ++j)
        if (!std::isfinite(ts[j]) || (j > 0 && !(ts[j] > ts[j - 1])))
            throw f.error("time variable '" + tn + "': " + numText(raw[j]) + " at index " + std::to_string(j) +
                          " does not convert to a finite time in seconds after the one before");
    return out;
}

namespace
{
/// The departure in field time (the first forecast time when none is given). @throws Error outside the forecast.
double departureOf(const NcFile &f, const NetCdfCurrentOptions &opt, const TimeValues &tv, const NetCdfCurrents &out)
{
    const std::vector<double> &ts = tv.times;
    double dep = ts.front();
    if (opt.departure.empty())
        return dep;
    try
    {
        dep = out.fieldTime(opt.departure);
    }
    catch (const Error &e)
    {
        throw f.error(std::string("departure: ") + e.what());
    }
    if (dep < ts.front() || dep > ts.back())
        throw f.error("departure " + opt.departure + " (" + out.isoTime(dep) +
                      ") is outside the forecast of variable '" + tv.name + "' [" + out.isoTime(ts.front()) + ", " +
                      out.isoTime(ts.back()) + "]");
    return dep;
}
}  // namespace

AxisSelection selectTimes(const NcFile &f, const Layout &l, const NetCdfCurrentOptions &opt, NetCdfCurrents &out)
{
    AxisSelection s;
    if (l.dimT < 0)
    {
        if (!opt.departure.empty())
            out.departureTime = out.fieldTime(opt.departure);
        return s;
    }
    const TimeValues tv = readTimeValues(f, l.coordVar[std::size_t(l.dimT)], !l.geographic);
    const std::vector<double> &ts = tv.times;
    out.dated = tv.dated;
    if (tv.dated)
    {
        out.calendar = tv.calendar;
        out.originSeconds = tv.originSeconds;
    }
    out.forecastBegin = ts.front();
    out.forecastEnd = ts.back();
    const double dep = departureOf(f, opt, tv, out);
    out.departureTime = dep;
    // departure to departure + horizon, plus 2 forecast steps on each side for cubic/Akima stencils
    const double end = std::isfinite(opt.horizon) ? dep + std::max(0.0, opt.horizon) : ts.back();
    const Axis ax(ts, "time '" + tv.name + "'");
    const std::size_t ta = ax.interval(dep), tb = ax.size() > 1 ? ax.interval(std::min(end, ts.back())) + 1 : 0;
    const std::size_t a = ta >= 2 ? ta - 2 : 0, b = std::min(ts.size() - 1, tb + 2);
    s.idx.clear();
    s.values.clear();
    s.tripBegin = ta - a;
    s.tripEnd = std::min(tb, ts.size() - 1) - a;
    for (std::size_t k = a; k <= b; ++k)
    {
        s.idx.push_back(k);
        s.values.push_back(ts[k]);
    }
    return s;
}
}  // namespace netcdf_detail

NetCdfTimeAxis readNetCdfTimeAxis(const std::string &path, const NetCdfCurrentOptions &options)
{
    using namespace netcdf_detail;
    NcFile f(path);
    const int uVar = findVelocity(f, options.uName, true, "uName");
    const DimensionRoles dr = classifyDimensions(f, options, uVar);
    NetCdfTimeAxis axis;
    const int dimT = dr.find(Role::Time);
    if (dimT < 0)
        return axis;
    const TimeValues tv = readTimeValues(f, dr.coordVar[std::size_t(dimT)], true);
    axis.found = true;
    axis.variable = tv.name;
    axis.dated = tv.dated;
    axis.calendar = tv.calendar;
    axis.originSeconds = tv.originSeconds;
    axis.size = tv.times.size();
    axis.span = tv.times.empty() ? 0.0 : tv.times.back() - tv.times.front();
    return axis;
}

NetCdfTimeAxis readNetCdfTimeAxis(const std::string &path, const std::string &timeName, const std::string &uName)
{
    NetCdfCurrentOptions options;
    options.timeName = timeName;
    options.uName = uName;
    return readNetCdfTimeAxis(path, options);
}
}  // namespace ompl_glider

// The CF time axis ("<unit> since <date>" with its calendar), the forecast times a mission needs, and
// readForecastTimeAxis(), which finds the axis exactly as the loader does.
#include <algorithm>
#include <cmath>
#include <functional>

#include "ForecastFiles.h"
#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
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
} // namespace

namespace
{
bool hasSince(const std::string &units)
{
    return lower(units).find(" since ") != std::string::npos;
}

/// The message for a time axis without "since" where dates are needed.
std::string undatedMessage(const std::string &tn, const std::string &units)
{
    return "time variable '" + tn + "': units '" + units +
           "' have no date; expected '<seconds|minutes|hours|days> since <date>': give the units with "
           "GriddedCurrentOptions::timeUnits (\"days since 2026-01-15\"), or plan on one record as a steady field "
           "with GriddedCurrentOptions::steadyRecord";
}
} // namespace

namespace
{
/// Row @p run of a 2-D time(run, time) without its fill values and NaN (a run shorter than the others), each value
/// with its index along time.
std::vector<double> timeRow(const GriddedDataset &f, int tv, std::size_t run, std::vector<std::size_t> &fileIdx)
{
    const std::vector<int> dims = f.varDims(tv);
    const std::size_t n = f.dimLen(dims.at(1));
    std::vector<double> row(n), out;
    if (n > 0)
        f.readBlock(tv, {run, 0}, {1, n}, row.data());
    const Packing p = packingOf(f, tv);
    fileIdx.clear();
    for (std::size_t k = 0; k < n; ++k)
        if (std::isfinite(row[k]) && !p.isFill(row[k]))
        {
            out.push_back(row[k]);
            fileIdx.push_back(k);
        }
    if (fileIdx.size() == n)
        fileIdx.clear(); // every index: record k is index k
    return out;
}
} // namespace

TimeValues readTimeValues(const GriddedDataset &f, int tv, bool allowUndated, const std::string &unitsOverride,
                          std::size_t run)
{
    TimeValues out;
    out.name = f.varName(tv);
    const std::string &tn = out.name;
    const bool overridden = !unitsOverride.empty();
    const std::string units = overridden ? trim(unitsOverride) : unitsOf(f, tv);
    if (overridden && !hasSince(units))
        throw f.error("GriddedCurrentOptions::timeUnits '" + unitsOverride + "' (for time variable '" + tn +
                          "'): expected '<seconds|minutes|hours|days> since <date>'",
                      "GriddedCurrentOptions::timeUnits");
    if (!hasSince(units) && !allowUndated)
        throw f.error(undatedMessage(tn, units));
    const bool twoD = f.varDims(tv).size() == 2; // time(run, time) of a file of several runs
    const std::vector<double> raw = twoD ? timeRow(f, tv, run, out.fileIdx) : f.readAll1D(tv);
    if (raw.empty())
        throw f.error("time variable '" + tn + "' has no values" +
                      (twoD ? " for run " + std::to_string(run) + " (index along its first dimension)" : ""));
    if (!twoD)
        checkAxisValues(f, tv, raw, "time variable");
    const std::size_t bad = firstNotIncreasing(raw);
    if (bad < raw.size())
        throw f.error("time variable '" + tn + "' is not strictly monotonic: " + text::number(raw[bad - 1]) +
                      " at index " + std::to_string(bad - 1) + ", then " + text::number(raw[bad]) + " at index " +
                      std::to_string(bad) + "; expected increasing times");
    const std::string cal = f.attText(tv, "calendar").value_or("standard");
    std::vector<double> &ts = out.times;
    ts.resize(raw.size());
    if (hasSince(units))
    {
        CfTimeUnits cu;
        try
        {
            cu = parseCfTimeUnits(units, cal);
        }
        catch (const Error &e)
        {
            if (overridden)
                throw f.error("GriddedCurrentOptions::timeUnits '" + unitsOverride + "' (for time variable '" + tn +
                                  "'): " + e.what(),
                              "GriddedCurrentOptions::timeUnits");
            throw f.error("time variable '" + tn + "': " + e.what());
        }
        out.dated = true;
        out.calendar = cu.calendar;
        out.originSeconds = cu.reference + raw.at(0) * cu.secondsPerUnit;
        for (std::size_t k = 0; k < raw.size(); ++k)
            ts[k] = (raw[k] - raw[0]) * cu.secondsPerUnit;
    }
    else
        ts = raw;
    for (std::size_t j = 0; j < ts.size(); ++j)
        if (!std::isfinite(ts[j]) || (j > 0 && !(ts[j] > ts[j - 1])))
            throw f.error("time variable '" + tn + "': " + text::number(raw[j]) + " at index " + std::to_string(j) +
                          " does not convert to a finite time in seconds after the one before");
    return out;
}

std::optional<SteadyRecord> steadyRecordOf(const GriddedDataset &f, int timeDim, int tv,
                                           const GriddedCurrentOptions &opt)
{
    if (!opt.steadyRecord)
        return std::nullopt;
    const std::size_t k = *opt.steadyRecord, n = f.dimLen(timeDim);
    const std::string tn = tv >= 0 ? f.varName(tv) : f.dimName(timeDim);
    if (k >= n)
        throw f.error("GriddedCurrentOptions::steadyRecord " + std::to_string(k) + " is out of range: time variable '" +
                          tn + "' has " + std::to_string(n) + " record" + (n == 1 ? "" : "s") +
                          (n > 0 ? " (0 to " + std::to_string(n - 1) + ")" : ""),
                      "GriddedCurrentOptions::steadyRecord");
    SteadyRecord r;
    r.index = k;
    // dated by the record's time when the axis (or GriddedCurrentOptions::timeUnits) has dates; else undated, and
    // the time values are not needed at all
    const std::string units = !opt.timeUnits.empty() ? opt.timeUnits : (tv >= 0 ? unitsOf(f, tv) : "");
    if (tv >= 0 && (hasSince(units) || !opt.timeUnits.empty()))
    {
        const TimeValues v = readTimeValues(f, tv, true, opt.timeUnits, opt.runIndex.value_or(0));
        if (k >= v.times.size())
            throw f.error("GriddedCurrentOptions::steadyRecord " + std::to_string(k) +
                              " is out of range: the run read "
                              "has " +
                              std::to_string(v.times.size()) + " times",
                          "GriddedCurrentOptions::steadyRecord");
        r.index = v.fileIndex(k);
        r.dated = v.dated;
        r.calendar = v.calendar;
        r.originSeconds = v.originSeconds + v.times.at(k);
    }
    return r;
}

namespace
{
/// "; the file is a climatology ..." when its dates lie in the years 0 and 1 (a climatology's year, as CDO and the
/// ocean models write one), else "": a pilot's real date must be given in that year.
std::string climatologyHint(const GriddedCurrents &out, const std::vector<double> &ts)
{
    if (!out.dated)
        return "";
    const int first = dateFromCalendarEpoch(out.originSeconds + ts.front(), out.calendar).year;
    const int last = dateFromCalendarEpoch(out.originSeconds + ts.back(), out.calendar).year;
    if (first < 0 || last > 1)
        return "";
    return std::string("; the file is a climatology (its dates are in year ") + (first == last ? "" : "0000-") +
           (last == 1 ? "0001" : "0000") + ", " + calendarName(out.calendar) +
           " calendar): give the departure as a date in that year, e.g. " + out.isoTime(ts.front()) + "";
}

/// The departure in field time (the first forecast time when none is given). @throws Error when it is not a time
/// of the file, or outside the forecast of an unsteady field.
double departureOf(const std::function<Error(const std::string &)> &error, const GriddedCurrentOptions &opt,
                   const std::string &tn, const std::vector<double> &ts, const GriddedCurrents &out)
{
    double dep = ts.front();
    if (opt.departure.empty())
        return dep;
    try
    {
        dep = out.fieldTime(opt.departure);
    }
    catch (const Error &e)
    {
        throw Error(error(std::string("departure: ") + e.what()).what(), "GriddedCurrentOptions::departure");
    }
    if (!out.steady && (dep < ts.front() || dep > ts.back()))
        throw Error(error("departure " + opt.departure + " (" + out.isoTime(dep) +
                          ") is outside the forecast of variable '" + tn + "' [" + out.isoTime(ts.front()) + ", " +
                          out.isoTime(ts.back()) + "]" + climatologyHint(out, ts))
                        .what(),
                    "GriddedCurrentOptions::departure");
    return dep;
}

/// The errors of one file.
std::function<Error(const std::string &)> fileErrors(const GriddedDataset &f)
{
    return [&f](const std::string &what) { return f.error(what); };
}
} // namespace

AxisSelection selectTimes(const GriddedDataset &f, const Layout &l, const GriddedCurrentOptions &opt,
                          GriddedCurrents &out)
{
    AxisSelection s;
    if (l.dimT < 0)
    {
        const std::string what = "variable '" + l.uName + "' has no time dimension (a steady field)";
        if (!opt.timeUnits.empty())
            throw f.error("GriddedCurrentOptions::timeUnits given, but " + what, "GriddedCurrentOptions::timeUnits");
        if (opt.steadyRecord)
            throw f.error("GriddedCurrentOptions::steadyRecord given, but " + what,
                          "GriddedCurrentOptions::steadyRecord");
        out.steady = true;
        out.departureTime = departureOf(fileErrors(f), opt, "", {0.0}, out);
        return s;
    }
    const int tVar = l.coordVar[std::size_t(l.dimT)];
    if (const auto rec = steadyRecordOf(f, l.dims[std::size_t(l.dimT)], tVar, opt))
    {
        out.steady = true;
        out.dated = rec->dated;
        out.calendar = rec->calendar;
        out.originSeconds = rec->originSeconds;
        out.departureTime = departureOf(fileErrors(f), opt, f.varName(tVar), {0.0}, out);
        s.idx = {rec->index};
        s.values = {0.0};
        return s;
    }
    checkRunIndex(f, l, opt);
    const TimeValues tv = readTimeValues(f, tVar, !l.geographic, opt.timeUnits, l.run);
    const std::vector<double> &ts = tv.times;
    out.dated = tv.dated;
    if (tv.dated)
    {
        out.calendar = tv.calendar;
        out.originSeconds = tv.originSeconds;
    }
    if (ts.size() == 1)
    {
        out.steady = true;
        out.forecastBegin = out.forecastEnd = ts.front();
        out.departureTime = departureOf(fileErrors(f), opt, tv.name, ts, out);
        s.idx = {tv.fileIndex(0)};
        return s; // the one record: {0}/{0}
    }
    s = selectForecastTimes(ts, tv.name, opt, out, fileErrors(f));
    for (std::size_t &k : s.idx) // records along the time dimension (a run's times without its fill values)
        k = tv.fileIndex(k);
    return s;
}

void checkRunIndex(const GriddedDataset &f, const Layout &l, const GriddedCurrentOptions &opt)
{
    if (l.dimRun < 0)
    {
        if (opt.runIndex && *opt.runIndex > 0)
            throw f.error("GriddedCurrentOptions::runIndex " + std::to_string(*opt.runIndex) +
                              " given, but variable '" + l.uName +
                              "' has no run dimension (a file of one forecast run)",
                          "GriddedCurrentOptions::runIndex");
        return;
    }
    const int dim = l.dims[std::size_t(l.dimRun)];
    const std::size_t n = f.dimLen(dim);
    const std::string what = "variable '" + l.uName + "' is on dimension '" + f.dimName(dim) + "' of " +
                             std::to_string(n) + " forecast runs (a forecast model run collection, a THREDDS FMRC";
    if (!opt.runIndex && n > 1)
        throw f.error(what + ", with a 2-D time): read it as forecast runs, each run one forecast, with "
                             "GriddedCurrentOptions::runIndex",
                      "GriddedCurrentOptions::runIndex");
    if (opt.runIndex && *opt.runIndex >= n)
        throw f.error(what + "): GriddedCurrentOptions::runIndex " + std::to_string(*opt.runIndex) +
                          " is out of range (0 to " + std::to_string(n - 1) + ")",
                      "GriddedCurrentOptions::runIndex");
}

AxisSelection selectForecastTimes(const std::vector<double> &ts, const std::string &name,
                                  const GriddedCurrentOptions &opt, GriddedCurrents &out,
                                  const std::function<Error(const std::string &)> &error)
{
    AxisSelection s;
    out.steady = false;
    out.forecastBegin = ts.front();
    out.forecastEnd = ts.back();
    const double dep = departureOf(error, opt, name, ts, out);
    out.departureTime = dep;
    // departure to departure + horizon, plus 2 forecast steps on each side for cubic/Akima stencils
    const double end = std::isfinite(opt.horizon) ? dep + std::max(0.0, opt.horizon) : ts.back();
    const Axis ax(ts, "time '" + name + "'");
    // the last record at or before the departure, the first at or after the end
    const std::size_t n = ts.size();
    const std::size_t ta =
        std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::max<std::ptrdiff_t>(
                                         0, std::upper_bound(ts.begin(), ts.end(), dep) - ts.begin() - 1)));
    const std::size_t tb =
        std::max(ta, std::min<std::size_t>(
                         n - 1, static_cast<std::size_t>(std::lower_bound(ts.begin(), ts.end(), end) - ts.begin())));
    // loaded: the intervals of departure and end, plus 2 records on each side for cubic/Akima stencils
    const std::size_t ia = ax.interval(dep), ib = ax.size() > 1 ? ax.interval(std::min(end, ts.back())) + 1 : 0;
    const std::size_t a = ia >= 2 ? ia - 2 : 0, b = std::min(ts.size() - 1, ib + 2);
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

namespace
{
/// The reference time of run @p run of a file of several runs: the value of the runs' coordinate @p runVar.
void runReferenceTime(const GriddedDataset &f, ForecastTimeAxis &axis, int runVar, std::size_t run)
{
    const std::string name = f.varName(runVar);
    const std::vector<double> v = f.readAll1D(runVar);
    if (run >= v.size() || !std::isfinite(v[run]) || packingOf(f, runVar).isFill(v[run]))
        throw f.error("variable '" + name + "' (the runs' reference times) has no value for run " +
                      std::to_string(run));
    CfTimeUnits cu;
    try
    {
        cu = parseCfTimeUnits(unitsOf(f, runVar), f.attText(runVar, "calendar").value_or(calendarName(axis.calendar)));
    }
    catch (const Error &e)
    {
        throw f.error("variable '" + name + "' (the runs' reference times): " + e.what());
    }
    if (cu.calendar != axis.calendar)
        throw f.error("variable '" + name + "' (the runs' reference times): its calendar (" +
                      calendarName(cu.calendar) + ") differs from the time axis's (" + calendarName(axis.calendar) +
                      ")");
    axis.referenceSeconds = cu.reference + v[run] * cu.secondsPerUnit;
    axis.referenceFrom = "variable '" + name + "', run " + std::to_string(run + 1) + " of " + std::to_string(v.size());
}

/// HYCOM's (GOFS 3.1, ESPC) `tau`: hours since the analysis at each time, so that the analysis (the reference time)
/// is the first time minus its first value; false without it.
bool hycomTau(const GriddedDataset &f, ForecastTimeAxis &axis)
{
    const std::optional<int> tau = f.findVar("tau");
    if (!tau)
        return false;
    const std::string units = lower(unitsOf(f, *tau));
    const std::size_t since = units.find(" since analysis");
    const std::vector<double> v = f.readAll1D(*tau);
    if (since == std::string::npos || v.empty() || !std::isfinite(v[0]))
        return false;
    double perUnit = 0.0;
    try
    {
        perUnit = parseCfTimeUnits(units.substr(0, since) + " since 2000-01-01", "standard").secondsPerUnit;
    }
    catch (const Error &)
    {
        return false;
    }
    axis.referenceSeconds = axis.originSeconds - v[0] * perUnit;
    axis.referenceFrom = "variable 'tau' (" + unitsOf(f, *tau) + "): the first time minus " + text::number(v[0]) + " " +
                         units.substr(0, since);
    return true;
}
} // namespace

void readReferenceTime(const GriddedDataset &f, ForecastTimeAxis &axis, int runVar, std::size_t run)
{
    if (runVar >= 0)
        return runReferenceTime(f, axis, runVar, run);
    const std::string calendar = calendarName(axis.calendar);
    for (int var = 0; var < f.nvars(); ++var)
    {
        const std::string name = f.varName(var);
        if (lower(f.attText(var, "standard_name").value_or("")) != "forecast_reference_time" &&
            lower(name) != "forecast_reference_time")
            continue;
        std::vector<double> v = f.readAll1D(var);
        // along time (a THREDDS best time series joins several runs, each record its own run's): complete when the
        // newest of them was
        const bool series = v.size() > 1 && f.varDims(var).size() == 1;
        if (series)
        {
            const Packing p = packingOf(f, var);
            double newest = kNaN;
            for (double x : v)
                if (std::isfinite(x) && !p.isFill(x) && !(x <= newest))
                    newest = x;
            v = {newest};
        }
        if (v.size() != 1 || !std::isfinite(v[0]))
            throw f.error("variable '" + name + "' (forecast_reference_time) holds " + std::to_string(v.size()) +
                          " values; a forecast run has one reference time (a file of several runs, a THREDDS FMRC "
                          "collection, has them as the coordinate of the velocities' run dimension)");
        const std::string units = unitsOf(f, var);
        CfTimeUnits cu;
        try
        {
            cu = parseCfTimeUnits(units, f.attText(var, "calendar").value_or(calendar));
        }
        catch (const Error &e)
        {
            throw f.error("variable '" + name + "' (forecast_reference_time): " + e.what());
        }
        if (cu.calendar != axis.calendar)
            throw f.error("variable '" + name + "' (forecast_reference_time): its calendar (" +
                          calendarName(cu.calendar) + ") differs from the time axis's (" + calendar + ")");
        axis.referenceSeconds = cu.reference + v[0] * cu.secondsPerUnit;
        axis.referenceFrom = "variable '" + name + "'" + (series ? " (the newest of its values along time)" : "");
        return;
    }
    if (const std::optional<std::string> text = f.attText(kGlobalAttributes, "forecast_reference_time"))
    {
        try
        {
            axis.referenceSeconds = secondsSinceCalendarEpoch(*text, axis.calendar);
        }
        catch (const Error &e)
        {
            throw f.error("global attribute 'forecast_reference_time' ('" + *text + "'): " + e.what());
        }
        axis.referenceFrom = "global attribute 'forecast_reference_time'";
        return;
    }
    if (hycomTau(f, axis))
        return;
    axis.referenceSeconds = axis.originSeconds;
    axis.referenceFrom = "its first time (no forecast_reference_time)";
}
} // namespace gridded_detail

ForecastTimeAxis readForecastTimeAxis(const std::string &path, const GriddedCurrentOptions &options)
{
    using namespace gridded_detail;
    GriddedDataset f(path);
    const int uVar = findVelocity(f, options.uName, true, "uName");
    const DimensionRoles dr = classifyDimensions(f, options, uVar);
    ForecastTimeAxis axis;
    const int dimT = dr.find(Role::Time);
    if (dimT < 0)
    {
        const std::string what = "variable '" + f.varName(uVar) + "' has no time dimension (a steady field)";
        if (!options.timeUnits.empty())
            throw f.error("GriddedCurrentOptions::timeUnits given, but " + what, "GriddedCurrentOptions::timeUnits");
        if (options.steadyRecord)
            throw f.error("GriddedCurrentOptions::steadyRecord given, but " + what,
                          "GriddedCurrentOptions::steadyRecord");
        axis.steady = true;
        return axis;
    }
    const int tVar = dr.coordVar[std::size_t(dimT)];
    axis.found = true;
    axis.variable = f.varName(tVar);
    if (const auto rec = steadyRecordOf(f, dr.dims[std::size_t(dimT)], tVar, options))
    {
        axis.steady = true;
        axis.dated = rec->dated;
        axis.calendar = rec->calendar;
        axis.originSeconds = rec->originSeconds;
        axis.size = 1;
        return axis;
    }
    const int dimRun = dr.find(Role::Run);
    const int runVar = dimRun < 0 ? -1 : dr.coordVar[std::size_t(dimRun)];
    const std::size_t nRuns = dimRun < 0 ? 1 : f.dimLen(dr.dims[std::size_t(dimRun)]);
    if (dimRun >= 0 && nRuns > 1 && f.varDims(tVar).size() != 2)
        throw f.error("variable '" + f.varName(uVar) + "' is on dimension '" + f.dimName(dr.dims[std::size_t(dimRun)]) +
                      "' of forecast runs, but its time '" + axis.variable +
                      "' is not a 2-D time(run, time); expected a THREDDS FMRC's layout");
    if (options.runIndex && *options.runIndex >= nRuns)
        throw f.error("GriddedCurrentOptions::runIndex " + std::to_string(*options.runIndex) +
                          " is out of range: the file holds " + std::to_string(nRuns) + " forecast run" +
                          (nRuns == 1 ? "" : "s"),
                      "GriddedCurrentOptions::runIndex");
    // each run of a file of several (its times without fill values; a run without times is left out), then the
    // axis of the run asked for (else the first)
    for (std::size_t k = 0; dimRun >= 0 && axis.found && k < nRuns; ++k)
    {
        std::vector<std::size_t> idx;
        if (timeRow(f, tVar, k, idx).empty())
            continue;
        const TimeValues tv = readTimeValues(f, tVar, true, options.timeUnits, k);
        ForecastTimeAxis one = axis;
        one.originSeconds = tv.originSeconds;
        if (tv.dated)
            readReferenceTime(f, one, runVar, k);
        axis.runs.push_back({k, tv.originSeconds, tv.times.size(), tv.times.back() - tv.times.front(),
                             one.referenceSeconds, one.referenceFrom});
    }
    const std::size_t run = options.runIndex.value_or(axis.runs.empty() ? 0 : axis.runs.front().index);
    const TimeValues tv = readTimeValues(f, tVar, true, options.timeUnits, run);
    axis.steady = tv.times.size() == 1;
    axis.dated = tv.dated;
    axis.calendar = tv.calendar;
    axis.originSeconds = tv.originSeconds;
    axis.size = tv.times.size();
    axis.span = tv.times.empty() ? 0.0 : tv.times.back() - tv.times.front();
    if (axis.dated)
        readReferenceTime(f, axis, runVar, run);
    if (!tv.dated)
        axis.runs.clear(); // (undated: no reference times; the caller refuses such runs)
    return axis;
}

ForecastTimeAxis readForecastTimeAxis(const std::string &path, const std::string &timeName, const std::string &uName)
{
    GriddedCurrentOptions options;
    options.timeName = timeName;
    options.uName = uName;
    return readForecastTimeAxis(path, options);
}
} // namespace ompl_glider

// A forecast in several NetCDF files (daily files of one model run, each with its own time axis) read as one:
// the files' time axes put on one origin, the records the trip needs chosen on the joined axis, each file that
// holds some of them read with the stages of loadGriddedCurrents() (readForecastPiece()), the pieces checked to be
// on one grid and joined along time, and one field built (buildForecast()). Also the file lists themselves:
// comma-separated lists and glob(3) patterns.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "ForecastFiles.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// One file's dated time axis.
struct FileTimes
{
    std::string path;
    TimeValues tv;
};

/// The time axis of the velocities of one file, found as readForecastTimeAxis() finds it; it must be dated.
FileTimes readFileTimes(const std::string &path, const GriddedCurrentOptions &opt)
{
    GriddedDataset f(path);
    const int uVar = findVelocity(f, opt.uName, true, "uName");
    const DimensionRoles dr = classifyDimensions(f, opt, uVar);
    const int dimT = dr.find(Role::Time);
    if (dimT < 0)
        throw f.error("variable '" + f.varName(uVar) +
                      "' has no time dimension: files of a forecast in several files are joined along their time "
                      "axes; give a file without time alone");
    if (const int run = dr.find(Role::Run); run >= 0 && f.dimLen(dr.dims[std::size_t(run)]) > 1)
        throw f.error("variable '" + f.varName(uVar) + "' is on dimension '" + f.dimName(dr.dims[std::size_t(run)]) +
                          "' of several forecast runs (a THREDDS FMRC): it is not joined with other files as one "
                          "forecast; read its runs as forecast runs (GriddedCurrentOptions::runIndex)",
                      "GriddedCurrentOptions::runIndex");
    FileTimes out;
    out.path = path;
    out.tv = readTimeValues(f, dr.coordVar[std::size_t(dimT)], true, opt.timeUnits);
    if (!out.tv.dated)
        throw f.error("time variable '" + out.tv.name + "': units '" + unitsOf(f, dr.coordVar[std::size_t(dimT)]) +
                      "' have no date: the files of a forecast in several files are ordered and joined by their "
                      "dates; expected '<seconds|minutes|hours|days> since <date>' (give the units with "
                      "GriddedCurrentOptions::timeUnits, or plan on one file)");
    return out;
}

std::string iso(double calendarSeconds, Calendar c)
{
    return formatDateTime(dateFromCalendarEpoch(calendarSeconds, c));
}

std::string hoursText(double seconds)
{
    return text::number(seconds / 3600.0) + " h";
}

/// The files' time axes on one origin (the first time of the earliest file). Records of a file at or after the
/// first time of the next file are dropped: the later file (the newer forecast) gives the times it covers.
struct JoinedAxis
{
    std::vector<FileTimes> files; ///< ordered by their first time
    Calendar calendar{Calendar::Standard};
    double originSeconds{0.0};
    std::vector<double> times;      ///< field times (seconds after originSeconds), strictly increasing
    std::vector<std::size_t> file;  ///< per record: position in files
    std::vector<std::size_t> index; ///< per record: index along the file's time dimension
    std::size_t dropped{0};         ///< records left out for a later file's

    std::string describe() const
    {
        return "gridded forecast of " + std::to_string(files.size()) + " files ('" + files.front().path + "' to '" +
               files.back().path + "')";
    }
};

JoinedAxis joinTimeAxes(const std::vector<std::string> &paths, const GriddedCurrentOptions &opt)
{
    if (opt.steadyRecord)
        throw Error("GriddedCurrentOptions::steadyRecord given with " + std::to_string(paths.size()) +
                        " NetCDF files: a steady record is one record of one file; give that file alone",
                    "GriddedCurrentOptions::steadyRecord");
    JoinedAxis a;
    for (const std::string &p : paths)
    {
        a.files.push_back(readFileTimes(p, opt));
        // dates of different calendars cannot be ordered: checked before anything is compared
        const FileTimes &f0 = a.files.front(), &q = a.files.back();
        if (q.tv.calendar != f0.tv.calendar)
            throw Error("NetCDF files '" + f0.path + "' and '" + q.path +
                        "' cannot be joined as one forecast: their calendars differ ('" +
                        std::string(calendarName(f0.tv.calendar)) + "' and '" + calendarName(q.tv.calendar) +
                        "', time variables '" + f0.tv.name + "' and '" + q.tv.name + "')");
    }
    std::stable_sort(a.files.begin(), a.files.end(),
                     [](const FileTimes &x, const FileTimes &y) { return x.tv.originSeconds < y.tv.originSeconds; });
    const FileTimes &first = a.files.front();
    a.calendar = first.tv.calendar;
    a.originSeconds = first.tv.originSeconds;
    for (std::size_t i = 1; i < a.files.size(); ++i)
    {
        const FileTimes &p = a.files[i - 1], &q = a.files[i];
        if (!(q.tv.originSeconds > p.tv.originSeconds))
            throw Error("NetCDF files '" + p.path + "' and '" + q.path +
                        "' cannot be joined as one forecast: both begin at " + iso(q.tv.originSeconds, a.calendar) +
                        " (time variables '" + p.tv.name + "' and '" + q.tv.name +
                        "'); expected one file per start time (the same file twice?)");
    }
    for (std::size_t i = 0; i < a.files.size(); ++i)
    {
        const FileTimes &f = a.files[i];
        const double shift = f.tv.originSeconds - a.originSeconds;
        const double next = i + 1 < a.files.size() ? a.files[i + 1].tv.originSeconds - a.originSeconds
                                                   : std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < f.tv.times.size(); ++k)
        {
            const double t = shift + f.tv.times[k];
            if (!(t < next))
            {
                ++a.dropped;
                continue;
            }
            a.times.push_back(t);
            a.file.push_back(i);
            a.index.push_back(k);
        }
    }
    return a;
}

/// The median step of the joined axis (at least 2 records).
double typicalStep(const std::vector<double> &ts)
{
    std::vector<double> d;
    for (std::size_t k = 1; k < ts.size(); ++k)
        d.push_back(ts[k] - ts[k - 1]);
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
    return d[d.size() / 2];
}

/// A gap of more than twice the typical step between two files within the records loaded is refused.
void checkGaps(const JoinedAxis &a, const AxisSelection &sel)
{
    const double step = typicalStep(a.times);
    for (std::size_t q = 1; q < sel.idx.size(); ++q)
    {
        const std::size_t c0 = sel.idx[q - 1], c1 = sel.idx[q];
        if (a.file[c0] == a.file[c1])
            continue;
        const double gap = a.times[c1] - a.times[c0];
        if (gap > 2.0 * step)
            throw Error("NetCDF files '" + a.files[a.file[c0]].path + "' and '" + a.files[a.file[c1]].path +
                            "': a gap of " + hoursText(gap) + " in the forecast within the trip's time window (" +
                            iso(a.originSeconds + a.times[c0], a.calendar) + " in the first, then " +
                            iso(a.originSeconds + a.times[c1], a.calendar) +
                            " in the second), more than twice the forecast's typical step of " + hoursText(step) +
                            ": a file missing? Give it, or choose a departure and horizon that avoid the gap",
                        "GriddedCurrentOptions::departure");
    }
}

template <class T>
std::string firstDifference(const std::vector<T> &a, const std::vector<T> &b, const std::string &what)
{
    if (a.size() != b.size())
        return what + ": " + std::to_string(a.size()) + " values against " + std::to_string(b.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        if (a[k] != b[k])
            return what + " at index " + std::to_string(k) + ": " + text::number(double(a[k])) + " against " +
                   text::number(double(b[k]));
    return "";
}

/// What differs between the loaded grids of two pieces ("" when they agree).
std::string gridDifference(const ForecastPiece &a, const ForecastPiece &b)
{
    const Layout &la = a.layout, &lb = b.layout;
    if (la.geographic != lb.geographic)
        return std::string("coordinates: ") + (la.geographic ? "longitude/latitude" : "Cartesian x/y") + " against " +
               (lb.geographic ? "longitude/latitude" : "Cartesian x/y");
    if (la.curvilinear != lb.curvilinear)
        return std::string("grid: ") + (la.curvilinear ? "curvilinear" : "rectilinear") + " against " +
               (lb.curvilinear ? "curvilinear" : "rectilinear");
    if (la.uName != lb.uName || la.vName != lb.vName)
        return "velocity variables: '" + la.uName + "'/'" + la.vName + "' against '" + lb.uName + "'/'" + lb.vName +
               "'";
    if (a.out.maskVariable != b.out.maskVariable)
        return "land/sea mask variable: " +
               (a.out.maskVariable.empty() ? std::string("none") : "'" + a.out.maskVariable + "'") + " against " +
               (b.out.maskVariable.empty() ? std::string("none") : "'" + b.out.maskVariable + "'");
    if (a.out.tracerVariable != b.out.tracerVariable)
        return "tracer variable marking land: " +
               (a.out.tracerVariable.empty() ? std::string("none") : "'" + a.out.tracerVariable + "'") + " against " +
               (b.out.tracerVariable.empty() ? std::string("none") : "'" + b.out.tracerVariable + "'");
    if (a.g.nx != b.g.nx || a.g.ny != b.g.ny)
        return "nodes in the region: " + std::to_string(a.g.nx) + " x " + std::to_string(a.g.ny) + " against " +
               std::to_string(b.g.nx) + " x " + std::to_string(b.g.ny) + " (x by y)";
    for (const std::string &d :
         {firstDifference(a.z.values, b.z.values, "depth layers (m)"),
          firstDifference(a.h.lon1D, b.h.lon1D, "x/longitude '" + la.xName + "' of the region's nodes"),
          firstDifference(a.h.lat1D, b.h.lat1D, "y/latitude '" + la.yName + "' of the region's nodes"),
          firstDifference(a.h.nodeLon, b.h.nodeLon, "longitude '" + la.xName + "' of the region's nodes"),
          firstDifference(a.h.nodeLat, b.h.nodeLat, "latitude '" + la.yName + "' of the region's nodes"),
          firstDifference(a.g.depth, b.g.depth, "depth layers (m)")})
        if (!d.empty())
            return d;
    return "";
}

bool isPacked(const ForecastPiece &p)
{
    const Packing pu = packingOf(*p.file, p.layout.uVar), pv = packingOf(*p.file, p.layout.vVar);
    return pu.scale != 1.0 || pu.offset != 0.0 || pv.scale != 1.0 || pv.offset != 0.0;
}

} // namespace
} // namespace gridded_detail

bool netCdfIsGeographic(const std::vector<std::string> &paths, const GriddedCurrentOptions &options)
{
    if (paths.empty())
        throw Error("gridded forecast: no file given");
    const bool first = netCdfIsGeographic(paths.front(), options);
    for (std::size_t i = 1; i < paths.size(); ++i)
        if (netCdfIsGeographic(paths[i], options) != first)
            throw Error("NetCDF files '" + paths.front() + "' and '" + paths[i] +
                        "' cannot be joined as one forecast: their coordinates differ (" +
                        (first ? "longitude/latitude" : "Cartesian x/y") + " against " +
                        (first ? "Cartesian x/y" : "longitude/latitude") + ")");
    return first;
}

ForecastTimeAxis readForecastTimeAxis(const std::vector<std::string> &paths, const GriddedCurrentOptions &options)
{
    if (paths.empty())
        throw Error("gridded forecast: no file given");
    if (paths.size() == 1)
        return readForecastTimeAxis(paths.front(), options);
    const gridded_detail::JoinedAxis a = gridded_detail::joinTimeAxes(paths, options);
    ForecastTimeAxis axis;
    axis.found = true;
    axis.steady = false;
    axis.dated = true;
    axis.variable = a.files.front().tv.name;
    axis.calendar = a.calendar;
    axis.originSeconds = a.originSeconds;
    axis.size = a.times.size();
    axis.span = a.times.back() - a.times.front();
    return axis;
}

GriddedCurrents loadGriddedCurrents(const std::vector<std::string> &paths, const GriddedCurrentOptions &opt)
{
    using namespace gridded_detail;
    if (paths.empty())
        throw Error("gridded forecast: no file given");
    if (paths.size() == 1)
        return loadGriddedCurrents(paths.front(), opt);
    const JoinedAxis a = joinTimeAxes(paths, opt);
    const std::string forecast = a.describe();
    // the records the trip needs, chosen on the joined axis exactly as in one file
    GriddedCurrents meta;
    meta.dated = true;
    meta.calendar = a.calendar;
    meta.originSeconds = a.originSeconds;
    const AxisSelection sel = selectForecastTimes(a.times, a.files.front().tv.name, opt, meta,
                                                  [&](const std::string &w) { return Error(forecast + ": " + w); });
    checkGaps(a, sel);
    // per file: its records among them (file indices), with the joined field times; the trip's records in it
    std::vector<std::pair<std::size_t, AxisSelection>> parts;
    for (std::size_t q = 0; q < sel.idx.size(); ++q)
    {
        const std::size_t c = sel.idx[q];
        if (parts.empty() || parts.back().first != a.file[c])
        {
            AxisSelection s;
            s.idx.clear();
            s.values.clear();
            s.tripBegin = 1; // none yet (inTrip() false everywhere)
            s.tripEnd = 0;
            parts.emplace_back(a.file[c], s);
        }
        AxisSelection &s = parts.back().second;
        if (sel.inTrip(q))
        {
            if (s.tripBegin > s.tripEnd)
                s.tripBegin = s.idx.size();
            s.tripEnd = s.idx.size();
        }
        s.idx.push_back(a.index[c]);
        s.values.push_back(a.times[c]);
    }
    // each file read with the same stages and options; zero-velocity land is decided below, on all the records
    GriddedCurrentOptions o = opt;
    o.zeroVelocityLand = false;
    // joined along time as they are read (internal order t, z, y, x: records are appended); land in any file's
    // trip records is land
    ForecastPiece p;
    std::vector<std::string> used;
    bool packed = false;
    std::size_t fileValues = 0;
    for (const auto &[fi, s] : parts)
    {
        const std::string &path = a.files[fi].path;
        ForecastPiece b = readForecastPiece(path, o, &s, sel.idx.size());
        used.push_back(path);
        packed = packed || isPacked(b);
        fileValues += b.out.fileValues;
        if (used.size() == 1)
        {
            p = std::move(b);
            continue;
        }
        const std::string d = gridDifference(p, b);
        if (!d.empty())
            throw Error("NetCDF files '" + used.front() + "' and '" + path +
                        "' cannot be joined as one forecast: their grids in the trip's region differ: " + d);
        p.g.u.insert(p.g.u.end(), b.g.u.begin(), b.g.u.end());
        p.g.v.insert(p.g.v.end(), b.g.v.begin(), b.g.v.end());
        for (std::size_t n = 0; n < p.g.water.size(); ++n)
        {
            p.g.water[n] = p.g.water[n] && b.g.water[n];
            p.fillWater[n] = p.fillWater[n] && b.fillWater[n];
            p.maskWater[n] = p.maskWater[n] && b.maskWater[n];
        }
        p.cornerGrid = p.cornerGrid || b.cornerGrid;
    }
    GriddedData &g = p.g;
    g.time = sel.values;
    p.t = sel;
    GriddedCurrents &out = p.out;
    // each node counted for the first signal that marks it in any file: fill values, the mask, the tracer
    out.fillLandNodes = out.maskLandNodes = out.tracerLandNodes = out.zeroLandNodes = 0;
    for (std::size_t n = 0; n < g.water.size(); ++n)
    {
        out.fillLandNodes += !p.fillWater[n];
        out.maskLandNodes += p.fillWater[n] && !p.maskWater[n];
        out.tracerLandNodes += p.maskWater[n] && !g.water[n];
    }
    out.cornerGrid = p.cornerGrid;
    if (opt.zeroVelocityLand)
    {
        const bool otherLand = out.fillLandNodes + out.maskLandNodes + out.tracerLandNodes > 0;
        out.zeroLandNodes =
            zeroVelocityLand(g, sel, packed, zeroLandRule(*p.file, p.layout, p.h, otherLand, p.cornerGrid));
    }
    out.landNodes = static_cast<std::size_t>(std::count(g.water.begin(), g.water.end(), 0));
    zeroLandVelocities(g); // as in one file: a land node keeps no velocity in any record
    out.dated = true;
    out.steady = false;
    out.calendar = a.calendar;
    out.originSeconds = a.originSeconds;
    out.departureTime = meta.departureTime;
    out.forecastBegin = meta.forecastBegin;
    out.forecastEnd = meta.forecastEnd;
    out.files = used;
    out.droppedRecords = a.dropped;
    out.fileValues = fileValues;
    std::string name = "netcdf:" + used.front();
    for (std::size_t i = 1; i < used.size(); ++i)
        name += "," + used[i];
    return buildForecast(p, opt, name);
}
} // namespace ompl_glider

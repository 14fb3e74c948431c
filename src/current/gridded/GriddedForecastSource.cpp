// The NetCDF reader as a gridded source of the registry (ForecastSource.h): files, a forecast in several files,
// OPeNDAP datasets, and the Zarr stores and GRIB files that GriddedDataset reads through GDAL. The request becomes the
// reader's options; the reader's messages name the settings in the caller's words.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "../../io/NumberText.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace
{
/// The reader's option fields a message may name, and the settings they are.
const std::vector<std::pair<std::string, ForecastOption>> &readerFields()
{
    static const std::vector<std::pair<std::string, ForecastOption>> fields{
        {"uName", ForecastOption::U},
        {"vName", ForecastOption::V},
        {"lonName", ForecastOption::Lon},
        {"latName", ForecastOption::Lat},
        {"depthName", ForecastOption::Depth},
        {"timeName", ForecastOption::Time},
        {"velocityUnits", ForecastOption::VelocityUnits},
        {"timeUnits", ForecastOption::TimeUnits},
        {"steadyRecord", ForecastOption::SteadyRecord},
        {"departure", ForecastOption::Departure},
        {"maxDepth", ForecastOption::MaxDepth},
        {"zeroVelocityLand", ForecastOption::ZeroVelocityLand},
        {"region", ForecastOption::Region},
        {"angleName", ForecastOption::Angle},
        {"maskName", ForecastOption::Mask},
        {"depthAverage", ForecastOption::DepthAverage},
        {"maxSpeed", ForecastOption::MaxSpeed},
        {"runIndex", ForecastOption::Run}};
    return fields;
}

/// The caller's words joined: "current.variables.u/v" where they share all but their last part, else "a/b".
std::string joinNames(const std::vector<std::string> &names)
{
    std::string prefix = names.front().substr(0, names.front().rfind('.') + 1);
    for (const std::string &n : names)
        if (prefix.empty() || n.compare(0, prefix.size(), prefix) != 0 || n.find('.', prefix.size()) != n.npos)
            prefix.clear();
    std::string out;
    for (std::size_t k = 0; k < names.size(); ++k)
        out += (k ? "/" : "") + (k && !prefix.empty() ? names[k].substr(prefix.size()) : names[k]);
    return out;
}

/// The setting at fault of a reader's error ("GriddedCurrentOptions::timeUnits") in the caller's words; as it is
/// when the caller has no name for it.
std::string callerField(const std::string &field, const ForecastRequest &request)
{
    static const std::string tag = "GriddedCurrentOptions::";
    for (const auto &[name, option] : readerFields())
        if (field == tag + name)
            return request.optionName(option, field);
    return field;
}

/// The reader's message with its option fields ("GriddedCurrentOptions::uName/vName") in the caller's words.
std::string callerWords(std::string what, const ForecastRequest &request)
{
    static const std::string tag = "GriddedCurrentOptions::";
    for (std::size_t at = what.find(tag); at != std::string::npos; at = what.find(tag, at + 1))
    {
        // the fields named after the tag, separated by '/'
        std::size_t end = at + tag.size();
        std::vector<std::string> names;
        bool all = true;
        while (true)
        {
            std::size_t stop = end;
            while (stop < what.size() && std::isalnum(static_cast<unsigned char>(what[stop])))
                ++stop;
            const std::string field = what.substr(end, stop - end);
            const auto it = std::find_if(readerFields().begin(), readerFields().end(),
                                         [&](const auto &f) { return f.first == field; });
            const std::string name = it == readerFields().end() ? "" : request.optionName(it->second, "");
            all = all && !name.empty();
            names.push_back(name);
            end = stop;
            if (end + 1 < what.size() && what[end] == '/' && std::isalpha(static_cast<unsigned char>(what[end + 1])))
                ++end;
            else
                break;
        }
        if (all)
            what.replace(at, end - at, joinNames(names));
    }
    return what;
}

GriddedCurrentOptions readerOptions(const ForecastRequest &r)
{
    GriddedCurrentOptions o;
    o.uName = r.variable("u");
    o.vName = r.variable("v");
    o.lonName = !r.variable("lon").empty() ? r.variable("lon") : r.variable("x");
    o.latName = !r.variable("lat").empty() ? r.variable("lat") : r.variable("y");
    o.depthName = r.variable("depth");
    o.timeName = r.variable("time");
    o.maskName = r.variable("mask");
    o.angleName = r.variable("angle");
    o.zeroVelocityLand = r.zeroVelocityLand;
    o.depthAverage = r.depthAverage;
    o.velocityUnits = r.velocityUnits;
    o.maxSpeed = r.maxSpeed;
    o.timeUnits = r.timeUnits;
    o.steadyRecord = r.steadyRecord;
    o.runIndex = r.run;
    o.field.xy = r.xy;
    o.field.depth = r.depth;
    o.field.time = r.time;
    o.field.beyond = r.beyond;
    if (!r.name.empty())
        o.field.name = r.name;
    o.maxDepth = r.maxDepth;
    o.departure = r.departure;
    o.horizon = r.horizon;
    o.lonMin = r.lonMin;
    o.lonMax = r.lonMax;
    o.latMin = r.latMin;
    o.latMax = r.latMax;
    o.refLon = r.refLon;
    o.refLat = r.refLat;
    return o;
}

/// What came from where for one remote source (OPeNDAP, a Zarr store), in the report's words.
std::string remoteNote(const RemoteFetch &f)
{
    const auto bytes = [](std::uint64_t b) {
        return b >= 1000000 ? text::number(b / 1e6, 4) + " MB"
               : b >= 1000  ? text::number(b / 1e3, 4) + " kB"
                            : std::to_string(b) + " B";
    };
    const std::string of = f.kind == RemoteKind::Opendap ? " of values" : " of chunks";
    std::string note = remoteKindName(f.kind) + std::string(" '") + f.source + "': ";
    if (!f.opened)
        note += "read from the cache, no network (" + bytes(f.bytesFromCache) + of + ")";
    else
        note += bytes(f.bytesFetched) + of + " fetched in " + std::to_string(f.requests) + " requests" +
                (f.bytesFromCache > 0 ? ", " + bytes(f.bytesFromCache) + " from the cache" : "");
    if (!f.cacheFile.empty())
        note += f.cacheProblem.empty()
                    ? (f.kind == RemoteKind::ZarrStore ? "; cache folder '" : "; cache file '") + f.cacheFile + "'"
                    : "; the cache file could not be written: " + f.cacheProblem;
    if (!f.cacheIgnored.empty())
        note += " (" + f.cacheIgnored + ")";
    return note;
}

/// What a loaded forecast decided that a pilot should know, one sentence each.
std::vector<std::string> readerNotes(const GriddedCurrents &nc, const ForecastRequest &r)
{
    std::vector<std::string> notes;
    if (!nc.projection && nc.xyMetres != 1.0)
        notes.push_back("x/y (start, goal, region, polygons) are read in the file's axis units (" +
                        text::number(nc.xyMetres) + " m each); the planning frame and the outputs' x/y are metres");
    if (nc.gridAngle.rfind("variable ", 0) == 0)
        notes.push_back("grid angle from the " + nc.gridAngle + " (velocities along the grid turned to east/north)");
    else if (!nc.gridAngle.empty())
        notes.push_back("grid angle " + nc.gridAngle +
                        " (the file has no angle variable and its velocities do not "
                        "say they are eastward/northward)");
    const std::string loaded =
        std::to_string(nc.loadedValues / std::max<std::size_t>(1, nc.loadedShape.empty() ? 1 : nc.loadedShape[0]));
    if (nc.tracerLandNodes > 0)
        notes.push_back(std::to_string(nc.tracerLandNodes) + " of the " + loaded +
                        " nodes loaded are land because the tracer '" + nc.tracerVariable + "' is missing there (" +
                        nc.tracerPlacement + ")");
    if (nc.zeroLandNodes > 0)
        notes.push_back(std::to_string(nc.zeroLandNodes) + " of the " + loaded +
                        " nodes loaded are land only because u = v = 0 in every record of the trip "
                        "(" +
                        r.optionName(ForecastOption::ZeroVelocityLand, "GriddedCurrentOptions::zeroVelocityLand") +
                        " turns this off, taking them as water)");
    for (const RemoteFetch &f : remoteFetchesOf(nc.files)) // OPeNDAP: what came from the network, the cache
        notes.push_back(remoteNote(f));
    return notes;
}

/// What makes land in the forecast, one phrase each.
std::vector<std::string> landCauses(const GriddedCurrents &nc, const ForecastRequest &r)
{
    std::vector<std::string> causes;
    if (nc.fillLandNodes > 0)
        causes.push_back("fill values of '" + nc.uVariable + "'/'" + nc.vVariable + "'");
    if (nc.maskLandNodes > 0)
        causes.push_back("the mask variable '" + nc.maskVariable + "'");
    if (nc.tracerLandNodes > 0)
        causes.push_back("missing values of the tracer '" + nc.tracerVariable + "'" +
                         (nc.cornerGrid ? " (any of the 4 tracer cells around a velocity point)" : ""));
    if (nc.zeroLandNodes > 0)
        causes.push_back("u = v = 0 in every record (" +
                         r.optionName(ForecastOption::ZeroVelocityLand, "GriddedCurrentOptions::zeroVelocityLand") +
                         " turns this off)");
    return causes;
}

class GriddedForecastSource final : public GriddedSource
{
public:
    bool geographic(const ForecastRequest &r) const override
    {
        return guarded(r, [&] { return netCdfIsGeographic(r.files, readerOptions(r)); });
    }
    ForecastExtent extent(const ForecastRequest &r) const override
    {
        return guarded(r, [&] { return readForecastExtent(first(r), readerOptions(r)); });
    }
    ForecastTimeAxis timeAxis(const ForecastRequest &r) const override
    {
        return guarded(r, [&] { return readForecastTimeAxis(r.files, readerOptions(r)); });
    }
    LoadedForecast load(const ForecastRequest &r) const override
    {
        GriddedCurrents nc = guarded(r, [&] { return loadGriddedCurrents(r.files, readerOptions(r)); });
        LoadedForecast f;
        static_cast<ForecastFrame &>(f) = nc;
        f.field = nc.field;
        f.depthLevels = nc.depthAxis;
        f.uVariable = nc.uVariable;
        std::string u = nc.uVariable; // a wind (uwnd, u10, eastward_wind...) is called so on the map
        std::transform(u.begin(), u.end(), u.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
        f.wind = u == "uwnd" || u == "u10" || u.find("wind") != std::string::npos;
        f.notes = readerNotes(nc, r);
        f.landCauses = landCauses(nc, r);
        return f;
    }

private:
    static const std::string &first(const ForecastRequest &r)
    {
        if (r.files.empty())
            throw Error("netcdf: no forecast file given");
        return r.files.front();
    }
    /// The reader's call, its message in the caller's words.
    template <class F> static auto guarded(const ForecastRequest &r, F &&call) -> decltype(call())
    {
        if (r.files.empty())
            throw Error("netcdf: no forecast file given");
        try
        {
            return call();
        }
        catch (const Error &e)
        {
            throw Error(callerWords(e.what(), r), callerField(e.field(), r));
        }
    }
};
} // namespace

std::shared_ptr<const GriddedSource> griddedForecastSource()
{
    static const auto source = std::make_shared<const GriddedForecastSource>();
    return source;
}
} // namespace ompl_glider

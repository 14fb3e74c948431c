/// @file GliderObservations.cpp
/// @brief A glider deployment's DAC records from IOOS profile NetCDF files or a CSV (GliderObservations.h); the entry
/// point of every source (ERDDAP URLs and Slocum dba files: ObservationReaders.h).

#include "ompl_glider/io/GliderObservations.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "CsvCells.h"
#include "GriddedDataset.h"
#include "NumberText.h"
#include "ObservationReaders.h"
#include "PathPattern.h"
#include "TextUtil.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/SlocumBinary.h"
#include "ompl_glider/io/Time.h"

namespace ompl_glider
{
namespace fs = std::filesystem;
using gridded_detail::GriddedDataset;
using observations_detail::dacProblem;
using observations_detail::isDbaFile;
using observations_detail::kFillValue;
using observations_detail::VelocityUnits;

namespace observations_detail
{
VelocityUnits velocityUnits(const std::string &name, const std::string &units, const std::string &where)
{
    VelocityUnits out{units, {}};
    if (text::trim(units).empty())
        return out;
    try
    {
        out.toMetres = velocityToMetresPerSecond(units);
    }
    catch (const Error &e)
    {
        throw Error(where + ": '" + name + "' is in '" + units + "': " + e.what());
    }
    return out;
}

std::string dacProblem(const DacRecord &r, const VelocityUnits &units)
{
    if (!std::isfinite(r.time) || !std::isfinite(r.at.lon) || !std::isfinite(r.at.lat))
        return "no time or position";
    if (std::abs(r.at.lat) > 90.0 || r.at.lon < -180.0 || r.at.lon > 360.0)
        return "position out of range";
    if (!std::isfinite(r.u) || !std::isfinite(r.v))
        return "u or v not a number";
    if (std::hypot(r.u, r.v) > kMaxPlausibleDac)
        return "faster than " + text::number(kMaxPlausibleDac) + " m/s (u, v read " +
               (text::trim(units.units).empty() ? std::string("without units, as m/s") : "in '" + units.units + "'") +
               ")";
    return "";
}

namespace
{
/// The first line of @p file (empty when it cannot be read).
std::string firstLine(const std::string &file)
{
    std::ifstream in(file, std::ios::binary);
    std::string first;
    std::getline(in, first);
    return first;
}
} // namespace

bool isSlocumBinaryFile(const std::string &file)
{
    if (isSlocumBinaryName(file))
        return true;
    if (fs::path(file).extension() == ".dba")
        return false;
    const std::string first = firstLine(file);
    return first.rfind("dbd_label:", 0) == 0 && first.find("DBD(dinkum_binary_data)") != std::string::npos;
}

bool isDbaFile(const std::string &file)
{
    if (fs::path(file).extension() == ".dba")
        return true;
    return !isSlocumBinaryFile(file) && firstLine(file).rfind("dbd_label:", 0) == 0;
}
} // namespace observations_detail

namespace
{
/// The files of @p path: the file, a folder's *.nc files (or its Slocum *.dba files, or its Slocum binary files), or a
/// glob pattern's matches, sorted.
std::vector<std::string> filesOf(const std::string &path)
{
    std::vector<std::string> out;
    std::error_code ec;
    if (fs::is_directory(path, ec))
    {
        std::vector<std::string> kinds[3]; // NetCDF, dba, binary
        const char *const names[3] = {"NetCDF (.nc)", "Slocum dba (.dba)", "Slocum binary (.sbd, .tbd, .scd, ...)"};
        const char *const patterns[3] = {"*.nc", "*.dba", "*.[st]bd"};
        for (const auto &e : fs::directory_iterator(path, ec))
            if (e.is_regular_file())
            {
                static const std::map<std::string, int> byExtension = {{".nc", 0}, {".dba", 1}};
                const std::string f = e.path().string();
                const auto known = byExtension.find(e.path().extension().string());
                const int kind = known != byExtension.end()                   ? known->second
                                 : observations_detail::isSlocumBinaryFile(f) ? 2
                                                                              : -1;
                if (kind >= 0)
                    kinds[kind].push_back(f);
            }
        for (int a = 0; a < 3; ++a)
            for (int b = a + 1; b < 3; ++b)
                if (!kinds[a].empty() && !kinds[b].empty())
                    throw Error("observations '" + path + "': the folder holds both " + names[a] + " and " + names[b] +
                                " files: give a pattern of one kind ('" + (fs::path(path) / patterns[b]).string() +
                                "')");
        for (auto &k : kinds)
            if (!k.empty())
                out = std::move(k);
        if (out.empty())
            throw Error("observations '" + path +
                        "': the folder holds no NetCDF (.nc), Slocum dba (.dba) or Slocum binary (.sbd, .tbd, .dbd, "
                        ".ebd, .scd, ...) file");
    }
    else if (io_detail::hasWildcards(path))
    {
        out = io_detail::matchPattern(path).files;
        if (out.empty())
            throw Error("observations '" + path + "': the pattern matches no file");
    }
    else
    {
        if (!fs::is_regular_file(path, ec))
            throw Error("observations '" + path + "': no such file or folder");
        out.push_back(path);
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// @p fixes in time order, one per time (the first reported of a time kept)
void sortFixes(std::vector<GliderFix> &fixes)
{
    std::stable_sort(fixes.begin(), fixes.end(),
                     [](const GliderFix &a, const GliderFix &b) { return a.time < b.time; });
    fixes.erase(std::unique(fixes.begin(), fixes.end(),
                            [](const GliderFix &a, const GliderFix &b) { return a.time == b.time; }),
                fixes.end());
}

void readCsv(const std::string &file, GliderObservations &o)
{
    std::ifstream in(file);
    if (!in)
        throw Error("observations '" + file + "': cannot open the file");
    std::string line;
    int n = 0;
    char separator = ',';
    std::map<std::string, std::size_t> col;
    VelocityUnits velocity; // of u and v: a header "u (cm/s)" gives the unit, "u" alone is m/s
    while (std::getline(in, line))
    {
        ++n;
        if (line.empty() || line[0] == '#')
            continue;
        if (col.empty() && line.find(',') == std::string::npos && line.find(';') != std::string::npos)
            separator = ';'; // a ';'-separated CSV (a spreadsheet's in a decimal-comma locale)
        const std::vector<std::string> cells = io_detail::csvCells(line, separator);
        if (col.empty())
        {
            std::map<std::string, std::string> units;
            for (std::size_t i = 0; i < cells.size(); ++i)
            {
                std::string name = cells[i];
                if (const std::size_t open = name.rfind('('); open != std::string::npos && name.back() == ')')
                {
                    units[text::trim(name.substr(0, open))] = name.substr(open + 1, name.size() - open - 2);
                    name = text::trim(name.substr(0, open));
                }
                col[name] = i;
            }
            for (const char *k : {"time", "lon", "lat", "u", "v"})
                if (!col.count(k))
                    throw Error(file + ":" + std::to_string(n) +
                                ": the header must name the columns time, lon, lat, "
                                "u, v (missing '" +
                                std::string(k) + "'" +
                                (separator == ';' ? std::string(" in this ';'-separated header") : std::string()) +
                                ")");
            const std::string where = file + ":" + std::to_string(n);
            velocity = observations_detail::velocityUnits("u", units["u"], where);
            if (units["v"] != units["u"])
                throw Error(where + ": 'u' is in '" + units["u"] + "' and 'v' in '" + units["v"] +
                            "': give both in one unit");
            continue;
        }
        const auto cell = [&](const char *k) { return col[k] < cells.size() ? cells[col[k]] : std::string(); };
        const auto number = [&](const char *k) {
            const std::string c = cell(k);
            std::size_t used = 0;
            double v = 0.0;
            try
            {
                v = std::stod(c, &used);
            }
            catch (const std::exception &)
            {
                used = 0;
            }
            if (used != c.size() || c.empty())
                throw Error(file + ":" + std::to_string(n) + ": column '" + k + "': expected a number, got '" + c +
                            "'" +
                            (separator == ';' && c.find(',') != std::string::npos
                                 ? " (a ';'-separated CSV with a decimal comma: write the numbers with a point)"
                                 : ""));
            return v;
        };
        DacRecord r;
        r.file = file;
        const std::string t = cell("time");
        try
        {
            r.time =
                t.find('T') != std::string::npos ? parseIsoTime(t) : number("time"); // a date, or seconds since 1970
        }
        catch (const Error &e)
        {
            throw Error(file + ":" + std::to_string(n) + ": column 'time': " + e.what());
        }
        r.at = {number("lon"), number("lat")};
        if (r.at.lon > 180.0)
            r.at.lon -= 360.0;
        if (!o.lastFix || r.time >= o.lastFix->time)
            o.lastFix = GliderFix{r.time, r.at};
        if (std::isfinite(r.time) && !(o.newestSurfacing >= r.time))
            o.newestSurfacing = r.time;
        if (std::isfinite(r.time) && std::isfinite(r.at.lon) && std::isfinite(r.at.lat))
            o.fixes.push_back(GliderFix{r.time, r.at});
        if (cell("u").empty() && cell("v").empty())
            continue; // a fix without a DAC
        r.u = velocity(number("u"));
        r.v = velocity(number("v"));
        const std::string why = dacProblem(r, velocity);
        if (!why.empty())
        {
            ++o.rejected[why];
            continue;
        }
        o.dac.push_back(r);
    }
    if (col.empty())
        throw Error("observations '" + file + "': empty (a header time,lon,lat,u,v and one row per DAC expected)");
}

/// One IOOS profile file: its DAC (the template's scalars; a file holding several, each variable a list of the same
/// length, gives them all), the reasons of those rejected, its profiles' fixes, its glider.
struct ProfileFile
{
    std::vector<DacRecord> dac;
    std::vector<std::string> rejected;
    std::vector<GliderFix> fixes;
    std::string platform;
};

ProfileFile readProfile(const std::string &file)
{
    const GriddedDataset nc(file);
    ProfileFile p;
    const auto var = [&](const char *name) -> std::optional<int> { return nc.findVar(name); };
    for (const char *name : {"time_uv", "lat_uv", "lon_uv", "u", "v"})
        if (!var(name))
            throw nc.error("variable '" + std::string(name) +
                           "' is missing (an IOOS glider profile file holds the depth-averaged current in time_uv, "
                           "lat_uv, lon_uv, u, v)");
    // a variable's values, NaN where they are fill values
    const auto values = [&](int id) {
        std::vector<double> v = nc.readAll1D(id);
        std::vector<double> fills = nc.attDoubles(id, "_FillValue");
        for (const double m : nc.attDoubles(id, "missing_value"))
            fills.push_back(m);
        if (fills.empty())
            fills.push_back(-999.0);
        for (double &x : v)
            if (std::find(fills.begin(), fills.end(), x) != fills.end())
                x = std::nan("");
        return v;
    };
    // seconds since 1970 of a time variable (CF units)
    const auto seconds = [&](int id) {
        std::vector<double> t = values(id);
        const std::string units = nc.attText(id, "units").value_or("seconds since 1970-01-01T00:00:00Z");
        const CfTimeUnits u = parseCfTimeUnits(units, nc.attText(id, "calendar").value_or("standard"));
        const double epoch1970 = secondsSinceCalendarEpoch(parseDateTime("1970-01-01T00:00:00Z"), u.calendar);
        for (double &x : t)
            x = x * u.secondsPerUnit + u.reference - epoch1970;
        return t;
    };
    // the variables of one record each, all of one length (@p what names them in the error)
    const auto sameLength = [&](const std::vector<std::pair<const char *, std::vector<double>>> &vars,
                                const char *what) {
        const std::size_t n = vars.front().second.size();
        for (const auto &[name, v] : vars)
            if (v.size() != n)
                throw nc.error("the " + std::string(what) + " variables hold lists of different lengths ('" +
                               vars.front().first + "' " + std::to_string(n) + " values, '" + name + "' " +
                               std::to_string(v.size()) + ")");
        return n;
    };
    if (const auto id = var("platform"))
        p.platform = nc.attText(*id, "id").value_or("");
    if (p.platform.empty())
        if (const auto id = var("trajectory");
            id && nc.varType(*id) == gridded_detail::ValueType::Char && nc.varDims(*id).size() == 1)
            p.platform = nc.readChars(*id).c_str(); // up to the first NUL
    if (const auto t = var("profile_time"), la = var("profile_lat"), lo = var("profile_lon"); t && la && lo)
    {
        const std::vector<double> time = seconds(*t), lat = values(*la), lon = values(*lo);
        const std::size_t n =
            sameLength({{"profile_time", time}, {"profile_lat", lat}, {"profile_lon", lon}}, "profile fix");
        for (std::size_t i = 0; i < n; ++i)
            if (std::isfinite(time[i]) && std::isfinite(lon[i]) && std::isfinite(lat[i]))
                p.fixes.push_back(GliderFix{time[i], {lon[i] > 180.0 ? lon[i] - 360.0 : lon[i], lat[i]}});
    }
    const auto units = [&](const char *name) {
        const int id = *var(name);
        return observations_detail::velocityUnits(name, nc.attText(id, "units").value_or(""),
                                                  "NetCDF file '" + file + "'");
    };
    const VelocityUnits velocity = units("u"), velocityV = units("v");
    if (velocityV.toMetres.factor != velocity.toMetres.factor)
        throw nc.error("'u' is in '" + velocity.units + "' and 'v' in '" + velocityV.units +
                       "': give both in one unit");
    const std::vector<double> time = seconds(*var("time_uv")), lon = values(*var("lon_uv")),
                              lat = values(*var("lat_uv")), u = values(*var("u")), v = values(*var("v"));
    const std::size_t n = sameLength({{"time_uv", time}, {"lat_uv", lat}, {"lon_uv", lon}, {"u", u}, {"v", v}}, "DAC");
    // the QC flags: one for the file's records, or one per record
    std::vector<std::pair<const char *, std::vector<double>>> flags;
    for (const char *qc : {"u_qc", "v_qc", "time_uv_qc", "lat_uv_qc", "lon_uv_qc"})
        if (const auto id = var(qc))
        {
            flags.emplace_back(qc, nc.readAll1D(*id));
            if (flags.back().second.size() != 1 && flags.back().second.size() != n)
                throw nc.error("variable '" + std::string(qc) + "' holds " +
                               std::to_string(flags.back().second.size()) + " flags for " + std::to_string(n) +
                               " DAC (one, or one each, expected)");
        }
    // the profile's depth range (the template's `depth`, m positive down), where the file has one
    double depthMin = NAN, depthMax = NAN;
    if (const auto id = var("depth"))
        for (const double z : values(*id))
            if (std::isfinite(z))
            {
                depthMin = std::isnan(depthMin) ? z : std::min(depthMin, z);
                depthMax = std::isnan(depthMax) ? z : std::max(depthMax, z);
            }
    for (std::size_t i = 0; i < n; ++i)
    {
        DacRecord r;
        r.file = file;
        r.depthMin = depthMin;
        r.depthMax = depthMax;
        r.time = time[i];
        r.at = {lon[i] > 180.0 ? lon[i] - 360.0 : lon[i], lat[i]};
        r.u = velocity(u[i]);
        r.v = velocity(v[i]);
        std::string why;
        for (const auto &[qc, f] : flags)
        {
            const double flag = f.empty() ? 0.0 : f[f.size() == 1 ? 0 : i];
            if (why.empty() && (flag == 3.0 || flag == 4.0 || flag == 9.0))
                why = "QC flag " + text::number(flag) + " (" + qc + ")";
        }
        if (why.empty())
            why = !std::isfinite(r.u) || !std::isfinite(r.v) ? kFillValue : dacProblem(r, velocity);
        if (why.empty())
            p.dac.push_back(r);
        else
            p.rejected.push_back(why);
    }
    return p;
}

/// The IOOS profile files @p files (one deployment) into @p o.
void readProfiles(const std::vector<std::string> &files, GliderObservations &o)
{
    std::vector<ProfileFile> profiles;
    std::map<std::string, std::size_t> gliders;
    for (const std::string &f : files)
    {
        profiles.push_back(readProfile(f));
        ++gliders[profiles.back().platform];
    }
    o.platform = observations_detail::mostNamed(gliders, o.source);
    for (const ProfileFile &p : profiles)
    {
        if (p.platform != o.platform)
        {
            o.rejected["another glider ('" + p.platform + "')"] +=
                std::max<std::size_t>(1, p.dac.size() + p.rejected.size());
            continue;
        }
        for (const GliderFix &f : p.fixes)
            o.fixes.push_back(f);
        for (const DacRecord &r : p.dac)
        {
            o.dac.push_back(r);
            o.fixes.push_back(GliderFix{r.time, r.at});
        }
        for (const std::string &why : p.rejected)
            ++o.rejected[why];
    }
}
} // namespace

GliderObservations readGliderObservations(const std::string &path, const ObservationReadOptions &options)
{
    GliderObservations o;
    o.source = withoutCredentials(path);
    std::string variables = "variables u, v"; // where the DAC is, for the message when none is usable
    if (isRemoteSource(path))
    {
#if OMPL_GLIDER_WITH_MISSION
        observations_detail::readErddap(path, o);
#else
        throw Error("observations '" + o.source + "': this build reads no URL (built without GDAL's HTTP client)");
#endif
    }
    else
    {
        const std::vector<std::string> files = filesOf(path);
        o.files = files.size();
        const bool csv = files.size() == 1 && fs::path(files[0]).extension() == ".csv";
        const auto count = [&](bool (*kind)(const std::string &)) {
            return static_cast<std::size_t>(std::count_if(files.begin(), files.end(), kind));
        };
        const std::size_t dba = count(isDbaFile), binary = count(observations_detail::isSlocumBinaryFile);
        if (csv)
            readCsv(files[0], o);
        else if ((dba == files.size() || binary == files.size()) && dba + binary == files.size())
        {
#if OMPL_GLIDER_WITH_MISSION
            observations_detail::readSlocumFiles(files, options.cache, o);
            variables = "sensors m_water_vx, m_water_vy";
#else
            throw Error("observations '" + path +
                        "': this build reads no Slocum dba or binary file (built without the mission layer)");
#endif
        }
        else if (dba + binary > 0)
            throw Error("observations '" + path + "': the pattern matches " +
                        (dba > 0 ? "both Slocum dba files" : "both Slocum binary files") +
                        (dba > 0 && binary > 0 ? " and Slocum binary files" : " and others") +
                        ": give a pattern of one kind");
        else
            readProfiles(files, o);
    }
    std::stable_sort(o.dac.begin(), o.dac.end(),
                     [](const DacRecord &a, const DacRecord &b) { return a.time < b.time; });
    // a record at the time of the one before it is a repeat (a profile file sent twice)
    std::vector<DacRecord> unique;
    for (const DacRecord &r : o.dac)
        if (!unique.empty() && unique.back().time == r.time)
            ++o.rejected["repeated time"];
        else
            unique.push_back(r);
    o.dac = std::move(unique);
    sortFixes(o.fixes);
    if (!o.lastFix && !o.fixes.empty())
        o.lastFix = o.fixes.back(); // the readers of ObservationReaders.h: the latest fix reported
    if (o.dac.empty())
    {
        std::string why;
        for (const auto &[reason, count] : o.rejected)
            why += (why.empty() ? "" : ", ") + std::to_string(count) + " " + reason;
        throw Error("observations '" + o.source + "': no usable depth-averaged current (" + variables +
                    (why.empty() ? std::string(")") : "; rejected: " + why + ")"));
    }
    return o;
}

std::string observationsText(const GliderObservations &o)
{
    std::string s = std::to_string(o.dac.size()) + " DAC from " + std::to_string(o.files) + " file(s)" +
                    (o.platform.empty() ? "" : " of glider '" + o.platform + "'");
    const auto list = [](const std::map<std::string, std::size_t> &counts) {
        std::string out;
        for (const auto &[reason, count] : counts)
            out += (out.empty() ? "" : ", ") + std::to_string(count) + " " + reason;
        return out;
    };
    const std::string why = list(o.rejected), notes = list(o.notes);
    return s + (why.empty() ? "" : "; rejected: " + why) + (notes.empty() ? "" : "; " + notes);
}
} // namespace ompl_glider

// The files of a forecast list: paths, glob patterns, URLs (FileList.h).
#include "ompl_glider/io/FileList.h"

#include <glob.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "PathPattern.h"
#include "TextUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/MemoryDataset.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace
{
/// Why the folder @p path (given as @p item) is no forecast: no Zarr store's metadata in it; what it holds instead
/// (NetCDF or GRIB files: give them; a Zarr v3 store: not read).
std::string folderIsNoStore(const std::string &item, const std::string &path)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    std::size_t netcdf = 0, grib = 0, shown = 0;
    bool v3 = fs::is_regular_file(fs::path(path) / "zarr.json", ec);
    for (fs::directory_iterator it(path, ec), end; !ec && it != end && shown < 100000; it.increment(ec), ++shown)
    {
        const std::string ext = text::lower(it->path().extension().string());
        netcdf += ext == ".nc" || ext == ".nc4" || ext == ".cdf";
        grib += ext == ".grib2" || ext == ".grb2" || ext == ".grib" || ext == ".grb";
    }
    std::string why = "forecast files: '" + item +
                      "' is a folder, not a forecast file nor a Zarr v2 store (it holds "
                      "no .zgroup, .zarray or .zmetadata)";
    const std::string dir = item.empty() || item.back() == '/' ? item : item + "/";
    if (v3)
        return why + "; its zarr.json makes it a Zarr v3 store, which is not read: write it as Zarr v2 (zarr_format=2)";
    if (netcdf > 0)
        return why + "; it holds " + std::to_string(netcdf) +
               " NetCDF file(s): give them as one forecast by a "
               "pattern ('" +
               dir + "*.nc', quoted) or a list of files separated by commas";
    if (grib > 0)
        return why + "; it holds " + std::to_string(grib) +
               " GRIB file(s): give them as one forecast by a pattern "
               "('" +
               dir + "*.grib2', quoted) or a list of files separated by commas";
    return why + "; give the forecast's files (a pattern such as '" + dir + "*.nc', or a list separated by commas)";
}
} // namespace

namespace io_detail
{
PatternMatches matchPattern(const std::string &pattern, std::size_t most)
{
    PatternMatches m;
    glob_t g{};
    m.status = ::glob(pattern.c_str(), 0, nullptr, &g);
    m.count = m.status == 0 ? g.gl_pathc : 0;
    if (m.count <= most)
        for (std::size_t k = 0; k < m.count; ++k)
            m.files.emplace_back(g.gl_pathv[k]);
    globfree(&g);
    return m;
}
} // namespace io_detail

std::vector<std::string> expandForecastFiles(const std::vector<std::string> &items, const std::string &baseDir)
{
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    for (const std::string &item0 : items)
    {
        const std::string item = text::trim(item0);
        if (item.empty())
            throw Error("forecast files: an empty name in the list (expected file names or glob patterns, "
                        "separated by commas)");
        if (isRemoteSource(item) || isMemoryDataset(item) || item.rfind("ZARR:", 0) == 0)
        { // an OPeNDAP URL, a dataset in memory, GDAL's name of a store: one dataset each (io/RemoteSource.h)
            out.push_back(item);
            continue;
        }
        const std::string path =
            baseDir.empty() || fs::path(item).is_absolute() ? item : (fs::path(baseDir) / item).string();
        std::error_code ec;
        if (!io_detail::hasWildcards(item) || fs::is_regular_file(path, ec))
        { // (a file that exists is that file, even when its name holds brackets: a[1].nc)
            if (fs::is_directory(path, ec) && !isZarrStore(path))
                throw Error(folderIsNoStore(item, path));
            out.push_back(path);
            continue;
        }
        // wildcards in the file name only: a pattern reads one directory, never walks a tree
        if (io_detail::hasWildcards(fs::path(item).parent_path().string()))
            throw Error("forecast files: the pattern '" + item +
                        "' has wildcards in its directory; put them in the "
                        "file name only (e.g. forecasts/hycom_*.nc)");
        const std::size_t kMaxFiles = 100000;
        const io_detail::PatternMatches matches = io_detail::matchPattern(path, kMaxFiles);
        if (matches.status == GLOB_NOMATCH)
            throw Error("forecast files: no file matches the pattern '" + path + "'");
        if (matches.status != 0)
            throw Error("forecast files: cannot expand the pattern '" + path + "' (" +
                        (matches.status == GLOB_NOSPACE ? "out of memory" : "a directory cannot be read") + ")");
        if (matches.count > kMaxFiles)
            throw Error("forecast files: the pattern '" + path + "' matches " + std::to_string(matches.count) +
                        " files, more than " + std::to_string(kMaxFiles) + "; narrow it");
        out.insert(out.end(), matches.files.begin(), matches.files.end());
    }
    if (out.empty())
        throw Error("forecast files: none given");
    return out;
}

std::vector<std::string> forecastFileList(const std::string &text, const std::string &baseDir)
{
    std::vector<std::string> items;
    std::size_t from = 0;
    for (std::size_t at = text.find(',');; at = text.find(',', from))
    {
        items.push_back(text.substr(from, at == std::string::npos ? std::string::npos : at - from));
        if (at == std::string::npos)
            break;
        from = at + 1;
    }
    return expandForecastFiles(items, baseDir);
}
namespace
{
bool endsWithLower(const std::string &s, const std::string &tail)
{
    return s.size() >= tail.size() && text::lower(s.substr(s.size() - tail.size())) == tail;
}

bool isHttp(const std::string &s)
{
    return s.rfind("http://", 0) == 0 || s.rfind("https://", 0) == 0;
}
} // namespace

bool isZarrStore(const std::string &path)
{
    std::string p = path;
    while (p.size() > 1 && p.back() == '/')
        p.pop_back();
    if (path.rfind("ZARR:", 0) == 0 || endsWithLower(p, ".zarr"))
        return true;
    if (isHttp(path))
        return false;
    std::error_code ec;
    for (const char *marker : {".zgroup", ".zmetadata", ".zarray"})
        if (std::filesystem::is_regular_file(std::filesystem::path(path) / marker, ec))
            return true;
    return false;
}

bool isGribFile(const std::string &path)
{
    for (const char *ext : {".grib2", ".grb2", ".grib", ".grb"})
        if (endsWithLower(path, ext))
            return true;
    std::error_code ec;
    if (isHttp(path) || !std::filesystem::is_regular_file(path, ec))
        return false;
    char magic[4] = {};
    std::ifstream in(path, std::ios::binary);
    return in.read(magic, 4) && std::memcmp(magic, "GRIB", 4) == 0;
}

DatasetKind datasetKindOf(const std::string &path)
{
    if (isZarrStore(path))
        return DatasetKind::ZarrStore;
    if (isGribFile(path))
        return DatasetKind::GribFile;
    if (isRemoteSource(path))
        return DatasetKind::Opendap;
    if (isMemoryDataset(path))
        return DatasetKind::MemoryDataset;
    return DatasetKind::NetCdfFile;
}

const char *datasetKindName(DatasetKind kind)
{
    switch (kind)
    {
    case DatasetKind::NetCdfFile:
        return "NetCDF file";
    case DatasetKind::Opendap:
        return "OPeNDAP dataset";
    case DatasetKind::MemoryDataset:
        return "in-memory dataset";
    case DatasetKind::ZarrStore:
        return "Zarr store";
    case DatasetKind::GribFile:
        return "GRIB file";
    }
    return "NetCDF file";
}

std::string forecastSourceKind(const std::string &path)
{
    return datasetKindName(datasetKindOf(path));
}
} // namespace ompl_glider

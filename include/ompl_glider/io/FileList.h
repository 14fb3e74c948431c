#pragma once
/// @file FileList.h
/// @brief The files of a forecast given as a list: paths, shell-style patterns, URLs (any gridded source's files).

#include <string>
#include <vector>

namespace ompl_glider
{
/// @brief The files of a list: each item a path, or a shell-style pattern (an item with `*`, `?` or `[`) expanded
/// with glob(3) (its matches in glob's order: by name). Relative items are taken relative to baseDir (empty: as
/// they are). @throws Error for an empty item, a pattern that matches nothing (naming it) or cannot be expanded,
/// and an empty list. Existence of plain paths is not checked. URLs and in-memory datasets are taken as they are.
std::vector<std::string> expandForecastFiles(const std::vector<std::string> &items, const std::string &baseDir = "");

/// @brief expandForecastFiles() of a comma-separated list ("a.nc,b.nc", "hycom_202603*.nc", "a.nc, b_*.nc").
std::vector<std::string> forecastFileList(const std::string &commaSeparated, const std::string &baseDir = "");

/// @brief A Zarr store: a folder holding `.zgroup`, `.zmetadata` or `.zarray`, a name ending in `.zarr` (also as an
/// http(s) URL), or GDAL's `ZARR:` prefix.
bool isZarrStore(const std::string &path);
/// @brief A GRIB file: `.grib2`, `.grb2`, `.grib`, `.grb` (also as a URL), or a file whose first bytes are "GRIB".
bool isGribFile(const std::string &path);

/// @brief What a gridded source is, which says what reads it: NetCDF-C (a file, an OPeNDAP URL, a dataset in memory)
/// or GDAL (a Zarr store, a GRIB file).
enum class DatasetKind
{
    NetCdfFile,    ///< a NetCDF file
    Opendap,       ///< an OPeNDAP dataset: an http(s) URL that is no Zarr store or GRIB file
    MemoryDataset, ///< an in-memory dataset (MemoryDataset.h)
    ZarrStore,     ///< a Zarr store, on disk or over HTTP (isZarrStore())
    GribFile       ///< a GRIB file, on disk or over HTTP (isGribFile())
};
/// @brief The kind of the source @p path: a Zarr store, a GRIB file, an OPeNDAP dataset (another URL), an in-memory
/// dataset, else a NetCDF file.
DatasetKind datasetKindOf(const std::string &path);
/// @brief How the report, summary.json and messages name @p kind: "NetCDF file", "OPeNDAP dataset", "in-memory
/// dataset", "Zarr store", "GRIB file".
const char *datasetKindName(DatasetKind kind);
/// @brief What a forecast source is, as the report and summary.json name it: datasetKindName(datasetKindOf(path)).
std::string forecastSourceKind(const std::string &path);
} // namespace ompl_glider

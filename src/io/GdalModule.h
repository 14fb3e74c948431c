#pragma once
/// @file GdalModule.h
/// @brief Internal to the library (not installed): the library's GDAL part, loaded when first needed.
///
/// Everything the library does with GDAL (Zarr stores and GRIB2 files through GDAL's multidimensional API, GdalGrid.h;
/// coastlines from GIS files and GEOS's check of a polygon, Coastline.h; HTTP requests through GDAL's client for Zarr,
/// GRIB and ERDDAP sources, HttpMirror.h) is built into a module of its own, `libompl_glider_gdal.so`, which sits
/// beside `libompl_glider.so` (in the build folder, and under lib/ where it is installed). The library opens it
/// (dlopen) the first time one of these is asked for. GDAL brings about a hundred shared libraries with it, and
/// loading them took 0.07 s of every process's start (0.15 s with AddressSanitizer): glider_plan, every test, the
/// Python module's import. A run that reads none of these sources, files or polygons now never loads them. A static
/// library (BUILD_SHARED_LIBS=OFF) holds the part itself and GDAL is linked as before.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "ompl_glider/io/Coastline.h"

namespace ompl_glider
{
namespace gridded_detail
{
class Dataset;
struct HttpFailure;

/// True for a source GDAL reads (GdalGrid): a Zarr store (a folder holding `.zgroup`, `.zmetadata` or `.zarray`, a
/// name ending in `.zarr`, also as an http(s) URL, or GDAL's `ZARR:` prefix) or a GRIB file (`.grib2`, `.grb2`,
/// `.grib`, `.grb`, or a file whose first bytes are "GRIB"). Asks no GDAL function (FileList.h's tests).
bool isGdalSource(const std::string &path);
} // namespace gridded_detail

namespace gdal_detail
{
/// The GDAL part's functions, as the module hands them out. Those of the NetCDF component are null in a build
/// without it.
struct EntryPoints
{
    std::vector<LandPolygon> (*readLandPolygons)(const std::string &path, const GeoBox &box,
                                                 std::vector<std::string> *repairs, CoastlineCount *count);
    std::string (*polygonFault)(const std::vector<Point2> &outer, const std::vector<std::vector<Point2>> &holes);
    /// GdalGrid::open()
    std::shared_ptr<gridded_detail::Dataset> (*openGrid)(const std::string &path);
    /// gridded_detail::httpGet() (HttpMirror.h)
    bool (*httpGet)(const std::string &url, std::size_t record, const std::string &who, const std::string &what,
                    std::string &body, gridded_detail::HttpFailure *failure, std::string *validator);
    /// gridded_detail::notDapAnswer() (HttpMirror.h)
    std::string (*notDapAnswer)(const std::string &url);
};

/// The GDAL part: the module loaded on the first call (once per process, from any thread).
/// @throws Error naming the module's file and the loader's reason when it cannot be loaded.
const EntryPoints &gdalPart();

/// The module's implementations (Coastline.cpp), under names of their own: the library's public readLandPolygons()
/// and polygonFault() hand over to them through gdalPart().
std::vector<LandPolygon> readLandPolygons(const std::string &path, const GeoBox &box, std::vector<std::string> *repairs,
                                          CoastlineCount *count);
std::string polygonFault(const std::vector<Point2> &outer, const std::vector<std::vector<Point2>> &holes);
} // namespace gdal_detail
} // namespace ompl_glider

/// The module's one exported entry point: its table of functions (GdalEntryPoints.cpp).
extern "C" const ompl_glider::gdal_detail::EntryPoints *ompl_glider_gdal_entry_points();

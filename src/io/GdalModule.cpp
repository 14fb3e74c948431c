// The library's GDAL part, loaded when first needed (see GdalModule.h).
#include "GdalModule.h"

#include "ompl_glider/Exception.h"
#include "ompl_glider/io/FileList.h"

#ifndef OMPL_GLIDER_GDAL_BUILT_IN
#include <dlfcn.h>

#include <filesystem>
#endif

namespace ompl_glider
{
namespace gridded_detail
{
bool isGdalSource(const std::string &path)
{
    return isZarrStore(path) || isGribFile(path);
}
} // namespace gridded_detail

namespace gdal_detail
{
namespace
{
#ifndef OMPL_GLIDER_GDAL_BUILT_IN
/// The module beside the file this library was loaded from (dladdr of one of its own functions).
const EntryPoints *loadModule()
{
    Dl_info self{};
    if (dladdr(reinterpret_cast<void *>(&gdalPart), &self) == 0 || self.dli_fname == nullptr)
        throw Error("the library's GDAL part (" OMPL_GLIDER_GDAL_MODULE_FILE
                    ": Zarr stores, GRIB2 files, coastline files, polygon checks, ERDDAP) cannot be found: the "
                    "loader does not say which file libompl_glider was loaded from");
    const std::filesystem::path dir = std::filesystem::path(self.dli_fname).parent_path();
    const std::string file =
        (dir.empty() ? std::filesystem::path(".") : dir).string() + "/" OMPL_GLIDER_GDAL_MODULE_FILE;
    void *handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
    {
        const char *why = dlerror();
        throw Error("the library's GDAL part '" + file +
                    "' (Zarr stores, GRIB2 files, coastline files, polygon checks, ERDDAP) cannot be loaded: " +
                    (why ? why : "no reason given") + " (it belongs beside " + self.dli_fname + ")");
    }
    using Get = const EntryPoints *(*)();
    auto get = reinterpret_cast<Get>(dlsym(handle, "ompl_glider_gdal_entry_points"));
    const EntryPoints *points = get ? get() : nullptr;
    if (points == nullptr)
        throw Error("the library's GDAL part '" + file +
                    "' has no entry points: it is not the module of this build of libompl_glider");
    return points;
}
#endif
} // namespace

const EntryPoints &gdalPart()
{
#ifdef OMPL_GLIDER_GDAL_BUILT_IN
    return *ompl_glider_gdal_entry_points();
#else
    // loaded once; a failed load throws and is tried again by the next call
    static const EntryPoints *const points = loadModule();
    return *points;
#endif
}
} // namespace gdal_detail

std::vector<LandPolygon> readLandPolygons(const std::string &path, const GeoBox &box, std::vector<std::string> *repairs,
                                          CoastlineCount *count)
{
    return gdal_detail::gdalPart().readLandPolygons(path, box, repairs, count);
}

std::string polygonFault(const std::vector<Point2> &outer, const std::vector<std::vector<Point2>> &holes)
{
    return gdal_detail::gdalPart().polygonFault(outer, holes);
}
} // namespace ompl_glider

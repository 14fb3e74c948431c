// The GDAL part's table of functions, the one symbol the library looks up in the module (GdalModule.h).
#include "GdalModule.h"

#include "ompl_glider/Config.h"

#if OMPL_GLIDER_WITH_NETCDF
#include "GdalGrid.h"
#include "HttpMirror.h"
#endif

namespace
{
using namespace ompl_glider;

#if OMPL_GLIDER_WITH_NETCDF
std::shared_ptr<gridded_detail::Dataset> openGrid(const std::string &path)
{
    return gridded_detail::GdalGrid::open(path);
}
#endif
} // namespace

extern "C" const gdal_detail::EntryPoints *ompl_glider_gdal_entry_points()
{
#if OMPL_GLIDER_WITH_NETCDF
    static const gdal_detail::EntryPoints points{&gdal_detail::readLandPolygons, &gdal_detail::polygonFault, &openGrid,
                                                 &gridded_detail::httpGet, &gridded_detail::notDapAnswer};
#else
    static const gdal_detail::EntryPoints points{&gdal_detail::readLandPolygons, &gdal_detail::polygonFault, nullptr,
                                                 nullptr, nullptr};
#endif
    return &points;
}

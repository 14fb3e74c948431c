// The process's one lock of NetCDF-C, HDF5 and GDAL's datasets (see DatasetLock.h).
#include "DatasetLock.h"

namespace ompl_glider
{
namespace gridded_detail
{
std::recursive_mutex &libraryMutex()
{
    // never destroyed: a reader closing its dataset at the process's exit still finds it
    static auto *m = new std::recursive_mutex();
    return *m;
}
} // namespace gridded_detail
} // namespace ompl_glider

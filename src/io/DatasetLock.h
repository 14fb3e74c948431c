#pragma once
/// @file DatasetLock.h
/// @brief Internal to the library (not installed): the process's one lock of the libraries that are not thread-safe:
/// NetCDF-C (files, in-memory datasets, OPeNDAP URLs through its DAP client, and HDF5 beneath it) and GDAL's
/// datasets (Zarr stores and GRIB files in GdalGrid, vector files in the coastline reader; GDAL's own netCDF driver
/// calls NetCDF-C too). Every call into NetCDF-C or HDF5, and every use of a GDAL dataset (open, query, read, close),
/// is made holding it, so that any number of threads may plan, each on its own forecast, at once.
///
/// It is recursive: a reader's query may ask another (an error naming its variable), and an OPeNDAP dataset is read
/// under the hold of the file that reads it. Lock order: this lock first. Code that holds another lock of the library
/// (RemoteDataset's, GdalGrid's, a fleet's loading lock excepted: it is taken before) never takes it; the other locks
/// of io/ are taken, if at all, under it, and are released before it. Nothing that holds it waits for Python's GIL
/// (no progress callback is called under it), so the Python module's calls that read files release the GIL first
/// and cannot deadlock with it.
///
/// A blocking request to an OPeNDAP server holds it: another thread's NetCDF or GDAL access waits until the request
/// ends (its time limit, at most the limit times the retries, or a stop request: StopRequest.h, RemoteDataset.h).
/// Planning itself holds no lock: a forecast is read whole into memory before the planners run.

#include <mutex>

namespace ompl_glider
{
namespace gridded_detail
{
/// The mutex itself (one per process).
std::recursive_mutex &libraryMutex();

/// Holds the lock for its scope.
class DatasetLock
{
public:
    DatasetLock() : hold_(libraryMutex()) {}
    DatasetLock(const DatasetLock &) = delete;
    DatasetLock &operator=(const DatasetLock &) = delete;

private:
    std::lock_guard<std::recursive_mutex> hold_;
};
} // namespace gridded_detail
} // namespace ompl_glider

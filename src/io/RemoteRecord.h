#pragma once
/// @file RemoteRecord.h
/// @brief Internal to the library (not installed): the process's record of remote sources (remoteFetches()), kept by
/// RemoteSource.cpp and written by the remote reader (RemoteDataset.cpp); the in-memory datasets (MemoryDataset.h).

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace remote_detail
{
/// A new entry of the record for @p source; its index.
std::size_t newFetchRecord(const std::string &source);
/// The bytes of the in-memory dataset @p name (io/MemoryDataset.h); null when there is none of that name.
std::shared_ptr<const std::string> memoryDataset(const std::string &name);
/// A name for a source's cache file or folder: the URL's host and path in safe characters, then a 64-bit FNV-1a
/// digest of the URL, then @p extension (".nc", ".zarr").
std::string cacheName(const std::string &url, const std::string &extension);
/// Applies @p change to entry @p k under the record's lock.
void updateFetchRecord(std::size_t k, const std::function<void(RemoteFetch &)> &change);
} // namespace remote_detail
} // namespace ompl_glider

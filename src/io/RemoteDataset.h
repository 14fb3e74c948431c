#pragma once
/// @file RemoteDataset.h
/// @brief Internal to the library (not installed): one OPeNDAP dataset as GriddedDataset reads it (io/RemoteSource.h):
/// opened once per process, its requests timed and retried, the values fetched kept in memory and in the cache file.

#include <netcdf.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ompl_glider/io/RemoteSource.h"
#include "ompl_glider/io/TempFolder.h"

namespace ompl_glider
{
namespace gridded_detail
{
/// Sets NetCDF-C's HTTP time limits (an rc file named by NCRCENV_RC: the user's own rc files, then HTTP.TIMEOUT and
/// HTTP.CONNECTTIMEOUT) before the process's first NetCDF access; later calls do nothing (NetCDF-C reads its rc
/// files once). A user who set NCRCENV_RC keeps that file.
void prepareNetcdfAccess(const RemoteAccess &access);
/// The request time limit given to NetCDF-C (whole seconds), 0 before the first NetCDF access or where the user's
/// own NCRCENV_RC file rules.
long requestLimitInForce();

/// "u[0:3][2:40]": the DAP constraint a block answers (inclusive stops).
std::string constraintOf(const std::string &name, const std::vector<std::size_t> &s, const std::vector<std::size_t> &c);
/// A text attribute of @p var in the NetCDF dataset @p ncid ("" when absent or not text).
std::string textAttribute(int ncid, int var, const char *name);

/// One remote dataset: its description read from the cache file when there is one (no network), else from the URL;
/// its values from the cache file, from what this process fetched already, or from the server.
class RemoteDataset
{
public:
    /// The dataset of @p url (with @p access's cache): one per URL and cache folder in the process, opened at the
    /// first call. @throws Error naming the URL when it cannot be opened (after the retries).
    static std::shared_ptr<RemoteDataset> open(const std::string &url, const RemoteAccess &access);
    ~RemoteDataset();
    RemoteDataset(const RemoteDataset &) = delete;
    RemoteDataset &operator=(const RemoteDataset &) = delete;

    /// The NetCDF id whose dimensions, variables and attributes the reader queries: the cache file's, else the URL's.
    int metadataId() const { return cacheId_ >= 0 ? cacheId_ : remoteId_; }
    /// The values of @p var in the block at @p start of @p count (as doubles, as nc_get_vara_double gives them).
    /// @throws Error naming the URL and the variable when the server fails (after the retries).
    void read(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count, double *out);
    /// Writes the cache file anew (all or nothing: a temporary file renamed) when values were fetched since it was
    /// last written; a failure is kept in the fetch record (RemoteFetch), the plan goes on (RemoteCache.cpp).
    void flush();
    /// "OPeNDAP source '<url>'".
    std::string who() const;

private:
    struct Block
    {
        int var{0};
        std::vector<std::size_t> start, count;
        std::vector<double> values; ///< empty for a block held only by the cache file
    };
    RemoteDataset(std::string url, RemoteAccess access, std::size_t record);
    int remoteId();
    /// Where the cache file describes the dataset (before the URL was opened): throws when the URL's dataset is not
    /// the one cached (its dimensions, its coordinates' units and calendars, or the cached coordinate values differ).
    void checkCacheAnswers();
    int attempt(const std::string &what, const std::function<int()> &call);
    std::uint64_t valueBytes(int var, std::size_t values) const;
    void writeCache(const std::string &tmp);

    std::string url_;
    RemoteAccess access_;
    std::size_t record_; ///< index of this dataset's RemoteFetch in the process's record
    std::string cachePath_;
    int remoteId_{-1}, cacheId_{-1};
    std::vector<Block> blocks_;
    bool dirty_{false};
    std::mutex mutex_;
};
} // namespace gridded_detail
} // namespace ompl_glider

#pragma once
/// @file RemoteSource.h
/// @brief Forecasts read from OPeNDAP (DAP2/DAP4) servers, as HYCOM's and NOAA's THREDDS servers publish them: what
/// a request may take, where what was fetched is kept (the cache), and what came from where.
///
/// A forecast given as an http:// or https:// URL is read through NetCDF-C's own DAP client exactly as a file is read
/// (GriddedDataset: the same layouts, units, land and time rules). Only what the reader asks for crosses the network:
/// the dataset's description (DDS and DAS), the coordinate variables, and the hyperslab of the trip's region, levels
/// and records of the velocities and masks, each variable in a few large requests (NetCDF-C itself fetches every
/// variable of at most 4096 values, the coordinates, whole with the first read).

#include <cstdint>
#include <string>
#include <vector>

namespace ompl_glider
{
/// @brief How a remote forecast is fetched.
struct RemoteAccess
{
    /// Folder of the cache; empty: no cache. What is fetched from a URL is kept there as an ordinary NetCDF-4 file
    /// (the dataset's dimensions, variables and attributes; the values fetched, and the DAP constraints they answer
    /// in the global attribute `ompl_glider_fetched`, the URL in `ompl_glider_source`). A later read of the same URL
    /// that the cache holds reads no network, so a plan made ashore can be made again at sea. The cache is never
    /// refreshed: remove its file to fetch a newer forecast published at the same URL.
    std::string cacheDir;
    /// Time limit of every HTTP request (seconds, > 0): NetCDF-C's HTTP.TIMEOUT and HTTP.CONNECTTIMEOUT, set before
    /// the process's first NetCDF access (NetCDF-C reads them once: the first access fixes the limit for the process;
    /// a user's own NCRCENV_RC file is left as it is).
    double requestTimeout{60.0};
    /// Further attempts after a request fails for the network or the server (no answer in time, connection refused,
    /// a server error), 1 s, 2 s, ... apart; never for an answer that the data do not exist (0..10).
    int retries{2};
};

/// @brief Sets how every remote source of the process is fetched from now on (glider_plan's --cache,
/// --request-timeout and --retries; Python's set_remote_access()). The request time limit takes effect only when
/// given before the process's first NetCDF access (NetCDF-C reads it once); the cache and the retries at once.
/// @throws Error for a time limit that is not a number > 0 or retries outside 0..10 (the settings are then unchanged).
void setRemoteAccess(const RemoteAccess &access);

/// @brief The settings in force (the defaults of RemoteAccess until setRemoteAccess()).
RemoteAccess remoteAccess();

/// @brief Fixes NetCDF-C's HTTP time limit to remoteAccess()'s now, before any NetCDF access (the first reader does it
/// otherwise); a later call does nothing.
void prepareRemoteAccess();

/// @brief @p source with the user information of a URL left out ("https://user:password@host/x" gives
/// "https://host/x"), as every output, message and cache file name shows a source: secrets never reach them. Other
/// text is returned as it is.
std::string withoutCredentials(const std::string &source);

/// @brief True when @p source is a URL (http://, https://, NetCDF-C's [mode]http:// prefixes, or GDAL's ZARR:http://
/// of a Zarr store), not a file path.
bool isRemoteSource(const std::string &source);

/// @brief What a remote source is.
enum class RemoteKind
{
    /// a DAP dataset; values in RemoteFetch::bytesFetched/bytesFromCache
    Opendap,
    /// a Zarr store over HTTP; its chunks' bytes as stored, compressed, in bytesFetched/bytesFromCache; its cache a
    /// folder, a copy of the store's consolidated metadata and of the chunks fetched
    ZarrStore,
    GribFile, ///< a GRIB file, fetched whole
    /// a glider's observations (readGliderObservations()): the answer's bytes in bytesFetched; never cached
    Erddap
};

/// @brief "OPeNDAP", "Zarr store", "GRIB file", "ERDDAP": how the report and summary.json name @p kind.
const char *remoteKindName(RemoteKind kind);

/// @brief What was read from one remote source in this process.
struct RemoteFetch
{
    std::string source;              ///< the URL
    std::string cacheFile;           ///< its cache file (empty without a cache)
    std::uint64_t bytesFetched{0};   ///< bytes of values fetched over the network (values x their type's size)
    std::uint64_t bytesFromCache{0}; ///< bytes of values read from the cache file instead
    std::uint64_t requests{0};       ///< data requests sent (opens and reads, retries included)
    bool opened{false};              ///< the URL itself was opened (its description fetched); false: all from cache
    std::string cacheProblem;        ///< why the cache file could not be written (empty when it was, or no cache)
    /// Why a file found at the cache file's place was not used (it names another source, or none): the forecast was
    /// fetched anew and the file replaced; empty otherwise
    std::string cacheIgnored;
    RemoteKind kind{RemoteKind::Opendap}; ///< what the source is (its name: remoteKindName())
};

/// @brief Every remote source read in this process so far, in the order first read.
std::vector<RemoteFetch> remoteFetches();

/// @brief The remote sources among @p sources, as remoteFetches() tells them (sources not read yet are left out).
std::vector<RemoteFetch> remoteFetchesOf(const std::vector<std::string> &sources);
} // namespace ompl_glider

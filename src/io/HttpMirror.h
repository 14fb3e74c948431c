#pragma once
/// @file HttpMirror.h
/// @brief Internal to the library (not installed): sources GDAL reads over HTTP, through a mirror of what was fetched
/// (GdalGrid opens the mirror). A GRIB file is fetched whole, once (FileMirror). A Zarr v2 store (ZarrMirror): its
/// consolidated metadata (`.zmetadata`) and each chunk the reader needs are fetched once, with the process's request
/// time limit and retries (RemoteSource.h), into a folder: the cache's, where a later run reads what it holds without
/// any request, or GDAL's memory (`/vsimem/`) without a cache. A chunk the server does not hold (404) is the array's
/// fill value, as Zarr defines it, and is remembered as absent.
///
/// Each chunk fetched is kept with the server's validator of it (its ETag, else its Last-Modified time and size).
/// Before a cached store is read further from the server, its metadata and the chunks of its one-dimensional arrays
/// (the coordinates) are fetched again and compared, and every chunk the cache holds is asked again (a HEAD request:
/// the same validator, else its bytes fetched and compared; a chunk absent then must be absent still): a store
/// republished at the same URL, its values rewritten under the same metadata included, is refused rather than mixed
/// with the cached one.
///
///  - HttpMirror.cpp    the mirrors: ZarrMirror, FileMirror
///  - HttpRequests.cpp  the requests: httpGet(), httpHead(), notDapAnswer(), keyUrl()

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ompl_glider/io/FileList.h"

namespace ompl_glider
{
namespace gridded_detail
{
/// What the server answered to a request that failed: its HTTP status (0: no answer) and body (a server's own words:
/// ERDDAP's `Error { ... message="..."; }`, an HTML page).
struct HttpFailure
{
    int status{0};
    std::string body;
};

/// GETs @p url with the process's request time limit and retries (RemoteSource.h), counting each request and the
/// bytes in entry @p record of the process's record: its bytes into @p body; false when the server does not hold it
/// (404). @throws Error "<who>: cannot fetch '<what>': <why> (request time limit N s, R retries)" after the retries for
/// the network or the server, and at a stop request. When the request fails (404 included), @p failure (if given)
/// receives the last answer's status and body.
/// @p validator (if given) receives the server's validator of the answer: "ETag <tag>", else "Last-Modified <date>,
/// <size> bytes", else "" (the server gives neither).
bool httpGet(const std::string &url, std::size_t record, const std::string &who, const std::string &what,
             std::string &body, HttpFailure *failure = nullptr, std::string *validator = nullptr);

/// A HEAD request of @p url (one attempt, the request time limit): true and its validator (as httpGet()'s) when the
/// server holds it, false for 404; nullopt when the server gives no usable answer (no HEAD, the network).
std::optional<bool> httpHead(const std::string &url, std::size_t record, std::string &validator);

/// Why the server at @p url is no OPeNDAP (DAP2/DAP4) endpoint, asked once after NetCDF-C failed to open it: its
/// answer to the DAP2 description ("<url>.dds") is an HTML page (a web page, a listing, an error page), or it holds
/// a Zarr store there (its `.zmetadata`, `.zgroup` or `.zarray`); "" when neither (NetCDF-C's own message stands).
/// Never quotes the page.
std::string notDapAnswer(const std::string &url);

/// @p url with @p key appended to its path (before a query string: "https://h/s.zarr?t=1" -> "https://h/s.zarr/k?t=1").
std::string keyUrl(const std::string &url, const std::string &key);

/// A file over HTTP (a GRIB file) fetched whole, once: into the cache folder (a later run reads it there, no
/// request), or GDAL's memory without a cache.
class FileMirror
{
public:
    /// @p extension names the cached copy (".grib2"); @p kind names the source in messages and the record ("GRIB
    /// file", datasetKindName()). @throws Error naming the URL when it cannot be fetched.
    FileMirror(const std::string &url, const std::string &extension, DatasetKind kind);
    ~FileMirror();
    FileMirror(const FileMirror &) = delete;
    FileMirror &operator=(const FileMirror &) = delete;
    /// The local copy GDAL opens.
    const std::string &file() const { return file_; }

private:
    std::string file_;
    bool cached_{false};
};

class ZarrMirror
{
public:
    /// The mirror of the store at @p url: the cache folder's copy when it holds one for this URL, else a new one
    /// (the metadata fetched). @throws Error naming the URL when the metadata cannot be fetched or is not JSON.
    explicit ZarrMirror(const std::string &url);
    ~ZarrMirror();
    ZarrMirror(const ZarrMirror &) = delete;
    ZarrMirror &operator=(const ZarrMirror &) = delete;

    /// The folder GDAL opens.
    const std::string &folder() const { return folder_; }
    /// Makes sure the mirror holds every chunk of the array at @p path ("uo", "grp/uo") covering the block at
    /// @p start of @p count (fetching those it lacks). @throws Error naming the URL and the chunk when one cannot be
    /// fetched, or when the store was republished since the cache was written.
    void ensure(const std::string &path, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count);

private:
    struct Array
    {
        std::vector<std::size_t> shape, chunks;
        std::string separator{"."};
    };
    /// The arrays of the consolidated metadata (its `<path>/.zarray` entries). @throws Error when it has none.
    void readArrays(const std::string &metadata);
    /// The chunks' keys of @p path covering the block.
    std::vector<std::string> keys(const std::string &path, const std::vector<std::size_t> &start,
                                  const std::vector<std::size_t> &count) const;
    /// GETs @p key of the store (httpGet()), its validator kept (validators_).
    bool fetch(const std::string &key, std::string &body);
    /// "" when the cached chunk @p key is the server's still; else what differs.
    std::string chunkChanged(const std::string &key);
    /// The keys of the chunks held in the cache folder (not the store's metadata, not the mirror's own files).
    std::vector<std::string> cachedChunks() const;
    /// Writes the validators of the chunks held (validators_) into the cache folder.
    void storeValidators();
    /// Writes @p bytes at @p key of the mirror (a temporary name renamed: never half a file).
    void store(const std::string &key, const std::string &bytes);
    /// The first time the cache is found short: the server's metadata and coordinate chunks are the cached ones.
    void checkRepublished();
    bool held(const std::string &key) const;
    /// "Zarr store '<url>'" (without credentials): how messages name the store.
    std::string who() const;

    std::string url_, folder_;
    bool cached_{false};    // the folder is the cache's (else GDAL's memory)
    bool fromCache_{false}; // the metadata came from the cache (no request yet)
    bool checked_{false};   // checkRepublished() done
    std::size_t record_{0}; // the source's entry in the process's record (remoteFetches())
    std::map<std::string, Array> arrays_;
    std::string rootKey_, rootText_; // the store's root entry (.zgroup, or .zarray) in the consolidated metadata
    std::set<std::string> absent_;   // keys the server does not hold
    std::set<std::string> seen_;     // keys this process asked for (fetched, or counted as the cache's)
    std::map<std::string, std::string> validators_; // key -> the server's validator when it was fetched
    bool validatorsChanged_{false};
};
} // namespace gridded_detail
} // namespace ompl_glider

// Sources over HTTP through a mirror of what was fetched (see HttpMirror.h): a Zarr store's (ZarrMirror), a GRIB
// file's (FileMirror). The requests themselves: HttpRequests.cpp.
#include "HttpMirror.h"

#include <algorithm>
#include <cctype>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <unistd.h>

#include <cpl_error.h>
#include <cpl_http.h>
#include <cpl_json.h>
#include <cpl_string.h>
#include <cpl_vsi.h>

#include "Dataset.h"
#include "FetchStop.h"
#include "RemoteRecord.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/StopRequest.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
const char *const kMarker = ".ompl_glider_source";         // the URL the mirror holds (without credentials)
const char *const kAbsent = ".ompl_glider_absent";         // keys the server does not hold, one a line
const char *const kValidators = ".ompl_glider_validators"; // "key<TAB>validator" of the chunks held, one a line

bool exists(const std::string &path)
{
    VSIStatBufL st;
    return VSIStatL(path.c_str(), &st) == 0;
}

std::uint64_t sizeOf(const std::string &path)
{
    VSIStatBufL st;
    return VSIStatL(path.c_str(), &st) == 0 ? static_cast<std::uint64_t>(st.st_size) : 0;
}

/// The whole file at @p path; false when it cannot be read.
bool slurp(const std::string &path, std::string &out)
{
    GByte *bytes = nullptr;
    vsi_l_offset size = 0;
    CPLPushErrorHandler(CPLQuietErrorHandler); // a missing file is an answer here, not a message
    const bool read = VSIIngestFile(nullptr, path.c_str(), &bytes, &size, 1ll << 30);
    CPLPopErrorHandler();
    CPLErrorReset();
    if (!read)
        return false;
    out.assign(reinterpret_cast<const char *>(bytes), static_cast<std::size_t>(size));
    VSIFree(bytes);
    return true;
}

/// Writes @p bytes at @p path through a temporary name renamed (never half a file); the folder made first.
void writeWhole(const std::string &path, const std::string &bytes, const std::string &who)
{
    const std::string parent = path.substr(0, path.rfind('/'));
    if (!exists(parent))
        VSIMkdirRecursive(parent.c_str(), 0755);
    // a name of this process and call: two runs filling one cache never write the same temporary file
    static std::atomic<unsigned long> serial{0};
    const std::string part =
        path + ".part" + std::to_string(static_cast<long>(::getpid())) + "-" + std::to_string(++serial);
    VSILFILE *f = VSIFOpenL(part.c_str(), "wb");
    const bool written = f && VSIFWriteL(bytes.data(), 1, bytes.size(), f) == bytes.size();
    const bool closed = f && VSIFCloseL(f) == 0;
    if (!written || !closed || VSIRename(part.c_str(), path.c_str()) != 0)
    {
        VSIUnlink(part.c_str());
        throw Error(who + ": '" + path + "' cannot be written (the disk full, or the folder not writable)");
    }
}

} // namespace

ZarrMirror::ZarrMirror(const std::string &url) : url_(url)
{
    const std::string source = withoutCredentials(url_);
    const std::string name = remote_detail::cacheName(source, ".zarr");
    record_ = remote_detail::newFetchRecord(source);
    remote_detail::updateFetchRecord(record_, [](RemoteFetch &f) { f.kind = RemoteKind::ZarrStore; });
    const RemoteAccess access = remoteAccess();
    if (!access.cacheDir.empty())
    {
        std::error_code ec;
        std::filesystem::create_directories(access.cacheDir, ec);
        if (!std::filesystem::is_directory(access.cacheDir, ec))
            throw Error(who() + ": the cache folder '" + access.cacheDir + "' cannot be made");
        cached_ = true;
        folder_ = (std::filesystem::path(access.cacheDir) / name).string();
        remote_detail::updateFetchRecord(record_, [&](RemoteFetch &f) { f.cacheFile = folder_; });
        std::string held;
        if (exists(folder_ + "/.zmetadata") && slurp(folder_ + "/" + kMarker, held) && held == source)
            fromCache_ = true;
        else if (exists(folder_))
        {
            // another source's folder, or one left half-made: not this store
            const std::string why = "the folder found at the cache's place holds " +
                                    (held.empty() ? std::string("no complete store") : "'" + held + "'") +
                                    ": fetched anew, the folder replaced";
            remote_detail::updateFetchRecord(record_, [&](RemoteFetch &f) { f.cacheIgnored = why; });
            VSIRmdirRecursive(folder_.c_str());
        }
    }
    else
    {
        static std::atomic<int> serial{0};
        folder_ = "/vsimem/ompl_glider_zarr/" + std::to_string(++serial) + "/" + name;
    }
    std::string metadata;
    if (fromCache_)
    {
        if (!slurp(folder_ + "/.zmetadata", metadata))
            throw Error(who() + ": the cache's copy '" + folder_ + "/.zmetadata' cannot be read");
        std::string absent;
        if (slurp(folder_ + "/" + kAbsent, absent))
            for (std::size_t at = 0; at < absent.size();)
            {
                const std::size_t end = std::min(absent.find('\n', at), absent.size());
                if (end > at)
                    absent_.insert(absent.substr(at, end - at));
                at = end + 1;
            }
        std::string lines;
        if (slurp(folder_ + "/" + kValidators, lines))
            for (std::size_t at = 0; at < lines.size();)
            {
                const std::size_t end = std::min(lines.find('\n', at), lines.size());
                const std::size_t tab = lines.find('\t', at);
                if (tab < end)
                    validators_[lines.substr(at, tab - at)] = lines.substr(tab + 1, end - tab - 1);
                at = end + 1;
            }
    }
    else
    {
        if (!fetch(".zmetadata", metadata))
            throw Error(who() + ": the server holds no consolidated metadata ('.zmetadata'); a "
                                "store is read over HTTP by it (zarr.consolidate_metadata() writes it)");
        remote_detail::updateFetchRecord(record_, [](RemoteFetch &f) { f.opened = true; });
    }
    readArrays(metadata);
    if (!fromCache_)
    {
        if (VSIMkdirRecursive(folder_.c_str(), 0755) != 0 && !exists(folder_))
            throw Error(who() + ": the folder '" + folder_ + "' cannot be made");
        store(".zmetadata", metadata);
        // GDAL knows a store by its .zgroup: the consolidated metadata's copy (a store whose root is an array has
        // its .zarray there instead), kept by readArrays()
        if (!rootKey_.empty())
            store(rootKey_, rootText_);
        store(kMarker, source); // last: a folder without it is not taken as this store's
    }
}

ZarrMirror::~ZarrMirror()
{
    if (!cached_)
        VSIRmdirRecursive(folder_.c_str());
}

void ZarrMirror::readArrays(const std::string &metadata)
{
    CPLJSONDocument doc;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const bool parsed = doc.LoadMemory(metadata);
    CPLPopErrorHandler();
    if (!parsed || !doc.GetRoot().GetObj("metadata").IsValid())
        throw Error(who() +
                    ": its '.zmetadata' is not a store's consolidated metadata (it "
                    "begins '" +
                    metadata.substr(0, 40) + "')");
    const CPLJSONObject meta = doc.GetRoot().GetObj("metadata");
    for (const char *root : {".zgroup", ".zarray"})
        if (rootKey_.empty() && meta.GetObj(root).IsValid())
        {
            rootKey_ = root;
            rootText_ = meta.GetObj(root).Format(CPLJSONObject::PrettyFormat::Plain);
        }
    for (const CPLJSONObject &entry : meta.GetChildren())
    {
        const std::string key = entry.GetName();
        if (key != ".zarray" && (key.size() < 8 || key.compare(key.size() - 8, 8, "/.zarray") != 0))
            continue;
        Array a;
        const CPLJSONArray shape = entry.GetArray("shape"), chunks = entry.GetArray("chunks");
        if (!shape.IsValid() || !chunks.IsValid() || shape.Size() != chunks.Size())
            throw Error(who() + ": '" + key + "' has no shape and chunks of one length");
        for (int k = 0; k < shape.Size(); ++k)
        {
            const long long n = shape[k].ToLong(-1), c = chunks[k].ToLong(0);
            if (n < 0 || c <= 0)
                throw Error(who() + ": '" + key + "' has a shape or chunk size that is not a count");
            a.shape.push_back(static_cast<std::size_t>(n));
            a.chunks.push_back(static_cast<std::size_t>(c));
        }
        a.separator = entry.GetString("dimension_separator", ".");
        arrays_[key == ".zarray" ? "" : key.substr(0, key.size() - 8)] = a;
    }
    if (arrays_.empty())
        throw Error(who() + ": its consolidated metadata names no array");
}

std::vector<std::string> ZarrMirror::keys(const std::string &path, const std::vector<std::size_t> &start,
                                          const std::vector<std::size_t> &count) const
{
    const auto it = arrays_.find(path);
    if (it == arrays_.end() || it->second.shape.size() != start.size() || start.size() != count.size())
        throw Error(who() + ": no array '" + path + "' of " + std::to_string(start.size()) +
                    " dimensions in its metadata");
    const Array &a = it->second;
    const std::string prefix = path.empty() ? "" : path + "/";
    if (a.shape.empty())
        return {prefix + "0"};
    std::vector<std::size_t> first(start.size()), last(start.size());
    for (std::size_t d = 0; d < start.size(); ++d)
    {
        if (count[d] == 0)
            return {};
        first[d] = start[d] / a.chunks[d];
        last[d] = (start[d] + count[d] - 1) / a.chunks[d];
    }
    std::vector<std::string> out;
    std::vector<std::size_t> idx = first;
    while (true)
    {
        std::string key = prefix;
        for (std::size_t d = 0; d < idx.size(); ++d)
            key += (d ? a.separator : "") + std::to_string(idx[d]);
        out.push_back(key);
        std::size_t d = idx.size();
        while (d > 0 && idx[d - 1] == last[d - 1])
        {
            idx[d - 1] = first[d - 1];
            --d;
        }
        if (d == 0)
            return out;
        ++idx[d - 1];
    }
}

bool ZarrMirror::held(const std::string &key) const
{
    return absent_.count(key) > 0 || exists(folder_ + "/" + key);
}

void ZarrMirror::ensure(const std::string &path, const std::vector<std::size_t> &start,
                        const std::vector<std::size_t> &count)
{
    bool newAbsent = false;
    std::uint64_t fromCache = 0;
    for (const std::string &key : keys(path, start, count))
    {
        if (held(key))
        {
            if (seen_.insert(key).second && !absent_.count(key))
                fromCache += sizeOf(folder_ + "/" + key); // held before this process asked for it: the cache's
            continue;
        }
        seen_.insert(key);
        if (fromCache_ && !checked_)
            checkRepublished();
        std::string body;
        if (fetch(key, body))
            store(key, body);
        else
        {
            absent_.insert(key); // Zarr: a chunk not written holds the fill value
            newAbsent = true;
        }
    }
    if (fromCache > 0)
        remote_detail::updateFetchRecord(record_, [&](RemoteFetch &f) { f.bytesFromCache += fromCache; });
    if (newAbsent)
    {
        std::string list;
        for (const std::string &key : absent_)
            list += key + "\n";
        store(kAbsent, list);
    }
    if (validatorsChanged_ && cached_)
        storeValidators();
}

void ZarrMirror::storeValidators()
{
    std::string lines;
    for (const auto &[key, validator] : validators_)
        if (!validator.empty() && key.find_first_of("\t\n") == std::string::npos)
            lines += key + "\t" + validator + "\n";
    store(kValidators, lines);
    validatorsChanged_ = false;
}

std::vector<std::string> ZarrMirror::cachedChunks() const
{
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec))
    {
        if (!it->is_regular_file(ec))
            continue;
        const std::string key = fs::relative(it->path(), folder_, ec).generic_string();
        const std::string name = it->path().filename().string();
        // a chunk's key ends in its indices ("uo/0.1.2", "uo/0/1/2"); metadata, the mirror's own files and
        // temporary names do not
        if (!ec && !name.empty() && name.find_first_not_of("0123456789.") == std::string::npos && name[0] != '.')
            out.push_back(key);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string ZarrMirror::chunkChanged(const std::string &key)
{
    const std::string url = keyUrl(url_, key);
    std::string now;
    const auto it = validators_.find(key);
    const std::string cached = it == validators_.end() ? "" : it->second;
    if (absent_.count(key))
    {
        const std::optional<bool> held = httpHead(url, record_, now);
        std::string body;
        if (held ? !*held : !fetch(key, body))
            return "";
        return "the server holds it now, absent when the cache was written";
    }
    if (!cached.empty() && httpHead(url, record_, now).value_or(false) && now == cached)
        return ""; // the same validator: the same bytes
    std::string mine, body;
    if (!slurp(folder_ + "/" + key, mine))
        return "";
    if (!fetch(key, body))
        return "the server no longer holds it";
    if (body == mine)
        return ""; // a new validator, the same bytes (kept by fetch())
    return std::to_string(mine.size()) + " bytes cached" + (cached.empty() ? "" : " (" + cached + ")") + ", " +
           std::to_string(body.size()) + " bytes now" + (validators_[key].empty() ? "" : " (" + validators_[key] + ")");
}

void ZarrMirror::checkRepublished()
{
    checked_ = true;
    const std::string advice = "; remove the cache folder '" + folder_ + "' to plan on the store as it is now";
    std::string now, cached;
    if (!fetch(".zmetadata", now) || !slurp(folder_ + "/.zmetadata", cached) || now != cached)
        throw Error(who() +
                    ": the store was republished since the cache was written (its "
                    "metadata differs from the cache's), and the plan needs chunks the cache does not hold" +
                    advice);
    remote_detail::updateFetchRecord(record_, [](RemoteFetch &f) { f.opened = true; });
    // the coordinates (the one-dimensional arrays) as cached: the same times and positions
    for (const auto &[path, a] : arrays_)
    {
        if (a.shape.size() != 1 || a.shape[0] == 0)
            continue;
        for (const std::string &key : keys(path, {0}, {a.shape[0]}))
        {
            std::string mine;
            if (absent_.count(key) || !slurp(folder_ + "/" + key, mine))
                continue;
            if (!fetch(key, now) || now != mine)
                throw Error(who() +
                            ": the store was republished since the cache was written "
                            "(its chunk '" +
                            key +
                            "' differs from the cache's), and the plan needs chunks the cache "
                            "does not hold" +
                            advice);
        }
    }
    // the values: every chunk the cache holds is the server's still (a store rewritten under the same metadata and
    // coordinates would otherwise be planned on as old chunks beside new ones)
    std::vector<std::string> held = cachedChunks();
    held.insert(held.end(), absent_.begin(), absent_.end());
    for (const std::string &key : held)
        if (const std::string what = chunkChanged(key); !what.empty())
            throw Error(who() +
                        ": the store was republished since the cache was written (its "
                        "chunk '" +
                        key + "' differs from the cache's: " + what +
                        "), and the plan needs chunks the "
                        "cache does not hold: the cached and the new values would be mixed" +
                        advice);
    if (validatorsChanged_)
        storeValidators();
}

FileMirror::FileMirror(const std::string &url, const std::string &extension, DatasetKind kind)
{
    const std::string source = withoutCredentials(url);
    const std::string who = datasetWho(kind, source);
    const std::size_t record = remote_detail::newFetchRecord(source);
    remote_detail::updateFetchRecord(record, [&](RemoteFetch &f) {
        f.kind = kind == DatasetKind::ZarrStore ? RemoteKind::ZarrStore : RemoteKind::GribFile;
    });
    const RemoteAccess access = remoteAccess();
    const std::string name = remote_detail::cacheName(source, extension);
    if (!access.cacheDir.empty())
    {
        std::error_code ec;
        std::filesystem::create_directories(access.cacheDir, ec);
        if (!std::filesystem::is_directory(access.cacheDir, ec))
            throw Error(who + ": the cache folder '" + access.cacheDir + "' cannot be made");
        cached_ = true;
        file_ = (std::filesystem::path(access.cacheDir) / name).string();
        remote_detail::updateFetchRecord(record, [&](RemoteFetch &f) { f.cacheFile = file_; });
        std::string held;
        if (exists(file_) && slurp(file_ + kMarker, held) && held == source)
        {
            // the cache's copy, whole (written by a rename): no request
            remote_detail::updateFetchRecord(record, [&](RemoteFetch &f) { f.bytesFromCache = sizeOf(file_); });
            return;
        }
        if (exists(file_))
        {
            const std::string why = "the file found at the cache's place holds " +
                                    (held.empty() ? std::string("no source name") : "'" + held + "'") +
                                    ": fetched anew, the file replaced";
            remote_detail::updateFetchRecord(record, [&](RemoteFetch &f) { f.cacheIgnored = why; });
        }
    }
    else
    {
        static std::atomic<int> serial{0};
        file_ = "/vsimem/ompl_glider_file/" + std::to_string(++serial) + "/" + name;
    }
    std::string body;
    if (!httpGet(url, record, who, source, body))
        throw Error(who + ": the server holds no such file (HTTP 404)");
    remote_detail::updateFetchRecord(record, [](RemoteFetch &f) { f.opened = true; });
    writeWhole(file_, body, who);
    if (cached_)
        writeWhole(file_ + kMarker, source, who);
}

FileMirror::~FileMirror()
{
    if (!cached_)
        VSIUnlink(file_.c_str());
}

bool ZarrMirror::fetch(const std::string &key, std::string &body)
{
    std::string validator;
    const bool found = httpGet(keyUrl(url_, key), record_, who(), key, body, nullptr, &validator);
    if (found && key.rfind(".z", 0) != 0 && validators_[key] != validator)
    {
        validators_[key] = validator;
        validatorsChanged_ = true;
    }
    return found;
}

std::string ZarrMirror::who() const
{
    return datasetWho(DatasetKind::ZarrStore, withoutCredentials(url_));
}

void ZarrMirror::store(const std::string &key, const std::string &bytes)
{
    writeWhole(folder_ + "/" + key, bytes, who() + (cached_ ? " (the cache folder)" : ""));
}
} // namespace gridded_detail
} // namespace ompl_glider

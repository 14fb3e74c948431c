// The settings of remote (OPeNDAP) sources and the process's record of what came from where (io/RemoteSource.h);
// the reading itself is RemoteDataset.cpp's (NetCDF builds only).
#include "ompl_glider/io/RemoteSource.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "NumberText.h"
#include "RemoteRecord.h"
#include "ompl_glider/Config.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/MemoryDataset.h"
#if OMPL_GLIDER_WITH_NETCDF
#include "RemoteDataset.h"
#endif

namespace ompl_glider
{
namespace
{
std::mutex &recordMutex()
{
    static std::mutex m;
    return m;
}

std::vector<RemoteFetch> &record()
{
    static std::vector<RemoteFetch> r;
    return r;
}

std::mutex &accessMutex()
{
    static std::mutex m;
    return m;
}

RemoteAccess &accessInForce()
{
    static RemoteAccess a;
    return a;
}
} // namespace

namespace remote_detail
{
std::size_t newFetchRecord(const std::string &source)
{
    std::lock_guard<std::mutex> lock(recordMutex());
    record().push_back(RemoteFetch{source, "", 0, 0, 0, false, "", "", RemoteKind::Opendap});
    return record().size() - 1;
}

std::string cacheName(const std::string &url, const std::string &extension)
{
    std::uint64_t h = 1469598103934665603ull;
    for (const unsigned char c : url)
        h = (h ^ c) * 1099511628211ull;
    std::string stem;
    for (std::size_t i = url.find("://") == std::string::npos ? 0 : url.find("://") + 3; i < url.size(); ++i)
    {
        const char c = url[i];
        stem += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') ? c : '_';
    }
    if (stem.size() > 80)
        stem = stem.substr(stem.size() - 80);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return stem + "-" + hex + extension;
}

void updateFetchRecord(std::size_t k, const std::function<void(RemoteFetch &)> &change)
{
    std::lock_guard<std::mutex> lock(recordMutex());
    change(record().at(k));
}
} // namespace remote_detail

void setRemoteAccess(const RemoteAccess &access)
{
    if (!(access.requestTimeout > 0) || !(access.requestTimeout <= 1e6))
        throw Error("the request time limit must be a number of seconds > 0 and at most 1e6 (11.6 days), got " +
                    text::number(access.requestTimeout));
#if OMPL_GLIDER_WITH_NETCDF
    // NetCDF-C reads its time limit once, at the process's first access: a change after it would be ignored
    const long inForce = gridded_detail::requestLimitInForce();
    if (inForce > 0 && std::max(1L, static_cast<long>(std::ceil(access.requestTimeout))) != inForce)
        throw Error("the request time limit is fixed at " + std::to_string(inForce) +
                    " s by the process's first NetCDF access (NetCDF-C reads it once): set it before the first plan");
#endif
    if (access.retries < 0 || access.retries > 10)
        throw Error("retries must be 0..10, got " + std::to_string(access.retries));
    std::lock_guard<std::mutex> lock(accessMutex());
    accessInForce() = access;
}

RemoteAccess remoteAccess()
{
    std::lock_guard<std::mutex> lock(accessMutex());
    return accessInForce();
}

void prepareRemoteAccess()
{
#if OMPL_GLIDER_WITH_NETCDF
    gridded_detail::prepareNetcdfAccess(remoteAccess());
#endif
}

std::string withoutCredentials(const std::string &source)
{
    const std::size_t scheme = source.find("://");
    if (scheme == std::string::npos)
        return source;
    const std::size_t host = scheme + 3;
    const std::size_t end = source.find_first_of("/?#", host);
    const std::size_t at = source.rfind('@', end == std::string::npos ? std::string::npos : end);
    if (at == std::string::npos || at < host)
        return source;
    return source.substr(0, host) + source.substr(at + 1);
}

bool isRemoteSource(const std::string &source)
{
    std::string s = source;
    if (s.rfind("ZARR:", 0) == 0) // GDAL's name of a Zarr store: ZARR:URL, ZARR:"URL"
        s = s.substr(s.size() > 5 && s[5] == '"' ? 6 : 5);
    while (!s.empty() && s.front() == '[') // NetCDF-C's [mode=dap4] / [noprefetch] prefixes
    {
        const std::size_t close = s.find(']');
        if (close == std::string::npos)
            return false;
        s = s.substr(close + 1);
    }
    return s.rfind("http://", 0) == 0 || s.rfind("https://", 0) == 0;
}

namespace
{
std::mutex &memoryMutex()
{
    static std::mutex m;
    return m;
}

std::map<std::string, std::shared_ptr<const std::string>> &memoryDatasets()
{
    static std::map<std::string, std::shared_ptr<const std::string>> d;
    return d;
}
} // namespace

std::string registerMemoryDataset(std::string bytes)
{
    static std::size_t count = 0;
    std::lock_guard<std::mutex> lock(memoryMutex());
    const std::string name = "memory:" + std::to_string(++count);
    memoryDatasets()[name] = std::make_shared<const std::string>(std::move(bytes));
    return name;
}

void releaseMemoryDataset(const std::string &name)
{
    std::lock_guard<std::mutex> lock(memoryMutex());
    memoryDatasets().erase(name);
}

bool isMemoryDataset(const std::string &source)
{
    return source.rfind("memory:", 0) == 0 && source.size() > 7 &&
           source.find_first_not_of("0123456789", 7) == std::string::npos;
}

namespace remote_detail
{
std::shared_ptr<const std::string> memoryDataset(const std::string &name)
{
    std::lock_guard<std::mutex> lock(memoryMutex());
    const auto it = memoryDatasets().find(name);
    return it == memoryDatasets().end() ? nullptr : it->second;
}
} // namespace remote_detail

const char *remoteKindName(RemoteKind kind)
{
    switch (kind)
    {
    case RemoteKind::Opendap:
        return "OPeNDAP";
    case RemoteKind::ZarrStore:
        return "Zarr store";
    case RemoteKind::GribFile:
        return "GRIB file";
    case RemoteKind::Erddap:
        return "ERDDAP";
    }
    return "?";
}

std::vector<RemoteFetch> remoteFetches()
{
    std::lock_guard<std::mutex> lock(recordMutex());
    return record();
}

std::vector<RemoteFetch> remoteFetchesOf(const std::vector<std::string> &sources)
{
    std::vector<RemoteFetch> out;
    // (a record holds the source without its credentials, a store given as ZARR:URL by its URL)
    const auto plain = [](std::string s) {
        if (s.rfind("ZARR:", 0) == 0)
            s = s.substr(5);
        if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
            s = s.substr(1, s.size() - 2);
        return withoutCredentials(s);
    };
    for (const RemoteFetch &f : remoteFetches())
        if (std::any_of(sources.begin(), sources.end(), [&](const std::string &s) { return plain(s) == f.source; }))
            out.push_back(f);
    return out;
}
} // namespace ompl_glider

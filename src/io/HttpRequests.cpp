// Requests over HTTP through GDAL's client (see HttpMirror.h): httpGet() with the process's time limit and
// retries, httpHead(), and notDapAnswer()'s probes of a URL that is no OPeNDAP endpoint.
#include "HttpMirror.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <thread>

#include <cpl_error.h>
#include <cpl_http.h>
#include <cpl_string.h>

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
/// The server's validator of an answer (httpGet()): its ETag, else its Last-Modified time and size; "" without
/// either. @p size: the body's bytes, or -1 for a HEAD answer (its Content-Length then).
std::string validatorOf(char **headers, long long size)
{
    const auto header = [&](const char *name) {
        const char *v = CSLFetchNameValue(headers, name);
        std::string s = v ? v : "";
        while (!s.empty() && (s.back() == '\r' || s.back() == '\n' || s.back() == ' '))
            s.pop_back();
        return s;
    };
    if (const std::string tag = header("ETag"); !tag.empty())
        return "ETag " + tag;
    const std::string modified = header("Last-Modified"), length = header("Content-Length");
    if (modified.empty() || (size < 0 && length.empty()))
        return "";
    return "Last-Modified " + modified + ", " + (size < 0 ? length : std::to_string(size)) + " bytes";
}

std::string limitText()
{
    const RemoteAccess a = remoteAccess();
    return "request time limit " + std::to_string(std::max(1L, std::lround(a.requestTimeout))) + " s, " +
           std::to_string(a.retries) + " retries";
}
} // namespace

std::string keyUrl(const std::string &url, const std::string &key)
{
    const std::size_t q = url.find('?');
    std::string base = url.substr(0, q);
    while (!base.empty() && base.back() == '/')
        base.pop_back();
    return base + "/" + key + (q == std::string::npos ? "" : url.substr(q));
}

bool httpGet(const std::string &url, std::size_t record, const std::string &who, const std::string &what,
             std::string &body, HttpFailure *failure, std::string *validator)
{
    const RemoteAccess a = remoteAccess();
    const std::string limit = std::to_string(std::max(1L, std::lround(a.requestTimeout)));
    const std::string timeout = "TIMEOUT=" + limit, connect = "CONNECTTIMEOUT=" + limit;
    const char *options[] = {timeout.c_str(), connect.c_str(), "MAX_RETRY=0", nullptr};
    std::string why;
    for (int attempt = 0; attempt <= a.retries; ++attempt)
    {
        if (attempt > 0)
        {
            // the pause before the next attempt (1 s, 2 s, ...), cut short by a stop request (Python's Ctrl-C)
            const auto resume = std::chrono::steady_clock::now() + std::chrono::seconds(attempt);
            while (std::chrono::steady_clock::now() < resume && !stopRequested())
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        if (stopRequested())
            throw Error(who + ": stopped while fetching '" + what + "'");
        remote_detail::updateFetchRecord(record, [](RemoteFetch &f) { ++f.requests; });
        CPLPushErrorHandler(CPLQuietErrorHandler);
        CPLHTTPResult *r = nullptr;
        {
            const FetchStopWatch watch(url); // a stop request cuts the request at once (FetchStop.h)
            r = CPLHTTPFetch(url.c_str(), options);
        }
        CPLPopErrorHandler();
        CPLErrorReset();
        if (stopRequested())
        {
            if (r)
                CPLHTTPDestroyResult(r);
            throw Error(who + ": stopped while fetching '" + what + "'");
        }
        const std::string errors = r && r->pszErrBuf ? r->pszErrBuf : "";
        const int curl = r ? r->nStatus : -1;
        int http = 0;
        if (errors.rfind("HTTP error code : ", 0) == 0)
            http = std::atoi(errors.c_str() + 18);
        if (r && curl == 0 && http == 0)
        {
            body.assign(reinterpret_cast<const char *>(r->pabyData), static_cast<std::size_t>(r->nDataLen));
            if (validator)
                *validator = validatorOf(r->papszHeaders, static_cast<long long>(body.size()));
            CPLHTTPDestroyResult(r);
            remote_detail::updateFetchRecord(record, [&](RemoteFetch &f) { f.bytesFetched += body.size(); });
            return true;
        }
        if (failure)
        {
            failure->status = curl == 0 ? http : 0;
            failure->body.assign(r && r->pabyData ? reinterpret_cast<const char *>(r->pabyData) : "",
                                 r && r->pabyData ? static_cast<std::size_t>(r->nDataLen) : 0);
        }
        if (r)
            CPLHTTPDestroyResult(r);
        if (curl == 0 && http == 404)
            return false;
        why = http ? "the server answered HTTP " + std::to_string(http) : errors.empty() ? "no answer" : errors;
        const bool transient = curl != 0 || http >= 500 || http == 408 || http == 429;
        if (!transient)
            break;
    }
    throw Error(who + ": cannot fetch '" + what + "': " + why + " (" + limitText() + ")");
}

std::optional<bool> httpHead(const std::string &url, std::size_t record, std::string &validator)
{
    const std::string limit = std::to_string(std::max(1L, std::lround(remoteAccess().requestTimeout)));
    const std::string timeout = "TIMEOUT=" + limit, connect = "CONNECTTIMEOUT=" + limit;
    const char *options[] = {timeout.c_str(), connect.c_str(), "MAX_RETRY=0", "NO_BODY=YES", nullptr};
    if (stopRequested())
        return std::nullopt;
    remote_detail::updateFetchRecord(record, [](RemoteFetch &f) { ++f.requests; });
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLHTTPResult *r = CPLHTTPFetch(url.c_str(), options);
    CPLPopErrorHandler();
    CPLErrorReset();
    const std::string errors = r && r->pszErrBuf ? r->pszErrBuf : "";
    const int http = errors.rfind("HTTP error code : ", 0) == 0 ? std::atoi(errors.c_str() + 18) : 0;
    std::optional<bool> held;
    if (r && r->nStatus == 0 && http == 0)
    {
        validator = validatorOf(r->papszHeaders, -1);
        held = true;
    }
    else if (r && r->nStatus == 0 && http == 404)
        held = false;
    if (r)
        CPLHTTPDestroyResult(r);
    return held;
}

namespace
{
/// One GET of @p url (one attempt, the request time limit, nothing counted): its HTTP status (0: no answer; 200 for
/// an answer without error), body and content type.
int probe(const std::string &url, std::string &body, std::string &type)
{
    const std::string limit = std::to_string(std::max(1L, std::lround(remoteAccess().requestTimeout)));
    const std::string timeout = "TIMEOUT=" + limit, connect = "CONNECTTIMEOUT=" + limit;
    const char *options[] = {timeout.c_str(), connect.c_str(), "MAX_RETRY=0", nullptr};
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLHTTPResult *r = CPLHTTPFetch(url.c_str(), options);
    CPLPopErrorHandler();
    CPLErrorReset();
    if (!r)
        return 0;
    const std::string errors = r->pszErrBuf ? r->pszErrBuf : "";
    const int status = r->nStatus != 0                              ? 0
                       : errors.rfind("HTTP error code : ", 0) == 0 ? std::atoi(errors.c_str() + 18)
                                                                    : 200;
    body.assign(r->pabyData ? reinterpret_cast<const char *>(r->pabyData) : "",
                r->pabyData ? static_cast<std::size_t>(std::min(r->nDataLen, 65536)) : 0);
    type = r->pszContentType ? r->pszContentType : "";
    CPLHTTPDestroyResult(r);
    return status;
}

bool looksHtml(const std::string &body, const std::string &type)
{
    std::string head;
    for (const char c : body.substr(0, 256))
        head += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::size_t at = head.find_first_not_of(" \t\r\n");
    head = at == std::string::npos ? "" : head.substr(at);
    std::string t;
    for (const char c : type)
        t += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return t.find("html") != std::string::npos || head.rfind("<!doctype html", 0) == 0 || head.rfind("<html", 0) == 0;
}
} // namespace

std::string notDapAnswer(const std::string &given)
{
    std::string url = given;
    while (!url.empty() && url.front() == '[') // NetCDF-C's [mode=dap4] prefixes
    {
        const std::size_t close = url.find(']');
        if (close == std::string::npos)
            return "";
        url = url.substr(close + 1);
    }
    const std::string shown = withoutCredentials(url);
    for (const char *key : {".zmetadata", ".zgroup", ".zarray"})
    {
        std::string body, type;
        if (probe(keyUrl(url, key), body, type) == 200 && !looksHtml(body, type) &&
            body.find_first_not_of(" \t\r\n") != std::string::npos && body[body.find_first_not_of(" \t\r\n")] == '{')
            return std::string("the server holds a Zarr store there (its '") + key +
                   "' found), not an OPeNDAP "
                   "dataset: give it as 'ZARR:" +
                   shown + "' (a store's URL ending in .zarr is read as one)";
    }
    std::string body, type;
    const std::size_t q = url.find('?');
    const std::string ddsUrl = url.substr(0, q) + ".dds" + (q == std::string::npos ? "" : url.substr(q));
    const int status = probe(ddsUrl, body, type);
    if (status == 0 || !looksHtml(body, type))
        return "";
    return "the server answered an HTML page" + (status != 200 ? " (HTTP " + std::to_string(status) + ")" : "") +
           ", not an OPeNDAP description, for '" + withoutCredentials(ddsUrl) +
           "': expected an OPeNDAP (DAP2) "
           "dataset URL (THREDDS dodsC, Hyrax, ERDDAP griddap), a Zarr store's URL ending in .zarr (or given as "
           "ZARR:URL), or a GRIB file's URL ending in .grib2";
}

} // namespace gridded_detail
} // namespace ompl_glider

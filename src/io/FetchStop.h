#pragma once
/// @file FetchStop.h
/// @brief Internal to the library (not installed): a stop request (StopRequest.h: Python's Ctrl-C) that ends a blocking
/// HTTP request within a moment instead of at its time limit. NetCDF-C's DAP client (OPeNDAP) and GDAL's HTTP client
/// run libcurl's transfer to its end and offer no way to abort it; so, while a request is under way, a thread watches
/// for a stop request and then shuts down the process's TCP connections to the request's server (its address and
/// port; Linux: found among /proc/self/fd). The transfer fails at once, and the caller, seeing the stop request,
/// throws "stopped". A request through a proxy (the user's HTTP.PROXY.SERVER, libcurl's http_proxy) is not cut: it
/// ends by its time limit.

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace ompl_glider
{
namespace gridded_detail
{
/// Shuts down this process's TCP connections to the server of @p url (http or https, its port or the scheme's): a
/// transfer on one of them fails at once.
void cutConnectionsTo(const std::string &url);

/// While alive, watches for a stop request (every 20 ms) and then cuts the connections to the server of its URL
/// (cutConnectionsTo(), again every 200 ms while it lives).
class FetchStopWatch
{
public:
    explicit FetchStopWatch(std::string url);
    ~FetchStopWatch();
    FetchStopWatch(const FetchStopWatch &) = delete;
    FetchStopWatch &operator=(const FetchStopWatch &) = delete;

private:
    void watch();

    std::string url_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool done_{false};
    std::thread thread_; // started once the rest is built; none when the system has no thread to spare
};
} // namespace gridded_detail
} // namespace ompl_glider

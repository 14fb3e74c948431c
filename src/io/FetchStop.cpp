// A stop request that ends a blocking HTTP request at once (see FetchStop.h).
#include "FetchStop.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <utility>

#include <arpa/inet.h>
#include <dirent.h>
#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "ompl_glider/StopRequest.h"

namespace ompl_glider
{
namespace gridded_detail
{
namespace
{
/// The host and port of @p url's server ("http://user@host:8080/x" gives host, "8080"; 80 or 443 by its scheme).
std::pair<std::string, std::string> hostAndPort(std::string url)
{
    while (!url.empty() && url.front() == '[' && url.find(']') != std::string::npos) // NetCDF-C's [mode=...] prefixes
        url = url.substr(url.find(']') + 1);
    const std::size_t scheme = url.find("://");
    const std::string port = url.rfind("https", 0) == 0 ? "443" : "80";
    std::string authority = url.substr(scheme == std::string::npos ? 0 : scheme + 3);
    authority = authority.substr(0, authority.find_first_of("/?#"));
    authority = authority.substr(authority.rfind('@') == std::string::npos ? 0 : authority.rfind('@') + 1);
    if (!authority.empty() && authority.front() == '[') // [::1]:8080
    {
        const std::size_t close = authority.find(']');
        const std::string rest = close == std::string::npos ? "" : authority.substr(close + 1);
        return {authority.substr(1, close - 1), rest.size() > 1 && rest[0] == ':' ? rest.substr(1) : port};
    }
    const std::size_t colon = authority.rfind(':');
    if (colon == std::string::npos)
        return {authority, port};
    return {authority.substr(0, colon), authority.substr(colon + 1)};
}

/// True when @p a and @p b are the same TCP endpoint (address and port).
bool sameEndpoint(const sockaddr_storage &a, const sockaddr *b)
{
    if (a.ss_family != b->sa_family)
        return false;
    if (a.ss_family == AF_INET)
    {
        const auto &x = reinterpret_cast<const sockaddr_in &>(a);
        const auto *y = reinterpret_cast<const sockaddr_in *>(b);
        return x.sin_port == y->sin_port && x.sin_addr.s_addr == y->sin_addr.s_addr;
    }
    if (a.ss_family == AF_INET6)
    {
        const auto &x = reinterpret_cast<const sockaddr_in6 &>(a);
        const auto *y = reinterpret_cast<const sockaddr_in6 *>(b);
        return x.sin6_port == y->sin6_port && std::memcmp(&x.sin6_addr, &y->sin6_addr, sizeof x.sin6_addr) == 0;
    }
    return false;
}
} // namespace

/// Shuts down this process's TCP connections to the server of @p url (its resolved addresses and port): a transfer
/// on one of them fails at once. Linux: the connections are found among /proc/self/fd.
void cutConnectionsTo(const std::string &url)
{
    const auto [host, port] = hostAndPort(url);
    addrinfo hints{};
    hints.ai_socktype = SOCK_STREAM;
    addrinfo *found = nullptr;
    if (host.empty() || ::getaddrinfo(host.c_str(), port.c_str(), &hints, &found) != 0)
        return;
    DIR *dir = ::opendir("/proc/self/fd");
    if (!dir)
    {
        ::freeaddrinfo(found);
        return;
    }
    for (const dirent *e; (e = ::readdir(dir)) != nullptr;)
    {
        const int fd = std::atoi(e->d_name);
        int type = 0;
        socklen_t len = sizeof type;
        sockaddr_storage peer{};
        socklen_t peerLen = sizeof peer;
        if (e->d_name[0] < '0' || e->d_name[0] > '9' || fd == ::dirfd(dir) ||
            ::getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &len) != 0 || type != SOCK_STREAM ||
            ::getpeername(fd, reinterpret_cast<sockaddr *>(&peer), &peerLen) != 0)
            continue;
        for (const addrinfo *a = found; a; a = a->ai_next)
            if (sameEndpoint(peer, a->ai_addr))
            {
                ::shutdown(fd, SHUT_RDWR);
                break;
            }
    }
    ::closedir(dir);
    ::freeaddrinfo(found);
}

FetchStopWatch::FetchStopWatch(std::string url) : url_(std::move(url))
{
    try
    {
        thread_ = std::thread([this] { watch(); });
    }
    catch (const std::system_error &)
    {
        // no thread to spare (ulimit -u): the request is not watched, and ends by its time limit
    }
}

FetchStopWatch::~FetchStopWatch()
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        done_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable())
        thread_.join();
}

void FetchStopWatch::watch()
{
    std::unique_lock<std::mutex> lock(mutex_);
    while (!done_)
    {
        if (stopRequested())
        {
            lock.unlock();
            cutConnectionsTo(url_); // again every 200 ms, should the client connect anew
            lock.lock();
            wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return done_; });
        }
        else
            wake_.wait_for(lock, std::chrono::milliseconds(20), [this] { return done_; });
    }
}
} // namespace gridded_detail
} // namespace ompl_glider

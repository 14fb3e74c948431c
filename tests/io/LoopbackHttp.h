#pragma once
// A small HTTP/1.1 server of the tests on 127.0.0.1 (a free port): each GET is answered by the test's handler (status,
// body, an optional delay before answering), one thread per connection; the server stops (and its delays are cut
// short) when it goes out of scope. Also: a port where nothing listens.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace loopback_test
{
struct Request
{
    std::string path;  // before '?', as sent
    std::string query; // after '?', percent-decoded
};

struct Response
{
    int status{200};
    std::string body;
    std::string contentType{"text/plain"};
    double delaySeconds{0.0};
};

/// "%3E" -> ">", "+" stays.
inline std::string percentDecoded(const std::string &s)
{
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(s[i + 2])))
        {
            out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
            i += 2;
        }
        else
            out += s[i];
    return out;
}

class Server
{
public:
    using Handler = std::function<Response(const Request &)>;

    explicit Server(Handler handler) : handler_(std::move(handler))
    {
        fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
        int one = 1;
        ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        a.sin_port = 0;
        socklen_t len = sizeof a;
        if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr *>(&a), sizeof a) != 0 || ::listen(fd_, 16) != 0 ||
            ::getsockname(fd_, reinterpret_cast<sockaddr *>(&a), &len) != 0)
            throw std::runtime_error("loopback server: cannot listen on 127.0.0.1");
        port_ = ntohs(a.sin_port);
        accepter_ = std::thread([this] { acceptLoop(); });
    }
    ~Server()
    {
        stop_ = true;
        accepter_.join();
        for (std::thread &t : workers_)
            t.join();
        ::close(fd_);
    }
    Server(const Server &) = delete;
    Server &operator=(const Server &) = delete;

    std::string url(const std::string &pathAndQuery) const
    {
        return "http://127.0.0.1:" + std::to_string(port_) + pathAndQuery;
    }
    int requests() const { return requests_; }
    std::vector<Request> received() const
    {
        std::lock_guard<std::mutex> lock(mutex_);
        return received_;
    }

private:
    void acceptLoop()
    {
        while (!stop_)
        {
            pollfd p{fd_, POLLIN, 0};
            if (::poll(&p, 1, 20) <= 0)
                continue;
            const int c = ::accept(fd_, nullptr, nullptr);
            if (c >= 0)
                workers_.emplace_back([this, c] { serve(c); });
        }
    }

    void serve(int c)
    {
        std::string in;
        char buf[4096];
        while (in.find("\r\n\r\n") == std::string::npos && !stop_)
        {
            pollfd p{c, POLLIN, 0};
            if (::poll(&p, 1, 20) <= 0)
                continue;
            const ssize_t n = ::recv(c, buf, sizeof buf, 0);
            if (n <= 0)
                break;
            in.append(buf, static_cast<std::size_t>(n));
        }
        const std::size_t sp1 = in.find(' '), sp2 = in.find(' ', sp1 + 1);
        if (sp1 == std::string::npos || sp2 == std::string::npos)
        {
            ::close(c);
            return;
        }
        const std::string target = in.substr(sp1 + 1, sp2 - sp1 - 1);
        Request r;
        r.path = target.substr(0, target.find('?'));
        if (target.find('?') != std::string::npos)
            r.query = percentDecoded(target.substr(target.find('?') + 1));
        ++requests_;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            received_.push_back(r);
        }
        const Response a = handler_(r);
        const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(a.delaySeconds);
        while (std::chrono::steady_clock::now() < until && !stop_)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        const std::string head = "HTTP/1.1 " + std::to_string(a.status) + " Answer\r\nContent-Type: " + a.contentType +
                                 "\r\nContent-Length: " + std::to_string(a.body.size()) +
                                 "\r\nConnection: close\r\n\r\n";
        const std::string out = head + a.body;
        for (std::size_t sent = 0; sent < out.size() && !stop_;)
        {
            const ssize_t n = ::send(c, out.data() + sent, out.size() - sent, MSG_NOSIGNAL);
            if (n <= 0)
                break;
            sent += static_cast<std::size_t>(n);
        }
        ::close(c);
    }

    Handler handler_;
    int fd_{-1};
    int port_{0};
    std::atomic<bool> stop_{false};
    std::atomic<int> requests_{0};
    std::thread accepter_;
    std::vector<std::thread> workers_; // joined by the destructor (only the accepter adds to it)
    mutable std::mutex mutex_;
    std::vector<Request> received_;
};

/// A port of 127.0.0.1 where nothing listens (bound, then closed): a server that is down.
inline int closedPort()
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof a;
    ::bind(fd, reinterpret_cast<sockaddr *>(&a), sizeof a);
    ::getsockname(fd, reinterpret_cast<sockaddr *>(&a), &len);
    ::close(fd);
    return ntohs(a.sin_port);
}
} // namespace loopback_test

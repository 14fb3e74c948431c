#pragma once
// The tests' DAP2 server (dap2_server.py beside this header) as a C++ test starts it: serving a folder on 127.0.0.1
// until the object goes.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

extern char **environ;

namespace dap_test
{
/// The tests' DAP2 server (tests/opendap/dap2_server.py) serving @p root on 127.0.0.1, stopped at scope exit; started
/// at once (Debian's python3 with netCDF4), waited for by url().
class DapServer
{
public:
    /// @p log: a file the server appends one JSON line per request to ("": none).
    explicit DapServer(const std::string &root, const std::string &log = "") : portFile_(root + "/../port")
    {
        const std::string script = std::string(OMPL_GLIDER_SOURCE_DIR) + "/tests/opendap/dap2_server.py";
        const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
        std::vector<std::string> args{python, script,        "--root",  root,         "--port",
                                      "0",    "--port-file", portFile_, "--lifetime", "300"};
        if (!log.empty())
        {
            args.push_back("--log");
            args.push_back(log);
        }
        std::vector<char *> argv;
        for (std::string &a : args)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        if (::posix_spawnp(&pid_, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
            throw std::runtime_error("cannot start " + python + " " + script);
    }
    ~DapServer()
    {
        ::kill(pid_, SIGTERM);
        ::waitpid(pid_, nullptr, 0);
    }
    std::string url(const std::string &name)
    {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        while (port_ == 0 && !std::filesystem::exists(portFile_))
        {
            if (std::chrono::steady_clock::now() > deadline || ::waitpid(pid_, nullptr, WNOHANG) == pid_)
                throw std::runtime_error("the DAP2 server did not start (python3 with netCDF4 needed)");
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        if (port_ == 0)
            std::ifstream(portFile_) >> port_;
        return "http://127.0.0.1:" + std::to_string(port_) + "/" + name;
    }

private:
    std::string portFile_;
    pid_t pid_{0};
    int port_{0};
};

} // namespace dap_test

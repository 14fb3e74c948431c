#pragma once
/// @file FuzzUtil.h
/// @brief What the fuzz targets share: an empty temporary directory made once per process (the working directory
/// of the mission fuzzer, the home of the NetCDF fuzzer's input file) and the quiet OMPL log.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <ompl/util/Console.h>

namespace ompl_glider_fuzz
{
/// @brief Makes an empty directory /tmp/<prefix>.XXXXXX (TMPDIR when set), removed with its contents at exit.
inline const std::string &scratchDirectory(const char *prefix)
{
    static std::string dir;
    if (!dir.empty())
        return dir;
    const char *tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/" + prefix + ".XXXXXX";
    if (!mkdtemp(pattern.data()))
    {
        std::perror("mkdtemp");
        std::abort();
    }
    dir = std::filesystem::canonical(pattern).string();
    std::atexit([] {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    });
    return dir;
}

/// @brief OMPL's messages off: a fuzzer runs millions of inputs.
inline void quietOmpl()
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
}
} // namespace ompl_glider_fuzz

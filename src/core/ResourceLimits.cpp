// The memory limit of a planning run (ResourceLimits.h), a top-level header every layer may use: the forecast
// reader and the lattice ask it before they allocate.
#include "ompl_glider/ResourceLimits.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace
{
double fromEnvironment(const char *text)
{
    char *end = nullptr;
    double v = std::strtod(text, &end);
    if (end != text)
    {
        // the bytes of a suffix (binary multiples); an unknown suffix scales to 0, refused below
        static const std::map<std::string, double> scales = {{"", 1.0},
                                                             {"K", 1024.0},
                                                             {"k", 1024.0},
                                                             {"M", 1024.0 * 1024.0},
                                                             {"G", 1024.0 * 1024.0 * 1024.0},
                                                             {"T", 1024.0 * 1024.0 * 1024.0 * 1024.0}};
        const auto it = scales.find(end);
        const double scale = it == scales.end() ? 0.0 : it->second;
        v *= scale;
        if (scale > 0.0 && std::isfinite(v) && v >= 1.0 && v < 1e19)
            return v;
    }
    throw Error(std::string("environment variable OMPL_GLIDER_MEMORY_LIMIT: expected a byte count such as "
                            "4000000000 or 4G, got '") +
                text + "'");
}
} // namespace

std::size_t memoryLimitBytes()
{
    if (const char *text = std::getenv("OMPL_GLIDER_MEMORY_LIMIT"))
        return static_cast<std::size_t>(fromEnvironment(text));
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
    double limit = pages > 0 && pageSize > 0 ? 0.5 * static_cast<double>(pages) * static_cast<double>(pageSize)
                                             : 2.0 * 1024.0 * 1024.0 * 1024.0;
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
        limit = std::min(limit, 0.75 * static_cast<double>(as.rlim_cur));
    return static_cast<std::size_t>(limit);
}

std::string formatBytes(double bytes)
{
    const char *units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
    int u = 0;
    while (bytes >= 1000.0 && u < 6)
    {
        bytes /= 1000.0;
        ++u;
    }
    char text[64];
    std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
    return text;
}

void checkMemory(double bytes, const std::string &what, const std::string &hint)
{
    const double limit = static_cast<double>(memoryLimitBytes());
    if (!(bytes <= limit))
        throw Error(what + " needs about " + formatBytes(bytes) + " of memory, more than the limit of " +
                    formatBytes(limit) +
                    " (half the physical memory, three quarters of the address-space limit ulimit -v, or "
                    "OMPL_GLIDER_MEMORY_LIMIT): " +
                    hint);
}
} // namespace ompl_glider

/// @file InputDigest.cpp
/// @brief The digest of a mission's inputs (InputDigest.h).

#include "ompl_glider/mission/InputDigest.h"

#include <fstream>
#include <string>
#include <vector>

namespace ompl_glider
{
namespace
{
struct Fnv
{
    std::uint64_t h{1469598103934665603ULL};
    void add(const char *p, std::size_t n)
    {
        for (std::size_t i = 0; i < n; ++i)
        {
            h ^= static_cast<unsigned char>(p[i]);
            h *= 1099511628211ULL;
        }
    }
    void add(const std::string &s)
    {
        add(s.data(), s.size());
        add("\0", 1);
    }
};

/// The size, head and tail of the file (all of it when it is short; its path when it cannot be read): its contents,
/// not where it lies (each node of a job may keep its copy elsewhere).
void addFile(Fnv &d, const std::string &path, bool whole)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
    {
        d.add(path);
        return;
    }
    const std::streamoff size = in.tellg();
    d.add(std::to_string(size));
    constexpr std::streamoff kPiece = 64 * 1024;
    std::vector<char> buf;
    const auto read = [&](std::streamoff from, std::streamoff n) {
        buf.resize(static_cast<std::size_t>(n));
        in.seekg(from);
        in.read(buf.data(), n);
        d.add(buf.data(), static_cast<std::size_t>(in.gcount()));
    };
    if (whole || size <= 2 * kPiece)
        read(0, size);
    else
    {
        read(0, kPiece);
        read(size - kPiece, kPiece);
    }
}

void addSource(Fnv &d, const CurrentSpec &c)
{
    d.add(c.type);
    for (const std::string &f : c.forecastFiles())
        addFile(d, f, false);
    for (const std::string &f : c.runs) // a forecast's runs (the first is also `file`)
        addFile(d, f, false);
    if (c.runIndex) // the run of a file of several
        d.add(std::to_string(*c.runIndex));
    for (const CurrentSpec &m : c.members)
        addSource(d, m);
}
} // namespace

std::uint64_t inputDigest(const MissionSpec &spec)
{
    Fnv d;
    if (!spec.file.empty())
        addFile(d, spec.file, true);
    addSource(d, spec.current);
    if (spec.execution.truth)
        addSource(d, *spec.execution.truth);
    for (const std::string *f :
         {&spec.dive.bathymetryFile, &spec.safety.bathymetry, &spec.forbidden.coastline, &spec.forbidden.geojson})
        if (!f->empty())
            addFile(d, *f, false);
    return d.h;
}
} // namespace ompl_glider

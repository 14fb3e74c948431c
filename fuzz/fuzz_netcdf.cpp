// Fuzz target: the NetCDF forecast reader. Bytes -> a temporary file -> loadGriddedCurrents() with the default options
// and with a small region (about the centre of the grid when the file loads, else a fixed lon/lat box), then a few
// queries (velocity, Jacobian, inWater, maxSpeed) at the centre of the loaded grid, and readForecastTimeAxis().
// ompl_glider::Error is the expected answer to a bad file; any other exception, a crash, a sanitizer report, a hang,
// or a non-finite velocity at a point the field calls water is a finding.
//
// Resources: OMPL_GLIDER_MEMORY_LIMIT is 256M in this process, so a header that announces a huge grid is refused
// by the reader's own check (ResourceLimits.h); run it with -rss_limit_mb=2048 (scripts/run_fuzzers.sh does).
//
// NetCDF-C 4.9 allocates (and zero-fills past the end of the file) whatever a classic header announces: a 640-byte
// file can ask for gigabytes (an attribute of 2^28 values, a variable of 2^30 dimensions). Such files are a known
// limitation of NetCDF-C, reported once (see the report of the fuzzing run) and skipped here (absurdClassicHeader())
// so that the fuzzer keeps looking at the reader.
//
// Leaks: NetCDF-C and HDF5 leak on their own error paths when nc_open() fails on a corrupt file (there is no handle
// to close). The harness opens the file itself first; when that fails, the reader runs with leak detection off, so
// a leak is only a finding for files NetCDF-C opens, where closing them is the reader's job.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include <netcdf.h>
#include "gridded/GriddedInternal.h"
#include "FuzzUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"

namespace
{
using namespace ompl_glider;

std::string gFile; // the input, written for the reader

/// The bytes of the classic (CDF-1, CDF-2, CDF-5) header read in order, for absurdClassicHeader().
class HeaderWalk
{
public:
    HeaderWalk(const std::uint8_t *data, std::size_t size) : data_(data), size_(size) {}
    std::size_t remaining() const { return size_ - at_; }
    /// A big-endian integer of @p bytes bytes; false past the end.
    bool integer(int bytes, std::uint64_t &v)
    {
        if (remaining() < static_cast<std::size_t>(bytes))
            return false;
        v = 0;
        for (int i = 0; i < bytes; ++i)
            v = v << 8 | data_[at_++];
        return true;
    }
    /// Skips @p n bytes rounded up to 4; false past the end.
    bool skip(std::uint64_t n)
    {
        n = (n + 3) / 4 * 4;
        if (n > remaining())
            return false;
        at_ += n;
        return true;
    }

private:
    const std::uint8_t *data_;
    std::size_t size_, at_{0};
};

/// True when a classic header announces more than the file can hold (a list, a name, an attribute's values or a
/// variable's dimensions longer than the rest of the file): NetCDF-C would allocate that size. A header cut short
/// within sane sizes is not absurd (the reader reports it).
bool absurdClassicHeader(const std::uint8_t *data, std::size_t size)
{
    if (size < 4 || data[0] != 'C' || data[1] != 'D' || data[2] != 'F')
        return false;
    const int version = data[3];
    const int big = version == 5 ? 8 : 4; // NON_NEG
    HeaderWalk h(data + 4, size - 4);
    std::uint64_t v = 0, tag = 0, n = 0;
    // a count of items that each take at least one byte; sets absurd when the rest of the file is shorter
    bool absurd = false;
    auto count = [&](std::uint64_t &c) {
        if (!h.integer(big, c))
            return false;
        absurd = absurd || c > h.remaining();
        return !absurd;
    };
    auto name = [&]() { return count(n) && h.skip(n); };
    auto attributes = [&]() {
        if (!h.integer(4, tag) || !count(n))
            return false;
        for (std::uint64_t a = n, i = 0; i < a; ++i)
        {
            std::uint64_t type = 0, values = 0;
            if (!name() || !h.integer(4, type) || !h.integer(big, values))
                return false;
            static const int kSize[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
            const std::uint64_t bytes = type >= 1 && type <= 11 ? kSize[type] : 1;
            absurd = absurd || values > h.remaining() / bytes;
            if (absurd || !h.skip(values * bytes))
                return false;
        }
        return true;
    };
    if (!h.integer(big, v) || !h.integer(4, tag) || !count(n)) // numrecs, dimensions
        return absurd;
    for (std::uint64_t d = n, i = 0; i < d; ++i)
        if (!name() || !h.integer(big, v))
            return absurd;
    if (!attributes() || !h.integer(4, tag) || !count(n)) // global attributes, variables
        return absurd;
    for (std::uint64_t vars = n, i = 0; i < vars; ++i)
    {
        std::uint64_t ndims = 0;
        if (!name() || !count(ndims))
            return absurd;
        for (std::uint64_t k = 0; k < ndims; ++k)
            if (!h.integer(big, v))
                return absurd;
        if (!attributes() || !h.integer(4, v) || !h.integer(big, v) || !h.integer(version == 1 ? 4 : 8, v))
            return absurd;
    }
    return absurd;
}

} // namespace

// LeakSanitizer's interface, weak: a fuzzer built without AddressSanitizer (OMPL_GLIDER_BUILD_FUZZERS alone) has no
// leak checker to switch off, and links
extern "C" __attribute__((weak)) void __lsan_disable();
extern "C" __attribute__((weak)) void __lsan_enable();

namespace
{
/// Leak detection off for the life of the object (allocations made meanwhile are never reported).
struct LeaksIgnored
{
    LeaksIgnored()
    {
        if (__lsan_disable)
            __lsan_disable();
    }
    ~LeaksIgnored()
    {
        if (__lsan_enable)
            __lsan_enable();
    }
};

/// True when NetCDF-C opens the file (it is closed again); a failed open's leaks are ignored. A classic file the
/// reader refuses before opening it (truncated, or a header that breaks the format: NetCDF-C divides by zero on a
/// type it does not know in a CDF-1 header) is not handed to NetCDF-C here either.
bool netCdfOpens(const std::string &path)
{
    if (ompl_glider::gridded_detail::classicTruncation(path))
        return false;
    const LeaksIgnored ignored;
    int id = 0;
    if (nc_open(path.c_str(), NC_NOWRITE, &id) != NC_NOERR)
        return false;
    nc_close(id);
    return true;
}

/// Queries at the centre of the loaded grid (and at its first and middle time): none may crash; in water, the
/// velocity must be finite.
void probe(const GriddedCurrents &nc)
{
    const GriddedCurrentField &field = *nc.field;
    const Region e = field.extent();
    const double x = 0.5 * (e.xMin + e.xMax), y = 0.5 * (e.yMin + e.yMax), z = e.zMin;
    const double t0 = field.timeBegin();
    const double t1 = std::isfinite(e.tMax) ? 0.5 * (t0 + e.tMax) : t0;
    for (const double t : {t0, t1, nc.departureTime})
    {
        const bool water = field.inWater(x, y, z);
        const Velocity v = field.velocity(x, y, z, t);
        (void)field.jacobian(x, y, z, t);
        if (water && !(std::isfinite(v.u) && std::isfinite(v.v)))
        {
            std::fprintf(stderr, "fuzz_netcdf: velocity (%g, %g) at (%g, %g, %g, %g), a point in water\n", v.u, v.v, x,
                         y, z, t);
            std::abort();
        }
    }
    (void)field.segmentInWater(e.xMin, e.yMin, e.xMax, e.yMax, z);
    (void)field.maxSpeed(e);
    (void)nc.toGeographic({x, y});
}

/// Loads with @p o and probes; Error is the expected failure. Returns the loaded forecast's centre in the file's
/// coordinates (lon/lat, or x/y in Cartesian files) through @p a, @p b when it loaded.
bool load(const GriddedCurrentOptions &o, double &a, double &b)
{
    try
    {
        const GriddedCurrents nc = loadGriddedCurrents(gFile, o);
        probe(nc);
        const Region e = nc.field->extent();
        const LonLat c = nc.toGeographic({0.5 * (e.xMin + e.xMax), 0.5 * (e.yMin + e.yMax)});
        a = c.lon;
        b = c.lat;
        return nc.geographic;
    }
    catch (const Error &)
    {
        a = b = std::nan("");
        return false;
    }
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
    setenv("OMPL_GLIDER_MEMORY_LIMIT", "256M", 1);
    gFile = ompl_glider_fuzz::scratchDirectory("fuzz_netcdf") + "/fuzz.nc";
    ompl_glider_fuzz::quietOmpl();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (absurdClassicHeader(data, size))
        return -1; // not added to the corpus
    {
        std::ofstream out(gFile, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
        if (!out)
            std::abort();
    }
    std::optional<LeaksIgnored> ignored;
    if (!netCdfOpens(gFile))
        ignored.emplace();
    try
    {
        (void)readForecastTimeAxis(gFile);
    }
    catch (const Error &)
    {
    }
    double a = 0.0, b = 0.0;
    const bool geographic = load(GriddedCurrentOptions{}, a, b);
    // A small region: 0.2 degrees about the centre of a geographic grid, 1 unit about a Cartesian one, or a fixed
    // lon/lat box when the whole file did not load (the subset code sees the file then).
    GriddedCurrentOptions o;
    const double half = std::isfinite(a) && std::isfinite(b) ? (geographic ? 0.1 : 0.5) : 0.0;
    if (half > 0.0)
    {
        o.lonMin = a - half;
        o.lonMax = a + half;
        o.latMin = b - half;
        o.latMax = b + half;
    }
    else
    {
        o.lonMin = -53.0;
        o.lonMax = -52.0;
        o.latMin = 47.0;
        o.latMax = 48.0;
    }
    load(o, a, b);
    return 0;
}

// The size check of classic-format files (CDF-1, CDF-2, CDF-5; src/io/ClassicSize.cpp): the header
// parsed to the end of the last non-record variable and of the last record, complete files accepted, files cut
// in the header, in the fixed data and in the last record refused with the byte counts, and loadGriddedCurrents()
// refusing a cut forecast that NetCDF-C would read as if complete.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "TestNetCdfUtil.h"
#include "gridded/GriddedInternal.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/current/GriddedCurrents.h"

using namespace ompl_glider;
using namespace ompl_glider::gridded_detail;
using glider_test::NcWriter;
using glider_test::TempDir;

namespace
{
constexpr std::size_t kRecords = 5;

/// Fixed variables lat(3) double, lon(4) double, s(4) short (64 bytes) and record variables time double and
/// u(time, lat, lon) float (56 bytes per record), kRecords records, no attributes.
void writeClassic(const std::string &path, int mode)
{
    NcWriter w(path, NC_CLOBBER | mode);
    const int dt = w.dim("time", NC_UNLIMITED), dy = w.dim("lat", 3), dx = w.dim("lon", 4);
    const int vy = w.var("lat", NC_DOUBLE, {dy}), vx = w.var("lon", NC_DOUBLE, {dx}), vs = w.var("s", NC_SHORT, {dx});
    const int vt = w.var("time", NC_DOUBLE, {dt}), vu = w.var("u", NC_FLOAT, {dt, dy, dx});
    w.enddef();
    w.put(vy, {1, 2, 3});
    w.put(vx, {1, 2, 3, 4});
    w.put(vs, {1, 2, 3, 4});
    const std::size_t start[3] = {0, 0, 0}, count[3] = {kRecords, 3, 4};
    const std::vector<double> t(kRecords, 1.0), u(kRecords * 12, 0.5);
    NCW_CHECK(nc_put_vara_double(w.id(), vt, start, count, t.data()));
    NCW_CHECK(nc_put_vara_double(w.id(), vu, start, count, u.data()));
}

/// The header size of writeClassic()'s file by the format specification: NON_NEG is 8 bytes in CDF-5, else 4;
/// OFFSET 4 bytes in CDF-1, else 8; names padded to 4 bytes; empty lists 4 + NON_NEG bytes.
std::uint64_t expectedHeaderBytes(int version)
{
    const std::uint64_t nn = version == 5 ? 8 : 4, off = version == 1 ? 4 : 8;
    const std::uint64_t name = nn + 4; // every name here has at most 4 characters
    const std::uint64_t list = 4 + nn; // tag and nelems (or ABSENT)
    const std::uint64_t dims = list + 3 * (name + nn);
    // per variable: name, ndims, dimids, empty attribute list, type, vsize, begin
    auto var = [&](std::uint64_t ndims) { return name + nn + ndims * nn + list + 4 + nn + off; };
    const std::uint64_t vars = list + var(1) + var(1) + var(1) + var(1) + var(3);
    return 4 + nn + dims + list + vars;
}

std::uint64_t fileSize(const std::string &path)
{
    return std::filesystem::file_size(path);
}

/// A copy of the first n bytes of `from`.
std::string cut(const TempDir &tmp, const std::string &from, std::uint64_t n, const std::string &name)
{
    const std::string to = tmp.file(name);
    std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(to, n);
    return to;
}

ClassicExtent extentOf(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    return classicExtent(in, fileSize(path));
}

std::string declared(std::uint64_t data, std::uint64_t end, std::uint64_t size)
{
    return "is truncated: its header declares " + std::to_string(data) + " bytes of data ending at byte " +
           std::to_string(end) + ", the file has " + std::to_string(size) + " bytes (" + std::to_string(end - size) +
           " missing)";
}
} // namespace

TEST(NetCdfClassicSize, CompleteFilesOfEachClassicFormatPass)
{
    TempDir tmp;
    for (const auto &[mode, version] : {std::pair<int, int>{0, 1}, {NC_64BIT_OFFSET, 2}, {NC_64BIT_DATA, 5}})
    {
        SCOPED_TRACE(version);
        const std::string path = tmp.file("complete" + std::to_string(version) + ".nc");
        writeClassic(path, mode);
        const ClassicExtent e = extentOf(path);
        EXPECT_EQ(e.version, version);
        EXPECT_FALSE(e.headerCut);
        EXPECT_FALSE(e.streaming);
        EXPECT_EQ(e.headerEnd, expectedHeaderBytes(version));
        EXPECT_GE(e.dataBegin, e.headerEnd);
        EXPECT_EQ(e.fixedEnd, e.dataBegin + 64);            // lat, lon, s contiguous
        EXPECT_EQ(e.recordEnd, fileSize(path));             // NetCDF-C sizes the file to the last record
        EXPECT_GE(e.recordEnd, e.fixedEnd + kRecords * 56); // 56 bytes per record after the fixed data
        EXPECT_EQ(e.dataEnd(), fileSize(path));
        EXPECT_FALSE(classicTruncation(path)) << *classicTruncation(path);
        // longer than declared is fine
        const std::string longer = cut(tmp, path, fileSize(path) + 100, "longer.nc");
        EXPECT_FALSE(classicTruncation(longer));
    }
}

TEST(NetCdfClassicSize, FilesCutInTheHeaderFixedDataOrLastRecordAreRefusedWithTheByteCounts)
{
    TempDir tmp;
    for (const auto &[mode, version] : {std::pair<int, int>{0, 1}, {NC_64BIT_OFFSET, 2}, {NC_64BIT_DATA, 5}})
    {
        SCOPED_TRACE(version);
        const std::string path = tmp.file("whole" + std::to_string(version) + ".nc");
        writeClassic(path, mode);
        const ClassicExtent whole = extentOf(path);
        const std::uint64_t size = fileSize(path), data = size - whole.dataBegin;
        // in the header: only what is there is known
        for (std::uint64_t n : {std::uint64_t(6), std::uint64_t(40), whole.headerEnd - 1})
        {
            const std::string c = cut(tmp, path, n, "header.nc");
            EXPECT_TRUE(extentOf(c).headerCut);
            EXPECT_EQ(classicTruncation(c).value_or(""),
                      "is truncated or corrupt: it ends inside its header, after " + std::to_string(n) +
                          " bytes (or its header declares more values than the file holds)");
        }
        // in the fixed data, in the last record, and one byte short
        for (std::uint64_t n : {whole.dataBegin + 10, size - 30, size - 1})
        {
            const std::string c = cut(tmp, path, n, "data.nc");
            EXPECT_EQ(classicTruncation(c).value_or(""), declared(data, size, n));
        }
    }
}

TEST(NetCdfClassicSize, OneShortRecordVariableIsUnpaddedAndPaddingAloneIsNotMissingData)
{
    TempDir tmp;
    // one record variable of 3 shorts: records of 6 bytes without padding
    const std::string one = tmp.file("one.nc");
    {
        NcWriter w(one, NC_CLOBBER);
        const int dt = w.dim("time", NC_UNLIMITED), dx = w.dim("x", 3);
        const int r = w.var("r", NC_SHORT, {dt, dx});
        w.enddef();
        const std::size_t start[2] = {0, 0}, count[2] = {4, 3};
        const std::vector<double> v(12, 7.0);
        NCW_CHECK(nc_put_vara_double(w.id(), r, start, count, v.data()));
    }
    ClassicExtent e = extentOf(one);
    EXPECT_EQ(e.recordEnd, e.dataBegin + 4 * 6);
    EXPECT_EQ(e.recordEnd, fileSize(one));
    // two such variables: records of 2 x 8 bytes; the last record's final 2 bytes are padding
    const std::string two = tmp.file("two.nc");
    {
        NcWriter w(two, NC_CLOBBER);
        const int dt = w.dim("time", NC_UNLIMITED), dx = w.dim("x", 3);
        const int r = w.var("r", NC_SHORT, {dt, dx}), q = w.var("q", NC_SHORT, {dt, dx});
        w.enddef();
        const std::size_t start[2] = {0, 0}, count[2] = {4, 3};
        const std::vector<double> v(12, 7.0);
        NCW_CHECK(nc_put_vara_double(w.id(), r, start, count, v.data()));
        NCW_CHECK(nc_put_vara_double(w.id(), q, start, count, v.data()));
    }
    e = extentOf(two);
    EXPECT_EQ(e.recordEnd, e.dataBegin + 8 + 3 * 16 + 6);
    EXPECT_EQ(fileSize(two), e.recordEnd + 2);
    EXPECT_FALSE(classicTruncation(cut(tmp, two, fileSize(two) - 2, "pad.nc")));
    EXPECT_EQ(classicTruncation(cut(tmp, two, fileSize(two) - 3, "short.nc")).value_or(""),
              declared(e.recordEnd - e.dataBegin, e.recordEnd, fileSize(two) - 3));
}

TEST(NetCdfClassicSize, StreamingRecordCountSkipsTheRecordsAndOtherFilesAreNotChecked)
{
    TempDir tmp;
    const std::string path = tmp.file("stream.nc");
    writeClassic(path, 0);
    const ClassicExtent whole = extentOf(path);
    {
        std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(4);
        f.write("\xFF\xFF\xFF\xFF", 4); // numrecs = STREAMING
    }
    const std::string c = cut(tmp, path, whole.fixedEnd + 4, "streamcut.nc");
    const ClassicExtent e = extentOf(c);
    EXPECT_TRUE(e.streaming);
    EXPECT_EQ(e.recordEnd, 0u);
    EXPECT_FALSE(classicTruncation(c));
    // ... but the fixed data are still checked
    EXPECT_TRUE(classicTruncation(cut(tmp, path, whole.fixedEnd - 1, "streamfixed.nc")));

    // netCDF-4, text, a missing file, two bytes of a magic number: not classic, not checked
    const std::string nc4 = tmp.file("nc4.nc");
    {
        NcWriter w(nc4);
        w.dim("x", 3);
    }
    EXPECT_EQ(extentOf(nc4).version, 0);
    EXPECT_FALSE(classicTruncation(nc4));
    std::istringstream text("hello, world\n");
    EXPECT_EQ(classicExtent(text, 13).version, 0);
    EXPECT_FALSE(classicTruncation(tmp.file("missing.nc")));
    EXPECT_FALSE(classicTruncation(cut(tmp, path, 2, "two.nc")));
}

TEST(NetCdfClassicSize, LoaderRefusesACutClassicForecast)
{
    TempDir tmp;
    const std::string cdl = tmp.file("f.cdl"), nc = tmp.file("f.nc");
    {
        std::ofstream f(cdl);
        f << "netcdf f {\ndimensions: time = UNLIMITED ; lat = 3 ; lon = 4 ;\nvariables:\n"
             "  double time(time) ; time:units = \"hours since 2026-03-15 00:00:00\" ;\n"
             "  double lat(lat) ; lat:units = \"degrees_north\" ;\n"
             "  double lon(lon) ; lon:units = \"degrees_east\" ;\n"
             "  float u(time, lat, lon) ; u:units = \"m s-1\" ; u:standard_name = \"eastward_sea_water_velocity\" ;\n"
             "  float v(time, lat, lon) ; v:units = \"m s-1\" ; v:standard_name = \"northward_sea_water_velocity\" ;\n"
             "data:\n  time = 0, 24, 48 ;\n  lat = 47.0, 47.2, 47.4 ;\n  lon = -53.0, -52.8, -52.6, -52.4 ;\n"
             "  u = ";
        for (int k = 0; k < 36; ++k)
            f << (k ? ", " : "") << "0.1";
        f << " ;\n  v = ";
        for (int k = 0; k < 36; ++k)
            f << (k ? ", " : "") << "0";
        f << " ;\n}\n";
    }
    // CDF-2 (ncgen -k nc6: 64-bit offset)
    ASSERT_EQ(std::system(("ncgen -k nc6 -o " + nc + " " + cdl).c_str()), 0);
    ASSERT_EQ(extentOf(nc).version, 2);
    EXPECT_NO_THROW(loadGriddedCurrents(nc));
    // cut halfway through the data
    const std::uint64_t size = fileSize(nc), begin = extentOf(nc).dataBegin, half = begin + (size - begin) / 2;
    const std::string c = cut(tmp, nc, half, "half.nc");
    std::string m;
    try
    {
        loadGriddedCurrents(c);
    }
    catch (const Error &e)
    {
        m = e.what();
    }
    EXPECT_EQ(m.rfind("NetCDF file '" + c + "' is truncated: its header declares ", 0), 0u) << m;
    EXPECT_NE(m.find("ending at byte " + std::to_string(size) + ", the file has " + std::to_string(half) + " bytes (" +
                     std::to_string(size - half) + " missing)"),
              std::string::npos)
        << m;
    // the time axis alone is refused too
    EXPECT_THROW(readForecastTimeAxis(c), Error);
    // cut inside the header (NetCDF-C may open it or not): truncated either way
    for (std::uint64_t n : {std::uint64_t(12), std::uint64_t(100)})
    {
        const std::string h = cut(tmp, nc, n, "head.nc");
        try
        {
            loadGriddedCurrents(h);
            ADD_FAILURE() << "loaded a file cut at " << n << " bytes";
        }
        catch (const Error &e)
        {
            EXPECT_NE(std::string(e.what()).find("is truncated or corrupt: it ends inside its header, after " +
                                                 std::to_string(n) + " bytes"),
                      std::string::npos)
                << e.what();
        }
    }
}

/// @file SlocumBinary.cpp
/// @brief The reader of a Slocum glider's binary files, "dinkum binary data" ([DinkumBinary]; SlocumBinary.h): the
/// ASCII header, the sensor list (in the file or a cache file), the known bytes and their byte order, the data cycles,
/// the LZ4 frames of the compressed files.

#include "ompl_glider/io/SlocumBinary.h"

#include <lz4.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "TextUtil.h"
#include "ompl_glider/Exception.h"

namespace ompl_glider
{
namespace fs = std::filesystem;

namespace
{
/// The encoding versions this reader knows: 1 (bytes, int16, floats), 2 (doubles added), 3, 4 (the sensor list
/// factored out into a cache file), 5.
constexpr long kFirstVersion = 1, kLastVersion = 5;
/// The largest an LZ4 block of at most 65535 bytes decompresses to (LZ4 expands at most 255 times).
constexpr std::size_t kMaxLz4Block = 65535u * 255u;

using text::lower;

std::string upper(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
}

std::string hex(unsigned char c)
{
    const char *digits = "0123456789abcdef";
    return {digits[c >> 4], digits[c & 15]};
}

std::string extensionOf(const std::string &file)
{
    const std::string e = fs::path(file).extension().string();
    return e.empty() ? e : lower(e.substr(1));
}

std::string readBytes(const std::string &file, const std::string &what)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw Error(what + " '" + file + "': cannot open the file");
    return std::string(std::istreambuf_iterator<char>(in), {});
}

long countOf(const std::string &text)
{
    char *end = nullptr;
    const long n = std::strtol(text.c_str(), &end, 10);
    return end != text.c_str() && *end == '\0' && n >= 0 && n < 1000000 ? n : -1;
}

/// Reads the text lines of @p bytes from @p at on (each up to '\n'); @p what names the source in the messages.
struct LineReader
{
    const std::string &bytes;
    std::string what;
    std::size_t at{0};
    int line{0};

    bool next(std::string &out)
    {
        ++line; // the line read, or missing
        if (at >= bytes.size())
            return false;
        const std::size_t end = bytes.find('\n', at);
        if (end == std::string::npos)
            return false; // a line cut short: the file ends inside it
        out = bytes.substr(at, end - at);
        if (!out.empty() && out.back() == '\r')
            out.pop_back();
        at = end + 1;
        return true;
    }
    [[noreturn]] void fail(const std::string &why) const
    {
        throw Error(what + ":" + std::to_string(line) + ": " + why);
    }
};

/// One line of a sensor list: "s: T 51 7 8 m_present_time timestamp".
struct ListedSensor
{
    bool inFile{false};
    long index{-1};
    SlocumSensor sensor;
};

std::vector<ListedSensor> readSensorList(LineReader &in, long count, const std::string &end)
{
    std::vector<ListedSensor> out;
    std::string line;
    for (long k = 0; k < count; ++k)
    {
        if (!in.next(line))
            in.fail("the sensor list ends after " + std::to_string(k) + " sensors (total_num_sensors says " +
                    std::to_string(count) + ")" + end);
        std::istringstream words(line);
        std::string tag, flag, number, index, bytes;
        ListedSensor s;
        words >> tag >> flag >> number >> index >> bytes >> s.sensor.name >> s.sensor.units;
        const long b = countOf(bytes);
        if (tag != "s:" || (flag != "T" && flag != "F") || countOf(number) < 0 || s.sensor.units.empty() ||
            (b != 1 && b != 2 && b != 4 && b != 8))
            in.fail("a sensor line 's: T|F <number> <index> <bytes 1, 2, 4 or 8> <name> <units>' expected, got '" +
                    line.substr(0, 80) + "'");
        s.inFile = flag == "T";
        s.index = std::strtol(index.c_str(), nullptr, 10);
        s.sensor.bytes = static_cast<int>(b);
        out.push_back(std::move(s));
    }
    return out;
}

/// The cache file of the sensor list @p crc: in @p cacheDir, beside @p file, in cache/ beside it (.cac, else .ccc).
std::string findCache(const std::string &file, const std::string &crc, const std::string &cacheDir,
                      std::string &searched)
{
    std::vector<fs::path> dirs;
    if (!cacheDir.empty())
        dirs.emplace_back(cacheDir);
    const fs::path beside = fs::path(file).parent_path().empty() ? fs::path(".") : fs::path(file).parent_path();
    dirs.push_back(beside);
    dirs.push_back(beside / "cache");
    std::error_code ec;
    for (const fs::path &d : dirs)
    {
        searched += (searched.empty() ? "" : ", ") + d.string();
        for (const std::string &name :
             {lower(crc) + ".cac", upper(crc) + ".CAC", lower(crc) + ".ccc", upper(crc) + ".CCC"})
            if (fs::is_regular_file(d / name, ec))
                return (d / name).string();
    }
    return "";
}

/// Reads a value of @p size bytes at @p p in the byte order @p big.
double valueAt(const unsigned char *p, int size, bool big)
{
    unsigned char b[8];
    for (int i = 0; i < size; ++i)
        b[i] = p[big ? i : size - 1 - i]; // most significant first
    switch (size)
    {
    case 1:
        return static_cast<double>(static_cast<std::int8_t>(b[0]));
    case 2:
        return static_cast<double>(static_cast<std::int16_t>(static_cast<std::uint16_t>((b[0] << 8) | b[1])));
    case 4: {
        std::uint32_t u = 0;
        for (int i = 0; i < 4; ++i)
            u = (u << 8) | b[i];
        float f = 0.0f;
        std::memcpy(&f, &u, 4);
        return static_cast<double>(f);
    }
    default: {
        std::uint64_t u = 0;
        for (int i = 0; i < 8; ++i)
            u = (u << 8) | b[i];
        double d = 0.0;
        std::memcpy(&d, &u, 8);
        return d;
    }
    }
}

/// The header's count @p key. @throws Error naming the file when it is missing or not a count.
long headerCount(const std::map<std::string, std::string> &h, const std::string &key, const std::string &file)
{
    const auto it = h.find(key);
    const long n = it == h.end() ? -1 : countOf(it->second);
    if (n < 0)
        throw Error(file + ": the header has no count '" + key + ":'" +
                    (it == h.end() ? std::string() : " (got '" + it->second + "')"));
    return n;
}

/// The sensors of the file's cycles, from the list in the file or in its cache file; @p in after the header.
std::vector<SlocumSensor> sensorsOf(LineReader &in, SlocumBinaryData &d, const std::string &cacheDir)
{
    const std::string &file = d.file;
    const long total = headerCount(d.header, "total_num_sensors", file);
    const long perCycle = headerCount(d.header, "sensors_per_cycle", file);
    const bool factored = d.header.count("sensor_list_factored") && d.header.at("sensor_list_factored") == "1";
    std::vector<ListedSensor> listed;
    if (!factored)
    {
        d.sensorList = file;
        listed = readSensorList(in, total, "");
    }
    else
    {
        const std::string crc = d.header.count("sensor_list_crc") ? d.header.at("sensor_list_crc") : "";
        if (crc.empty() || crc.find_first_of("/\\. ") != std::string::npos)
            throw Error(file +
                        ": the sensor list is factored out (sensor_list_factored: 1) but the header names no "
                        "cache file (sensor_list_crc: '" +
                        crc + "')");
        std::string searched;
        d.sensorList = findCache(file, crc, cacheDir, searched);
        if (d.sensorList.empty())
            throw Error(
                file + ": the sensor list is in the cache file '" + lower(crc) +
                ".cac' (sensor_list_factored: 1), found in none of the folders " + searched +
                ": copy it from the dockserver's cache folder beside the files or into a cache/ folder beside them");
        std::string bytes = readBytes(d.sensorList, "cache file");
        if (extensionOf(d.sensorList) == "ccc")
            bytes = decompressSlocumLz4(bytes, d.sensorList);
        LineReader cache{bytes, d.sensorList};
        listed = readSensorList(cache, total, " (of " + file + ")");
    }
    std::vector<SlocumSensor> out(static_cast<std::size_t>(perCycle));
    std::vector<bool> seen(out.size(), false);
    for (const ListedSensor &s : listed)
    {
        if (!s.inFile)
            continue;
        if (s.index < 0 || s.index >= perCycle || seen[static_cast<std::size_t>(s.index)])
            throw Error(d.sensorList + ": sensor '" + s.sensor.name + "' has the index " + std::to_string(s.index) +
                        " in " + file + "'s cycles: each of 0 to " + std::to_string(perCycle - 1) +
                        " once expected (sensors_per_cycle: " + std::to_string(perCycle) + ")");
        seen[static_cast<std::size_t>(s.index)] = true;
        out[static_cast<std::size_t>(s.index)] = s.sensor;
    }
    if (std::find(seen.begin(), seen.end(), false) != seen.end())
        throw Error(d.sensorList + ": the sensor list marks " +
                    std::to_string(std::count(seen.begin(), seen.end(), true)) + " sensors 'T' (in the file), " + file +
                    "'s sensors_per_cycle says " + std::to_string(perCycle) +
                    (factored ? " (a cache file of another sensor list?)" : ""));
    return out;
}

/// Checks the known-bytes cycle at @p at and returns the byte order it gives.
bool knownBytes(const std::string &bytes, std::size_t &at, long version, const std::string &file)
{
    const std::size_t size = version >= 2 ? 16 : 8;
    const auto fail = [&](const std::string &why) {
        throw Error(file + ": byte " + std::to_string(at) + ": " + why +
                    " (the known-bytes cycle 's', 'a', 0x1234, 123.456, 123456789.12345 that gives the byte order)");
    };
    if (bytes.size() < at + size)
        fail("the file ends before its known bytes");
    const auto *p = reinterpret_cast<const unsigned char *>(bytes.data() + at);
    if (p[0] != 's' || p[1] != 'a')
        fail("bad known bytes: 's', 'a' expected");
    bool big = true;
    if (p[2] == 0x12 && p[3] == 0x34)
        big = true;
    else if (p[2] == 0x34 && p[3] == 0x12)
        big = false;
    else
        fail("bad known bytes: the int16 0x1234 reads in neither byte order");
    if (valueAt(p + 4, 4, big) != static_cast<double>(123.456f))
        fail("bad known bytes: the float 123.456 does not read as one");
    if (version >= 2 && valueAt(p + 8, 8, big) != 123456789.12345)
        fail("bad known bytes: the double 123456789.12345 does not read as one");
    at += size;
    return big;
}

/// Reads the data cycles of @p bytes from @p at into @p d.
void readCycles(const std::string &bytes, std::size_t at, SlocumBinaryData &d)
{
    const std::size_t n = d.sensors.size();
    const long stateBytes = headerCount(d.header, "state_bytes_per_cycle", d.file);
    if (static_cast<std::size_t>(stateBytes) != (n + 3) / 4)
        throw Error(d.file + ": state_bytes_per_cycle: " + std::to_string(stateBytes) + " for " + std::to_string(n) +
                    " sensors (2 bits each: " + std::to_string((n + 3) / 4) + " expected)");
    std::vector<int> columnOf(n, -1);
    for (std::size_t c = 0; c < d.columns.size(); ++c)
        columnOf[d.columns[c]] = static_cast<int>(c);
    std::vector<double> last(d.columns.size(), NAN);
    const auto *data = reinterpret_cast<const unsigned char *>(bytes.data());
    while (true)
    {
        if (at >= bytes.size())
            throw Error(d.file + ": byte " + std::to_string(at) +
                        ": the file ends without its end tag 'X' (cut short: a transfer not finished?)");
        const unsigned char tag = data[at];
        if (tag == 'X')
            return;
        if (tag != 'd')
            throw Error(d.file + ": byte " + std::to_string(at) +
                        ": a cycle tag 'd' or the end tag 'X' expected, got 0x" + hex(tag));
        const std::size_t cycle = at;
        const unsigned char *state = data + at + 1;
        at += 1 + static_cast<std::size_t>(stateBytes);
        if (at > bytes.size())
            throw Error(d.file + ": byte " + std::to_string(cycle) + ": the file ends inside a cycle's state bytes");
        std::vector<double> row(d.columns.size(), NAN);
        for (std::size_t k = 0; k < n; ++k)
        {
            const int s = (state[k / 4] >> (6 - 2 * (k % 4))) & 3;
            const int c = columnOf[k];
            if (s == 2)
            {
                const auto size = static_cast<std::size_t>(d.sensors[k].bytes);
                if (at + size > bytes.size())
                    throw Error(d.file + ": byte " + std::to_string(cycle) +
                                ": the file ends inside a cycle (sensor '" + d.sensors[k].name + "')");
                if (c >= 0)
                    row[c] = last[c] = valueAt(data + at, d.sensors[k].bytes, d.bigEndian);
                at += size;
            }
            else if (s == 1 && c >= 0)
                row[c] = last[c];
            else if (s == 3)
                throw Error(d.file + ": byte " + std::to_string(cycle) + ": sensor '" + d.sensors[k].name +
                            "' has the state 3 (0, 1 or 2 expected)");
        }
        d.cycles.push_back(std::move(row));
    }
}
} // namespace

bool isSlocumBinaryName(const std::string &file)
{
    static const char *const kinds[] = {"sbd", "tbd", "dbd", "ebd", "mbd", "nbd",
                                        "scd", "tcd", "dcd", "ecd", "mcd", "ncd"};
    const std::string e = extensionOf(file);
    return std::any_of(std::begin(kinds), std::end(kinds), [&](const char *k) { return e == k; });
}

std::string decompressSlocumLz4(const std::string &bytes, const std::string &file)
{
    std::string out;
    std::vector<char> block(65536);
    std::size_t at = 0;
    while (at < bytes.size())
    {
        if (at + 2 > bytes.size())
            throw Error(file + ": byte " + std::to_string(at) + ": an LZ4 frame cut short (its 2-byte length)");
        const std::size_t size =
            (static_cast<unsigned char>(bytes[at]) << 8) | static_cast<unsigned char>(bytes[at + 1]);
        if (at + 2 + size > bytes.size())
            throw Error(file + ": byte " + std::to_string(at) + ": an LZ4 frame of " + std::to_string(size) +
                        " bytes cut short (the file ends after " + std::to_string(bytes.size() - at - 2) + ")");
        int got = -1;
        while (true)
        {
            got = LZ4_decompress_safe(bytes.data() + at + 2, block.data(), static_cast<int>(size),
                                      static_cast<int>(block.size()));
            if (got >= 0 || block.size() >= kMaxLz4Block)
                break;
            block.resize(std::min(kMaxLz4Block, 4 * block.size()));
        }
        if (got < 0)
            throw Error(file + ": byte " + std::to_string(at) + ": a corrupt LZ4 block (" + std::to_string(size) +
                        " bytes)");
        out.append(block.data(), static_cast<std::size_t>(got));
        at += 2 + size;
    }
    return out;
}

SlocumBinaryData readSlocumBinary(const std::string &file, const std::vector<std::string> &sensors,
                                  const std::string &cacheDir)
{
    SlocumBinaryData d;
    d.file = file;
    std::string bytes = readBytes(file, "observations");
    const std::string e = extensionOf(file);
    d.compressed = e.size() == 3 && e[1] == 'c';
    if (d.compressed)
        bytes = decompressSlocumLz4(bytes, file);
    LineReader in{bytes, file};
    std::string line;
    long tags = -1;
    for (long k = 0; tags < 0 || k < tags; ++k)
    {
        if (!in.next(line))
            in.fail("the file ends in its header (num_ascii_tags lines 'key: value')");
        const std::size_t colon = line.find(':');
        if (k == 0 && line.rfind("dbd_label:", 0) != 0)
            in.fail("not a Slocum binary file (its first line is 'dbd_label: DBD(dinkum_binary_data)file')");
        if (colon == std::string::npos || colon == 0)
            in.fail("a header line 'key: value' expected");
        const std::string key = text::trim(line.substr(0, colon)), value = text::trim(line.substr(colon + 1));
        d.header[key] = value;
        if (key == "num_ascii_tags" && (tags = countOf(value)) < 0)
            in.fail("num_ascii_tags: a count expected, got '" + value + "'");
    }
    const long version = headerCount(d.header, "encoding_ver", file);
    if (version < kFirstVersion || version > kLastVersion)
        throw Error(file + ": unknown encoding version " + std::to_string(version) +
                    " (encoding_ver; this reader knows " + std::to_string(kFirstVersion) + " to " +
                    std::to_string(kLastVersion) + ")");
    d.sensors = sensorsOf(in, d, cacheDir);
    for (std::size_t k = 0; k < d.sensors.size(); ++k)
        if (version < 2 && d.sensors[k].bytes == 8)
            throw Error(d.sensorList + ": sensor '" + d.sensors[k].name +
                        "' of 8 bytes in a file of encoding version 1 (doubles came with version 2)");
    if (sensors.empty())
        for (std::size_t k = 0; k < d.sensors.size(); ++k)
            d.columns.push_back(k);
    for (const std::string &name : sensors)
        for (std::size_t k = 0; k < d.sensors.size(); ++k)
            if (d.sensors[k].name == name)
                d.columns.push_back(k);
    std::size_t at = in.at;
    d.bigEndian = knownBytes(bytes, at, version, file);
    readCycles(bytes, at, d);
    return d;
}
} // namespace ompl_glider

#pragma once
// Writes a Slocum glider's binary files for the tests, from the format's public description ([DinkumBinary]), not
// through the library: the ASCII header, the sensor list (in the file, or factored out into a cache file), the
// known-bytes cycle in either byte order, one data cycle per row (2 bits of state per sensor: 0 not updated, 1 the
// value it had, 2 a new value, then the new values), the end tag 'X'; and the LZ4 frames of the compressed files
// (a 2-byte big-endian length, then an LZ4 block).
#include <lz4.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace slocum_test
{
struct Sensor
{
    std::string name, units;
    int bytes;         // 1, 2, 4, 8
    bool inFile{true}; // F: listed, not in the cycles
};

struct Options
{
    bool bigEndian{true};
    bool factored{false};         // the sensor list in a cache file
    std::string crc{"1a2b3c4d"};  // sensor_list_crc
    int version{5};               // encoding_ver
    std::string extension{"sbd"}; // filename_extension
};

/// The sensor list's lines ("s: T 0 0 8 m_present_time timestamp"), as in a file or a cache file.
inline std::string sensorList(const std::vector<Sensor> &sensors)
{
    std::string out;
    int index = 0;
    for (std::size_t k = 0; k < sensors.size(); ++k)
    {
        const Sensor &s = sensors[k];
        out += "s: " + std::string(s.inFile ? "T" : "F") + " " + std::to_string(k) + " " +
               std::to_string(s.inFile ? index++ : -1) + " " + std::to_string(s.bytes) + " " + s.name + " " + s.units +
               "\n";
    }
    return out;
}

/// @p size bytes of @p bits (most significant first) in the byte order @p big.
inline void put(std::string &out, std::uint64_t bits, int size, bool big)
{
    for (int i = 0; i < size; ++i)
    {
        const int shift = 8 * (big ? size - 1 - i : i);
        out += static_cast<char>((bits >> shift) & 0xff);
    }
}

inline void putValue(std::string &out, double x, int size, bool big)
{
    if (size == 8)
    {
        std::uint64_t u;
        std::memcpy(&u, &x, 8);
        put(out, u, 8, big);
    }
    else if (size == 4)
    {
        const float f = static_cast<float>(x);
        std::uint32_t u;
        std::memcpy(&u, &f, 4);
        put(out, u, 4, big);
    }
    else if (size == 2)
        put(out, static_cast<std::uint16_t>(static_cast<std::int16_t>(x)), 2, big);
    else
        put(out, static_cast<std::uint8_t>(static_cast<std::int8_t>(x)), 1, big);
}

/// A binary file of @p name ("ru29-2026-074-0-0") whose cycles are @p rows (one value per sensor in the file, in the
/// file's order; NaN: not updated).
inline std::string encode(const std::string &name, const std::vector<Sensor> &sensors,
                          const std::vector<std::vector<double>> &rows, const Options &o = {})
{
    std::vector<int> sizes;
    for (const Sensor &s : sensors)
        if (s.inFile)
            sizes.push_back(s.bytes);
    const std::size_t n = sizes.size(), stateBytes = (n + 3) / 4;
    std::string out = "dbd_label: DBD(dinkum_binary_data)file\n"
                      "encoding_ver: " +
                      std::to_string(o.version) +
                      "\n"
                      "num_ascii_tags: 14\n"
                      "all_sensors: 0\n"
                      "the8x3_filename: 01230000\n"
                      "full_filename: " +
                      name + "\nfilename_extension: " + o.extension +
                      "\n"
                      "mission_name: MICRO.MI\n"
                      "fileopen_time: Sun_Mar_15_06:00:00_2026\n"
                      "total_num_sensors: " +
                      std::to_string(sensors.size()) + "\nsensors_per_cycle: " + std::to_string(n) +
                      "\nstate_bytes_per_cycle: " + std::to_string(stateBytes) + "\nsensor_list_crc: " + o.crc +
                      "\nsensor_list_factored: " + (o.factored ? "1" : "0") + "\n";
    if (!o.factored)
        out += sensorList(sensors);
    out += "sa";
    put(out, 0x1234, 2, o.bigEndian);
    putValue(out, 123.456, 4, o.bigEndian);
    if (o.version >= 2)
        putValue(out, 123456789.12345, 8, o.bigEndian);
    std::vector<double> last(n, NAN);
    for (const std::vector<double> &row : rows)
    {
        if (row.size() != n)
            throw std::runtime_error("a row of " + std::to_string(row.size()) + " values for " + std::to_string(n));
        std::string state(stateBytes, '\0'), values;
        for (std::size_t k = 0; k < n; ++k)
        {
            int code = 0;
            if (!std::isnan(row[k]))
            {
                code = row[k] == last[k] ? 1 : 2;
                if (code == 2)
                    putValue(values, row[k], sizes[k], o.bigEndian);
                last[k] = row[k];
            }
            state[k / 4] = static_cast<char>(static_cast<unsigned char>(state[k / 4]) | (code << (6 - 2 * (k % 4))));
        }
        out += "d" + state + values;
    }
    return out + "X";
}

/// @p raw as a compressed Slocum file: frames of at most @p chunk bytes, each a 2-byte big-endian length and an LZ4
/// block.
inline std::string compress(const std::string &raw, std::size_t chunk = 1000)
{
    std::string out;
    for (std::size_t at = 0; at < raw.size(); at += chunk)
    {
        const int size = static_cast<int>(std::min(chunk, raw.size() - at));
        std::string block(static_cast<std::size_t>(LZ4_compressBound(size)), '\0');
        const int got = LZ4_compress_default(raw.data() + at, block.data(), size, static_cast<int>(block.size()));
        if (got <= 0 || got > 65535)
            throw std::runtime_error("LZ4 compression failed");
        out += static_cast<char>(got >> 8);
        out += static_cast<char>(got & 0xff);
        out.append(block.data(), static_cast<std::size_t>(got));
    }
    return out;
}
} // namespace slocum_test

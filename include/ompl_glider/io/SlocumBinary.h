#pragma once
/// @file SlocumBinary.h
/// @brief A Slocum glider's own binary files, the "dinkum binary data" format ([DinkumBinary]): `sbd`, `tbd`, `dbd`,
/// `ebd`, `mbd`, `nbd`, and their LZ4-compressed versions `scd`, `tcd`, `dcd`, `ecd`, `mcd`, `ncd`.
///
/// A file: `num_ascii_tags` ASCII header lines `key: value` (the first `dbd_label: DBD(dinkum_binary_data)file`;
/// `encoding_ver`, `full_filename`, `total_num_sensors`, `sensors_per_cycle`, `state_bytes_per_cycle`,
/// `sensor_list_crc`, `sensor_list_factored`), then the sensor list, one line per sensor of the glider
/// (`s: T 51 7 8 m_present_time timestamp`: in this file T/F, the sensor's number, its index in the file's cycles or
/// -1, bytes per value 1, 2, 4 or 8, name, units), unless it is factored out (`sensor_list_factored: 1`) into the
/// cache file `<sensor_list_crc>.cac` (lower case; `.ccc` LZ4-compressed). Then the binary part: the known-bytes cycle
/// ('s', 'a', the int16 0x1234, the float 123.456, the double 123456789.12345 from encoding version 2 on), which gives
/// the byte order; cycles tagged 'd', each `state_bytes_per_cycle` bytes of 2 bits per sensor of the file (the first
/// sensor in the most significant bits: 0 not updated, 1 updated with the value it had, 2 updated with a new value),
/// then the new values in the file's sensor order (int8, int16, float, double as the sizes say); the end tag 'X'.
/// A compressed file is a series of frames, each a 2-byte big-endian length and an LZ4 block of that many bytes.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace ompl_glider
{
/// @brief One sensor of a Slocum binary file's cycles.
struct SlocumSensor
{
    std::string name;  ///< "m_present_time"
    std::string units; ///< "timestamp"
    int bytes{8};      ///< 1 (int8), 2 (int16), 4 (float) or 8 (double)
};

/// @brief What a Slocum binary file holds (of the sensors asked for).
struct SlocumBinaryData
{
    std::string file;                          ///< the path read
    std::map<std::string, std::string> header; ///< the ASCII header's `key: value` lines
    std::vector<SlocumSensor> sensors;         ///< the sensors of the file's cycles, in their order
    std::string sensorList;                    ///< where the sensor list was read: the file, or the cache file's path
    bool bigEndian{true};                      ///< the byte order the known bytes gave
    bool compressed{false};                    ///< read from an LZ4-compressed file
    /// indices into sensors of the columns of cycles (the sensors asked for that the file has, in the order asked)
    std::vector<std::size_t> columns;
    /// one row per data cycle: each column's value in that cycle, NaN when not updated (state 0); state 1 repeats the
    /// value the sensor had
    std::vector<std::vector<double>> cycles;
};

/// @brief True when @p file's extension is one of a Slocum binary file (sbd tbd dbd ebd mbd nbd, or the compressed
/// scd tcd dcd ecd mcd ncd; any case).
bool isSlocumBinaryName(const std::string &file);

/// @brief Reads the Slocum binary file @p file: of the sensors named in @p sensors (all when empty). A factored sensor
/// list is read from `<sensor_list_crc>.cac` (or `.ccc`) in @p cacheDir when given, then beside the file, then in a
/// `cache/` folder beside it.
/// @throws Error naming the file (and the byte offset or the line) for a file that cannot be opened, a header that is
/// not the format's, an unknown encoding version, a sensor list that does not match the header, a missing cache file
/// (the folders searched named), known bytes that read in neither byte order, an unknown cycle tag, a file cut short
/// (no end tag 'X'), or a corrupt LZ4 frame.
SlocumBinaryData readSlocumBinary(const std::string &file, const std::vector<std::string> &sensors = {},
                                  const std::string &cacheDir = "");

/// @brief The bytes of the LZ4-compressed Slocum file @p bytes (frames of a 2-byte big-endian length and an LZ4 block)
/// decompressed; @p file names it in the messages. @throws Error naming the file and byte offset of a frame cut short
/// or corrupt.
std::string decompressSlocumLz4(const std::string &bytes, const std::string &file);
} // namespace ompl_glider

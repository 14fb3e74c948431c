/// @file SlocumDba.cpp
/// @brief A Slocum glider's dba files, the ASCII tables dbd2asc writes of the glider's binary data, read into the one
/// table of the observations (SlocumTable.h); and the binary files' table (SlocumBinary.h).
///
/// A dba file: `num_ascii_tags` header lines `key: value` (the first `dbd_label: DBD_ASC(dinkum_binary_data_ascii)
/// file`; `filename: ru29-2026-074-0-12` names the glider, `sensors_per_cycle`, `num_label_lines`), then the label
/// lines (sensor names; units; bytes per value), then one line per cycle of space-separated values, `NaN` where a
/// sensor has no new value.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "SlocumTable.h"
#include "TextUtil.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/SlocumBinary.h"

namespace ompl_glider::observations_detail
{
namespace
{
std::vector<std::string> words(const std::string &line)
{
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string w; in >> w;)
        out.push_back(w);
    return out;
}

/// A header count ("num_ascii_tags: 14"); -1 when @p text is not one.
long countOf(const std::string &text)
{
    char *end = nullptr;
    const long n = std::strtol(text.c_str(), &end, 10);
    return end != text.c_str() && *end == '\0' && n >= 0 && n < 100000 ? n : -1;
}

/// A dba file's header and label lines.
struct Header
{
    std::map<std::string, std::string> tags; // "key: value"
    std::vector<std::string> names, units;   // the sensors
    int namesLine{0};                        // the line of the names (the units' is the next)
};

/// Reads the header and the label lines of a dba file; @p n counts the lines read.
Header readHeader(std::istream &in, const std::string &file, int &n)
{
    const auto fail = [&](const std::string &what) { throw Error(file + ":" + std::to_string(n) + ": " + what); };
    Header h;
    long tags = -1;
    std::string line;
    for (long read = 0; tags < 0 || read < tags; ++read)
    {
        if (!std::getline(in, line))
            fail("the file ends in its header (dbd2asc writes num_ascii_tags lines 'key: value')");
        ++n;
        const std::size_t colon = line.find(':');
        if (n == 1 && line.rfind("dbd_label:", 0) != 0)
            fail("not a Slocum dba file (dbd2asc's first line is 'dbd_label: DBD_ASC(dinkum_binary_data_ascii)file')");
        if (colon == std::string::npos || colon == 0)
            fail(tags < 0 ? "the header has no num_ascii_tags line (the number of header lines)"
                          : "a header line 'key: value' expected (num_ascii_tags says " + std::to_string(tags) + ")");
        const std::string key = text::trim(line.substr(0, colon)), value = text::trim(line.substr(colon + 1));
        h.tags[key] = value;
        if (key == "num_ascii_tags" && (tags = countOf(value)) < 0)
            fail("num_ascii_tags: a count expected, got '" + value + "'");
    }
    const long labels = h.tags.count("num_label_lines") ? countOf(h.tags["num_label_lines"]) : 3;
    if (labels < 2)
        fail("num_label_lines: 2 or more expected (sensor names, units, bytes), got '" + h.tags["num_label_lines"] +
             "'");
    const long perCycle = h.tags.count("sensors_per_cycle") ? countOf(h.tags["sensors_per_cycle"]) : -1;
    for (long k = 0; k < labels; ++k)
    {
        if (!std::getline(in, line))
            throw Error(file + ":" + std::to_string(n + 1) + ": the file ends before its label lines (" +
                        std::to_string(labels) + ": sensor names, units, bytes per value)");
        ++n;
        const std::vector<std::string> w = words(line);
        if (k == 0)
        {
            h.names = w;
            h.namesLine = n;
            if (perCycle >= 0 && static_cast<long>(w.size()) != perCycle)
                fail("the label line names " + std::to_string(w.size()) + " sensors, sensors_per_cycle says " +
                     std::to_string(perCycle));
        }
        else if (w.size() != h.names.size())
            fail("label line " + std::to_string(k + 1) + " has " + std::to_string(w.size()) + " entries for " +
                 std::to_string(h.names.size()) + " sensors");
        if (k == 1)
            h.units = w;
    }
    return h;
}

} // namespace

std::string slocumGliderOf(const std::string &filename)
{
    std::vector<std::size_t> dashes;
    for (std::size_t i = 0; i < filename.size(); ++i)
        if (filename[i] == '-')
            dashes.push_back(i);
    return dashes.size() >= 4 ? filename.substr(0, dashes[dashes.size() - 4]) : filename;
}

SlocumTable readDbaTable(const std::string &file)
{
    std::ifstream in(file);
    if (!in)
        throw Error("observations '" + file + "': cannot open the file");
    SlocumTable t;
    t.file = file;
    int n = 0;
    const Header h = readHeader(in, file, n);
    const std::vector<std::string> &names = h.names;
    t.platform = h.tags.count("filename") ? slocumGliderOf(h.tags.at("filename")) : "";
    t.sensorsWhere = file + ":" + std::to_string(h.namesLine);
    t.unitsWhere = file + ":" + std::to_string(h.namesLine + 1);
    std::array<std::size_t, kColumns> column{};
    for (std::size_t c = 0; c < kColumns; ++c)
    {
        const auto it = std::find(names.begin(), names.end(), kSlocumSensors[c]);
        t.present[c] = it != names.end();
        column[c] = static_cast<std::size_t>(it - names.begin());
        if (t.present[c])
            t.units[c] = h.units[column[c]];
    }
    std::string line;
    std::vector<double> values(names.size());
    while (std::getline(in, line))
    {
        ++n;
        const std::vector<std::string> w = words(line);
        if (w.empty())
            continue;
        if (w.size() != names.size())
            throw Error(file + ":" + std::to_string(n) + ": " + std::to_string(w.size()) + " values, the label line (" +
                        std::to_string(h.namesLine) + ") names " + std::to_string(names.size()) + " sensors");
        for (std::size_t k = 0; k < w.size(); ++k)
        {
            char *end = nullptr;
            values[k] = std::strtod(w[k].c_str(), &end);
            if (end == w[k].c_str() || *end != '\0' || std::isinf(values[k]))
                throw Error(file + ":" + std::to_string(n) + ": sensor '" + names[k] + "': '" + w[k] +
                            "' is not a number (or NaN)");
        }
        std::array<double, kColumns> row;
        bool any = false;
        for (std::size_t c = 0; c < kColumns; ++c)
        {
            row[c] = t.present[c] ? values[column[c]] : NAN;
            any = any || (c != kTime && !std::isnan(row[c]));
        }
        if (any)
            t.rows.push_back(row);
    }
    return t;
}

SlocumTable readBinaryTable(const std::string &file, const std::string &cacheDir)
{
    const std::vector<std::string> wanted(kSlocumSensors.begin(), kSlocumSensors.end());
    const SlocumBinaryData d = readSlocumBinary(file, wanted, cacheDir);
    SlocumTable t;
    t.file = file;
    t.binary = true;
    const auto name = d.header.find("full_filename");
    t.platform = name != d.header.end() ? slocumGliderOf(name->second) : "";
    t.sensorsWhere = t.unitsWhere =
        d.sensorList == file ? file + " (its sensor list)" : file + " (the sensor list of '" + d.sensorList + "')";
    std::array<int, kColumns> column;
    column.fill(-1);
    for (std::size_t k = 0; k < d.columns.size(); ++k)
        for (std::size_t c = 0; c < kColumns; ++c)
            if (d.sensors[d.columns[k]].name == kSlocumSensors[c])
            {
                column[c] = static_cast<int>(k);
                t.present[c] = true;
                t.units[c] = d.sensors[d.columns[k]].units;
            }
    for (const std::vector<double> &cycle : d.cycles)
    {
        std::array<double, kColumns> row;
        bool any = false;
        for (std::size_t c = 0; c < kColumns; ++c)
        {
            row[c] = column[c] >= 0 ? cycle[static_cast<std::size_t>(column[c])] : NAN;
            any = any || (c != kTime && !std::isnan(row[c]));
        }
        if (any)
            t.rows.push_back(row);
    }
    return t;
}
} // namespace ompl_glider::observations_detail

#pragma once
/// @file CsvCells.h
/// @brief Internal to src/io: the cells of one line of a CSV file, as the glider observations' CSV reader and the
/// ERDDAP tabledap answers read them.
#include <string>
#include <vector>

#include "TextUtil.h"

namespace ompl_glider::io_detail
{
/// @brief The cells of one CSV line: split at @p separator, carriage returns dropped and each cell trimmed of white
/// space (text::trim()). With @p quotes (as ERDDAP writes them) a cell in double quotes may hold the separator,
/// and a quote doubled inside it is one quote; without, a quote is a character like any other. A line that ends in the
/// separator ends with an empty cell; an empty line is one empty cell.
inline std::vector<std::string> csvCells(const std::string &line, char separator = ',', bool quotes = false)
{
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i)
    {
        const char c = line[i];
        if (quotes && quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
            out.back() += line[++i];
        else if (quotes && c == '"')
            quoted = !quoted;
        else if (c == separator && !quoted)
            out.emplace_back();
        else if (c != '\r')
            out.back() += c;
    }
    for (std::string &cell : out)
        cell = text::trim(cell);
    return out;
}
} // namespace ompl_glider::io_detail

#pragma once
/// @file OutputFormatWriters.h
/// @brief The writer of every output format: one row per format of outputFormats() (mission/OutputFormats.h, which
/// the mission layer reads for the names of `outputs.files`), keyed by its OutputFormatId. A row's writer makes the
/// OutputFile list of its format for a result; outputFiles() (OutputWriter.h) asks the rows of the formats a run
/// wants, in the order of outputFormats().

#include <string>
#include <vector>

#include "ompl_glider/mission/OutputFormats.h"
#include "ompl_glider/mission/Planning.h"
#include "ompl_glider/output/OutputWriter.h"

namespace ompl_glider
{
/// @brief Makes the files of one format for @p result on @p problem: none where the format does not apply to it
/// (isochrones without contours, the goto list without lon/lat, ...); nothing is written yet, each OutputFile writes
/// itself when called. @p listed: the names of every file of the run (summary.json lists them; the other formats
/// ignore it). Each OutputFile keeps pointers to @p result and @p problem, which must outlive it.
/// @throws Error when the format cannot be written by this build (the map without OMPL_GLIDER_WITH_MAP).
using OutputFormatWriter = std::vector<OutputFile> (*)(const MissionResult &result, const MissionProblem &problem,
                                                       const std::vector<std::string> &listed);

/// @brief One row of the writers' table: a format and its writer.
struct OutputFormatWriterRow
{
    OutputFormatId id;         ///< the format (its name and declared files: outputFormats())
    OutputFormatWriter writer; ///< makes its files
};

/// @brief Every format's writer, one row per format of outputFormats() (tests/output/TestOutputFormats.cpp checks
/// that each format has exactly one, and that it makes the files its row of outputFormats() declares).
const std::vector<OutputFormatWriterRow> &outputFormatWriters();

/// @brief The writer of @p id. @throws Error when the format has none (a row missing from outputFormatWriters()).
OutputFormatWriter outputFormatWriter(OutputFormatId id);

/// @brief The names of the files @p format declares (OutputFormat::files: "a.csv, b.svg/png, goto_lNN.ma"), each on
/// its own: "b.svg/png" gives b.svg and b.png; goto_lNN.ma is gotoFileName(@p gotoNumber).
std::vector<std::string> declaredFileNames(const OutputFormat &format, int gotoNumber);
} // namespace ompl_glider

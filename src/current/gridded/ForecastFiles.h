#pragma once
/// @file ForecastFiles.h
/// @brief Internal: the stages of loadGriddedCurrents() as two calls (read one file's data; build the field), so
/// that a forecast in several files (ForecastFiles.cpp) reads each file with the same stages and builds one field.
/// Not installed.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "GriddedInternal.h"

namespace ompl_glider
{
namespace gridded_detail
{
/// The record selection of selectTimes() on given times (seconds after the forecast's first time, strictly
/// increasing, at least 2): sets out.steady (false), forecastBegin/End and departureTime (out.dated, calendar and
/// originSeconds must be set: the departure is read with out.fieldTime()). `name` names the time variable in
/// messages; `error` makes the Error (naming the file or files). idx are positions in ts.
AxisSelection selectForecastTimes(const std::vector<double> &ts, const std::string &name,
                                  const GriddedCurrentOptions &opt, GriddedCurrents &out,
                                  const std::function<Error(const std::string &)> &error);

/// One file's data as loadGriddedCurrents() reads it: velocities (unpacked, in m/s, internal order t, z, y, x) and
/// land, before the depth average, the node coordinates and the field.
struct ForecastPiece
{
    std::unique_ptr<GriddedDataset> file;
    Layout layout;
    RegionOfInterest region;
    AxisSelection z, t;
    HorizontalSubset h;
    GriddedData g;                       ///< nx, ny, depth, time, u, v, water (no coordinates yet)
    std::vector<std::uint8_t> fillWater; ///< g.water before the mask stage (land from fill values)
    std::vector<std::uint8_t> maskWater; ///< g.water after the mask stage, before the tracer's
    bool cornerGrid{false};              ///< GriddedCurrents::cornerGrid (a B grid: every still node is land)
    GriddedCurrents out;                 ///< what is known so far (variables, time fields, land counts, values)
};

/// Opens the file and runs the stages up to the land: fill values, the mask, the tracer, and (one file: times null)
/// zero velocity. times null: the records are chosen by selectTimes() (the single-file path); else they are
/// `*times` (positions in idx are file indices, values the field times of the whole forecast), totalTimes, the
/// records of the whole forecast, is what the memory check counts, and zero-velocity land is left to the caller.
ForecastPiece readForecastPiece(const std::string &path, const GriddedCurrentOptions &opt,
                                const AxisSelection *times = nullptr, std::size_t totalTimes = 0);

/// The rest of loadGriddedCurrents(): depth average, node coordinates, bounds, the GriddedCurrentField (named
/// opt.field.name, else fieldName).
GriddedCurrents buildForecast(ForecastPiece &p, const GriddedCurrentOptions &opt, const std::string &fieldName);
} // namespace gridded_detail
} // namespace ompl_glider

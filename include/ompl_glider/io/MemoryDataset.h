#pragma once
/// @file MemoryDataset.h
/// @brief NetCDF datasets held in memory (Python's Field.from_arrays): a dataset's bytes registered under a name
/// "memory:N" that the forecast reader opens wherever a file name goes (nc_open_mem), so that currents given as arrays
/// reach the pipeline by the reader's one path without a file on disk.

#include <string>

namespace ompl_glider
{
/// @brief Keeps @p bytes (a NetCDF dataset, as nc_close_memio() gives it) for the process and returns its name,
/// "memory:N" (N counts the datasets of the process).
std::string registerMemoryDataset(std::string bytes);

/// @brief Forgets the dataset @p name (readers that have it open keep their copy until they close it).
void releaseMemoryDataset(const std::string &name);

/// @brief True when @p source names a dataset of registerMemoryDataset() ("memory:" and a number).
bool isMemoryDataset(const std::string &source);
} // namespace ompl_glider

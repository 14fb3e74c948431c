#pragma once
/// @file Dataset.h
/// @brief Internal to the library (not installed): what the NetCDF readers (the forecasts of current/netcdf/, the
/// bathymetry) ask of an open gridded dataset, whatever reads it: NetCDF-C for files, in-memory datasets and OPeNDAP
/// URLs (NcFile.cpp), GDAL's multidimensional API for Zarr stores and GRIB files (GdalGrid.h). NcFile holds one and
/// words its errors.

#include <netcdf.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ompl_glider
{
namespace netcdf_detail
{
class Dataset
{
public:
    virtual ~Dataset() = default;
    /// "NetCDF file '<path>'", "OPeNDAP source '<url>'", "Zarr store '<path>'": how messages name it.
    virtual std::string who() const = 0;
    /// Variables and dimensions by index, as NetCDF numbers them (NC_GLOBAL for the dataset's own attributes).
    virtual int nvars() const = 0;
    virtual std::string varName(int var) const = 0;
    virtual std::string dimName(int dim) const = 0;
    virtual std::size_t dimLen(int dim) const = 0;
    virtual std::optional<int> findVar(const std::string &name) const = 0;
    virtual std::vector<int> varDims(int var) const = 0;
    virtual nc_type varType(int var) const = 0;
    /// A text attribute, trimmed; nullopt when absent or numeric.
    virtual std::optional<std::string> attText(int var, const char *name) const = 0;
    /// A numeric attribute's values (empty when absent); text yields {} and sets @p isText.
    virtual std::vector<double> attDoubles(int var, const char *name, bool &isText) const = 0;
    /// The stored values of @p var in the block at @p start of @p count, as doubles (as nc_get_vara_double gives
    /// them), into @p out. @throws Error naming the dataset and the variable.
    virtual void readBlock(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count,
                           double *out) const = 0;
    /// What the dataset holds but cannot be read (arrays GDAL cannot open, with its reason), for messages; "" when
    /// nothing.
    virtual std::string unreadable() const
    {
        return {};
    }
    /// The NetCDF id of the dataset (its groups are asked through it); -1 when NetCDF-C does not read it.
    virtual int netcdfId() const
    {
        return -1;
    }
};
}  // namespace netcdf_detail
}  // namespace ompl_glider

#pragma once
/// @file Dataset.h
/// @brief Internal to the library (not installed): what the gridded readers (the forecasts of current/gridded/, the
/// bathymetry, a glider's NetCDF observations) ask of an open gridded dataset, whatever reads it: NetCDF-C for files,
/// in-memory datasets and OPeNDAP URLs (GriddedDataset.cpp), GDAL's multidimensional API for Zarr stores and GRIB
/// files (GdalGrid.h). In the project's own types (ValueType, kGlobalAttributes): NetCDF-C's ids and types stay
/// inside its reader. GriddedDataset holds one and words its errors.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "ompl_glider/Exception.h"
#include "ompl_glider/io/FileList.h"

namespace ompl_glider
{
namespace gridded_detail
{
/// The type of a variable's stored values, whatever reads the dataset (NetCDF-C's nc_type, GDAL's data types).
enum class ValueType
{
    Byte,
    UByte,
    Short,
    UShort,
    Int,
    UInt,
    Int64,
    UInt64,
    Float,
    Double,
    Char,   ///< characters (a NetCDF `char` variable: text by rows)
    String, ///< variable-length strings
    Other   ///< a type of the reader's own (compound, opaque, enum, ...)
};

/// How messages name the source @p source of kind @p kind: "Zarr store '<source>'", "GRIB file '<source>'", ...
/// (datasetKindName(); @p source without credentials).
inline std::string datasetWho(DatasetKind kind, const std::string &source)
{
    return std::string(datasetKindName(kind)) + " '" + source + "'";
}

/// The variable number of the dataset's own attributes (attText(), attDoubles()): NetCDF's NC_GLOBAL.
inline constexpr int kGlobalAttributes = -1;

class Dataset
{
public:
    virtual ~Dataset() = default;
    /// "NetCDF file '<path>'", "OPeNDAP source '<url>'", "Zarr store '<path>'": how messages name it.
    virtual std::string who() const = 0;
    /// Variables and dimensions by index, as NetCDF numbers them (kGlobalAttributes for the dataset's own
    /// attributes).
    virtual int nvars() const = 0;
    virtual std::string varName(int var) const = 0;
    virtual std::string dimName(int dim) const = 0;
    virtual std::size_t dimLen(int dim) const = 0;
    virtual std::optional<int> findVar(const std::string &name) const = 0;
    virtual std::vector<int> varDims(int var) const = 0;
    virtual ValueType varType(int var) const = 0;
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
    virtual std::string unreadable() const { return {}; }
    /// The names of the root group's subgroups (a NetCDF-4 file's groups, which are not read); empty when none.
    virtual std::vector<std::string> groupNames() const { return {}; }
    /// All the characters of the text variable @p var (ValueType::Char), row after row, NULs included.
    /// @throws Error naming the dataset and the variable when they cannot be read (or the reader has no text).
    virtual std::string readChars(int var) const
    {
        throw Error(who() + ": read '" + varName(var) + "': no text variables in this dataset");
    }
};
} // namespace gridded_detail
} // namespace ompl_glider

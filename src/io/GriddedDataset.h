#pragma once
/// @file GriddedDataset.h
/// @brief Internal to the library (not installed): the open gridded dataset of every gridded reader (the forecasts of
/// current/gridded/, the bathymetry of io/GriddedBathymetry.cpp, a glider's NetCDF observations), whatever reads it
/// (a NetCDF file, an OPeNDAP URL, a dataset in memory, a Zarr store, a GRIB file), its queries whose errors name it,
/// and the size check of classic-format NetCDF files done before NetCDF-C opens one.
///
///  - GriddedDataset.cpp  the open dataset, attribute/variable queries, errors that name it; NetCDF-C's reader
///  - ClassicSize.cpp     the size a classic-format file must have, from its header (refuses truncated files)

#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Dataset.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace gridded_detail
{
// ---- the open dataset (GriddedDataset.cpp) ----

/// The open dataset, closed on scope exit; its queries throw Errors that name it. What reads it is a Dataset
/// (Dataset.h): NetCDF-C's, or GDAL's (GdalGrid).
class GriddedDataset
{
public:
    /// @throws Error "NetCDF file '<path>': cannot open: ..." when the file is missing or not NetCDF, and
    /// "NetCDF file '<path>' is truncated: ..." when it is a classic-format file shorter than its header declares
    /// (classicTruncation(); netCDF-4/HDF5 files are not checked).
    /// A URL (isRemoteSource()) is read through NetCDF-C's DAP client as the process's remoteAccess() says
    /// (RemoteDataset.h): its description from the cache file when there is one, its values through
    /// readBlock()/readAll1D(). A Zarr store or a GRIB file (isGdalSource(), GdalGrid.h) is read through GDAL's
    /// multidimensional API, queried the same way.
    explicit GriddedDataset(const std::string &path);
    ~GriddedDataset();
    GriddedDataset(const GriddedDataset &) = delete;
    GriddedDataset &operator=(const GriddedDataset &) = delete;

    const std::string &path() const { return path_; }
    /// An Error "NetCDF file '<path>': <what>" ("OPeNDAP source '<url>': <what>" for a URL).
    Error error(const std::string &what) const;
    /// @brief error() about the setting @p field (Error::field()).
    Error error(const std::string &what, const std::string &field) const;

    int nvars() const;
    std::string varName(int var) const;
    std::string dimName(int dim) const;
    std::size_t dimLen(int dim) const;
    std::optional<int> findVar(const std::string &name) const;
    std::vector<int> varDims(int var) const;
    ValueType varType(int var) const;
    /// A text attribute (characters, or the first of strings), trimmed; nullopt when absent or numeric
    /// (@p var: kGlobalAttributes for the dataset's own).
    std::optional<std::string> attText(int var, const char *name) const;
    /// A numeric attribute's values; empty when absent. @throws Error naming the variable and the attribute when it
    /// is text (a `scale_factor` of "0.01" is not applied in silence).
    std::vector<double> attDoubles(int var, const char *name) const;
    /// What the dataset holds but cannot be read ("array 'uo' cannot be opened: <GDAL's reason>"); "" when nothing.
    std::string unreadable() const;
    /// The names of a NetCDF-4 file's groups under the root (only the root group is read); empty when none.
    std::vector<std::string> groupNames() const;
    /// All the characters of the text variable @p var (ValueType::Char), row after row (NULs included).
    std::string readChars(int var) const;
    /// All values of a variable (any number of dimensions), as doubles.
    std::vector<double> readAll1D(int var) const;
    /// The values of @p var in the block at @p start of @p count, as doubles (nc_get_vara_double), into @p out;
    /// from the file, or for a URL from its cache or the server.
    void readBlock(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count,
                   double *out) const;

private:
    std::string path_;
    std::shared_ptr<Dataset> data_; ///< what reads it: NetCDF-C (a file, in memory, OPeNDAP) or GDAL
};

// ---- classic-format files (ClassicSize.cpp) ----

/// What the header of a classic-format file (CDF-1, CDF-2 or CDF-5) declares about where its data end.
struct ClassicExtent
{
    int version{0};             ///< 1, 2 or 5; 0 when the bytes are not a classic header
    std::string corrupt;        ///< after a classic magic number, what breaks the format (unknown type or tag,
                                ///< a dimension id out of range, a variable of more than 2^64 bytes)
    bool headerCut{false};      ///< the bytes end inside the header (headerEnd and the data fields are then 0)
    bool streaming{false};      ///< numrecs is STREAMING: the record count is unknown and the records unchecked
    std::uint64_t fileBytes{0}; ///< bytes of the file
    std::uint64_t headerEnd{0}; ///< first byte after the header
    std::uint64_t dataBegin{0}; ///< first byte of the first variable's values (headerEnd without variables)
    std::uint64_t fixedEnd{0};  ///< end of the last non-record variable's values (0 without one)
    std::uint64_t recordEnd{0}; ///< end of the last record variable's values in the last record (0 without)

    /// The byte where the declared contents end: the largest of headerEnd, fixedEnd and recordEnd.
    std::uint64_t dataEnd() const;
};

/// Parses the classic header at the start of `in`, a file of `size` bytes. Never throws for bad bytes: version 0
/// when they are not a classic header, corrupt when they break the format after a classic magic number,
/// headerCut when they end inside it.
ClassicExtent classicExtent(std::istream &in, std::uint64_t size);

/// Why the classic-format file at `path` is shorter than its header declares ("is truncated: its header declares
/// N bytes of data ending at byte B, the file has S bytes (M missing)", or "is truncated: it ends inside its
/// header, after S bytes"); nullopt when it is complete, not a classic file, or cannot be read.
std::optional<std::string> classicTruncation(const std::string &path);
} // namespace gridded_detail
} // namespace ompl_glider

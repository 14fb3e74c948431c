#pragma once
/// @file GdalGrid.h
/// @brief Internal to the library (not installed): a gridded dataset read through GDAL's multidimensional API (Zarr v2
/// stores on disk or over HTTP, GRIB2 files), seen as GriddedDataset sees a NetCDF file: variables and dimensions by
/// index, CF attributes by name, values as doubles by hyperslab. So the forecast reader (current/gridded/) applies the
/// same rules to every layout: CF units and time, longitude conventions, land from fill values, the trip's region, only
/// the records and levels it needs read.
///
/// GDAL folds some CF attributes into properties of an array; they are given back under their CF names: `units`
/// (GDALMDArray::GetUnit()), `_FillValue` (the no-data value: Zarr's `fill_value`), `scale_factor` and `add_offset`
/// (GetScale()/GetOffset()). The values read are the stored ones (not unpacked), as nc_get_vara_double gives them.

#include "Dataset.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ompl_glider
{
namespace gridded_detail
{
/// (isGdalSource(), which sources are read here: GdalModule.h)
class GdalGrid final : public Dataset
{
public:
    /// The dataset of @p path: a URL's is opened once per process, a file's anew. Each keeps the blocks it read in
    /// memory (the reader asks for some twice: the grid's land, then its values; a GRIB message is decoded whole).
    static std::shared_ptr<GdalGrid> open(const std::string &path);

    /// Opens @p path (an http(s) URL through /vsicurl/, with the process's request time limit and retries,
    /// RemoteSource.h). @throws Error naming the source when GDAL cannot open it as a multidimensional dataset.
    explicit GdalGrid(const std::string &path);
    ~GdalGrid() override;
    GdalGrid(const GdalGrid &) = delete;
    GdalGrid &operator=(const GdalGrid &) = delete;

    /// "Zarr store '<path>'" or "GRIB file '<path>'".
    std::string who() const override;
    int nvars() const override;
    std::string varName(int var) const override;
    std::string dimName(int dim) const override;
    std::size_t dimLen(int dim) const override;
    std::optional<int> findVar(const std::string &name) const override;
    std::vector<int> varDims(int var) const override;
    ValueType varType(int var) const override;
    /// A text attribute of @p var (kGlobalAttributes: the root group's); nullopt when absent or numeric.
    std::optional<std::string> attText(int var, const char *name) const override;
    /// A numeric attribute's values (empty when absent); text yields {} and sets @p isText.
    std::vector<double> attDoubles(int var, const char *name, bool &isText) const override;
    /// The arrays GDAL lists (or the store's consolidated metadata names) but cannot open, each with GDAL's reason
    /// ("array 'uo' cannot be opened: Decompressor foo not handled"), joined; "" when every array opened.
    std::string unreadable() const override;
    /// The stored values of @p var in the block at @p start of @p count, as doubles. @throws Error naming the source
    /// and the variable when GDAL cannot read them (a missing or corrupt chunk, the server).
    void readBlock(int var, const std::vector<std::size_t> &start, const std::vector<std::size_t> &count,
                   double *out) const override;

private:
    struct Impl; // GdalGridImpl.h
    std::unique_ptr<Impl> impl_;
};
} // namespace gridded_detail
} // namespace ompl_glider

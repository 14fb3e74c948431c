#pragma once
/// @file GdalFaults.h
/// @brief Internal to the library (not installed): what is wrong with a source GDAL reads (GdalGrid), said in its own
/// words: GDAL's messages while a dataset is opened (a codec it does not handle, an array's metadata that is not
/// JSON), the arrays of a Zarr store's consolidated metadata GDAL left out, a GRIB file cut short or corrupt, a GRIB
/// file holding one velocity component of a pair.

#include <memory>
#include <set>
#include <string>
#include <vector>

#include <cpl_error.h>

class GDALMDArray;

namespace ompl_glider
{
namespace gridded_detail
{
/// GDAL's errors and warnings for the life of the object, kept in order (GDAL's last error alone would lose the
/// first), GDAL's own printing of them off.
class CollectGdalErrors
{
public:
    CollectGdalErrors();
    ~CollectGdalErrors();
    CollectGdalErrors(const CollectGdalErrors &) = delete;
    CollectGdalErrors &operator=(const CollectGdalErrors &) = delete;
    /// The messages from the @p from-th on, joined by "; " ("" when none).
    std::string since(std::size_t from) const;
    std::size_t count() const { return messages_.size(); }

private:
    static void CPL_STDCALL handler(CPLErr level, CPLErrorNum number, const char *message);
    std::vector<std::string> messages_;
};

/// Why the GRIB file at @p path (GDAL's virtual file names too) is not whole ("its message 7 at byte 26881 declares
/// 4510 bytes, the file ends after 2 of them: the file is truncated ..."; bytes between messages that are not a
/// message; a message not ending in "7777"); "" when every message is whole as its section 0 declares.
std::string gribTruncation(const std::string &path);

/// The arrays the consolidated metadata (`.zmetadata`) of the Zarr store at @p folder names ("uo", "grp/uo") that
/// are not in @p opened; none when the store has no consolidated metadata.
std::vector<std::string> droppedArrays(const std::string &folder, const std::set<std::string> &opened);

/// "holds UOGRD but no VOGRD ...: <why>" when the GRIB arrays @p vars (GDAL's attribute `name`) hold one velocity
/// component of a pair (UOGRD/VOGRD, UGRD/VGRD) without the other, with what gribTruncation() says of @p file;
/// "" otherwise.
std::string loneVelocityComponent(const std::vector<std::shared_ptr<GDALMDArray>> &vars, const std::string &file);
} // namespace gridded_detail
} // namespace ompl_glider

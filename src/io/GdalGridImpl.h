#pragma once
/// @file GdalGridImpl.h
/// @brief Internal to the library's GDAL part (not installed): what a GdalGrid holds (GdalGrid::Impl), shared by its
/// two files:
///
///  - GdalGrid.cpp   opening a store or a GRIB file, the queries of the Dataset interface, reading blocks
///  - GribTimes.cpp  the time dimension of a GRIB file's fields, assembled from GDAL's arrays; CF's names of GRIB2
///                   parameters

#include <algorithm>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <gdal_priv.h>

#include "GdalFaults.h"
#include "GdalGrid.h"
#include "HttpMirror.h"
#include "ompl_glider/io/FileList.h"

namespace ompl_glider
{
namespace gridded_detail
{
/// CF's standard name of a GRIB2 parameter (its short name, as GDAL's "name" attribute gives it): the currents of
/// ocean models (RTOFS) and the winds of weather models (for vehicles in wind); nullopt for another (GribTimes.cpp).
std::optional<std::string> gribStandardName(const std::string &shortName);

struct GdalGrid::Impl
{
    std::string path;
    DatasetKind kind{DatasetKind::ZarrStore};
    bool geographic{false}; // GRIB: the arrays' grid is in longitude and latitude
    // (declared before the dataset: destroyed after it)
    std::unique_ptr<ZarrMirror> mirror; // a store over HTTP: what was fetched of it (GDAL reads the mirror)
    std::unique_ptr<FileMirror> file;   // a GRIB file over HTTP: its copy (GDAL reads the copy)
    std::unique_ptr<GDALDataset> dataset;
    std::unique_ptr<GDALDataset> timeHolder; // the in-memory dataset of an added time coordinate (addFileTime())
    std::shared_ptr<GDALGroup> root;
    std::vector<std::shared_ptr<GDALMDArray>> vars;
    /// A GRIB field: a 2-D array (record -1), or record `record` of a 3-D array over GDAL's TIME dimension.
    struct Field
    {
        std::shared_ptr<GDALMDArray> array;
        long record{-1};
    };
    /// per var: the GRIB fields of one parameter and level, one per time of the added time dimension (empty: the
    /// array as GDAL gives it)
    std::vector<std::vector<Field>> series;
    int timeDim{-1}; // that dimension, -1 without
    std::vector<std::shared_ptr<GDALDimension>> dims;
    std::map<std::string, int> dimIndex; // by full name
    mutable std::mutex mutex;            // GDAL's datasets are not thread-safe
    struct Block
    {
        int var;
        std::vector<std::size_t> start, count;
        std::vector<double> values;
    };
    std::vector<Block> blocks; // the blocks read so far (a URL's chunks fetched, a GRIB message decoded, once)

    int dimOf(const std::shared_ptr<GDALDimension> &d)
    {
        const auto [it, added] = dimIndex.emplace(d->GetFullName(), static_cast<int>(dims.size()));
        if (added)
            dims.push_back(d);
        return it->second;
    }

    std::vector<std::string> unreadable; // "array 'uo': <GDAL's reason>", the arrays GDAL lists but cannot open

    void addGroup(const std::shared_ptr<GDALGroup> &g, CollectGdalErrors &errors)
    {
        for (const std::string &name : g->GetMDArrayNames())
        {
            const std::size_t before = errors.count();
            if (auto a = g->OpenMDArray(name))
                vars.push_back(a);
            else
            {
                const std::string why = errors.since(before);
                unreadable.push_back("array '" + (g->GetFullName() == "/" ? "" : g->GetFullName().substr(1) + "/") +
                                     name + "' cannot be opened" + (why.empty() ? std::string() : ": " + why));
            }
        }
        for (const std::string &name : g->GetGroupNames()) // GRIB: none; a store's subgroups
            if (auto sub = g->OpenGroup(name))
                addGroup(sub, errors);
    }

    /// The fields of a GRIB file over one time dimension, where GDAL gives some field of some time its own 2-D array
    /// with the time only in attributes (GribTimes.cpp).
    void addFileTime();
    /// A velocity parameter (UOGRD, VOGRD, UGRD, VGRD) missing at one of @p times is refused, naming the time.
    void refuseGap(const std::string &key, const std::map<double, Field> &byTime, const std::set<double> &times) const;

    /// The arrays of the store's consolidated metadata at @p folder that GDAL left out, with @p why.
    void addDropped(const std::string &folder, const std::string &why)
    {
        std::set<std::string> opened;
        for (const auto &a : vars)
            opened.insert(a->GetFullName().substr(1));
        for (const std::string &name : droppedArrays(folder, opened))
            if (std::none_of(unreadable.begin(), unreadable.end(),
                             [&](const std::string &u) { return u.rfind("array '" + name + "'", 0) == 0; }))
                unreadable.push_back("array '" + name + "' of its consolidated metadata cannot be opened" +
                                     (why.empty() ? std::string() : ": " + why));
    }

    static std::vector<double> readAll(const GDALMDArray &a)
    {
        std::vector<double> v(a.GetTotalElementsCount());
        const GUInt64 first = 0;
        const std::size_t n = v.size();
        if (a.GetDimensionCount() != 1 ||
            !a.Read(&first, &n, nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64), v.data()))
            return {};
        return v;
    }

    bool hasAddedTime(int var) const
    {
        return static_cast<std::size_t>(var) < series.size() && !series[static_cast<std::size_t>(var)].empty();
    }

    std::shared_ptr<GDALAttribute> attribute(int var, const char *name) const
    {
        return var == kGlobalAttributes ? root->GetAttribute(name)
                                        : vars.at(static_cast<std::size_t>(var))->GetAttribute(name);
    }
};
} // namespace gridded_detail
} // namespace ompl_glider

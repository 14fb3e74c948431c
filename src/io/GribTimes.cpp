// The time dimension of a GRIB file's fields, assembled from GDAL's arrays (see GdalGridImpl.h), and CF's names of
// GRIB2 parameters.
#include <algorithm>
#include <cstring>
#include <ctime>
#include <map>
#include <set>

#include "GdalGridImpl.h"
#include "ompl_glider/Exception.h"
#include "ompl_glider/io/RemoteSource.h"

namespace ompl_glider
{
namespace gridded_detail
{
/// CF's standard name of a GRIB2 parameter (its short name, as GDAL's "name" attribute gives it): the currents of
/// ocean models (RTOFS) and the winds of weather models (for vehicles in wind).
std::optional<std::string> gribStandardName(const std::string &shortName)
{
    static const std::map<std::string, std::string> names = {{"UOGRD", "eastward_sea_water_velocity"},
                                                             {"VOGRD", "northward_sea_water_velocity"},
                                                             {"UGRD", "eastward_wind"},
                                                             {"VGRD", "northward_wind"}};
    const auto it = names.find(shortName);
    return it == names.end() ? std::nullopt : std::optional<std::string>(it->second);
}

/// The fields of a GRIB file over one time dimension, where GDAL gives some field of some time its own 2-D array
/// with the time only in attributes: a file of one forecast time (RTOFS writes one per forecast hour), or several
/// times with the parameters interleaved (U, V of one time, then of the next: ERA5-like downloads), which GDAL
/// gives as 2-D arrays and, where records of one parameter follow each other, 3-D arrays over a TIME dimension.
/// The fields of one parameter and level (attributes `name`, `first_level`), wherever GDAL put them, become one
/// variable over the file's times (`validity_time`, or the TIME coordinate: seconds of the Unix epoch); several
/// files of one time each then read as one forecast. A velocity parameter missing at one of the times is refused
/// (its fields alone would plan on one time in silence); another parameter missing somewhere stays as GDAL gives
/// it. A file whose fields GDAL gave all as TIME arrays is read as GDAL gives it.
void GdalGrid::Impl::addFileTime()
{
    std::map<std::string, std::map<double, Field>> fields; // name|level -> time -> field
    std::vector<std::string> order;                        // the parameters in the file's order
    std::set<std::size_t> used;                            // the vars that hold fields
    std::set<double> times;
    bool loose = false; // some field is a 2-D array of its own
    for (std::size_t k = 0; k < vars.size(); ++k)
    {
        const auto &a = vars[k];
        std::string key;
        for (const char *name : {"name", "first_level"})
            if (auto text = a->GetAttribute(name); text && text->GetDataType().GetClass() == GEDTC_STRING)
                key += std::string(text->ReadAsString() ? text->ReadAsString() : "") + "|";
        std::vector<std::pair<double, long>> at; // (time, record; -1: the 2-D array itself)
        const auto &d = a->GetDimensions();
        if (!d.empty() && d[0]->GetType() == GDAL_DIM_TYPE_TEMPORAL && d.size() == 3)
        {
            const auto axis = d[0]->GetIndexingVariable();
            const std::vector<double> values = axis ? readAll(*axis) : std::vector<double>{};
            if (values.size() != d[0]->GetSize())
                return;
            for (std::size_t r = 0; r < values.size(); ++r)
                at.emplace_back(values[r], static_cast<long>(r));
        }
        else if (const auto t = a->GetAttribute("validity_time"); t && d.size() == 2)
        {
            at.emplace_back(t->ReadAsDouble(), -1);
            loose = true;
        }
        if (at.empty() || key.empty())
            continue;
        if (!fields.count(key))
            order.push_back(key);
        for (const auto &[time, record] : at)
        {
            if (!fields[key].emplace(time, Field{a, record}).second)
                return; // two fields of one parameter, level and time: GDAL's arrays as they are
            times.insert(time);
        }
        used.insert(k);
    }
    if (!loose)
        return;
    for (auto it = fields.begin(); it != fields.end();)
    {
        if (it->second.size() == times.size())
        {
            ++it;
            continue;
        }
        refuseGap(it->first, it->second, times);
        for (const auto &[time, f] : it->second) // not a velocity: its arrays as GDAL gives them
            for (std::size_t k = 0; k < vars.size(); ++k)
                if (vars[k] == f.array)
                    used.erase(k);
        order.erase(std::find(order.begin(), order.end(), it->first));
        it = fields.erase(it);
    }
    GDALDriver *mem = GetGDALDriverManager()->GetDriverByName("MEM");
    if (fields.empty() || !mem)
        return;
    const std::vector<double> values(times.begin(), times.end());
    timeHolder.reset(mem->CreateMultiDimensional("time", nullptr, nullptr));
    auto group = timeHolder ? timeHolder->GetRootGroup() : nullptr;
    auto dim = group ? group->CreateDimension("time", GDAL_DIM_TYPE_TEMPORAL, "", values.size()) : nullptr;
    auto array = dim ? group->CreateMDArray("time", {dim}, GDALExtendedDataType::Create(GDT_Float64)) : nullptr;
    const GUInt64 first = 0;
    const std::size_t n = values.size();
    if (!array ||
        !array->Write(&first, &n, nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64), values.data()) ||
        !array->SetUnit("sec UTC"))
        return;
    // one variable per parameter and level, its earliest field standing for it (name, attributes, type); the
    // arrays of other parameters as GDAL gives them
    std::vector<std::shared_ptr<GDALMDArray>> kept;
    std::vector<std::vector<Field>> keptSeries;
    for (std::size_t k = 0; k < vars.size(); ++k)
        if (!used.count(k))
        {
            kept.push_back(vars[k]);
            keptSeries.emplace_back();
        }
    for (const std::string &key : order)
    {
        std::vector<Field> one;
        for (const auto &[time, f] : fields.at(key))
            one.push_back(f);
        kept.push_back(one.front().array);
        keptSeries.push_back(one);
    }
    timeDim = dimOf(dim);
    kept.push_back(array);
    keptSeries.emplace_back();
    vars = kept;
    series = keptSeries;
}

/// A velocity parameter (UOGRD, VOGRD, UGRD, VGRD) missing at one of @p times is refused, naming the time.
void GdalGrid::Impl::refuseGap(const std::string &key, const std::map<double, Field> &byTime,
                               const std::set<double> &times) const
{
    const std::string parameter = key.substr(0, key.find('|'));
    if (!gribStandardName(parameter))
        return;
    double missing = 0.0;
    for (const double t : times)
        if (!byTime.count(t))
        {
            missing = t;
            break;
        }
    const std::time_t when = static_cast<std::time_t>(missing);
    char date[32] = "?";
    if (const std::tm *tm = std::gmtime(&when))
        std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", tm);
    throw Error(datasetWho(kind, withoutCredentials(path)) + ": " + parameter + " has fields at " +
                std::to_string(byTime.size()) + " of the " + std::to_string(times.size()) +
                " times of the file (none at " + date + "): a forecast needs its currents at every time");
}
} // namespace gridded_detail
} // namespace ompl_glider

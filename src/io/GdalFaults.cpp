// What is wrong with a source GDAL reads, in its own words (see GdalFaults.h).
#include "GdalFaults.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include <cpl_json.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>

namespace ompl_glider
{
namespace gridded_detail
{
CollectGdalErrors::CollectGdalErrors()
{
    CPLPushErrorHandlerEx(&CollectGdalErrors::handler, this);
    CPLErrorReset();
}

CollectGdalErrors::~CollectGdalErrors()
{
    CPLPopErrorHandler();
}

void CPL_STDCALL CollectGdalErrors::handler(CPLErr level, CPLErrorNum, const char *message)
{
    auto *self = static_cast<CollectGdalErrors *>(CPLGetErrorHandlerUserData());
    if (self && level >= CE_Warning && message && *message &&
        std::find(self->messages_.begin(), self->messages_.end(), message) == self->messages_.end())
        self->messages_.emplace_back(message);
}

std::string CollectGdalErrors::since(std::size_t from) const
{
    std::string out;
    for (std::size_t k = from; k < messages_.size(); ++k)
        out += (out.empty() ? "" : "; ") + messages_[k];
    return out;
}

std::string gribTruncation(const std::string &path)
{
    VSILFILE *f = VSIFOpenL(path.c_str(), "rb");
    if (!f)
        return "";
    VSIFSeekL(f, 0, SEEK_END);
    const vsi_l_offset size = VSIFTellL(f);
    vsi_l_offset at = 0;
    std::string why;
    for (int message = 1; at < size && why.empty(); ++message)
    {
        unsigned char head[16] = {};
        VSIFSeekL(f, at, SEEK_SET);
        const std::size_t got = VSIFReadL(head, 1, sizeof head, f);
        if (got < 8 || std::memcmp(head, "GRIB", 4) != 0)
        {
            why = "at byte " + std::to_string(at) + ", after " + std::to_string(message - 1) + " whole message(s), " +
                  (got < 8 && at + got == size ? "the file ends inside a message's first bytes: the file is truncated"
                                               : "the bytes are not a GRIB message: the file is corrupt");
            break;
        }
        vsi_l_offset length = 0;
        if (head[7] == 2 && got == sizeof head)
            for (int k = 8; k < 16; ++k)
                length = (length << 8) | head[k];
        else if (head[7] == 1)
            length = (vsi_l_offset(head[4]) << 16) | (vsi_l_offset(head[5]) << 8) | head[6];
        else
            break; // an edition GDAL judges itself
        char tail[4] = {};
        if (length < 16 || at + length > size)
            why = "its message " + std::to_string(message) + " at byte " + std::to_string(at) + " declares " +
                  std::to_string(length) + " bytes, the file ends after " + std::to_string(size - at) +
                  " of them: the file is truncated (a download cut short?)";
        else if (VSIFSeekL(f, at + length - 4, SEEK_SET) != 0 || VSIFReadL(tail, 1, 4, f) != 4 ||
                 std::memcmp(tail, "7777", 4) != 0)
            why = "its message " + std::to_string(message) + " at byte " + std::to_string(at) +
                  " does not end in "
                  "'7777' where its length says: the file is corrupt";
        at += length;
    }
    VSIFCloseL(f);
    return why;
}

std::vector<std::string> droppedArrays(const std::string &folder, const std::set<std::string> &opened)
{
    CPLJSONDocument doc;
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const bool parsed = doc.Load(folder + "/.zmetadata");
    CPLPopErrorHandler();
    std::vector<std::string> out;
    if (!parsed)
        return out;
    for (const CPLJSONObject &entry : doc.GetRoot().GetObj("metadata").GetChildren())
    {
        const std::string key = entry.GetName();
        if (key.size() < 8 || key.compare(key.size() - 8, 8, "/.zarray") != 0)
            continue;
        const std::string name = key.substr(0, key.size() - 8);
        if (!opened.count(name))
            out.push_back(name);
    }
    return out;
}

std::string loneVelocityComponent(const std::vector<std::shared_ptr<GDALMDArray>> &vars, const std::string &file)
{
    std::set<std::string> parameters;
    for (const auto &a : vars)
        if (auto n = a->GetAttribute("name"); n && n->GetDataType().GetClass() == GEDTC_STRING && n->ReadAsString())
            parameters.insert(n->ReadAsString());
    for (const auto &[u, v] : {std::pair<std::string, std::string>{"UOGRD", "VOGRD"}, {"UGRD", "VGRD"}})
        if (parameters.count(u) != parameters.count(v))
        {
            const std::string has = parameters.count(u) ? u : v, lacks = parameters.count(u) ? v : u;
            const std::string cut = gribTruncation(file);
            return "holds " + has + " but no " + lacks + " (the other velocity component)" +
                   (cut.empty() ? ": the file may be cut short at the end of a message (a download stopped early), "
                                  "or hold one of the two parameters only; give a file with both"
                                : ": " + cut);
        }
    return "";
}
} // namespace gridded_detail
} // namespace ompl_glider

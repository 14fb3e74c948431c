#pragma once
// JSON values of the output layer's files (summary.json, the GeoJSON, fleet summaries): a number that is not finite
// and an empty text are written as null, never as NaN or "".
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

namespace ompl_glider
{
namespace output_json
{
using json = nlohmann::ordered_json;

inline json jnum(double v)
{
    return std::isfinite(v) ? json(v) : json(nullptr);
}

inline json jtext(const std::string &s)
{
    return s.empty() ? json(nullptr) : json(s);
}

/// The text of a JSON value, bytes that are not UTF-8 (a Latin-1 file or mission name) written as U+FFFD rather than
/// thrown (nlohmann's type_error.316 would end a finished plan).
template <class Json> std::string utf8Dump(const Json &j, int indent = -1)
{
    return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}
} // namespace output_json
} // namespace ompl_glider

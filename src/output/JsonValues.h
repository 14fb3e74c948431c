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
}  // namespace output_json
}  // namespace ompl_glider

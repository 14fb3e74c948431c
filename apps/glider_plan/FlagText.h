#pragma once
/// @file FlagText.h
/// @brief Internal to glider_plan: flag values read as numbers, pairs, lists and boxes, refused with a UsageError
/// naming the flag.

#include <optional>
#include <string>
#include <vector>

#include "Flags.h"
#include "ompl_glider/Geometry.h"

namespace glider_plan
{
/// @brief The whole of @p text as a finite number, or nullopt.
std::optional<double> finiteNumber(const std::string &text);
/// @brief @p text as a finite number. @throws UsageError naming @p flag.
double number(const std::string &flag, const std::string &text);
/// @brief "x,y" as two finite numbers. @throws UsageError naming @p flag.
ompl_glider::Point2 pair(const std::string &flag, const std::string &text);
/// @brief The comma-separated items of a flag's value, empty ones included ("a,,b" -> a, "", b).
std::vector<std::string> commaItems(const std::string &text);
/// @brief Four numbers separated by commas (--region), in GeoJSON bbox order: x_min,y_min,x_max,y_max (for a
/// geographic file lon_min,lat_min,lon_max,lat_max), as given. @throws UsageError naming @p flag.
ompl_glider::Box quad(const std::string &flag, const std::string &text);
} // namespace glider_plan

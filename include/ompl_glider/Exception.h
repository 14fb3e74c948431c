#pragma once
/// @file Exception.h
/// @brief The library's exception type for configuration and I/O errors.

#include <stdexcept>
#include <string>

namespace ompl_glider
{
/// @brief Thrown for bad configuration or input (a missing NetCDF variable, a wrong mission field, ...).
/// The message says what was wrong and where (file, variable or field, and what was expected).
/// Planning outcomes (no path found) are reported through ompl::base::PlannerStatus, never with this type.
class Error : public std::runtime_error
{
public:
    explicit Error(const std::string &what) : std::runtime_error(what)
    {
    }
};
}  // namespace ompl_glider

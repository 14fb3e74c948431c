#pragma once
/// @file Exception.h
/// @brief The library's exception type for configuration and I/O errors.

#include <stdexcept>
#include <string>
#include <utility>

namespace ompl_glider
{
/// @brief Thrown for bad configuration or input (a missing NetCDF variable, a wrong mission field, ...).
/// The message says what was wrong and where (file, variable or field, and what was expected).
/// Planning outcomes (no path found) are reported through ompl::base::PlannerStatus, never with this type.
/// An error about one setting carries it (field()), so that a caller places it on that setting (a mission file's
/// line, a flag, a keyword) without reading the message.
class Error : public std::runtime_error
{
public:
    explicit Error(const std::string &what) : std::runtime_error(what) {}
    /// @brief An error about the setting @p field (the thrower's name for it: "GriddedCurrentOptions::timeUnits" in
    /// the forecast reader, a dotted mission field above it).
    Error(const std::string &what, std::string field) : std::runtime_error(what), field_(std::move(field)) {}
    /// @brief The setting at fault; empty when the error is not about one setting.
    const std::string &field() const { return field_; }

private:
    std::string field_;
};
} // namespace ompl_glider

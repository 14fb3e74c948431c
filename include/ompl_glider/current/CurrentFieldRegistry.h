#pragma once
/// @file CurrentFieldRegistry.h
/// @brief The kinds of current field known by name (mission files' `current.type`, the command line, the docs).
/// Adding an analytic flow is one entry here (see docs/ARCHITECTURE.md).

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/current/CurrentField.h"

namespace ompl_glider
{
/// @brief One kind of current field.
struct CurrentFieldKind
{
    std::string name;         ///< e.g. "meandering_jet", "netcdf"
    std::string description;  ///< one line for the docs and messages
    /// Parameters of an analytic kind with their defaults (empty for gridded kinds, which take a file).
    std::vector<std::pair<std::string, double>> parameters;
    bool gridded{false};  ///< read from a file (NetCDF); made by the NetCDF loader, not by make
    /// Makes an analytic field from a complete parameter map (every name of `parameters`); null for gridded kinds.
    std::function<std::shared_ptr<const CurrentField>(const std::map<std::string, double> &)> make;
};

/// @brief Every kind: meandering_jet ([EichhornRAS] Sec. 6.1), uniform, linear_shear, double_gyre ([ShaddenLCS]),
/// rankine_vortex ([LollaLevelSet]), netcdf.
const std::vector<CurrentFieldKind> &currentFieldKinds();

/// @brief The kind called @p name; null when there is none.
const CurrentFieldKind *findCurrentFieldKind(const std::string &name);

/// @brief The names of all kinds joined by @p separator.
std::string currentFieldKindList(const std::string &separator = ", ");

/// @brief Makes an analytic field of kind @p name; missing parameters take their defaults.
/// @throws Error for an unknown kind, a gridded kind or a parameter the kind does not have.
std::shared_ptr<const CurrentField> makeAnalyticField(const std::string &name,
                                                      const std::map<std::string, double> &parameters = {});
}  // namespace ompl_glider

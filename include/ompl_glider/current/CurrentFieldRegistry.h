#pragma once
/// @file CurrentFieldRegistry.h
/// @brief The kinds of current field known by name (mission files' `current.type`, the command line, the docs):
/// analytic flows made from parameters, and gridded sources that read a forecast (ForecastSource.h). Adding an
/// analytic flow is one entry here; adding a gridded source is a GriddedSource and one entry here or a
/// registerCurrentFieldKind() call (see docs/ARCHITECTURE.md).

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ompl_glider/current/CurrentField.h"
#include "ompl_glider/current/ForecastSource.h"

namespace ompl_glider
{
/// @brief One kind of current field.
struct CurrentFieldKind
{
    std::string name;        ///< e.g. "meandering_jet", "gridded"
    std::string description; ///< one line for the docs and messages
    /// Parameters of an analytic kind with their defaults (empty for gridded kinds, which take a file).
    std::vector<std::pair<std::string, double>> parameters;
    /// Makes an analytic field from a complete parameter map (every name of `parameters`); null for gridded kinds.
    std::function<std::shared_ptr<const CurrentField>(const std::map<std::string, double> &)> make;
    /// The source that reads a gridded kind's forecast (files, folders or URLs); null for analytic kinds.
    std::shared_ptr<const GriddedSource> source;

    /// @brief Read from files by a source (not made from parameters).
    bool gridded() const { return source != nullptr; }
};

/// @brief Every kind: meandering_jet ([EichhornRAS] Sec. 6.1), uniform, linear_shear, double_gyre ([ShaddenLCS]),
/// rankine_vortex ([LollaLevelSet]), gridded (alias netcdf: NetCDF files, OPeNDAP, Zarr and GRIB:
/// griddedForecastSource()), then those of registerCurrentFieldKind(). A deque: an entry never moves.
const std::deque<CurrentFieldKind> &currentFieldKinds();

/// @brief Adds @p kind, so that mission files, the command line's forecast missions (ForecastInput::current.type)
/// and Python can ask for it by name like a built-in kind (a source of an application, or one a test registers).
/// Call it before planning starts, not while other threads plan; pointers from findCurrentFieldKind() stay valid.
/// @throws Error when the kind has no name, has neither a make function nor a source (or both), or its name is
/// taken (as a name or an alias).
void registerCurrentFieldKind(CurrentFieldKind kind);

/// @brief Makes @p alias another name of the kind called @p name: findCurrentFieldKind(alias) finds it, and mission
/// files, the command line and Python may give either. A mission keeps the name it was given (CurrentSpec::type), so
/// its outputs say what its file says. The built-in alias: "netcdf" for `gridded` (its name before it read OPeNDAP,
/// Zarr and GRIB too). Call it before planning starts, as registerCurrentFieldKind().
/// @throws Error when there is no kind @p name, or @p alias is empty or taken (as a name or an alias).
void addCurrentFieldKindAlias(const std::string &alias, const std::string &name);

/// @brief The other names of @p kind (addCurrentFieldKindAlias()), in the order they were added.
std::vector<std::string> currentFieldKindAliases(const CurrentFieldKind &kind);

/// @brief The kind called @p name, by its name or one of its aliases ("netcdf" finds `gridded`); null when there is
/// none.
const CurrentFieldKind *findCurrentFieldKind(const std::string &name);

/// @brief True when @p name (a name or an alias) is a kind read from files by a gridded source; false for an
/// analytic flow or an unknown name.
bool isGriddedKind(const std::string &name);

/// @brief Every name a mission may give (the kinds' names and their aliases), as `current.type` accepts them.
std::vector<std::string> currentFieldKindNames();

/// @brief The names of all kinds joined by @p separator (their names, not their aliases).
std::string currentFieldKindList(const std::string &separator = ", ");

/// @brief True when the analytic flow @p kind has the parameter @p name.
bool hasParameter(const CurrentFieldKind &kind, const std::string &name);

/// @brief The parameters of @p kind by name, comma-separated ("B0, c, k, omega, eps, L"): what a message about an
/// unknown parameter lists.
std::string parameterNameList(const CurrentFieldKind &kind);

/// @brief The names of the gridded kinds joined by @p separator ("gridded"; not their aliases).
std::string griddedKindList(const std::string &separator = ", ");

/// @brief Makes an analytic field of kind @p name; missing parameters take their defaults.
/// @throws Error for an unknown kind, a gridded kind or a parameter the kind does not have.
std::shared_ptr<const CurrentField> makeAnalyticField(const std::string &name,
                                                      const std::map<std::string, double> &parameters = {});
} // namespace ompl_glider

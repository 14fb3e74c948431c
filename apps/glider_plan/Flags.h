#pragma once
/// @file Flags.h
/// @brief glider_plan's command line: the flags, their checks and the MissionSpec they describe for the built-in
/// mode and the --currents mode. Running, printing and exit codes are main.cpp's; this part is also linked by the
/// command-line fuzzer (fuzz/fuzz_cli.cpp).

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "ompl_glider/mission/ForecastMission.h"
#include "ompl_glider/mission/MissionSpec.h"
#include "ompl_glider/mission/Overrides.h"

namespace glider_plan
{
/// @brief A bad flag value: exit 2 with the message.
struct UsageError
{
    std::string message;
};

/// @brief Everything the flags say.
struct Flags
{
    std::string mission, currents, out, start, goal, departure, planner, coastline, region, arriveBetween;
    std::string via, order;            ///< --via 'lon,lat;lon,lat', --order given|free
    std::string observations;          ///< --observations PATH: the glider's DAC files
    std::string observationsCache;     ///< --observations-cache DIR: a Slocum's cache files
    bool runs{false};                  ///< --runs: the --currents files are forecast runs
    std::optional<std::string> speeds; // given, even empty, is a sweep request
    std::optional<double> speed, gridSize, timeLimit, depth;
    std::optional<int> sectors;
    bool noSmooth{false}, noRefine{false}, noGlobalCheck{false}, optimum{false}, verbose{false};
    // reachable-set contours: --isochrones, --isochrone-interval
    bool isochrones{false};
    std::string isochroneInterval;
    // the probability of reach: --reachability, --reach-horizon, --reach-interval
    bool reachability{false};
    std::string reachHorizon, reachInterval;
    std::optional<double> gotoTurn; // --goto-turn: the goto list's turn threshold in degrees
    std::string holdTolerance;      // --hold-tolerance: the uploads' merged holds (metres, or with a unit)
    // forecasts from OPeNDAP servers: --cache, --request-timeout, --retries (io/RemoteSource.h)
    std::string cache;
    std::optional<double> requestTimeout;
    std::optional<int> retries;
    // execution in another ocean (any of these enables it)
    std::string truth, surfacingInterval, strategies, acrossRuns;
    std::optional<double> radius;
    std::optional<unsigned> executionPairs, executionSeed;
    ompl_glider::ForecastInput forecast;
    // safety margins: --keep-off, --bathymetry, --bathymetry-variable, --min-depth
    std::string keepOff, bathymetry, bathymetryVariable, minDepth;
    bool snapToWater{false};      ///< --snap-to-water
    bool showMission{false};      ///< --show-mission: print the fields the flags can change, plan nothing
    bool showObservations{false}; ///< --show-observations: print the fixes and DAC of --observations, plan nothing
};

/// @brief How the command line names the mission's settings in messages (MissionSpec::term()): its flags.
std::shared_ptr<const ompl_glider::SettingWords> flagWords();

/// @brief The flags that Python's keywords share, as the library's typed overrides (Overrides.h), each named by its
/// flag. @throws UsageError for a malformed pair, box or window.
ompl_glider::MissionOverrides overridesOf(const Flags &f);

/// @brief Declares every flag on @p app, storing into @p f (which must outlive @p app).
void defineFlags(CLI::App &app, Flags &f);

/// @brief Flags that do not go together (--mission with --currents or its NetCDF options; the NetCDF flags need
/// --currents; --currents needs --start and --goal). @throws UsageError naming the flag.
void checkCombinations(const CLI::App &app, const Flags &f);

/// @brief app.parse() then checkCombinations(). @throws CLI::ParseError (CLI::CallForHelp for --help) or
/// UsageError.
void parseFlags(CLI::App &app, const Flags &f, int argc, const char *const *argv);

/// @brief The speed list of --speeds ("0.25,0.30,0.35"). @throws UsageError unless every item is a number > 0.
std::vector<double> speedList(const std::string &text);

/// @brief The built-in Gulf Stream mission with the flags applied. @throws UsageError for a malformed number.
ompl_glider::MissionSpec builtInMission(const Flags &f);

/// @brief The mission file of --mission with the flags applied on top of it: a flag given replaces the field it
/// names (planner, grid, sectors, time limit, smoothing, speed, start, goal, departure, region, arrival window,
/// coastline, execution, --out; the planner's parameters are dropped when --planner names another planner).
/// @throws UsageError for a malformed flag, ompl_glider::Error for the file.
ompl_glider::MissionSpec missionFileOf(const Flags &f);

/// @brief The mission of a --currents forecast (reads the file's time axis and grid: forecastMission()).
/// @throws UsageError for a malformed --start/--goal, ompl_glider::Error for the file and the request.
ompl_glider::MissionSpec forecastMissionOf(Flags f);
} // namespace glider_plan

#pragma once
/// @file FleetFiles.h
/// @brief The outputs of a fleet (mission `fleet`, mission/Fleet.h): one folder per glider under the output
/// directory, holding the glider's files as outputFiles() makes them, beside fleet.csv (one row per glider) and a
/// summary.json with the fleet's table; all written in one transaction (writeOutputFiles()).

#include <ostream>
#include <string>
#include <vector>

#include "ompl_glider/mission/Fleet.h"
#include "ompl_glider/output/OutputWriter.h"

namespace ompl_glider
{
/// @brief The files outputFiles() makes of @p result, rendered to bytes (written in a private temporary directory
/// and read back): runFleet()'s keep function, so that the files travel between the processes of a job as they are.
/// @throws Error when a file cannot be made.
std::string renderOutputFiles(const MissionResult &result, const MissionProblem &problem);

/// @brief fleet.csv: name, status, travel_time, path_length (field units), departure, arrival_time,
/// departure_iso, arrival_iso, reason.
std::string fleetCsv(const std::vector<FleetGlider> &gliders);

/// @brief The fleet's files: each glider's rendered files in its folder ("NAME/summary.json"), fleet.csv and a
/// summary.json whose `fleet` array holds the table and whose `files` list every file.
std::vector<OutputFile> fleetOutputFiles(const MissionSpec &mission, const std::vector<FleetGlider> &gliders,
                                         double wallSeconds);

/// @brief The fleet's table for the terminal: glider, status, travel time, path length, arrival (hours and km
/// where the mission's units are physical).
void printFleetTable(std::ostream &out, const MissionSpec &mission, const std::vector<FleetGlider> &gliders);
} // namespace ompl_glider

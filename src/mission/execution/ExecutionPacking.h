#pragma once
/// @file ExecutionPacking.h
/// @brief Internal to the library (not installed): an execution run as bytes (every bit of its numbers), for the
/// processes of a job (MissionExecution.cpp spreads the runs over them).

#include <string>

#include "ompl_glider/mission/MissionExecution.h"

namespace ompl_glider
{
namespace execution_detail
{
/// @p run as bytes: its plan, held headings, legs and every strategy's flight.
std::string packRun(const ExecutionRun &run);
/// The run packRun() wrote, into @p run.
void unpackRun(const std::string &bytes, ExecutionRun &run);
} // namespace execution_detail
} // namespace ompl_glider

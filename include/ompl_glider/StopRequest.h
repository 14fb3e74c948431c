#pragma once
/// @file StopRequest.h
/// @brief A request to stop the plans under way in this process (Python's Ctrl-C): their searches end at their next
/// check, as at a time limit, and they return without a path, saying they were stopped.

namespace ompl_glider
{
/// @brief Asks every plan running in this process to stop (async-signal-safe: one atomic store).
void requestStop();
/// @brief Clears the request (the next plans run to their end).
void clearStop();
/// @brief True while a stop is requested.
bool stopRequested();
} // namespace ompl_glider

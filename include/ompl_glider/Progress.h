#pragma once
/// @file Progress.h
/// @brief The one way the library reports progress of long runs (departure-time search, speed sweep): a
/// replaceable sink. The library never writes to stderr itself; the command line prints what the sink receives.

#include <functional>
#include <string>

namespace ompl_glider
{
/// @brief Receives a progress line; @p done is true for the last line of a phase (e.g. "12/12 departures searched").
/// An empty sink reports nothing.
using ProgressSink = std::function<void(const std::string &line, bool done)>;
} // namespace ompl_glider

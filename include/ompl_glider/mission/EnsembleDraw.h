#pragma once
/// @file EnsembleDraw.h
/// @brief An ensemble of an analytic flow drawn from one set of parameters (`current: {type: ..., parameters: ...,
/// members: N, spread: {...}, seed: S}`): expanded when the mission is read into the members a listed ensemble
/// (`current: {ensemble: [...]}`) would have, so that every ensemble feature takes it as it is.

#include <string>
#include <vector>

#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider
{
/// @brief The @p count members drawn from @p control (an analytic kind). Member 0 is the control run: @p control's
/// parameters, each spread parameter it does not give set to its kind's default. Members 1..count-1 draw, member by
/// member and within a member the spread parameters in the order of their names, p (1 + s u) with u =
/// -1 + 2 (x + 0.5) / 2^32 for x the next output of std::mt19937(draw.seed): uniform in (-1, 1) and the same on every
/// standard library (std::uniform_real_distribution is not). A parameter without a spread keeps its value. Each
/// member is @p control with its own parameters, without members or draw of its own.
/// @throws Error for a gridded or unknown kind, a spread parameter the kind does not have, a spread outside [0, 1)
/// or a count below 2.
std::vector<CurrentSpec> drawEnsembleMembers(const CurrentSpec &control, unsigned count,
                                             const CurrentSpec::EnsembleDraw &draw);

/// @brief One line on the ensemble of @p c for the report: "meandering_jet ensemble of 24 members (control + 23
/// drawn, spread B0 25 %, c 25 %, k 25 %, seed 7)", "... of 3 members (listed)"; empty without members.
std::string ensembleDescription(const CurrentSpec &c);
} // namespace ompl_glider

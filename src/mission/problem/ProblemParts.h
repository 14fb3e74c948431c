#pragma once
// What the files of MissionProblem share: MissionProblem.cpp (the inputs: endpoints in the planning frame, the box,
// the projection, times, the glider problem), ProblemField.cpp (the field), ProblemLand.cpp and Safety.cpp (land
// and safety), Endpoints.cpp (a start or goal on land), FieldChecks.cpp (checks of the sources).

#include <string>

#include "ompl_glider/mission/MissionSpec.h"

namespace ompl_glider
{
/// "FILE:LINE: " of a mark from a mission file, else "MISSION_FILE: ".
std::string sourcePlace(const MissionSpec &m, const SourceMark &mark = {});
} // namespace ompl_glider

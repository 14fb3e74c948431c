# mission/: a mission as the pilot describes it, the problem it makes, the one planning pipeline and the plan flown.
# One folder a concept (docs/ARCHITECTURE.md, the mission/ row of the layers):
#   loader/     mission files: the YAML reader and one file a section
#   settings/       what the front ends give: overrides, the settings' declared ranges, forecast missions, output names
#   inputs/     what a mission reads, once (ProblemInputs): resuming at the last fix, the forecast, its members and
#               truth, the planning frame, the glider's observations, the coastline and the bathymetry
#   problem/    MissionProblem, built from the inputs and reading nothing: endpoints, the correction by the DAC,
#               forbidden regions and safety margins, and its variants (a leg, a member, another field)
#   planning/   the pipeline: planner set-up, legs, global check, heading fallback, ensembles, windows, evaluations
#   execution/  the plan flown in another ocean, per strategy, once or in a batch
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/loader/MissionLoader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/MissionReader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Current.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/DrawnEnsemble.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Region.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Departure.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Waypoints.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Dive.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/ForbiddenRegions.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Safety.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Observations.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Planner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Stints.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Outputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Execution.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Fleet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/settings/Overrides.cpp
  ${CMAKE_CURRENT_LIST_DIR}/settings/OverridableFields.cpp
  ${CMAKE_CURRENT_LIST_DIR}/settings/SettingRanges.cpp
  ${CMAKE_CURRENT_LIST_DIR}/settings/OutputFormats.cpp
  ${CMAKE_CURRENT_LIST_DIR}/settings/InputDigest.cpp
  ${CMAKE_CURRENT_LIST_DIR}/settings/MissionSpecText.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs/ProblemInputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs/ForecastRequest.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs/ProblemField.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs/Runs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs/FieldChecks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs/Frame.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs/LandInputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/inputs/Resume.cpp
  ${CMAKE_CURRENT_LIST_DIR}/problem/MissionProblem.cpp
  ${CMAKE_CURRENT_LIST_DIR}/problem/Endpoints.cpp
  ${CMAKE_CURRENT_LIST_DIR}/problem/Correction.cpp
  ${CMAKE_CURRENT_LIST_DIR}/problem/Land.cpp
  ${CMAKE_CURRENT_LIST_DIR}/problem/Safety.cpp
  # the planning pipeline, one concern per file (see planning/PlanningInternal.h)
  ${CMAKE_CURRENT_LIST_DIR}/planning/Planning.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/PlannerSetup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/MissionLegs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/FreeOrder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/GlobalCheck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/HeadingRoutes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/NoPathReason.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/NoPathDiagnosis.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/Ensembles.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/GoalWindow.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/DepartureTimeSearch.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/Evaluations.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/WorkEstimates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/Isochrones.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/Fleet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/PlanStatus.cpp
  ${CMAKE_CURRENT_LIST_DIR}/execution/MissionExecution.cpp
  ${CMAKE_CURRENT_LIST_DIR}/execution/ExecutionPacking.cpp
  ${CMAKE_CURRENT_LIST_DIR}/execution/ExecutionTruth.cpp
  ${CMAKE_CURRENT_LIST_DIR}/execution/ExecutionOracle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/execution/ExecutionRuns.cpp
  ${CMAKE_CURRENT_LIST_DIR}/execution/ExecutionOutcome.cpp
  ${CMAKE_CURRENT_LIST_DIR}/planning/ReachProbability.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Reachability.cpp
)
if(OMPL_GLIDER_WITH_NETCDF)
  list(APPEND OMPL_GLIDER_SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/settings/ForecastMission.cpp  # a mission from a forecast and a handful of inputs
  )
endif()

# mission/: mission files, the problem, the one planning pipeline, departure-time search
list(APPEND OMPL_GLIDER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/DepartureTimeSearch.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MissionLoader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/OutputFormats.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Overrides.cpp
  ${CMAKE_CURRENT_LIST_DIR}/SettingRanges.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/MissionReader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Current.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Region.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Departure.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Dive.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Planner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Stints.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Outputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Execution.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Observations.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Safety.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/ForbiddenRegions.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Fleet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/Waypoints.cpp
  ${CMAKE_CURRENT_LIST_DIR}/loader/DrawnEnsemble.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MissionProblem.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ProblemField.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ProblemLand.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Safety.cpp
  ${CMAKE_CURRENT_LIST_DIR}/FieldChecks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Endpoints.cpp
  # the planning pipeline, one concern per file (see PlanningInternal.h)
  ${CMAKE_CURRENT_LIST_DIR}/Planning.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MissionLegs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GlobalCheck.cpp
  ${CMAKE_CURRENT_LIST_DIR}/HeadingRoutes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PlannerSetup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/NoPathReason.cpp
  ${CMAKE_CURRENT_LIST_DIR}/NoPathDiagnosis.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Ensembles.cpp
  ${CMAKE_CURRENT_LIST_DIR}/GoalWindow.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Evaluations.cpp
  ${CMAKE_CURRENT_LIST_DIR}/WorkEstimates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Isochrones.cpp
  ${CMAKE_CURRENT_LIST_DIR}/MissionExecution.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ExecutionPacking.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ExecutionTruth.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ExecutionOracle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/Fleet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/PlanStatus.cpp
  ${CMAKE_CURRENT_LIST_DIR}/InputDigest.cpp
)
if(OMPL_GLIDER_WITH_NETCDF)
  list(APPEND OMPL_GLIDER_SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/ForecastMission.cpp
    ${CMAKE_CURRENT_LIST_DIR}/Observations.cpp  # a glider's measurements: the last fix, the corrected forecast
  )
endif()

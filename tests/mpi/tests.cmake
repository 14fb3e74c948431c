# MPI (OMPL_GLIDER_WITH_MPI): real mpirun jobs of 2 and 3 ranks on a small campaign, an ensemble and an execution
# batch, a fleet, a departure search with a speed sweep, compared with one process; a failing task, a glider's bad
# input, a rank failing outside the tasks and an overrunning task end the job with nothing written.
if(TARGET glider_plan AND TARGET glider_campaign AND MPIEXEC_EXECUTABLE)
  foreach(np 2 3)
    foreach(mode campaign ensemble execution fleet sweep_departure)
      add_test(NAME mpi.${mode}_np${np}
        COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_mpi_test.sh ${mode} ${np} ${MPIEXEC_EXECUTABLE}
                $<TARGET_FILE:glider_plan> $<TARGET_FILE:glider_campaign>)
    endforeach()
  endforeach()
  foreach(mode fail_plan fail_fleet fail_outside fail_campaign time_limit)
    add_test(NAME mpi.${mode}_np3
      COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run_mpi_test.sh ${mode} 3 ${MPIEXEC_EXECUTABLE}
              $<TARGET_FILE:glider_plan> $<TARGET_FILE:glider_campaign>)
  endforeach()
  set_tests_properties(mpi.campaign_np2 mpi.campaign_np3 mpi.ensemble_np2 mpi.ensemble_np3 mpi.execution_np2
    mpi.execution_np3 mpi.fleet_np2 mpi.fleet_np3 mpi.sweep_departure_np2 mpi.sweep_departure_np3 mpi.fail_plan_np3
    mpi.fail_fleet_np3 mpi.fail_outside_np3 mpi.fail_campaign_np3 mpi.time_limit_np3 PROPERTIES TIMEOUT 120)
endif()

# plot_results.py draws only the files of the run it plots. Runs COMMAND ('|'-separated
# arguments, a mesh run writing profile_t<OWN>.csv into DIRECTORY, which is emptied first), then
# copies that profile to profile_t<STALE>.csv, as another run into the same directory might have
# left it, and plots DIRECTORY with PYTHON PLOT into DIRECTORY/plots. Passes if the plot of
# OWN exists and none of STALE was drawn.
file(REMOVE_RECURSE "${DIRECTORY}")
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "run: exit code ${result}.\nstdout: ${output}\nstderr: ${error}")
endif()
file(COPY_FILE "${DIRECTORY}/profile_t${OWN}.csv" "${DIRECTORY}/profile_t${STALE}.csv")
execute_process(COMMAND ${PYTHON} ${PLOT} ${DIRECTORY} --output ${DIRECTORY}/plots
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "plot_results.py: exit code ${result}.\nstdout: ${output}\nstderr: ${error}")
endif()
if(NOT EXISTS "${DIRECTORY}/plots/deformed_mesh_t${OWN}.png")
  message(FATAL_ERROR "no plot of the run's own profile at t = ${OWN}:\n${output}")
endif()
if(EXISTS "${DIRECTORY}/plots/deformed_mesh_t${STALE}.png")
  message(FATAL_ERROR "the stale profile_t${STALE}.csv was drawn as a result of the run")
endif()
if(NOT error MATCHES "profile_t${STALE}.csv is not a result of this run")
  message(FATAL_ERROR "plot_results.py did not say that it skipped profile_t${STALE}.csv:\n${error}")
endif()

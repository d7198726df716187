# Runs two command lines (RUN_A and RUN_B, '|'-separated, each followed by --output into its own
# directory under DIRECTORY) and compares their history.csv files with compare_histories.py to
# TOLERANCE (relative to each column's maximum). If EXPECTED_B is set, run B's standard output
# must match that regular expression.
file(REMOVE_RECURSE "${DIRECTORY}")
foreach(run A B)
  string(REPLACE "|" ";" command "${RUN_${run}}")
  execute_process(COMMAND ${command} --output ${DIRECTORY}/${run}
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "run ${run} failed (${result}): ${error}")
  endif()
endforeach()
if(DEFINED EXPECTED_B AND NOT output MATCHES "${EXPECTED_B}")
  message(FATAL_ERROR "run B (${RUN_B}) printed no line matching '${EXPECTED_B}':\n${output}")
endif()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${DIRECTORY}/A/history.csv ${DIRECTORY}/B/history.csv
                        ${TOLERANCE}
                RESULT_VARIABLE compare_result)
if(NOT compare_result EQUAL 0)
  message(FATAL_ERROR "the histories of run A (${RUN_A}) and run B (${RUN_B}) differ beyond "
                      "${TOLERANCE}")
endif()

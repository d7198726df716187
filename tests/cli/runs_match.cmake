# Runs two command lines (RUN_A and RUN_B, '|'-separated, each followed by --output into its own
# directory under DIRECTORY) and compares their history.csv files with compare_histories.py to
# TOLERANCE (relative to each column's maximum).
file(REMOVE_RECURSE "${DIRECTORY}")
foreach(run A B)
  string(REPLACE "|" ";" command "${RUN_${run}}")
  execute_process(COMMAND ${command} --output ${DIRECTORY}/${run}
                  RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "run ${run} failed (${result}): ${error}")
  endif()
endforeach()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${DIRECTORY}/A/history.csv ${DIRECTORY}/B/history.csv
                        ${TOLERANCE}
                RESULT_VARIABLE compare_result)
if(NOT compare_result EQUAL 0)
  message(FATAL_ERROR "the histories of run A (${RUN_A}) and run B (${RUN_B}) differ beyond "
                      "${TOLERANCE}")
endif()

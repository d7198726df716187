# Runs PRM (with the '|'-separated OPTIONS) on one rank and with mpirun on NP ranks, and compares
# the two history.csv files with compare_histories.py to TOLERANCE (relative to each column's max).
string(REPLACE "|" ";" options "${OPTIONS}")
file(REMOVE_RECURSE "${DIRECTORY}")
execute_process(COMMAND ${EXECUTABLE} ${PRM} ${options} --output ${DIRECTORY}/serial
                RESULT_VARIABLE serial_result OUTPUT_QUIET ERROR_VARIABLE serial_error)
if(NOT serial_result EQUAL 0)
  message(FATAL_ERROR "serial run failed (${serial_result}): ${serial_error}")
endif()
execute_process(COMMAND ${MPIEXEC} -np ${NP} ${EXECUTABLE} ${PRM} ${options}
                        --output ${DIRECTORY}/parallel
                RESULT_VARIABLE parallel_result OUTPUT_QUIET ERROR_VARIABLE parallel_error)
if(NOT parallel_result EQUAL 0)
  message(FATAL_ERROR "run on ${NP} ranks failed (${parallel_result}): ${parallel_error}")
endif()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${DIRECTORY}/serial/history.csv
                        ${DIRECTORY}/parallel/history.csv ${TOLERANCE}
                RESULT_VARIABLE compare_result)
if(NOT compare_result EQUAL 0)
  message(FATAL_ERROR "histories on 1 and ${NP} ranks differ beyond ${TOLERANCE}")
endif()

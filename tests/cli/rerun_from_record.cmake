# A run's records make it re-runnable from anywhere (issue 15, B): runs EXECUTABLE on PRM (with the
# '|'-separated OPTIONS) into WORK/first; then, from another working directory, WORK/elsewhere,
# `--validate WORK/first/parameters.prm` must pass and re-running that record into WORK/second must
# reproduce WORK/first/history.csv byte for byte. run.json of the first run must name the commit,
# the outcome "completed" and exit code 0.
string(REPLACE "|" ";" options "${OPTIONS}")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/elsewhere")
execute_process(COMMAND ${EXECUTABLE} ${PRM} ${options} --quiet --output ${WORK}/first
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the first run exited with ${result}:\n${output}\n${error}")
endif()
file(READ "${WORK}/first/run.json" record)
foreach(pattern "\"commit\": \"[0-9a-f]+(-dirty)?\"|\"commit\": \"unknown\"" "\"outcome\": \"completed\""
                "\"exit_code\": 0" "\"mpi_ranks\": 1")
  if(NOT record MATCHES "${pattern}")
    message(FATAL_ERROR "run.json does not match '${pattern}':\n${record}")
  endif()
endforeach()
execute_process(COMMAND ${EXECUTABLE} --validate ../first/parameters.prm
                WORKING_DIRECTORY "${WORK}/elsewhere"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0 OR NOT output MATCHES "is valid")
  message(FATAL_ERROR "--validate of the record from another directory exited with ${result}:\n"
                      "${output}\n${error}")
endif()
execute_process(COMMAND ${EXECUTABLE} ../first/parameters.prm --quiet --output ../second
                WORKING_DIRECTORY "${WORK}/elsewhere"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the re-run of the record exited with ${result}:\n${output}\n${error}")
endif()
file(SHA256 "${WORK}/first/history.csv" first)
file(SHA256 "${WORK}/second/history.csv" second)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "the re-run's history.csv differs from the first run's")
endif()
file(STRINGS "${WORK}/first/history.csv" rows)
list(LENGTH rows n_rows)
message("the record validates from another directory and reproduces all ${n_rows} lines of history.csv")

# Runs COMMAND ('|'-separated) into DIRECTORY and passes only if its solve fails the way a user
# should see it: exit code 3, one line on stderr "dyncontact: solve failed: ..." matching EXPECTED,
# history.csv kept, and run.json recording the outcome "solve failed" with exit code 3 and the
# message.
string(REPLACE "|" ";" command "${COMMAND}")
file(REMOVE_RECURSE "${DIRECTORY}")
execute_process(COMMAND ${command} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 3)
  message(FATAL_ERROR "expected exit code 3, got ${result}.\nstderr: ${error}")
endif()
string(STRIP "${error}" error)
if(NOT error MATCHES "^dyncontact: solve failed: ${EXPECTED}" OR error MATCHES "\n")
  message(FATAL_ERROR "stderr is not one line 'dyncontact: solve failed: ${EXPECTED}':\n${error}")
endif()
if(NOT EXISTS "${DIRECTORY}/history.csv")
  message(FATAL_ERROR "history.csv was not kept")
endif()
file(READ "${DIRECTORY}/run.json" record)
foreach(pattern "\"outcome\": \"solve failed\"" "\"exit_code\": 3" "\"message\": \"${EXPECTED}")
  if(NOT record MATCHES "${pattern}")
    message(FATAL_ERROR "run.json does not match '${pattern}':\n${record}")
  endif()
endforeach()
message(STATUS "exit code 3: ${error}")

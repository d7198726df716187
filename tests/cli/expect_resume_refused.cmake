# A checkpoint resumed by another problem or layout must be refused as bad input, never continued:
# runs FIRST ('|'-separated: optional launcher, executable and arguments), which must exit 0 and
# leave DIRECTORY/checkpoint.bin, then RESUME (the same form, without --resume, which is added),
# which must fail as expect_failure.cmake requires: exit code 2 and one line on stderr matching
# EXPECTED. DIRECTORY is removed first.
string(REPLACE "|" ";" first "${FIRST}")
string(REPLACE "|" ";" resume "${RESUME}")
file(REMOVE_RECURSE "${DIRECTORY}")
execute_process(COMMAND ${first} --output ${DIRECTORY} RESULT_VARIABLE result OUTPUT_QUIET
                ERROR_VARIABLE error)
if(NOT result EQUAL 0 OR NOT EXISTS "${DIRECTORY}/checkpoint.bin")
  message(FATAL_ERROR "the first run failed (${result}) or wrote no checkpoint: ${error}")
endif()
set(COMMAND "${RESUME}|--resume|${DIRECTORY}")
include(${CMAKE_CURRENT_LIST_DIR}/expect_failure.cmake)

# A run owns its output directory. Runs FIRST and then SECOND (each '|'-separated arguments, both
# writing into DIRECTORY, which is emptied first), with a file of the user, notes.txt, put into
# DIRECTORY between the two. Passes if both runs exit with 0, the second's stdout matches EXPECTED,
# every file in GONE ('|'-separated) is absent afterwards, every file in KEPT is present, and
# notes.txt is untouched.
# Runs dyncontact with the '|'-separated ARGUMENTS; fails unless it exits with 0. Sets `output`.
function(run_dyncontact which arguments)
  string(REPLACE "|" ";" command "${arguments}")
  execute_process(COMMAND ${command} RESULT_VARIABLE result OUTPUT_VARIABLE stdout
                  ERROR_VARIABLE stderr)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${which} run: exit code ${result}.\nstdout: ${stdout}\nstderr: ${stderr}")
  endif()
  set(output "${stdout}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${DIRECTORY}")
run_dyncontact(first "${FIRST}")
file(WRITE "${DIRECTORY}/notes.txt" "the user's own file\n")
run_dyncontact(second "${SECOND}")
if(NOT output MATCHES "${EXPECTED}")
  message(FATAL_ERROR "stdout of the second run does not match '${EXPECTED}':\n${output}")
endif()
string(REPLACE "|" ";" gone "${GONE}")
foreach(name IN LISTS gone)
  if(EXISTS "${DIRECTORY}/${name}")
    message(FATAL_ERROR "stale result ${DIRECTORY}/${name} of the first run is still there")
  endif()
endforeach()
string(REPLACE "|" ";" kept "${KEPT}")
foreach(name IN LISTS kept)
  if(NOT EXISTS "${DIRECTORY}/${name}")
    message(FATAL_ERROR "missing output ${DIRECTORY}/${name} of the second run")
  endif()
endforeach()
file(READ "${DIRECTORY}/notes.txt" notes)
if(NOT notes STREQUAL "the user's own file\n")
  message(FATAL_ERROR "the user's file notes.txt was changed or removed")
endif()

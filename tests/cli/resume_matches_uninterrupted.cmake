# Checkpoint and restart (issue 10, D): a run interrupted mid-contact and resumed must write a
# history.csv equal, byte for byte, to that of the uninterrupted run. LAUNCH is an optional
# '|'-separated launcher (mpirun -np 2), OPTIONS the run's '|'-separated arguments; CHECKPOINT_STEP
# the step at which Output/checkpoint interval writes the checkpoint (mid-contact); RESUMED_AT, if
# set, the time the resumed run must report starting from.
# 1. the uninterrupted run, writing a checkpoint every CHECKPOINT_STEP steps;
# 2. the interrupted one: the same run stopped by SIGTERM once its history.csv has SIGNAL_ROW rows
#    (SIGNALLER polls it) if SIGNAL_ROW is set, or else the
#    uninterrupted run's directory cut back to its checkpoint (history.csv removed, so the resumed
#    run must rebuild it from the checkpoint);
# 3. --resume on it, and the two history files compared;
# 4. if OTHER_PRM is set, --resume of that problem on the checkpoint must be refused (exit 2).
include(${CMAKE_CURRENT_LIST_DIR}/../first_difference.cmake)
string(REPLACE "|" ";" launch "${LAUNCH}")
string(REPLACE "|" ";" options "${OPTIONS}")
file(REMOVE_RECURSE "${DIRECTORY}")
execute_process(COMMAND ${launch} ${EXECUTABLE} ${options} --output ${DIRECTORY}/uninterrupted
                        --set "Output/checkpoint interval=${CHECKPOINT_STEP}"
                RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the uninterrupted run failed (${result}): ${error}")
endif()
if(SIGNAL_ROW)
  execute_process(COMMAND ${SIGNALLER} ${DIRECTORY}/interrupted/history.csv ${SIGNAL_ROW} ${launch}
                          ${EXECUTABLE} ${options} --output ${DIRECTORY}/interrupted
                  RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE error)
  set(interrupted_error "${error}")
  if(result EQUAL 0)
    message(FATAL_ERROR "the run finished before its history reached row ${SIGNAL_ROW}")
  endif()
  if(NOT error MATCHES "interrupted by signal 15 at t = .*resume with: dyncontact .* --resume ")
    message(FATAL_ERROR "no resume line after SIGTERM (exit ${result}):\n${error}")
  endif()
else()
  file(COPY ${DIRECTORY}/uninterrupted/ DESTINATION ${DIRECTORY}/interrupted)
  file(REMOVE ${DIRECTORY}/interrupted/history.csv)
endif()
execute_process(COMMAND ${launch} ${EXECUTABLE} ${options} --resume ${DIRECTORY}/interrupted
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0 OR NOT output MATCHES "resumed from .* at t = ${RESUMED_AT}")
  message(FATAL_ERROR "the resumed run failed or did not resume at t = ${RESUMED_AT} (${result}): "
                      "${error}\n${output}")
endif()
if(output MATCHES "done, [0-9]+ steps \\(0 taken")
  message(FATAL_ERROR "the resumed run took no step: it did not resume mid-run\n${output}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${DIRECTORY}/uninterrupted/history.csv
                        ${DIRECTORY}/interrupted/history.csv RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  file(STRINGS ${DIRECTORY}/uninterrupted/history.csv expected_rows)
  file(STRINGS ${DIRECTORY}/interrupted/history.csv resumed_rows)
  list(LENGTH expected_rows n_expected)
  list(LENGTH resumed_rows n_resumed)
  first_difference(resumed_rows expected_rows row resumed_row expected_row)
  message(FATAL_ERROR "history.csv of the resumed run differs from the uninterrupted run's "
                      "(${n_resumed} vs ${n_expected} rows), first at row ${row}:\n"
                      "  resumed:       ${resumed_row}\n  uninterrupted: ${expected_row}\n"
                      "interrupted run: ${interrupted_error}")
endif()
if(OTHER_PRM)
  # A checkpoint of another problem: one line, exit 2.
  execute_process(COMMAND ${EXECUTABLE} ${OTHER_PRM} --resume ${DIRECTORY}/interrupted
                  RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  if(NOT result EQUAL 2 OR NOT error MATCHES "checkpoint belongs to another problem")
    message(FATAL_ERROR "resuming another problem's checkpoint: exit ${result}, ${error}")
  endif()
endif()
string(REGEX MATCH "resumed from [^\n]*" resumed "${output}")
message(STATUS "identical histories; ${resumed}")

# Checkpoint and restart (issue 10, D): a run interrupted mid-contact and resumed must write a
# history.csv equal, byte for byte, to that of the uninterrupted run. LAUNCH is an optional
# '|'-separated launcher (mpirun -np 2), OPTIONS the run's '|'-separated arguments; CHECKPOINT_STEP
# the step at which Output/checkpoint interval writes the checkpoint (mid-contact); RESUMED_AT, if
# set, the time the resumed run must report starting from.
# 1. the uninterrupted run, writing a checkpoint every CHECKPOINT_STEP steps (removed at its end:
#    a state before the end time is no use once the run is complete);
# 2. the interrupted one: the same run stopped by SIGTERM once its history.csv has SIGNAL_ROW rows
#    (SIGNALLER polls it; its summaries must say they are incomplete) if SIGNAL_ROW is set, or else
#    the run ended at RESUMED_AT, the checkpoint's time, which it keeps (its end state), with its
#    history.csv removed, so that the resumed run must rebuild it from the checkpoint;
# 3. if OTHER_PRM is set, --resume of that problem on the checkpoint must be refused (exit 2) and
#    leave the interrupted run's files as they were (issue 26);
# 4. --resume on it, and the two history files compared; the consumed checkpoint is removed.
include(${CMAKE_CURRENT_LIST_DIR}/../first_difference.cmake)
string(REPLACE "|" ";" launch "${LAUNCH}")
string(REPLACE "|" ";" options "${OPTIONS}")
file(REMOVE_RECURSE "${DIRECTORY}")
execute_process(COMMAND ${launch} ${EXECUTABLE} ${options} --output ${DIRECTORY}/uninterrupted
                        --set "Output/checkpoint interval=${CHECKPOINT_STEP}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the uninterrupted run failed (${result}): ${error}")
endif()
# Its last checkpoint is kept only if it is of the end time (then it can extend the run).
if(EXISTS ${DIRECTORY}/uninterrupted/checkpoint.bin)
  set(expected "kept [^\n]*checkpoint.bin, the state at the end time")
else()
  set(expected "removed [^\n]*checkpoint.bin [(]the state at t = ")
endif()
if(NOT output MATCHES "${expected}")
  message(FATAL_ERROR "the completed run's checkpoint and its message disagree:\n${output}")
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
  # The summaries of the part before the signal say so (issue 26: they read as a finished impact).
  file(READ ${DIRECTORY}/interrupted/impact_summary.csv summary)
  file(READ ${DIRECTORY}/interrupted/run.json record)
  if(NOT summary MATCHES "peak_force,[^\n]*,incomplete: interrupted by signal 15 after t = " OR
     NOT record MATCHES "\"summaries\": \"incomplete: interrupted by signal 15 after t = ")
    message(FATAL_ERROR "the interrupted run's summaries are not marked incomplete:\n${summary}\n${record}")
  endif()
else()
  execute_process(COMMAND ${launch} ${EXECUTABLE} ${options} --output ${DIRECTORY}/interrupted
                          --set "Output/checkpoint interval=${CHECKPOINT_STEP}"
                          --set "Time integration/end time=${RESUMED_AT}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0 OR NOT output MATCHES "kept [^\n]*checkpoint.bin, the state at the end time")
    message(FATAL_ERROR "the run to t = ${RESUMED_AT} failed or dropped its end state (${result}): "
                        "${error}\n${output}")
  endif()
  file(REMOVE ${DIRECTORY}/interrupted/history.csv)
endif()
if(OTHER_PRM)
  # A checkpoint of another problem: one line, exit 2, and the interrupted run's files untouched.
  file(READ ${DIRECTORY}/interrupted/run.json record_before)
  execute_process(COMMAND ${EXECUTABLE} ${OTHER_PRM} --resume ${DIRECTORY}/interrupted
                  RESULT_VARIABLE result ERROR_VARIABLE error OUTPUT_QUIET)
  if(NOT result EQUAL 2 OR NOT error MATCHES "checkpoint belongs to another problem")
    message(FATAL_ERROR "resuming another problem's checkpoint: exit ${result}, ${error}")
  endif()
  file(READ ${DIRECTORY}/interrupted/run.json record_after)
  if(NOT record_after STREQUAL record_before OR NOT EXISTS ${DIRECTORY}/interrupted/checkpoint.bin)
    message(FATAL_ERROR "the refused resume changed run.json or removed the checkpoint")
  endif()
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
if(EXISTS ${DIRECTORY}/interrupted/checkpoint.bin OR NOT output MATCHES "removed [^\n]*checkpoint.bin")
  message(FATAL_ERROR "the completed resume kept its consumed checkpoint or did not say so:\n${output}")
endif()
if(SIGNAL_ROW)
  file(READ ${DIRECTORY}/interrupted/impact_summary.csv summary)
  if(NOT summary MATCHES "peak_force,[^\n]*,complete\n")
    message(FATAL_ERROR "the resumed run's impact summary is not marked complete:\n${summary}")
  endif()
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
string(REGEX MATCH "resumed from [^\n]*" resumed "${output}")
message(STATUS "identical histories; ${resumed}")

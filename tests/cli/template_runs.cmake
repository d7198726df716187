# --print-parameters KIND prints a valid parameter file (issue 15, C): EXECUTABLE prints the
# template of KIND into WORK/template.prm, which must validate and, for bars (300 steps of one bar
# at rest, 0.2 s), run to the end with exit code 0.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND ${EXECUTABLE} --print-parameters ${KIND} OUTPUT_FILE ${WORK}/template.prm
                RESULT_VARIABLE result ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "--print-parameters ${KIND} exited with ${result}: ${error}")
endif()
set(commands "--validate")
if(RUN)
  list(APPEND commands "--quiet")
endif()
foreach(option IN LISTS commands)
  execute_process(COMMAND ${EXECUTABLE} ${WORK}/template.prm ${option} --output ${WORK}/run
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the ${KIND} template with ${option} exited with ${result}:\n${output}\n${error}")
  endif()
  message("${option}: ${output}")
endforeach()

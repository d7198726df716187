# --print-parameters KIND prints a parameter file that validates and runs as printed (issue 15, C;
# issue 26): EXECUTABLE prints the template of KIND into WORK/template.prm, which must validate
# and run to its end with exit code 0. The mesh template (the paper's spheres approaching each
# other) and the 3d template (the paper's sphere as a coarse quarter dropped on a rigid plane) must
# also write a complete impact summary whose peak force is within 3 % of the finite-sphere law's
# (measured: +1.8 % and +2.1 % on their coarse meshes).
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND ${EXECUTABLE} --print-parameters ${KIND} OUTPUT_FILE ${WORK}/template.prm
                RESULT_VARIABLE result ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "--print-parameters ${KIND} exited with ${result}: ${error}")
endif()
foreach(option "--validate" "--quiet")
  execute_process(COMMAND ${EXECUTABLE} ${WORK}/template.prm ${option} --output ${WORK}/run
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "the ${KIND} template with ${option} exited with ${result}:\n${output}\n${error}")
  endif()
  message("${option}: ${output}")
endforeach()
if(KIND STREQUAL "mesh" OR KIND STREQUAL "3d")
  file(STRINGS ${WORK}/run/impact_summary.csv peak REGEX "^peak_force,")
  string(REPLACE "," ";" peak "${peak}")
  list(GET peak 6 status)
  list(GET peak 5 law_difference)
  if(NOT status STREQUAL "complete" OR law_difference GREATER 0.03 OR law_difference LESS -0.03)
    message(FATAL_ERROR "the ${KIND} template's impact: ${peak} (expected complete, peak within 3 % "
                        "of the finite-sphere law)")
  endif()
endif()

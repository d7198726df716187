# The README's package list is the install script's (issue 15): README must contain
# `<the output of scripts/install-deps --list>` verbatim.
execute_process(COMMAND ${INSTALL_DEPS} --list OUTPUT_VARIABLE packages RESULT_VARIABLE result
                OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT result EQUAL 0 OR packages STREQUAL "")
  message(FATAL_ERROR "scripts/install-deps --list failed (${result})")
endif()
file(READ ${README} readme)
string(FIND "${readme}" "`${packages}`" position)
if(position EQUAL -1)
  message(FATAL_ERROR "README.md does not list the packages of scripts/install-deps: `${packages}`")
endif()
message("README lists `${packages}`")

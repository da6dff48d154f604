# cmake -DCOMMAND="a|b|c" -DEXPECTED_EXIT=1 -DEXPECTED_REGEX=... [-DFORBIDDEN_PATH=dir] -P this
# Runs COMMAND; passes only if it exits with EXPECTED_EXIT, its output matches EXPECTED_REGEX, and
# FORBIDDEN_PATH (an output directory the failed run must not create) does not exist. Used for
# bad-input tests: an error must be clear, non-zero, and leave no output behind.
string(REPLACE "|" ";" COMMAND "${COMMAND}")
if(FORBIDDEN_PATH)
  file(REMOVE_RECURSE "${FORBIDDEN_PATH}")
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc STREQUAL "${EXPECTED_EXIT}")
  message(FATAL_ERROR "expected exit status ${EXPECTED_EXIT}, got '${rc}'")
endif()
string(REGEX MATCH "${EXPECTED_REGEX}" found "${out}${err}")
if(NOT found)
  message(FATAL_ERROR "output does not match the expected message: ${EXPECTED_REGEX}")
endif()
if(FORBIDDEN_PATH AND EXISTS "${FORBIDDEN_PATH}")
  message(FATAL_ERROR "the failed run left output behind: ${FORBIDDEN_PATH}")
endif()

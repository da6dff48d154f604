# cmake -DCOMMAND="a|b|c" -DEXPECTED_EXIT=1 -DEXPECTED_REGEX=... [-DFORBIDDEN_PATH=dir]
#       [-DEXPECTED_COUNT=n] [-DFORBIDDEN_REGEX=...] -P this
# Runs COMMAND; passes only if it exits with EXPECTED_EXIT, its output matches EXPECTED_REGEX
# (exactly EXPECTED_COUNT times if given: an MPI error is printed once, not once per rank), does
# not match FORBIDDEN_REGEX (e.g. MPI_ABORT banners), and FORBIDDEN_PATH (an output directory the
# failed run must not create) does not exist. Used for bad-input tests: an error must be clear,
# non-zero, and leave no output behind.
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
if(DEFINED EXPECTED_COUNT)
  string(REGEX MATCHALL "${EXPECTED_REGEX}" all "${out}${err}")
  list(LENGTH all count)
  if(NOT count EQUAL EXPECTED_COUNT)
    message(FATAL_ERROR "the message appears ${count} times, expected ${EXPECTED_COUNT}: ${EXPECTED_REGEX}")
  endif()
endif()
if(FORBIDDEN_REGEX)
  string(REGEX MATCH "${FORBIDDEN_REGEX}" bad "${out}${err}")
  if(bad)
    message(FATAL_ERROR "the output contains '${bad}' (forbidden: ${FORBIDDEN_REGEX})")
  endif()
endif()
if(FORBIDDEN_PATH AND EXISTS "${FORBIDDEN_PATH}")
  message(FATAL_ERROR "the failed run left output behind: ${FORBIDDEN_PATH}")
endif()

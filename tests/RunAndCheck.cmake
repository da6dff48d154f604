# Lists (SETS, MPIFLAGS) are "|"-separated.
# Run the app on DECK with --set SETS into OUT (through mpiexec with NP ranks), then check its
# summary.json with check_summary against the stored values of EXPECTED (a tests/expected file),
# and that the XDMF output exists and no temporary file is left; with OUTPUT_REGEX, that the run's
# output matches it.
foreach(v SETS MPIFLAGS)
  string(REPLACE "|" ";" ${v} "${${v}}")
endforeach()
file(REMOVE_RECURSE "${OUT}")
set(cmd ${MPIEXEC} -n ${NP} ${MPIFLAGS} ${APP} ${DECK} --output ${OUT})
foreach(s IN LISTS SETS)
  list(APPEND cmd --set "${s}")
endforeach()
if(OUTPUT_REGEX)
  # The run's progress output (stdout and stderr, echoed) must match OUTPUT_REGEX: e.g. the cycle
  # summary line with the numbers that summary.json holds.
  execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE runOut ERROR_VARIABLE runErr)
  message("${runOut}${runErr}")
  if(NOT "${runOut}${runErr}" MATCHES "${OUTPUT_REGEX}")
    message(FATAL_ERROR "the run's output does not match OUTPUT_REGEX '${OUTPUT_REGEX}'")
  endif()
else()
  execute_process(COMMAND ${cmd} RESULT_VARIABLE rc)
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "stresscontact failed with status ${rc}")
endif()
foreach(f summary.json solution.xdmf ${EXTRA_FILES})
  if(NOT EXISTS "${OUT}/${f}")
    message(FATAL_ERROR "missing output file ${OUT}/${f}")
  endif()
endforeach()
file(GLOB leftovers "${OUT}/*.tmp*")
if(leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
if(NOT EXPECTED)
  message(FATAL_ERROR "no EXPECTED file of stored values (tests/expected/README.md)")
endif()
execute_process(COMMAND ${CHECK} ${OUT}/summary.json --expected ${EXPECTED} --np ${NP}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "summary.json checks failed")
endif()

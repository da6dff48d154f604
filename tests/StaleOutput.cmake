# cmake -DAPP=stresscontact -DDECK=hertz2d.xml -DOUT=dir -P StaleOutput.cmake
# A run owns its output directory (docs/output.md "An earlier run's files"): a second run into the
# directory of an earlier, longer run leaves none of that run's files, a failed run leaves no
# fields of the earlier successful run beside its own summary, and other files are kept.
file(REMOVE_RECURSE "${OUT}")
set(common ${DECK} --quiet --output ${OUT} --set "Mesh/Initial mesh size=0.25")

function(run_app expected)
  execute_process(COMMAND ${APP} ${common} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  message("${APP} ${ARGN}: exit ${rc}\n${out}${err}")
  if(NOT rc STREQUAL "${expected}")
    message(FATAL_ERROR "expected exit status ${expected}, got '${rc}'")
  endif()
endfunction()

function(expect_files present absent)
  foreach(f IN LISTS present)
    if(NOT EXISTS "${OUT}/${f}")
      message(FATAL_ERROR "missing ${OUT}/${f}")
    endif()
  endforeach()
  foreach(f IN LISTS absent)
    if(EXISTS "${OUT}/${f}")
      message(FATAL_ERROR "${OUT}/${f} of the earlier run is still there")
    endif()
  endforeach()
endfunction()

# 1. Two cycles, fields and CSVs; a file of the user's beside them.
run_app(0 --set "Adaptivity/Cycles=1")
expect_files("summary.json;history.csv;solution.xdmf;solution_c0000.h5;solution_c0001.h5;contact_cycle0.csv;contact_cycle1.csv" "")
file(WRITE "${OUT}/notes.txt" "mine\n")
# 2. One cycle without XDMF: only its own summary and CSV remain, and the user's file.
run_app(0 --set "Adaptivity/Cycles=0" --set "Output/Write XDMF=false")
expect_files("summary.json;history.csv;contact_cycle0.csv;notes.txt"
             "solution.xdmf;solution_c0000.h5;solution_c0001.h5;contact_cycle1.csv")
# 3. A successful run, then a failing one (Newton stopped after one step): the failed run's
#    summary says converged: false and stands alone.
run_app(0 --set "Adaptivity/Cycles=1")
run_app(2 --set "Adaptivity/Cycles=1" --set "Contact/Newton/Maximum iterations=1")
expect_files("summary.json;notes.txt"
             "history.csv;solution.xdmf;solution_c0000.h5;solution_c0001.h5;contact_cycle0.csv;contact_cycle1.csv")
file(READ "${OUT}/summary.json" summary)
string(JSON converged GET "${summary}" converged)
if(converged)
  message(FATAL_ERROR "the failed run's summary.json says converged: ${converged}")
endif()

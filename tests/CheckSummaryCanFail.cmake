# cmake -DCHECK=check_summary -DDIR=tests/tools/fixtures -P CheckSummaryCanFail.cmake
# Each kind of check of check_summary (tests/tools/check_summary.cpp) is shown able to fail: on a
# synthetic summary with η = 1/DOFs (rate 1, strictly decreasing) and a load of 106.805, the
# true statements pass and the false ones (a stored value off its tolerance, a rate outside its
# range, a sequence that is not monotone, a wrong size or equality) each exit 1.
function(expect rc file)
  execute_process(COMMAND ${CHECK} ${DIR}/${file} ${ARGN} RESULT_VARIABLE got OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT got EQUAL rc)
    message(FATAL_ERROR "check_summary ${file} ${ARGN}: exit ${got}, expected ${rc}\n${out}${err}")
  endif()
endfunction()
expect(0 rate1_summary.json "near:/cycles/-1/contact/force/1=106.805:1e-12" "rate:0:-1=0.99:1.01"
       "decreasing:0" "size:/cycles=5" "eq:/converged=true")
expect(1 rate1_summary.json "near:/cycles/-1/contact/force/1=106.806:1e-6")   # stored value
expect(1 rate1_summary.json "rate:0:-1=1.5:2.5")                              # rate
expect(1 not_monotone_summary.json "decreasing:0")                            # monotone
expect(1 rate1_summary.json "size:/cycles=4")                                 # size
expect(1 rate1_summary.json "eq:/converged=false")                            # equality
expect(1 rate1_summary.json "exists:/cycles/0/nothing")                       # presence
message("check_summary: every kind of check fails when it should")

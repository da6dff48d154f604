# cmake -DAPP=stresscontact -DHISTORY=check_history -DMPIEXEC=mpiexec -DMPIFLAGS="a|b" -DNP=2
#       -DDECK=deck.xml -DOUT=dir -DSETS="k=v|..." -P ContactFieldsAndHistory.cmake
# Runs the deck with --set SETS on NP ranks into OUT, then checks what a user reads
# (docs/output.md): history.csv against summary.json (check_history), and that the check can
# fail (one ulp more on the last η, --perturb).
foreach(v SETS MPIFLAGS)
  string(REPLACE "|" ";" ${v} "${${v}}")
endforeach()
file(REMOVE_RECURSE "${OUT}")
set(cmd ${MPIEXEC} -n ${NP} ${MPIFLAGS} ${APP} ${DECK} --quiet --output ${OUT})
foreach(s IN LISTS SETS)
  list(APPEND cmd --set "${s}")
endforeach()
execute_process(COMMAND ${cmd} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "stresscontact failed with status ${rc}")
endif()

execute_process(COMMAND ${HISTORY} ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "history.csv disagrees with summary.json")
endif()
execute_process(COMMAND ${HISTORY} ${OUT} --perturb RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "check_history did not report the perturbed eta (status ${rc})")
endif()

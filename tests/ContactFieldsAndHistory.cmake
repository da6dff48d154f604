# cmake -DAPP=stresscontact -DFIELDS=check_contact_fields -DHISTORY=check_history -DMPIEXEC=mpiexec
#       -DMPIFLAGS="a|b" -DNP=2 -DDECK=deck.xml -DOUT=dir -DSETS="k=v|..." [-DCYCLES="0|1"
#       -DDEGREE=1 -DCONSTRAINTS=points|bernstein] -P ContactFieldsAndHistory.cmake
# Runs the deck with --set SETS on NP ranks into OUT, then checks what a user reads and looks at
# (docs/output.md):
#   - history.csv against summary.json (check_history), and that the check can fail (one ulp
#     more on the last η, --perturb);
#   - with CYCLES, the contact grid of the XDMF output of each of these cycles against the
#     contact CSV (check_contact_fields, to 1e-12; DEGREE and CONSTRAINTS: how the CSV's traction
#     coefficients give point values), and that the check can fail (the CSV's largest sigma_n
#     changed by 1e-11, --perturb).
foreach(v SETS MPIFLAGS CYCLES)
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

foreach(c IN LISTS CYCLES)
  execute_process(COMMAND ${FIELDS} ${OUT} ${c} ${DEGREE} ${CONSTRAINTS} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the contact fields of cycle ${c} disagree with contact_cycle${c}.csv")
  endif()
endforeach()
if(CYCLES)
  list(GET CYCLES -1 last)
  execute_process(COMMAND ${FIELDS} ${OUT} ${last} ${DEGREE} ${CONSTRAINTS} --perturb
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 1)
    message(FATAL_ERROR "check_contact_fields did not report the perturbed sigma_n (status ${rc})")
  endif()
endif()

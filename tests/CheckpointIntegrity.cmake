# cmake -DAPP=stresscontact -DFLIP=flip_checkpoint_bit -DDECK=deck.xml -DOUT=dir -P this
# A damaged checkpoint is refused before a restart changes anything (docs/reliability.md,
# "interruption"): a short contact run killed in cycle 2 leaves the checkpoint of cycle 1; for a
# sample of single flipped bits in its datasets (a refinement generation's sign bit, which once
# made the restart allocate without end, a coordinate, a contact point, the parameters, the
# summary records, the marked elements), `--restart` on a copy exits 1 naming the file and the
# integrity check, and the killed cycle's files and the checkpoint are left as they were.
set(sets --set "Adaptivity/Cycles=3" --set "Mesh/Initial mesh size=0.2")
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND ${CMAKE_COMMAND} -E env SC_KILL_IN_CYCLE=2 ${APP} ${DECK} --quiet
                        --output ${OUT}/killed ${sets} RESULT_VARIABLE rc ERROR_QUIET)
if(rc EQUAL 0 OR NOT EXISTS "${OUT}/killed/checkpoint.h5")
  message(FATAL_ERROR "the run to be killed in cycle 2 did not leave a checkpoint (status ${rc})")
endif()
set(samples "mesh_generations 3 7" "mesh_generations 0 0" "mesh_coordinates 13 2"
            "contact_points 0 0" "parameters 10 1" "summary_cycles 40 5" "marked_elements 0 3")
set(n 0)
foreach(sample IN LISTS samples)
  separate_arguments(s UNIX_COMMAND "${sample}")
  list(GET s 0 dataset)
  list(GET s 1 byte)
  list(GET s 2 bit)
  set(dir ${OUT}/flip${n})
  math(EXPR n "${n} + 1")
  file(COPY ${OUT}/killed/ DESTINATION ${dir})
  execute_process(COMMAND ${FLIP} ${dir}/checkpoint.h5 ${dataset} ${byte} ${bit} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "could not flip bit ${bit} of byte ${byte} of '${dataset}'")
  endif()
  file(SHA256 ${dir}/checkpoint.h5 before)
  file(GLOB filesBefore RELATIVE ${dir} ${dir}/*)
  execute_process(COMMAND ${APP} ${DECK} --quiet --restart ${dir} ${sets} TIMEOUT 60
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL 1 OR NOT "${o}${e}" MATCHES "the checkpoint '[^']*checkpoint.h5' fails its integrity check")
    message(FATAL_ERROR "'${dataset}' byte ${byte} bit ${bit}: expected exit 1 and the integrity "
                        "error, got status ${rc}:\n${o}${e}")
  endif()
  file(SHA256 ${dir}/checkpoint.h5 after)
  file(GLOB filesAfter RELATIVE ${dir} ${dir}/*)
  if(NOT before STREQUAL after OR NOT filesBefore STREQUAL filesAfter)
    message(FATAL_ERROR "'${dataset}' byte ${byte} bit ${bit}: the refused restart changed the directory")
  endif()
  foreach(f solution_c0002.h5 contact_cycle2.csv summary.json)
    if(NOT EXISTS ${dir}/${f})
      message(FATAL_ERROR "'${dataset}' byte ${byte} bit ${bit}: the refused restart removed ${f}")
    endif()
  endforeach()
  message("'${dataset}' byte ${byte} bit ${bit}: refused, directory unchanged")
endforeach()
# The intact checkpoint restarts (the check is not refusing everything).
execute_process(COMMAND ${APP} ${DECK} --quiet --restart ${OUT}/killed ${sets} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the intact checkpoint did not restart (status ${rc})")
endif()

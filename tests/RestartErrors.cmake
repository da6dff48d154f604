# cmake -DAPP=stresscontact -DDECK=hertz2d.xml -DOUT=dir -P RestartErrors.cmake
# `--restart DIR` refuses what it cannot continue (docs/reliability.md), with
# exit status 1, a message naming the file or the parameter, and the directory left as it was:
# other parameters than the checkpoint's, no checkpoint, a file that is not HDF5, an HDF5 file
# that is not a checkpoint, and --output naming another directory.
file(REMOVE_RECURSE "${OUT}")
set(common ${DECK} --quiet --set "Adaptivity/Cycles=3")

function(run_app expected regex)
  execute_process(COMMAND ${APP} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${APP} ${ARGN}: exit ${rc}\n${out}${err}")
  if(NOT rc STREQUAL "${expected}")
    message(FATAL_ERROR "expected exit status ${expected}, got '${rc}'")
  endif()
  if(regex AND NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "the output does not match: ${regex}")
  endif()
endfunction()

# A run killed in cycle 2: checkpoint of cycle 1.
execute_process(COMMAND ${CMAKE_COMMAND} -E env SC_KILL_IN_CYCLE=2 ${APP} ${common} --output ${OUT}/run
                RESULT_VARIABLE rc)
if(rc EQUAL 0 OR NOT EXISTS "${OUT}/run/checkpoint.h5")
  message(FATAL_ERROR "the run to be killed in cycle 2 exited with '${rc}' or left no checkpoint")
endif()
file(GLOB before RELATIVE "${OUT}/run" "${OUT}/run/*")
file(SHA256 "${OUT}/run/checkpoint.h5" checkpointHash)
file(SHA256 "${OUT}/run/summary.json" summaryHash)

function(expect_unchanged)
  file(GLOB after RELATIVE "${OUT}/run" "${OUT}/run/*")
  file(SHA256 "${OUT}/run/checkpoint.h5" h1)
  file(SHA256 "${OUT}/run/summary.json" h2)
  if(NOT after STREQUAL before OR NOT h1 STREQUAL checkpointHash OR NOT h2 STREQUAL summaryHash)
    message(FATAL_ERROR "a refused restart changed the directory: ${before} -> ${after}")
  endif()
endfunction()

# 1. Other parameters: each difference named, with both values.
run_app(1 "checkpoint '[^']*run/checkpoint.h5' belongs to a run with other parameters: 'Adaptivity/Cycles' is 3 in the checkpoint and 4 in this run; 'Material/Poisson ratio' is 0.28 in the checkpoint and 0.3 in this run"
        ${common} --restart ${OUT}/run --set "Material/Poisson ratio=0.3" --set "Adaptivity/Cycles=4")
expect_unchanged()
# 2. --output elsewhere.
run_app(1 "--restart [^ ]*run continues the run in" ${common} --restart ${OUT}/run --output ${OUT}/other)
expect_unchanged()
# 3. No checkpoint.
file(MAKE_DIRECTORY "${OUT}/empty")
run_app(1 "no checkpoint '[^']*empty/checkpoint.h5'" ${common} --restart ${OUT}/empty)
# 4. Not an HDF5 file.
file(MAKE_DIRECTORY "${OUT}/garbage")
file(WRITE "${OUT}/garbage/checkpoint.h5" "not a checkpoint\n")
run_app(1 "the checkpoint '[^']*garbage/checkpoint.h5' cannot be read: not an HDF5 file" ${common} --restart ${OUT}/garbage)
# 5. An HDF5 file that is not a checkpoint (a cycle's fields).
file(MAKE_DIRECTORY "${OUT}/fields")
file(COPY_FILE "${OUT}/run/solution_c0000.h5" "${OUT}/fields/checkpoint.h5")
run_app(1 "the checkpoint '[^']*fields/checkpoint.h5' cannot be read: no 'format' attribute" ${common} --restart ${OUT}/fields)
# 6. --check --restart reads and checks the checkpoint too, and writes nothing.
run_app(1 "'Material/Poisson ratio' is 0.28 in the checkpoint and 0.3 in this run"
        ${common} --check --restart ${OUT}/run --set "Material/Poisson ratio=0.3")
run_app(0 "is valid" ${common} --check --restart ${OUT}/run)
expect_unchanged()
# And the good restart goes on from cycle 2 to the end.
run_app(0 "" ${common} --restart ${OUT}/run)
file(READ "${OUT}/run/summary.json" s)
string(JSON n LENGTH "${s}" cycles)
string(JSON converged GET "${s}" converged)
string(JSON from GET "${s}" restart checkpoint_cycle)
if(NOT n EQUAL 4 OR NOT converged STREQUAL "ON" OR NOT from EQUAL 1)
  message(FATAL_ERROR "the restarted run has ${n} cycles (expected 4), converged = ${converged}, "
                      "restarted from the checkpoint of cycle ${from} (expected 1)")
endif()

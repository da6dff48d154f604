# cmake -DAPP=stresscontact -DDECK=hertz2d.xml -DOUT=dir -DMPIEXEC=mpiexec -DMPIFLAGS="a|b"
#       -P OutputLock.cmake
# One run per output directory (io/OutputLock.hpp; docs/reliability.md, "output"). Without the lock,
# two runs into one directory both exit 0 and leave the summary.json of one beside the CSVs and
# .h5 of the other.
#   1. A run leaves no lock behind.
#   2. A lock held by a live process (this cmake process: the parent of a shell it starts):
#      a run (at 2 ranks: the message once), --restart and --check exit 1 naming the directory
#      and the pid; the first run's files and the lock are untouched.
#   3. Two real runs: the second, started while the first one runs, fails naming the first's
#      pid; then the first is killed (SIGKILL), leaving its lock behind.
#   4. That stale lock is taken over by the next run, with a note on stderr; the lock goes at
#      the end.
#   5. A run that fails (no convergence, exit 2) removes its lock too.
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...)
string(REPLACE "|" ";" MPIFLAGS "${MPIFLAGS}")
set(lock "${OUT}/stresscontact.lock")
set(logs "${OUT}_logs")
file(REMOVE_RECURSE "${OUT}" "${logs}")
file(MAKE_DIRECTORY "${logs}")
set(quick --quiet --set "Adaptivity/Cycles=1" --set "Mesh/Initial mesh size=0.25")
cmake_host_system_information(RESULT host QUERY HOSTNAME)
string(REGEX REPLACE "([.+*?()|^$])" "\\\\\\1" out_re "${OUT}")

function(run expected what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  message("${what}: exit ${rc}\n${out}${err}")
  if(NOT rc STREQUAL "${expected}")
    message(FATAL_ERROR "${what}: expected exit status ${expected}, got '${rc}'")
  endif()
  set(output "${out}${err}" PARENT_SCOPE)
endfunction()

function(expect_match what text regex)
  string(REGEX MATCHALL "${regex}" all "${text}")
  list(LENGTH all count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "${what}: expected the message once, found it ${count} times: ${regex}")
  endif()
endfunction()

function(expect_no_lock what)
  if(EXISTS "${lock}")
    file(READ "${lock}" text)
    message(FATAL_ERROR "${what} left its lock behind: ${text}")
  endif()
endfunction()

# 1.
run(0 "first run" ${APP} ${DECK} ${quick} --output ${OUT})
expect_no_lock("the first run")
file(GLOB firstFiles RELATIVE "${OUT}" "${OUT}/*")
file(SHA256 "${OUT}/summary.json" firstSummary)
if(NOT "checkpoint.h5" IN_LIST firstFiles OR NOT "solution_c0001.h5" IN_LIST firstFiles)
  message(FATAL_ERROR "the first run did not write its files: ${firstFiles}")
endif()

# 2. $PPID of the shell is this cmake process, alive until the test ends.
execute_process(COMMAND sh -c "echo $PPID" OUTPUT_VARIABLE pid OUTPUT_STRIP_TRAILING_WHITESPACE)
file(WRITE "${lock}" "pid ${pid}\nhost ${host}\n")
file(READ "${lock}" heldLock)
set(inUse "the output directory '${out_re}' is in use by another StressContact run: process ${pid} on this host \\([^)]*\\) holds its lock '${out_re}/stresscontact.lock'")
run(1 "second run, 2 ranks" ${MPIEXEC} -n 2 ${MPIFLAGS} ${APP} ${DECK} ${quick} --output ${OUT})
expect_match("second run" "${output}" "${inUse}")
run(1 "--restart" ${APP} ${DECK} ${quick} --restart ${OUT})
expect_match("--restart" "${output}" "${inUse}")
run(1 "--check" ${APP} --check ${DECK} ${quick} --output ${OUT})
expect_match("--check" "${output}" "${inUse}")
file(GLOB files RELATIVE "${OUT}" "${OUT}/*")
list(REMOVE_ITEM files stresscontact.lock)
file(SHA256 "${OUT}/summary.json" summary)
file(READ "${lock}" lockNow)
if(NOT files STREQUAL firstFiles OR NOT summary STREQUAL firstSummary OR NOT lockNow STREQUAL heldLock)
  message(FATAL_ERROR "the refused runs changed the directory: ${files} (was ${firstFiles}), "
                      "lock '${lockNow}'")
endif()
file(REMOVE "${lock}")

# 3. The first run (the deck's 16 adaptive cycles, seconds) in the background; the second one
#    starts once the first holds the lock, then the first is killed.
set(script [=[
"$APP" "$DECK" --quiet --output "$OUT" > "$LOGS/first.log" 2>&1 &
first=$!
echo $first > "$LOGS/first.pid"
i=0
while [ ! -s "$OUT/stresscontact.lock" ] && [ $i -lt 1200 ]; do sleep 0.05; i=$((i+1)); done
"$APP" "$DECK" --quiet --set Adaptivity/Cycles=0 --output "$OUT" > "$LOGS/second.log" 2>&1
echo $? > "$LOGS/second.rc"
kill -0 $first 2> /dev/null && echo running > "$LOGS/first.state"
kill -9 $first
wait $first
exit 0
]=])
execute_process(COMMAND ${CMAKE_COMMAND} -E env APP=${APP} DECK=${DECK} OUT=${OUT} LOGS=${logs}
                        sh -c "${script}" TIMEOUT 120 RESULT_VARIABLE rc)
file(READ "${logs}/first.pid" first)
string(STRIP "${first}" first)
file(READ "${logs}/second.rc" secondRc)
string(STRIP "${secondRc}" secondRc)
file(READ "${logs}/second.log" second)
message("two runs at once (first: pid ${first}); the second: exit ${secondRc}\n${second}")
if(NOT EXISTS "${logs}/first.state")
  message(FATAL_ERROR "the first run had ended before the second one was checked: the test "
                      "did not test concurrent runs")
endif()
if(NOT secondRc STREQUAL "1")
  message(FATAL_ERROR "the second of two runs at once: expected exit status 1, got '${secondRc}'")
endif()
expect_match("the second of two runs at once" "${second}"
             "the output directory '${out_re}' is in use by another StressContact run: process ${first} on this host")
file(READ "${lock}" staleLock)
if(NOT staleLock MATCHES "^pid ${first}\nhost ")
  message(FATAL_ERROR "the killed run's lock is not there: '${staleLock}'")
endif()

# 4.
run(0 "run after the killed one" ${APP} ${DECK} ${quick} --output ${OUT})
expect_match("run after the killed one" "${output}"
             "stresscontact: note: took over the stale lock '${out_re}/stresscontact.lock' of process ${first} on this host \\([^)]*\\), which no longer runs")
expect_no_lock("the run that took over the stale lock")

# 5.
run(2 "failing run" ${APP} ${DECK} ${quick} --set "Contact/Newton/Maximum iterations=1" --output ${OUT})
expect_no_lock("the run that did not converge")
file(GLOB leftovers "${OUT}/*.tmp*" "${OUT}/*.stale*")
if(leftovers)
  message(FATAL_ERROR "files left behind: ${leftovers}")
endif()
file(REMOVE_RECURSE "${OUT}" "${logs}")

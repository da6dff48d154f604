# cmake -DAPP=stresscontact -DDECK=hertz2d.xml -DOUT=dir -DNAMES="summary.json|..." [-DFIFO=name]
#       -P OutputNamesTaken.cmake
# For each of NAMES: the output directory holds a directory of that name (with a file in it)
# beside a file of the user's. The run and --check must both exit with status 1 and the message
# "'OUT/NAME' is a directory, but a run writes its file NAME there", and leave the directory as
# it was: the same entries, no lock, temporary or summary written (docs/reliability.md). Unchecked,
# --check says the deck is valid, and the run writes its files and stops at the first rename
# ("Cannot rename '...tmp.<pid>' to '...': Is a directory", a temporary left behind) or, for
# summary.json, at "basic_filebuf::underflow error reading the file: Is a directory".
# With FIFO: a named pipe of that name (unchecked, the run waits forever opening it as a summary).
string(REPLACE "|" ";" NAMES "${NAMES}")

function(expect_refused name kind)
  foreach(mode run check)
    file(REMOVE_RECURSE "${OUT}")
    file(MAKE_DIRECTORY "${OUT}")
    file(WRITE "${OUT}/notes.txt" "mine\n")
    if(kind STREQUAL "directory")
      file(WRITE "${OUT}/${name}/inside.txt" "mine\n")
      set(what "a directory")
    else()
      execute_process(COMMAND mkfifo "${OUT}/${name}" RESULT_VARIABLE rc)
      if(NOT rc EQUAL 0)
        message(FATAL_ERROR "mkfifo ${OUT}/${name} failed")
      endif()
      set(what "not a regular file \\(a device, pipe or socket\\)")
    endif()
    file(GLOB_RECURSE before LIST_DIRECTORIES true RELATIVE "${OUT}" "${OUT}/*")
    set(flag)
    if(mode STREQUAL "check")
      set(flag --check)
    endif()
    execute_process(COMMAND ${APP} ${flag} ${DECK} --quiet --set "Adaptivity/Cycles=0" --output ${OUT}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
    message("${name} (${kind}), ${mode}: exit ${rc}\n${out}${err}")
    if(NOT rc STREQUAL "1")
      message(FATAL_ERROR "${mode} with ${kind} '${name}': expected exit status 1, got '${rc}'")
    endif()
    string(REGEX REPLACE "([.+])" "\\\\\\1" quoted "${OUT}/${name}")
    string(REGEX REPLACE "([.+])" "\\\\\\1" quotedName "${name}")
    set(regex "'${quoted}' is ${what}, but a run writes its file ${quotedName} there")
    if(NOT "${out}${err}" MATCHES "${regex}")
      message(FATAL_ERROR "${mode} with ${kind} '${name}': the message does not match '${regex}'")
    endif()
    file(GLOB_RECURSE after LIST_DIRECTORIES true RELATIVE "${OUT}" "${OUT}/*")
    if(NOT before STREQUAL after)
      message(FATAL_ERROR "${mode} with ${kind} '${name}' changed the directory:\n"
                          "before: ${before}\nafter: ${after}")
    endif()
  endforeach()
endfunction()

foreach(name IN LISTS NAMES)
  expect_refused(${name} directory)
endforeach()
if(FIFO)
  expect_refused(${FIFO} fifo)
endif()
file(REMOVE_RECURSE "${OUT}")

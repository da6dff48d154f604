# cmake -DAPP=stresscontact -DDECK=input/hertz2d.xml -DEMPTY_DECK=bad_decks/output_directory_empty.xml
#       -DWORK=dir -P this
# An empty output directory is a scripting error (`--output "$DIR"` with DIR unset), not "not
# given": `--output ''` (run and --check), `--restart ''` and Output/Directory = "" (in a deck and by
# --set) exit 1 with a message naming the option or key, and write nothing. Each runs in the empty
# directory WORK, which must still be empty afterwards: DECK's own Output/Directory is relative
# ("output/hertz2d"), so a run that took '' for "not given" would create WORK/output/hertz2d
# (docs/reliability.md). The empty arguments are written out in each execute_process: CMake drops
# empty elements when it expands a list, so they could not pass through add_test or a variable.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(quick --set "Adaptivity/Cycles=0" --set "Mesh/Initial mesh size=0.5")
set(outputRegex "--output '' is an empty directory name: give a directory \\(e.g. --output out\\), or omit --output to use the deck's Output/Directory")
set(restartRegex "--restart '' is an empty directory name: give a directory \\(e.g. --restart out\\), or omit --restart for a new run")
set(keyRegex "Output/Directory is empty. give a directory such as \"output\"")

function(check name regex rc out)
  message("${name}:\n${out}")
  if(NOT rc STREQUAL "1")
    message(FATAL_ERROR "${name}: expected exit status 1, got '${rc}'")
  endif()
  if(NOT "${out}" MATCHES "${regex}")
    message(FATAL_ERROR "${name}: the output does not match: ${regex}")
  endif()
  file(GLOB_RECURSE written LIST_DIRECTORIES true "${WORK}/*")
  if(written)
    message(FATAL_ERROR "${name} wrote into its working directory: ${written}")
  endif()
endfunction()

execute_process(COMMAND ${APP} ${DECK} --output "" ${quick} WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
check("--output ''" "${outputRegex}" "${rc}" "${out}")
execute_process(COMMAND ${APP} --check ${DECK} --output "" ${quick} WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
check("--check --output ''" "${outputRegex}" "${rc}" "${out}")
execute_process(COMMAND ${APP} ${DECK} --restart "" ${quick} WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
check("--restart ''" "${restartRegex}" "${rc}" "${out}")
execute_process(COMMAND ${APP} ${EMPTY_DECK} WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
check("Output/Directory = \"\" in the deck" "${keyRegex}" "${rc}" "${out}")
execute_process(COMMAND ${APP} --check ${EMPTY_DECK} WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
check("--check, Output/Directory = \"\" in the deck" "${keyRegex}" "${rc}" "${out}")
execute_process(COMMAND ${APP} ${DECK} --set "Output/Directory=" ${quick} WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
check("--set Output/Directory=" "${keyRegex}" "${rc}" "${out}")

# Install the build tree into PREFIX, configure + build the consumer project in WORK against it,
# and run the consumer; then run the installed application on a shipped deck from the prefix,
# without any environment setting (no LD_LIBRARY_PATH). Called by the CTest install_and_consume.
file(REMOVE_RECURSE "${PREFIX}" "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
string(REPLACE "|" ";" CONSUMER_ARGS "${CONSUMER_ARGS}")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK} -G ${GENERATOR}
                        -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_BUILD_TYPE=Release ${CONSUMER_ARGS}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer against the installed package failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK} -j 2 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer failed (${rc})")
endif()
execute_process(COMMAND ${WORK}/consumer WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer failed (${rc})")
endif()
if(NOT EXISTS ${WORK}/summary.json)
  message(FATAL_ERROR "the consumer wrote no summary.json")
endif()

# The installed application starts and runs a small deck from the install prefix by itself (its
# RPATH finds the installed libraries; docs/reliability.md).
set(app_out ${WORK}/installed-app-output)
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH
                        ${PREFIX}/bin/stresscontact ${PREFIX}/share/stresscontact/input/hertz2d.xml
                        --set "Mesh/Initial mesh size=0.25" --set "Adaptivity/Cycles=0"
                        --output ${app_out} --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed application failed (${rc}): ${out}${err}")
endif()
if(NOT EXISTS ${app_out}/summary.json)
  message(FATAL_ERROR "the installed application wrote no summary.json in ${app_out}")
endif()

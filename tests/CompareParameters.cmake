# docs/parameters.txt must equal `stresscontact --print-parameters` (MueLu's habit: one master
# list from which code defaults and documentation both come).
execute_process(COMMAND ${APP} --print-parameters OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "stresscontact --print-parameters failed (${rc})")
endif()
file(READ ${DOC} stored)
if(NOT generated STREQUAL stored)
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/parameters.generated.txt "${generated}")
  message(FATAL_ERROR "${DOC} is out of date with the code. Regenerate it:\n"
                      "  ${APP} --print-parameters > ${DOC}")
endif()

# cmake -DAPP=stresscontact -DCHECK=check_summary -DDECK=hertz2d.xml -DOUT=dir
#       -DEXPONENTS="-100|-50|4|50|100" [-DSETS="k=v|..."] -P YoungModulusRange.cmake
# The problem is linear in Young's modulus E (docs/theory.md): with displacement loads the
# displacements and the contact state do not depend on E, and stresses and forces scale with it.
# Runs the deck with E = 1 (the reference) and with E = 1e<k> for every k of EXPONENTS, then
# checks every cycle of every run against the reference: converged, the same number of cycles,
# contact force / E within 1e-8 (relative), the same half-width and stick half-width (1e-12),
# and the same numbers of free, stick and slip points. This is why 'Material/Young modulus' is
# limited to [1e-100, 1e100]: E = 1e-165 on hertz2d.xml (Coulomb friction) gives another
# stick/slip state and force/E 0.7 % off, and this script fails there (docs/reliability.md).
foreach(v SETS EXPONENTS)
  string(REPLACE "|" ";" ${v} "${${v}}")
endforeach()
file(REMOVE_RECURSE "${OUT}")

function(run_with_modulus name modulus)
  set(cmd ${APP} ${DECK} --quiet --output ${OUT}/${name} --set "Material/Young modulus=${modulus}")
  foreach(s IN LISTS SETS)
    list(APPEND cmd --set "${s}")
  endforeach()
  execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "E = ${modulus}: stresscontact failed with status ${rc}\n${out}${err}")
  endif()
endfunction()

# value × 1e<k> as text: the exponent of the reference's number is shifted (no floating-point
# arithmetic in CMake; check_summary reads the result with std::stod).
function(scaled value k out)
  if(value MATCHES "^(-?[0-9.]+)[eE]([-+]?)0*([0-9]+)$")
    math(EXPR e "${CMAKE_MATCH_2}${CMAKE_MATCH_3} + ${k}")
    set(${out} "${CMAKE_MATCH_1}e${e}" PARENT_SCOPE)
  else()
    set(${out} "${value}e${k}" PARENT_SCOPE)
  endif()
endfunction()

run_with_modulus(reference 1)
file(READ "${OUT}/reference/summary.json" reference)
string(JSON cycles LENGTH "${reference}" cycles)
math(EXPR last "${cycles} - 1")
foreach(k IN LISTS EXPONENTS)
  run_with_modulus(e${k} 1e${k})
  set(checks "eq:/converged=true" "size:/cycles=${cycles}")
  foreach(c RANGE ${last})
    string(JSON force GET "${reference}" cycles ${c} contact force 1)
    scaled("${force}" ${k} expected)
    list(APPEND checks "near:/cycles/${c}/contact/force/1=${expected}:1e-8")
    foreach(key half_width stick_half_width)
      string(JSON value GET "${reference}" cycles ${c} contact ${key})
      list(APPEND checks "near:/cycles/${c}/contact/${key}=${value}:1e-12")
    endforeach()
    foreach(kind free stick slip)
      string(JSON count GET "${reference}" cycles ${c} contact points ${kind})
      list(APPEND checks "eq:/cycles/${c}/contact/points/${kind}=${count}")
    endforeach()
  endforeach()
  execute_process(COMMAND ${CHECK} ${OUT}/e${k}/summary.json ${checks} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out)
  message("E = 1e${k} against E = 1:\n${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "E = 1e${k} does not give the results of E = 1 scaled by E")
  endif()
endforeach()

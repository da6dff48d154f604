# Helpers shared by all StressContact packages, apps and tests.
#
#   sc_add_package(<name> [INCLUDE_NAME <dir>] DEPENDS <package> ... SOURCES ...
#                  [PUBLIC_LIBS ...] [PRIVATE_LIBS ...])
#     Library target sc_<name> (alias StressContact::<name>, exported as StressContact::<name>),
#     headers under packages/<name>/src/sc/<dir>/ (dir = INCLUDE_NAME, default <name>) included as
#     <sc/<dir>/X.hpp>. DEPENDS declares the package's upstream StressContact packages (TriBITS'
#     LIB_REQUIRED_PACKAGES): each must be added before it, every sc_* library it links must be
#     declared there, and the test package_includes_declared checks that its sources include
#     only headers of itself and of its declared packages and their upstream packages.
#
#   sc_check_package_links()
#     After the last package: every StressContact library a package's target links, also through
#     a target_link_libraries call outside sc_add_package, must be declared in its DEPENDS.
#
#   sc_add_test(<name> SOURCES ... | COMMAND ...  [LIBS ...] [MPI_RANKS 1 2 4] [ARGS ...]
#               [WILL_FAIL] [PASS_REGULAR_EXPRESSION re] [LABELS ...] [TIMEOUT s])
#     One CTest per rank count, named <name>_np<N>, run through mpiexec (DUNE's dune_add_test).
#     Without MPI_RANKS the test runs once, serially, under its plain name. SCRIPT_RANKS 1 2 4 makes
#     the same per-rank tests for a command that calls mpiexec itself (@NP@ in its arguments).

set(SC_MPIEXEC_EXTRA_FLAGS "--oversubscribe")
# The tests run on one machine: under Open MPI they use its shared-memory transport (ob1 with the
# self and vader BTLs) instead of initialising UCX, the network layer, in every rank, which costs
# about 0.2 s per launch here, and some 380 launches make the default suite (docs/performance.md
# "Start-up"). Other MPI implementations get no extra flags.
execute_process(COMMAND ${MPIEXEC_EXECUTABLE} --version OUTPUT_VARIABLE _sc_mpiexec_version
                ERROR_QUIET)
if(_sc_mpiexec_version MATCHES "Open MPI|OpenRTE")
  list(APPEND SC_MPIEXEC_EXTRA_FLAGS --mca pml ob1 --mca btl self,vader)
endif()
# Every test runs with floating-point exceptions trapped (FE_INVALID, FE_DIVBYZERO, FE_OVERFLOW;
# sc/core/FloatingPointTraps.hpp) unless configured with -DSC_TRAP_FPE=0.
set(SC_TRAP_FPE 1 CACHE STRING "Value of SC_TRAP_FPE in the tests' environment (1: trap)")
# Sanitized code runs 2-7 times slower (docs/reliability.md "Sanitizers"): the time limits of
# sc_add_test grow with it.
if(SC_ENABLE_SANITIZERS OR SC_ENABLE_FUZZING)
  set(SC_TEST_TIMEOUT_FACTOR 3)
else()
  set(SC_TEST_TIMEOUT_FACTOR 1)
endif()
execute_process(COMMAND id -u OUTPUT_VARIABLE _sc_uid OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(_sc_uid STREQUAL "0")
  list(APPEND SC_MPIEXEC_EXTRA_FLAGS "--allow-run-as-root")
endif()

function(sc_add_package name)
  cmake_parse_arguments(P "" "INCLUDE_NAME" "DEPENDS;SOURCES;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  set(tgt sc_${name})
  if(NOT P_INCLUDE_NAME)
    set(P_INCLUDE_NAME ${name})
  endif()
  # The package graph (docs/architecture.md) is enforced here: CMake itself lets a target link one
  # defined later, and any target it likes. A package declares its upstream packages (DEPENDS),
  # which must be added before it; it may link only those.
  get_property(defined GLOBAL PROPERTY SC_PACKAGES)
  foreach(dep IN LISTS P_DEPENDS)
    if(NOT dep IN_LIST defined)
      message(FATAL_ERROR "package '${name}' depends on '${dep}', which is not defined before it. A "
                          "package may use only the packages added before it in "
                          "packages/CMakeLists.txt (docs/architecture.md); defined so far: ${defined}")
    endif()
  endforeach()
  foreach(lib IN LISTS P_PUBLIC_LIBS P_PRIVATE_LIBS)
    if(lib MATCHES "^sc_(.+)$")
      set(dep ${CMAKE_MATCH_1})
      if(NOT dep IN_LIST defined)
        message(FATAL_ERROR "package '${name}' links '${lib}', which is not defined before it. A "
                            "package may use only the packages added before it in "
                            "packages/CMakeLists.txt (docs/architecture.md); defined so far: ${defined}")
      endif()
      if(NOT dep IN_LIST P_DEPENDS)
        message(FATAL_ERROR "package '${name}' links '${lib}', but does not declare '${dep}' in its "
                            "DEPENDS (${P_DEPENDS}): declare it, or do not link it "
                            "(docs/architecture.md \"Packages and their order\")")
      endif()
    endif()
  endforeach()
  # The upstream closure, for the include check: the declared packages and theirs.
  set(closure ${P_DEPENDS})
  foreach(dep IN LISTS P_DEPENDS)
    get_property(up GLOBAL PROPERTY SC_PACKAGE_CLOSURE_${dep})
    list(APPEND closure ${up})
  endforeach()
  list(REMOVE_DUPLICATES closure)
  set_property(GLOBAL PROPERTY SC_PACKAGE_CLOSURE_${name} ${closure})
  set_property(GLOBAL PROPERTY SC_PACKAGE_DEPENDS_${name} ${P_DEPENDS})
  set_property(GLOBAL PROPERTY SC_PACKAGE_INCLUDE_NAME_${name} ${P_INCLUDE_NAME})
  set_property(GLOBAL APPEND PROPERTY SC_PACKAGE_SOURCE_DIRS "${name}=${CMAKE_CURRENT_SOURCE_DIR}/src")
  add_library(${tgt} ${P_SOURCES})
  add_library(StressContact::${name} ALIAS ${tgt})
  set_target_properties(${tgt} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME stresscontact_${name}
                                          VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR})
  target_include_directories(${tgt} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/src>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_options(${tgt} PRIVATE -Wall -Wextra)
  target_link_libraries(${tgt} PUBLIC ${P_PUBLIC_LIBS} PRIVATE ${P_PRIVATE_LIBS})
  install(TARGETS ${tgt} EXPORT StressContactTargets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/src/sc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.hpp")
  set_property(GLOBAL APPEND PROPERTY SC_PACKAGES ${name})
endfunction()

function(sc_check_package_links)
  get_property(packages GLOBAL PROPERTY SC_PACKAGES)
  set(problems "")
  foreach(pkg IN LISTS packages)
    get_property(declared GLOBAL PROPERTY SC_PACKAGE_DEPENDS_${pkg})
    get_target_property(direct sc_${pkg} LINK_LIBRARIES)
    get_target_property(iface sc_${pkg} INTERFACE_LINK_LIBRARIES)
    foreach(lib IN LISTS direct iface)
      # Plain names, aliases and $<LINK_ONLY:...> wrappers alike.
      if(lib MATCHES "(^|[:<])(sc_|StressContact::)([a-z_]+)>?$")
        set(dep ${CMAKE_MATCH_3})
        if(dep IN_LIST packages AND NOT dep STREQUAL pkg AND NOT dep IN_LIST declared)
          string(APPEND problems "  package '${pkg}' links '${lib}' (declared: ${declared})\n")
        endif()
      endif()
    endforeach()
  endforeach()
  if(problems)
    message(FATAL_ERROR "packages link StressContact libraries they do not declare in DEPENDS:\n"
                        "${problems}Declare the package in DEPENDS (packages/<name>/CMakeLists.txt) "
                        "or do not link it (docs/architecture.md \"Packages and their order\")")
  endif()
endfunction()

function(sc_add_test name)
  cmake_parse_arguments(T "WILL_FAIL;UNIT_TEST" "PASS_REGULAR_EXPRESSION;TIMEOUT;WORKING_DIRECTORY"
                        "SOURCES;COMMAND;LIBS;MPI_RANKS;SCRIPT_RANKS;ARGS;LABELS;FAIL_REGULAR_EXPRESSION" ${ARGN})
  if(T_SOURCES)
    add_executable(${name} ${T_SOURCES})
    target_link_libraries(${name} PRIVATE ${T_LIBS})
    if(T_UNIT_TEST)
      target_link_libraries(${name} PRIVATE sc_unit_test_main)
    endif()
    set(cmd $<TARGET_FILE:${name}>)
  else()
    set(cmd ${T_COMMAND})
  endif()
  if(T_UNIT_TEST)
    list(APPEND T_LABELS unit)
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 300)
  endif()
  math(EXPR T_TIMEOUT "${T_TIMEOUT} * ${SC_TEST_TIMEOUT_FACTOR}")
  if(NOT T_WORKING_DIRECTORY)
    set(T_WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  endif()
  if(T_MPI_RANKS)
    set(runs ${T_MPI_RANKS})
  elseif(T_SCRIPT_RANKS)
    set(runs ${T_SCRIPT_RANKS})
  else()
    set(runs 0)
  endif()
  foreach(np IN LISTS runs)
    if(np EQUAL 0)
      set(tname ${name})
      set(full ${cmd} ${T_ARGS})
      set(procs 1)
    elseif(T_SCRIPT_RANKS)
      # The command launches mpiexec itself (a -P script): only @NP@ is substituted.
      set(tname ${name}_np${np})
      set(full ${cmd} ${T_ARGS})
      set(procs ${np})
    else()
      set(tname ${name}_np${np})
      set(full ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${np} ${SC_MPIEXEC_EXTRA_FLAGS}
               ${cmd} ${T_ARGS})
      set(procs ${np})
    endif()
    string(REPLACE "@NP@" "${np}" full "${full}")
    add_test(NAME ${tname} COMMAND ${full} WORKING_DIRECTORY ${T_WORKING_DIRECTORY})
    # Oversubscribed ranks on a 2-core machine: PROCESSORS keeps ctest -j from stacking them.
    set_tests_properties(${tname} PROPERTIES PROCESSORS ${procs} TIMEOUT ${T_TIMEOUT}
                         SKIP_RETURN_CODE 77
                         ENVIRONMENT "OMPI_MCA_rmaps_base_oversubscribe=1;SC_TRAP_FPE=${SC_TRAP_FPE}")
    if(T_WILL_FAIL)
      set_tests_properties(${tname} PROPERTIES WILL_FAIL TRUE)
    endif()
    if(T_PASS_REGULAR_EXPRESSION)
      set_tests_properties(${tname} PROPERTIES PASS_REGULAR_EXPRESSION "${T_PASS_REGULAR_EXPRESSION}")
    endif()
    if(T_FAIL_REGULAR_EXPRESSION)
      set_tests_properties(${tname} PROPERTIES FAIL_REGULAR_EXPRESSION "${T_FAIL_REGULAR_EXPRESSION}")
    endif()
    if(T_LABELS)
      set_tests_properties(${tname} PROPERTIES LABELS "${T_LABELS}")
    endif()
  endforeach()
endfunction()

#   sc_add_unit_test(<name> SOURCES ... LIBS ... [MPI_RANKS ...])
#     A Teuchos unit-test executable (shared main in packages/core/test/UnitTestMain.cpp).
function(sc_add_unit_test name)
  sc_add_test(${name} UNIT_TEST ${ARGN})
endfunction()

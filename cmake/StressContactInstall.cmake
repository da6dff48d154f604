# Installed CMake package: find_package(StressContact) gives StressContact::<package> targets
# (core, mesh, io, ...) and finds the same dependencies as the build did.
include(CMakePackageConfigHelpers)
set(SC_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/StressContact)
get_property(SC_PACKAGES GLOBAL PROPERTY SC_PACKAGES)
install(EXPORT StressContactTargets NAMESPACE StressContact:: DESTINATION ${SC_CMAKE_INSTALL_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/StressContactConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/StressContactConfig.cmake INSTALL_DESTINATION ${SC_CMAKE_INSTALL_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/StressContactConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/StressContactConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/StressContactConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/StressContactDependencies.cmake
              ${CMAKE_CURRENT_LIST_DIR}/FindMETIS.cmake
              ${CMAKE_CURRENT_LIST_DIR}/FindGmsh.cmake
              ${CMAKE_CURRENT_LIST_DIR}/FindMUMPS.cmake
              ${CMAKE_CURRENT_LIST_DIR}/FindMuparser.cmake
        DESTINATION ${SC_CMAKE_INSTALL_DIR})

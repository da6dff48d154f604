# Finds muparser 2.x (Debian: libmuparser-dev), which evaluates the deck's formulas of x, y, z
# (core/Expression.hpp). pkg-config gives the hints when it knows the package; the header and the
# library are found either way. Defines muparser::muparser.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(PC_MUPARSER QUIET muparser)
endif()
find_path(Muparser_INCLUDE_DIR muParser.h HINTS ${PC_MUPARSER_INCLUDE_DIRS} PATH_SUFFIXES muparser)
find_library(Muparser_LIBRARY muparser HINTS ${PC_MUPARSER_LIBRARY_DIRS})
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Muparser REQUIRED_VARS Muparser_LIBRARY Muparser_INCLUDE_DIR)
if(Muparser_FOUND AND NOT TARGET muparser::muparser)
  add_library(muparser::muparser UNKNOWN IMPORTED)
  set_target_properties(muparser::muparser PROPERTIES IMPORTED_LOCATION ${Muparser_LIBRARY}
                        INTERFACE_INCLUDE_DIRECTORIES ${Muparser_INCLUDE_DIR})
endif()
mark_as_advanced(Muparser_INCLUDE_DIR Muparser_LIBRARY)

# Finds parallel double-precision MUMPS (Debian: libmumps-dev). Defines MUMPS::MUMPS.
find_path(MUMPS_INCLUDE_DIR dmumps_c.h PATH_SUFFIXES MUMPS)
find_library(MUMPS_D_LIBRARY dmumps)
find_library(MUMPS_COMMON_LIBRARY mumps_common)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS REQUIRED_VARS MUMPS_D_LIBRARY MUMPS_COMMON_LIBRARY
                                  MUMPS_INCLUDE_DIR)
if(MUMPS_FOUND AND NOT TARGET MUMPS::MUMPS)
  add_library(MUMPS::MUMPS INTERFACE IMPORTED)
  set_target_properties(MUMPS::MUMPS PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES ${MUMPS_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES "${MUMPS_D_LIBRARY};${MUMPS_COMMON_LIBRARY};MPI::MPI_C")
endif()
mark_as_advanced(MUMPS_INCLUDE_DIR MUMPS_D_LIBRARY MUMPS_COMMON_LIBRARY)

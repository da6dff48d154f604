# Third-party dependencies, all from Debian 12 packages (scripts/setup-common.sh installs them).
# The same file is included by the installed StressContactConfig.cmake so that consumers get
# identical imported targets.

find_package(MPI REQUIRED COMPONENTS C CXX)

# Debian's Trilinos 13.2 (built with MPI; Scalar double, LO int, GO long long, Serial node).
set(SC_TRILINOS_COMPONENTS Teuchos Tpetra Belos MueLu Teko Ifpack2 Amesos2 Intrepid2 Zoltan2
    Thyra Stratimikos Xpetra)
find_package(Trilinos 13.2 REQUIRED COMPONENTS ${SC_TRILINOS_COMPONENTS})

if(NOT TARGET StressContact::Teuchos)
  # Light target: parameter lists, RCP, comm, timers. Packages without linear algebra use this one
  # so that their translation units stay cheap to compile.
  add_library(StressContact::Teuchos INTERFACE IMPORTED GLOBAL)
  target_include_directories(StressContact::Teuchos INTERFACE ${Teuchos_INCLUDE_DIRS}
                             ${Teuchos_TPL_INCLUDE_DIRS})
  target_link_libraries(StressContact::Teuchos INTERFACE ${Teuchos_LIBRARIES} MPI::MPI_CXX)

  # Everything else of Trilinos that StressContact uses (Tpetra, Intrepid2, solvers, Zoltan2).
  set(_sc_tri_libs "")
  set(_sc_tri_incs "")
  foreach(pkg IN LISTS SC_TRILINOS_COMPONENTS)
    list(APPEND _sc_tri_libs ${${pkg}_LIBRARIES})
    list(APPEND _sc_tri_incs ${${pkg}_INCLUDE_DIRS} ${${pkg}_TPL_INCLUDE_DIRS})
  endforeach()
  list(REMOVE_DUPLICATES _sc_tri_libs)
  list(REMOVE_DUPLICATES _sc_tri_incs)
  add_library(StressContact::Trilinos INTERFACE IMPORTED GLOBAL)
  target_include_directories(StressContact::Trilinos INTERFACE ${_sc_tri_incs})
  target_link_libraries(StressContact::Trilinos INTERFACE ${_sc_tri_libs} MPI::MPI_CXX)
endif()

# Parallel HDF5 (Debian's openmpi flavour).
set(HDF5_PREFER_PARALLEL TRUE)
find_package(HDF5 REQUIRED COMPONENTS C)
if(NOT HDF5_IS_PARALLEL)
  message(FATAL_ERROR "StressContact needs parallel HDF5 (Debian: libhdf5-openmpi-dev); found a "
                      "serial HDF5 at ${HDF5_INCLUDE_DIRS}.")
endif()
if(NOT TARGET StressContact::HDF5)
  add_library(StressContact::HDF5 INTERFACE IMPORTED GLOBAL)
  target_include_directories(StressContact::HDF5 INTERFACE ${HDF5_INCLUDE_DIRS})
  target_compile_definitions(StressContact::HDF5 INTERFACE ${HDF5_DEFINITIONS})
  target_link_libraries(StressContact::HDF5 INTERFACE ${HDF5_C_LIBRARIES} MPI::MPI_C)
endif()

find_package(METIS REQUIRED)
find_package(Gmsh REQUIRED)
find_package(MUMPS REQUIRED)
find_package(Muparser REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)

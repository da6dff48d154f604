#include <sc/io/MpiIoEnvironment.hpp>

#include <cstdlib>

#include <mpi.h>

namespace sc::io {

bool leaveOutOverflowingMpiIoComponents()
{
#ifdef OPEN_MPI
  if (std::getenv("OMPI_MCA_sharedfp") != nullptr) return false;
  return ::setenv("OMPI_MCA_sharedfp", "^lockedfile", /*overwrite=*/0) == 0;
#else
  return false;  // MPICH and others have no such component
#endif
}

}  // namespace sc::io

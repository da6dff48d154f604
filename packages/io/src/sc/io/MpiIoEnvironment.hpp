#pragma once
// MPI-IO settings that must be in place before MPI_Init.

namespace sc::io {

/// Open MPI 4.1's shared-file-pointer component "lockedfile" probes every file MPI_File_open
/// opens by writing "<path>.locktest.<rank>" into a 256-byte stack buffer with sprintf
/// (ompi/mca/sharedfp/lockedfile/sharedfp_lockedfile.c, component_file_query): a path of more than
/// 244 characters (243 from rank 10 on) overflows it, and glibc's fortify check aborts the process
/// ("*** buffer overflow detected ***", exit status 134) inside H5Fcreate of the first field file,
/// after the first solve. Neither HDF5 nor StressContact uses shared file pointers, so the
/// component is left out: OMPI_MCA_sharedfp=^lockedfile, set in this process's environment, where
/// Open MPI reads it during MPI_Init (also under mpiexec: each rank sets it for itself). A value
/// the user gave (environment, or `mpiexec --mca sharedfp ...`, which reaches the ranks as the
/// same variable) is left alone. Call before MPI_Init; returns whether the variable was set.
bool leaveOutOverflowingMpiIoComponents();

}  // namespace sc::io

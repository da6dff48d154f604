#pragma once
// The run's output directory: created (with parents) before anything is written, and probed for
// writability up front, so that a bad Output/Directory fails at start-up with a clear message
// instead of after hours of computing.

#include <Teuchos_Comm.hpp>

#include <string>
#include <vector>

namespace sc::io {

/// Create \p directory (and its parents) if needed and check that a file can be created in it.
/// Throws sc::core::InputError naming the directory and the reason.
void createOutputDirectory(const std::string& directory);

/// Collective version: rank 0 creates and probes, every rank throws the same error on failure.
void createOutputDirectory(const std::string& directory, const Teuchos::Comm<int>& comm);

/// A run owns its output directory (docs/output.md "An earlier run's files"): remove from
/// \p directory the files that a StressContact run writes there: summary.json, history.csv,
/// `<base>.xdmf`, `<base>_c<NNNN>.h5`, contact_cycle<N>.csv, checkpoint.h5 and leftover
/// `<one of these>.tmp.<pid>`,
/// for \p baseName and for the Output/Base name recorded in an earlier summary.json. Other files
/// are left alone. Returns the names removed (sorted); throws sc::core::InputError if one cannot
/// be removed.
std::vector<std::string> removeEarlierRunFiles(const std::string& directory,
                                               const std::string& baseName);

/// Collective version: rank 0 removes, every rank gets the list (or the same error).
std::vector<std::string> removeEarlierRunFiles(const std::string& directory,
                                               const std::string& baseName,
                                               const Teuchos::Comm<int>& comm);

/// `--restart` (docs/adaptivity.md): the restarted run continues the files of the run it
/// restarts, whose last complete cycle is \p lastCycle. Remove what that run wrote after it (the
/// `<base>_c<NNNN>.h5` and contact_cycle<N>.csv of cycles N > lastCycle, written by a cycle that
/// was killed) and every leftover temporary `<one of the run's files>.tmp.<pid>`; keep the rest
/// (summary.json and history.csv are rewritten from the checkpoint's records).
/// Returns the names removed (sorted); throws sc::core::InputError if one cannot be removed.
std::vector<std::string> removeFilesAfterCycle(const std::string& directory,
                                               const std::string& baseName, int lastCycle);

/// Collective version: rank 0 removes, every rank gets the list (or the same error).
std::vector<std::string> removeFilesAfterCycle(const std::string& directory,
                                               const std::string& baseName, int lastCycle,
                                               const Teuchos::Comm<int>& comm);

/// Is there room for a file of about \p bytes at \p path (in \p directory)? Checks the free space
/// of the file system holding \p directory (statvfs) and the file-size limit (RLIMIT_FSIZE,
/// `ulimit -f`). Throws sc::core::Error naming the file, the size needed and what is available: a
/// full disk is found before HDF5 starts writing (a write that fails half-way leaves HDF5 unable
/// to close the file).
void checkRoomForFile(const std::string& directory, const std::string& path,
                      unsigned long long bytes);

/// Is anything in the way of the files a run writes in \p directory (summary.json, history.csv,
/// checkpoint.h5, `<base>.xdmf`, `<base>_c<NNNN>.h5`, contact_cycle<N>.csv)? An entry with one of
/// these names that is a directory, device, pipe or socket cannot be replaced by the file (the
/// rename fails after the file was written) and cannot be read as an earlier run's summary.
/// Throws sc::core::InputError naming the first such path; a missing directory is no error.
/// Writes nothing (run and --check alike).
void checkRunFileNamesAreFree(const std::string& directory, const std::string& baseName);

/// Collective version: rank 0 checks, every rank throws the same error on failure. Checks
/// checkRunFileNameLengths too.
void checkRunFileNamesAreFree(const std::string& directory, const std::string& baseName,
                              const Teuchos::Comm<int>& comm);

/// Do the names and paths of the files a run writes in \p directory fit the file system's
/// limits (pathconf: NAME_MAX per name, PATH_MAX per path; those of the nearest existing
/// ancestor if \p directory does not exist yet)? The longest is a cycle's field file under its
/// temporary name, `<base>_c<NNNN>.h5.tmp.<pid>` (pid up to 7 digits). Throws
/// sc::core::InputError naming Output/Base name or Output/Directory, the length and the limit:
/// otherwise the first field file fails after the first solve. Writes nothing.
void checkRunFileNameLengths(const std::string& directory, const std::string& baseName);

/// `--check`: would createOutputDirectory(\p directory) succeed? Creates nothing: an existing
/// directory, or else its nearest existing ancestor, must be a directory in which a file can be
/// created (probed with a file removed at once). Throws sc::core::InputError naming the directory.
void checkOutputDirectory(const std::string& directory);

/// Collective version: rank 0 checks, every rank throws the same error on failure.
void checkOutputDirectory(const std::string& directory, const Teuchos::Comm<int>& comm);

}  // namespace sc::io

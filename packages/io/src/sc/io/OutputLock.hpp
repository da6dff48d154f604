#pragma once
// One run per output directory. Two runs writing into one directory would both succeed and leave
// the summary.json of one beside the fields and CSVs of the other; so a run holds a lock file,
// `stresscontact.lock`, in its output directory from before it removes an earlier run's files
// until it ends (docs/reliability.md, "output").
//
// The lock is a file created with O_CREAT | O_EXCL, holding the owner's pid, host name and
// process start time; not an flock/fcntl lock. Reasons:
//  - O_EXCL creation is atomic on local file systems and on NFS (v3 and later), and the file is
//    seen from every node of a cluster. flock/fcntl locks depend on the NFS lock manager (lockd,
//    or NFSv4 state); on file systems mounted with local-only locking (e.g. Lustre's localflock,
//    NFS with nolock) they exclude processes of one node only, and two runs on two nodes would
//    both get the lock without any error.
//  - The price: a lock file outlives a run that is killed (SIGKILL, a node failure), whereas an
//    flock/fcntl lock is released by the kernel. Such a stale lock is recognised: its host is
//    this host and its pid no longer runs (or now belongs to another process: a different start
//    time, or a zombie). The next run takes it over with a note on stderr. A lock of another host
//    cannot be checked from here: it is treated as live, and the error says to remove the file if
//    that run is gone.
// Only rank 0 touches the lock; errors reach every rank (runOnRoot).

#include <Teuchos_Comm.hpp>

#include <string>

namespace sc::io {

/// The lock file's name in the output directory.
inline constexpr const char* kOutputLockName = "stresscontact.lock";

/// The lock of a run's output directory, held for the object's lifetime.
class OutputLock {
public:
  /// Collective; rank 0 takes the lock of \p directory (which must exist). Throws
  /// sc::core::InputError on every rank, naming the directory, the owner's pid and host, if
  /// another run that is alive (or on another host) holds it; the directory is then left as it
  /// was. A stale lock is taken over (takenOver() describes it).
  OutputLock(const Teuchos::Comm<int>& comm, std::string directory);
  /// Rank 0: removes the lock file if it is still this process's (no communication, so it is
  /// safe during stack unwinding after an error).
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  /// On rank 0 after taking over a stale lock: a sentence naming it and its dead owner; else "".
  const std::string& takenOver() const { return takenOver_; }
  /// The lock file's path.
  const std::string& path() const { return path_; }

private:
  std::string directory_, path_, takenOver_;
  bool held_ = false;
};

/// `--check`: throws sc::core::InputError (as the run would) if \p directory holds the lock of a
/// live run, or a lock file that names no run. Writes nothing; a missing directory or lock, or a
/// stale lock, is no error.
void checkOutputLock(const std::string& directory);

/// Collective version: rank 0 checks, every rank throws the same error on failure.
void checkOutputLock(const std::string& directory, const Teuchos::Comm<int>& comm);

}  // namespace sc::io

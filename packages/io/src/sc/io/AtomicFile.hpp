#pragma once
// A file that appears under its final name only once it is complete (docs/output.md, "Atomic
// writes"). Content goes to "<path>.tmp.<pid>" and is renamed over <path> by commit(); rename(2)
// within one directory is atomic on POSIX file systems, so a reader (or a run killed half-way)
// sees either the previous complete file or the new complete file, never a truncated one.

#include <fstream>
#include <string>

namespace sc::io {

/// Temporary name used for \p path by this process: "<path>.tmp.<pid>".
std::string temporaryPathFor(const std::string& path);

/// Same with an explicit process id (all ranks writing one collective file must agree on it).
std::string temporaryPathFor(const std::string& path, long processId);

/// Rename \p from to \p to (atomic replace); throws sc::core::Error naming both paths.
void renameFile(const std::string& from, const std::string& to);

class AtomicFile {
public:
  /// Opens "<path>.tmp.<pid>" for writing; throws sc::core::Error naming it if that fails.
  explicit AtomicFile(std::string path);
  /// Removes the temporary if commit() was not reached (e.g. an exception while writing).
  ~AtomicFile();

  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Stream to write the content to.
  std::ostream& stream() { return out_; }

  /// Flush, close, check for write errors, and rename onto the final path.
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temporaryPath() const { return tmpPath_; }

private:
  std::string path_;
  std::string tmpPath_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Write \p content to \p path atomically (AtomicFile in one call).
void writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace sc::io

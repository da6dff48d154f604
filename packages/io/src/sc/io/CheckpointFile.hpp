#pragma once
// A checkpoint file (docs/output.md "checkpoint.h5"): named integer arrays,
// double arrays and strings in one HDF5 file, written by one process under a temporary name and
// renamed into place, so that a run killed while writing it leaves the previous checkpoint
// intact. The io package stores the arrays; what they mean is the caller's (the application
// keeps the mesh, the contact state and the summary in it).
//
// Layout: one 1-D dataset per entry at the root, int64 ("ints"), float64 ("doubles") or uint8
// (strings, UTF-8 bytes, no terminator), the root attribute "format" = formatName() and the root
// attribute "checksum" (uint64, checksum()): read() verifies it, so that a damaged or edited
// checkpoint is refused before a restart changes anything.

#include <map>
#include <string>
#include <vector>

namespace sc::io {

class CheckpointFile {
public:
  /// The value of the root attribute "format" (a file without it is not a checkpoint).
  static const char* formatName() { return "StressContact checkpoint"; }

  void setInts(const std::string& name, std::vector<long long> values);
  void setDoubles(const std::string& name, std::vector<double> values);
  void setString(const std::string& name, const std::string& value);

  /// The entry \p name; throws sc::core::InputError naming the file and the entry if it is
  /// missing (or of another kind).
  const std::vector<long long>& ints(const std::string& name) const;
  const std::vector<double>& doubles(const std::string& name) const;
  const std::string& string(const std::string& name) const;
  bool has(const std::string& name) const;

  /// Not collective: write to "<path>.tmp.<pid>" and rename onto \p path. Throws sc::core::Error
  /// naming the file (and the system's reason for a full disk) on failure; no temporary is left.
  void write(const std::string& path) const;

  /// Not collective: read every entry of \p path. Throws sc::core::InputError naming the file if
  /// it is missing, not an HDF5 file, or not a checkpoint.
  static CheckpointFile read(const std::string& path);

  /// FNV-1a (64 bits) over every entry's kind, name, length and bytes. write() records it in the
  /// root attribute "checksum"; read() refuses a file whose datasets do not hash to it.
  unsigned long long checksum() const;

  /// The file this was read from (quoted in errors), empty for one being built.
  const std::string& path() const { return path_; }

private:
  std::string path_;
  std::map<std::string, std::vector<long long>> ints_;
  std::map<std::string, std::vector<double>> doubles_;
  std::map<std::string, std::string> strings_;
};

}  // namespace sc::io

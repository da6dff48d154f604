#pragma once
// One progress line per phase and cycle on rank 0, flushed at once, with the elapsed wall time,
// so that a long run shows where it is:
//   [    12.3 s] cycle 2/5 | assemble | 81920 DOFs

#include <ostream>
#include <string>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

namespace sc::core {

class Progress {
public:
  Progress(Teuchos::RCP<const Teuchos::Comm<int>> comm, std::ostream& out, bool quiet = false);

  void setCycle(int cycle, int totalCycles);
  /// A line "[t s] cycle c/n | phase | detail" on rank 0.
  void report(const std::string& phase, const std::string& detail = "") const;
  /// A plain message on rank 0 (no cycle prefix).
  void message(const std::string& text) const;
  bool isRoot() const { return rank_ == 0; }

private:
  std::ostream& out_;
  int rank_;
  bool quiet_;
  int cycle_ = -1, totalCycles_ = 0;
  double start_;
};

}  // namespace sc::core

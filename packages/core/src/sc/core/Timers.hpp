#pragma once
// Wall-clock time per phase (mesh, assemble, solve, reconstruct, estimate, mark, refine, transfer,
// output, ...), per cycle, and the peak resident memory.
// Each phase is also a Teuchos::TimeMonitor timer ("StressContact: <phase>") so that Trilinos'
// own summary tables include it. Reported times are the maximum over ranks (the slowest rank
// is what a user waits for).

#include <map>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Teuchos_Time.hpp>

namespace sc::core {

class PhaseTimers {
public:
  explicit PhaseTimers(Teuchos::RCP<const Teuchos::Comm<int>> comm);

  /// RAII scope: time from construction to destruction is added to `phase` of the current cycle.
  class Scope {
  public:
    Scope(PhaseTimers& owner, std::string phase);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

  private:
    PhaseTimers& owner_;
    std::string phase_;
    Teuchos::RCP<Teuchos::Time> teuchosTimer_;
    double start_;
  };

  Scope scope(const std::string& phase) { return Scope(*this, phase); }

  /// Close the current cycle; subsequent scopes count towards a new one.
  void nextCycle();

  /// Seconds per phase in the current cycle, maximum over ranks (collective call).
  std::map<std::string, double> cycleTimings() const;

  /// Seconds since construction on this rank.
  double elapsed() const;

  /// Peak resident memory of the process since it started (getrusage ru_maxrss), in MB
  /// (2^20 bytes): the maximum over ranks and the sum over ranks (collective call). ru_maxrss is
  /// a high-water mark: per cycle it is the peak of all cycles so far, not of that cycle alone.
  struct PeakMemory {
    double maxMB = 0.0;
    double sumMB = 0.0;
  };
  PeakMemory peakMemory() const;

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<std::string> order_;  // phases in first-use order
  std::map<std::string, double> current_;
  double start_;
};

}  // namespace sc::core

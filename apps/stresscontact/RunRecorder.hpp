#pragma once
// The output step's record of a cycle (docs/output.md): summary.json's cycle record with its
// timings, history.csv, the contact CSV and the progress lines that report them, all from a
// CycleResults value.
#include <map>
#include <string>

#include <Teuchos_Comm.hpp>

#include <sc/adapt/AdaptiveProblem.hpp>
#include <sc/adapt/AdaptivitySettings.hpp>
#include <sc/core/Progress.hpp>
#include <sc/core/Timers.hpp>

#include "CycleResults.hpp"

namespace sc::io {
class RunSummary;
}

namespace sc::app {

class RunRecorder {
public:
  /// Records into `summary` (kept by the caller: the checkpoint copies it) and reports through
  /// `progress`; `directory` is the run's output directory.
  RunRecorder(const Teuchos::Comm<int>& comm, const core::Progress& progress,
              io::RunSummary& summary, std::string directory, int dim, bool hasContact);

  /// contact_cycle<N>.csv: one row per contact point of every rank (collective; nothing
  /// without contact).
  void writeContactTable(const CycleResults& results) const;
  /// The cycle's record in summary.json: contact (with the Hertz comparison), η, the stop
  /// reason, reactions and force balance, DOFs, the linear solver, the errors, the mesh; reports
  /// the contact and error lines.
  void recordCycle(const CycleResults& results, const adapt::Marking& marking,
                   const std::string& stopReason);
  /// The cycle's timings and peak memory into its record, and the one-line cycle summary.
  void recordCost(const CycleResults& results, const std::map<std::string, double>& timings,
                  const core::PhaseTimers::PeakMemory& memory);
  /// summary.json, then history.csv from its cycle records (collective).
  void write();
  /// Why the run stopped, into summary.json's "stop" record, and with accuracy targets or a time
  /// budget whether the targets were met; returns the progress line's note on that ("" without
  /// targets or budget).
  std::string recordStop(const std::string& stopReason,
                         const adapt::AdaptivitySettings& adaptivity);

private:
  const Teuchos::Comm<int>& comm_;
  const core::Progress& progress_;
  io::RunSummary& summary_;
  std::string directory_;
  int dim_;
  bool hasContact_;
};

}  // namespace sc::app

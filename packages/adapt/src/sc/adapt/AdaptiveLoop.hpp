#pragma once
// The adaptive loop (docs/theory.md §"Adaptivity", docs/architecture.md "The adaptive loop"):
//
//   for cycle = first, first + 1, ...:
//     refine(marking of the previous cycle)          (not in cycle 0)
//     solve(cycle); estimate(cycle)
//     stop criteria: Cycles, Max DOFs, Target error, the accuracy targets
//     if going on: mark; the next mesh's memory forecast, the time budget (may stop the run)
//     output(cycle, marking, stop reason)
//     if going on: checkpoint(cycle, marking), else return the stop reason
//
// It owns the Marker and the StopCriteria built from the `Adaptivity` settings (so a bad
// setting fails when the loop is built, before any work); the problem (AdaptiveProblem.hpp)
// owns everything else. Refinement happens at the start of the next cycle so that its progress
// lines and timings count towards the cycle whose mesh it builds, and so that a restart from a
// checkpoint of cycle N is run(problem, N + 1, marking saved with it).
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/adapt/AdaptiveProblem.hpp>
#include <sc/adapt/AdaptivitySettings.hpp>

namespace sc::core {
class Progress;
class PhaseTimers;
}  // namespace sc::core

namespace sc::adapt {

class Marker;
class StopCriteria;

class AdaptiveLoop {
public:
  /// Throws core::InputError for settings out of range. `progress` (cycle numbers, the marking
  /// and stop lines) and `timers` (the "mark" phase) are optional and borrowed: they must
  /// outlive the loop. Collective (rank 0's clock starts the time budget).
  AdaptiveLoop(const AdaptivitySettings& settings, Teuchos::RCP<const Teuchos::Comm<int>> comm,
               core::Progress* progress = nullptr, core::PhaseTimers* timers = nullptr);
  ~AdaptiveLoop();
  AdaptiveLoop(const AdaptiveLoop&) = delete;
  AdaptiveLoop& operator=(const AdaptiveLoop&) = delete;

  /// Cycles from `firstCycle` until a stop criterion holds; returns its reason. A restart passes
  /// the cycle after its checkpoint's and the marking saved with it (Marking::elements; the
  /// loop sets Marking::uniform from the settings). Exceptions of the problem's steps pass
  /// through.
  /// `cycleOffset` (load steps, docs/theory.md §"Load steps"): the problem's steps are called
  /// with cycle + cycleOffset, so that the cycles of a run's later steps continue its numbering,
  /// while the loop counts its own cycles from 0 (a cycle 0 is not refined, and Cycles counts
  /// the cycles of this run() call).
  std::string run(AdaptiveProblem& problem, int firstCycle = 0,
                  std::vector<int> markedBeforeFirstCycle = {}, int cycleOffset = 0);

  const AdaptivitySettings& settings() const { return settings_; }
  const Marker& marker() const { return *marker_; }
  const StopCriteria& stopCriteria() const { return *stop_; }

private:
  /// The marking of a cycle that goes on.
  Marking mark(const CycleEstimate& estimate) const;

  AdaptivitySettings settings_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  core::Progress* progress_;
  core::PhaseTimers* timers_;
  std::unique_ptr<Marker> marker_;
  std::unique_ptr<StopCriteria> stop_;
  double startTime_;  ///< rank 0's wall time at construction: `Time budget` counts from here
};

}  // namespace sc::adapt

#pragma once
// When the adaptive loop stops refining (docs/theory.md §"Adaptivity", docs/adaptivity.md
// "Accuracy targets and a time budget"): after `Cycles` refinements, once a solved cycle has
// `Max DOFs` DOFs, once η ≤ `Target error` · ‖A^{1/2}σ_h‖, once the estimated errors of the
// quantities with a target (`Target force error`, ...) all meet them, or when the next cycle is
// forecast to end beyond the `Time budget`. Checked after each solved (and estimated) cycle.
#include <string>
#include <vector>

#include <sc/adapt/AdaptiveProblem.hpp>
#include <sc/adapt/AdaptivitySettings.hpp>

namespace sc::adapt {

/// One accuracy target against a cycle's estimate.
struct TargetStatus {
  std::string name;             ///< the quantity (QuantityEstimate::name)
  std::string key;              ///< its deck key, e.g. "Adaptivity/Target force error"
  double target = 0.0;          ///< relative
  double relativeError = -1.0;  ///< estimated error / |value|; negative: no estimate
  bool met = false;
};

class StopCriteria {
public:
  explicit StopCriteria(const AdaptivitySettings& settings);
  /// The reason to stop after cycle `cycle` (0-based), or "" to refine and go on. `eta` and
  /// `stressNorm` (‖A^{1/2}σ_h‖) are ignored when negative (no estimate this cycle).
  std::string reason(int cycle, long long dofs, double eta, double stressNorm) const;
  /// Every target given, against `quantities` (a target whose quantity is missing or has no
  /// estimate is not met).
  std::vector<TargetStatus> targets(const std::vector<QuantityEstimate>& quantities) const;
  /// "accuracy targets met: ..." when there are targets and all are met, else "".
  std::string targetsReason(const std::vector<QuantityEstimate>& quantities) const;
  /// The reason to stop before a next cycle forecast to take `nextSeconds` after `elapsed`
  /// seconds of the run, if that ends beyond `Time budget` (the run keeps its best cycle, this
  /// one); names the targets not met. "" without a budget or within it.
  std::string budgetReason(double elapsed, double nextSeconds,
                           const std::vector<QuantityEstimate>& quantities) const;
  /// "; accuracy targets not met: ..." for a run that stops for another reason with targets
  /// not met, else "".
  std::string unmetTargets(const std::vector<QuantityEstimate>& quantities) const;
  /// The reason to stop before a refinement whose next mesh is estimated at `nextDofs` DOFs
  /// and `nextBytes` bytes, if that exceeds `limitBytes` (from `limitSource`, e.g.
  /// "MemAvailable in /proc/meminfo"), or "" (the run stops cleanly, with
  /// its solved cycles written, instead of dying in std::bad_alloc; docs/mesh.md "Resource
  /// limits").
  std::string memoryReason(double nextDofs, double nextBytes, double limitBytes,
                           const std::string& limitSource) const;

private:
  AdaptivitySettings settings_;
};

}  // namespace sc::adapt

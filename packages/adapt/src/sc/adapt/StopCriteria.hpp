#pragma once
// When the adaptive loop stops refining (docs/theory.md §"Adaptivity"): after `Cycles`
// refinements, once a solved cycle has `Max DOFs` DOFs, or once η ≤ `Target error` ·
// ‖A^{1/2}σ_h‖. Checked after each solved (and estimated) cycle.
#include <string>

#include <sc/adapt/AdaptivitySettings.hpp>

namespace sc::adapt {

class StopCriteria {
public:
  explicit StopCriteria(const AdaptivitySettings& settings);
  /// The reason to stop after cycle `cycle` (0-based), or "" to refine and go on. `eta` and
  /// `stressNorm` (‖A^{1/2}σ_h‖) are ignored when negative (no estimate this cycle).
  std::string reason(int cycle, long long dofs, double eta, double stressNorm) const;

private:
  AdaptivitySettings settings_;
};

}  // namespace sc::adapt

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
  /// The reason to stop before a refinement whose next mesh is estimated at `nextDofs` DOFs
  /// and `nextBytes` bytes, if that exceeds `limitBytes` (from `limitSource`, e.g.
  /// "MemAvailable in /proc/meminfo"), or "" (the run stops cleanly, with
  /// its solved cycles written, instead of dying in std::bad_alloc; docs/mesh.md "Resource limits").
  std::string memoryReason(double nextDofs, double nextBytes, double limitBytes,
                           const std::string& limitSource) const;

private:
  AdaptivitySettings settings_;
};

}  // namespace sc::adapt

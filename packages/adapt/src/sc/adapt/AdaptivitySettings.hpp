#pragma once
// The "Adaptivity" sublist (docs/parameters.txt): cycles, marking and the stop criteria of the
// solve → estimate → mark → refine loop (docs/theory.md §"Adaptivity").
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace sc::adapt {

struct AdaptivitySettings {
  int cycles{};            ///< refinement cycles after the first solve
  std::string marking;     ///< a name known to createMarker (Marker.hpp)
  double bulkParameter{};  ///< θ ∈ (0, 1] of Dörfler / maximum marking
  long long maxDofs{};     ///< no refinement once a solved cycle has this many DOFs
  double targetError{};    ///< stop when η ≤ targetError · ‖A^{1/2}σ_h‖ (0: never)
  /// Relative targets on the estimated errors of the quantities users read (0: none), checked
  /// together: the run stops at the first cycle that meets all of them (StopCriteria).
  double targetForceError{};     ///< |contact force|
  double targetWidthError{};     ///< contact half-width (2D) / radius (3D)
  double targetPressureError{};  ///< peak contact pressure
  double targetStickError{};     ///< stick-zone half-width / radius
  double timeBudget{};           ///< seconds of the run (0: none)

  /// Any target on a quantity is set.
  bool hasQuantityTargets() const
  {
    return targetForceError > 0.0 || targetWidthError > 0.0 || targetPressureError > 0.0 ||
           targetStickError > 0.0;
  }

  /// Marking needs element indicators (every strategy but Uniform).
  bool needsIndicators() const { return marking != "Uniform"; }

  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  /// Reads a validated "Adaptivity" list (no second default).
  static AdaptivitySettings fromParameters(const Teuchos::ParameterList& adaptivityList);
};

}  // namespace sc::adapt

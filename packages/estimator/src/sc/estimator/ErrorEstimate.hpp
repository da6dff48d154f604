#pragma once
// The result of an estimate: η² split into named global parts, and the element indicators η_T²
// (the sum of every part's share on T), which the marking uses. docs/theory.md §"Estimator".
#include <string>
#include <utility>
#include <vector>

namespace sc::estimator {

struct ErrorEstimate {
  /// η_T² of this rank's owned elements, in MixedElasticitySpace::ownedElements() order.
  std::vector<double> indicators;
  /// Global η² of each part, in report order; Σ parts = η². Elasticity: "volume", "asymmetry",
  /// "oscillation"; the contact parts of η_CF will be appended by their EstimatorContribution.
  std::vector<std::pair<std::string, double>> parts;
  /// ‖A^{1/2}σ_h‖ (global): the norm that `Adaptivity/Target error` is relative to.
  double stressEnergyNorm = 0.0;

  /// η = (Σ parts)^{1/2}.
  double total() const;
  /// η² of the part `name` (InternalError if absent).
  double squared(const std::string& name) const;
  void addPart(const std::string& name, double squaredValue)
  {
    parts.emplace_back(name, squaredValue);
  }
  /// Signed quantities reported beside η but not part of it (the talk's signed normal contact
  /// part `contact_normal_signed`, in the units of η²).
  std::vector<std::pair<std::string, double>> diagnostics;
  void addDiagnostic(const std::string& name, double value)
  {
    diagnostics.emplace_back(name, value);
  }
};

}  // namespace sc::estimator

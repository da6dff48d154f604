#pragma once
// The "Estimator" sublist (docs/parameters.txt): the degree of the displacement reconstruction.
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace sc::estimator {

struct EstimatorSettings {
  /// u^R in continuous P_{k+1} (default, docs/theory.md) or P_k (the talk's choice: rate k, and
  /// an efficiency index that grows under refinement).
  bool reconstructionDegreeKPlusOne{};

  /// Degree p of u^R for a discretisation of degree k.
  int reconstructionDegree(int k) const { return reconstructionDegreeKPlusOne ? k + 1 : k; }

  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  /// Reads a validated "Estimator" list (no second default).
  static EstimatorSettings fromParameters(const Teuchos::ParameterList& estimatorList);
};

}  // namespace sc::estimator

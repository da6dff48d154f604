#include "sc/estimator/EstimatorSettings.hpp"

#include <sc/core/Parameters.hpp>

namespace sc::estimator {

Teuchos::RCP<const Teuchos::ParameterList> EstimatorSettings::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Estimator"));
    core::declareChoice(*pl, "Reconstruction degree", "k+1", {"k+1", "k"},
                        "Polynomial degree of the continuous reconstructed displacement u^R "
                        "(docs/theory.md): k+1 (default; ‖∇(u − u^R)‖ = O(h^{k+1}), efficiency "
                        "index bounded) or k (the talk's P_k: one order lower, the index grows "
                        "under refinement).");
    return pl;
  }();
  return valid;
}

EstimatorSettings EstimatorSettings::fromParameters(const Teuchos::ParameterList& pl)
{
  EstimatorSettings s;
  s.reconstructionDegreeKPlusOne = pl.get<std::string>("Reconstruction degree") == "k+1";
  return s;
}

}  // namespace sc::estimator

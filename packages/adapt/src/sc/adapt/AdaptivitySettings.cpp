#include "sc/adapt/AdaptivitySettings.hpp"

#include <climits>

#include <sc/core/Parameters.hpp>

namespace sc::adapt {

Teuchos::RCP<const Teuchos::ParameterList> AdaptivitySettings::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Adaptivity"));
    core::declareInt(*pl, "Cycles", 0,
                     "Most refinement cycles after the first solve: the run has at most Cycles + 1 "
                     "levels (fewer if Max DOFs or Target error stops it).",
                     0, 100);
    core::declareChoice(*pl, "Marking", "Dorfler", {"Dorfler", "Maximum", "Uniform"},
                        "Dorfler: the smallest set of elements holding the fraction Bulk parameter "
                        "of η² = Σ η_T²; Maximum: elements with η_T ≥ Bulk parameter · max η_T; "
                        "Uniform: every element (convergence studies, no estimator needed).");
    core::declareReal(*pl, "Bulk parameter", 0.5,
                      "θ of Dörfler and maximum marking, in (0, 1]: larger marks more.", 0.0, true,
                      1.0, false);
    core::declareInt(*pl, "Max DOFs", 2000000,
                     "No further refinement once a solved cycle has at least this many DOFs "
                     "(total of σ, u, θ).",
                     1, INT_MAX);
    core::declareReal(*pl, "Target error", 0.0,
                      "Stop when η ≤ Target error · ‖A^{1/2}σ_h‖ (η relative to the energy norm "
                      "of the discrete stress, docs/theory.md); 0: never.",
                      0.0, false, core::kInfinity, false);
    return pl;
  }();
  return valid;
}

AdaptivitySettings AdaptivitySettings::fromParameters(const Teuchos::ParameterList& pl)
{
  AdaptivitySettings s;
  s.cycles = pl.get<int>("Cycles");
  s.marking = pl.get<std::string>("Marking");
  s.bulkParameter = pl.get<double>("Bulk parameter");
  s.maxDofs = pl.get<int>("Max DOFs");
  s.targetError = pl.get<double>("Target error");
  return s;
}

}  // namespace sc::adapt

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
    // Accuracy as the user's input (docs/adaptivity.md "Accuracy targets and a time budget").
    const std::string relative =
        " relative to the quantity, from the error bars of summary.json (contact.estimated_error, "
        "docs/output.md); the run stops at the first cycle that meets every target given; 0: no "
        "target. Scenes with contact only.";
    core::declareReal(*pl, "Target force error", 0.0,
                      "Target on the estimated error of the contact force |F|" + relative, 0.0,
                      false, 1.0, false);
    core::declareReal(*pl, "Target width error", 0.0,
                      "Target on the estimated error of the contact half-width (2D) or radius "
                      "(3D)" +
                          relative,
                      0.0, false, 1.0, false);
    core::declareReal(*pl, "Target pressure error", 0.0,
                      "Target on the estimated error of the peak contact pressure" + relative, 0.0,
                      false, 1.0, false);
    core::declareReal(*pl, "Target stick width error", 0.0,
                      "Target on the estimated error of the stick zone's half-width (2D) or "
                      "radius (3D)" +
                          relative + " Needs friction.",
                      0.0, false, 1.0, false);
    core::declareReal(*pl, "Time budget", 0.0,
                      "Wall-time budget of the run in seconds, counted from the start of the run "
                      "(after reading the deck): no cycle is started that the previous cycle's "
                      "time, scaled by the growth of the DOFs, forecasts to end beyond it; the run "
                      "then stops with the best cycle it reached. 0: no budget.",
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
  s.targetForceError = pl.get<double>("Target force error");
  s.targetWidthError = pl.get<double>("Target width error");
  s.targetPressureError = pl.get<double>("Target pressure error");
  s.targetStickError = pl.get<double>("Target stick width error");
  s.timeBudget = pl.get<double>("Time budget");
  return s;
}

}  // namespace sc::adapt

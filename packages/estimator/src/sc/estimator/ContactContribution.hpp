#pragma once
// The contact and friction parts of η_CF (docs/theory.md §"Contact terms", docs/theory.md
// §"Estimator"), added to the elasticity estimate by ErrorEstimator::addContribution. On each
// contact face F, at face quadrature points, in the contact frame (n, tangent plane) of the contact
// solver (Contact/Frame) with the gap g along n, t = σ_h n_F, σ_N = n·t, σ_T = t − σ_N n, u_N =
// n·u^R, u_T = u^R − u_N n:
//   contact_complementarity  ∫_F (g − u_N)₊ (−σ_N)₊                 (the gap left open under
//   pressure) contact_penetration      ∫_F (u_N − g)₊ |σ_N|                    (u^R is not
//   constrained: it can penetrate) contact_tension          h_F ‖(σ_N)₊‖²_F / (2μ) (the trace pulls
//   between the DOF points) friction                 |∫_F (s |u_T| + σ_T·u_T)|,  s = μ_F|σ_N|
//   (Coulomb) or the Tresca bound
// Every part is an energy (stress × displacement × measure), like 2μ‖Aσ_h − ε(u^R)‖². The friction
// part is the talk's tangential and friction parts integrated as one pointwise sum: each alone is
// the frictional work on the whole slip (~100× the estimate) and they cancel. The talk's signed
// normal part ∫_ΓC (u_N − g) σ_N is reported beside them as the diagnostic
// `contact_normal_signed` (negative where u^R penetrates), not added to η.
#include <string>
#include <vector>

#include <sc/contact/ContactSettings.hpp>
#include <sc/core/ProblemData.hpp>

#include "sc/estimator/ErrorEstimator.hpp"

namespace sc::disc {
class MixedElasticitySpace;
}

namespace sc::estimator {

/// The friction part does not vanish in the stick limit: in the stick zone it is about
/// μ_F|σ_N| |u^R_T|, with u^R_T the reconstruction's tangential trace (its error there), so at
/// a fixed mesh η grows like √μ_F while the solution does not change (docs/theory.md §"Friction
/// part for large μ_F"). On the Hertz deck it is 33–54% of η² at μ_F = 2 over the first three
/// cycles, 58–86% at 5 to 10 and 98% at 100; above this Coulomb coefficient a run is warned.
inline constexpr double kLargeFrictionCoefficient = 2.0;

/// For Coulomb friction with Contact/Friction coefficient above kLargeFrictionCoefficient, the
/// warning that η and the marking are dominated by the friction part; "" otherwise.
std::string largeFrictionWarning(const contact::ContactSettings& settings);

class ContactContribution : public EstimatorContribution {
public:
  ContactContribution(const disc::MixedElasticitySpace& space,
                      const contact::ContactSettings& settings, const core::Material& material,
                      std::vector<std::string> contactBoundaries);
  void addTo(ErrorEstimate& estimate, assembly::ElementSolution& solution,
             const DisplacementReconstruction& reconstruction,
             const Teuchos::Comm<int>& comm) const override;

private:
  const disc::MixedElasticitySpace& space_;
  contact::ContactSettings settings_;
  core::Material material_;
  std::vector<std::string> boundaries_;
};

}  // namespace sc::estimator

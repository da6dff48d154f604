#pragma once
// The reconstruction-based a posteriori estimator of the mixed elasticity solution
// (docs/theory.md §"Estimator"). Per owned element T, with u^R the reconstruction:
//   volume      2μ ‖Aσ_h − ε(u^R)‖²_T             (every part is an energy: λ- and unit-robust)
//   asymmetry   ‖as σ_h‖²_T / (2μ)               (σ_h is only weakly symmetric)
//   oscillation (h_T/π)² ‖f + div σ_h‖²_T / (2μ)                      (f − Π_k f)
//             + Σ_{F ⊂ Γ_N ∩ ∂T} h_F ‖t − σ_h n‖²_F / (2μ)            (traction data)
//             + Σ_{F ⊂ Γ_D ∩ ∂T} 2μ h_F⁻¹ ‖u_D − u^R‖²_F              (u_D vs its interpolant)
// η_T² is their sum, η² = Σ_T η_T². Contact terms (η_CF) are not built here: they come in
// through an EstimatorContribution (added by the contact scene), which appends its parts and its
// element shares. Without one, a scene with a Contact boundary has no complete estimate, and the
// estimator refuses it.
#include <memory>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/estimator/DisplacementReconstruction.hpp>
#include <sc/estimator/ErrorEstimate.hpp>
#include <sc/estimator/EstimatorSettings.hpp>

namespace sc::assembly {
class ElementSolution;
}

namespace sc::estimator {

/// Another term of η² (the contact parts of η_CF): adds its global parts (addPart) and its
/// element shares (into estimate.indicators) after the elasticity terms are in.
class EstimatorContribution {
public:
  virtual ~EstimatorContribution() = default;
  virtual void addTo(ErrorEstimate& estimate, assembly::ElementSolution& solution,
                     const DisplacementReconstruction& reconstruction,
                     const Teuchos::Comm<int>& comm) const = 0;
};

class ErrorEstimator {
public:
  ErrorEstimator(const assembly::MixedElasticityAssembler& assembler,
                 const EstimatorSettings& settings, Teuchos::RCP<const Teuchos::Comm<int>> comm);
  ~ErrorEstimator();
  ErrorEstimator(const ErrorEstimator&) = delete;
  ErrorEstimator& operator=(const ErrorEstimator&) = delete;

  void addContribution(std::shared_ptr<const EstimatorContribution> contribution);

  /// Reconstruct u^R from `solution` (owned map of the assembler) and estimate. `data` must be
  /// the data the system was assembled with. The same as reconstruct() then
  /// estimateReconstructed(), the two steps the application times separately.
  ErrorEstimate estimate(const assembly::MultiVector& solution,
                         const assembly::ElasticityData& data);

  /// Step 1: u^R from `solution` (local Neumann problems, averaging at shared nodes; collective).
  void reconstruct(const assembly::MultiVector& solution, const assembly::ElasticityData& data);
  /// Step 2: η and its parts from `solution` and the u^R of the last reconstruct() (same
  /// solution and data).
  ErrorEstimate estimateReconstructed(const assembly::MultiVector& solution,
                                      const assembly::ElasticityData& data);

  /// The reconstruction of the last estimate().
  const DisplacementReconstruction& reconstruction() const { return *reconstruction_; }

private:
  const assembly::MixedElasticityAssembler& assembler_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::unique_ptr<DisplacementReconstruction> reconstruction_;
  bool reconstructed_ = false;
  std::vector<std::shared_ptr<const EstimatorContribution>> contributions_;
};

}  // namespace sc::estimator

#pragma once
// A solution vector read element by element: the element's coefficients (from the overlap map,
// so shared DOFs owned by other ranks are included) and σ_h, div σ_h, u_h, θ_h at the points of
// an ElementValues / FaceValues. Shared by the postprocessing (errors, cell averages) and the
// estimator, so that every element loop reads the solution the same way.
#include <vector>

#include <Teuchos_ArrayRCP.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>

namespace sc::disc {
class ElementValues;
class FaceValues;
}  // namespace sc::disc

namespace sc::assembly {

/// σ_h (d×d row-major), div σ_h, u_h, θ_h at one point.
struct PointValues {
  double sigma[9], divSigma[3], u[3], theta[3];
};

class ElementSolution {
public:
  /// `solution` lives on the assembler's owned map; it is imported once to the overlap map.
  ElementSolution(const MixedElasticityAssembler& assembler, const MultiVector& solution);
  ~ElementSolution();
  ElementSolution(const ElementSolution&) = delete;
  ElementSolution& operator=(const ElementSolution&) = delete;

  /// Load element e's coefficients (e must be one of the space's owned elements).
  void gather(int e);
  /// The loaded coefficients, in the space's element-local layout.
  const std::vector<double>& coefficients() const { return c_; }
  /// All fields at cubature point q of `ev` (reinit'ed on the gathered element).
  void evaluate(const disc::ElementValues& ev, int q, PointValues& v) const;
  /// σ_h (d×d row-major) at point q of `fv` (reinit'ed on a face of the gathered element).
  void stress(const disc::FaceValues& fv, int q, double* sigma) const;

private:
  const disc::MixedElasticitySpace& space_;
  Teuchos::RCP<const Map> overlapMap_;
  Teuchos::RCP<MultiVector> overlap_;
  Teuchos::ArrayRCP<const double> x_;
  std::vector<double> c_;
};

}  // namespace sc::assembly

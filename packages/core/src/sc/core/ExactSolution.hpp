#pragma once
// Exact solutions for verification (manufactured solutions, patch tests): σ, u, θ and the data
// f, u_D, t they induce. Points are given as x[0..d-1]; tensors row-major d×d.
//
// SmoothManufacturedSolution is robust in the incompressible limit (docs/theory.md §"The problem"):
//   u = u0 + (1/λ) ∇φ,  div u0 = 0,  φ = Π sin(ω x_i),
//   2D: u0 = curl(sin ωx sin ωy);  3D: u0 = (ω sx cy sz, −ω cx sy sz, 0)  (s_i = sin ωx_i),
// with wavenumber ω (default π: one half wave across the unit square/cube),
//   σ = 2μ ε(u) + λ div(u) I = 2μ ε(u0) + (2μ/λ) ∇²φ + Δφ I,
// so σ stays bounded as λ → ∞ and at ν = 0.5 (1/λ = 0) it is the Stokes-like limit. Since
// ε(u) = Aσ, div σ = −f and as σ = 0 hold exactly, the errors of the mixed method measure only
// discretisation error. 1/λ = (1 − 2ν)/(2μν): ν must be > 0.

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "sc/core/ProblemData.hpp"

namespace sc::core {

class ExactSolution {
public:
  virtual ~ExactSolution() = default;
  virtual int dim() const = 0;
  /// σ(x), d×d row-major.
  virtual void stress(const double* x, double* sigma) const = 0;
  /// u(x), d components.
  virtual void displacement(const double* x, double* u) const = 0;
  /// θ(x) = the skew part of ∇u as in docs/theory.md §"Estimator": 2D one value ½(∂y u1 − ∂x u2);
  /// 3D three values (½(∂y u3 − ∂z u2), ½(∂z u1 − ∂x u3), ½(∂x u2 − ∂y u1)).
  virtual void rotation(const double* x, double* theta) const = 0;
  /// Body force f = −div σ.
  virtual void bodyForce(const double* x, double* f) const = 0;
  /// Traction σ(x) n: the boundary data of 'Data' = 'Exact solution' traction conditions, with n
  /// the discrete face's normal at x. Virtual so that a test can tie the data to an exact
  /// geometry instead (ConvergenceTest: the circle's normal on a curved boundary).
  virtual void traction(const double* x, const double* n, double* t) const;
  int numRotationComponents() const { return dim() == 2 ? 1 : 3; }
};

class SmoothManufacturedSolution : public ExactSolution {
public:
  SmoothManufacturedSolution(int dim, const Material& material, double wavenumber = M_PI);
  int dim() const override { return dim_; }
  void stress(const double* x, double* sigma) const override;
  void displacement(const double* x, double* u) const override;
  void rotation(const double* x, double* theta) const override;
  void bodyForce(const double* x, double* f) const override;
  /// ∇u (d×d row-major, (∇u)_ij = ∂_j u_i): for tests of ε(u) = Aσ.
  void displacementGradient(const double* x, double* gradU) const;

private:
  void u0AndGradient(const double* x, double* u0, double* grad) const;
  void phiDerivatives(const double* x, double* gradPhi, double* hessPhi) const;
  int dim_;
  double omega_;
  double mu_, inverseLambda_;
};

/// A linear stress field σ(x) = S0 + Σ_k x_k S_k (symmetric, divergence-free part plus constant
/// body force), with its u and θ, for the patch test (docs/verification.md "Patch test"): RT_k
/// with k ≥ 1 reproduces it exactly on any mesh, so any error above round-off is a bug
/// (orientation, Piola, assembly).
class LinearPatchSolution : public ExactSolution {
public:
  LinearPatchSolution(int dim, const Material& material);
  int dim() const override { return dim_; }
  void stress(const double* x, double* sigma) const override;
  void displacement(const double* x, double* u) const override;
  void rotation(const double* x, double* theta) const override;
  void bodyForce(const double* x, double* f) const override;
  /// ∇u (linear in x).
  void displacementGradient(const double* x, double* gradU) const;

private:
  double lameLambda() const;
  int dim_;
  Material material_;
};

/// "Problem/Exact solution": None | Manufactured smooth | Linear patch.
/// `wavenumber` is ω of the manufactured solution ("Problem/Manufactured wavenumber").
std::unique_ptr<ExactSolution> createExactSolution(const std::string& name, int dim,
                                                   const Material& material,
                                                   double wavenumber = M_PI);

}  // namespace sc::core

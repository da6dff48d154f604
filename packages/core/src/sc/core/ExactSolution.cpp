#include "sc/core/ExactSolution.hpp"

#include <cmath>

#include "sc/core/Error.hpp"

namespace sc::core {

namespace {
// θ from a displacement gradient g (row-major, g_ij = ∂_j u_i), as in ExactSolution::rotation.
void rotationFromGradient(int d, const double* g, double* theta)
{
  auto G = [&](int i, int j) { return g[i * d + j]; };
  if (d == 2) {
    theta[0] = 0.5 * (G(0, 1) - G(1, 0));
  } else {
    theta[0] = 0.5 * (G(2, 1) - G(1, 2));
    theta[1] = 0.5 * (G(0, 2) - G(2, 0));
    theta[2] = 0.5 * (G(1, 0) - G(0, 1));
  }
}
}  // namespace

void ExactSolution::traction(const double* x, const double* n, double* t) const
{
  const int d = dim();
  double s[9];
  stress(x, s);
  for (int i = 0; i < d; ++i) {
    t[i] = 0.0;
    for (int j = 0; j < d; ++j)
      t[i] += s[i * d + j] * n[j];
  }
}

// ------------------------------------------------------------------ smooth manufactured solution
SmoothManufacturedSolution::SmoothManufacturedSolution(int dim, const Material& m,
                                                       double wavenumber)
    : dim_(dim), omega_(wavenumber), mu_(m.shearModulus())
{
  SC_THROW_IF(!(wavenumber > 0.0), InputError,
              "'Problem/Manufactured wavenumber' must be > 0 (got " << wavenumber << ").");
  SC_THROW_IF(m.poissonRatio <= 0.0, InputError,
              "the manufactured solution u = u0 + (1/λ)∇φ needs λ > 0, i.e. 'Material/Poisson "
              "ratio' > 0 (got "
                  << m.poissonRatio << ").");
  // 1/λ = (1 − 2ν)/(2μν) for plane strain and 3D alike; exactly 0 at ν = 0.5. Plane stress
  // has the effective λ* = 2μν/(1 − ν) (c_d = λ*/(2λ* + 2μ) = ν/(1 + ν)).
  const double numerator =
      dim == 2 && m.planeStress ? 1.0 - m.poissonRatio : 1.0 - 2.0 * m.poissonRatio;
  inverseLambda_ = numerator / (2.0 * mu_ * m.poissonRatio);
}

void SmoothManufacturedSolution::u0AndGradient(const double* x, double* u0, double* g) const
{
  const double p = omega_;
  const double sx = std::sin(p * x[0]), cx = std::cos(p * x[0]);
  const double sy = std::sin(p * x[1]), cy = std::cos(p * x[1]);
  if (dim_ == 2) {
    // u0 = curl ψ = (∂y ψ, −∂x ψ), ψ = sx sy.
    u0[0] = p * sx * cy;
    u0[1] = -p * cx * sy;
    g[0] = p * p * cx * cy;
    g[1] = -p * p * sx * sy;
    g[2] = p * p * sx * sy;
    g[3] = -p * p * cx * cy;
  } else {
    const double sz = std::sin(p * x[2]), cz = std::cos(p * x[2]);
    u0[0] = p * sx * cy * sz;
    u0[1] = -p * cx * sy * sz;
    u0[2] = 0.0;
    g[0] = p * p * cx * cy * sz;
    g[1] = -p * p * sx * sy * sz;
    g[2] = p * p * sx * cy * cz;
    g[3] = p * p * sx * sy * sz;
    g[4] = -p * p * cx * cy * sz;
    g[5] = -p * p * cx * sy * cz;
    g[6] = g[7] = g[8] = 0.0;
  }
}

void SmoothManufacturedSolution::phiDerivatives(const double* x, double* grad, double* hess) const
{
  const int d = dim_;
  const double p = omega_;
  double s[3], c[3];
  for (int i = 0; i < d; ++i) {
    s[i] = std::sin(p * x[i]);
    c[i] = std::cos(p * x[i]);
  }
  // φ = Π sin(ω x_i): ∂_i φ = ω c_i Π_{j≠i} s_j, ∂_i∂_i φ = −ω² φ, ∂_i∂_j φ = ω² c_i c_j Π_{k≠i,j}
  // s_k.
  for (int i = 0; i < d; ++i) {
    grad[i] = p * c[i];
    for (int j = 0; j < d; ++j) {
      if (j != i) grad[i] *= s[j];
      double h = (i == j) ? -p * p * s[i] : p * p * c[i] * c[j];
      for (int k = 0; k < d; ++k)
        if (k != i && k != j) h *= s[k];
      hess[i * d + j] = h;
    }
  }
}

void SmoothManufacturedSolution::displacement(const double* x, double* u) const
{
  double g[9], gp[3], hp[9];
  u0AndGradient(x, u, g);
  phiDerivatives(x, gp, hp);
  for (int i = 0; i < dim_; ++i)
    u[i] += inverseLambda_ * gp[i];
}

void SmoothManufacturedSolution::displacementGradient(const double* x, double* gradU) const
{
  double u0[3], gp[3], hp[9];
  u0AndGradient(x, u0, gradU);
  phiDerivatives(x, gp, hp);
  for (int i = 0; i < dim_ * dim_; ++i)
    gradU[i] += inverseLambda_ * hp[i];
}

void SmoothManufacturedSolution::stress(const double* x, double* sigma) const
{
  const int d = dim_;
  double u0[3], g[9], gp[3], hp[9];
  u0AndGradient(x, u0, g);
  phiDerivatives(x, gp, hp);
  double laplacePhi = 0.0;
  for (int i = 0; i < d; ++i)
    laplacePhi += hp[i * d + i];
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      sigma[i * d + j] = mu_ * (g[i * d + j] + g[j * d + i]) +
                         2.0 * mu_ * inverseLambda_ * hp[i * d + j] + (i == j ? laplacePhi : 0.0);
}

void SmoothManufacturedSolution::rotation(const double* x, double* theta) const
{
  // The Hessian part of ∇u is symmetric: only u0 rotates.
  double u0[3], g[9];
  u0AndGradient(x, u0, g);
  rotationFromGradient(dim_, g, theta);
}

void SmoothManufacturedSolution::bodyForce(const double* x, double* f) const
{
  // div σ = μ Δu0 + (2μ/λ + 1) ∇Δφ with Δu0 = −dω² u0 and ∇Δφ = −dω² ∇φ (docs of the class).
  const int d = dim_;
  const double k = d * omega_ * omega_;
  double u0[3], g[9], gp[3], hp[9];
  u0AndGradient(x, u0, g);
  phiDerivatives(x, gp, hp);
  for (int i = 0; i < d; ++i)
    f[i] = -(-mu_ * k * u0[i] - (2.0 * mu_ * inverseLambda_ + 1.0) * k * gp[i]);
}

// ------------------------------------------------------------------ linear patch solution
namespace {
// Fixed coefficients of u = Q(x, x) + L x + c (any generic values do).
double Q(int i, int j, int k)
{
  static const double q[3][3][3] = {{{0.3, -0.2, 0.1}, {0.0, 0.5, -0.4}, {0.2, 0.0, 0.3}},
                                    {{-0.1, 0.4, 0.0}, {0.2, -0.3, 0.1}, {0.0, 0.6, -0.2}},
                                    {{0.1, 0.0, 0.2}, {-0.3, 0.1, 0.0}, {0.4, -0.1, 0.5}}};
  return q[i][j][k];
}
double L(int i, int j)
{
  static const double l[3][3] = {{0.7, -0.3, 0.2}, {0.4, -0.5, 0.1}, {-0.2, 0.3, 0.6}};
  return l[i][j];
}
}  // namespace

LinearPatchSolution::LinearPatchSolution(int dim, const Material& material)
    : dim_(dim), material_(material)
{
  SC_THROW_IF(material.poissonRatio >= 0.5 && !(dim == 2 && material.planeStress), InputError,
              "the linear patch solution is built from u through Hooke's law and needs ν < 0.5 "
              "(got "
                  << material.poissonRatio << ").");
}

double LinearPatchSolution::lameLambda() const
{
  // λ = 2μν/(1 − 2ν); plane stress: the effective λ* = 2μν/(1 − ν).
  const double mu = material_.shearModulus(), nu = material_.poissonRatio;
  return 2.0 * mu * nu / (dim_ == 2 && material_.planeStress ? 1.0 - nu : 1.0 - 2.0 * nu);
}

void LinearPatchSolution::displacement(const double* x, double* u) const
{
  for (int i = 0; i < dim_; ++i) {
    u[i] = 0.1 * (i + 1);
    for (int j = 0; j < dim_; ++j) {
      u[i] += L(i, j) * x[j];
      for (int k = 0; k < dim_; ++k)
        u[i] += Q(i, j, k) * x[j] * x[k];
    }
  }
}

void LinearPatchSolution::stress(const double* x, double* sigma) const
{
  const int d = dim_;
  const double mu = material_.shearModulus();
  const double lambda = lameLambda();
  double g[9];
  displacementGradient(x, g);
  double div = 0.0;
  for (int i = 0; i < d; ++i)
    div += g[i * d + i];
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      sigma[i * d + j] = mu * (g[i * d + j] + g[j * d + i]) + (i == j ? lambda * div : 0.0);
}

void LinearPatchSolution::rotation(const double* x, double* theta) const
{
  double g[9];
  displacementGradient(x, g);
  rotationFromGradient(dim_, g, theta);
}

void LinearPatchSolution::displacementGradient(const double* x, double* g) const
{
  const int d = dim_;
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      g[i * d + j] = L(i, j);
      for (int k = 0; k < d; ++k)
        g[i * d + j] += (Q(i, j, k) + Q(i, k, j)) * x[k];
    }
}

void LinearPatchSolution::bodyForce(const double*, double* f) const
{
  // div σ_i = μ Σ_j H_ijj + (μ + λ) Σ_j H_jji with H_ijk = ∂_j∂_k u_i = Q_ijk + Q_ikj.
  const int d = dim_;
  const double mu = material_.shearModulus();
  const double lambda = lameLambda();
  auto H = [](int i, int j, int k) { return Q(i, j, k) + Q(i, k, j); };
  for (int i = 0; i < d; ++i) {
    double div = 0.0;
    for (int j = 0; j < d; ++j)
      div += mu * H(i, j, j) + (mu + lambda) * H(j, j, i);
    f[i] = -div;
  }
}

std::unique_ptr<ExactSolution> createExactSolution(const std::string& name, int dim,
                                                   const Material& material, double wavenumber)
{
  if (name == "Manufactured smooth")
    return std::make_unique<SmoothManufacturedSolution>(dim, material, wavenumber);
  if (name == "Linear patch") return std::make_unique<LinearPatchSolution>(dim, material);
  SC_THROW_IF(
      name != "None", InputError,
      "'Problem/Exact solution' = '"
          << name
          << "' is not valid. Valid values: 'None', 'Manufactured smooth', 'Linear patch'.");
  return nullptr;
}

}  // namespace sc::core

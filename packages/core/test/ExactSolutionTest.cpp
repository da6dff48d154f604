// The exact solutions used for verification must satisfy the equations they claim, or every
// convergence test built on them is meaningless. Checked by central finite differences
// (h = 1e-5, truncation O(h²) ≈ 1e-10 relative to the second derivatives; tolerances 1e-6):
//   f = −div σ,  σ symmetric,  Aσ = ε(u),  θ = skew part of ∇u,  at ν ∈ {0.3, 0.4999}.
#include <cmath>

#include <Teuchos_UnitTestHarness.hpp>

#include "sc/core/Error.hpp"
#include "sc/core/ExactSolution.hpp"

namespace {

void checkSolution(const sc::core::ExactSolution& s, const sc::core::Material& m, int d,
                   Teuchos::FancyOStream& out, bool& success)
{
  const double h = 1e-5;
  const double cd = m.complianceCoefficient(d), mu = m.shearModulus();
  const double pts[3][3] = {{0.31, 0.62, 0.17}, {0.83, 0.11, 0.54}, {0.47, 0.49, 0.91}};
  for (const auto& x0 : pts) {
    double sigma[9], f[3], u[3], theta[3];
    s.stress(x0, sigma);
    s.bodyForce(x0, f);
    s.rotation(x0, theta);
    double scale = 1e-300;
    for (int i = 0; i < d * d; ++i)
      scale = std::max(scale, std::abs(sigma[i]));
    // ∂_j σ_ij and ∂_j u_i by central differences.
    double divSigma[3] = {0, 0, 0}, gradU[9];
    for (int j = 0; j < d; ++j) {
      double xp[3] = {x0[0], x0[1], x0[2]}, xm[3] = {x0[0], x0[1], x0[2]};
      xp[j] += h;
      xm[j] -= h;
      double sp[9], sm[9], up[3], um[3];
      s.stress(xp, sp);
      s.stress(xm, sm);
      s.displacement(xp, up);
      s.displacement(xm, um);
      for (int i = 0; i < d; ++i) {
        divSigma[i] += (sp[i * d + j] - sm[i * d + j]) / (2 * h);
        gradU[i * d + j] = (up[i] - um[i]) / (2 * h);
      }
    }
    s.displacement(x0, u);
    double fscale = 1e-300;
    for (int i = 0; i < d; ++i)
      fscale = std::max(fscale, std::abs(f[i]));
    for (int i = 0; i < d; ++i)
      TEST_COMPARE(std::abs(f[i] + divSigma[i]), <=, 1e-6 * fscale);
    double trace = 0.0;
    for (int i = 0; i < d; ++i)
      trace += sigma[i * d + i];
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) {
        TEST_COMPARE(std::abs(sigma[i * d + j] - sigma[j * d + i]), <=, 1e-12 * scale);
        const double asigma = (sigma[i * d + j] - (i == j ? cd * trace : 0.0)) / (2 * mu);
        const double eps = 0.5 * (gradU[i * d + j] + gradU[j * d + i]);
        TEST_COMPARE(std::abs(asigma - eps), <=, 1e-6 * scale / (2 * mu));
      }
    if (d == 2) {
      TEST_COMPARE(std::abs(theta[0] - 0.5 * (gradU[1] - gradU[2])), <=, 1e-6 * scale / mu);
    } else {
      TEST_COMPARE(std::abs(theta[0] - 0.5 * (gradU[7] - gradU[5])), <=, 1e-6 * scale / mu);
      TEST_COMPARE(std::abs(theta[1] - 0.5 * (gradU[2] - gradU[6])), <=, 1e-6 * scale / mu);
      TEST_COMPARE(std::abs(theta[2] - 0.5 * (gradU[3] - gradU[1])), <=, 1e-6 * scale / mu);
    }
  }
}

}  // namespace

TEUCHOS_UNIT_TEST(ExactSolution, SmoothManufacturedSatisfiesEquations)
{
  for (int d : {2, 3})
    for (double nu : {0.3, 0.4999})
      for (double omega : {M_PI, 0.5 * M_PI}) {  // 'Problem/Manufactured wavenumber'
        sc::core::Material m{20600.0, nu};
        sc::core::SmoothManufacturedSolution s(d, m, omega);
        checkSolution(s, m, d, out, success);
      }
}

TEUCHOS_UNIT_TEST(ExactSolution, IncompressibleLimitIsFinite)
{
  // ν = 0.5: 1/λ = 0, σ bounded (analytic: σ = 2με(u0) + Δφ I).
  sc::core::Material m{1.0, 0.5};
  sc::core::SmoothManufacturedSolution s(2, m);
  const double x[2] = {0.25, 0.25};
  double sigma[4];
  s.stress(x, sigma);
  // At (1/4, 1/4): sin = cos = 1/√2; 2μ ε(u0)_00 = 2μ π² cx cy = π²/1.5 · 0.5 ... μ = 1/3.
  const double mu = 1.0 / 3.0, pi2 = M_PI * M_PI;
  TEST_FLOATING_EQUALITY(sigma[0], 2 * mu * pi2 * 0.5 - 2 * pi2 * 0.5, 1e-12);
  TEST_FLOATING_EQUALITY(sigma[3], -2 * mu * pi2 * 0.5 - 2 * pi2 * 0.5, 1e-12);
}

TEUCHOS_UNIT_TEST(ExactSolution, LinearPatchSatisfiesEquations)
{
  for (int d : {2, 3}) {
    sc::core::Material m{3.0, 0.3};
    sc::core::LinearPatchSolution s(d, m);
    checkSolution(s, m, d, out, success);
  }
  TEST_THROW(sc::core::LinearPatchSolution(2, sc::core::Material{1.0, 0.5}), sc::core::InputError);
  TEST_THROW(sc::core::createExactSolution("Quadratic", 2, sc::core::Material{}),
             sc::core::InputError);
}

// Plane stress (Material/Plane = Stress): the same identities with the plane-stress compliance
// Aσ = ((1+ν)σ − ν tr(σ) I)/E (c_d = ν/(1+ν), checkSolution uses complianceCoefficient), for
// the manufactured and the patch solutions, also at ν = 0.5 where plane stress stays
// compressible (the effective λ* = 2μν/(1 − ν) is finite).
TEUCHOS_UNIT_TEST(ExactSolution, PlaneStressSatisfiesEquations)
{
  for (double nu : {0.3, 0.5}) {
    sc::core::Material m{20600.0, nu, true};
    TEST_FLOATING_EQUALITY(m.complianceCoefficient(2), nu / (1 + nu), 1e-15);
    sc::core::SmoothManufacturedSolution s(2, m);
    checkSolution(s, m, 2, out, success);
    sc::core::LinearPatchSolution p(2, m);
    checkSolution(p, m, 2, out, success);
  }
}

#pragma once
// Bernstein polynomials of degree k on a face (an edge: 2 barycentric coordinates, a triangle: 3),
// the basis of the contact constraints in 3D and on curved faces (docs/contact.md "Constraint
// points"). A face's constraint p is the coefficient of B_{α_p}, α_p = bernsteinIndices(k, nv)[p];
// its control point is Σ_i (α_p,i / k) v_i.
#include <array>
#include <cmath>
#include <vector>

namespace sc::disc {

/// Multi-indices α (|α| = k) over `nv` barycentric coordinates, in the order of a face's
/// constraint points.
inline std::vector<std::array<int, 3>> bernsteinIndices(int k, int nv)
{
  std::vector<std::array<int, 3>> out;
  for (int a = k; a >= 0; --a)
    if (nv == 2)
      out.push_back({a, k - a, 0});
    else
      for (int b = k - a; b >= 0; --b)
        out.push_back({a, b, k - a - b});
  return out;
}

/// B_α(λ) = k!/(α_0! α_1! α_2!) Π λ_i^α_i.
inline double bernstein(const std::array<int, 3>& alpha, const std::array<double, 3>& lambda, int k)
{
  double f = std::tgamma(k + 1.0);
  for (int i = 0; i < 3; ++i)
    f *= std::pow(lambda[i], alpha[i]) / std::tgamma(alpha[i] + 1.0);
  return f;
}

/// Barycentric coordinates of y in the face with vertices v[0..d-1] (an edge in 2D, a triangle in
/// 3D; y on the face's line or plane).
std::array<double, 3> faceBarycentric(const std::array<const double*, 3>& v, const double* y,
                                      int d);

/// Inverse of a face's small Bernstein collocation matrix (n × n, row-major), by LAPACK through
/// Teuchos; InternalError if it is singular.
std::vector<double> invertCollocation(const std::vector<double>& a, int n);

}  // namespace sc::disc

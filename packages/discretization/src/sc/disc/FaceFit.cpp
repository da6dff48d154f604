#include "sc/disc/FaceFit.hpp"

#include <algorithm>
#include <cmath>

namespace sc::disc {

std::array<double, 3> fitAffineOnFace(const std::vector<const double*>& c,
                                      const std::vector<const double*>& v, int d, const double* x)
{
  const std::size_t m = c.size();
  std::array<double, 3> mean{0, 0, 0}, cbar{0, 0, 0};
  for (std::size_t q = 0; q < m; ++q)
    for (int i = 0; i < d; ++i) {
      mean[i] += v[q][i] / m;
      cbar[i] += c[q][i] / m;
    }
  // Orthonormal directions e[0..d-2] from the points (Gram–Schmidt on c[q] − c[0]).
  std::vector<std::array<double, 3>> e;
  double scale = 0.0;
  for (std::size_t q = 1; q < m; ++q)
    for (int i = 0; i < d; ++i)
      scale = std::max(scale, std::abs(c[q][i] - c[0][i]));
  for (std::size_t q = 1; q < m && static_cast<int>(e.size()) < d - 1; ++q) {
    std::array<double, 3> a{0, 0, 0};
    for (int i = 0; i < d; ++i)
      a[i] = c[q][i] - c[0][i];
    for (const auto& b : e) {
      const double ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      for (int i = 0; i < 3; ++i)
        a[i] -= ab * b[i];
    }
    const double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (norm <= 1e-8 * scale) continue;
    for (double& ai : a)
      ai /= norm;
    e.push_back(a);
  }
  if (scale == 0.0 || static_cast<int>(e.size()) < d - 1) return mean;
  // Normal equations in the face coordinates s = E (x − c̄): (Σ s sᵀ) g_i = Σ s (v_i − v̄_i).
  const int k = d - 1;
  auto coords = [&](const double* y) {
    std::array<double, 2> s{0, 0};
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < d; ++i)
        s[j] += e[j][i] * (y[i] - cbar[i]);
    return s;
  };
  double S[2][2] = {{0, 0}, {0, 0}}, rhs[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  for (std::size_t q = 0; q < m; ++q) {
    const auto s = coords(c[q]);
    for (int a = 0; a < k; ++a) {
      for (int b = 0; b < k; ++b)
        S[a][b] += s[a] * s[b];
      for (int i = 0; i < d; ++i)
        rhs[i][a] += s[a] * (v[q][i] - mean[i]);
    }
  }
  const auto sx = coords(x);
  std::array<double, 3> out = mean;
  if (k == 1) {
    if (S[0][0] <= 0.0) return mean;
    for (int i = 0; i < d; ++i)
      out[i] += sx[0] * rhs[i][0] / S[0][0];
    return out;
  }
  const double det = S[0][0] * S[1][1] - S[0][1] * S[1][0];
  if (std::abs(det) <= 1e-12 * (S[0][0] * S[1][1])) return mean;
  for (int i = 0; i < d; ++i) {
    const double g0 = (S[1][1] * rhs[i][0] - S[0][1] * rhs[i][1]) / det;
    const double g1 = (S[0][0] * rhs[i][1] - S[1][0] * rhs[i][0]) / det;
    out[i] += g0 * sx[0] + g1 * sx[1];
  }
  return out;
}

}  // namespace sc::disc

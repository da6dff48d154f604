#include "sc/disc/Bernstein.hpp"

#include <Teuchos_SerialDenseMatrix.hpp>
#include <Teuchos_SerialDenseSolver.hpp>

#include <sc/core/Error.hpp>

namespace sc::disc {

std::array<double, 3> faceBarycentric(const std::array<const double*, 3>& v, const double* y, int d)
{
  if (d == 2) {
    double e[2] = {v[1][0] - v[0][0], v[1][1] - v[0][1]};
    const double t =
        ((y[0] - v[0][0]) * e[0] + (y[1] - v[0][1]) * e[1]) / (e[0] * e[0] + e[1] * e[1]);
    return {1.0 - t, t, 0.0};
  }
  double e1[3], e2[3], r[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = v[1][i] - v[0][i];
    e2[i] = v[2][i] - v[0][i];
    r[i] = y[i] - v[0][i];
  }
  auto dot = [](const double* a, const double* b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  const double a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2), b1 = dot(r, e1),
               b2 = dot(r, e2);
  const double det = a11 * a22 - a12 * a12;
  const double l1 = (b1 * a22 - b2 * a12) / det, l2 = (a11 * b2 - a12 * b1) / det;
  return {1.0 - l1 - l2, l1, l2};
}

std::vector<double> invertCollocation(const std::vector<double>& a, int n)
{
  Teuchos::SerialDenseMatrix<int, double> A(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      A(r, c) = a[r * n + c];
  Teuchos::SerialDenseSolver<int, double> solver;
  solver.setMatrix(Teuchos::rcpFromRef(A));
  SC_THROW_IF(solver.invert() != 0, core::InternalError,
              "singular Bernstein collocation matrix on a contact face");
  std::vector<double> inv(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      inv[r * n + c] = A(r, c);
  return inv;
}

}  // namespace sc::disc

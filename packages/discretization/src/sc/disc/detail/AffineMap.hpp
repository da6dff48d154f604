#pragma once
// Internal to the discretization package: the affine map of a simplex.
#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::disc {

/// J⁻¹ of a d×d Jacobian (d = 2, 3) with determinant det, by the adjugate: (J⁻¹)_ij = cof(J)_ji /
/// det.
inline void invertJacobian(int d, const double J[3][3], double det, double inv[3][3])
{
  if (d == 2) {
    inv[0][0] = J[1][1] / det;
    inv[0][1] = -J[0][1] / det;
    inv[1][0] = -J[1][0] / det;
    inv[1][1] = J[0][0] / det;
    return;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      inv[i][j] = (J[i1][j1] * J[i2][j2] - J[i1][j2] * J[i2][j1]) / det;
    }
}

// Affine map of element e: x = x0 + J x̂ (J's columns are x_{i+1} − x_0), det J > 0 by the
// mesh's orientation convention.
struct AffineMap {
  double x0[3] = {0, 0, 0};
  double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double det = 0.0;

  AffineMap(const mesh::SimplexMesh& m, int e)
  {
    const int d = m.dim();
    const int* v = m.elementVertices(e);
    const double* p0 = m.vertex(v[0]);
    for (int i = 0; i < d; ++i)
      x0[i] = p0[i];
    for (int j = 0; j < d; ++j) {
      const double* pj = m.vertex(v[j + 1]);
      for (int i = 0; i < d; ++i)
        J[i][j] = pj[i] - p0[i];
    }
    det = d == 2 ? J[0][0] * J[1][1] - J[0][1] * J[1][0]
                 : J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                       J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                       J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    SC_THROW_IF(!(det > 0.0), core::InternalError,
                "element " << e << " has det J = " << det
                           << " (mesh orientation convention broken)");
  }
  /// J⁻¹ (d = 2, 3) by the adjugate.
  void inverse(int d, double inv[3][3]) const { invertJacobian(d, J, det, inv); }
  void map(const double* xh, int d, double* x) const
  {
    for (int i = 0; i < d; ++i) {
      x[i] = x0[i];
      for (int j = 0; j < d; ++j)
        x[i] += J[i][j] * xh[j];
    }
  }
};

}  // namespace sc::disc

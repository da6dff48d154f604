#pragma once
// Internal to the discretization (and estimator) code: the map x = F(x̂) of one element evaluated
// at a fixed set of reference points. Affine elements: F(x̂) = x0 + J x̂ (AffineMap, J constant).
// Curved elements (MixedElasticitySpace::isCurved, Mesh/Geometry order = 2): the quadratic map of
// the Triangle<6> / Tetrahedron<10> nodes (mesh::CurvedElements), with the P2 Lagrange basis
// tabulated once at the points and J(x̂_q) from Intrepid2's CellTools::setJacobian. det J must
// stay positive at every point (else InputError: the mesh is too coarse for the curvature).
#include <array>
#include <vector>

#include "sc/disc/detail/Intrepid2Impl.hpp"

namespace sc::disc {

class ElementMap {
public:
  /// `refPoints`: (nq, d) reference points (cubature, face or lattice points).
  ElementMap(const MixedElasticitySpace& space, const View& refPoints);

  void reinit(int element);
  int element() const { return element_; }
  bool curved() const { return curved_; }
  int numPoints() const { return nq_; }
  /// Physical point q (3 coordinates, z = 0 in 2D), J(x̂_q) (3×3, row-major, d×d used), det J.
  const double* x(int q) const { return &x_[3 * q]; }
  const double* jacobian(int q) const { return &J_[9 * q]; }
  double det(int q) const { return det_[q]; }
  /// G = J^{-T}(x̂_q): physical gradient = G reference gradient.
  void inverseTranspose(int q, double G[3][3]) const;
  /// For points on reference side `side` (Intrepid2 ordinal): the unit normal out of the element
  /// and the ratio of the physical surface measure to the side's parameter measure at q
  /// (|J t̂| in 2D, |J t̂_u × J t̂_v| in 3D, with the tangents of CellTools' side parametrisation).
  void sideFrame(int q, int side, std::array<double, 3>& normal, double& stretch) const;

  /// Reference coordinates (d each) of physical points (3 each) of element e: J⁻¹(x − x0) on
  /// affine elements, CellTools::mapToReferenceFrame (Newton) on curved ones.
  static std::vector<double> toReference(const MixedElasticitySpace& space, int element,
                                         const std::vector<double>& physicalPoints);

private:
  const MixedElasticitySpace& space_;
  int d_, nq_, element_ = -1;
  bool curved_ = false;
  View refPoints_, p2Values_, p2Grads_;              // (nq, d), (nN, nq), (nN, nq, d)
  std::vector<std::array<double, 3>> sideTangents_;  // per side: d−1 tangents of 3
  std::vector<double> x_, J_, det_;
};

}  // namespace sc::disc

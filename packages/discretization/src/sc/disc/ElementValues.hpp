#pragma once
// Physical values of the element basis functions at cubature points, oriented (Intrepid2
// OrientationTools) and mapped (contravariant Piola for RT: φ = J φ̂ / det J, div φ = div̂ φ̂ / det J;
// identity for the P_k bases), on an element (ElementValues) or on one face of it (FaceValues).
// Cubature from Intrepid2's DefaultCubatureFactory, exact for polynomials of the given degree.
// Affine elements have one J; curved elements (Mesh/Geometry order = 2, quadratic map) have J,
// det J, the face normal and the surface element at each point (detail/ElementMap.hpp).
#include <array>
#include <memory>
#include <vector>

namespace sc::disc {

class MixedElasticitySpace;

class ElementValues {
public:
  ElementValues(const MixedElasticitySpace& space, int cubatureDegree);
  ~ElementValues();
  void reinit(int element);
  /// Values of `element`'s basis at arbitrary physical points (3 coordinates per point; inside or
  /// on the element, or outside for polynomial extension), e.g. a child element's cubature points
  /// for transfers between nested meshes. weight() is 0 then; reinit() is not allowed afterwards.
  void reinitAtPoints(int element, const std::vector<double>& physicalPoints);

  int numPoints() const { return nq_; }
  /// Physical cubature point q (dim coordinates) and weight (reference weight × det J).
  const double* point(int q) const { return &points_[q * 3]; }
  double weight(int q) const { return weights_[q]; }
  /// RT basis function a (one row's basis) at q: component c, and its divergence.
  double stress(int a, int q, int c) const { return rt_[(a * nq_ + q) * 3 + c]; }
  double stressDiv(int a, int q) const { return rtDiv_[a * nq_ + q]; }
  /// DP_k basis function a at q.
  double displacement(int a, int q) const { return dp_[a * nq_ + q]; }
  /// CP_k basis function a at q.
  double rotation(int a, int q) const { return cp_[a * nq_ + q]; }
  double measure() const { return measure_; }

  struct Impl;

private:
  void fill(int element);

  const MixedElasticitySpace& space_;
  std::unique_ptr<Impl> impl_;
  int nq_;
  std::vector<double> points_, weights_, rt_, rtDiv_, dp_, cp_;
  double measure_ = 0.0;
};

class FaceValues {
public:
  FaceValues(const MixedElasticitySpace& space, int cubatureDegree);
  ~FaceValues();
  /// Values of element `element`'s basis on its face opposite local vertex `localFace`.
  void reinit(int element, int localFace);

  int numPoints() const { return nq_; }
  const double* point(int q) const { return &points_[q * 3]; }
  /// Reference weight times the physical surface element.
  double weight(int q) const { return weights_[q]; }
  /// Unit normal at q pointing out of the element (constant on a straight face).
  const std::array<double, 3>& normal(int q) const { return normals_[q]; }
  /// Length/area of the face (of the curved face on a curved element).
  double measure() const { return measure_; }
  bool curved() const { return curved_; }
  double stress(int a, int q, int c) const { return rt_[(a * nq_ + q) * 3 + c]; }
  /// φ_a · n at q.
  double stressNormal(int a, int q) const;
  double displacement(int a, int q) const { return dp_[a * nq_ + q]; }
  double rotation(int a, int q) const { return cp_[a * nq_ + q]; }

  struct Impl;

private:
  const MixedElasticitySpace& space_;
  std::unique_ptr<Impl> impl_;
  int nq_;
  std::vector<double> points_, weights_, rt_, dp_, cp_;
  std::vector<std::array<double, 3>> normals_;
  double measure_ = 0.0;
  bool curved_ = false;
};

/// Σ |T| over this rank's elements (curved elements by quadrature of det J): the area/volume of
/// the discrete domain once summed over ranks.
double ownedMeasure(const MixedElasticitySpace& space);

}  // namespace sc::disc

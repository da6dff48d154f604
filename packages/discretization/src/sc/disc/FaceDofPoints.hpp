#pragma once
// The RT face DOFs of Intrepid2's HDIV In_FEM bases (equispaced lattice) are point values of the
// normal flux at lattice points of the face, up to a scale: DOF j of a face is ±(φ_j·n)(p_j) times
// a face-size factor (docs/theory.md §"Contact and friction"). Contact works with these points, so
// this finds them: for each face DOF, its physical point p_j and s_j = (φ_j·n)(p_j) with the
// outward unit normal n of the element (sign included), after checking (φ_j·n)(p_l) = 0 for l ≠ j.
// An element's traction at p_j is then t_i(p_j) = s_j c_{i,j} with c_{i,j} the coefficient of row
// i's DOF j. On a curved element (quadratic map) the Piola map keeps the DOFs point values of the
// normal flux (φ·n dS = φ̂·n̂ dŜ), with n and s_j taken at each point.
#include <array>
#include <vector>

namespace sc::disc {

class MixedElasticitySpace;

struct FaceDofPoint {
  int localDof = -1;                ///< element-local RT index (within one row block)
  std::array<double, 3> x{};        ///< physical point p_j (on the curved face of a curved element)
  std::array<double, 3> xAffine{};  ///< the same reference point on the straight face (chord)
  std::array<double, 3> normal{};   ///< outward unit normal n(p_j) (varies on a curved face)
  double scale = 0.0;               ///< s_j = (φ_j·n)(p_j), outward n
};

/// The DOF points of element `element`'s face opposite local vertex `localFace`. Throws
/// InternalError if the face DOFs are not point values (the contact method needs them).
std::vector<FaceDofPoint> stressFaceDofPoints(const MixedElasticitySpace& space, int element,
                                              int localFace);

}  // namespace sc::disc

namespace sc::disc {
/// min over the faces of the reference simplex and their RT_k face DOF points p of
/// ∫_F L_p ds / |F|, where L_p is the Lagrange function of the normal trace at p (1 at p, 0 at
/// the face's other DOF points). The ratio is invariant under affine maps, so it holds for every
/// straight-sided mesh. Contact needs it positive (docs/contact.md, "Degree").
double minRelativeFaceDofWeight(int dim, int degree);
}  // namespace sc::disc

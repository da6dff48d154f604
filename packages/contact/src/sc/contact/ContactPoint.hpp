#pragma once
// Contact points: the constraints of the contact solver (built by ActiveSetSolver from the contact
// faces, evaluated after each Newton step, carried to the next mesh by
// ActiveSetSolver::transferState) and how they tabulate themselves for the outputs (the contact
// CSV, the per-face fields and the contact point grid of the XDMF output, docs/output.md).
#include <array>
#include <map>
#include <string>
#include <vector>

namespace sc::contact {

enum class PointStatus { Free = 0, Stick = 1, Slip = 2 };
std::string toString(PointStatus s);

/// One contact constraint: a coefficient of the normal traction on a contact face (docs/theory.md
/// §"Contact and friction", docs/contact.md "Constraint points"). Either a face DOF point p (the
/// coefficient is the traction σn(p), the dual weight is its Lagrange function ℓ_p) or, where the
/// DOF points' interpolatory rule cannot keep the weighted gap of a non-negative linear gap
/// non-negative (3D, 2D k = 3), a Bernstein coefficient B_p of the face (non-negative dual weight
/// B_p).
struct ContactPoint {
  int face = -1;              ///< mesh face
  int block = -1;             ///< index of its face block in the solver (internal)
  int index = -1;             ///< index within the face block
  std::array<double, 3> x{};  ///< the DOF point, or the Bernstein control point
  std::array<double, 3> n{}, t1{}, t2{};
  double gap = 0.0;     ///< weighted gap G_p = ∫_F g w_p ds (w_p = ℓ_p or B_p)
  double weight = 0.0;  ///< ∫_F w_p ds (for the resultant force)
  double c = 0.0;       ///< semismooth Newton constant 2μ/(h_F |F|)
  // State and results.
  PointStatus status = PointStatus::Free;
  std::array<double, 2> direction{};  ///< slip direction ξ in (t1, t2)
  double sigmaN = 0.0, rN = 0.0;
  /// σ_N at the face's DOF point with this index (= sigmaN for point constraints): the traction
  /// trace's value, where a Bernstein coefficient (a control value) can overshoot.
  double sigmaNAtDofPoint = 0.0;
  double frictionBound = 0.0;  ///< s_p of the Coulomb fixed point (a Tresca bound per point)
  std::array<double, 2> sigmaT{}, rT{};
  // Load steps (docs/theory.md §"Load steps"): friction acts on the slip increment.
  /// The weight's centroid ∫_F x w_p ds / W (where the per-weight history is placed when it is
  /// carried to a refined face).
  std::array<double, 3> centroid{};
  /// r_T of the end of the previous load step, as a vector in global coordinates (the weighted
  /// tangential displacement trace ∫_F ũ_T^{n−1} w_p ds); zero in the first step.
  std::array<double, 3> history{};
  /// `history` in this point's tangential frame (t1, t2): what r_T is compared with.
  std::array<double, 2> previousRT() const;
  /// r_N of the end of the previous load step (zero in the first step): where the first Newton
  /// update of a load step measures a free point's penetration from (docs/contact.md "Load
  /// steps", the damped entry test).
  double previousRN = 0.0;
};

/// End of a load step: every point's history becomes its current r_T (in global coordinates),
/// so that the next step's friction acts on the increment r_T − r_T^{n−1}, and its previousRN its
/// current r_N.
void commitLoadStep(std::vector<ContactPoint>& points);

/// The columns of the contact CSV (docs/output.md): x, y[, z], sigma_n, sigma_t[, sigma_t2],
/// weighted_gap, weighted_slip, status.
std::vector<std::string> csvColumns(int dim);
/// A point's numbers in the columns of csvColumns(dim) but the last (status, toString(p.status)):
/// weighted_gap = G − r_N ≥ 0 (the weighted gap left open; 0 on active points), weighted_slip =
/// |r_T| (the weighted tangential displacement).
std::vector<double> csvValues(const ContactPoint& p, int dim);

/// A contact point's quantities as values at its position, for the XDMF `contact` grid
/// (docs/output.md "Fields in a run's files").
struct PointValues {
  double pressure = 0.0;           ///< −σ_N at the point
  std::array<double, 2> sigmaT{};  ///< (σ_T·t1, σ_T·t2) at the point (t2 part 0 in 2D)
  double gap = 0.0;                ///< (G − r_N)/W: the weighted gap left open per weight
  std::array<double, 2> slip{};    ///< r_T/W: the weighted tangential displacement per weight
};
/// The values of `points` in their order. The traction of a face is Σ_q τ_q V_q with V_q the
/// Lagrange basis of the face's DOF points (point constraints: τ_q are already the values at
/// the points) or the Bernstein polynomials B_{α_q} of degree `degree` (bernsteinCoefficients: the
/// value at a control point, λ = α_p/k, is Σ_q τ_q B_{α_q}(α_p/k), which equals τ_p at the
/// vertices and at k = 1 everywhere). The weighted quantities are divided by the point's weight
/// W = ∫_F w_p ds > 0 (a weighted mean over the face, not a point value). Every face of a point in
/// `points` must have all its points there (a rank holds all points of its faces).
std::vector<PointValues> pointValues(const std::vector<ContactPoint>& points, int dim, int degree,
                                     bool bernsteinCoefficients);

/// Mean contact pressure −σ_N and mean first tangential traction σ_T·t1 of the points of a face.
struct FaceTraction {
  double pressure = 0.0, shear = 0.0;
};
/// Per mesh face (those with points among `points`): the means of its points.
std::map<int, FaceTraction> faceMeans(const std::vector<ContactPoint>& points);

}  // namespace sc::contact

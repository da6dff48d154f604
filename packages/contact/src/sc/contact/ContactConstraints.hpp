#pragma once
// The contact constraints of a cycle's space (docs/contact.md "Constraint points"): on each owned
// face of a Contact boundary part, m coefficients of the normal traction (the values at the RT
// face DOF points, or the Bernstein coefficients of the face's traction), each a ContactPoint with
// its frame, weighted gap, dual weight and Newton constant. ActiveSetSolver builds them once per
// cycle and iterates their state.
#include <array>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>

#include <sc/contact/ContactPoint.hpp>
#include <sc/contact/ContactSettings.hpp>
#include <sc/core/ProblemData.hpp>

namespace sc::disc {
class MixedElasticitySpace;
}

namespace sc::contact {

class Obstacle;

/// Throws InputError naming 'Discretization/Degree' if contact at this degree and dimension is
/// not supported: the RT_k face DOF points must have positive weights ∫_F L_p (docs/contact.md,
/// "Degree"). Supported: k = 1..4 in 2D, k = 1, 2 in 3D. Call it before any work (--check too).
void checkContactDegree(int dim, int degree);

/// Contact on curved faces (Mesh/Geometry order = 2) is verified at k = 1, 2 in 2D and k = 1 in
/// 3D, in the obstacle frame; anything else is an InputError naming the keys. Called by
/// buildContactConstraints when its contact faces are curved, and up front by the application.
void checkCurvedContact(int dim, int degree, ContactFrame frame);

/// Whether the contact constraints of this dimension and degree act on the Bernstein
/// coefficients of each face's traction (non-negative dual weights) instead of the DOF points:
/// in 3D, and on curved faces (Mesh/Geometry order = 2).
bool useBernsteinConstraints(int dim, int degree, bool curvedFaces = false);

/// The RT face DOFs of one contact face and the map between their point values and the
/// face's constraint coefficients: traction t(x_q) = Σ_p V(q,p) τ_p, dual ρ_p = Σ_q V(q,p) r_q.
struct ContactFace {
  int m = 0;                                   ///< DOF points (= constraint coefficients)
  std::vector<std::array<long long, 3>> gids;  ///< per point q: the d row DOFs
  std::vector<double> scale;                   ///< s_q: traction = s_q × coefficient
  std::vector<double> V, Vinv;                 ///< m × m, row-major V[q*m + p]
  double meanScale = 0.0;                      ///< mean |s_q|
};

/// The constraints of this rank: its contact faces and their points (a point's `block` is its
/// face's index in `faces`, its `index` the coefficient's within the face), all free.
struct ContactConstraints {
  std::vector<ContactFace> faces;
  std::vector<ContactPoint> points;
  bool bernstein = false;  ///< Bernstein coefficients (useBernsteinConstraints), else DOF points
};

/// The constraints on the owned faces of `contactBoundaries` of `space`, in the frame of
/// `settings.frame`, with the gaps to `obstacle` and the Newton constants c = penalty factor ×
/// 2μ/(h_F |F|). Checks curved contact faces (checkCurvedContact) and that every point's weight is
/// positive. Collective.
ContactConstraints buildContactConstraints(const disc::MixedElasticitySpace& space,
                                           const ContactSettings& settings,
                                           const core::Material& material,
                                           const std::vector<std::string>& contactBoundaries,
                                           const Obstacle& obstacle,
                                           const Teuchos::Comm<int>& comm);

}  // namespace sc::contact

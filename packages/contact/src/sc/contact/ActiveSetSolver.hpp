#pragma once
// Frictional contact on the stress DOFs (docs/theory.md §"Contact and friction"): semismooth Newton
// / primal–dual active set.
//
// The constraints act on m coefficients per contact face (docs/contact.md "Constraint
// points"): in 2D the traction at the RT face DOF points (s_p × the DOF coefficients, s_p from
// disc::stressFaceDofPoints), in 3D the Bernstein coefficients τ = V⁻¹(s ∘ x) of the face's
// traction. The dual quantities are the weighted displacement traces r = Vᵀ(R/s) (R: residual of
// the first block row without contact term), the weighted gaps G = ∫_F g w_p. All are written in
// the contact frame (n, t_1[, t_2]) of Contact/Frame (obstacle normal −ν or face normal):
//   A (contact):  σ_N − c(r_N − G) < 0 → normal row kept with r_N = G (G on the right-hand side)
//   I (free):     σ_N = 0, σ_T = 0 (rows replaced)
//   on A, with s = μ_F max(0, −(σ_N − c(r_N − G))) (Hüeber–Stadler–Wohlmuth):
//     stick if |σ_T − c r_T| ≤ s → tangential rows kept with r_T = 0;
//     slip → σ_T = −μ_F σ_N ξ, ξ = (σ_T − c r_T)/|σ_T − c r_T|: exact Newton row in 2D; in 3D the
//            Hüeber–Stadler–Wohlmuth linearisation (or the frozen direction, by choice).
//     frictionless: σ_T = 0.  Tresca: s given.
// The state (sets, directions) is iterated until it does not change; a state seen before is a
// cycle: points whose direction flipped move to the stick set (a bounded number of times), then
// the solver stops with a ConvergenceError. Rows replaced keep the matrix graph, so the direct
// solver's symbolic factorisation is reused across Newton steps.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>

#include <sc/contact/BalancedStopping.hpp>
#include <sc/contact/ContactConstraints.hpp>
#include <sc/contact/ContactSettings.hpp>
#include <sc/core/ProblemData.hpp>

#include "sc/contact/ContactPoint.hpp"

namespace sc::disc {
class MixedElasticitySpace;
}
namespace sc::solvers {
class LinearSolver;
}

namespace sc::contact {

class Obstacle;

struct ContactStatistics {
  int newtonIterations = 0;
  int remedies = 0;
  int fixedPointIterations = 0;  ///< outer Coulomb fixed-point steps (0: Newton converged)
  bool converged = false;
  std::vector<int> changesPerIteration;
  std::vector<int> linearIterationsPerStep;  ///< Krylov iterations per Newton step (Krylov solvers)
  /// Contact/Newton/Stopping = Balanced, last Newton step (BalancedStopping.hpp): the estimated
  /// algebraic error Δ (−1: accepted at the fixed tolerance before a Δ, or the rule did not apply),
  /// the relative tolerance of the accepted stage, and the bound γ η (0: the rule did not apply).
  double algebraicError = -1.0;
  double krylovTolerance = 0.0;
  double balancedBound = 0.0;
  /// Stopping = Fixed (BalancedStopping::finalSolve): the Krylov iterations that continued the
  /// settled state's solve (not in linearIterationsPerStep), its estimated algebraic error after
  /// them (−1: not applied) and the bound (0: not applied).
  int finalSolveIterations = 0;
  double finalAlgebraicError = -1.0;
  double finalBound = 0.0;
};

class ActiveSetSolver {
public:
  using CrsMatrix = Tpetra::CrsMatrix<>;
  using MultiVector = Tpetra::MultiVector<>;

  /// Valid "Contact/Newton" keys (sublist of Contact): Maximum iterations, Penalty factor,
  /// Maximum remedies, 3D slip linearisation, Coulomb method, Maximum fixed-point iterations,
  /// Fixed-point tolerance, Stopping, Balance fraction (BalancedStopping.hpp).
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();

  /// Points on the faces of `contactBoundaries` owned by this rank; the Newton limits and
  /// variants are `settings.newton` (read once with the "Contact" list).
  ActiveSetSolver(const disc::MixedElasticitySpace& space, const ContactSettings& settings,
                  const core::Material& material, const std::vector<std::string>& contactBoundaries,
                  Teuchos::RCP<const Teuchos::Comm<int>> comm);
  ~ActiveSetSolver();

  /// Start from the states of the previous cycle's points through the refinement history
  /// (transferContactState in StateTransfer.hpp says how). Collective.
  void transferState(const std::vector<ContactPoint>& previous, const std::vector<int>& parentFace);

  /// Solve K x = b with the contact conditions. K, b: the elasticity system without contact
  /// terms; x: initial guess in, solution out (each Newton step starts the linear solver from the
  /// previous iterate). Throws ConvergenceError if the state does not settle within the limits
  /// (statistics() then says converged = false). A direct solver gets each step's modified
  /// matrix (non-symmetric); a Krylov solver the same equations in the constraints' coordinates
  /// (eliminatedMatrix: symmetric without slip rows) and their basis (BlockStructure::stressBasis).
  /// Both unscaled: scaling and preconditioning are the solver's (LinearSolver).
  void solve(const CrsMatrix& K, const MultiVector& b, solvers::LinearSolver& solver,
             MultiVector& x);

  /// Called after every Newton step on every rank (collective data only): the step number,
  /// the global number of points whose state changed, and the step's wall time in seconds.
  /// Simulation uses it for progress output on long 3D runs.
  using StepCallback = std::function<void(int step, long long changes, double seconds)>;
  void setStepCallback(StepCallback callback) { stepCallback_ = std::move(callback); }

  /// Contact/Newton/Stopping = Balanced: the Krylov solves stop by this rule (borrowed, kept by
  /// the caller across cycles: it carries η and the stage tolerance; null: the fixed tolerance).
  void setBalancedStopping(BalancedStopping* stopping) { balanced_ = stopping; }

  /// The contact alone holds the body along the obstacle's normal (no Displacement part, and
  /// Symmetry parts normal to every other axis: assembly::checkLoadsAndSupports). Without a
  /// point in contact the system is then singular, so a Newton start with none puts the points
  /// nearest the obstacle in contact (smallest mean gap G_p / ∫_F w_p, within 1e-9 of the
  /// mesh's size; stick with friction), and a step that leaves no point in contact stops with a
  /// ConvergenceError (the loads pull the body off the obstacle: no equilibrium).
  void setContactHoldsBody(bool holds) { holdsBody_ = holds; }

  /// The first cycle of a load step after the first (the points carry the step before's state
  /// and its r_N, previousRN): the first Newton update damps the entry of free points into
  /// contact (docs/contact.md "Load steps"). Convergence is decided by the undamped update, so
  /// the solution is the same; only the Newton path changes.
  void setLoadStepStart(bool start) { loadStepStart_ = start; }

  const std::vector<ContactPoint>& points() const { return points_; }
  /// True if the points' coefficients are Bernstein coefficients of each face's traction
  /// (useBernsteinConstraints), false if they are its values at the face's DOF points.
  bool bernsteinConstraints() const { return bernstein_; }
  const ContactStatistics& statistics() const { return stats_; }
  long long globalNumPoints() const;
  bool hasFriction() const;

private:
  void evaluate(const CrsMatrix& K, const MultiVector& b, const MultiVector& x);
  /// `dampedEntry`: a free point's penetration is measured at kEntryDamping of the way from
  /// previousRN to r_N (the first update of a load step, firstUpdateOfLoadStep).
  int updateState(bool allowFlipRemedy, bool dampedEntry = false);
  /// The first update of a load step (setLoadStepStart): the undamped update; if it changes
  /// the state, the damped-entry update instead, unless that one changes nothing.
  int firstUpdateOfLoadStep();
  void solveActiveSet(const CrsMatrix& K, const MultiVector& b, solvers::LinearSolver& solver,
                      MultiVector& x);
  /// One Newton step's linear solve with the solver's operator, by the fixed or the balanced rule
  /// (`energy`: its σ block is the compliance in the operator's unknowns). Returns the Krylov
  /// iterations.
  int linearSolve(solvers::LinearSolver& solver, const MultiVector& rhs, MultiVector& x,
                  const CrsMatrix& energy);
  double trescaBound(const ContactPoint& p) const;
  /// setContactHoldsBody: the start with the nearest points in contact, and the check that a
  /// step has some point in contact (collective).
  void startNearestPointsInContact();
  void checkSomePointInContact(int step) const;
  /// K with the contact rows of the current state, and its right-hand side. `reuse`: the
  /// matrix of the previous Newton step on K's graph, whose values are overwritten (null: a new
  /// copy of K).
  Teuchos::RCP<CrsMatrix> modifiedMatrix(const CrsMatrix& K, MultiVector& rhs, const MultiVector& b,
                                         const Teuchos::RCP<CrsMatrix>& reuse) const;
  /// Row r (0: normal, 1..: tangential) of point p in the current state:
  /// Σ_i α_i ρ_i + Σ_i β_i τ_i = γ (ρ: the point's dual quantities, τ: its traction coefficients,
  /// global components; see the file comment).
  struct ConstraintRow {
    std::array<double, 3> alpha{0, 0, 0}, beta{0, 0, 0};
    double gamma = 0.0;
  };
  std::array<ConstraintRow, 3> constraintRows(const ContactPoint& p) const;

  /// The contact Newton systems of a Krylov solver in the points' frame coordinates
  /// (ContactElimination.cpp, docs/solvers.md "Contact with the stress multigrid").
  struct Elimination {
    Teuchos::RCP<CrsMatrix> Q, T, G;  ///< x = Q y, y = T x, G = Qᵀ K Q
    Teuchos::RCP<MultiVector> Qb;     ///< Qᵀ b
  };
  /// Q, T = Q⁻¹, Qᵀ K Q and Qᵀ b for this K and b (once per solve: they do not depend on the
  /// state).
  Elimination eliminationBasis(const CrsMatrix& K, const MultiVector& b) const;
  /// The system of the current state in frame coordinates y (x = Q y): traction rows that fix
  /// one coordinate are eliminated with their column, dual rows are Galerkin rows of Qᵀ K Q.
  /// Returns whether it is symmetric (no mixed rows, e.g. Coulomb slip, on any rank).
  bool eliminatedMatrix(const Elimination& e, Teuchos::RCP<CrsMatrix>& A, MultiVector& rhs) const;

  const disc::MixedElasticitySpace& space_;
  ContactSettings settings_;
  bool bernstein_ = false;  ///< constraints on Bernstein coefficients (else on DOF points)
  std::vector<ContactFace> faces_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::unique_ptr<Obstacle> obstacle_;
  std::vector<ContactPoint> points_;
  bool fixedPoint_ = false;  ///< inside the Coulomb fixed point: Tresca rows with p.frictionBound
  ContactStatistics stats_;
  StepCallback stepCallback_;
  bool holdsBody_ = false;
  bool loadStepStart_ = false;
  BalancedStopping* balanced_ = nullptr;
  double meshSize_ = 0.0;  ///< the diagonal of the mesh's bounding box
};

}  // namespace sc::contact

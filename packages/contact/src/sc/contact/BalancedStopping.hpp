#pragma once
// The algebraic stopping rule of the contact Newton's linear solves (docs/theory.md §"Solves
// balanced with the discretisation error"), `Contact/Newton/Stopping`:
//   Fixed     every Newton step's Krylov solve reaches `Linear Solver/Iterative/Tolerance`, and
//             the solve of the step that settled the active set (the cycle's answer) goes on until
//             its estimated algebraic error is at most kFinalFraction × η of the previous cycle
//             (finalSolve: η moves with the algebraic error, docs/solvers.md "Iterative solver");
//   Balanced  from the second adaptive cycle on, each Krylov solve stops at a relative residual t
//             chosen so that the estimated algebraic error of the stresses in the energy norm,
//             ‖A^{1/2} e_σ‖ with e = P⁻¹(b − K x) (the block preconditioner applied to the
//             residual, LinearSolver::estimateError), is at most γ η, η the estimate η_CF of the
//             previous cycle. After each solve the estimate is computed; above γ η the solve goes
//             on from where it stopped with a tighter t (never tighter than the fixed tolerance).
//             t is predicted from the error per unit of relative residual of the last solve,
//             aiming at γ η / 2; the first balanced solve tries t = γ η/‖A^{1/2}σ_h‖; t ≤ 1e-2.
// The Newton loop itself is unchanged: it stops only when no point changes state, so the active
// set it ends on is the one its last iterate satisfies. The first cycle (no η yet) and the first
// cycle of each load step use the fixed tolerance, and so does a restarted run's first cycle with
// Balanced; with Fixed a restarted run takes η from the checkpoint's last cycle (as the
// uninterrupted run has it).
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>

namespace sc::solvers {
class LinearSolver;
}

namespace sc::contact {

class BalancedStopping {
public:
  /// From a validated "Contact/Newton" list: null-like (isBalanced() false) for Stopping = Fixed.
  static BalancedStopping fromParameters(const Teuchos::ParameterList& newtonList);

  bool isBalanced() const { return balanced_; }
  double fraction() const { return fraction_; }

  /// η of the cycle before and η/‖A^{1/2}σ_h‖ (eta < 0: none, the fixed tolerance is used).
  void setDiscretisationError(double eta, double relative = 0.0)
  {
    eta_ = eta;
    relativeEta_ = relative;
  }
  double discretisationError() const { return eta_; }
  /// Whether the next solve with this solver is balanced (Balanced, a Krylov solver and an η).
  bool appliesTo(const solvers::LinearSolver& solver) const;

  struct Result {
    int iterations = 0;            ///< Krylov iterations over all stages
    int stages = 0;                ///< solves (1, or more when the estimate was above γ η)
    double tolerance = 0.0;        ///< relative residual tolerance of the last solve
    double algebraicError = -1.0;  ///< the estimate ‖A^{1/2} e_σ‖ of the last solve
  };

  /// Solve with the solver's current operator by the balanced rule (see the file comment); x:
  /// initial guess in, solution out. `energy`: a matrix whose block of the first `stressDofs`
  /// global ids is the compliance (A σ, τ) in the operator's unknowns. Restores the solver's
  /// tolerance and residual limit. Collective.
  Result solve(solvers::LinearSolver& solver, const Tpetra::MultiVector<>& rhs,
               Tpetra::MultiVector<>& x, const Tpetra::CrsMatrix<>& energy, long long stressDofs);

  /// Stopping = Fixed with a Krylov solver and an η: whether finalSolve applies.
  bool finalApplies(const solvers::LinearSolver& solver) const;

  /// Stopping = Fixed: the solve of the Newton step that settled the active set (the iterate the
  /// cycle reports) goes on from where it stopped until the estimated algebraic error
  /// ‖A^{1/2} e_σ‖ is at most kFinalFraction × η (η of the cycle before). x: that solve's
  /// solution in and out, the solver's operator still set. Returns stages 0 when the estimate
  /// was below the bound already (x unchanged). A stage that does not converge leaves x as it was
  /// before it. Collective.
  Result finalSolve(solvers::LinearSolver& solver, const Tpetra::MultiVector<>& rhs,
                    Tpetra::MultiVector<>& x, const Tpetra::CrsMatrix<>& energy,
                    long long stressDofs) const;

  /// The final solve's bound over η (kFinalFraction).
  static double finalFraction();

  /// ‖A^{1/2} v_σ‖: the energy norm of the stress part (global ids < stressDofs) of v.
  static double stressEnergyNorm(const Tpetra::CrsMatrix<>& energy, const Tpetra::MultiVector<>& v,
                                 long long stressDofs);

private:
  bool balanced_ = false;
  double fraction_ = 1e-3;
  double eta_ = -1.0, relativeEta_ = 0.0;
  double errorPerResidual_ = 0.0;  ///< the last solve's estimate over its relative residual
  /// The loosest tolerance: the active-set decisions need a meaningful iterate.
  static constexpr double kLoosestTolerance = 1e-2;
  /// Stopping = Fixed: the final solve's bound over η. η moves with the algebraic error; on the
  /// Hertz 2D multigrid runs 1e-7 kept η within 5.4e-7 of MUMPS' (docs/solvers.md "Iterative
  /// solver").
  static constexpr double kFinalFraction = 1e-7;
};

}  // namespace sc::contact

#pragma once
// Krylov solver for the 3×3 mixed system (docs/theory.md §"Linear solvers"): Belos MINRES
// (symmetric operator, SPD preconditioner) or flexible GMRES (contact rows: non-symmetric),
// preconditioned by the block diagonal
//
//   P = diag(S_σ, 2μ M_u, 2μ M_θ),   S_σ = A + (2μ)⁻¹ B_uᵀ M_u⁻¹ B_u,
//
// taken from the operator actually solved: S_σ = K_σσ + K_σu (2μ M_u)⁻¹ K_uσ, so replaced contact
// rows are in S_σ as docs/theory.md §"Linear solvers" asks (rebuilt at every setOperator). With the
// physical scaling D of LinearSolver the blocks are formed in the scaled system (D P D). M_u⁻¹ is
// exact (element blocks inverted); the θ block is diag(2μ M_θ). S_σ⁻¹ is applied by the "Stress
// block" sub-solver:
//   - MUMPS or KLU2: exact (robust in h and λ; the cost of a direct solve of the σ block, which
//     is SPD and smaller than the saddle-point system);
//   - Multigrid: one symmetric V(1,1) cycle of geometric multigrid on the nested hierarchy of
//     BlockStructure::multigrid (Galerkin coarse operators, additive Schwarz smoother
//     on vertex (2D) or edge (3D) patches, direct coarsest solve), docs/theory.md §"Linear
//     solvers";
//   - MueLu: smoothed-aggregation AMG, one V-cycle. Not robust (the kernel of div): offered to
//     measure that, docs/solvers.md.
//
// Convergence (solveKrylov): the criterion is the true relative residual ‖b − A x‖/‖b‖ of the
// working system ≤ `Tolerance`. Belos stops on its own residual relative to its initial one
// (MINRES: the preconditioned one), so it is asked for the reduction that reaches `Tolerance` from
// the initial guess, the true residual is checked after it returns, and Belos is restarted from
// the current iterate (at most 6 times) until it is below `Tolerance`. Otherwise: a
// sc::core::ConvergenceError naming the method, the iterations, Belos's own residual and the true
// one — also when Belos reported convergence ("loss of accuracy"): never a solution accepted on
// Belos's word.

#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_Operator_fwd.hpp>

#include <sc/solvers/LinearSolver.hpp>

namespace sc::solvers {

/// The Linear Solver/Iterative keys (read by LinearSolverFactory from the validated list; their
/// defaults are declared there, in getValidParameters(), and nowhere else).
struct IterativeOptions {
  std::string method;  ///< Auto (MINRES if symmetric, else GMRES), MINRES, GMRES
  double tolerance;
  int maxIterations;
  int restart;              ///< GMRES Krylov subspace size
  int outputFrequency;      ///< print the residual every n iterations (0: never)
  std::string stressBlock;  ///< MUMPS, KLU2, Multigrid, MueLu
  /// Stress block = Multigrid: Chebyshev degree of the patch smoother (0: 2 in 2D, 3 in 3D) and
  /// the ratio λ_max/λ_min of the smoothed part of the spectrum of B A.
  int smootherDegree;
  double smootherRatio;
  /// The validated "Linear Solver" list of the direct stress-block sub-solver (Type set from
  /// stressBlock).
  Teuchos::ParameterList directList;
};

/// What a Krylov solve achieved: its iterations, the true relative residual ‖b − A x‖/‖b‖ (the
/// worst column) and Belos's own last residual (relative to its initial one).
struct KrylovOutcome {
  int iterations = 0;
  double residual = 0.0;
  double ownResidual = 0.0;
};

/// The Krylov driver of IterativeSolver (see the file comment): Belos `method` (MINRES: `prec`
/// on the left, SPD; GMRES: on the right) on A x = b from the initial guess x, until the true
/// relative residual is ≤ options.tolerance within options.maxIterations. Throws
/// sc::core::ConvergenceError (on every rank) naming `name`, the iterations, Belos's residual and
/// the true one otherwise, in particular when Belos reports convergence that the true residual
/// does not confirm. Collective.
KrylovOutcome solveKrylov(const std::string& method,
                          const Teuchos::RCP<const Tpetra::Operator<>>& A,
                          const Teuchos::RCP<const Tpetra::Operator<>>& prec, const MultiVector& b,
                          MultiVector& x, const IterativeOptions& options, const std::string& name);

class IterativeSolver : public LinearSolver {
public:
  explicit IterativeSolver(IterativeOptions options);
  ~IterativeSolver() override;
  std::string name() const override;
  bool isIterative() const override { return true; }
  double relativeTolerance() const override { return options_.tolerance; }
  void setRelativeTolerance(double tolerance) override { options_.tolerance = tolerance; }

  /// Krylov methods and stress-block solvers this build offers.
  static const std::vector<std::string>& methods();
  static const std::vector<std::string>& stressBlockSolvers();

protected:
  void operatorChanged(const Teuchos::RCP<const CrsMatrix>& A, bool symmetric) override;
  void solveOperator(const MultiVector& b, MultiVector& x) override;
  bool applyPreconditioner(const MultiVector& r, MultiVector& z) const override;

private:
  std::string method() const;

  IterativeOptions options_;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sc::solvers

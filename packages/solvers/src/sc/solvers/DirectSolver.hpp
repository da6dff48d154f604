#pragma once
// A sparse direct solver for the distributed saddle-point systems of DESIGN §2–§3, with
// equilibration (DESIGN §3, "Replaced rows ... equilibrate") and reuse of the symbolic
// factorisation across Newton steps (DESIGN §6, "Contact rows change every Newton step").
//
// Usage:
//   auto solver = createDirectSolver(linearSolverList);   // LinearSolverFactory.hpp
//   solver->setOperator(A);
//   solver->solve(b, x);          // factorises as needed
//   ... change A's values, keeping its graph ...
//   solver->setOperator(A);       // same graph: the next factorisation reuses the analysis
//   solver->solve(b, x);
//
// "Same graph" means: the same row map and, in every locally owned row, the same global column
// indices in the same order (Tpetra keeps that order for a static graph or for a matrix refilled
// with the same insertions). Replaced contact rows must therefore keep a fixed pattern (store
// explicit zeros) for the analysis to be reused; otherwise a new analysis is done automatically.

#include <memory>
#include <string>

#include <Teuchos_RCP.hpp>

#include <sc/solvers/LinearAlgebraTypes.hpp>
#include <sc/solvers/SolveStatistics.hpp>

namespace sc::solvers {

class RuizEquilibration;

class DirectSolver {
public:
  virtual ~DirectSolver();
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;

  /// Name of the method ("KLU2", "MUMPS").
  virtual std::string name() const = 0;

  /// Set (or replace) the square operator A (fill-complete; row, range and domain maps with the
  /// same global indices, each owned by exactly one rank). Invalidates the numerical
  /// factorisation; keeps the symbolic one if A has the same graph as the previous operator.
  void setOperator(const Teuchos::RCP<const CrsMatrix>& A);

  /// Declare A symmetric (MUMPS then uses LDLᵀ, SYM = 2, from the lower triangle only). Contact
  /// rows make A non-symmetric (DESIGN §3): call setSymmetric(false) then. KLU2 ignores it.
  void setSymmetric(bool symmetric);
  bool isSymmetric() const { return symmetric_; }

  /// Ruiz diagonal scaling D_r A D_c before factorising (on by default; D_r = D_c when symmetric).
  void setEquilibration(bool equilibrate);
  bool equilibrationEnabled() const { return equilibrate_; }

  /// Ordering and symbolic analysis of the current operator's graph, always redone. Not needed in
  /// a Newton loop: numericFactorization() and solve() analyse only when the graph changed, and
  /// calling this every step throws the reuse away (DESIGN §6).
  void symbolicFactorization();
  /// Numerical factorisation; reuses the symbolic factorisation if it is still valid (same graph),
  /// otherwise analyses first.
  void numericFactorization();
  /// x = A⁻¹ b for every column; factorises first if the operator changed since the last
  /// factorisation. Afterwards lastSolveStats().relativeResidual holds ‖b − A x‖/‖b‖; a residual
  /// above the limit (default 1e-6, see LinearSolverFactory) or not finite throws
  /// sc::core::ConvergenceError on every rank.
  void solve(const MultiVector& b, MultiVector& x);

  const SolveStatistics& lastSolveStats() const { return stats_; }

  /// Largest accepted relative residual of a solve (<= 0: not checked).
  void setMaximumRelativeResidual(double limit) { maxRelativeResidual_ = limit; }
  void setEquilibrationIterations(int iterations);

protected:
  DirectSolver();

  // The hooks see the operator actually factorised (the equilibrated copy if equilibration is on)
  // and right-hand sides already scaled. They run on every rank of A's communicator and must
  // throw the same sc::core::Error on every rank.
  virtual void doSymbolicFactorization(const Teuchos::RCP<const CrsMatrix>& A) = 0;
  virtual void doNumericFactorization(const Teuchos::RCP<const CrsMatrix>& A) = 0;
  virtual void doSolve(const MultiVector& b, MultiVector& x) = 0;
  /// The symmetry flag changed (MUMPS must re-initialise).
  virtual void symmetryChanged() {}

  SolveStatistics stats_;

private:
  Teuchos::RCP<const CrsMatrix> operatorToFactor();

  Teuchos::RCP<const CrsMatrix> A_;        // the caller's operator
  Teuchos::RCP<const CrsMatrix> scaledA_;  // D_r A D_c when equilibrating
  std::unique_ptr<RuizEquilibration> equilibration_;
  unsigned long long graphHash_ = 0;
  bool symbolicValid_ = false;
  bool symbolicUsed_ = false;  // a numerical factorisation has used the current analysis
  bool numericValid_ = false;
  bool scaledValid_ = false;
  bool symmetric_ = false;
  bool equilibrate_ = true;
  double maxRelativeResidual_ = 1e-6;
  int equilibrationIterations_ = 20;
};

}  // namespace sc::solvers

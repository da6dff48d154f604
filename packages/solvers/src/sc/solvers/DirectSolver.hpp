#pragma once
// A sparse direct solver for the distributed saddle-point systems of docs/theory.md §"Mixed
// formulation", §"Contact and friction", with equilibration (docs/theory.md §"Contact and
// friction", "Replaced rows ... equilibrate") and reuse of the symbolic factorisation across Newton
// steps (docs/theory.md §"Linear solvers", "Contact rows change every Newton step").
//
// Usage (the LinearSolver interface):
//   auto solver = createDirectSolver(linearSolverList);   // LinearSolverFactory.hpp
//   solver->setOperator(A, symmetric);
//   solver->solve(b, x);          // factorises as needed
//   ... change A's values, keeping its graph ...
//   solver->setOperator(A, symmetric);  // same graph: the next factorisation reuses the analysis
//   solver->solve(b, x);
//
// "Same graph" means: the same row map and, in every locally owned row, the same global column
// indices in the same order (Tpetra keeps that order for a static graph or for a matrix refilled
// with the same insertions). Replaced contact rows must therefore keep a fixed pattern (store
// explicit zeros) for the analysis to be reused; otherwise a new analysis is done automatically.

#include <memory>
#include <string>

#include <Teuchos_RCP.hpp>

#include <sc/solvers/LinearSolver.hpp>

namespace sc::solvers {

class RuizEquilibration;

class DirectSolver : public LinearSolver {
public:
  ~DirectSolver() override;

  /// Ruiz diagonal scaling D_r A D_c before factorising (on by default; D_r = D_c when
  /// symmetric), on top of the physical scaling of LinearSolver::setScaling.
  void setEquilibration(bool equilibrate);
  bool equilibrationEnabled() const { return equilibrate_; }

  /// Ordering and symbolic analysis of the current operator's graph, always redone. Not needed in
  /// a Newton loop: numericFactorization() and solve() analyse only when the graph changed, and
  /// calling this every step throws the reuse away (docs/theory.md §"Linear solvers").
  void symbolicFactorization();
  /// Numerical factorisation; reuses the symbolic factorisation if it is still valid (same graph
  /// and symmetry), otherwise analyses first.
  void numericFactorization();

  void setEquilibrationIterations(int iterations);

protected:
  DirectSolver();

  void operatorChanged(const Teuchos::RCP<const CrsMatrix>& A, bool symmetric) override;
  /// Factorises first if the operator changed since the last factorisation.
  void solveOperator(const MultiVector& b, MultiVector& x) override;

  // The hooks see the operator actually factorised (the equilibrated copy if equilibration is on)
  // and right-hand sides already scaled. They run on every rank of A's communicator and must
  // throw the same sc::core::Error on every rank.
  virtual void doSymbolicFactorization(const Teuchos::RCP<const CrsMatrix>& A) = 0;
  virtual void doNumericFactorization(const Teuchos::RCP<const CrsMatrix>& A) = 0;
  virtual void doSolve(const MultiVector& b, MultiVector& x) = 0;
  /// The symmetry flag changed (MUMPS must re-initialise).
  virtual void symmetryChanged() {}

private:
  Teuchos::RCP<const CrsMatrix> operatorToFactor();

  Teuchos::RCP<const CrsMatrix> A_;  // the operator to factorise (after physical scaling)
  // D_r A D_c when equilibrating; its values are rewritten in place while the graph stays (a
  // contact Newton loop refactorises on one graph: no new matrix per step).
  Teuchos::RCP<CrsMatrix> scaledA_;
  std::unique_ptr<RuizEquilibration> equilibration_;
  unsigned long long graphHash_ = 0;
  bool factorizedSymmetric_ = false;  // the symmetry of the current analysis
  bool symbolicValid_ = false;
  bool symbolicUsed_ = false;  // a numerical factorisation has used the current analysis
  bool numericValid_ = false;
  bool scaledValid_ = false;
  bool equilibrate_ = true;
  int equilibrationIterations_ = 20;
};

}  // namespace sc::solvers

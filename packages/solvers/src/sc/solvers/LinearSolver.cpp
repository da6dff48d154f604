// The common part of every solver: scaling, the symmetry flag, the residual check.

#include <sc/solvers/LinearSolver.hpp>

#include <cmath>
#include <limits>

#include <Teuchos_Time.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Error.hpp>

namespace sc::solvers {

bool LinearSolver::estimateError(const MultiVector& b, const MultiVector& x,
                                 MultiVector& error) const
{
  if (working_.is_null()) return false;
  // The working system's residual r̃ = D (b − A x) = D b − (D A D)(D⁻¹ x); error = D P̃⁻¹ r̃.
  MultiVector r(b, Teuchos::Copy);
  A_->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
  if (!D_.is_null())
    for (size_t j = 0; j < r.getNumVectors(); ++j)
      r.getVectorNonConst(j)->elementWiseMultiply(1.0, *D_, *r.getVector(j), 0.0);
  MultiVector z(x.getMap(), x.getNumVectors());
  if (!applyPreconditioner(r, z)) return false;
  if (!D_.is_null())
    for (size_t j = 0; j < z.getNumVectors(); ++j)
      z.getVectorNonConst(j)->elementWiseMultiply(1.0, *D_, *z.getVector(j), 0.0);
  error.assign(z);
  return true;
}

Teuchos::RCP<CrsMatrix> copyMatrixValues(const CrsMatrix& source,
                                         const Teuchos::RCP<CrsMatrix>& reuse)
{
  SC_THROW_IF(reuse.get() == &source, sc::core::InternalError,
              "copyMatrixValues: the target is the source");
  if (reuse.is_null() || reuse->getCrsGraph().get() != source.getCrsGraph().get())
    return Teuchos::rcp(new CrsMatrix(source, Teuchos::Copy));
  Kokkos::deep_copy(reuse->getLocalMatrixHost().values, source.getLocalMatrixHost().values);
  return reuse;
}

LinearSolver::LinearSolver() = default;
LinearSolver::~LinearSolver() = default;

void LinearSolver::setScaling(const Teuchos::RCP<const Vector>& D) { D_ = D; }

void LinearSolver::setBlockStructure(const BlockStructure& blocks) { blocks_ = blocks; }

void LinearSolver::setExploitSymmetry(bool exploit) { exploitSymmetry_ = exploit; }

void LinearSolver::setOperator(const Teuchos::RCP<const CrsMatrix>& A, bool symmetric)
{
  SC_THROW_IF(A.is_null(), sc::core::InternalError, name() << " solver: setOperator(null)");
  SC_THROW_IF(!A->isFillComplete(), sc::core::InternalError,
              name() << " solver: the operator must be fill-complete");
  SC_THROW_IF(A->getGlobalNumRows() != A->getGlobalNumCols(), sc::core::InternalError,
              name() << " solver: the operator is " << A->getGlobalNumRows() << " x "
                     << A->getGlobalNumCols() << ", not square");
  A_ = A;
  if (D_.is_null()) {
    working_ = A;
  } else {
    SC_THROW_IF(!D_->getMap()->isSameAs(*A->getRowMap()), sc::core::InternalError,
                name() << " solver: the scaling vector's map differs from the operator's row map");
    auto S = copyMatrixValues(*A, scaledWorking_.get() != A.get() ? scaledWorking_ : Teuchos::null);
    scaledWorking_ = isIterative() ? Teuchos::null : S;
    S->leftScale(*D_);
    S->rightScale(*D_);
    working_ = S;
  }
  symmetric_ = symmetric && exploitSymmetry_;
  operatorChanged(working_, symmetric_);
}

void LinearSolver::solve(const MultiVector& b, MultiVector& x)
{
  SC_THROW_IF(A_.is_null(), sc::core::InternalError,
              name() << " solver: no operator set (call setOperator first)");
  SC_THROW_IF(b.getNumVectors() != x.getNumVectors(), sc::core::InternalError,
              name() << " solver: b has " << b.getNumVectors() << " columns, x has "
                     << x.getNumVectors());
  const size_t m = b.getNumVectors();
  // The working system: D A D y = D b with y0 = D⁻¹ x0, x = D y (or A x = b without scaling).
  Teuchos::RCP<const MultiVector> bw = Teuchos::rcpFromRef(b);
  Teuchos::RCP<MultiVector> y = Teuchos::rcpFromRef(x);
  if (!D_.is_null()) {
    auto Db = Teuchos::rcp(new MultiVector(b.getMap(), m, false));
    y = Teuchos::rcp(new MultiVector(x.getMap(), m, false));
    Vector Dinv(D_->getMap(), false);
    Dinv.reciprocal(*D_);
    for (size_t j = 0; j < m; ++j) {
      Db->getVectorNonConst(j)->elementWiseMultiply(1.0, *D_, *b.getVector(j), 0.0);
      y->getVectorNonConst(j)->elementWiseMultiply(1.0, Dinv, *x.getVector(j), 0.0);
    }
    bw = Db;
  }
  solveOperator(*bw, *y);

  // Residual of the working system (the one the solver sees; with the physical scaling its
  // blocks are of order one whatever E is): catches a wrong symmetry flag, a singular pivot that
  // slipped through, loss of accuracy or a Krylov solve stopped early, on every rank at once.
  MultiVector r(*bw, Teuchos::Copy);
  working_->apply(*y, r, Teuchos::NO_TRANS, -1.0, 1.0);
  Teuchos::Array<double> rNorm(m), bNorm(m);
  r.norm2(rNorm());
  bw->norm2(bNorm());
  double worst = 0.0;
  for (size_t j = 0; j < m; ++j) {
    const double rel = bNorm[j] > 0.0 ? rNorm[j] / bNorm[j] : rNorm[j];
    worst = std::isfinite(rel) ? std::max(worst, rel) : std::numeric_limits<double>::infinity();
  }
  stats_.relativeResidual = worst;
  SC_THROW_IF(!std::isfinite(worst), sc::core::ConvergenceError,
              name() << " solver: the solution is not finite (singular or badly scaled matrix of "
                     << A_->getGlobalNumRows() << " rows)");
  SC_THROW_IF(
      maxRelativeResidual_ > 0.0 && worst > maxRelativeResidual_, sc::core::ConvergenceError,
      name() << " solver: relative residual ‖b − A x‖/‖b‖ = " << worst
             << " exceeds Linear Solver/Maximum relative residual = " << maxRelativeResidual_
             << " (singular or nearly singular matrix, or an operator declared symmetric "
                "that is not?)");
  if (!D_.is_null())
    for (size_t j = 0; j < m; ++j)
      x.getVectorNonConst(j)->elementWiseMultiply(1.0, *D_, *y->getVector(j), 0.0);
}

}  // namespace sc::solvers

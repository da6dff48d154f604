// Common part of the direct solvers: operator bookkeeping (graph check for symbolic reuse),
// equilibration around the concrete factorisation. The residual check is LinearSolver's.

#include <sc/solvers/DirectSolver.hpp>

#include "sc/core/Collective.hpp"
#include <Teuchos_Time.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Error.hpp>
#include <sc/solvers/RuizEquilibration.hpp>

namespace sc::solvers {

namespace {

// 64-bit hash of the locally owned pattern (row GIDs, then the column GIDs of each row in storage
// order). splitmix64 mixing: an accidental collision between two different graphs has probability
// ~2^-64.
unsigned long long mix(unsigned long long h, unsigned long long v)
{
  unsigned long long z = h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

unsigned long long localGraphHash(const CrsMatrix& A)
{
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  const auto lclA = A.getLocalMatrixHost();
  unsigned long long h = mix(0, static_cast<unsigned long long>(A.getGlobalNumRows()));
  const auto nRows = static_cast<int>(A.getNodeNumRows());
  for (int i = 0; i < nRows; ++i) {
    h = mix(h, static_cast<unsigned long long>(rowMap->getGlobalElement(i)));
    for (auto k = lclA.graph.row_map(i); k < lclA.graph.row_map(i + 1); ++k)
      h = mix(h, static_cast<unsigned long long>(colMap->getGlobalElement(lclA.graph.entries(k))));
    h = mix(h, 0xffffffffffffffffULL);  // row separator
  }
  return h;
}

}  // namespace

DirectSolver::DirectSolver() = default;
DirectSolver::~DirectSolver() = default;

void DirectSolver::operatorChanged(const Teuchos::RCP<const CrsMatrix>& A, bool symmetric)
{
  if (symmetric != factorizedSymmetric_) {
    // LDLᵀ and LU analyses differ (MUMPS SYM), and so does the Ruiz scaling (D_r = D_c or not).
    factorizedSymmetric_ = symmetric;
    symbolicValid_ = false;
    equilibration_.reset();
    symmetryChanged();
  }
  const unsigned long long hash = localGraphHash(*A);
  bool sameGraph = symbolicValid_ && !A_.is_null() && A_->getComm().get() == A->getComm().get() &&
                   A_->getGlobalNumRows() == A->getGlobalNumRows() &&
                   A_->getGlobalNumEntries() == A->getGlobalNumEntries() &&
                   A_->getRowMap()->isSameAs(*A->getRowMap());
  // every rank must agree (isSameAs is collective; the hash is local)
  const int localSame = (sameGraph && hash == graphHash_) ? 1 : 0;
  const int globalSame = sc::core::minOverRanks(*A->getComm(), localSame);
  A_ = A;
  graphHash_ = hash;
  symbolicValid_ = globalSame == 1;
  numericValid_ = false;
  scaledValid_ = false;
}

void DirectSolver::setEquilibration(bool equilibrate)
{
  if (equilibrate == equilibrate_) return;
  equilibrate_ = equilibrate;
  numericValid_ = scaledValid_ = false;  // the graph is unchanged: the analysis stays valid
}

void DirectSolver::setEquilibrationIterations(int iterations)
{
  SC_THROW_IF(iterations < 1, sc::core::InputError,
              "Linear Solver/Equilibration iterations = " << iterations << " must be >= 1");
  equilibrationIterations_ = iterations;
  equilibration_.reset();
  numericValid_ = scaledValid_ = false;
}

// The operator handed to the concrete solver: A itself or its equilibrated copy (recomputed when
// the values changed, i.e. after setOperator).
Teuchos::RCP<const CrsMatrix> DirectSolver::operatorToFactor()
{
  SC_THROW_IF(A_.is_null(), sc::core::InternalError,
              name() << " solver: no operator set (call setOperator first)");
  if (!equilibrate_) return A_;
  if (!scaledValid_) {
    Teuchos::Time timer("equilibration");
    timer.start(true);
    if (!equilibration_)
      equilibration_ =
          std::make_unique<RuizEquilibration>(factorizedSymmetric_, equilibrationIterations_, 0.1);
    equilibration_->compute(*A_);
    if (!scaledA_.is_null() && scaledA_.get() != A_.get() &&
        scaledA_->getCrsGraph().get() == A_->getCrsGraph().get())
      equilibration_->scaleInto(*A_, *scaledA_);
    else
      scaledA_ = equilibration_->scaledCopy(*A_);
    stats_.equilibrationSeconds = timer.stop();
    stats_.totalEquilibrationSeconds += stats_.equilibrationSeconds;
    stats_.equilibrationIterations = equilibration_->iterations();
    scaledValid_ = true;
  }
  return scaledA_;
}

void DirectSolver::symbolicFactorization()
{
  const auto op = operatorToFactor();
  Teuchos::Time timer("symbolic");
  timer.start(true);
  doSymbolicFactorization(op);
  stats_.symbolicSeconds = timer.stop();
  stats_.totalSymbolicSeconds += stats_.symbolicSeconds;
  ++stats_.symbolicFactorizations;
  symbolicValid_ = true;
  symbolicUsed_ = false;
  numericValid_ = false;
}

void DirectSolver::numericFactorization()
{
  const auto op = operatorToFactor();
  if (!symbolicValid_)
    symbolicFactorization();
  else if (symbolicUsed_)
    ++stats_.symbolicReuses;
  Teuchos::Time timer("numeric");
  timer.start(true);
  doNumericFactorization(op);
  stats_.numericSeconds = timer.stop();
  stats_.totalNumericSeconds += stats_.numericSeconds;
  ++stats_.numericFactorizations;
  symbolicUsed_ = true;
  numericValid_ = true;
}

void DirectSolver::solveOperator(const MultiVector& b, MultiVector& x)
{
  if (!numericValid_) numericFactorization();
  Teuchos::Time timer("solve");
  timer.start(true);
  if (equilibrate_) {
    // A x = b  <=>  (D_r A D_c) y = D_r b,  x = D_c y
    MultiVector bScaled(b.getMap(), b.getNumVectors(), false);
    bScaled.elementWiseMultiply(1.0, equilibration_->rowScaling(), b, 0.0);
    MultiVector y(x.getMap(), x.getNumVectors(), false);
    doSolve(bScaled, y);
    x.elementWiseMultiply(1.0, equilibration_->columnScaling(), y, 0.0);
  } else {
    doSolve(b, x);
  }
  stats_.solveSeconds = timer.stop();
  stats_.totalSolveSeconds += stats_.solveSeconds;
  ++stats_.solves;
}

}  // namespace sc::solvers

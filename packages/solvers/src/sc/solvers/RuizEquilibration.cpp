// Ruiz equilibration of a distributed Tpetra::CrsMatrix (see the header for the method and why).

#include <sc/solvers/RuizEquilibration.hpp>

#include <algorithm>
#include <climits>
#include <cmath>

#include "sc/core/Collective.hpp"
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Error.hpp>

namespace sc::solvers {

namespace {

// Throw on every rank if some rank has a zero norm; name the smallest such global index.
void checkNonzero(const Teuchos::Comm<int>& comm, const Map& map,
                  const Teuchos::ArrayRCP<const double>& norms, const char* what)
{
  long long firstZero = LLONG_MAX;
  for (size_t i = 0; i < map.getNodeNumElements(); ++i)
    if (!(norms[i] > 0.0))
      firstZero = std::min(firstZero, static_cast<long long>(map.getGlobalElement(i)));
  const long long globalFirst = sc::core::minOverRanks(comm, firstZero);
  SC_THROW_IF(globalFirst != LLONG_MAX, sc::core::Error,
              "Equilibration: " << what << " with global index " << globalFirst
                                << " of the linear system is zero: the matrix is singular "
                                   "(a missing boundary condition or an unconstrained DOF?)");
}

double powerOfTwo(double d) { return std::exp2(std::round(std::log2(d))); }

}  // namespace

RuizEquilibration::RuizEquilibration(bool symmetric, int maxIterations, double tolerance)
    : symmetric_(symmetric), maxIterations_(maxIterations), tolerance_(tolerance)
{
}

RuizEquilibration::~RuizEquilibration() = default;

void RuizEquilibration::compute(const CrsMatrix& A)
{
  const auto comm = A.getComm();
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  const auto domainMap = A.getDomainMap();
  SC_THROW_IF(!rowMap->isSameAs(*A.getRangeMap()), sc::core::InternalError,
              "Equilibration: the row map of the matrix must equal its range map");
  SC_THROW_IF(symmetric_ && !domainMap->isSameAs(*A.getRangeMap()), sc::core::InternalError,
              "Equilibration: a symmetric scaling needs equal domain and range maps");

  rowScale_ = Teuchos::rcp(new Vector(A.getRangeMap()));
  colScale_ = Teuchos::rcp(new Vector(domainMap));
  rowScale_->putScalar(1.0);
  colScale_->putScalar(1.0);
  Vector colScaleOnColMap(colMap), colNormOnColMap(colMap), rowNorm(A.getRangeMap()),
      colNorm(domainMap);
  const Tpetra::Import<> importer(domainMap, colMap);

  const auto lclA = A.getLocalMatrixHost();
  const auto nRows = static_cast<int>(A.getNodeNumRows());
  iterations_ = 0;
  for (int sweep = 0; sweep < maxIterations_; ++sweep) {
    colScaleOnColMap.doImport(*colScale_, importer, Tpetra::INSERT);
    colNormOnColMap.putScalar(0.0);
    {
      auto dr = rowScale_->getData(0);
      auto dc = colScaleOnColMap.getData(0);
      auto rn = rowNorm.getDataNonConst(0);
      auto cn = colNormOnColMap.getDataNonConst(0);
      for (int i = 0; i < nRows; ++i) {
        double m = 0.0;
        for (auto k = lclA.graph.row_map(i); k < lclA.graph.row_map(i + 1); ++k) {
          const int j = lclA.graph.entries(k);
          const double v = std::abs(dr[i] * lclA.values(k) * dc[j]);
          m = std::max(m, v);
          cn[j] = std::max(cn[j], v);
        }
        rn[i] = m;
      }
    }
    colNorm.putScalar(0.0);
    colNorm.doExport(colNormOnColMap, importer, Tpetra::ABSMAX);

    if (sweep == 0) {
      checkNonzero(*comm, *rowMap, rowNorm.getData(0), "row");
      checkNonzero(*comm, *domainMap, colNorm.getData(0), "column");
    }
    // deviation from an equilibrated matrix (all row and column ∞-norms 1)
    double localDev = 0.0;
    {
      auto rn = rowNorm.getData(0);
      auto cn = colNorm.getData(0);
      for (long i = 0; i < rn.size(); ++i)
        localDev = std::max(localDev, std::abs(1.0 - rn[i]));
      for (long i = 0; i < cn.size(); ++i)
        localDev = std::max(localDev, std::abs(1.0 - cn[i]));
    }
    deviation_ = sc::core::maxOverRanks(*comm, localDev);
    if (deviation_ <= tolerance_) break;
    ++iterations_;

    auto dr = rowScale_->getDataNonConst(0);
    auto dc = colScale_->getDataNonConst(0);
    auto rn = rowNorm.getData(0);
    auto cn = colNorm.getData(0);
    if (symmetric_) {
      for (long i = 0; i < dr.size(); ++i) {
        dr[i] /= std::sqrt(std::max(rn[i], cn[i]));
        dc[i] = dr[i];
      }
    } else {
      for (long i = 0; i < dr.size(); ++i)
        dr[i] /= std::sqrt(rn[i]);
      for (long i = 0; i < dc.size(); ++i)
        dc[i] /= std::sqrt(cn[i]);
    }
  }
  // Powers of two: the scaling itself then commits no rounding error.
  {
    auto dr = rowScale_->getDataNonConst(0);
    auto dc = colScale_->getDataNonConst(0);
    for (long i = 0; i < dr.size(); ++i)
      dr[i] = powerOfTwo(dr[i]);
    for (long i = 0; i < dc.size(); ++i)
      dc[i] = powerOfTwo(dc[i]);
  }
}

Teuchos::RCP<CrsMatrix> RuizEquilibration::scaledCopy(const CrsMatrix& A) const
{
  SC_THROW_IF(rowScale_.is_null(), sc::core::InternalError,
              "Equilibration: scaledCopy() before compute()");
  // Copy shares A's (static) graph and deep-copies the values.
  auto B = Teuchos::rcp(new CrsMatrix(A, Teuchos::Copy));
  scaleInto(A, *B);
  return B;
}

void RuizEquilibration::scaleInto(const CrsMatrix& A, CrsMatrix& B) const
{
  SC_THROW_IF(rowScale_.is_null(), sc::core::InternalError,
              "Equilibration: scaleInto() before compute()");
  SC_THROW_IF(A.getCrsGraph().get() != B.getCrsGraph().get(), sc::core::InternalError,
              "Equilibration: scaleInto() needs a target on the graph of the source matrix");
  Vector colScaleOnColMap(A.getColMap());
  colScaleOnColMap.doImport(*colScale_, Tpetra::Import<>(A.getDomainMap(), A.getColMap()),
                            Tpetra::INSERT);
  auto dr = rowScale_->getData(0);
  auto dc = colScaleOnColMap.getData(0);
  const auto lclA = A.getLocalMatrixHost();
  const auto lclB = B.getLocalMatrixHost();
  const auto nRows = static_cast<int>(B.getNodeNumRows());
  for (int i = 0; i < nRows; ++i)
    for (auto k = lclB.graph.row_map(i); k < lclB.graph.row_map(i + 1); ++k)
      lclB.values(k) = lclA.values(k) * (dr[i] * dc[lclB.graph.entries(k)]);
}

}  // namespace sc::solvers

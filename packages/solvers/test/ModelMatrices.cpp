// Model systems for the solver tests and the benchmark (see the header).

#include "ModelMatrices.hpp"

#include <cmath>
#include <functional>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

namespace sc::solvers::testing {

namespace {

using GO = long long;
using RowFunction = std::function<void(GO row, std::vector<GO>& cols, std::vector<double>& vals)>;

// Build an N × N matrix with Tpetra's uniform contiguous row distribution; each rank fills its
// own rows from rowEntries (columns sorted by the formula).
Teuchos::RCP<CrsMatrix> assemble(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, GO N,
                                 size_t maxPerRow, const RowFunction& rowEntries)
{
  auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(N), 0, comm));
  auto A = Teuchos::rcp(new CrsMatrix(map, maxPerRow));
  std::vector<GO> cols;
  std::vector<double> vals;
  for (size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GO row = map->getGlobalElement(i);
    cols.clear();
    vals.clear();
    rowEntries(row, cols, vals);
    A->insertGlobalValues(row, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

void poisson2dRow(GO n, GO row, std::vector<GO>& cols, std::vector<double>& vals)
{
  const GO ix = row % n, iy = row / n;
  if (iy > 0) cols.push_back(row - n), vals.push_back(-1.0);
  if (ix > 0) cols.push_back(row - 1), vals.push_back(-1.0);
  cols.push_back(row), vals.push_back(4.0);
  if (ix + 1 < n) cols.push_back(row + 1), vals.push_back(-1.0);
  if (iy + 1 < n) cols.push_back(row + n), vals.push_back(-1.0);
}

template <class F>
Teuchos::RCP<CrsMatrix> modifiedCopy(const CrsMatrix& A, F modifyRow)
{
  auto B = Teuchos::rcp(new CrsMatrix(A, Teuchos::Copy));
  const auto lcl = B->getLocalMatrixHost();
  const auto rowMap = B->getRowMap();
  const auto colMap = B->getColMap();
  for (int i = 0; i < static_cast<int>(B->getNodeNumRows()); ++i) {
    const GO row = rowMap->getGlobalElement(i);
    for (auto k = lcl.graph.row_map(i); k < lcl.graph.row_map(i + 1); ++k)
      modifyRow(row, colMap->getGlobalElement(lcl.graph.entries(k)), lcl.values(k));
  }
  return B;
}

}  // namespace

Teuchos::RCP<CrsMatrix> poisson2d(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int n,
                                  bool duplicateLastRow)
{
  const GO N = static_cast<GO>(n) * n;
  return assemble(comm, N, 5, [=](GO row, std::vector<GO>& c, std::vector<double>& v) {
    poisson2dRow(n, duplicateLastRow && row == N - 1 ? N - 2 : row, c, v);
  });
}

Teuchos::RCP<CrsMatrix> poisson3d(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int n)
{
  const GO nn = n, N = nn * nn * nn;
  return assemble(comm, N, 7, [=](GO row, std::vector<GO>& c, std::vector<double>& v) {
    const GO ix = row % nn, iy = (row / nn) % nn, iz = row / (nn * nn);
    if (iz > 0) c.push_back(row - nn * nn), v.push_back(-1.0);
    if (iy > 0) c.push_back(row - nn), v.push_back(-1.0);
    if (ix > 0) c.push_back(row - 1), v.push_back(-1.0);
    c.push_back(row), v.push_back(6.0);
    if (ix + 1 < nn) c.push_back(row + 1), v.push_back(-1.0);
    if (iy + 1 < nn) c.push_back(row + nn), v.push_back(-1.0);
    if (iz + 1 < nn) c.push_back(row + nn * nn), v.push_back(-1.0);
  });
}

Teuchos::RCP<CrsMatrix> saddlePoint(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, int n,
                                    double scaleM, double scaleB)
{
  const GO nu = static_cast<GO>(n) * n, np = nu / 2, N = nu + np;
  return assemble(comm, N, 8, [=](GO row, std::vector<GO>& c, std::vector<double>& v) {
    if (row < nu) {
      // K = Laplacian + I, scaled; then Bᵀ: column j = row of u gets B[p, j] for p with j in
      // {2p, 2p+1, 2p+3}.
      poisson2dRow(n, row, c, v);
      for (auto& x : v)
        x *= scaleM;
      for (size_t k = 0; k < c.size(); ++k)
        if (c[k] == row) v[k] += scaleM;
      const GO j = row;
      if (j % 2 == 0) {
        c.push_back(nu + j / 2), v.push_back(2.0 * scaleB);
      } else {
        if (j >= 3) c.push_back(nu + (j - 3) / 2), v.push_back(0.5 * scaleB);
        c.push_back(nu + (j - 1) / 2), v.push_back(-1.0 * scaleB);
      }
    } else {
      const GO p = row - nu;
      c.push_back(2 * p), v.push_back(2.0 * scaleB);
      c.push_back(2 * p + 1), v.push_back(-1.0 * scaleB);
      if (2 * p + 3 < nu) c.push_back(2 * p + 3), v.push_back(0.5 * scaleB);
    }
  });
}

Teuchos::RCP<CrsMatrix> withReplacedRows(const CrsMatrix& A, long long period, double coupling,
                                         long long rowLimit)
{
  // The coupling entry is chosen by global index (not storage order, which depends on the
  // column map and so on the number of ranks).
  return modifiedCopy(A, [=](GO row, GO col, double& value) {
    if (row % period != 0 || (rowLimit >= 0 && row >= rowLimit)) return;
    value = col == row ? 1.0 : (col == row + 1 ? coupling : 0.0);
  });
}

Teuchos::RCP<CrsMatrix> withZeroRow(const CrsMatrix& A, long long zeroRow)
{
  return modifiedCopy(A, [=](GO row, GO, double& value) {
    if (row == zeroRow) value = 0.0;
  });
}

Teuchos::RCP<CrsMatrix> withShiftedDiagonal(const CrsMatrix& A, double shift)
{
  return modifiedCopy(A, [=](GO row, GO col, double& value) {
    if (row == col) value += shift;
  });
}

Teuchos::RCP<MultiVector> manufacturedSolution(const Teuchos::RCP<const Map>& map, int columns)
{
  auto x = Teuchos::rcp(new MultiVector(map, columns));
  for (int j = 0; j < columns; ++j) {
    auto d = x->getDataNonConst(j);
    for (size_t i = 0; i < map->getNodeNumElements(); ++i) {
      const double g = static_cast<double>(map->getGlobalElement(i));
      d[i] = std::sin(0.37 * g + 0.1 + j) + 0.5 * std::cos(0.011 * g);
    }
  }
  return x;
}

Teuchos::RCP<MultiVector> manufacturedSaddleSolution(const Teuchos::RCP<const Map>& map,
                                                     long long nu, double scaleM, double scaleB)
{
  auto x = manufacturedSolution(map, 1);
  auto d = x->getDataNonConst(0);
  for (size_t i = 0; i < map->getNodeNumElements(); ++i)
    if (map->getGlobalElement(i) >= nu) d[i] *= scaleM / scaleB;
  return x;
}

double relativeErrorInRange(const MultiVector& x, const MultiVector& y, long long begin,
                            long long end)
{
  const auto map = x.getMap();
  double worst = 0.0;
  for (size_t j = 0; j < x.getNumVectors(); ++j) {
    auto xd = x.getData(j);
    auto yd = y.getData(j);
    double local[2] = {0.0, 0.0}, global[2] = {0.0, 0.0};
    for (size_t i = 0; i < map->getNodeNumElements(); ++i) {
      const GO g = map->getGlobalElement(i);
      if (g < begin || g >= end) continue;
      local[0] += (xd[i] - yd[i]) * (xd[i] - yd[i]);
      local[1] += yd[i] * yd[i];
    }
    Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_SUM, 2, local, global);
    worst = std::max(worst, std::sqrt(global[0] / global[1]));
  }
  return worst;
}

double relativeError(const MultiVector& x, const MultiVector& y)
{
  MultiVector d(x, Teuchos::Copy);
  d.update(-1.0, y, 1.0);
  Teuchos::Array<double> dn(x.getNumVectors()), yn(x.getNumVectors());
  d.norm2(dn());
  y.norm2(yn());
  double worst = 0.0;
  for (size_t j = 0; j < dn.size(); ++j)
    worst = std::max(worst, dn[j] / yn[j]);
  return worst;
}

std::vector<double> gatherToRoot(const MultiVector& x)
{
  const auto map = x.getMap();
  const auto comm = map->getComm();
  const auto N = map->getGlobalNumElements();
  auto rootMap = Teuchos::rcp(
      new Map(N, comm->getRank() == 0 ? static_cast<size_t>(N) : 0, map->getIndexBase(), comm));
  MultiVector onRoot(rootMap, x.getNumVectors());
  onRoot.doImport(x, Tpetra::Import<>(map, rootMap), Tpetra::INSERT);
  std::vector<double> all;
  if (comm->getRank() == 0) {
    all.resize(static_cast<size_t>(N) * x.getNumVectors());
    onRoot.get1dCopy(Teuchos::ArrayView<double>(all), static_cast<size_t>(N));
  }
  return all;
}

}  // namespace sc::solvers::testing

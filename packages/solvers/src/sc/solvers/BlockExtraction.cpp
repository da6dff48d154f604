// Field blocks of the mixed system (see the header).

#include <sc/solvers/BlockExtraction.hpp>

#include <algorithm>
#include <map>

#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>

#include <sc/core/Error.hpp>

namespace sc::solvers {

namespace {
using GO = Map::global_ordinal_type;
using LO = Map::local_ordinal_type;
}  // namespace

Teuchos::RCP<const Map> subMap(const Map& map, long long begin, long long end,
                               std::vector<int>& localIndices)
{
  std::vector<GO> gids;
  localIndices.clear();
  const LO n = static_cast<LO>(map.getNodeNumElements());
  for (LO i = 0; i < n; ++i) {
    const GO g = map.getGlobalElement(i);
    if (g >= begin && g < end) {
      gids.push_back(g);
      localIndices.push_back(i);
    }
  }
  const auto inv = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  return Teuchos::rcp(new Map(inv, Teuchos::ArrayView<const GO>(gids), 0, map.getComm()));
}

// The block of K with rows `rowMap` (a subset of K's owned rows, same global ids) and columns in
// [colBegin, colEnd), as a fill-complete matrix with domain `domainMap` and range `rowMap`.
Teuchos::RCP<CrsMatrix> extractBlock(const CrsMatrix& K, const Teuchos::RCP<const Map>& rowMap,
                                     long long colBegin, long long colEnd,
                                     const Teuchos::RCP<const Map>& domainMap)
{
  const auto& kRows = *K.getRowMap();
  const auto& kCols = *K.getColMap();
  const LO n = static_cast<LO>(rowMap->getNodeNumElements());
  std::vector<size_t> counts(n, 0);
  std::vector<std::vector<GO>> cols(n);
  std::vector<std::vector<double>> vals(n);
  for (LO i = 0; i < n; ++i) {
    const LO r = kRows.getLocalElement(rowMap->getGlobalElement(i));
    typename CrsMatrix::local_inds_host_view_type inds;
    typename CrsMatrix::values_host_view_type v;
    K.getLocalRowView(r, inds, v);
    for (size_t k = 0; k < inds.extent(0); ++k) {
      const GO g = kCols.getGlobalElement(inds(k));
      if (g >= colBegin && g < colEnd) {
        cols[i].push_back(g);
        vals[i].push_back(v(k));
      }
    }
    counts[i] = cols[i].size();
  }
  auto B = Teuchos::rcp(new CrsMatrix(rowMap, Teuchos::ArrayView<const size_t>(counts)));
  for (LO i = 0; i < n; ++i)
    if (!cols[i].empty())
      B->insertGlobalValues(rowMap->getGlobalElement(i), Teuchos::ArrayView<const GO>(cols[i]),
                            Teuchos::ArrayView<const double>(vals[i]));
  B->fillComplete(domainMap, rowMap);
  return B;
}

// Exact inverse of a block-diagonal SPD matrix whose blocks are owned by one rank each (the
// displacement mass of discontinuous elements): rows with the same smallest column id form a block.
Teuchos::RCP<CrsMatrix> blockInverse(const CrsMatrix& M)
{
  const auto& rows = *M.getRowMap();
  const auto& colMap = *M.getColMap();
  const LO n = static_cast<LO>(rows.getNodeNumElements());
  std::map<GO, std::vector<LO>> blocks;
  for (LO i = 0; i < n; ++i) {
    typename CrsMatrix::local_inds_host_view_type inds;
    typename CrsMatrix::values_host_view_type v;
    M.getLocalRowView(i, inds, v);
    GO first = rows.getGlobalElement(i);
    for (size_t k = 0; k < inds.extent(0); ++k)
      first = std::min(first, colMap.getGlobalElement(inds(k)));
    blocks[first].push_back(i);
  }
  std::vector<size_t> counts(n, 0);
  for (const auto& b : blocks)
    for (LO i : b.second)
      counts[i] = b.second.size();
  auto inv = Teuchos::rcp(new CrsMatrix(M.getRowMap(), Teuchos::ArrayView<const size_t>(counts)));
  Teuchos::LAPACK<int, double> lapack;
  for (const auto& b : blocks) {
    const auto& r = b.second;
    const int m = static_cast<int>(r.size());
    std::vector<GO> gids(m);
    for (int a = 0; a < m; ++a)
      gids[a] = rows.getGlobalElement(r[a]);
    std::vector<double> dense(static_cast<std::size_t>(m) * m, 0.0);
    for (int a = 0; a < m; ++a) {
      typename CrsMatrix::local_inds_host_view_type inds;
      typename CrsMatrix::values_host_view_type v;
      M.getLocalRowView(r[a], inds, v);
      for (size_t k = 0; k < inds.extent(0); ++k) {
        const GO g = colMap.getGlobalElement(inds(k));
        const auto it = std::find(gids.begin(), gids.end(), g);
        SC_THROW_IF(it == gids.end() && v(k) != 0.0, sc::core::InternalError,
                    "block preconditioner: the displacement mass is not block diagonal with "
                    "blocks owned by one rank (row "
                        << gids[a] << ", column " << g << ")");
        if (it != gids.end())
          dense[static_cast<std::size_t>(it - gids.begin()) * m + a] = v(k);  // column-major
      }
    }
    int info = 0;
    lapack.POTRF('L', m, dense.data(), m, &info);
    SC_THROW_IF(info != 0, sc::core::InternalError,
                "block preconditioner: a displacement mass block is not positive definite "
                "(LAPACK potrf info "
                    << info << ", rows from " << gids[0] << ")");
    lapack.POTRI('L', m, dense.data(), m, &info);
    for (int a = 0; a < m; ++a) {
      std::vector<double> row(m);
      for (int c = 0; c < m; ++c)
        row[c] = a >= c ? dense[static_cast<std::size_t>(c) * m + a]
                        : dense[static_cast<std::size_t>(a) * m + c];
      inv->insertGlobalValues(gids[a], Teuchos::ArrayView<const GO>(gids),
                              Teuchos::ArrayView<const double>(row));
    }
  }
  inv->fillComplete(M.getDomainMap(), M.getRangeMap());
  return inv;
}

}  // namespace sc::solvers

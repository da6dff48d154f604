// The patch smoother of the stress-block multigrid (see the header).

#include <sc/solvers/PatchSmoother.hpp>

#include <algorithm>
#include <type_traits>

#include <Teuchos_LAPACK.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/core/Error.hpp>

namespace sc::solvers {

namespace {
using GO = Map::global_ordinal_type;
using LO = Map::local_ordinal_type;
static_assert(std::is_same_v<LO, int>, "PatchSmoother keeps local ids as int");
}  // namespace

PatchSmoother::PatchSmoother(const CrsMatrix& A, const std::vector<std::vector<long long>>& patches,
                             bool symmetric)
    : rowMap_(A.getRowMap()), symmetric_(symmetric)
{
  std::vector<GO> ov;
  for (const auto& p : patches)
    ov.insert(ov.end(), p.begin(), p.end());
  std::sort(ov.begin(), ov.end());
  ov.erase(std::unique(ov.begin(), ov.end()), ov.end());
  const auto inv = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  overlapMap_ = Teuchos::rcp(new Map(inv, Teuchos::ArrayView<const GO>(ov), 0, A.getComm()));
  import_ = Teuchos::rcp(new Tpetra::Import<>(A.getRowMap(), overlapMap_));
  export_ = Teuchos::rcp(new Tpetra::Export<>(overlapMap_, A.getRowMap()));
  CrsMatrix Aov(overlapMap_, 0);
  Aov.doImport(A, *import_, Tpetra::INSERT);
  Aov.fillComplete(A.getDomainMap(), A.getRangeMap());
  const auto& colMap = *Aov.getColMap();
  std::size_t total = 0, lids = 0;
  for (const auto& p : patches) {
    total += p.size() * p.size();
    lids += p.size();
  }
  if (symmetric)
    factors_.reserve(total);
  else
    luFactors_.reserve(total);
  lids_.reserve(lids);
  if (!symmetric) pivots_.reserve(lids);
  Teuchos::LAPACK<int, double> lapack;
  std::vector<double> dense;
  std::vector<int> ipiv;
  // position in the current patch of each column of Aov (−1: not in the patch)
  std::vector<int> position(colMap.getNodeNumElements(), -1);
  for (const auto& p : patches) {
    const int m = static_cast<int>(p.size());
    if (m == 0) continue;
    sizes_.push_back(m);
    for (int a = 0; a < m; ++a) {
      lids_.push_back(overlapMap_->getLocalElement(p[a]));
      const LO c = colMap.getLocalElement(p[a]);
      if (c != Teuchos::OrdinalTraits<LO>::invalid()) position[c] = a;
    }
    dense.assign(static_cast<std::size_t>(m) * m, 0.0);
    for (int a = 0; a < m; ++a) {
      typename CrsMatrix::local_inds_host_view_type inds;
      typename CrsMatrix::values_host_view_type v;
      Aov.getLocalRowView(lids_[lids_.size() - m + a], inds, v);
      for (size_t k = 0; k < inds.extent(0); ++k)
        if (position[inds(k)] >= 0)
          dense[static_cast<std::size_t>(position[inds(k)]) * m + a] = v(k);  // column-major
    }
    for (int a = 0; a < m; ++a) {
      const LO c = colMap.getLocalElement(p[a]);
      if (c != Teuchos::OrdinalTraits<LO>::invalid()) position[c] = -1;
    }
    int info = 0;
    if (symmetric) {
      lapack.POTRF('L', m, dense.data(), m, &info);
      SC_THROW_IF(info != 0, sc::core::ConvergenceError,
                  "stress multigrid: a patch block is not positive definite (LAPACK potrf "
                  "info "
                      << info << ")");
    } else {
      ipiv.resize(m);
      lapack.GETRF(m, m, dense.data(), m, ipiv.data(), &info);
      SC_THROW_IF(info != 0, sc::core::ConvergenceError,
                  "stress multigrid: a patch block is singular (LAPACK getrf info " << info << ")");
      pivots_.insert(pivots_.end(), ipiv.begin(), ipiv.end());
    }
    if (symmetric)
      factors_.insert(factors_.end(), dense.begin(), dense.end());  // rounded to float
    else
      luFactors_.insert(luFactors_.end(), dense.begin(), dense.end());
  }
}

PatchSmoother::~PatchSmoother() = default;

void PatchSmoother::apply(const MultiVector& r, MultiVector& z, double omega, double beta) const
{
  const size_t nv = r.getNumVectors();
  MultiVector rov(overlapMap_, nv, false), zov(overlapMap_, nv, true);
  rov.doImport(r, *import_, Tpetra::INSERT);
  Teuchos::LAPACK<int, float> lapackFloat;
  Teuchos::LAPACK<int, double> lapackDouble;
  std::vector<float> xf;
  std::vector<double> xd;
  for (size_t j = 0; j < nv; ++j) {
    const auto rv = rov.getData(j);
    auto zv = zov.getDataNonConst(j);
    std::size_t lid = 0, entry = 0;
    for (int m : sizes_) {
      int info = 0;
      if (symmetric_) {
        xf.resize(m);
        for (int a = 0; a < m; ++a)
          xf[a] = static_cast<float>(rv[lids_[lid + a]]);
        lapackFloat.POTRS('L', m, 1, factors_.data() + entry, m, xf.data(), m, &info);
        for (int a = 0; a < m; ++a)
          zv[lids_[lid + a]] += xf[a];
      } else {
        xd.resize(m);
        for (int a = 0; a < m; ++a)
          xd[a] = rv[lids_[lid + a]];
        lapackDouble.GETRS('N', m, 1, luFactors_.data() + entry, m, pivots_.data() + lid, xd.data(),
                           m, &info);
        for (int a = 0; a < m; ++a)
          zv[lids_[lid + a]] += xd[a];
      }
      lid += m;
      entry += static_cast<std::size_t>(m) * m;
    }
  }
  MultiVector sum(rowMap_, nv, true);
  sum.doExport(zov, *export_, Tpetra::ADD);
  z.update(omega, sum, beta);
}

}  // namespace sc::solvers

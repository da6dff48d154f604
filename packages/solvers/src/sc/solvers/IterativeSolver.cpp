// Belos MINRES/GMRES with the block-diagonal preconditioner of docs/theory.md §"Linear solvers"
// (see the header). The Belos, MueLu and TpetraExt templates stay in this translation unit (compile
// time).

#include <sc/solvers/IterativeSolver.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory_Tpetra.hpp>
#include <BelosTpetraAdapter.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_BLAS.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Teuchos_Time.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Error.hpp>
#include <sc/solvers/DirectSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

namespace sc::solvers {

namespace {

using GO = Map::global_ordinal_type;
using LO = Map::local_ordinal_type;
using Operator = Tpetra::Operator<>;

// The owned rows of `map` whose global ids lie in [begin, end), as a map with the same global ids
// and the monolithic local indices of those rows.
Teuchos::RCP<const Map> subMap(const Map& map, long long begin, long long end,
                               std::vector<LO>& localIndices)
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
                    "blocks owned by one rank (row " << gids[a] << ", column " << g << ")");
        if (it != gids.end())
          dense[static_cast<std::size_t>(it - gids.begin()) * m + a] = v(k);  // column-major
      }
    }
    int info = 0;
    lapack.POTRF('L', m, dense.data(), m, &info);
    SC_THROW_IF(info != 0, sc::core::InternalError,
                "block preconditioner: a displacement mass block is not positive definite "
                "(LAPACK potrf info " << info << ", rows from " << gids[0] << ")");
    lapack.POTRI('L', m, dense.data(), m, &info);
    for (int a = 0; a < m; ++a) {
      std::vector<double> row(m);
      for (int c = 0; c < m; ++c)
        row[c] = a >= c ? dense[static_cast<std::size_t>(c) * m + a] : dense[static_cast<std::size_t>(a) * m + c];
      inv->insertGlobalValues(gids[a], Teuchos::ArrayView<const GO>(gids),
                              Teuchos::ArrayView<const double>(row));
    }
  }
  inv->fillComplete(M.getDomainMap(), M.getRangeMap());
  return inv;
}

double maxOverRanks(const Teuchos::Comm<int>& comm, double v)
{
  double r = v;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &v, &r);
  return r;
}

}  // namespace

namespace {

// The additive Schwarz smoother B = Σ_i R_iᵀ A_i⁻¹ R_i over the patches (σ global ids) of this
// rank, applied matrix-free: each patch block A_i is factorised once by LAPACK in double
// (Cholesky when symmetric, LU with partial pivoting otherwise) and the factors are kept in
// single precision (a preconditioner needs no more; it halves the largest memory item);
// apply() imports the residual onto the union of this rank's patches (rows of patches cut by the
// partition come from the other ranks), solves with each patch's factors and exports (adds) the
// corrections to their owners. Memory: Σ_i m_i² floats. (Assembling B as a sparse matrix took
// more than 5 GB at 262k 3D DOFs with vertex stars.)
class PatchSmoother {
public:
  PatchSmoother(const CrsMatrix& A, const std::vector<std::vector<long long>>& patches,
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
    factors_.reserve(total);
    lids_.reserve(lids);
    if (!symmetric)
      pivots_.reserve(lids);
    Teuchos::LAPACK<int, double> lapack;
    std::vector<double> dense;
    std::vector<int> ipiv;
    // position in the current patch of each column of Aov (−1: not in the patch)
    std::vector<int> position(colMap.getNodeNumElements(), -1);
    for (const auto& p : patches) {
      const int m = static_cast<int>(p.size());
      if (m == 0)
        continue;
      sizes_.push_back(m);
      for (int a = 0; a < m; ++a) {
        lids_.push_back(overlapMap_->getLocalElement(p[a]));
        const LO c = colMap.getLocalElement(p[a]);
        if (c != Teuchos::OrdinalTraits<LO>::invalid())
          position[c] = a;
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
        if (c != Teuchos::OrdinalTraits<LO>::invalid())
          position[c] = -1;
      }
      int info = 0;
      if (symmetric) {
        lapack.POTRF('L', m, dense.data(), m, &info);
        SC_THROW_IF(info != 0, sc::core::ConvergenceError,
                    "stress multigrid: a patch block is not positive definite (LAPACK potrf "
                    "info " << info << ")");
      } else {
        ipiv.resize(m);
        lapack.GETRF(m, m, dense.data(), m, ipiv.data(), &info);
        SC_THROW_IF(info != 0, sc::core::ConvergenceError,
                    "stress multigrid: a patch block is singular (LAPACK getrf info " << info
                                                                                     << ")");
        pivots_.insert(pivots_.end(), ipiv.begin(), ipiv.end());
      }
      factors_.insert(factors_.end(), dense.begin(), dense.end());  // rounded to float
    }
  }

  /// z ← β z + ω B r.
  void apply(const MultiVector& r, MultiVector& z, double omega, double beta) const
  {
    const size_t nv = r.getNumVectors();
    MultiVector rov(overlapMap_, nv, false), zov(overlapMap_, nv, true);
    rov.doImport(r, *import_, Tpetra::INSERT);
    Teuchos::LAPACK<int, float> lapack;
    std::vector<float> x;
    for (size_t j = 0; j < nv; ++j) {
      const auto rv = rov.getData(j);
      auto zv = zov.getDataNonConst(j);
      std::size_t lid = 0, entry = 0;
      for (int m : sizes_) {
        x.resize(m);
        for (int a = 0; a < m; ++a)
          x[a] = static_cast<float>(rv[lids_[lid + a]]);
        int info = 0;
        if (symmetric_)
          lapack.POTRS('L', m, 1, factors_.data() + entry, m, x.data(), m, &info);
        else
          lapack.GETRS('N', m, 1, factors_.data() + entry, m, pivots_.data() + lid, x.data(), m,
                       &info);
        for (int a = 0; a < m; ++a)
          zv[lids_[lid + a]] += x[a];
        lid += m;
        entry += static_cast<std::size_t>(m) * m;
      }
    }
    MultiVector sum(rowMap_, nv, true);
    sum.doExport(zov, *export_, Tpetra::ADD);
    z.update(omega, sum, beta);
  }

private:
  Teuchos::RCP<const Map> rowMap_, overlapMap_;
  Teuchos::RCP<Tpetra::Import<>> import_;
  Teuchos::RCP<Tpetra::Export<>> export_;
  bool symmetric_ = true;
  std::vector<int> sizes_;      // patch sizes m_i
  std::vector<LO> lids_;        // the patches' rows, local ids of the overlap map, concatenated
  std::vector<float> factors_;  // Cholesky (lower) or LU factors, column-major m_i × m_i
  std::vector<int> pivots_;     // LU: the pivots of each patch, concatenated
};

// One symmetric V-cycle of geometric multigrid for S_σ (docs/theory.md §"Linear solvers"):
// Galerkin coarse operators A_{l−1} = P_lᵀ A_l P_l on the nested hierarchy; on every finer level
// the Chebyshev polynomial of degree `degree` in B_l A_l before and after the coarse correction,
// B_l = Σ_i R_iᵀ A_{l,i}⁻¹ R_i the additive Schwarz smoother on vertex (2D) or edge (3D) patches
// (PatchSmoother), on the interval [λ_max/ratio, λ_max] of B_l A_l; a direct solve on the
// coarsest level. The same polynomial before and after keeps the cycle symmetric (MINRES).
class StressMultigrid : public Operator {
public:
  struct Level {
    Teuchos::RCP<const CrsMatrix> A, P;  // P: from level l−1 into l
    std::shared_ptr<const PatchSmoother> B;
    double lambdaMax = 1.0;  // upper bound of the spectrum of B A (power iteration × 1.1)
  };
  std::vector<Level> levels;  // coarsest first
  Teuchos::RCP<DirectSolver> coarse;
  int degree = 2;       // Chebyshev degree (smoother applications before and after)
  double ratio = 10.0;  // λ_max / λ_min of the smoothed interval

  Teuchos::RCP<const Map> getDomainMap() const override { return levels.back().A->getDomainMap(); }
  Teuchos::RCP<const Map> getRangeMap() const override { return levels.back().A->getRangeMap(); }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override
  {
    SC_THROW_IF(mode != Teuchos::NO_TRANS || alpha != 1.0 || beta != 0.0, sc::core::InternalError,
                "stress multigrid: only Y = V(X) is implemented");
    vcycle(static_cast<int>(levels.size()) - 1, X, Y);
  }

  void vcycle(int l, const MultiVector& b, MultiVector& x) const
  {
    if (l == 0) {
      x.putScalar(0.0);
      coarse->solve(b, x);
      return;
    }
    const Level& L = levels[l];
    const size_t m = b.getNumVectors();
    smooth(L, b, x, true);
    MultiVector r(b, Teuchos::Copy);
    L.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
    MultiVector rc(L.P->getDomainMap(), m, false), ec(L.P->getDomainMap(), m, false);
    L.P->apply(r, rc, Teuchos::TRANS);
    vcycle(l - 1, rc, ec);
    L.P->apply(ec, x, Teuchos::NO_TRANS, 1.0, 1.0);
    smooth(L, b, x, false);
  }

  // x ← x + p(B A) B (b − A x) with the Chebyshev iteration of `degree` steps on
  // [λ_max/ratio, λ_max] (Saad, Iterative Methods, Alg. 12.1, preconditioned by B); `zero`: x = 0
  // on entry (its residual is b).
  void smooth(const Level& L, const MultiVector& b, MultiVector& x, bool zero) const
  {
    const double lmax = L.lambdaMax, lmin = lmax / ratio;
    const double theta = 0.5 * (lmax + lmin), delta = 0.5 * (lmax - lmin), sigma = theta / delta;
    double rho = 1.0 / sigma;
    MultiVector r(b, Teuchos::Copy), d(x.getMap(), x.getNumVectors(), false);
    if (!zero)
      L.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
    L.B->apply(r, d, 1.0 / theta, 0.0);
    if (zero)
      Tpetra::deep_copy(x, d);
    else
      x.update(1.0, d, 1.0);
    for (int k = 1; k < degree; ++k) {
      Tpetra::deep_copy(r, b);
      L.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
      const double rhoNew = 1.0 / (2.0 * sigma - rho);
      d.scale(rhoNew * rho);
      L.B->apply(r, d, 2.0 * rhoNew / delta, 1.0);
      x.update(1.0, d, 1.0);
      rho = rhoNew;
    }
  }
};

// λ_max(B A) by power iteration (B A is similar to an SPD operator when both are SPD).
double largestEigenvalue(const PatchSmoother& B, const CrsMatrix& A, int iterations)
{
  MultiVector v(A.getDomainMap(), 1), w(A.getRangeMap(), 1), z(A.getDomainMap(), 1);
  v.randomize();
  double lambda = 0.0;
  for (int it = 0; it < iterations; ++it) {
    Teuchos::Array<double> n(1);
    v.norm2(n());
    v.scale(1.0 / n[0]);
    A.apply(v, w);
    B.apply(w, z, 1.0, 0.0);
    z.norm2(n());
    lambda = n[0];
    Tpetra::deep_copy(v, z);
  }
  return lambda;
}

// The V-cycle of S (the finest level's S_σ) on the hierarchy of `blocks`.
Teuchos::RCP<StressMultigrid> buildMultigrid(const BlockStructure& blocks,
                                             const Teuchos::RCP<CrsMatrix>& S,
                                             const std::vector<char>& constraintRows,
                                             bool symmetric,
                                             const IterativeOptions& options,
                                             const Teuchos::ParameterList& directList)
{
  const auto& levels = blocks.multigrid;
  const int L = static_cast<int>(levels.size());
  SC_THROW_IF(L < 1, sc::core::InputError,
              "Linear Solver/Iterative/Stress block = Multigrid needs the nested mesh hierarchy "
              "(solvers::BlockStructure::multigrid, e.g. from sc::assembly::StressHierarchy); "
              "none was given. Use a Stress block of MUMPS or KLU2.");
  auto mg = Teuchos::rcp(new StressMultigrid());
  mg->degree = options.smootherDegree > 0 ? options.smootherDegree : (blocks.dimension == 2 ? 2 : 3);
  mg->ratio = options.smootherRatio;
  mg->levels.resize(L);
  mg->levels[L - 1].A = S;
  for (int l = L - 1; l >= 1; --l) {
    SC_THROW_IF(levels[l].prolongation.is_null(), sc::core::InternalError,
                "stress multigrid: level " << l << " has no prolongation");
    auto P = Teuchos::rcp(new CrsMatrix(*levels[l].prolongation, Teuchos::Copy));
    const auto& A = *mg->levels[l].A;
    {
      // Rows with only a diagonal (fixed by traction data on the finest level; decoupled rows of
      // a coarser one, below) take no coarse correction.
      Vector mask(P->getRangeMap());
      auto mv = mask.getDataNonConst(0);
      const auto& rows = *A.getRowMap();
      const auto& cols = *A.getColMap();
      for (LO i = 0; i < static_cast<LO>(mv.size()); ++i) {
        const GO g = P->getRangeMap()->getGlobalElement(i);
        typename CrsMatrix::local_inds_host_view_type inds;
        typename CrsMatrix::values_host_view_type v;
        A.getLocalRowView(rows.getLocalElement(g), inds, v);
        bool offDiagonal = false;
        for (size_t k = 0; k < inds.extent(0) && !offDiagonal; ++k)
          offDiagonal = v(k) != 0.0 && cols.getGlobalElement(inds(k)) != g;
        const bool constraint = l == L - 1 && constraintRows[rows.getLocalElement(g)];
        mv[i] = offDiagonal && !constraint ? 1.0 : 0.0;
      }
      // The coarse basis functions with a normal trace on those rows' faces (traction DOFs of
      // the coarse level) violate the fine constraint: drop them from the coarse space (zero
      // columns; their coarse rows get a unit diagonal below). Keeping them with their
      // constrained part cut off made P rank-deficient on locally refined hierarchies (a patch
      // of a Galerkin operator not positive definite).
      Vector flagged(P->getColMap(), true);
      {
        auto fv = flagged.getDataNonConst(0);
        for (LO i = 0; i < static_cast<LO>(mv.size()); ++i) {
          if (mv[i] != 0.0)
            continue;
          typename CrsMatrix::local_inds_host_view_type inds;
          typename CrsMatrix::values_host_view_type v;
          P->getLocalRowView(i, inds, v);
          for (size_t k = 0; k < inds.extent(0); ++k)
            if (v(k) != 0.0)
              fv[inds(k)] = 1.0;
        }
      }
      Vector coarseFlag(P->getDomainMap(), true);
      coarseFlag.doExport(flagged, Tpetra::Export<>(P->getColMap(), P->getDomainMap()),
                          Tpetra::ADD);
      {
        auto cv = coarseFlag.getDataNonConst(0);
        for (LO j = 0; j < static_cast<LO>(cv.size()); ++j)
          cv[j] = cv[j] != 0.0 ? 0.0 : 1.0;
      }
      P->leftScale(mask);
      P->rightScale(coarseFlag);
    }
    auto AP = Teuchos::rcp(new CrsMatrix(A.getRowMap(), 0));
    Tpetra::MatrixMatrix::Multiply(A, false, *P, false, *AP);
    auto Ac = Teuchos::rcp(new CrsMatrix(P->getDomainMap(), 0));
    Tpetra::MatrixMatrix::Multiply(*P, true, *AP, false, *Ac);
    // A coarse DOF whose fine image is only masked rows (on locally refined hierarchies: a
    // traction DOF of an element that was not refined) has a zero row and column: set its
    // diagonal to 1, a decoupled unknown that the restriction never excites.
    {
      Vector diag(Ac->getRowMap());
      Ac->getLocalDiagCopy(diag);
      const auto dv = diag.getData(0);
      std::vector<LO> dead;
      for (LO i = 0; i < static_cast<LO>(dv.size()); ++i)
        if (dv[i] == 0.0)
          dead.push_back(i);
      long long nDead = static_cast<long long>(dead.size()), anyDead = 0;
      Teuchos::reduceAll(*Ac->getComm(), Teuchos::REDUCE_SUM, 1, &nDead, &anyDead);
      if (anyDead > 0) {
        CrsMatrix D(Ac->getRowMap(), 1);
        for (LO i : dead) {
          const GO g = Ac->getRowMap()->getGlobalElement(i);
          const double one = 1.0;
          D.insertGlobalValues(g, Teuchos::ArrayView<const GO>(&g, 1),
                               Teuchos::ArrayView<const double>(&one, 1));
        }
        D.fillComplete(P->getDomainMap(), P->getDomainMap());
        Ac = Tpetra::MatrixMatrix::add(1.0, false, *Ac, 1.0, false, D, P->getDomainMap(),
                                       P->getDomainMap());
      }
    }
    mg->levels[l].P = P;
    mg->levels[l - 1].A = Ac;
  }
  for (int l = 1; l < L; ++l) {
    auto& lev = mg->levels[l];
    lev.B = std::make_shared<PatchSmoother>(*lev.A, levels[l].patches, symmetric);
    // 15 power steps underestimate λ_max; the Chebyshev polynomial grows outside its interval,
    // so the bound is raised by 10% (Ifpack2's default boost factor).
    lev.lambdaMax = 1.1 * largestEigenvalue(*lev.B, *lev.A, 15);
  }
  Teuchos::ParameterList dl(directList);
  if (!dl.isParameter("Type"))
    dl.set("Type", std::string("MUMPS"));
  mg->coarse = createDirectSolver(dl);
  mg->coarse->setOperator(mg->levels[0].A, symmetric);
  mg->coarse->numericFactorization();
  return mg;
}

}  // namespace

// diag(S_σ⁻¹, (2μM_u)⁻¹, diag(2μM_θ)⁻¹) in the working (scaled) system, as one Tpetra operator.
class BlockDiagonalPreconditioner : public Operator {
public:
  Teuchos::RCP<const Map> map, stressMap, displacementMap;
  std::vector<LO> stressLids, displacementLids, rotationLids;
  std::vector<double> rotationInverseDiagonal;
  Teuchos::RCP<CrsMatrix> displacementInverse;
  Teuchos::RCP<DirectSolver> stressDirect;       // exact S_σ⁻¹
  Teuchos::RCP<Operator> stressMultigrid;        // or one AMG / geometric multigrid V-cycle

  Teuchos::RCP<const Map> getDomainMap() const override { return map; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map; }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override
  {
    SC_THROW_IF(mode != Teuchos::NO_TRANS || alpha != 1.0 || beta != 0.0, sc::core::InternalError,
                "block preconditioner: only Y = P⁻¹ X is implemented");
    const size_t m = X.getNumVectors();
    MultiVector xs(stressMap, m, false), ys(stressMap, m, true);
    MultiVector xu(displacementMap, m, false), yu(displacementMap, m, false);
    for (size_t j = 0; j < m; ++j) {
      const auto x = X.getData(j);
      auto a = xs.getDataNonConst(j);
      for (std::size_t i = 0; i < stressLids.size(); ++i)
        a[i] = x[stressLids[i]];
      auto c = xu.getDataNonConst(j);
      for (std::size_t i = 0; i < displacementLids.size(); ++i)
        c[i] = x[displacementLids[i]];
    }
    if (!stressDirect.is_null())
      stressDirect->solve(xs, ys);
    else
      stressMultigrid->apply(xs, ys);
    displacementInverse->apply(xu, yu);
    for (size_t j = 0; j < m; ++j) {
      const auto x = X.getData(j);
      auto y = Y.getDataNonConst(j);
      const auto a = ys.getData(j);
      for (std::size_t i = 0; i < stressLids.size(); ++i)
        y[stressLids[i]] = a[i];
      const auto c = yu.getData(j);
      for (std::size_t i = 0; i < displacementLids.size(); ++i)
        y[displacementLids[i]] = c[i];
      for (std::size_t i = 0; i < rotationLids.size(); ++i)
        y[rotationLids[i]] = rotationInverseDiagonal[i] * x[rotationLids[i]];
    }
  }
};

struct IterativeSolver::Impl {
  Teuchos::RCP<const CrsMatrix> A;
  bool symmetric = false;
  Teuchos::RCP<BlockDiagonalPreconditioner> prec;
  // What the mass blocks were built from (rebuilt when either changes). Held, so that a new
  // object can never have the address of one compared against.
  Teuchos::RCP<const CrsMatrix> massUsed;
  Teuchos::RCP<const Vector> scalingUsed;
  Teuchos::RCP<CrsMatrix> stressOfOperator;  // S_σ of the current operator
};

IterativeSolver::IterativeSolver(IterativeOptions options)
  : options_(std::move(options)), impl_(std::make_unique<Impl>())
{
  const auto& m = methods();
  SC_THROW_IF(std::find(m.begin(), m.end(), options_.method) == m.end(), sc::core::InputError,
              "Linear Solver/Iterative/Method = \"" << options_.method
                  << "\" is not available; valid: Auto, MINRES, GMRES");
  const auto& s = stressBlockSolvers();
  SC_THROW_IF(std::find(s.begin(), s.end(), options_.stressBlock) == s.end(),
              sc::core::InputError,
              "Linear Solver/Iterative/Stress block = \"" << options_.stressBlock
                  << "\" is not available; valid: MUMPS, KLU2, Multigrid, MueLu");
}

IterativeSolver::~IterativeSolver() = default;

const std::vector<std::string>& IterativeSolver::methods()
{
  static const std::vector<std::string> m = {"Auto", "MINRES", "GMRES"};
  return m;
}

const std::vector<std::string>& IterativeSolver::stressBlockSolvers()
{
  static const std::vector<std::string> s = {"MUMPS", "KLU2", "Multigrid", "MueLu"};
  return s;
}

std::string IterativeSolver::method() const
{
  if (options_.method != "Auto")
    return options_.method;
  return impl_->symmetric ? "MINRES" : "GMRES";
}

std::string IterativeSolver::name() const
{
  return method() + "/block diagonal (S_σ: " + options_.stressBlock + ")";
}

void IterativeSolver::operatorChanged(const Teuchos::RCP<const CrsMatrix>& A, bool symmetric)
{
  const auto& blocks = blockStructure();
  SC_THROW_IF(!blocks.isSet() || blocks.fieldMass.is_null(), sc::core::InternalError,
              "iterative solver: setBlockStructure (field sizes and masses) must come before "
              "setOperator");
  SC_THROW_IF(static_cast<long long>(A->getGlobalNumRows()) != blocks.end(2),
              sc::core::InternalError,
              "iterative solver: the operator has " << A->getGlobalNumRows()
                  << " rows, the block structure " << blocks.end(2));
  SC_THROW_IF(options_.method == "MINRES" && !symmetric, sc::core::InputError,
              "Linear Solver/Iterative/Method = MINRES needs a symmetric operator, but this one "
              "is not (contact rows, or Linear Solver/Symmetric = false): use GMRES or Auto");
  Teuchos::Time timer("preconditioner");
  timer.start(true);
  Impl& m = *impl_;
  m.A = A;
  m.symmetric = symmetric;
  const auto& map = A->getRowMap();
  if (m.prec.is_null() || m.massUsed.get() != blocks.fieldMass.get() ||
      m.scalingUsed.get() != scaling().get() || !m.prec->map->isSameAs(*map)) {
    // Mass blocks of the working system: D (2μ M) D.
    SC_THROW_IF(!blocks.fieldMass->getRowMap()->isSameAs(*map), sc::core::InternalError,
                "block preconditioner: the field mass matrix's row map differs from the operator's");
    auto P = Teuchos::rcp(new CrsMatrix(*blocks.fieldMass, Teuchos::Copy));
    Vector s(map);  // √(2μ) D
    if (scaling().is_null())
      s.putScalar(std::sqrt(blocks.twoMu));
    else
      s.update(std::sqrt(blocks.twoMu), *scaling(), 0.0);
    P->leftScale(s);
    P->rightScale(s);
    auto prec = Teuchos::rcp(new BlockDiagonalPreconditioner());
    prec->map = map;
    prec->stressMap = subMap(*map, blocks.begin(0), blocks.end(0), prec->stressLids);
    prec->displacementMap = subMap(*map, blocks.begin(1), blocks.end(1), prec->displacementLids);
    subMap(*map, blocks.begin(2), blocks.end(2), prec->rotationLids);
    auto Pu = extractBlock(*P, prec->displacementMap, blocks.begin(1), blocks.end(1),
                           prec->displacementMap);
    prec->displacementInverse = blockInverse(*Pu);
    Vector diag(map);
    P->getLocalDiagCopy(diag);
    const auto dv = diag.getData(0);
    // HRZ lumping: the diagonal scaled to keep the total mass, c = 1ᵀM_θ1 / tr M_θ (the same
    // ratio on every affine element, so this is the element-wise HRZ lumping; = row-sum lumping
    // for P1, and positive for k ≥ 2 where row sums are not).
    double sums[2] = {0.0, 0.0}, global[2] = {0.0, 0.0};
    for (LO l : prec->rotationLids) {
      typename CrsMatrix::local_inds_host_view_type inds;
      typename CrsMatrix::values_host_view_type v;
      P->getLocalRowView(l, inds, v);
      for (size_t k = 0; k < inds.extent(0); ++k)
        sums[0] += v(k);
      sums[1] += dv[l];
    }
    Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_SUM, 2, sums, global);
    const double hrz = global[1] > 0.0 ? global[0] / global[1] : 1.0;
    prec->rotationInverseDiagonal.resize(prec->rotationLids.size());
    for (std::size_t i = 0; i < prec->rotationLids.size(); ++i) {
      const double v = hrz * dv[prec->rotationLids[i]];
      SC_THROW_IF(!(v > 0.0), sc::core::InternalError,
                  "block preconditioner: rotation mass diagonal " << v << " is not positive");
      prec->rotationInverseDiagonal[i] = 1.0 / v;
    }
    if (options_.stressBlock == "MUMPS" || options_.stressBlock == "KLU2") {
      Teuchos::ParameterList dl(options_.directList);
      dl.set("Type", options_.stressBlock);
      prec->stressDirect = createDirectSolver(dl);
    }
    m.prec = prec;
    m.massUsed = blocks.fieldMass;
    m.scalingUsed = scaling();
  }
  auto& prec = *m.prec;

  // S_σ = K_σσ + K_σu (D_u 2μ M_u D_u)⁻¹ K_uσ of the operator actually solved.
  auto Kss = extractBlock(*A, prec.stressMap, blocks.begin(0), blocks.end(0), prec.stressMap);
  auto Ksu = extractBlock(*A, prec.stressMap, blocks.begin(1), blocks.end(1), prec.displacementMap);
  auto Kus = extractBlock(*A, prec.displacementMap, blocks.begin(0), blocks.end(0), prec.stressMap);
  auto T = Teuchos::rcp(new CrsMatrix(prec.stressMap, 0));
  Tpetra::MatrixMatrix::Multiply(*Ksu, false, *prec.displacementInverse, false, *T);
  auto T2 = Teuchos::rcp(new CrsMatrix(prec.stressMap, 0));
  Tpetra::MatrixMatrix::Multiply(*T, false, *Kus, false, *T2);
  m.stressOfOperator =
      Tpetra::MatrixMatrix::add(1.0, false, *Kss, 1.0, false, *T2, prec.stressMap, prec.stressMap);
  if (!prec.stressDirect.is_null()) {
    prec.stressDirect->setOperator(m.stressOfOperator, symmetric);
    prec.stressDirect->numericFactorization();
  } else if (options_.stressBlock == "Multigrid") {
    Teuchos::ParameterList dl(options_.directList);
    dl.set("Type", std::string("MUMPS"));
    // Rows of S_σ without displacement coupling are constraints (traction data, contact rows
    // replaced by the active-set step): no coarse correction there (buildMultigrid).
    std::vector<char> constraintRows(prec.stressMap->getNodeNumElements(), 0);
    for (LO i = 0; i < static_cast<LO>(constraintRows.size()); ++i) {
      typename CrsMatrix::local_inds_host_view_type inds;
      typename CrsMatrix::values_host_view_type v;
      Ksu->getLocalRowView(i, inds, v);
      bool coupled = false;
      for (size_t k = 0; k < inds.extent(0) && !coupled; ++k)
        coupled = v(k) != 0.0;
      constraintRows[i] = coupled ? 0 : 1;
    }
    prec.stressMultigrid =
        buildMultigrid(blocks, m.stressOfOperator, constraintRows, symmetric, options_, dl);
  } else {
    Teuchos::ParameterList ml;
    ml.set("verbosity", "none");
    ml.set("multigrid algorithm", symmetric ? "sa" : "pg");
    ml.set("coarse: type", "Klu");  // SuperLU (MueLu's default) is not in Debian's build
    ml.set("smoother: type", "CHEBYSHEV");
    ml.set("problem: symmetric", symmetric);
    Teuchos::RCP<Operator> op = m.stressOfOperator;
    prec.stressMultigrid = MueLu::CreateTpetraPreconditioner(op, ml);
  }
  stats_.preconditionerSeconds = maxOverRanks(*map->getComm(), timer.stop());
  ++stats_.preconditionerSetups;
}

void IterativeSolver::solveOperator(const MultiVector& b, MultiVector& x)
{
  Impl& m = *impl_;
  Teuchos::Time timer("solve");
  timer.start(true);
  const std::string meth = method();
  auto params = Teuchos::rcp(new Teuchos::ParameterList());
  params->set("Maximum Iterations", options_.maxIterations);
  params->set("Convergence Tolerance", options_.tolerance);
  if (options_.outputFrequency > 0) {
    params->set("Verbosity", static_cast<int>(Belos::Errors + Belos::Warnings + Belos::StatusTestDetails));
    params->set("Output Frequency", options_.outputFrequency);
    params->set("Output Style", static_cast<int>(Belos::Brief));
  } else {
    params->set("Verbosity", static_cast<int>(Belos::Errors));
  }
  if (meth == "GMRES") {
    params->set("Num Blocks", options_.restart);
    params->set("Maximum Restarts", options_.maxIterations / std::max(1, options_.restart) + 1);
  }
  Belos::SolverFactory<double, MultiVector, Operator> factory;
  auto solver = factory.create(meth, params);

  Teuchos::RCP<const Operator> op = m.A;
  Teuchos::RCP<const Operator> prec = m.prec;
  const size_t nv = b.getNumVectors();
  Teuchos::Array<double> bNorm(nv), rNorm(nv);
  b.norm2(bNorm());
  auto relativeResidual = [&]() {
    MultiVector r(b, Teuchos::Copy);
    m.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
    r.norm2(rNorm());
    double worst = 0.0;
    for (size_t j = 0; j < nv; ++j)
      worst = std::max(worst, bNorm[j] > 0.0 ? rNorm[j] / bNorm[j] : rNorm[j]);
    return worst;
  };
  int iterations = 0;
  double residual = relativeResidual();
  // MINRES monitors the preconditioned residual (docs/theory.md §"Linear solvers"): restart with a
  // tighter tolerance until the true one is below the requested tolerance.
  double tol = options_.tolerance;
  for (int attempt = 0; residual > options_.tolerance && iterations < options_.maxIterations &&
                        attempt < 6;
       ++attempt) {
    auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MultiVector, Operator>(
        op, Teuchos::rcpFromRef(x), Teuchos::rcpFromRef(b)));
    if (meth == "MINRES")
      problem->setLeftPrec(prec);  // MINRES: an SPD preconditioner, applied symmetrically
    else
      problem->setRightPrec(prec);  // GMRES: its residual is the true one
    problem->setProblem();
    params->set("Maximum Iterations", options_.maxIterations - iterations);
    params->set("Convergence Tolerance", tol);
    solver->setParameters(params);
    solver->setProblem(problem);
    solver->solve();
    iterations += solver->getNumIters();
    const double previous = residual;
    residual = relativeResidual();
    if (residual > options_.tolerance)
      tol = std::max(1e-15, tol * 0.5 * options_.tolerance / residual);
    if (!(residual < previous))
      break;  // no progress: report below
  }
  stats_.iterations = iterations;
  stats_.totalIterations += iterations;
  stats_.solveSeconds = maxOverRanks(*m.A->getComm(), timer.stop());
  ++stats_.solves;
  SC_THROW_IF(!(residual <= options_.tolerance), sc::core::ConvergenceError,
              name() << ": no convergence in " << iterations
                     << " iterations: relative residual " << residual
                     << " > Linear Solver/Iterative/Tolerance = " << options_.tolerance
                     << " (Maximum iterations = " << options_.maxIterations
                     << "). Try Linear Solver/Type = MUMPS, or a Stress block of MUMPS or KLU2.");
}

}  // namespace sc::solvers

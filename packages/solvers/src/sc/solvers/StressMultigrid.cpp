// The V-cycle of the stress block (see the header).

#include <sc/solvers/StressMultigrid.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <unordered_map>

#include <Teuchos_LAPACK.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/solvers/DirectSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>
#include <sc/solvers/PatchSmoother.hpp>

namespace sc::solvers {

namespace {

using GO = Map::global_ordinal_type;
using LO = Map::local_ordinal_type;
using Operator = Tpetra::Operator<>;

// One symmetric V-cycle of geometric multigrid for S_σ (docs/theory.md §"Linear solvers"):
// Galerkin coarse operators A_{l−1} = P_lᵀ A_l P_l on the nested hierarchy; on every finer level
// the Chebyshev polynomial of degree `degree` in B_l A_l before and after the coarse correction,
// B_l = Σ_i R_iᵀ A_{l,i}⁻¹ R_i the additive Schwarz smoother on vertex (2D) or edge (3D) patches
// (PatchSmoother), on the interval [λ_max/ratio, λ_max] of B_l A_l; a direct solve on the
// coarsest level. The same polynomial before and after keeps the cycle symmetric (MINRES). Where
// a coarse function was cut by the contact constraints and extended into its coarse element E (the
// contact zone's ends), all fine DOFs of E form one block solved exactly after the pre-smoothing
// and, in reverse order, before the post-smoothing (docs/solvers.md "Contact with the stress
// multigrid").
class StressMultigrid : public Operator {
public:
  struct Level {
    Teuchos::RCP<const CrsMatrix> A, P;  // P: from level l−1 into l
    std::shared_ptr<const PatchSmoother> B;
    // Zone-end blocks: one exact block solve per block, applied one after the other (each a
    // PatchSmoother of at most one block on every rank), after the pre-smoothing and in reverse
    // order before the post-smoothing.
    std::vector<std::shared_ptr<const PatchSmoother>> zoneBlocks;
    int largestZoneBlock = 0;  // DOFs (this rank)
    double lambdaMax = 1.0;    // upper bound of the spectrum of B A (Lanczos/Arnoldi × 1.1)
  };
  std::vector<Level> levels;  // coarsest first
  Teuchos::RCP<DirectSolver> coarse;
  int extendedFunctions = 0;        // coarse functions extended into their element (all levels)
  int degree = 2;                   // Chebyshev degree (smoother applications before and after)
  double ratio = 10.0;              // λ_max / λ_min of the smoothed interval
  mutable bool skipCoarse = false;  // diagnostics: the finest level's smoothing only

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
    blockSweep(L, b, x, true);
    if (skipCoarse && l == static_cast<int>(levels.size()) - 1) {
      blockSweep(L, b, x, false);
      smooth(L, b, x, false);
      return;
    }
    MultiVector r(b, Teuchos::Copy);
    L.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
    MultiVector rc(L.P->getDomainMap(), m, false), ec(L.P->getDomainMap(), m, false);
    L.P->apply(r, rc, Teuchos::TRANS);
    vcycle(l - 1, rc, ec);
    L.P->apply(ec, x, Teuchos::NO_TRANS, 1.0, 1.0);
    blockSweep(L, b, x, false);
    smooth(L, b, x, false);
  }

  // x ← x + R_kᵀ A_k⁻¹ R_k (b − A x) for the zone-end blocks k in turn (reversed: `forward` false).
  void blockSweep(const Level& L, const MultiVector& b, MultiVector& x, bool forward) const
  {
    const int n = static_cast<int>(L.zoneBlocks.size());
    if (n == 0) return;
    MultiVector r(b.getMap(), b.getNumVectors(), false);
    for (int i = 0; i < n; ++i) {
      const int k = forward ? i : n - 1 - i;
      Tpetra::deep_copy(r, b);
      L.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
      L.zoneBlocks[k]->apply(r, x, 1.0, 1.0);
    }
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
    if (!zero) L.A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
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

// The safeguard of both Krylov estimates below: they take at least `steps` steps, then go on by 5
// while the top Ritz value grew by more than this over the last 5, up to 2 × `steps` (a top that
// still rises has not converged; docs/solvers.md "Contact with the stress multigrid").
constexpr double kRitzGrowth = 0.01;

// The top Ritz value of a symmetric tridiagonal matrix (α on the diagonal, β beside it).
double topOfTridiagonal(const std::vector<double>& alpha, const std::vector<double>& beta)
{
  const int n = static_cast<int>(alpha.size());
  std::vector<double> T(static_cast<std::size_t>(n) * n, 0.0), eig(n), work(3 * n + 1);
  for (int i = 0; i < n; ++i) {
    T[static_cast<std::size_t>(i) * n + i] = alpha[i];
    if (i + 1 < n) {
      T[static_cast<std::size_t>(i) * n + i + 1] = beta[i];
      T[static_cast<std::size_t>(i + 1) * n + i] = beta[i];
    }
  }
  int info = 0;
  Teuchos::LAPACK<int, double>().SYEV('N', 'U', n, T.data(), n, eig.data(), work.data(),
                                      static_cast<int>(work.size()), &info);
  SC_THROW_IF(info != 0, sc::core::InternalError,
              "stress multigrid: LAPACK syev failed on the Lanczos matrix (info " << info << ")");
  return eig.back();
}

// λ_max(B A) by at least `steps` Lanczos steps on B A in the A inner product (B A is self-adjoint
// there when A and B are SPD), from a random vector: the largest eigenvalue of the Lanczos matrix,
// a lower bound that converges from below. A power iteration (15 steps of ‖B A v‖/‖v‖) converges
// only like (λ_2/λ_1)^k and missed the top of the spectrum when its eigenvectors are
// local: on the contact systems λ_max(B A) = 3 (2D vertex patches; the top eigenvectors sit on
// the interior DOFs of a few dozen elements) was estimated as 2.33, the Chebyshev polynomial
// (< 1 in modulus only up to 1.1 × its upper end) amplified those modes and the V-cycle was
// indefinite (MINRES broke down: docs/solvers.md "Contact with the stress multigrid").
double largestEigenvalueLanczos(const PatchSmoother& B, const CrsMatrix& A, int steps)
{
  MultiVector v(A.getDomainMap(), 1), Av(A.getRangeMap(), 1), z(A.getDomainMap(), 1),
      Az(A.getRangeMap(), 1), vPrev(A.getDomainMap(), 1, true), AvPrev(A.getRangeMap(), 1, true);
  v.randomize();
  Teuchos::Array<double> d(1);
  A.apply(v, Av);
  v.dot(Av, d());
  if (!(d[0] > 0.0)) return 1.0;
  v.scale(1.0 / std::sqrt(d[0]));
  Av.scale(1.0 / std::sqrt(d[0]));
  std::vector<double> alpha, beta;
  double top = 0.0, topBefore = 0.0;
  for (int k = 0; k < 2 * steps; ++k) {
    B.apply(Av, z, 1.0, 0.0);  // z = B A v
    z.dot(Av, d());            // α = (B A v, v)_A
    alpha.push_back(d[0]);
    A.apply(z, Az);
    const double b = beta.empty() ? 0.0 : beta.back();
    z.update(-alpha.back(), v, -b, vPrev, 1.0);
    Az.update(-alpha.back(), Av, -b, AvPrev, 1.0);
    z.dot(Az, d());
    if ((k + 1) % 5 == 0) {
      topBefore = top;
      top = topOfTridiagonal(alpha, beta);
      if (k + 1 >= steps && !(top > (1.0 + kRitzGrowth) * topBefore)) break;
    }
    if (!(d[0] > 0.0)) break;
    beta.push_back(std::sqrt(d[0]));
    Tpetra::deep_copy(vPrev, v);
    Tpetra::deep_copy(AvPrev, Av);
    Tpetra::deep_copy(v, z);
    Tpetra::deep_copy(Av, Az);
    v.scale(1.0 / beta.back());
    Av.scale(1.0 / beta.back());
  }
  if (beta.size() >= alpha.size()) beta.resize(alpha.size() - 1);
  return topOfTridiagonal(alpha, beta);
}

// The largest modulus of the eigenvalues of the leading n × n block of H (column-major, leading
// dimension ld).
double topOfHessenberg(const std::vector<double>& H, int ld, int n)
{
  std::vector<double> Hn(static_cast<std::size_t>(n) * n), wr(n), wi(n), work(4 * n + 16);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      Hn[static_cast<std::size_t>(j) * n + i] = H[static_cast<std::size_t>(j) * ld + i];
  int info = 0;
  double none = 0.0;
  Teuchos::LAPACK<int, double>().GEEV('N', 'N', n, Hn.data(), n, wr.data(), wi.data(), &none, 1,
                                      &none, 1, work.data(), static_cast<int>(work.size()), &info);
  SC_THROW_IF(info != 0, sc::core::InternalError,
              "stress multigrid: LAPACK geev failed on the Arnoldi matrix (info " << info << ")");
  double top = 0.0;
  for (int i = 0; i < n; ++i)
    top = std::max(top, std::hypot(wr[i], wi[i]));
  return top;
}

// λ_max(B A) for non-symmetric operators (Coulomb slip rows, LU patches), where the Lanczos
// recurrence above does not apply: Arnoldi on B A in the Euclidean inner product from a random
// vector (classical Gram–Schmidt, twice), the largest modulus of the Ritz values, with the same
// steps and safeguard as the Lanczos estimate. The Krylov space is the one Lanczos would build, so
// it reaches a local top of the spectrum as fast. The power iteration (15 steps, ‖B A v‖/‖v‖) used
// before did not: on the middle level of the three-level Coulomb Hertz systems λ_max(B A) =
// 3.62–3.68 was estimated as 2.91–3.61, and at 2.91 the Chebyshev polynomial was 1.18 in modulus
// there (docs/solvers.md "Contact with the stress multigrid"). Memory: up to 2 × `steps` + 1
// vectors of the level, during the set-up.
double largestEigenvalueArnoldi(const PatchSmoother& B, const CrsMatrix& A, int steps)
{
  std::vector<Teuchos::RCP<MultiVector>> V;
  V.push_back(Teuchos::rcp(new MultiVector(A.getDomainMap(), 1)));
  V[0]->randomize();
  Teuchos::Array<double> d(1);
  V[0]->norm2(d());
  if (!(d[0] > 0.0)) return 1.0;
  V[0]->scale(1.0 / d[0]);
  MultiVector w(A.getRangeMap(), 1);
  const int m = 2 * steps;
  std::vector<double> H(static_cast<std::size_t>(m + 1) * m, 0.0);  // column-major (m + 1) × m
  auto h = [&](int i, int j) -> double& { return H[static_cast<std::size_t>(j) * (m + 1) + i]; };
  int n = 0;
  double top = 0.0, topBefore = 0.0;
  for (int j = 0; j < m; ++j) {
    auto z = Teuchos::rcp(new MultiVector(A.getDomainMap(), 1));
    A.apply(*V[j], w);
    B.apply(w, *z, 1.0, 0.0);
    for (int pass = 0; pass < 2; ++pass)
      for (int i = 0; i <= j; ++i) {
        z->dot(*V[i], d());
        h(i, j) += d[0];
        z->update(-d[0], *V[i], 1.0);
      }
    z->norm2(d());
    h(j + 1, j) = d[0];
    n = j + 1;
    if (n % 5 == 0) {
      topBefore = top;
      top = topOfHessenberg(H, m + 1, n);
      if (n >= steps && !(top > (1.0 + kRitzGrowth) * topBefore)) return top;
    }
    if (!(d[0] > 1e-12 * std::abs(h(j, j)))) break;  // an invariant subspace
    z->scale(1.0 / d[0]);
    V.push_back(z);
  }
  return topOfHessenberg(H, m + 1, n);
}

// The coarse space of one level under the fine level's constraints (docs/solvers.md "Contact
// with the stress multigrid"). Fine rows: `masked` (no coarse correction: data, eliminated or
// constraint rows), `contact` (contact coordinates, or coarse functions made of them). Coarse
// functions (columns of P0) are
//   - dropped (zero column) when they touch a masked row that is not a contact row (traction
//     data: cutting those made P rank-deficient on locally refined hierarchies), or when they
//     touch masked contact rows but no open one;
//   - otherwise kept with their masked part cut off;
//   - a kept function that lost a significant part (≥ 5% of its largest coefficient) on the
//     boundary of a coarse element E is extended into E: the fine interior DOFs of E are set to
//     minimise A's energy with the function's values on E's boundary fixed (a local solve with
//     A's block on E's interior). The cut alone leaves the lost flux as a divergence layer one
//     fine element thick along the cut, whose energy grows like H/h (coarse over fine mesh size
//     near the contact zone's ends, which adaptive cycles refine); the extension spreads it over
//     E.
// Coarse rows are contact rows when their function touches one.
struct ConstrainedProlongation {
  Teuchos::RCP<CrsMatrix> P;
  std::vector<char> coarseContact;  // per local row of P's domain map
  int extended = 0;                 // functions extended (global)
  std::vector<char> zoneElements;   // per coarse element of this rank: a function was extended
};

ConstrainedProlongation
constrainProlongation(const CrsMatrix& A, const CrsMatrix& P0, const std::vector<char>& masked,
                      const std::vector<char>& contact,
                      const std::vector<MultigridLevel::CoarseElement>& coarseElements)
{
  const auto& rowMap = P0.getRowMap();
  const auto& colMap = P0.getColMap();
  const auto& domainMap = P0.getDomainMap();
  const LO nRows = static_cast<LO>(P0.getNodeNumRows());
  // a coefficient counts when it is above 1e-8 of its row's largest (curved boundaries leave
  // round-off-sized traces of interior functions on boundary faces)
  auto rowThreshold = [](const typename CrsMatrix::values_host_view_type& v) {
    double m = 0.0;
    for (size_t k = 0; k < v.extent(0); ++k)
      m = std::max(m, std::abs(v(k)));
    return 1e-8 * m;
  };
  // flags per coarse column: 0 a masked non-contact row, 1 a masked contact row, 2 an open
  // contact row, 3 any contact row
  Tpetra::MultiVector<> flagged(colMap, 4, true);
  {
    auto f0 = flagged.getDataNonConst(0), f1 = flagged.getDataNonConst(1),
         f2 = flagged.getDataNonConst(2), f3 = flagged.getDataNonConst(3);
    for (LO i = 0; i < nRows; ++i) {
      if (!masked[i] && !contact[i]) continue;
      typename CrsMatrix::local_inds_host_view_type inds;
      typename CrsMatrix::values_host_view_type v;
      P0.getLocalRowView(i, inds, v);
      const double tiny = rowThreshold(v);
      for (size_t k = 0; k < inds.extent(0); ++k) {
        if (v(k) == 0.0) continue;
        if (masked[i] && !contact[i]) f0[inds(k)] = 1.0;
        if (std::abs(v(k)) > tiny && contact[i]) {
          (masked[i] ? f1 : f2)[inds(k)] = 1.0;
          f3[inds(k)] = 1.0;
        }
      }
    }
  }
  Tpetra::MultiVector<> coarseFlags(domainMap, 4, true);
  const Tpetra::Export<> toDomain(colMap, domainMap);
  coarseFlags.doExport(flagged, toDomain, Tpetra::ADD);
  // largest coefficient of each coarse function, and on open rows: a function that keeps less
  // than 1e-3 of it is dropped (cut functions so small made Galerkin patches indefinite)
  Tpetra::MultiVector<> largest(colMap, 2, true), coarseLargest(domainMap, 2, true);
  {
    auto all = largest.getDataNonConst(0), open = largest.getDataNonConst(1);
    for (LO i = 0; i < nRows; ++i) {
      typename CrsMatrix::local_inds_host_view_type inds;
      typename CrsMatrix::values_host_view_type v;
      P0.getLocalRowView(i, inds, v);
      for (size_t k = 0; k < inds.extent(0); ++k) {
        all[inds(k)] = std::max(all[inds(k)], std::abs(v(k)));
        if (!masked[i]) open[inds(k)] = std::max(open[inds(k)], std::abs(v(k)));
      }
    }
  }
  coarseLargest.doExport(largest, toDomain, Tpetra::ABSMAX);
  Vector keep(domainMap, false);
  ConstrainedProlongation out;
  out.zoneElements.assign(coarseElements.size(), 0);
  std::vector<GO> cutMine;
  {
    const auto c0 = coarseFlags.getData(0), c1 = coarseFlags.getData(1),
               c2 = coarseFlags.getData(2), c3 = coarseFlags.getData(3);
    const auto lAll = coarseLargest.getData(0), lOpen = coarseLargest.getData(1);
    auto kv = keep.getDataNonConst(0);
    out.coarseContact.assign(kv.size(), 0);
    for (LO j = 0; j < static_cast<LO>(kv.size()); ++j) {
      kv[j] =
          c0[j] == 0.0 && (c1[j] == 0.0 || c2[j] != 0.0) && lOpen[j] >= 1e-3 * lAll[j] ? 1.0 : 0.0;
      out.coarseContact[j] = c3[j] != 0.0;
      if (kv[j] != 0.0 && c1[j] != 0.0) cutMine.push_back(domainMap->getGlobalElement(j));
    }
  }
  Vector keepCols(colMap, false);
  keepCols.doImport(keep, Tpetra::Import<>(domainMap, colMap), Tpetra::INSERT);
  const auto kc = keepCols.getData(0);
  // The rows of P: kept columns on open rows; masked rows empty.
  std::vector<std::vector<GO>> cols(nRows);
  std::vector<std::vector<double>> vals(nRows);
  auto addRow = [&](LO target, LO source, double factor) {
    typename CrsMatrix::local_inds_host_view_type inds;
    typename CrsMatrix::values_host_view_type v;
    P0.getLocalRowView(source, inds, v);
    for (size_t k = 0; k < inds.extent(0); ++k)
      if (v(k) != 0.0 && kc[inds(k)] != 0.0) {
        const GO g = colMap->getGlobalElement(inds(k));
        auto at = std::find(cols[target].begin(), cols[target].end(), g);
        if (at == cols[target].end()) {
          cols[target].push_back(g);
          vals[target].push_back(factor * v(k));
        } else {
          vals[target][at - cols[target].begin()] += factor * v(k);
        }
      }
  };
  for (LO i = 0; i < nRows; ++i)
    if (!masked[i]) addRow(i, i, 1.0);
  auto build = [&](std::vector<std::vector<GO>>& cs, std::vector<std::vector<double>>& vs) {
    std::vector<size_t> counts(nRows);
    for (LO i = 0; i < nRows; ++i)
      counts[i] = cs[i].size();
    auto M = Teuchos::rcp(new CrsMatrix(rowMap, Teuchos::ArrayView<const size_t>(counts)));
    for (LO i = 0; i < nRows; ++i)
      if (!cs[i].empty())
        M->insertGlobalValues(rowMap->getGlobalElement(i), Teuchos::ArrayView<const GO>(cs[i]),
                              Teuchos::ArrayView<const double>(vs[i]));
    M->fillComplete(domainMap, P0.getRangeMap());
    return M;
  };
  auto P = build(cols, vals);

  // Extension of the cut functions into their coarse elements.
  const auto& comm = *rowMap->getComm();
  std::vector<double> mineAsDouble(cutMine.begin(), cutMine.end());
  const auto cutAll = sc::core::gatherAllConcatenated(comm, mineAsDouble);
  if (cutAll.empty()) {
    out.P = P;
    return out;
  }
  // overlap maps: the boundary and interior DOFs of this rank's coarse elements
  auto unionMap = [&](bool interior) {
    std::vector<GO> ids;
    for (const auto& c : coarseElements) {
      const auto& v = interior ? c.interior : c.boundary;
      ids.insert(ids.end(), v.begin(), v.end());
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    const auto inv = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    return Teuchos::rcp(new Map(inv, Teuchos::ArrayView<const GO>(ids), 0, rowMap->getComm()));
  };
  const auto boundaryMap = unionMap(false), interiorMap = unionMap(true);
  const Tpetra::Import<> toBoundary(rowMap, boundaryMap), toInterior(rowMap, interiorMap);
  const Tpetra::Export<> fromInterior(interiorMap, rowMap);
  CrsMatrix Aov(interiorMap, 0);
  Aov.doImport(A, Tpetra::Import<>(A.getRowMap(), interiorMap), Tpetra::INSERT);
  Aov.fillComplete(A.getDomainMap(), A.getRangeMap());
  Vector maskedRows(rowMap, true), maskedBoundary(boundaryMap, false);
  {
    auto mv = maskedRows.getDataNonConst(0);
    for (LO i = 0; i < nRows; ++i)
      mv[i] = masked[i] ? 1.0 : 0.0;
  }
  maskedBoundary.doImport(maskedRows, toBoundary, Tpetra::INSERT);
  const auto mb = maskedBoundary.getData(0);
  std::vector<std::vector<GO>> cCols(nRows);
  std::vector<std::vector<double>> cVals(nRows);
  Teuchos::LAPACK<int, double> lapack;
  const int chunk = 32;
  std::vector<GO> droppedGids;
  for (std::size_t begin = 0; begin < cutAll.size(); begin += chunk) {
    const int nc = static_cast<int>(std::min<std::size_t>(chunk, cutAll.size() - begin));
    std::unordered_map<GO, int> column;
    for (int k = 0; k < nc; ++k)
      column[static_cast<GO>(cutAll[begin + k])] = k;
    // Xu: the uncut functions, X: the cut ones (rows of P0 and P), R = A X
    MultiVector Xu(rowMap, nc, true), X(rowMap, nc, true);
    for (int which = 0; which < 2; ++which) {
      const CrsMatrix& M = which == 0 ? P0 : *P;
      MultiVector& Y = which == 0 ? Xu : X;
      for (LO i = 0; i < nRows; ++i) {
        typename CrsMatrix::local_inds_host_view_type inds;
        typename CrsMatrix::values_host_view_type v;
        M.getLocalRowView(i, inds, v);
        for (size_t k = 0; k < inds.extent(0); ++k) {
          const auto at = column.find(M.getColMap()->getGlobalElement(inds(k)));
          if (at != column.end()) Y.replaceLocalValue(i, at->second, v(k));
        }
      }
    }
    Teuchos::Array<double> largest(nc);
    Xu.normInf(largest());
    MultiVector R(A.getRangeMap(), nc, false);
    A.apply(X, R);
    MultiVector XuB(boundaryMap, nc, false), XB(boundaryMap, nc, false),
        Rov(interiorMap, nc, false), Cov(interiorMap, nc, true);
    XuB.doImport(Xu, toBoundary, Tpetra::INSERT);
    XB.doImport(X, toBoundary, Tpetra::INSERT);
    std::vector<int> dependent(nc, 0);
    Rov.doImport(R, toInterior, Tpetra::INSERT);
    const auto& ovCols = *Aov.getColMap();
    std::vector<int> position(ovCols.getNodeNumElements(), -1);
    std::vector<double> dense, rhs;
    std::vector<int> pivots;
    std::vector<Teuchos::ArrayRCP<const double>> xbs(nc), cbs(nc);
    for (int k = 0; k < nc; ++k) {
      xbs[k] = XuB.getData(k);
      cbs[k] = XB.getData(k);
    }
    for (std::size_t ci = 0; ci < coarseElements.size(); ++ci) {
      const auto& c = coarseElements[ci];
      // the functions that lost a significant part on E's boundary
      std::vector<int> home;
      for (int k = 0; k < nc; ++k) {
        const auto& xb = xbs[k];
        bool lost = false;
        for (GO g : c.boundary) {
          const LO b = boundaryMap->getLocalElement(g);
          lost = lost || (mb[b] != 0.0 && std::abs(xb[b]) >= 0.05 * largest[k]);
        }
        if (lost) home.push_back(k);
      }
      const int m = static_cast<int>(c.interior.size());
      if (home.empty() || m == 0) continue;
      out.zoneElements[ci] = 1;
      {
        // The extension depends only on the values on E's boundary: a function whose boundary
        // values are a combination of the others' (two functions of a coarse face that keep the
        // same few open points) would duplicate them; it is dropped (Gram–Schmidt).
        const int nb = static_cast<int>(c.boundary.size());
        std::vector<std::vector<double>> basis;
        std::vector<int> independent;
        for (int k : home) {
          std::vector<double> t(nb);
          double norm0 = 0.0;
          for (int b = 0; b < nb; ++b) {
            t[b] = cbs[k][boundaryMap->getLocalElement(c.boundary[b])];
            norm0 += t[b] * t[b];
          }
          for (const auto& q : basis) {
            double dot = 0.0;
            for (int b = 0; b < nb; ++b)
              dot += q[b] * t[b];
            for (int b = 0; b < nb; ++b)
              t[b] -= dot * q[b];
          }
          double norm = 0.0;
          for (double x : t)
            norm += x * x;
          if (!(norm > 1e-12 * norm0)) {
            dependent[k] = 1;
            continue;
          }
          for (double& x : t)
            x /= std::sqrt(norm);
          basis.push_back(std::move(t));
          independent.push_back(k);
        }
        home = independent;
        if (home.empty()) continue;
      }
      for (int a = 0; a < m; ++a) {
        const LO col = ovCols.getLocalElement(c.interior[a]);
        if (col != Teuchos::OrdinalTraits<LO>::invalid()) position[col] = a;
      }
      dense.assign(static_cast<std::size_t>(m) * m, 0.0);
      for (int a = 0; a < m; ++a) {
        typename CrsMatrix::local_inds_host_view_type inds;
        typename CrsMatrix::values_host_view_type v;
        Aov.getLocalRowView(interiorMap->getLocalElement(c.interior[a]), inds, v);
        for (size_t k = 0; k < inds.extent(0); ++k)
          if (position[inds(k)] >= 0)
            dense[static_cast<std::size_t>(position[inds(k)]) * m + a] = v(k);  // column-major
      }
      for (int a = 0; a < m; ++a) {
        const LO col = ovCols.getLocalElement(c.interior[a]);
        if (col != Teuchos::OrdinalTraits<LO>::invalid()) position[col] = -1;
      }
      const int nh = static_cast<int>(home.size());
      rhs.assign(static_cast<std::size_t>(m) * nh, 0.0);
      for (int h = 0; h < nh; ++h) {
        const auto rv = Rov.getData(home[h]);
        for (int a = 0; a < m; ++a)
          rhs[static_cast<std::size_t>(h) * m + a] =
              -rv[interiorMap->getLocalElement(c.interior[a])];
      }
      pivots.resize(m);
      int info = 0;
      lapack.GETRF(m, m, dense.data(), m, pivots.data(), &info);
      SC_THROW_IF(info != 0, sc::core::ConvergenceError,
                  "stress multigrid: the interior block of a coarse element is singular "
                  "(LAPACK getrf info "
                      << info << ")");
      lapack.GETRS('N', m, nh, dense.data(), m, pivots.data(), rhs.data(), m, &info);
      for (int h = 0; h < nh; ++h) {
        auto cv = Cov.getDataNonConst(home[h]);
        for (int a = 0; a < m; ++a)
          cv[interiorMap->getLocalElement(c.interior[a])] +=
              rhs[static_cast<std::size_t>(h) * m + a];
      }
      out.extended += nh;
    }
    std::vector<int> anyDependent(nc, 0);
    core::sumOverRanks(comm, nc, dependent.data(), anyDependent.data());
    for (int k = 0; k < nc; ++k)
      if (anyDependent[k]) droppedGids.push_back(static_cast<GO>(cutAll[begin + k]));
    MultiVector C(rowMap, nc, true);
    C.doExport(Cov, fromInterior, Tpetra::ADD);
    for (int k = 0; k < nc; ++k) {
      const auto cv = C.getData(k);
      for (LO i = 0; i < nRows; ++i)
        if (cv[i] != 0.0) {
          cCols[i].push_back(static_cast<GO>(cutAll[begin + k]));
          cVals[i].push_back(cv[i]);
        }
    }
  }
  out.extended = core::sumOverRanks(comm, out.extended);
  auto correction = build(cCols, cVals);
  out.P = Tpetra::MatrixMatrix::add(1.0, false, *P, 1.0, false, *correction, domainMap,
                                    P0.getRangeMap());
  if (!droppedGids.empty()) {
    Vector keepAfter(domainMap, false);
    keepAfter.putScalar(1.0);
    for (GO g : droppedGids) {
      const LO j = domainMap->getLocalElement(g);
      if (j != Teuchos::OrdinalTraits<LO>::invalid()) keepAfter.replaceLocalValue(j, 0.0);
    }
    out.P->rightScale(keepAfter);
  }
  return out;
}

// Diagnostics, printed by rank 0 when the environment variable SC_MULTIGRID_DIAGNOSTICS is set
// (docs/solvers.md "Contact with the stress multigrid"): the levels, the constraint rows, λ_max per
// level, the zone-end blocks per level, and for the stationary iteration e ← (I − V S) e from a
// random error, per V-cycle, the error ratio ‖e_k‖/‖e_{k−1}‖, the residual ratio
// ‖S e_k‖/‖S e_{k−1}‖ (2-norms) and the energy ratio (e_kᵀ S e_k / e_{k−1}ᵀ S e_{k−1})^{1/2}
// (a norm when S is symmetric), with the coarse correction and with the finest level's smoothing
// only.
void printDiagnostics(const StressMultigrid& mg, const std::vector<char>& constraintRows)
{
  const CrsMatrix& S = *mg.levels.back().A;
  const int rank = S.getComm()->getRank();
  long long nConstraint = 0;
  for (char c : constraintRows)
    nConstraint += c != 0;
  nConstraint = core::sumOverRanks(*S.getComm(), nConstraint);
  std::ostringstream os;
  os << "multigrid diagnostics: " << mg.levels.size() << " levels, " << S.getGlobalNumRows()
     << " rows (" << nConstraint << " constraint rows), extended " << mg.extendedFunctions
     << ", lambda_max per level:";
  for (std::size_t l = 1; l < mg.levels.size(); ++l)
    os << " " << mg.levels[l].lambdaMax;
  os << ", zone blocks per level:";
  for (std::size_t l = 1; l < mg.levels.size(); ++l)
    os << " " << mg.levels[l].zoneBlocks.size() << " (largest " << mg.levels[l].largestZoneBlock
       << ")";
  os << "\n";
  for (int coarse = 1; coarse >= 0; --coarse) {
    mg.skipCoarse = coarse == 0;
    MultiVector e(S.getDomainMap(), 1), r(S.getRangeMap(), 1), z(S.getDomainMap(), 1);
    e.randomize();
    Teuchos::Array<double> n0(1), n1(1), rn0(1), rn1(1);
    os << "  " << (coarse ? "V-cycle" : "smoother only")
       << ": per cycle, error ratio;residual ratio;energy ratio:";
    Teuchos::Array<double> en0(1), en1(1);
    for (int k = 0; k < 12; ++k) {
      e.norm2(n0());
      S.apply(e, r);
      r.norm2(rn0());
      e.dot(r, en0());
      mg.apply(r, z);
      e.update(-1.0, z, 1.0);
      e.norm2(n1());
      S.apply(e, r);
      r.norm2(rn1());
      e.dot(r, en1());
      os << " " << std::setprecision(3) << n1[0] / n0[0] << ";" << rn1[0] / rn0[0] << ";"
         << std::sqrt(std::abs(en1[0] / en0[0]));
    }
    os << "\n";
  }
  mg.skipCoarse = false;
  if (rank == 0) std::cout << os.str() << std::flush;
}

}  // namespace

Teuchos::RCP<Operator> buildStressMultigrid(const BlockStructure& blocks,
                                            const Teuchos::RCP<CrsMatrix>& S,
                                            const std::vector<char>& constraintRows, bool symmetric,
                                            const IterativeOptions& options,
                                            const Teuchos::ParameterList& directList,
                                            const Teuchos::RCP<const CrsMatrix>& stressBasis)
{
  const auto& levels = blocks.multigrid;
  const int L = static_cast<int>(levels.size());
  SC_THROW_IF(L < 1, sc::core::InputError,
              "Linear Solver/Iterative/Stress block = Multigrid needs the nested mesh hierarchy "
              "(solvers::BlockStructure::multigrid, e.g. from sc::solvers::StressHierarchy); "
              "none was given. Use a Stress block of MUMPS or KLU2.");
  auto mg = Teuchos::rcp(new StressMultigrid());
  mg->degree =
      options.smootherDegree > 0 ? options.smootherDegree : (blocks.dimension == 2 ? 2 : 3);
  mg->ratio = options.smootherRatio;
  mg->levels.resize(L);
  mg->levels[L - 1].A = S;
  std::vector<char> contact;  // per row of the level being coarsened: a contact coordinate's
  // per level: the fine DOFs (interior and boundary) of each coarse element of this rank into
  // which a cut function was extended (the contact zone's ends), smoothed as one block each
  std::vector<std::vector<std::vector<long long>>> zoneBlocks(L);
  for (int l = L - 1; l >= 1; --l) {
    SC_THROW_IF(levels[l].prolongation.is_null(), sc::core::InternalError,
                "stress multigrid: level " << l << " has no prolongation");
    auto P = Teuchos::rcp(new CrsMatrix(*levels[l].prolongation, Teuchos::Copy));
    if (l == L - 1 && !stressBasis.is_null()) {
      // the finest unknowns are stressBasis × the σ DOFs (contact faces in constraint coordinates)
      auto TP = Teuchos::rcp(new CrsMatrix(stressBasis->getRowMap(), 0));
      Tpetra::MatrixMatrix::Multiply(*stressBasis, false, *P, false, *TP);
      P = TP;
    }
    const auto& A = *mg->levels[l].A;
    // Rows with only a diagonal (fixed by traction data on the finest level; decoupled rows of
    // a coarser one) and, on the finest level, the constraint rows take no coarse correction.
    std::vector<char> masked(P->getNodeNumRows(), 0);
    {
      const auto& rows = *A.getRowMap();
      const auto& cols = *A.getColMap();
      for (LO i = 0; i < static_cast<LO>(masked.size()); ++i) {
        const GO g = P->getRowMap()->getGlobalElement(i);
        typename CrsMatrix::local_inds_host_view_type inds;
        typename CrsMatrix::values_host_view_type v;
        A.getLocalRowView(rows.getLocalElement(g), inds, v);
        bool offDiagonal = false;
        for (size_t k = 0; k < inds.extent(0) && !offDiagonal; ++k)
          offDiagonal = v(k) != 0.0 && cols.getGlobalElement(inds(k)) != g;
        const bool constraint = l == L - 1 && constraintRows[rows.getLocalElement(g)];
        masked[i] = offDiagonal && !constraint ? 0 : 1;
      }
    }
    if (l == L - 1) {
      // Contact coordinates: rows of stressBasis other than the identity.
      contact.assign(masked.size(), 0);
      if (!stressBasis.is_null()) {
        const auto& bRows = *stressBasis->getRowMap();
        const auto& bCols = *stressBasis->getColMap();
        for (LO i = 0; i < static_cast<LO>(masked.size()); ++i) {
          const GO g = P->getRowMap()->getGlobalElement(i);
          typename CrsMatrix::local_inds_host_view_type inds;
          typename CrsMatrix::values_host_view_type v;
          stressBasis->getLocalRowView(bRows.getLocalElement(g), inds, v);
          contact[i] =
              !(inds.extent(0) == 1 && bCols.getGlobalElement(inds(0)) == g && v(0) == 1.0);
        }
      }
    }
    auto cp = constrainProlongation(A, *P, masked, contact, levels[l].coarseElements);
    P = cp.P;
    contact = std::move(cp.coarseContact);
    for (std::size_t ci = 0; ci < cp.zoneElements.size(); ++ci)
      if (cp.zoneElements[ci]) {
        const auto& c = levels[l].coarseElements[ci];
        std::vector<long long> ids(c.interior.begin(), c.interior.end());
        ids.insert(ids.end(), c.boundary.begin(), c.boundary.end());
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        zoneBlocks[l].push_back(std::move(ids));
      }
    mg->extendedFunctions += cp.extended;
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
        if (dv[i] == 0.0) dead.push_back(i);
      const long long anyDead =
          core::sumOverRanks(*Ac->getComm(), static_cast<long long>(dead.size()));
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
    // λ_max from below (Lanczos on symmetric, Arnoldi on non-symmetric systems, at least 15
    // steps); the Chebyshev polynomial grows outside its interval, so the bound is raised by 10%
    // (Ifpack2's default boost factor).
    lev.lambdaMax = 1.1 * (symmetric ? largestEigenvalueLanczos(*lev.B, *lev.A, 15)
                                     : largestEigenvalueArnoldi(*lev.B, *lev.A, 15));
    const auto& mine = zoneBlocks[l];
    const int n = core::maxOverRanks(*lev.A->getComm(), static_cast<int>(mine.size()));
    for (int k = 0; k < n; ++k) {
      std::vector<std::vector<long long>> one;
      if (k < static_cast<int>(mine.size())) {
        one.push_back(mine[k]);
        lev.largestZoneBlock = std::max(lev.largestZoneBlock, static_cast<int>(mine[k].size()));
      }
      lev.zoneBlocks.push_back(std::make_shared<PatchSmoother>(*lev.A, one, false));
    }
  }
  mg->coarse = createDirectSolverFromValidated(directList);
  mg->coarse->setOperator(mg->levels[0].A, symmetric);
  mg->coarse->numericFactorization();
  if (L > 1 && std::getenv("SC_MULTIGRID_DIAGNOSTICS") != nullptr)
    printDiagnostics(*mg, constraintRows);
  return mg;
}

}  // namespace sc::solvers

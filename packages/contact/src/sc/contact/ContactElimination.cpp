// The contact Newton systems for a Krylov solver (docs/solvers.md "Contact with the stress
// multigrid"): the rows of ActiveSetSolver::modifiedMatrix, written in the coordinates of the
// constraints instead of the RT face DOFs, so that the free points' rows and columns are
// eliminated symmetrically.
//
// On a contact face with DOF points q (scales s_q) and constraint coefficients p (V: points ×
// coefficients), the coordinates y_{p,r} = frame_r · τ_p, τ_{p,i} = Σ_q V⁻¹(p,q) s_q x_{q,i},
// replace the face's DOFs x_{q,i} (in the slot of DOF (p, r), as the replaced rows of
// modifiedMatrix): x = Q y with Q_{(q,i),(p,r)} = V(q,p)/s_q frame_r[i], T = Q⁻¹, the identity off
// the contact faces. Then the dual quantities are rows of Qᵀ(K x − b) (ρ_p = Vᵀ S⁻¹ (K x − b)), so
// that
//   - a dual row α·ρ_p = γ with α = frame_r is the Galerkin row (p, r) of G = Qᵀ K Q with
//     right-hand side (Qᵀ b)_{(p,r)} + γ;
//   - a traction row β·τ_p = γ with β = c frame_r fixes y_{(p,r)} = γ/c: eliminated with its
//     column (moved to the right-hand side), its diagonal kept;
//   - any other row (Coulomb slip y_T + μ ξ y_N = 0, the 3D Hüeber–Stadler–Wohlmuth rows) is
//     written as it is: Σ_r' (α·frame_r') G_{(p,r')} + Σ_r' (β·frame_r') e_{(p,r')}.
// Free points (σ_N = σ_T = 0), frictionless contact (r_N = G, σ_T = 0), stick (r_N = G, r_T =
// r_T^{n−1}) and Tresca slip (σ_T = s ξ) give only the first two kinds: the system is symmetric
// (MINRES). The solution is the same as modifiedMatrix's (the same equations in another basis).

#include "sc/contact/ActiveSetSolver.hpp"

#include <algorithm>
#include <cmath>

#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>

namespace sc::contact {

namespace {
using LO = Tpetra::CrsMatrix<>::local_ordinal_type;
using GO = Tpetra::CrsMatrix<>::global_ordinal_type;

// c·frame_r for r < d (the frame is orthonormal: n, t1[, t2]).
std::array<double, 3> inFrame(const std::array<double, 3>& v, const ContactPoint& p, int d)
{
  const std::array<const std::array<double, 3>*, 3> frame = {&p.n, &p.t1, &p.t2};
  std::array<double, 3> c{0, 0, 0};
  for (int r = 0; r < d; ++r)
    c[r] = v[0] * (*frame[r])[0] + v[1] * (*frame[r])[1] + v[2] * (*frame[r])[2];
  return c;
}
}  // namespace

ActiveSetSolver::Elimination ActiveSetSolver::eliminationBasis(const CrsMatrix& K,
                                                               const MultiVector& b) const
{
  const int d = space_.dim();
  const auto rowMap = K.getRowMap();
  const LO n = static_cast<LO>(rowMap->getNodeNumElements());
  // Per owned row: the entries of Q and of T (the identity off the contact faces).
  std::vector<std::vector<GO>> qCols(n), tCols(n);
  std::vector<std::vector<double>> qVals(n), tVals(n);
  std::vector<char> onFace(n, 0);
  for (const auto& p : points_) {
    const ContactFace& cf = faces_[p.block];
    const int m = cf.m, pp = p.index;
    const std::array<const std::array<double, 3>*, 3> frame = {&p.n, &p.t1, &p.t2};
    for (int r = 0; r < d; ++r) {
      const LO row = rowMap->getLocalElement(cf.gids[pp][r]);
      SC_THROW_IF(row == Teuchos::OrdinalTraits<LO>::invalid(), core::InternalError,
                  "contact elimination: a contact DOF is not owned by the face's rank");
      onFace[row] = 1;
      // T row (p, r): y_{p,r} = Σ_{q,i} frame_r[i] V⁻¹(p,q) s_q x_{q,i}
      for (int q = 0; q < m; ++q)
        for (int i = 0; i < d; ++i) {
          const double v = (*frame[r])[i] * cf.Vinv[pp * m + q] * cf.scale[q];
          if (v != 0.0) {
            tCols[row].push_back(cf.gids[q][i]);
            tVals[row].push_back(v);
          }
        }
    }
    // Q rows (q, i) get column (p, r): V(q,p)/s_q frame_r[i]
    for (int q = 0; q < m; ++q)
      for (int i = 0; i < d; ++i) {
        const LO row = rowMap->getLocalElement(cf.gids[q][i]);
        for (int r = 0; r < d; ++r) {
          const double v = cf.V[q * m + pp] / cf.scale[q] * (*frame[r])[i];
          if (v != 0.0) {
            qCols[row].push_back(cf.gids[pp][r]);
            qVals[row].push_back(v);
          }
        }
      }
  }
  auto build = [&](std::vector<std::vector<GO>>& cols, std::vector<std::vector<double>>& vals) {
    std::vector<size_t> counts(n);
    for (LO i = 0; i < n; ++i) {
      if (!onFace[i]) {
        cols[i] = {rowMap->getGlobalElement(i)};
        vals[i] = {1.0};
      }
      counts[i] = cols[i].size();
    }
    auto M = Teuchos::rcp(new CrsMatrix(rowMap, Teuchos::ArrayView<const size_t>(counts)));
    for (LO i = 0; i < n; ++i)
      M->insertGlobalValues(rowMap->getGlobalElement(i), Teuchos::ArrayView<const GO>(cols[i]),
                            Teuchos::ArrayView<const double>(vals[i]));
    M->fillComplete(K.getDomainMap(), K.getRangeMap());
    return M;
  };
  Elimination e;
  e.Q = build(qCols, qVals);
  e.T = build(tCols, tVals);
  auto QtK = Teuchos::rcp(new CrsMatrix(rowMap, 0));
  Tpetra::MatrixMatrix::Multiply(*e.Q, true, K, false, *QtK);
  auto G = Teuchos::rcp(new CrsMatrix(rowMap, 0));
  Tpetra::MatrixMatrix::Multiply(*QtK, false, *e.Q, false, *G);
  // The rows (p, 0..d−1) of one point get one pattern, the union of theirs (explicit zeros): a
  // mixed row (Coulomb slip, the 3D Hüeber–Stadler–Wohlmuth rows) combines them and has entries
  // in the point's own coordinates. With a frame along the axes these rows are K's rows of single
  // components, whose patterns differed in 3D (docs/solvers.md "Contact with the stress
  // multigrid", 3D).
  {
    const auto& colMap = *G->getColMap();
    std::vector<std::vector<GO>> cols(n);
    std::vector<std::vector<double>> vals(n);
    for (LO i = 0; i < n; ++i) {
      CrsMatrix::local_inds_host_view_type inds;
      CrsMatrix::values_host_view_type v;
      G->getLocalRowView(i, inds, v);
      for (size_t k = 0; k < inds.extent(0); ++k) {
        cols[i].push_back(colMap.getGlobalElement(inds(k)));
        vals[i].push_back(v(k));
      }
    }
    for (const auto& p : points_) {
      const ContactFace& cf = faces_[p.block];
      std::vector<GO> all;
      for (int r = 0; r < d; ++r) {
        const auto& c = cols[rowMap->getLocalElement(cf.gids[p.index][r])];
        all.insert(all.end(), c.begin(), c.end());
      }
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      for (int r = 0; r < d; ++r) {
        const LO row = rowMap->getLocalElement(cf.gids[p.index][r]);
        std::vector<GO> c = cols[row];
        std::sort(c.begin(), c.end());
        for (GO g : all)
          if (!std::binary_search(c.begin(), c.end(), g)) {
            cols[row].push_back(g);
            vals[row].push_back(0.0);
          }
      }
    }
    std::vector<size_t> counts(n);
    for (LO i = 0; i < n; ++i)
      counts[i] = cols[i].size();
    e.G = Teuchos::rcp(new CrsMatrix(rowMap, Teuchos::ArrayView<const size_t>(counts)));
    for (LO i = 0; i < n; ++i)
      e.G->insertGlobalValues(rowMap->getGlobalElement(i), Teuchos::ArrayView<const GO>(cols[i]),
                              Teuchos::ArrayView<const double>(vals[i]));
    e.G->fillComplete(K.getDomainMap(), K.getRangeMap());
  }
  e.Qb = Teuchos::rcp(new MultiVector(b.getMap(), 1));
  e.Q->apply(b, *e.Qb, Teuchos::TRANS);
  return e;
}

bool ActiveSetSolver::eliminatedMatrix(const Elimination& e, Teuchos::RCP<CrsMatrix>& A,
                                       MultiVector& rhs) const
{
  const int d = space_.dim();
  const CrsMatrix& G = *e.G;
  A = Teuchos::rcp(new CrsMatrix(G, Teuchos::Copy));
  const auto& rowMap = *G.getRowMap();
  const auto& colMap = *G.getColMap();
  rhs.assign(*e.Qb);
  Tpetra::Vector<> fixed(G.getRowMap(), true), keep(G.getRowMap(), false);
  keep.putScalar(1.0);
  Tpetra::Vector<> diagonal(G.getRowMap(), false);
  G.getLocalDiagCopy(diagonal);
  auto fv = fixed.getDataNonConst(0);
  auto kv = keep.getDataNonConst(0);
  auto rv = rhs.getDataNonConst(0);
  const auto qb = e.Qb->getData(0);
  int mixed = 0;
  A->resumeFill();
  for (const auto& p : points_) {
    const ContactFace& cf = faces_[p.block];
    const auto rows = constraintRows(p);
    for (int r = 0; r < d; ++r) {
      const auto ca = inFrame(rows[r].alpha, p, d), cb = inFrame(rows[r].beta, p, d);
      const LO slot = rowMap.getLocalElement(cf.gids[p.index][r]);
      auto only = [&](const std::array<double, 3>& c) {
        for (int s = 0; s < d; ++s)
          if (s != r && std::abs(c[s]) > 1e-12 * std::abs(c[r])) return false;
        return c[r] != 0.0;
      };
      const bool noA = ca[0] == 0.0 && ca[1] == 0.0 && ca[2] == 0.0;
      const bool noB = cb[0] == 0.0 && cb[1] == 0.0 && cb[2] == 0.0;
      if (noB && only(ca)) {
        // Galerkin row (p, r) scaled by ca[r]: its right-hand side (Qᵀ b) + γ / ca[r]
        rv[slot] = qb[slot] + rows[r].gamma / ca[r];
      } else if (noA && only(cb)) {
        fv[slot] = rows[r].gamma / cb[r];
        kv[slot] = 0.0;
      } else {
        ++mixed;
        CrsMatrix::local_inds_host_view_type pattern;
        CrsMatrix::values_host_view_type unused;
        G.getLocalRowView(slot, pattern, unused);
        std::vector<double> vals(pattern.extent(0), 0.0);
        auto add = [&](LO col, double v) {
          const LO* at = std::find(pattern.data(), pattern.data() + pattern.extent(0), col);
          SC_THROW_IF(at == pattern.data() + pattern.extent(0), core::InternalError,
                      "contact elimination: a face coordinate is not in its row");
          vals[at - pattern.data()] += v;
        };
        double rhsValue = rows[r].gamma;
        for (int s = 0; s < d; ++s) {
          const LO other = rowMap.getLocalElement(cf.gids[p.index][s]);
          if (ca[s] != 0.0) {
            CrsMatrix::local_inds_host_view_type inds;
            CrsMatrix::values_host_view_type v;
            G.getLocalRowView(other, inds, v);
            for (size_t k = 0; k < inds.extent(0); ++k)
              add(inds(k), ca[s] * v(k));
            rhsValue += ca[s] * qb[other];
          }
          if (cb[s] != 0.0) add(colMap.getLocalElement(cf.gids[p.index][s]), cb[s]);
        }
        A->replaceLocalValues(slot, Teuchos::ArrayView<const LO>(pattern.data(), pattern.extent(0)),
                              Teuchos::ArrayView<const double>(vals));
        rv[slot] = rhsValue;
      }
    }
  }
  A->fillComplete(G.getDomainMap(), G.getRangeMap());
  // Fixed coordinates: their columns go to the right-hand side, their rows become the diagonal
  // of G (the scale of the row they replace).
  MultiVector Af(rhs.getMap(), 1);
  A->apply(fixed, Af);
  rhs.update(-1.0, Af, 1.0);
  A->leftScale(keep);
  A->rightScale(keep);
  A->resumeFill();
  const auto dv = diagonal.getData(0);
  rv = rhs.getDataNonConst(0);
  kv = keep.getDataNonConst(0);
  fv = fixed.getDataNonConst(0);
  for (LO i = 0; i < static_cast<LO>(kv.size()); ++i)
    if (kv[i] == 0.0) {
      const GO g = rowMap.getGlobalElement(i);
      const LO c = colMap.getLocalElement(g);
      const double diag = std::abs(dv[i]) > 0.0 ? std::abs(dv[i]) : 1.0;
      SC_THROW_IF(A->replaceLocalValues(i, Teuchos::ArrayView<const LO>(&c, 1),
                                        Teuchos::ArrayView<const double>(&diag, 1)) != 1,
                  core::InternalError, "contact elimination: no diagonal entry in row " << g);
      rv[i] = diag * fv[i];
    }
  A->fillComplete(G.getDomainMap(), G.getRangeMap());
  return core::maxOverRanks(*comm_, mixed) == 0;
}

}  // namespace sc::contact

// The V-cycle of the stress block (see the header).

#include <sc/solvers/StressMultigrid.hpp>

#include <memory>

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
  mg->degree = options.smootherDegree > 0 ? options.smootherDegree : (blocks.dimension == 2 ? 2 : 3);
  mg->ratio = options.smootherRatio;
  mg->levels.resize(L);
  mg->levels[L - 1].A = S;
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
      // Contact coordinates (rows of stressBasis other than the identity) are cut off instead:
      // their coarse functions keep the rest of their image. Dropping them left the coarse
      // space without normal traction anywhere near the contact zone (the load path of the
      // contact force), and MINRES took 200-360 iterations on Hertz 2D instead of ~50.
      std::vector<char> cutOnly(mv.size(), 0);
      if (l == L - 1 && !stressBasis.is_null()) {
        const auto& bRows = *stressBasis->getRowMap();
        const auto& bCols = *stressBasis->getColMap();
        for (LO i = 0; i < static_cast<LO>(mv.size()); ++i) {
          const GO g = P->getRangeMap()->getGlobalElement(i);
          typename CrsMatrix::local_inds_host_view_type inds;
          typename CrsMatrix::values_host_view_type v;
          stressBasis->getLocalRowView(bRows.getLocalElement(g), inds, v);
          cutOnly[i] = !(inds.extent(0) == 1 && bCols.getGlobalElement(inds(0)) == g && v(0) == 1.0);
        }
      }
      // flags per coarse column: 0 touches a masked row that is not a contact coordinate,
      // 1 a masked contact coordinate, 2 an open (unmasked) contact coordinate
      Tpetra::MultiVector<> flagged(P->getColMap(), 3, true);
      {
        auto f0 = flagged.getDataNonConst(0), f1 = flagged.getDataNonConst(1),
             f2 = flagged.getDataNonConst(2);
        for (LO i = 0; i < static_cast<LO>(mv.size()); ++i) {
          if (mv[i] != 0.0 && !cutOnly[i])
            continue;
          auto& f = !cutOnly[i] ? f0 : mv[i] == 0.0 ? f1 : f2;
          typename CrsMatrix::local_inds_host_view_type inds;
          typename CrsMatrix::values_host_view_type v;
          P->getLocalRowView(i, inds, v);
          for (size_t k = 0; k < inds.extent(0); ++k)
            if (v(k) != 0.0)
              f[inds(k)] = 1.0;
        }
      }
      Tpetra::MultiVector<> coarseFlags(P->getDomainMap(), 3, true);
      coarseFlags.doExport(flagged, Tpetra::Export<>(P->getColMap(), P->getDomainMap()),
                           Tpetra::ADD);
      Vector coarseFlag(P->getDomainMap(), false);
      {
        const auto c0 = coarseFlags.getData(0), c1 = coarseFlags.getData(1),
                   c2 = coarseFlags.getData(2);
        auto cv = coarseFlag.getDataNonConst(0);
        // kept: no masked data row, and where a contact coordinate is masked, some open one
        for (LO j = 0; j < static_cast<LO>(cv.size()); ++j)
          cv[j] = c0[j] == 0.0 && (c1[j] == 0.0 || c2[j] != 0.0) ? 1.0 : 0.0;
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
    // 15 power steps underestimate λ_max; the Chebyshev polynomial grows outside its interval,
    // so the bound is raised by 10% (Ifpack2's default boost factor).
    lev.lambdaMax = 1.1 * largestEigenvalue(*lev.B, *lev.A, 15);
  }
  mg->coarse = createDirectSolverFromValidated(directList);
  mg->coarse->setOperator(mg->levels[0].A, symmetric);
  mg->coarse->numericFactorization();
  return mg;
}

}  // namespace sc::solvers

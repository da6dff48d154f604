// Belos MINRES/GMRES with the block-diagonal preconditioner of docs/theory.md §"Linear solvers"
// (see the header): the Krylov driver and the preconditioner's assembly from the field blocks
// (BlockExtraction.hpp); the stress-block multigrid is StressMultigrid.hpp. The Belos and MueLu
// templates stay in this translation unit (compile time).

#include <sc/solvers/IterativeSolver.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory_Tpetra.hpp>
#include <BelosTpetraAdapter.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_Time.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/solvers/BlockExtraction.hpp>
#include <sc/solvers/DirectSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>
#include <sc/solvers/StressMultigrid.hpp>

namespace sc::solvers {

namespace {

using GO = Map::global_ordinal_type;
using LO = Map::local_ordinal_type;
using Operator = Tpetra::Operator<>;

}  // namespace

// diag(S_σ⁻¹, (2μM_u)⁻¹, diag(2μM_θ)⁻¹) in the working (scaled) system, as one Tpetra operator.
class BlockDiagonalPreconditioner : public Operator {
public:
  Teuchos::RCP<const Map> map, stressMap, displacementMap;
  std::vector<LO> stressLids, displacementLids, rotationLids;
  std::vector<double> rotationInverseDiagonal;
  Teuchos::RCP<CrsMatrix> displacementInverse;
  Teuchos::RCP<DirectSolver> stressDirect;  // exact S_σ⁻¹
  Teuchos::RCP<Operator> stressMultigrid;   // or one AMG / geometric multigrid V-cycle

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
              "Linear Solver/Iterative/Method = \""
                  << options_.method << "\" is not available; valid: Auto, MINRES, GMRES");
  const auto& s = stressBlockSolvers();
  SC_THROW_IF(std::find(s.begin(), s.end(), options_.stressBlock) == s.end(), sc::core::InputError,
              "Linear Solver/Iterative/Stress block = \""
                  << options_.stressBlock
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
  if (options_.method != "Auto") return options_.method;
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
              "iterative solver: the operator has "
                  << A->getGlobalNumRows() << " rows, the block structure " << blocks.end(2));
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
    SC_THROW_IF(
        !blocks.fieldMass->getRowMap()->isSameAs(*map), sc::core::InternalError,
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
    core::sumOverRanks(*map->getComm(), 2, sums, global);
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
      prec->stressDirect = createDirectSolverFromValidated(dl);
    }
    m.prec = prec;
    m.massUsed = blocks.fieldMass;
    m.scalingUsed = scaling();
  }
  auto& prec = *m.prec;
  // The previous step's S_σ and its multigrid or MueLu hierarchy are not used by the new build:
  // release them first, so that a rebuild does not hold two hierarchies at once (at 2·10⁶ 3D
  // DOFs that was ~10% above the first build's peak, docs/solvers.md "3D contact at 2·10⁶ DOFs").
  if (prec.stressDirect.is_null()) {
    prec.stressMultigrid = Teuchos::null;
    m.stressOfOperator = Teuchos::null;
  }

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
    Teuchos::RCP<const CrsMatrix> basis;
    if (!blocks.stressBasis.is_null())
      basis = extractBlock(*blocks.stressBasis, prec.stressMap, blocks.begin(0), blocks.end(0),
                           prec.stressMap);
    prec.stressMultigrid = buildStressMultigrid(blocks, m.stressOfOperator, constraintRows,
                                                symmetric, options_, dl, basis);
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
  stats_.preconditionerSeconds = core::maxOverRanks(*map->getComm(), timer.stop());
  ++stats_.preconditionerSetups;
}

bool IterativeSolver::applyPreconditioner(const MultiVector& r, MultiVector& z) const
{
  if (impl_->prec.is_null()) return false;
  impl_->prec->apply(r, z);
  return true;
}

KrylovOutcome solveKrylov(const std::string& method, const Teuchos::RCP<const Operator>& A,
                          const Teuchos::RCP<const Operator>& prec, const MultiVector& b,
                          MultiVector& x, const IterativeOptions& options, const std::string& name)
{
  auto params = Teuchos::rcp(new Teuchos::ParameterList());
  if (options.outputFrequency > 0) {
    params->set("Verbosity",
                static_cast<int>(Belos::Errors + Belos::Warnings + Belos::StatusTestDetails));
    params->set("Output Frequency", options.outputFrequency);
    params->set("Output Style", static_cast<int>(Belos::Brief));
  } else {
    params->set("Verbosity", static_cast<int>(Belos::Errors));
  }
  // GMRES is flexible (FGMRES, Belos's block GMRES): it keeps the preconditioned vectors, so the
  // solution it forms is the one its residual recurrence describes even under a preconditioner
  // that is not one linear operator to working precision (docs/solvers.md "Iterative solver").
  if (method == "GMRES") {
    params->set("Num Blocks", options.restart);
    params->set("Maximum Restarts", options.maxIterations / std::max(1, options.restart) + 1);
    params->set("Flexible Gmres", true);
  }
  Belos::SolverFactory<double, MultiVector, Operator> factory;
  auto solver = factory.create(method == "GMRES" ? "BLOCK GMRES" : method, params);

  const size_t nv = b.getNumVectors();
  Teuchos::Array<double> bNorm(nv), rNorm(nv);
  b.norm2(bNorm());
  // The criterion: the true relative residual ‖b − A x‖/‖b‖ (the worst column).
  auto relativeResidual = [&]() {
    MultiVector r(b, Teuchos::Copy);
    A->apply(x, r, Teuchos::NO_TRANS, -1.0, 1.0);
    r.norm2(rNorm());
    double worst = 0.0;
    for (size_t j = 0; j < nv; ++j) {
      const double rel = bNorm[j] > 0.0 ? rNorm[j] / bNorm[j] : rNorm[j];
      worst = std::isfinite(rel) ? std::max(worst, rel) : std::numeric_limits<double>::infinity();
    }
    return worst;
  };
  KrylovOutcome out;
  out.residual = relativeResidual();
  // Belos measures its own residual relative to its initial one (MINRES: the preconditioned
  // residual; GMRES with the right preconditioner: the true one, up to rounding). Each attempt
  // asks it for the reduction `target / residual` that would bring the true relative residual to
  // `target`: from a nearly converged initial guess (a Newton step whose state barely changed)
  // that is a small reduction, not the full Tolerance again (which asked for 1e-16 and ran into
  // the iteration limit, docs/solvers.md). After each attempt the true residual is checked; above
  // Tolerance the next attempt starts from the current x with a tighter target (at most 6).
  double target = options.tolerance;
  for (int attempt = 0;
       out.residual > options.tolerance && out.iterations < options.maxIterations && attempt < 6;
       ++attempt) {
    auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MultiVector, Operator>(
        A, Teuchos::rcpFromRef(x), Teuchos::rcpFromRef(b)));
    if (method == "MINRES")
      problem->setLeftPrec(prec);  // MINRES: an SPD preconditioner, applied symmetrically
    else
      problem->setRightPrec(prec);  // GMRES: its residual is the true one
    problem->setProblem();
    params->set("Maximum Iterations", options.maxIterations - out.iterations);
    params->set("Convergence Tolerance", std::clamp(target / out.residual, 1e-15, 0.5));
    solver->setParameters(params);
    solver->setProblem(problem);
    try {
      solver->solve();  // its verdict is not taken: the true residual is checked below
    } catch (const std::exception& e) {
      // Belos throws when its iteration breaks down (MINRES: an indefinite preconditioner or
      // operator, seen with the stress multigrid on adaptive contact meshes, docs/solvers.md):
      // a convergence error naming the solver and the remedy, not an anonymous exception
      SC_THROW_IF(true, sc::core::ConvergenceError,
                  name << ": the Krylov iteration broke down in attempt " << attempt + 1
                       << " (after " << out.iterations << " iterations of the attempts before; "
                       << e.what()
                       << "). Try Linear Solver/Type = MUMPS, or a Stress block of MUMPS or KLU2.");
    }
    out.iterations += solver->getNumIters();
    out.ownResidual = solver->achievedTol();
    const double previous = out.residual;
    out.residual = relativeResidual();
    if (out.residual > options.tolerance)
      target = std::max(1e-15, target * 0.5 * options.tolerance / out.residual);
    if (!(out.residual < previous)) break;  // no progress: report below
  }
  // Never a solution accepted on Belos's word: also when Belos's own stopping test passed while
  // the true residual did not (its residual recurrence drifted from b − A x, "loss of accuracy",
  // e.g. under a preconditioner that is singular or not one fixed linear operator to working
  // precision).
  SC_THROW_IF(!(out.residual <= options.tolerance), sc::core::ConvergenceError,
              name << ": no convergence in " << out.iterations
                   << " iterations: true relative residual ‖b − A x‖/‖b‖ = " << out.residual
                   << " > Linear Solver/Iterative/Tolerance = " << options.tolerance
                   << " (Maximum iterations = " << options.maxIterations
                   << "); Belos's own residual " << out.ownResidual
                   << " relative to its initial one. Try Linear Solver/Type = MUMPS, or a Stress "
                      "block of MUMPS or KLU2.");
  return out;
}

void IterativeSolver::solveOperator(const MultiVector& b, MultiVector& x)
{
  Impl& m = *impl_;
  Teuchos::Time timer("solve");
  timer.start(true);
  KrylovOutcome outcome;
  try {
    outcome = solveKrylov(method(), m.A, m.prec, b, x, options_, name());
  } catch (const sc::core::ConvergenceError&) {
    stats_.solveSeconds = core::maxOverRanks(*m.A->getComm(), timer.stop());
    ++stats_.solves;
    throw;
  }
  stats_.iterations = outcome.iterations;
  stats_.totalIterations += outcome.iterations;
  stats_.solveSeconds = core::maxOverRanks(*m.A->getComm(), timer.stop());
  ++stats_.solves;
}

}  // namespace sc::solvers

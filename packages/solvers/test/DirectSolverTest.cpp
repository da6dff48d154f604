// Tests of the direct solvers (KLU2, MUMPS), equilibration and symbolic reuse on model systems
// whose exact solution is known: x* is manufactured and b = A x* (ModelMatrices.hpp), so every
// bound below is a bound on the forward error of the solver, with the tolerances of
// docs/solvers.md "Tests" (1e-10 for Poisson, 1e-8 for the scaled saddle point, 1e-12 across
// rank counts).

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/FloatingPointTraps.hpp>
#include <sc/solvers/DirectSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>
#include <sc/solvers/RuizEquilibration.hpp>
#include <sc/solvers/SaddlePointOrdering.hpp>

#include "ModelMatrices.hpp"

namespace {

using namespace sc::solvers;
using namespace sc::solvers::testing;

Teuchos::RCP<DirectSolver> makeSolver(const std::string& type, bool symmetric,
                                      bool equilibrate = true)
{
  Teuchos::ParameterList pl;
  pl.set("Type", type);
  pl.set("Symmetric", symmetric);
  pl.set("Equilibrate", equilibrate);
  return createDirectSolver(pl);
}

Teuchos::RCP<MultiVector> rhsFor(const CrsMatrix& A, const MultiVector& xExact)
{
  auto b = Teuchos::rcp(new MultiVector(A.getRangeMap(), xExact.getNumVectors()));
  A.apply(xExact, *b);
  return b;
}

// Solve A x = A x* (x* = manufacturedSolution unless given) and return x.
Teuchos::RCP<MultiVector> solveFor(DirectSolver& solver, const Teuchos::RCP<const CrsMatrix>& A,
                                   const MultiVector& xExact)
{
  auto b = rhsFor(*A, xExact);
  auto x = Teuchos::rcp(new MultiVector(A->getDomainMap(), xExact.getNumVectors()));
  solver.setOperator(A, solver.exploitsSymmetry());
  solver.solve(*b, *x);
  return x;
}

// ‖x − x*‖/‖x*‖ for the manufactured solution with `columns` right-hand sides.
double solveManufactured(DirectSolver& solver, const Teuchos::RCP<const CrsMatrix>& A,
                         int columns = 1)
{
  auto xExact = manufacturedSolution(A->getDomainMap(), columns);
  return relativeError(*solveFor(solver, A, *xExact), *xExact);
}

const int kPoissonN = 30;  // 900 unknowns
const int kSaddleN = 16;   // 256 + 128 unknowns
const long long kSaddleNu = static_cast<long long>(kSaddleN) * kSaddleN;
const double kScaleM = 1e-8;  // compliance-like block ~ 1/E
const double kScaleB = 1e4;   // divergence-like block

// Errors of the two blocks of the scaled saddle point, x* scaled as the physics scales it (see
// manufacturedSaddleSolution): an O(1) x* in both blocks is no test of a solver, because no
// backward-stable method resolves the block that is 12 orders below the other in the
// equilibrated variables.
struct BlockErrors {
  double first, second;
  double max() const { return std::max(first, second); }
};
BlockErrors solveSaddle(DirectSolver& solver, const Teuchos::RCP<const CrsMatrix>& A,
                        Teuchos::RCP<MultiVector>* solution = nullptr)
{
  auto xExact = manufacturedSaddleSolution(A->getDomainMap(), kSaddleNu, kScaleM, kScaleB);
  auto x = solveFor(solver, A, *xExact);
  if (solution) *solution = x;
  const long long N = static_cast<long long>(A->getGlobalNumRows());
  return {relativeErrorInRange(*x, *xExact, 0, kSaddleNu),
          relativeErrorInRange(*x, *xExact, kSaddleNu, N)};
}

// The same system solved by the same kind of solver on rank 0 alone (MPI_COMM_SELF): the
// relative difference to the distributed solution, broadcast to every rank.
template <class BuildMatrix>
double differenceToSerialSolve(const std::string& type, bool symmetric, BuildMatrix build)
{
  auto comm = Tpetra::getDefaultComm();
  auto solveOn = [&](const Teuchos::RCP<const Teuchos::Comm<int>>& c) {
    Teuchos::RCP<const CrsMatrix> A = build(c);
    auto solver = makeSolver(type, symmetric);
    auto xExact = manufacturedSaddleSolution(A->getDomainMap(), kSaddleNu, kScaleM, kScaleB);
    return gatherToRoot(*solveFor(*solver, A, *xExact));
  };
  const std::vector<double> parallel = solveOn(comm);
  double diff = 0.0;
  if (comm->getRank() == 0) {
    const std::vector<double> serial =
        solveOn(Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF)));
    // blockwise relative difference (the blocks differ in size by sM/sB)
    double num[2] = {0, 0}, den[2] = {0, 0};
    for (size_t i = 0; i < serial.size(); ++i) {
      const int blk = static_cast<long long>(i) < kSaddleNu ? 0 : 1;
      num[blk] += (parallel[i] - serial[i]) * (parallel[i] - serial[i]);
      den[blk] += serial[i] * serial[i];
    }
    for (int blk = 0; blk < 2; ++blk)
      if (den[blk] > 0) diff = std::max(diff, std::sqrt(num[blk] / den[blk]));
  }
  Teuchos::broadcast(*comm, 0, &diff);
  return diff;
}

// (a) Poisson with a manufactured solution, two right-hand sides; both solvers, both MUMPS
// symmetry modes (the 5-point Laplacian is SPD). Source: analytic x*, tolerance 1e-10.
// (Values are computed before TEST_COMPARE, which evaluates its arguments twice.)
TEUCHOS_UNIT_TEST(DirectSolver, PoissonManufacturedSolution)
{
  auto comm = Tpetra::getDefaultComm();
  Teuchos::RCP<const CrsMatrix> A = poisson2d(comm, kPoissonN);
  for (const auto& [type, symmetric] :
       {std::pair<std::string, bool>{"KLU2", false}, {"MUMPS", false}, {"MUMPS", true}}) {
    auto solver = makeSolver(type, symmetric);
    const double err = solveManufactured(*solver, A, 2);
    const auto& st = solver->lastSolveStats();
    out << type << (symmetric ? " (SYM=2)" : "") << ": relative error " << err << ", residual "
        << st.relativeResidual << ", factor entries " << st.factorNonzeros << "\n";
    TEST_COMPARE(err, <=, 1e-10);
    TEST_COMPARE(st.relativeResidual, <=, 1e-13);
    TEST_COMPARE(st.factorNonzeros, >, 0);
    if (type == "MUMPS") TEST_COMPARE(st.mumpsMemoryTotalMB, >, 0.0);
  }
  Teuchos::RCP<const CrsMatrix> A3 = poisson3d(comm, 8);
  for (const std::string type : {"KLU2", "MUMPS"}) {
    auto solver = makeSolver(type, false);
    const double err = solveManufactured(*solver, A3);
    out << type << " 3D: relative error " << err << "\n";
    TEST_COMPARE(err, <=, 1e-10);
  }
}

// (b) Symmetric indefinite saddle point with blocks scaled by 1e-8 and 1e4, equilibrated: both
// solvers (MUMPS as LU and as LDLᵀ) reach 1e-8 relative error in each block and agree with each
// other to 1e-8. Source: analytic x*.
TEUCHOS_UNIT_TEST(DirectSolver, ScaledSaddlePointEquilibrated)
{
  auto comm = Tpetra::getDefaultComm();
  Teuchos::RCP<const CrsMatrix> A = saddlePoint(comm, kSaddleN, kScaleM, kScaleB);
  Teuchos::RCP<MultiVector> xKlu, xMumps, xMumpsSym;
  auto klu = makeSolver("KLU2", false);
  auto mumps = makeSolver("MUMPS", false);
  auto mumpsSym = makeSolver("MUMPS", true);
  const BlockErrors eKlu = solveSaddle(*klu, A, &xKlu);
  const BlockErrors eMumps = solveSaddle(*mumps, A, &xMumps);
  const BlockErrors eMumpsSym = solveSaddle(*mumpsSym, A, &xMumpsSym);
  const double dMumps = relativeErrorInRange(*xMumps, *xKlu, 0, kSaddleNu);
  const double dMumpsSym = relativeErrorInRange(*xMumpsSym, *xKlu, 0, kSaddleNu);
  out << "block errors KLU2 " << eKlu.first << " " << eKlu.second << ", MUMPS " << eMumps.first
      << " " << eMumps.second << ", MUMPS LDLt " << eMumpsSym.first << " " << eMumpsSym.second
      << "; MUMPS-KLU2 " << dMumps << ", " << dMumpsSym << "; Ruiz sweeps "
      << klu->lastSolveStats().equilibrationIterations << "\n";
  TEST_COMPARE(eKlu.max(), <=, 1e-8);
  TEST_COMPARE(eMumps.max(), <=, 1e-8);
  TEST_COMPARE(eMumpsSym.max(), <=, 1e-8);
  TEST_COMPARE(dMumps, <=, 1e-8);
  TEST_COMPARE(dMumpsSym, <=, 1e-8);
  TEST_COMPARE(klu->lastSolveStats().equilibrationIterations, >, 0);
}

// Equilibration of the same saddle point: every row ∞-norm of D A D within a factor 2.2 of 1
// (tolerance 0.1, then rounding each factor to a power of two moves an entry by at most 2), the
// factors are powers of two, and the symmetric variant gives D_r = D_c.
TEUCHOS_UNIT_TEST(RuizEquilibration, SaddlePointNorms)
{
  auto comm = Tpetra::getDefaultComm();
  auto A = saddlePoint(comm, kSaddleN, kScaleM, kScaleB);
  RuizEquilibration ruiz(true, 50, 0.1);
  ruiz.compute(*A);
  auto S = ruiz.scaledCopy(*A);
  double localMax = 0.0, localMin = 1e300;
  const auto lcl = S->getLocalMatrixHost();
  for (int i = 0; i < static_cast<int>(S->getNodeNumRows()); ++i) {
    double m = 0.0;
    for (auto k = lcl.graph.row_map(i); k < lcl.graph.row_map(i + 1); ++k)
      m = std::max(m, std::abs(lcl.values(k)));
    localMax = std::max(localMax, m);
    localMin = std::min(localMin, m);
  }
  double gMax = 0.0, gMin = 0.0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, localMax, Teuchos::outArg(gMax));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, localMin, Teuchos::outArg(gMin));
  out << "row norms in [" << gMin << ", " << gMax << "] after " << ruiz.iterations() << " sweeps\n";
  TEST_COMPARE(gMax, <=, 2.2);
  TEST_COMPARE(gMin, >=, 1.0 / 2.2);
  auto dr = ruiz.rowScaling().getData(0);
  auto dc = ruiz.columnScaling().getData(0);
  bool powersOfTwo = true, symmetric = true;
  for (long i = 0; i < dr.size(); ++i) {
    int e = 0;
    powersOfTwo = powersOfTwo && std::frexp(dr[i], &e) == 0.5;
    symmetric = symmetric && dr[i] == dc[i];
  }
  TEST_ASSERT(powersOfTwo);
  TEST_ASSERT(symmetric);
}

// (c) Symbolic reuse: new values on the same graph reuse the analysis (also values changed in
// place in the same matrix object); a new graph does not. Source: analytic x*.
TEUCHOS_UNIT_TEST(DirectSolver, SymbolicReuse)
{
  auto comm = Tpetra::getDefaultComm();
  Teuchos::RCP<const CrsMatrix> A = poisson2d(comm, kPoissonN);
  Teuchos::RCP<const CrsMatrix> A2 = withShiftedDiagonal(*A, 0.5);
  Teuchos::RCP<const CrsMatrix> A3 = withReplacedRows(*A, 7, 0.4);  // non-symmetric
  for (const std::string type : {"KLU2", "MUMPS"}) {
    auto solver = makeSolver(type, false);
    const double e1 = solveManufactured(*solver, A);
    TEST_COMPARE(e1, <=, 1e-10);
    TEST_EQUALITY(solver->lastSolveStats().symbolicFactorizations, 1);
    TEST_EQUALITY(solver->lastSolveStats().numericFactorizations, 1);
    TEST_EQUALITY(solver->lastSolveStats().symbolicReuses, 0);

    const double e2 = solveManufactured(*solver, A2);
    const double e3 = solveManufactured(*solver, A3);
    const auto& s = solver->lastSolveStats();
    out << type << ": errors " << e1 << ", after value changes " << e2 << ", " << e3
        << "; analyses " << s.symbolicFactorizations << ", reuses " << s.symbolicReuses << "\n";
    TEST_COMPARE(e2, <=, 1e-10);
    TEST_COMPARE(e3, <=, 1e-10);
    TEST_EQUALITY(s.symbolicFactorizations, 1);
    TEST_EQUALITY(s.numericFactorizations, 3);
    TEST_EQUALITY(s.symbolicReuses, 2);

    // The same matrix object with its values changed in place.
    auto A4 = withShiftedDiagonal(*A, 1.0);
    const double e4 = solveManufactured(*solver, A4);
    {
      const auto lcl = A4->getLocalMatrixHost();
      for (size_t k = 0; k < lcl.values.extent(0); ++k)
        lcl.values(k) *= 3.0;
    }
    const double e5 = solveManufactured(*solver, A4);
    TEST_COMPARE(e4, <=, 1e-10);
    TEST_COMPARE(e5, <=, 1e-10);
    TEST_EQUALITY(solver->lastSolveStats().symbolicReuses, 4);

    // A different graph: a new analysis.
    Teuchos::RCP<const CrsMatrix> B = poisson2d(comm, kPoissonN + 1);
    const double e6 = solveManufactured(*solver, B);
    TEST_COMPARE(e6, <=, 1e-10);
    TEST_EQUALITY(solver->lastSolveStats().symbolicFactorizations, 2);
    TEST_EQUALITY(solver->lastSolveStats().symbolicReuses, 4);

    // Explicit phases: symbolic once, numeric twice with new values -> one more reuse.
    solver->setOperator(A, solver->exploitsSymmetry());
    solver->symbolicFactorization();
    solver->numericFactorization();
    solver->setOperator(A2, solver->exploitsSymmetry());
    solver->numericFactorization();
    TEST_EQUALITY(solver->lastSolveStats().symbolicFactorizations, 3);
    TEST_EQUALITY(solver->lastSolveStats().symbolicReuses, 5);
    const double e7 = solveManufactured(*solver, A2);  // same graph, new setOperator
    TEST_COMPARE(e7, <=, 1e-10);
  }
}

// (d) Contact-like replaced rows make the scaled saddle point non-symmetric: MUMPS with SYM = 0
// and KLU2 solve it to 1e-8 per block and agree; declaring it symmetric is caught by the residual
// check (ConvergenceError), not returned as a wrong answer.
TEUCHOS_UNIT_TEST(DirectSolver, NonSymmetricReplacedRows)
{
  auto comm = Tpetra::getDefaultComm();
  auto S = saddlePoint(comm, kSaddleN, kScaleM, kScaleB);
  Teuchos::RCP<const CrsMatrix> A = withReplacedRows(*S, 7, 0.4, kSaddleNu);
  Teuchos::RCP<MultiVector> xKlu, xMumps;
  auto klu = makeSolver("KLU2", false);
  auto mumps = makeSolver("MUMPS", false);
  const BlockErrors eKlu = solveSaddle(*klu, A, &xKlu);
  const BlockErrors eMumps = solveSaddle(*mumps, A, &xMumps);
  const double d = relativeErrorInRange(*xMumps, *xKlu, 0, kSaddleNu);
  out << "block errors KLU2 " << eKlu.first << " " << eKlu.second << ", MUMPS SYM=0 "
      << eMumps.first << " " << eMumps.second << "; MUMPS-KLU2 " << d << "\n";
  TEST_COMPARE(eKlu.max(), <=, 1e-8);
  TEST_COMPARE(eMumps.max(), <=, 1e-8);
  TEST_COMPARE(d, <=, 1e-8);

  auto wrong = makeSolver("MUMPS", true);
  TEST_THROW(solveSaddle(*wrong, A), sc::core::ConvergenceError);
}

// (e) Singular matrices give a sc::core::Error on every rank (no crash, no hang), with and
// without equilibration: two identical rows (exactly singular), and a zero row, which the
// equilibration names by its global index.
TEUCHOS_UNIT_TEST(DirectSolver, SingularMatrixIsAnError)
{
  auto comm = Tpetra::getDefaultComm();
  Teuchos::RCP<const CrsMatrix> dup = poisson2d(comm, 12, true);
  Teuchos::RCP<const CrsMatrix> zero = withZeroRow(*poisson2d(comm, 12), 17);
  for (const std::string type : {"KLU2", "MUMPS"}) {
    for (const bool equilibrate : {true, false}) {
      auto s1 = makeSolver(type, false, equilibrate);
      TEST_THROW(solveManufactured(*s1, dup), sc::core::Error);
      auto s2 = makeSolver(type, false, equilibrate);
      bool threw = false;
      try {
        solveManufactured(*s2, zero);
      } catch (const sc::core::Error& e) {
        threw = true;
        out << type << (equilibrate ? " equilibrated" : "") << ": " << e.what() << "\n";
        if (equilibrate)
          TEST_ASSERT(std::string(e.what()).find("global index 17") != std::string::npos);
      }
      TEST_ASSERT(threw);
    }
  }
  // The solver is usable again afterwards.
  auto s = makeSolver("MUMPS", false);
  TEST_THROW(solveManufactured(*s, dup), sc::core::Error);
  const double err = solveManufactured(*s, poisson2d(comm, 12));
  TEST_COMPARE(err, <=, 1e-10);
}

// A NaN in the matrix (a corrupted assembly) gives an error naming the non-finite solution or the
// singular factorisation on every rank, never a NaN solution returned as a result. Traps are
// suspended: under SC_TRAP_FPE=1 the first NaN operation would stop the test, which is what
// traps are for, but here the NaN is the input.
TEUCHOS_UNIT_TEST(DirectSolver, NonFiniteMatrixIsAnError)
{
  auto comm = Tpetra::getDefaultComm();
  auto A = poisson2d(comm, 12);
  A->resumeFill();
  const auto& rows = *A->getRowMap();
  for (size_t i = 0; i < A->getNodeNumRows(); ++i) {
    const long long g = rows.getGlobalElement(i);
    if (g == 17) {
      const long long col = g;
      const double nan = std::nan("");
      A->replaceGlobalValues(g, Teuchos::ArrayView<const long long>(&col, 1),
                             Teuchos::ArrayView<const double>(&nan, 1));
    }
  }
  A->fillComplete();
  sc::core::FloatingPointTrapsSuspended noTraps;
  for (const std::string type : {"KLU2", "MUMPS"})
    for (const bool equilibrate : {true, false}) {
      auto s = makeSolver(type, false, equilibrate);
      bool threw = false;
      try {
        solveManufactured(*s, A);
      } catch (const sc::core::Error& e) {
        threw = true;
        out << type << (equilibrate ? " equilibrated" : "") << ": " << e.what() << "\n";
      }
      TEST_ASSERT(threw);
    }
}

// Results agree across rank counts: the distributed solve equals the same solver's solve on rank 0
// alone (MPI_COMM_SELF) to 1e-12 per block, so runs at 1, 2 and 4 ranks agree to that tolerance.
TEUCHOS_UNIT_TEST(DirectSolver, SameResultOnOneRank)
{
  auto contactLike = [](const Teuchos::RCP<const Teuchos::Comm<int>>& c) {
    return Teuchos::RCP<const CrsMatrix>(
        withReplacedRows(*saddlePoint(c, kSaddleN, kScaleM, kScaleB), 7, 0.4, kSaddleNu));
  };
  auto saddle = [](const Teuchos::RCP<const Teuchos::Comm<int>>& c) {
    return Teuchos::RCP<const CrsMatrix>(saddlePoint(c, kSaddleN, kScaleM, kScaleB));
  };
  const double d1 = differenceToSerialSolve("KLU2", false, contactLike);
  const double d2 = differenceToSerialSolve("MUMPS", false, contactLike);
  const double d3 = differenceToSerialSolve("MUMPS", true, saddle);
  const double d4 = differenceToSerialSolve("KLU2", false, saddle);
  out << "parallel vs one rank: KLU2 " << d1 << ", MUMPS " << d2 << ", MUMPS LDLt " << d3
      << ", KLU2 symmetric " << d4 << "\n";
  TEST_COMPARE(d1, <=, 1e-12);
  TEST_COMPARE(d2, <=, 1e-12);
  TEST_COMPARE(d3, <=, 1e-12);
  TEST_COMPARE(d4, <=, 1e-12);
}

}  // namespace

namespace {

using namespace sc::solvers;
using namespace sc::solvers::testing;

// MUMPS with no workspace relaxation (ICNTL(14) = 0) on the non-symmetric saddle point, whose
// delayed pivots need more than the analysis estimate: it must still succeed, through the
// automatic retries with a doubled ICNTL(14) if MUMPS reports -8/-9.
TEUCHOS_UNIT_TEST(MumpsSolver, WorkspaceRetry)
{
  auto comm = Tpetra::getDefaultComm();
  auto S = saddlePoint(comm, kSaddleN, kScaleM, kScaleB);
  Teuchos::RCP<const CrsMatrix> A = withReplacedRows(*S, 7, 0.4, kSaddleNu);
  Teuchos::ParameterList pl;
  pl.set("Type", std::string("MUMPS"));
  pl.sublist("MUMPS").set("Memory relaxation percent", 0);
  pl.sublist("MUMPS").set("Workspace retries", 5);
  pl.set("Symmetric", false);  // solveSaddle declares the operator symmetric iff this is true
  auto solver = createDirectSolver(pl);
  const BlockErrors e = solveSaddle(*solver, A);
  out << "block errors " << e.first << " " << e.second << " after "
      << solver->lastSolveStats().workspaceRetries << " workspace retries\n";
  TEST_COMPARE(e.max(), <=, 1e-8);
  // 3 at 1, 2 and 4 ranks (ICNTL(14) 0 -> 20 -> 40 -> 80) when written
  TEST_COMPARE(solver->lastSolveStats().workspaceRetries, >=, 1);
}

// MUMPS' own scaling (ICNTL(8), 'MUMPS/Scaling', docs/solvers.md "Equilibration"): None, and Auto
// with our equilibration, apply none (INFOG(33) = 0); MUMPS (ICNTL(8) = 77) and Auto without
// equilibration let MUMPS scale (INFOG(33) != 0). On the non-symmetric saddle point with
// contact-like rows the answers agree to 1e-10 (manufactured x*), and the analysis reports its
// memory estimate INFOG(16)/(17).
TEUCHOS_UNIT_TEST(MumpsSolver, OwnScalingOnTopOfOurs)
{
  auto comm = Tpetra::getDefaultComm();
  auto S = saddlePoint(comm, kSaddleN, kScaleM, kScaleB);
  Teuchos::RCP<const CrsMatrix> A = withReplacedRows(*S, 7, 0.4, kSaddleNu);
  const auto run = [&](const std::string& scaling, bool equilibrate, Teuchos::RCP<MultiVector>* x) {
    Teuchos::ParameterList pl;
    pl.set("Type", std::string("MUMPS"));
    pl.set("Symmetric", false);
    pl.set("Equilibrate", equilibrate);
    pl.sublist("MUMPS").set("Scaling", scaling);
    auto solver = createDirectSolver(pl);
    const BlockErrors e = solveSaddle(*solver, A, x);
    const auto& st = solver->lastSolveStats();
    out << scaling << (equilibrate ? ", equilibrated" : ", not equilibrated")
        << ": INFOG(33) = " << st.mumpsScaling
        << ", INFOG(16)/(17) = " << st.mumpsEstimatedMemoryMaxMB << "/"
        << st.mumpsEstimatedMemoryTotalMB << " MB, block errors " << e.first << " " << e.second
        << "\n";
    TEST_COMPARE(e.max(), <=, 1e-8);
    TEST_COMPARE(st.mumpsEstimatedMemoryMaxMB, >, 0.0);
    TEST_COMPARE(st.mumpsEstimatedMemoryTotalMB, >=, st.mumpsEstimatedMemoryMaxMB);
    return st.mumpsScaling;
  };
  Teuchos::RCP<MultiVector> xMumps, xNone, xAuto, xAutoRaw;
  const int mumps = run("MUMPS", true, &xMumps);
  TEST_ASSERT(mumps != 0);
  TEST_EQUALITY(run("None", true, &xNone), 0);
  TEST_EQUALITY(run("Auto", true, &xAuto), 0);
  TEST_ASSERT(run("Auto", false, &xAutoRaw) != 0);  // without ours, MUMPS scales
  const double d = relativeErrorInRange(*xNone, *xMumps, 0, kSaddleNu);
  out << "|x(None) - x(MUMPS)| / |x(MUMPS)| (stress block) = " << d << "\n";
  TEST_COMPARE(d, <=, 1e-10);
  TEST_COMPARE(relativeErrorInRange(*xAuto, *xNone, 0, kSaddleNu), <=, 1e-14);
}

// 'MUMPS/Ordering' = METIS (docs/solvers.md "Ordering"): our nested dissection given to MUMPS as
// its pivot order (ICNTL(7) = 1) solves the scaled saddle point (LDLᵀ and LU) and the saddle
// point with contact-like rows (LU) to the same answer as the default AMF, per block to 1e-10
// (source: the AMF solution and the manufactured x*), with the graph gathered from every rank.
// The factors stay within 2× of AMF's (a nested dissection that eliminated the zero-diagonal
// rows first gave 5-10× larger ones, docs/solvers.md "Ordering").
TEUCHOS_UNIT_TEST(MumpsSolver, MetisOrderingSameSolution)
{
  auto comm = Tpetra::getDefaultComm();
  auto S = saddlePoint(comm, kSaddleN, kScaleM, kScaleB);
  Teuchos::RCP<const CrsMatrix> contact = withReplacedRows(*S, 7, 0.4, kSaddleNu);
  const long long N = static_cast<long long>(S->getGlobalNumRows());
  for (const auto& [name, A, symmetric] :
       {std::tuple<std::string, Teuchos::RCP<const CrsMatrix>, bool>{"saddle LDLT", S, true},
        {"saddle LU", S, false},
        {"contact-like LU", contact, false}}) {
    const auto run = [&, &A = A, symmetric = symmetric](const std::string& ordering,
                                                        Teuchos::RCP<MultiVector>* x) {
      Teuchos::ParameterList pl;
      pl.set("Type", std::string("MUMPS"));
      pl.set("Symmetric", symmetric);
      pl.sublist("MUMPS").set("Ordering", ordering);
      auto solver = createDirectSolver(pl);
      const BlockErrors e = solveSaddle(*solver, A, x);
      TEST_COMPARE(e.max(), <=, 1e-8);
      return solver->lastSolveStats().factorNonzeros;
    };
    Teuchos::RCP<MultiVector> xAmf, xMetis;
    const long long fAmf = run("AMF", &xAmf);
    const long long fMetis = run("METIS", &xMetis);
    const double d1 = relativeErrorInRange(*xMetis, *xAmf, 0, kSaddleNu);
    const double d2 = relativeErrorInRange(*xMetis, *xAmf, kSaddleNu, N);
    out << name << ": factor entries AMF " << fAmf << ", METIS " << fMetis
        << "; difference per block " << d1 << " " << d2 << "\n";
    TEST_COMPARE(d1, <=, 1e-10);
    TEST_COMPARE(d2, <=, 1e-10);
    TEST_COMPARE(fMetis, >, 0);
    TEST_COMPARE(fMetis, <=, 2 * fAmf);
  }
}

// saddlePointOrdering itself: a permutation; every zero-diagonal row follows one of its
// nonzero-diagonal neighbours (in A or Aᵀ) with only zero-diagonal rows between them; a
// zero-diagonal row without such a neighbour is last. The graph has a non-symmetric pattern and
// duplicate entries.
TEUCHOS_UNIT_TEST(SaddlePointOrdering, ZeroDiagonalRowsAfterTheirNeighbours)
{
  // 6 × 6 grid of nonzero-diagonal rows (5-point), then one zero-diagonal row per grid cell
  // coupled to the cell's 4 corners, and one zero-diagonal row coupled to another zero row only.
  const int g = 6, nv = g * g, cells = (g - 1) * (g - 1), n = nv + cells + 1;
  std::vector<std::vector<int>> rows(static_cast<size_t>(n));
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) {
      const int v = i * g + j;
      rows[static_cast<size_t>(v)] = {v, v};  // duplicate diagonal entry
      if (i > 0) rows[static_cast<size_t>(v)].push_back(v - g);
      if (i + 1 < g) rows[static_cast<size_t>(v)].push_back(v + g);
      if (j > 0) rows[static_cast<size_t>(v)].push_back(v - 1);
      if (j + 1 < g) rows[static_cast<size_t>(v)].push_back(v + 1);
    }
  std::vector<char> zero(static_cast<size_t>(n), 0);
  for (int i = 0; i + 1 < g; ++i)
    for (int j = 0; j + 1 < g; ++j) {
      const int z = nv + i * (g - 1) + j, v = i * g + j;
      zero[static_cast<size_t>(z)] = 1;
      rows[static_cast<size_t>(z)] = {v, v + 1};  // the other two corners only in Aᵀ
      rows[static_cast<size_t>(v + g)].push_back(z);
      rows[static_cast<size_t>(v + g + 1)].push_back(z);
    }
  zero[static_cast<size_t>(n - 1)] = 1;
  rows[static_cast<size_t>(n - 1)] = {nv};
  std::vector<std::int64_t> start{0};
  std::vector<int> cols;
  for (const auto& r : rows) {
    cols.insert(cols.end(), r.begin(), r.end());
    start.push_back(static_cast<std::int64_t>(cols.size()));
  }
  const std::vector<int> position = saddlePointOrdering(n, start, cols, zero);
  std::vector<int> seen(static_cast<size_t>(n), 0);
  for (int p : position) {
    TEST_ASSERT(p >= 0 && p < n);
    if (p >= 0 && p < n) ++seen[static_cast<size_t>(p)];
  }
  TEST_EQUALITY(static_cast<int>(std::count(seen.begin(), seen.end(), 1)), n);
  std::vector<int> at(static_cast<size_t>(n), 0);  // the row at each place
  for (int r = 0; r < n; ++r)
    if (position[static_cast<size_t>(r)] >= 0 && position[static_cast<size_t>(r)] < n)
      at[static_cast<size_t>(position[static_cast<size_t>(r)])] = r;
  for (int i = 0; i + 1 < g; ++i)
    for (int j = 0; j + 1 < g; ++j) {
      const int z = nv + i * (g - 1) + j, v = i * g + j;
      int p = position[static_cast<size_t>(z)] - 1;
      while (p >= 0 && zero[static_cast<size_t>(at[static_cast<size_t>(p)])])
        --p;
      TEST_ASSERT(p >= 0);
      const int hostRow = p >= 0 ? at[static_cast<size_t>(p)] : -1;
      out << "zero row " << z << " after row " << hostRow << "\n";
      TEST_ASSERT(hostRow == v || hostRow == v + 1 || hostRow == v + g || hostRow == v + g + 1);
    }
  TEST_EQUALITY(position[static_cast<size_t>(n - 1)], n - 1);
}

}  // namespace

// solvers_benchmark: time and memory of the direct solvers on model systems of growing size.
//
//   mpiexec -n 2 solvers_benchmark [--max-dofs=N] [--max-klu2-dofs=N] [--problems=a,b]
//                                  [--solvers=KLU2,MUMPS] [--no-equilibrate]
//                                  [--ordering=METIS|AMD|AMF|SCOTCH|PORD|QAMD|Auto] (MUMPS)
//                                  [--general] (MUMPS LU, SYM = 0, also for symmetric problems)
//   solvers_benchmark --print-parameters   (the "Linear Solver" keys, as in docs/solvers.md)
//   problems: poisson2d (5-point), poisson3d (7-point), saddle (the scaled symmetric indefinite
//   saddle point of the unit tests, blocks 1e-8 and 1e4), contact (saddle with replaced rows).
//
// Per size and solver one line: DOFs, stored entries, equilibration / analysis / factorisation /
// solve seconds, a second factorisation with new values (symbolic reuse, docs/theory.md §"Linear
// solvers"), DOFs/s of analysis + factorisation + solve, entries in the factors, peak resident
// memory (getrusage, max over ranks, cumulative over the run), MUMPS INFOG(21)/(22) (MB, max per
// rank / sum), residual.

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

#include "ModelMatrices.hpp"

namespace {

using namespace sc::solvers;

std::vector<std::string> split(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');)
    out.push_back(item);
  return out;
}

double peakMemoryMB(const Teuchos::Comm<int>& comm)
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double local = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kB
  double global = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  return global;
}

struct Problem {
  std::string name;
  std::vector<int> sizes;  // grid parameter n
  long long dofs(int n) const
  {
    const long long nn = n;
    if (name == "poisson3d") return nn * nn * nn;
    if (name == "saddle" || name == "contact") return nn * nn + nn * nn / 2;
    return nn * nn;
  }
  Teuchos::RCP<const CrsMatrix> build(const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                      int n) const
  {
    using namespace sc::solvers::testing;
    if (name == "poisson2d") return poisson2d(comm, n);
    if (name == "poisson3d") return poisson3d(comm, n);
    auto S = saddlePoint(comm, n, 1e-8, 1e4);
    if (name == "saddle") return S;
    return withReplacedRows(*S, 7, 0.4, static_cast<long long>(n) * n);
  }
  bool symmetric() const { return name != "contact"; }
};

}  // namespace

int main(int argc, char* argv[])
{
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;

  long long maxDofs = 1000000, maxKluDofs = 300000;
  std::vector<std::string> problems = {"poisson2d", "poisson3d", "saddle", "contact"};
  std::vector<std::string> solvers = {"KLU2", "MUMPS"};
  bool equilibrate = true;
  std::string ordering;  // empty: the Linear Solver default
  bool general = false;  // MUMPS LU (SYM = 0) also for the symmetric problems
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* key) {
      const std::string k = std::string(key) + "=";
      return a.rfind(k, 0) == 0 ? a.substr(k.size()) : std::string();
    };
    if (!value("--max-dofs").empty())
      maxDofs = std::atoll(value("--max-dofs").c_str());
    else if (!value("--max-klu2-dofs").empty())
      maxKluDofs = std::atoll(value("--max-klu2-dofs").c_str());
    else if (!value("--problems").empty())
      problems = split(value("--problems"));
    else if (!value("--solvers").empty())
      solvers = split(value("--solvers"));
    else if (!value("--ordering").empty())
      ordering = value("--ordering");
    else if (a == "--no-equilibrate")
      equilibrate = false;
    else if (a == "--general")
      general = true;
    else if (a == "--print-parameters") {
      if (root)
        sc::core::printParameterDocumentation(*LinearSolverFactory::getValidParameters(),
                                              std::cout);
      return 0;
    } else {
      if (root)
        std::cerr << "solvers_benchmark: unknown argument '" << a << "' (see the source "
                  << "header for the options)\n";
      return 2;
    }
  }

  const std::vector<Problem> all = {
      {"poisson2d", {32, 64, 128, 256, 512, 724, 1000}},
      {"poisson3d", {10, 16, 24, 32, 48, 64}},
      {"saddle", {32, 64, 128, 256, 512, 816}},
      {"contact", {32, 64, 128, 256, 512}},
  };

  if (root) {
    std::printf("# solvers_benchmark: %d rank(s), equilibration %s, MUMPS ordering %s%s\n",
                comm->getSize(), equilibrate ? "on" : "off",
                ordering.empty() ? "default" : ordering.c_str(), general ? ", SYM = 0" : "");
    std::printf("%-10s %-6s %9s %10s %7s %8s %8s %7s %8s %10s %11s %9s %9s %9s %9s\n", "problem",
                "solver", "DOFs", "nnz(A)", "equil_s", "symb_s", "num_s", "solve_s", "renum_s",
                "DOFs/s", "nnz(LU)", "peakRSS", "MUMPS21", "MUMPS22", "residual");
  }
  for (const auto& pname : problems) {
    const Problem* p = nullptr;
    for (const auto& q : all)
      if (q.name == pname) p = &q;
    if (!p) {
      if (root) std::cerr << "unknown problem " << pname << "\n";
      return 2;
    }
    for (int n : p->sizes) {
      if (p->dofs(n) > maxDofs) break;
      auto A = p->build(comm, n);
      auto xExact = sc::solvers::testing::manufacturedSolution(A->getDomainMap());
      MultiVector b(A->getRangeMap(), 1), x(A->getDomainMap(), 1);
      A->apply(*xExact, b);
      // second operator: same graph, new values (as a Newton step's contact rows)
      Teuchos::RCP<const CrsMatrix> A2 = sc::solvers::testing::withShiftedDiagonal(*A, 0.0);
      for (const auto& type : solvers) {
        if (type == "KLU2" && p->dofs(n) > maxKluDofs) continue;
        Teuchos::ParameterList pl;
        pl.set("Type", type);
        pl.set("Symmetric", type == "MUMPS");
        pl.set("Equilibrate", equilibrate);
        if (type == "MUMPS" && !ordering.empty()) pl.sublist("MUMPS").set("Ordering", ordering);
        try {
          auto solver = createDirectSolver(pl);
          const bool symmetric = p->symmetric() && !general;
          solver->setOperator(A, symmetric);
          solver->solve(b, x);
          const SolveStatistics first = solver->lastSolveStats();
          solver->setOperator(A2, symmetric);
          solver->numericFactorization();
          const SolveStatistics& second = solver->lastSolveStats();
          const double total = first.symbolicSeconds + first.numericSeconds + first.solveSeconds;
          const double mem = peakMemoryMB(*comm);
          if (root)
            std::printf("%-10s %-6s %9lld %10lld %7.3f %8.3f %8.3f %7.3f %8.3f %10.3g %11lld "
                        "%9.0f %9.0f %9.0f %9.1e\n",
                        pname.c_str(), type.c_str(), p->dofs(n),
                        static_cast<long long>(A->getGlobalNumEntries()),
                        first.equilibrationSeconds, first.symbolicSeconds, first.numericSeconds,
                        first.solveSeconds, second.numericSeconds,
                        static_cast<double>(p->dofs(n)) / total, first.factorNonzeros, mem,
                        first.mumpsMemoryMaxMB, first.mumpsMemoryTotalMB, first.relativeResidual);
        } catch (const sc::core::Error& e) {
          if (root)
            std::printf("%-10s %-6s %9lld  failed: %s\n", pname.c_str(), type.c_str(), p->dofs(n),
                        e.what());
        }
        std::fflush(stdout);
      }
    }
  }
  return 0;
}

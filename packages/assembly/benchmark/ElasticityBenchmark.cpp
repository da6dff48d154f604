// elasticity_benchmark: assembly throughput and direct-solve time against DOFs for the mixed
// elasticity system. Prints one line per size and solver; numbers in docs/benchmarks.md.
//
//   elasticity_benchmark [--dim=2|3] [--max-dofs=N] [--degree=k] [--solvers=KLU2,MUMPS,Iterative]
//                        [--mesh-size=h] [--nu=ν] [--min-dofs=N]
//                        [--stress-block=MUMPS|Multigrid|...]
//   mpiexec -n 2 elasticity_benchmark --dim=3 --max-dofs=600000 --mesh-size=0.4
//
// Sizes: the initial Gmsh mesh of the unit square/cube (element size h, default 0.25 in 2D and
// 0.5 in 3D), then uniform bisection until the DOF count exceeds --max-dofs. One uniform cycle
// multiplies the DOFs by ~4 in 2D and ~8 in 3D; --mesh-size fills the gaps (DOFs ~ h^-d).
//
// setup = partition + DOF numbering (number_s, on the whole replicated mesh) + the exact graph of
// this rank's owned rows. Every time is the maximum over ranks (phases start after a barrier);
// "per rank" rates are the global count / that time / number of ranks; peak memory is the
// resident-set high-water mark (getrusage) since the start of the program, maximum and sum over
// ranks. Iterative: Belos MINRES with the block-diagonal preconditioner (docs/theory.md
// §"Linear solvers") to a 1e-8 relative residual; "analyse" is then the preconditioner build (S_σ
// and its factorisation), "factor" 0, "iters" the MINRES iterations. scripts/solver-study.sh runs
// the tables of docs/solvers.md.
#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <Teuchos_Time.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/assembly/MixedElasticitySystem.hpp>
#include <sc/solvers/StressHierarchy.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/ExactSolution.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/SimplexMesh.hpp>
#include <sc/solvers/LinearSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

namespace {
double peakMemoryMB()
{
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

double maxOverRanks(const Teuchos::Comm<int>& comm, double v)
{
  double r = v;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &v, &r);
  return r;
}

double sumOverRanks(const Teuchos::Comm<int>& comm, double v)
{
  double r = v;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 1, &v, &r);
  return r;
}
}  // namespace

int main(int argc, char* argv[])
{
  Teuchos::GlobalMPISession session(&argc, &argv, nullptr);
  Kokkos::ScopeGuard kokkos(argc, argv);
  auto comm = Teuchos::DefaultComm<int>::getComm();
  int dim = 2, degree = 1;
  long long maxDofs = 200000;
  double meshSize = 0.0;  // 0: the default of the dimension
  double nu = 0.3;
  long long minDofs = 0;
  std::vector<std::string> solvers = {"KLU2", "MUMPS"};
  std::string stressBlock = "MUMPS";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--dim=", 0) == 0)
      dim = std::stoi(a.substr(6));
    else if (a.rfind("--degree=", 0) == 0)
      degree = std::stoi(a.substr(9));
    else if (a.rfind("--max-dofs=", 0) == 0)
      maxDofs = std::stoll(a.substr(11));
    else if (a.rfind("--mesh-size=", 0) == 0)
      meshSize = std::stod(a.substr(12));
    else if (a.rfind("--nu=", 0) == 0)
      nu = std::stod(a.substr(5));
    else if (a.rfind("--min-dofs=", 0) == 0)
      minDofs = std::stoll(a.substr(11));
    else if (a.rfind("--stress-block=", 0) == 0)
      stressBlock = a.substr(15);
    else if (a.rfind("--solvers=", 0) == 0) {
      solvers.clear();
      std::string list = a.substr(10), item;
      for (char c : list + ",")
        if (c == ',') {
          solvers.push_back(item);
          item.clear();
        } else {
          item += c;
        }
    } else {
      if (comm->getRank() == 0) std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 1;
    }
  }
  Teuchos::ParameterList meshList;
  meshList.set("Source", std::string(dim == 2 ? "Unit square" : "Unit cube"));
  if (meshSize <= 0.0) meshSize = dim == 2 ? 0.25 : 0.5;
  meshList.set("Initial mesh size", meshSize);
  auto refiner = sc::mesh::MeshFactory::build(meshList, dim, *comm);
  sc::core::Material material{1.0, nu};
  auto exact = sc::core::createExactSolution("Manufactured smooth", dim, material);
  sc::core::BoundaryConditions bcs;
  for (const char* n : {"Left", "Bottom"})
    bcs.conditions.push_back({n, sc::core::BoundaryType::Displacement, {}, true});
  const int nRanks = comm->getSize();
  if (comm->getRank() == 0) {
    std::string solverList;
    for (const auto& t : solvers)
      solverList += (solverList.empty() ? "" : ",") + t;
    std::printf(
        "# elasticity_benchmark %dD k=%d nu=%g ranks=%d mesh-size=%g max-dofs=%lld solvers=%s "
        "stress-block=%s\n"
        "# times: max over ranks [s]; rates: global count / time / ranks; peakMB: RSS "
        "high-water mark, max and sum over ranks\n",
        dim, degree, nu, nRanks, meshSize, maxDofs, solverList.c_str(), stressBlock.c_str());
    std::printf("# %9s %8s %8s %8s %8s %10s %10s %-9s %8s %8s %8s %9s %8s %8s %6s\n", "dofs",
                "elements", "setup_s", "number_s", "assem_s", "dofs/s/rk", "elem/s/rk", "solver",
                "analyse", "factor", "solve", "residual", "peakMB", "sumMB", "iters");
    std::fflush(stdout);
  }
  // Stress block = Multigrid: the nested hierarchy (coarsest first), extended at every refinement.
  const bool multigrid = stressBlock == "Multigrid";
  sc::solvers::StressHierarchy hierarchy(degree, comm);
  std::vector<int> parent;  // fine element -> coarse element of the last refinement
  while (true) {
    auto m = refiner->mesh();
    comm->barrier();
    const double t0 = Teuchos::Time::wallTime();
    // The application's pipeline (assembly::MixedElasticitySystem), one step at a time so that
    // each is timed and the graph of a mesh above --max-dofs is never built.
    sc::assembly::MixedElasticitySystem system(m, degree, comm);  // partition, DOF numbering
    const auto& space = system.space();
    if (space.numGlobalDofs() > maxDofs) break;
    if (multigrid) hierarchy.addMesh(m, parent);
    if (space.numGlobalDofs() < minDofs || (multigrid && hierarchy.numMeshes() < 2)) {
      parent = refiner->refineUniformly().elementParent;
      continue;
    }
    const double tSpace = Teuchos::Time::wallTime();
    system.setupAssembler();
    const double t1 = Teuchos::Time::wallTime();
    comm->barrier();
    const double t1b = Teuchos::Time::wallTime();
    system.assemble({material, bcs, exact.get()});
    const double t2 = Teuchos::Time::wallTime();
    const double setupS = maxOverRanks(*comm, t1 - t0);
    const double numberS = maxOverRanks(*comm, tSpace - t0);
    const double assembleS = maxOverRanks(*comm, t2 - t1b);
    const long long dofs = space.numGlobalDofs();
    const int elements = m->numElements();
    const auto& assembler = system.assembler();
    for (const auto& type : solvers) {
      Teuchos::ParameterList sl;
      sl.set("Type", type);
      if (type == "Iterative") sl.sublist("Iterative").set("Stress block", stressBlock);
      auto solver = sc::solvers::createLinearSolver(sl);
      auto x = assembler.createVector();
      // scaling and (Krylov) block structure, as the application
      system.prepareSolver(*solver, type == "Iterative" && multigrid
                                        ? hierarchy.levels(space)
                                        : std::vector<sc::solvers::MultigridLevel>{});
      comm->barrier();
      const double tOp = Teuchos::Time::wallTime();
      double opS = 0.0;
      try {
        solver->setOperator(assembler.matrix(), true);
        opS = maxOverRanks(*comm, Teuchos::Time::wallTime() - tOp);
        comm->barrier();
        solver->solve(*assembler.rhs(), *x);
      } catch (const sc::core::Error& e) {  // thrown on every rank (e.g. MUMPS out of memory)
        if (comm->getRank() == 0)
          std::printf("  %9lld %8d %-9s failed after %.1f s, peak %.0f MB: %s\n", dofs, elements,
                      type.c_str(), Teuchos::Time::wallTime() - tOp, peakMemoryMB(), e.what());
        std::fflush(stdout);
        continue;
      }
      const auto& st = solver->lastSolveStats();
      const double analyseS = solver->isIterative() ? opS : maxOverRanks(*comm, st.symbolicSeconds);
      const double factorS = maxOverRanks(*comm, st.numericSeconds);
      const double solveS = maxOverRanks(*comm, st.solveSeconds);
      const double peakMax = maxOverRanks(*comm, peakMemoryMB());
      const double peakSum = sumOverRanks(*comm, peakMemoryMB());
      if (comm->getRank() == 0)
        std::printf("  %9lld %8d %8.3f %8.3f %8.3f %10.3g %10.3g %-9s %8.3f %8.3f %8.3f %9.2e "
                    "%8.0f %8.0f %6d\n",
                    dofs, elements, setupS, numberS, assembleS, dofs / assembleS / nRanks,
                    elements / assembleS / nRanks, type.c_str(), analyseS, factorS, solveS,
                    st.relativeResidual, peakMax, peakSum, st.iterations);
      std::fflush(stdout);
    }
    parent = refiner->refineUniformly().elementParent;
  }
  return 0;
}

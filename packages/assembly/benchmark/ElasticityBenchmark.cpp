// elasticity_benchmark: assembly throughput and direct-solve time against DOFs for the mixed
// elasticity system (issue #4). Prints one line per size and solver; numbers in docs/benchmarks.md.
//
//   elasticity_benchmark [--dim=2|3] [--max-dofs=N] [--degree=k] [--solvers=KLU2,MUMPS]
//   mpiexec -n 2 elasticity_benchmark --dim=3 --max-dofs=500000
#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <Teuchos_Time.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/core/ExactSolution.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/Partitioning.hpp>
#include <sc/mesh/SimplexMesh.hpp>
#include <sc/solvers/DirectSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

namespace {
double peakMemoryMB()
{
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}
}  // namespace

int main(int argc, char* argv[])
{
  Teuchos::GlobalMPISession session(&argc, &argv, nullptr);
  Kokkos::ScopeGuard kokkos(argc, argv);
  auto comm = Teuchos::DefaultComm<int>::getComm();
  int dim = 2, degree = 1;
  long long maxDofs = 200000;
  std::vector<std::string> solvers = {"KLU2", "MUMPS"};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--dim=", 0) == 0)
      dim = std::stoi(a.substr(6));
    else if (a.rfind("--degree=", 0) == 0)
      degree = std::stoi(a.substr(9));
    else if (a.rfind("--max-dofs=", 0) == 0)
      maxDofs = std::stoll(a.substr(11));
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
      if (comm->getRank() == 0)
        std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 1;
    }
  }
  Teuchos::ParameterList meshList;
  meshList.set("Source", std::string(dim == 2 ? "Unit square" : "Unit cube"));
  meshList.set("Initial mesh size", dim == 2 ? 0.25 : 0.5);
  auto refiner = sc::mesh::MeshFactory::build(meshList, dim, *comm);
  sc::core::Material material{1.0, 0.3};
  auto exact = sc::core::createExactSolution("Manufactured smooth", dim, material);
  sc::core::BoundaryConditions bcs;
  for (const char* n : {"Left", "Bottom"})
    bcs.conditions.push_back({n, sc::core::BoundaryType::Displacement, {}, true});
  if (comm->getRank() == 0)
    std::printf("# %dD k=%d ranks=%d\n# %10s %9s %12s %12s %12s %-6s %9s %9s %9s %10s %9s\n", dim,
                degree, comm->getSize(), "dofs", "elements", "setup_s", "assemble_s",
                "dofs/s/rank", "solver", "analyse_s", "factor_s", "solve_s", "residual", "peakMB");
  while (true) {
    auto m = refiner->mesh();
    const double t0 = Teuchos::Time::wallTime();
    auto owner = sc::mesh::partitionElements(*m, *comm);
    auto space = Teuchos::rcp(new sc::disc::MixedElasticitySpace(m, degree, owner, comm->getRank()));
    if (space->numGlobalDofs() > maxDofs)
      break;
    sc::assembly::MixedElasticityAssembler assembler(space, comm);
    const double t1 = Teuchos::Time::wallTime();
    assembler.assemble({material, bcs, exact.get()});
    const double t2 = Teuchos::Time::wallTime();
    for (const auto& type : solvers) {
      Teuchos::ParameterList sl;
      sl.set("Type", type);
      auto solver = sc::solvers::createDirectSolver(sl);
      solver->setSymmetric(true);
      auto x = assembler.createVector();
      solver->setOperator(assembler.matrix());
      solver->solve(*assembler.rhs(), *x);
      const auto& st = solver->lastSolveStats();
      if (comm->getRank() == 0)
        std::printf("  %10lld %9d %12.3f %12.3f %12.3g %-6s %9.3f %9.3f %9.3f %10.2e %9.0f\n",
                    space->numGlobalDofs(), m->numElements(), t1 - t0, t2 - t1,
                    space->numGlobalDofs() / (t2 - t1) / comm->getSize(), type.c_str(),
                    st.symbolicSeconds, st.numericSeconds, st.solveSeconds, st.relativeResidual,
                    peakMemoryMB());
      std::fflush(stdout);
    }
    refiner->refineUniformly();
  }
  return 0;
}

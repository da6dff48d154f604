#pragma once
// Shared by the assembly tests: solve a verification problem (an exact solution with Dirichlet
// data on some sides and tractions on the others) on a scene mesh with uniform refinements.
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/assembly/MixedElasticitySystem.hpp>
#include <sc/solvers/StressHierarchy.hpp>
#include <sc/core/ExactSolution.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/Partitioning.hpp>
#include <sc/mesh/SimplexMesh.hpp>
#include <sc/solvers/LinearSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

namespace sc::test {

struct LevelResult {
  double h = 0.0;
  long long dofs = 0;
  assembly::ErrorNorms errors;
  int iterations = -1;  ///< Krylov iterations (Iterative solver), -1 for direct solvers
  double relativeResidual = 0.0;
};

struct VerificationSetup {
  std::string source = "Unit square";
  std::string file;  ///< Mesh/File, for source = "Gmsh file" or "Gmsh geometry"
  int dim = 2;
  double meshSize = 0.5;
  int levels = 1;
  int initialRefinements = 0;  ///< uniform refinements of the Gmsh mesh before the first level
  int degree = 1;
  double nu = 0.3;
  double E = 1.0;
  std::string exact = "Manufactured smooth";
  double wavenumber = M_PI;     ///< ω of the manufactured solution
  std::string solver = "KLU2";  ///< Linear Solver/Type: KLU2, MUMPS, Iterative
  /// Extra entries of the "Linear Solver" list (e.g. the Iterative sublist).
  Teuchos::ParameterList solverOptions;
  /// Keep the nested hierarchy (prolongations, smoother patches) for Stress block = Multigrid: the
  /// initial mesh is the coarsest level and level 0 is its first uniform refinement.
  bool multigrid = false;
  /// false: level l is the previous level refined uniformly (bisection); true: level l is a new
  /// Gmsh mesh of size meshSize / 2^l (same element quality on every level).
  bool remesh = false;
  /// true: every element on rank 0 (the serial partition, run on all ranks of the communicator),
  /// to compare a parallel partition with it in one run.
  bool allOnRankZero = false;
  /// Boundary conditions other than verificationBoundaryConditions (with exact = "None": a scene
  /// driven by constant data; the errors are then not computed).
  std::vector<core::BoundaryCondition> boundaryConditions;
  /// Mesh/Geometry order: 2 = quadratic elements at the scene's curved boundary parts.
  int geometryOrder = 1;
  /// Replaces the exact solution named by `exact` (e.g. one whose boundary data follow the exact
  /// geometry rather than the discrete one).
  std::shared_ptr<const core::ExactSolution> exactOverride;
};

/// Called on every level after the solve, for tests that postprocess the solution (estimator).
using LevelCallback = std::function<void(int level, const assembly::MixedElasticityAssembler&,
                                         const Tpetra::MultiVector<>& solution,
                                         const assembly::ElasticityData& data)>;

/// Boundary data: displacement from the exact solution on Left/Bottom(/Front), traction on the
/// rest.
inline core::BoundaryConditions verificationBoundaryConditions(int dim)
{
  core::BoundaryConditions bcs;
  const std::vector<std::string> dirichlet =
      dim == 2 ? std::vector<std::string>{"Left", "Bottom"}
               : std::vector<std::string>{"Left", "Bottom", "Front"};
  const std::vector<std::string> neumann = dim == 2
                                               ? std::vector<std::string>{"Right", "Top"}
                                               : std::vector<std::string>{"Right", "Top", "Back"};
  for (const auto& n : dirichlet)
    bcs.conditions.push_back({n, core::BoundaryType::Displacement, {}, true});
  for (const auto& n : neumann)
    bcs.conditions.push_back({n, core::BoundaryType::Traction, {}, true});
  return bcs;
}

inline std::vector<LevelResult>
solveVerification(const VerificationSetup& s, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                  const LevelCallback& onLevel = {})
{
  Teuchos::ParameterList meshList;
  meshList.set("Source", s.source);
  if (!s.file.empty()) meshList.set("File", s.file);
  meshList.set("Initial mesh size", s.meshSize);
  meshList.set("Uniform refinements", s.initialRefinements);
  auto refiner = mesh::MeshFactory::build(meshList, s.dim);
  core::Material material{s.E, s.nu};
  std::shared_ptr<const core::ExactSolution> exact =
      s.exactOverride ? s.exactOverride
                      : std::shared_ptr<const core::ExactSolution>(
                            core::createExactSolution(s.exact, s.dim, material, s.wavenumber));
  Teuchos::ParameterList solverList(s.solverOptions);
  solverList.set("Type", s.solver);
  auto solver = solvers::createLinearSolver(solverList);
  std::vector<LevelResult> results;
  solvers::StressHierarchy hierarchy(s.degree, comm);
  if (s.multigrid) hierarchy.addMesh(refiner->mesh(), {});
  for (int level = 0; level < s.levels; ++level) {
    const mesh::RefinementStep* step = nullptr;
    if (s.multigrid) {
      step = &refiner->refineUniformly();
    } else if (level > 0 && s.remesh) {
      meshList.set("Initial mesh size", s.meshSize / std::pow(2.0, level));
      refiner = mesh::MeshFactory::build(meshList, s.dim);
    } else if (level > 0) {
      refiner->refineUniformly();
    }
    auto m = refiner->mesh();
    Teuchos::RCP<const mesh::CurvedElements> curved;
    if (s.geometryOrder == 2)
      curved = Teuchos::rcp(new mesh::CurvedElements(m, *refiner->geometry()));
    // The application's pipeline: partition, spaces, assembly, and the solve with the solver
    // prepared as the application prepares it (physical scaling; block structure for Krylov).
    auto system =
        s.allOnRankZero
            ? std::make_unique<assembly::MixedElasticitySystem>(
                  m, s.degree, std::vector<int>(m->numElements(), 0), comm, curved)
            : std::make_unique<assembly::MixedElasticitySystem>(m, s.degree, comm, curved);
    const auto& space = system->space();
    if (s.multigrid) hierarchy.addMesh(m, step->elementParent);
    assembly::ElasticityData data{material, verificationBoundaryConditions(s.dim), exact.get()};
    if (!s.boundaryConditions.empty()) data.boundaryConditions.conditions = s.boundaryConditions;
    system->assemble(data);
    const auto& assembler = system->assembler();
    auto x = system->solve(*solver, s.multigrid ? hierarchy.levels(space)
                                                : std::vector<solvers::MultigridLevel>{});
    LevelResult r;
    r.iterations = solver->lastSolveStats().iterations;
    r.relativeResidual = solver->lastSolveStats().relativeResidual;
    // Effective mesh size (|Ω|/#elements)^{1/d}: uniform bisection shrinks it by exactly 2 per
    // level, unlike the largest diameter (3D bisection leaves long edges for a while).
    r.h = std::pow(m->measure() / m->numElements(), 1.0 / s.dim);
    r.dofs = space.numGlobalDofs();
    if (exact) r.errors = assembly::computeErrors(assembler, *x, *exact, *comm);
    if (onLevel) onLevel(level, assembler, *x, data);
    results.push_back(r);
  }
  return results;
}

/// Least-squares slope of log(error) against log(h).
inline double fittedRate(const std::vector<LevelResult>& r, double assembly::ErrorNorms::*field)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int n = static_cast<int>(r.size());
  for (const auto& l : r) {
    const double x = std::log(l.h), y = std::log(l.errors.*field);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace sc::test

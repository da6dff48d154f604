#pragma once
// The mixed elasticity system on one mesh: the pipeline mesh → partition → space → assembler →
// solve that the application, the tests and the benchmarks share, so that a test exercises
// what users run (docs/architecture.md "One pipeline").
//
//   sc::assembly::MixedElasticitySystem system(mesh, degree, comm, curved);  // METIS, DOFs
//   system.assemble({material, boundaryConditions, exact});  // graph (first call), matrix, rhs
//   auto solver = sc::solvers::createLinearSolver(linearSolverList);
//   Teuchos::RCP<Tpetra::MultiVector<>> x = system.solve(*solver);   // the symmetric system
//
// A contact solve builds on the same system and takes the solver prepared from it:
//
//   sc::contact::ActiveSetSolver contact(system.space(), settings, material, names, newton, comm);
//   system.prepareSolver(*solver);            // scaling D and (Krylov) the block structure
//   auto x = system.assembler().createVector();
//   contact.solve(*system.assembler().matrix(), *system.assembler().rhs(), *solver, *x);
//
// Timing: with a core::PhaseTimers the steps are timed as the application's phases
// "partition" (METIS), "numbering" (the spaces and the DOF numbering), "setup" (the assembler's
// maps and graph), "assemble" and "solve"; without one, time the calls (the constructor,
// setupAssembler, assemble, solve).
#include <memory>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/solvers/LinearSolver.hpp>

namespace sc::core {
class PhaseTimers;
}
namespace sc::mesh {
class SimplexMesh;
class CurvedElements;
}  // namespace sc::mesh

namespace sc::assembly {

class MixedElasticitySystem {
public:
  /// Partition `mesh` over the ranks of `comm` with METIS (mesh::partitionElements; collective,
  /// the same partition on every rank) and number the DOFs of RT_k × DP_k × CP_k, k = `degree`.
  /// `curved` (Mesh/Geometry order = 2): the quadratic elements at curved boundaries, or null.
  MixedElasticitySystem(Teuchos::RCP<const mesh::SimplexMesh> mesh, int degree,
                        Teuchos::RCP<const Teuchos::Comm<int>> comm,
                        Teuchos::RCP<const mesh::CurvedElements> curved = Teuchos::null,
                        core::PhaseTimers* timers = nullptr);
  /// The same on a given partition: `elementOwner[e]` is the rank that owns element e.
  MixedElasticitySystem(Teuchos::RCP<const mesh::SimplexMesh> mesh, int degree,
                        std::vector<int> elementOwner, Teuchos::RCP<const Teuchos::Comm<int>> comm,
                        Teuchos::RCP<const mesh::CurvedElements> curved = Teuchos::null,
                        core::PhaseTimers* timers = nullptr);
  ~MixedElasticitySystem();
  MixedElasticitySystem(const MixedElasticitySystem&) = delete;
  MixedElasticitySystem& operator=(const MixedElasticitySystem&) = delete;

  /// Build the assembler (maps, importer, the graph of this rank's owned rows). assemble()
  /// does it when it has not been done; call it first to time the graph on its own or to look
  /// at the DOF count before paying for it.
  void setupAssembler();
  /// Assemble the matrix and right-hand side; keeps `data.material` for the scaling (2μ).
  void assemble(const ElasticityData& data);

  /// Hand `solver` the physical block scaling D = physicalScaling(2μ) (√(2μ) on σ, 1/√(2μ) on
  /// u and θ: robust in E) and, for a Krylov solver, the BlockStructure its block preconditioner
  /// needs (field sizes, 2μ, the u and θ mass matrices, and `multigrid`, the nested hierarchy of
  /// `Stress block` = Multigrid). After assemble(), before the solver's setOperator; the one
  /// place where a solver is prepared for this system.
  void prepareSolver(solvers::LinearSolver& solver,
                     std::vector<solvers::MultigridLevel> multigrid = {}) const;
  /// Solve the elasticity system without contact rows, which is symmetric (tractions are
  /// eliminated symmetrically): prepareSolver, setOperator(matrix, symmetric = true), solve from
  /// x = 0. Returns x on the owned map. Throws ConvergenceError as LinearSolver::solve does.
  Teuchos::RCP<MultiVector> solve(solvers::LinearSolver& solver,
                                  std::vector<solvers::MultigridLevel> multigrid = {}) const;

  const mesh::SimplexMesh& mesh() const;
  const Teuchos::RCP<const Teuchos::Comm<int>>& comm() const { return comm_; }
  /// Owning rank of every element (the partition).
  const std::vector<int>& elementOwner() const { return elementOwner_; }
  const disc::MixedElasticitySpace& space() const { return *space_; }
  Teuchos::RCP<const disc::MixedElasticitySpace> spacePtr() const { return space_; }
  /// The assembler (InternalError before setupAssembler or assemble).
  const MixedElasticityAssembler& assembler() const;
  /// The material of the last assemble() (InternalError before it).
  const core::Material& material() const;

private:
  void setupSpace(Teuchos::RCP<const mesh::SimplexMesh> mesh, int degree,
                  Teuchos::RCP<const mesh::CurvedElements> curved);

  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  core::PhaseTimers* timers_ = nullptr;  ///< optional, not owned
  std::vector<int> elementOwner_;
  Teuchos::RCP<const disc::MixedElasticitySpace> space_;
  std::unique_ptr<MixedElasticityAssembler> assembler_;
  core::Material material_;
  bool assembled_ = false;
};

}  // namespace sc::assembly

#include "sc/assembly/MixedElasticitySystem.hpp"

#include <optional>
#include <string>
#include <utility>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/Timers.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/Partitioning.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::assembly {
namespace {

/// A phase scope of the optional timers (nothing without them).
class OptionalPhase {
public:
  OptionalPhase(core::PhaseTimers* timers, const char* name)
  {
    if (timers) scope_.emplace(*timers, name);
  }

private:
  std::optional<core::PhaseTimers::Scope> scope_;
};

}  // namespace

MixedElasticitySystem::MixedElasticitySystem(Teuchos::RCP<const mesh::SimplexMesh> mesh, int degree,
                                             Teuchos::RCP<const Teuchos::Comm<int>> comm,
                                             Teuchos::RCP<const mesh::CurvedElements> curved,
                                             core::PhaseTimers* timers)
    : comm_(std::move(comm)), timers_(timers)
{
  {
    OptionalPhase t(timers_, "partition");
    elementOwner_ = mesh::partitionElements(*mesh, *comm_);
  }
  setupSpace(std::move(mesh), degree, std::move(curved));
}

MixedElasticitySystem::MixedElasticitySystem(Teuchos::RCP<const mesh::SimplexMesh> mesh, int degree,
                                             std::vector<int> elementOwner,
                                             Teuchos::RCP<const Teuchos::Comm<int>> comm,
                                             Teuchos::RCP<const mesh::CurvedElements> curved,
                                             core::PhaseTimers* timers)
    : comm_(std::move(comm)), timers_(timers), elementOwner_(std::move(elementOwner))
{
  setupSpace(std::move(mesh), degree, std::move(curved));
}

MixedElasticitySystem::~MixedElasticitySystem() = default;

void MixedElasticitySystem::setupSpace(Teuchos::RCP<const mesh::SimplexMesh> mesh, int degree,
                                       Teuchos::RCP<const mesh::CurvedElements> curved)
{
  OptionalPhase t(timers_, "numbering");
  space_ = Teuchos::rcp(new disc::MixedElasticitySpace(std::move(mesh), degree, elementOwner_,
                                                       comm_->getRank(), std::move(curved)));
}

void MixedElasticitySystem::setupAssembler()
{
  if (assembler_) return;
  OptionalPhase t(timers_, "setup");
  assembler_ = std::make_unique<MixedElasticityAssembler>(space_, comm_);
}

void MixedElasticitySystem::assemble(const ElasticityData& data)
{
  setupAssembler();
  OptionalPhase t(timers_, "assemble");
  assembler_->assemble(data);
  material_ = data.material;
  assembled_ = true;
}

void MixedElasticitySystem::prepareSolver(solvers::LinearSolver& solver,
                                          std::vector<solvers::MultigridLevel> multigrid) const
{
  SC_THROW_IF(!assembled_, core::InternalError,
              "MixedElasticitySystem::prepareSolver called before assemble()");
  const double twoMu = 2.0 * material_.shearModulus();
  solver.setScaling(assembler_->physicalScaling(twoMu)->getVector(0));
  if (solver.isIterative()) {
    solvers::BlockStructure blocks;
    blocks.dimension = space_->dim();
    blocks.stressDofs = space_->numStressDofs();
    blocks.displacementDofs = space_->numDisplacementDofs();
    blocks.rotationDofs = space_->numRotationDofs();
    blocks.twoMu = twoMu;
    blocks.fieldMass = assembler_->fieldMassMatrix();
    blocks.multigrid = std::move(multigrid);
    solver.setBlockStructure(blocks);
  }
}

Teuchos::RCP<MultiVector>
MixedElasticitySystem::solve(solvers::LinearSolver& solver,
                             std::vector<solvers::MultigridLevel> multigrid) const
{
  OptionalPhase t(timers_, "solve");
  prepareSolver(solver, std::move(multigrid));
  solver.setOperator(assembler_->matrix(), true);
  auto x = assembler_->createVector();
  solver.solve(*assembler_->rhs(), *x);
  return x;
}

const mesh::SimplexMesh& MixedElasticitySystem::mesh() const { return space_->mesh(); }

const MixedElasticityAssembler& MixedElasticitySystem::assembler() const
{
  SC_THROW_IF(!assembler_, core::InternalError,
              "MixedElasticitySystem::assembler() called before setupAssembler() or assemble()");
  return *assembler_;
}

const core::Material& MixedElasticitySystem::material() const
{
  SC_THROW_IF(!assembled_, core::InternalError,
              "MixedElasticitySystem::material() called before assemble()");
  return material_;
}

}  // namespace sc::assembly

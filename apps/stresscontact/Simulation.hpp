#pragma once
// One run of StressContact, in the deal.II tutorial shape: a constructor that reads and checks
// everything, then run() = for each cycle { refine, solve, estimate, mark, output }, until a
// stop criterion of sc::adapt holds (Cycles, Max DOFs, Target error).
//
// What each cycle does depends on what the scene needs (docs/theory.md): no contact machinery
// without a Contact boundary, no friction rows when the law is None or μ_F = 0. Phases that do
// not exist yet (the contact terms of the estimator, η_CF) are reported as absent in
// summary.json ("phases_missing"), never faked: a contact scene is not estimated and can only be
// refined uniformly.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_MultiVector_fwd.hpp>

#include <sc/adapt/AdaptivitySettings.hpp>
#include <sc/core/Progress.hpp>
#include <sc/core/ProblemData.hpp>
#include <sc/core/Timers.hpp>
#include <sc/estimator/EstimatorSettings.hpp>
#include <sc/io/OutputSettings.hpp>
#include <sc/mesh/ResourceEstimate.hpp>

namespace sc::mesh {
class SimplexMesh;
class BisectionRefiner;
}  // namespace sc::mesh
namespace sc::io {
class CheckpointFile;
class RunSummary;
class XdmfWriter;
}  // namespace sc::io
namespace sc::disc {
class MixedElasticitySpace;
}
namespace sc::assembly {
class MixedElasticityAssembler;
}
namespace sc::solvers {
class LinearSolver;
}
namespace sc::core {
class ExactSolution;
}
namespace sc::estimator {
class ErrorEstimator;
struct ErrorEstimate;
}  // namespace sc::estimator
namespace sc::adapt {
class Marker;
class StopCriteria;
}  // namespace sc::adapt
namespace sc::contact {
class ActiveSetSolver;
struct ContactPoint;
}

namespace sc::app {

/// A prescribed displacement above this fraction of the body's size (bounding-box diagonal)
/// draws a small-strain warning.
inline constexpr double kLargeDisplacementFraction = 0.05;

class Simulation {
public:
  /// Reads the validated parameter list; throws InputError for combinations that this build
  /// cannot run (e.g. contact at an unsupported degree, no Displacement boundary), before any
  /// work.
  Simulation(Teuchos::RCP<const Teuchos::Comm<int>> comm,
             Teuchos::RCP<Teuchos::ParameterList> params, std::string deckPath, bool quiet);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// `--check`: build the initial mesh and check the boundary conditions against it. Writes
  /// nothing.
  void checkScene();
  /// All cycles; writes summary.json after each cycle and XDMF output.
  void run();

  /// `--restart DIR`: run() continues the run whose output directory (this run's Output/Directory)
  /// is \p directory from its checkpoint (docs/adaptivity.md "Checkpoint and restart").
  void restartFrom(std::string directory) { restartDirectory_ = std::move(directory); }

private:
  void setupMesh();
  void warnIfLargeDisplacement() const;
  void refineMesh();
  void partitionMesh();
  void setupElasticity();
  /// Hand the solver the scaling and (Krylov) the block structure of the assembled system.
  void prepareSolver();
  void solveElasticity();
  void solveContact(int cycle);
  void estimate();
  /// The reason to stop after this cycle ("" = go on), then the marking for the next one.
  std::string checkStop(int cycle);
  /// After marking: "" or the reason to stop because the next mesh would exceed the memory
  /// limit (estimated from the marked elements and the current DOFs per element).
  std::string checkNextMesh() const;
  void mark();
  void writeFields(int cycle);
  void recordCycle(int cycle);
  /// The cycle's timings and peak memory into summary.json, and its one-line progress summary.
  void recordCost();

  // Checkpoint/restart (SimulationCheckpoint.cpp; issue #12, item 7).
  /// Collective: after cycle `cycle` is complete (summary written), write checkpoint.h5.
  void writeCheckpoint(int cycle);
  /// Collective, before anything is written: read the checkpoint of restartDirectory_, check it
  /// belongs to this deck, restore the refiner (mesh of its cycle), the marked elements and the
  /// contact state. Returns the cycle to continue with.
  int readCheckpoint();
  /// After the output directory is set up: the checkpoint's summary cycles and XDMF steps.
  void restoreOutputs();
  /// SC_KILL_IN_CYCLE (test only): kill the process in that cycle, after its fields are written.
  void killIfAsked(int cycle) const;

  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  Teuchos::RCP<Teuchos::ParameterList> params_;
  std::string deckPath_;

  // Scene data and method settings (read once, in the constructor).
  core::ProblemSettings problem_;
  core::Material material_;
  core::BoundaryConditions boundaryConditions_;
  core::ContactSettings contact_;
  core::DiscretizationSettings discretization_;
  estimator::EstimatorSettings estimatorSettings_;
  adapt::AdaptivitySettings adaptivity_;
  io::OutputSettings output_;

  core::Progress progress_;
  core::PhaseTimers timers_;

  Teuchos::RCP<mesh::BisectionRefiner> refiner_;  ///< owns the mesh hierarchy
  mesh::ResourceLimit limit_;  ///< Mesh/Memory limit (GB) or the available memory (rank 0's)
  Teuchos::RCP<const mesh::SimplexMesh> mesh_;      ///< the current mesh
  std::vector<int> elementOwner_;  ///< METIS partition: owning rank of each element
  std::vector<std::string> phasesMissing_;
  std::unique_ptr<adapt::Marker> marker_;
  std::unique_ptr<adapt::StopCriteria> stop_;

  // Mixed elasticity (no contact boundary): spaces, system, solver, solution of the cycle.
  std::unique_ptr<core::ExactSolution> exact_;
  Teuchos::RCP<disc::MixedElasticitySpace> space_;
  std::unique_ptr<assembly::MixedElasticityAssembler> assembler_;
  Teuchos::RCP<solvers::LinearSolver> solver_;
  std::vector<int> linearIterations_;  // Krylov iterations per solve of the current cycle
  Teuchos::RCP<Tpetra::MultiVector<>> solution_;
  bool solved_ = false;

  // Estimate and marking of the cycle (elasticity scenes).
  std::unique_ptr<estimator::ErrorEstimator> estimator_;
  std::unique_ptr<estimator::ErrorEstimate> estimate_;
  double stressEnergyError_ = -1.0;  ///< ‖A^{1/2}(σ − σ_h)‖ when the exact solution is known
  std::vector<int> marked_;          ///< elements to bisect for the next cycle
  std::string stopReason_;

  // Contact (a boundary of Type Contact): the active-set solver of the cycle and the points of
  // the previous cycle (nested iteration: the next cycle starts from their state).
  std::unique_ptr<contact::ActiveSetSolver> contactSolver_;
  std::vector<contact::ContactPoint> previousPoints_;
  /// For every face of the current mesh, the boundary face of the previous mesh that contains it
  /// (-1 off the boundary), from the last refinement step; empty without one (first cycle).
  std::vector<int> contactFaceParents_;

  std::unique_ptr<io::RunSummary> summary_;
  std::unique_ptr<io::XdmfWriter> writer_;

  // Restart: the directory, the checkpoint read from it, and the linear solver's counts before
  // it (summary.json counts symbolic reuses and preconditioner set-ups over the run).
  std::string restartDirectory_;
  std::unique_ptr<io::CheckpointFile> checkpoint_;
  long long symbolicReusesBefore_ = 0;
  long long preconditionerSetupsBefore_ = 0;
};

}  // namespace sc::app

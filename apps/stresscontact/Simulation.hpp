#pragma once
// One run of StressContact, in the deal.II tutorial shape: a constructor that reads and checks
// everything, then run() sets up the output (directory, summary.json, restart) and hands itself
// to sc::adapt::AdaptiveLoop, which calls the named steps of adapt::AdaptiveProblem for each
// cycle { refine, solve, estimate, (mark), output, checkpoint } until a stop criterion holds
// (Cycles, Max DOFs, Target error, the memory forecast of the next mesh).
//
// Simulation.cpp holds the steps, one function each; what they rely on lives beside it: the
// deck read once and its combinations checked (RunSettings.cpp), the scene checked against the
// initial mesh (SimulationChecks.cpp), the load steps (SimulationLoadSteps.cpp), checkpoint and
// restart (SimulationCheckpoint.cpp), and the output step's recorder and field writer
// (RunRecorder.cpp, FieldWriter.cpp, from a CycleResults value).
//
// What each cycle does depends on what the scene needs (docs/theory.md): no contact machinery
// without a Contact boundary, no friction rows when the law is None or μ_F = 0. Every scene is
// estimated (η without contact, η_CF with the contact and friction parts) and can be refined by
// any marking. summary.json keeps the list "phases_missing" for phases this build cannot run;
// it is empty now (a phase that is missing is reported there, never faked).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_MultiVector_fwd.hpp>

#include <sc/adapt/AdaptiveProblem.hpp>
#include <sc/contact/BalancedStopping.hpp>
#include <sc/contact/ContactSettings.hpp>
#include <sc/core/Progress.hpp>
#include <sc/core/ProblemData.hpp>
#include <sc/core/Timers.hpp>
#include <sc/mesh/ResourceEstimate.hpp>
#include <sc/solvers/SolveStatistics.hpp>

#include "RunSettings.hpp"

namespace sc::mesh {
class SimplexMesh;
class BisectionRefiner;
}  // namespace sc::mesh
namespace sc::io {
class CheckpointFile;
class OutputLock;
class RunSummary;
class XdmfWriter;
}  // namespace sc::io
namespace sc::disc {
class MixedElasticitySpace;
}
namespace sc::assembly {
class MixedElasticityAssembler;
class MixedElasticitySystem;
}  // namespace sc::assembly
namespace sc::solvers {
class LinearSolver;
struct MultigridLevel;
class SolverPolicy;
class StressHierarchy;
}  // namespace sc::solvers
namespace sc::core {
class ExactSolution;
}
namespace sc::estimator {
class ErrorEstimator;
}
namespace sc::adapt {
class AdaptiveLoop;
}
namespace sc::contact {
class ContactProblem;
}

namespace sc::app {

struct CycleResults;
class RunRecorder;

class Simulation : public adapt::AdaptiveProblem {
public:
  /// Reads the validated parameter list; throws InputError for combinations that this build
  /// cannot run (e.g. contact at an unsupported degree, no Displacement boundary), before any
  /// work.
  Simulation(Teuchos::RCP<const Teuchos::Comm<int>> comm,
             Teuchos::RCP<Teuchos::ParameterList> params, std::string deckPath, bool quiet);
  ~Simulation() override;
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// `--check`: build the initial mesh and check the boundary conditions against it. Writes
  /// nothing.
  void checkScene();
  /// All cycles (adapt::AdaptiveLoop over the steps below); writes summary.json after each cycle
  /// and XDMF output.
  void run();

  /// `--restart DIR`: run() continues the run whose output directory (this run's Output/Directory)
  /// is \p directory from its checkpoint (docs/adaptivity.md "Checkpoint and restart").
  void restartFrom(std::string directory) { restartDirectory_ = std::move(directory); }

private:
  // The steps of adapt::AdaptiveProblem, called by the loop (AdaptiveLoop.hpp for their order).
  /// Bisect the marked elements (or every element, uniformly), then compute the parents of the
  /// new boundary faces for the contact state's transfer and forget the refinement history.
  void refine(const adapt::Marking& marking) override;
  /// Partition, set up, assemble and solve (elasticity, or the contact Newton loop); starts the
  /// cycle's results_ with the solver's and the contact's record.
  void solve(int cycle) override;
  /// Reconstruction and η (η_CF with contact), the errors against an exact solution, then the
  /// rest of results_ (forces, mesh record, fields); the DOFs, η, ‖A^{1/2}σ_h‖ and η_T² for the
  /// loop.
  adapt::CycleEstimate estimate(int cycle) override;
  /// The next mesh's DOFs and bytes against the memory limit (estimated from the marked
  /// elements and the current DOFs per element); no limit when none is active.
  adapt::NextMeshForecast forecastNextMesh(const adapt::Marking& marking) const override;
  /// results_ into the contact CSV, the fields (XDMF), the cycle's summary record and cost,
  /// summary.json and history.csv.
  void output(int cycle, const adapt::Marking& marking, const std::string& stopReason) override;
  /// checkpoint.h5, timed into summary.json's "checkpoint" phase.
  void checkpoint(int cycle, const adapt::Marking& marking) override;

  /// The initial mesh (within the memory limit), the scene checked against it, and the contact
  /// problem of a scene with contact.
  void setupMesh();
  /// The contact problem that lives across the cycles (`contactHoldsBody`: no support holds the
  /// body along the obstacle's normal but the contact).
  void setupContactProblem(bool contactHoldsBody);
  /// The cycle's assembly::MixedElasticitySystem: partition, spaces, assembled matrix.
  void setupElasticity();
  void solveElasticity();
  /// The stress-block multigrid levels for this cycle's space (empty without hierarchy_).
  std::vector<solvers::MultigridLevel> multigridLevels();
  void solveContact();
  /// The solved cycle's DOFs, linear solver and contact state (with the Hertz comparison) into
  /// *results_.
  void recordSolve();
  /// The reconstruction and estimate of the cycle (none if nothing was solved), and the errors
  /// against the exact solution when there is one, into results_.
  void estimateError();
  /// The reactions and force balance, the mesh record and (with XDMF output) the fields of the
  /// cycle into results_.
  void collectResults();

  /// run(): the output directory taken (under `lock`) and emptied of an earlier run's files (a
  /// restart: of the files after its checkpoint's cycle), summary.json, the recorder and the
  /// field writer.
  void openOutput(int firstCycle, const io::OutputLock& lock);

  // The scene against the initial mesh (SimulationChecks.cpp).
  /// Boundary names, supports, curved contact faces, the obstacle at every load step, an element
  /// per rank, and the warnings; returns whether only the contact holds the body along the
  /// obstacle's normal.
  bool checkSceneOnMesh();
  void checkObstacleAtEveryLoadStep();
  void warnIfLargeDisplacement() const;
  /// After a contact solve with no point in contact: a warning (once per run).
  void warnIfNoContact();

  // Load steps (SimulationLoadSteps.cpp; docs/theory.md §"Load steps").
  /// Load step `step` (0-based): the step's boundary values, body force, obstacle position and
  /// formula time become current.
  void applyLoadStep(int step);
  /// The load steps from resume_ (the first, or a checkpoint's), each an adaptive loop from
  /// cycle `firstCycle` with the checkpoint's `marked` elements when it continues a step;
  /// returns the last loop's stop reason.
  std::string runLoadSteps(int firstCycle, std::vector<int> marked);
  /// The current cycle's load step, its prescribed values and the 2D stick zone's ends into its
  /// summary record.
  void recordLoadStep();

  // Checkpoint/restart (SimulationCheckpoint.cpp; docs/adaptivity.md "Checkpoint and restart").
  /// Collective: after cycle `cycle` is complete (summary written), write checkpoint.h5 with the
  /// elements `marked` for the next cycle, the load step (loadStep_, stepFirstCycle_; with
  /// `stepComplete` the cycle was the step's last, and the next cycle starts the next step) and
  /// the contact points with their friction history.
  void writeCheckpoint(int cycle, const std::vector<int>& marked, bool stepComplete);
  /// Collective, before anything is written: read the checkpoint of restartDirectory_, check it
  /// belongs to this deck, restore the refiner (mesh of its cycle), the marked elements (into
  /// `marked`), the contact state and where the load steps go on (resume_). Returns the cycle to
  /// continue with.
  int readCheckpoint(std::vector<int>& marked);
  /// checkpoint(): the checkpoint written and its time put into the cycle's summary record.
  void timedCheckpoint(int cycle, const std::vector<int>& marked, bool stepComplete);
  /// After the output directory is set up: the checkpoint's summary cycles and XDMF steps.
  void restoreOutputs();
  /// SC_KILL_IN_CYCLE (test only): kill the process in that cycle, after its fields are written.
  void killIfAsked(int cycle) const;

  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  Teuchos::RCP<Teuchos::ParameterList> params_;
  std::string deckPath_;

  /// The deck, read once (RunSettings.hpp).
  RunSettings settings_;

  // The current load step: its conditions, body force and contact settings (the obstacle at the
  // step), its number (0-based) and the (run-wide) number of its first cycle.
  core::BoundaryConditions boundaryConditions_;
  core::BodyForce bodyForce_;
  contact::ContactSettings contact_;
  int loadStep_ = 0;
  int stepFirstCycle_ = 0;
  /// Where run() starts (a restart: the checkpoint's load step): the step, the number of its
  /// first cycle, and whether the first cycle run starts that step (its friction history is
  /// then committed from the previous step's state) or continues it.
  struct Resume {
    int step = 0;
    int stepFirstCycle = 0;
    bool startsStep = false;
  } resume_;
  /// The loop of the load steps after the first (Load steps/Cycles per later step cycles).
  std::unique_ptr<adapt::AdaptiveLoop> laterStepLoop_;
  bool warnedNoContact_ = false;
  int lastCycle_ = -1;  ///< the last cycle output (numbered through the load steps)

  core::Progress progress_;
  core::PhaseTimers timers_;

  Teuchos::RCP<mesh::BisectionRefiner> refiner_;  ///< owns the mesh hierarchy
  mesh::ResourceLimit limit_;  ///< Mesh/Memory limit (GB) or the available memory (rank 0's)
  Teuchos::RCP<const mesh::SimplexMesh> mesh_;  ///< the current mesh
  std::vector<int> elementOwner_;  ///< METIS partition: owning rank of each element (system_'s)
  std::vector<std::string> phasesMissing_;  ///< phases this build cannot run (none now)
  std::vector<std::string> warnings_;       ///< warnings of the run (summary.json "warnings")
  /// The cycle loop with its marker and stop criteria (built in the constructor so that bad
  /// Adaptivity values fail before any work).
  std::unique_ptr<adapt::AdaptiveLoop> loop_;

  // Mixed elasticity: the cycle's system (partition, spaces, assembled matrix, built by the
  // pipeline the tests and benchmarks share), solver and solution.
  std::unique_ptr<core::ExactSolution> exact_;
  std::unique_ptr<assembly::MixedElasticitySystem> system_;
  Teuchos::RCP<const disc::MixedElasticitySpace> space_;           ///< system_'s space
  const assembly::MixedElasticityAssembler* assembler_ = nullptr;  ///< system_'s assembler
  Teuchos::RCP<solvers::LinearSolver> solver_;
  /// Linear Solver/Iterative/Stress block = Multigrid, or Type = Auto on a 3D scene without
  /// contact: the meshes of the run (initial mesh and every refinement, or the restored mesh
  /// after a restart), from which the multigrid levels are chosen each cycle; null otherwise.
  std::unique_ptr<solvers::StressHierarchy> hierarchy_;
  /// Linear Solver/Type = Auto: solver_ is chosen per cycle; autoType_ = its resolved Type.
  std::string autoType_;
  std::vector<int> linearIterations_;  // Krylov iterations per solve of the current cycle
  Teuchos::RCP<Tpetra::MultiVector<>> solution_;
  bool solved_ = false;

  // Estimate of the cycle.
  std::unique_ptr<estimator::ErrorEstimator> estimator_;

  /// What the cycle produced, for the output step (started by solve, completed by estimate).
  std::unique_ptr<CycleResults> results_;

  // Contact (a boundary of Type Contact): the problem that lives across the cycles, with the
  // points and their transfer to the next mesh and load step (null without contact).
  std::unique_ptr<contact::ContactProblem> contactProblem_;
  /// Contact/Newton/Stopping (contact/BalancedStopping.hpp): kept across cycles, it carries η of
  /// the cycle before (none in the first cycle of a run, a restart or a load step).
  contact::BalancedStopping balancedStopping_;

  std::unique_ptr<io::RunSummary> summary_;
  std::unique_ptr<RunRecorder> recorder_;  ///< records results_ into summary_ and the CSVs
  std::unique_ptr<io::XdmfWriter> writer_;

  // Restart: the directory, the checkpoint read from it, and the linear solver's counts before
  // it (summary.json counts symbolic reuses and preconditioner set-ups over the run).
  std::string restartDirectory_;
  std::unique_ptr<io::CheckpointFile> checkpoint_;
  long long symbolicReusesBefore_ = 0;
  long long preconditionerSetupsBefore_ = 0;
  /// The solver's statistics when the cycle's solve began (its seconds per part are the
  /// difference).
  solvers::SolveStatistics solverBefore_;
};

}  // namespace sc::app

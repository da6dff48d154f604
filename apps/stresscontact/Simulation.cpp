#include "Simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <Teuchos_Time.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/adapt/AdaptiveLoop.hpp>
#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/assembly/MixedElasticitySystem.hpp>
#include <sc/solvers/StressHierarchy.hpp>
#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/contact/ContactConstraints.hpp>
#include <sc/contact/ContactProblem.hpp>
#include <sc/contact/ContactSummary.hpp>
#include <sc/contact/Hertz.hpp>
#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/ExactSolution.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/estimator/ContactContribution.hpp>
#include <sc/estimator/DisplacementReconstruction.hpp>
#include <sc/estimator/ErrorEstimator.hpp>
#include <sc/io/CheckpointFile.hpp>
#include <sc/solvers/LinearSolver.hpp>
#include <sc/solvers/SolverPolicy.hpp>
#include <sc/io/OutputDirectory.hpp>
#include <sc/io/OutputLock.hpp>
#include <sc/io/RunSummary.hpp>
#include <sc/io/XdmfWriter.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "ContactFields.hpp"
#include "CycleResults.hpp"
#include "DeckParameters.hpp"
#include "EstimatedErrors.hpp"
#include "FieldWriter.hpp"
#include "ForceBalance.hpp"
#include "RunRecorder.hpp"

namespace sc::app {

Simulation::Simulation(Teuchos::RCP<const Teuchos::Comm<int>> comm,
                       Teuchos::RCP<Teuchos::ParameterList> params, std::string deckPath,
                       bool quiet)
    : comm_(std::move(comm)), params_(std::move(params)), deckPath_(std::move(deckPath)),
      settings_(readRunSettings(*params_, comm_->getRank(), comm_->getSize())),
      progress_(comm_, std::cout, quiet), timers_(comm_)
{
  warnings_ = settings_.warnings;
  balancedStopping_ = settings_.balancedStopping;
  applyLoadStep(0);  // the run starts with step 1's data
  if (settings_.solverPolicy->needsHierarchy())
    hierarchy_ = std::make_unique<solvers::StressHierarchy>(settings_.discretization.degree, comm_);
  loop_ = std::make_unique<adapt::AdaptiveLoop>(settings_.adaptivity, comm_, &progress_, &timers_);
  if (settings_.loadSteps.numSteps() > 1) {
    adapt::AdaptivitySettings later = settings_.adaptivity;
    later.cycles = settings_.loadSteps.cyclesPerLaterStep;
    laterStepLoop_ = std::make_unique<adapt::AdaptiveLoop>(later, comm_, &progress_, &timers_);
  }
  exact_ = core::createExactSolution(settings_.problem.exactSolution, settings_.problem.dimension,
                                     settings_.material, settings_.problem.manufacturedWavenumber);
  for (const auto& bc : settings_.conditions.conditions)
    SC_THROW_IF(bc.fromExactSolution && !exact_, core::InputError,
                "'Boundary Conditions/"
                    << bc.boundary << "/Data' = 'Exact solution' needs "
                    << "'Problem/Exact solution' (valid: 'Manufactured smooth', 'Linear patch'), "
                    << "but it is 'None'.");
  // Type = Auto: resolved per cycle from the system's size (setupElasticity); MUMPS until then.
  solver_ = settings_.solverPolicy->create(0);
}

Simulation::~Simulation() = default;

void Simulation::setupMesh()
{
  auto t = timers_.scope("mesh");
  // The memory limit: Mesh/Memory limit (GB), or rank 0's available memory, the same on every
  // rank so that the estimates of MeshFactory and of the adaptive steps agree (docs/mesh.md).
  double available = 0.0;
  std::string source;
  if (comm_->getRank() == 0) available = mesh::availableMemoryBytes(&source);
  core::broadcast(*comm_, 0, available);
  core::broadcast(*comm_, 0, source);
  // The program's own memory before any mesh, on all ranks: a Memory limit counts it too.
  const double baseline = core::sumOverRanks(*comm_, mesh::residentMemoryBytes());
  limit_ = mesh::makeResourceLimit(settings_.mesh.memoryLimitGB, settings_.problem.dimension,
                                   settings_.discretization.degree, comm_->getSize(),
                                   settings_.adaptivity.maxDofs, available, source, baseline);
  limit_.contact = boundaryConditions_.hasContact();  // 3D contact: LU factors, N^(4/3)
  // Type = Auto solves 3D contact systems from a threshold on with the multigrid: its memory
  // model there, not MUMPS' (docs/mesh.md "Resource limits"), with Coulomb friction plus the
  // basis of GMRES (the slip steps are non-symmetric), which Belos allocates whole.
  if (const long long from = settings_.solverPolicy->autoIterativeFrom(); from >= 0) {
    limit_.multigridFromDofs = static_cast<double>(from);
    if (settings_.contact.frictionLaw == contact::FrictionLaw::Coulomb)
      limit_.multigridBytesPerDof += 8.0 * settings_.solverPolicy->gmresBasisVectors();
  }
  // Rank 0 runs Gmsh and broadcasts: every rank holds the bit-identical mesh.
  refiner_ = mesh::MeshFactory::build(settings_.mesh, settings_.problem.dimension, *comm_,
                                      /*splitBoundarySimplices=*/false, limit_);
  mesh_ = refiner_->mesh();
  if (hierarchy_) hierarchy_->addMesh(mesh_, {});
  const bool contactHoldsBody = checkSceneOnMesh();
  if (boundaryConditions_.hasContact()) setupContactProblem(contactHoldsBody);
  progress_.report("mesh", std::to_string(mesh_->numElements()) + " elements, " +
                               std::to_string(mesh_->numVertices()) + " vertices");
}

void Simulation::setupContactProblem(bool contactHoldsBody)
{
  contactProblem_ = std::make_unique<contact::ContactProblem>(
      settings_.material, boundaryConditions_.boundariesOfType(core::BoundaryType::Contact), comm_);
  contactProblem_->setContactHoldsBody(contactHoldsBody);
  // Balanced: every Newton step's solve; Fixed: the final solve (contact/BalancedStopping.hpp)
  contactProblem_->setBalancedStopping(&balancedStopping_);
  contactProblem_->setStepCallback([this](int step, long long changes, double seconds) {
    std::ostringstream os;
    os << "Newton step " << step << ": " << changes << " points changed state";
    if (solver_->isIterative())
      os << ", " << solver_->lastSolveStats().iterations << " Krylov iterations";
    os << " (" << std::fixed << std::setprecision(1) << seconds << " s)";
    progress_.report("contact", os.str());
  });
}

void Simulation::refine(const adapt::Marking& marking)
{
  const long long before = mesh_->numElements();
  const Teuchos::RCP<const mesh::SimplexMesh> previous = mesh_;
  const mesh::RefinementStep* step = nullptr;
  {
    auto t = timers_.scope("refine");
    if (!marking.uniform) {
      step = &refiner_->refine(marking.elements);
    } else {
      // Uniform: dim bisections of every element (exactly ×4 in 2D), as in convergence studies.
      step = &refiner_->refineUniformly();
    }
  }
  if (contactProblem_) {
    // The contact state goes to the next mesh through the history of this step (the parent of
    // every new boundary face); then the history is forgotten, so that memory stays O(N).
    auto t = timers_.scope("transfer");
    contactProblem_->refined(*previous, *refiner_->mesh(), *step);
  }
  if (hierarchy_) hierarchy_->addMesh(refiner_->mesh(), step->elementParent);
  refiner_->forgetHistory();
  mesh_ = refiner_->mesh();
  progress_.report("refine", settings_.adaptivity.marking + ": " + std::to_string(before) + " -> " +
                                 std::to_string(mesh_->numElements()) + " elements");
}

void Simulation::solve(int cycle)
{
  results_ = std::make_unique<CycleResults>();
  results_->cycle = cycle;
  if (boundaryConditions_.hasContact())
    solveContact();
  else
    solveElasticity();
  recordSolve();
}

void Simulation::setupElasticity()
{
  // Mesh/Geometry order = 2: quadratic elements at the curved boundary (null otherwise).
  Teuchos::RCP<const mesh::CurvedElements> curved;
  {
    auto t = timers_.scope("setup");
    curved = mesh::MeshFactory::curvedElements(settings_.mesh, *refiner_);
  }
  // The pipeline shared with the tests and benchmarks: METIS partition ("partition" phase), DOF
  // numbering ("numbering") and the assembler's graph ("setup").
  system_ = std::make_unique<assembly::MixedElasticitySystem>(
      mesh_, settings_.discretization.degree, comm_, curved, &timers_);
  system_->setupAssembler();
  elementOwner_ = system_->elementOwner();
  space_ = system_->spacePtr();
  assembler_ = &system_->assembler();
  if (settings_.solverPolicy->isAuto()) {
    // Type = Auto (docs/solvers.md): the solver for this cycle's size; a new one only if the
    // choice changes.
    const std::string type = settings_.solverPolicy->typeFor(space_->numGlobalDofs());
    if (type != autoType_) {
      solver_ = settings_.solverPolicy->create(space_->numGlobalDofs());
      autoType_ = type;
      progress_.report("setup", "Linear Solver/Type = Auto: " + solver_->name() + " for " +
                                    std::to_string(space_->numGlobalDofs()) + " DOFs");
    }
  }
  progress_.report("setup", std::to_string(space_->numGlobalDofs()) + " DOFs (stress " +
                                std::to_string(space_->numStressDofs()) + ", displacement " +
                                std::to_string(space_->numDisplacementDofs()) + ", rotation " +
                                std::to_string(space_->numRotationDofs()) + ")" +
                                (curved ? ", " + std::to_string(curved->numCurvedElements()) +
                                              " curved (quadratic) elements"
                                        : std::string()));
  system_->assemble(
      {settings_.material, boundaryConditions_, exact_.get(), bodyForce_});  // "assemble" phase
  progress_.report("assemble", std::to_string(assembler_->statistics().nonzeros) + " nonzeros");
}

std::vector<solvers::MultigridLevel> Simulation::multigridLevels()
{
  // Type = Auto keeps the meshes in 3D but builds levels only for the cycles it solves with the
  // multigrid.
  if (!hierarchy_ || !settings_.solverPolicy->usesMultigrid(space_->numGlobalDofs())) return {};
  auto levels = hierarchy_->levels(*space_);
  std::ostringstream os;
  os << "stress multigrid: " << levels.size() << " level(s), elements";
  for (int i : hierarchy_->chosen())
    os << " " << hierarchy_->meshElements(i);
  progress_.report("setup", os.str());
  return levels;
}

void Simulation::solveElasticity()
{
  setupElasticity();
  linearIterations_.clear();
  // The "solve" phase: the solver gets the physical block scaling D (√(2μ) on σ, 1/√(2μ) on u,
  // θ: robust in E) and, if Krylov, the block structure; the system without contact rows is
  // symmetric (tractions are eliminated symmetrically).
  solverBefore_ = solver_->lastSolveStats();
  solution_ = system_->solve(*solver_, multigridLevels());
  if (solver_->isIterative()) linearIterations_.push_back(solver_->lastSolveStats().iterations);
  std::ostringstream os;
  os << solver_->name() << ", relative residual " << solver_->lastSolveStats().relativeResidual;
  if (solver_->isIterative()) os << ", " << solver_->lastSolveStats().iterations << " iterations";
  progress_.report("solve", os.str());
  solved_ = true;
}

void Simulation::solveContact()
{
  setupElasticity();
  {
    auto t = timers_.scope("contact setup");
    contactProblem_->setUp(*space_, contact_);  // the obstacle of the current load step
  }
  {
    // Nested iteration: the previous cycle's contact state is the Newton start, carried by the
    // refinement history (first cycle: no history, every point starts free).
    auto t = timers_.scope("transfer");
    contactProblem_->transferState();
  }
  const contact::ActiveSetSolver& contactSolver = contactProblem_->solver();
  progress_.report("contact", std::to_string(contactSolver.globalNumPoints()) +
                                  " contact points, " +
                                  (contactSolver.hasFriction() ? "with" : "without") + " friction");
  solution_ = assembler_->createVector();
  {
    auto t = timers_.scope("solve");
    solverBefore_ = solver_->lastSolveStats();
    system_->prepareSolver(*solver_, multigridLevels());
    linearIterations_.clear();
    contactProblem_->solve(*assembler_->matrix(), *assembler_->rhs(), *solver_, *solution_);
    linearIterations_ = contactSolver.statistics().linearIterationsPerStep;
  }
  const auto& st = contactSolver.statistics();
  std::ostringstream os;
  os << st.newtonIterations << " Newton steps, changes per step:";
  for (int c : st.changesPerIteration)
    os << " " << c;
  if (st.balancedBound > 0.0)
    os << "; balanced Krylov stop: tolerance " << st.krylovTolerance << ", algebraic error "
       << st.algebraicError << " (bound gamma eta = " << st.balancedBound << ")";
  if (st.finalBound > 0.0)
    os << "; final solve: " << st.finalSolveIterations
       << " more Krylov iterations, estimated algebraic error " << st.finalAlgebraicError
       << " (bound " << contact::BalancedStopping::finalFraction() << " eta = " << st.finalBound
       << ")";
  progress_.report("contact solve", os.str());
  solved_ = true;
  warnIfNoContact();
}

void Simulation::recordSolve()
{
  CycleResults& r = *results_;
  r.solved = solved_;
  if (!solved_) return;
  r.dofs = {space_->numStressDofs(), space_->numDisplacementDofs(), space_->numRotationDofs(),
            space_->numGlobalDofs()};
  LinearSolveRecord& ls = r.linearSolve.emplace();
  ls.name = solver_->name();
  ls.iterative = solver_->isIterative();
  ls.last = solver_->lastSolveStats();
  ls.cycleEquilibrationSeconds =
      ls.last.totalEquilibrationSeconds - solverBefore_.totalEquilibrationSeconds;
  ls.cycleSymbolicSeconds = ls.last.totalSymbolicSeconds - solverBefore_.totalSymbolicSeconds;
  ls.cycleNumericSeconds = ls.last.totalNumericSeconds - solverBefore_.totalNumericSeconds;
  ls.cycleSolveSeconds = ls.last.totalSolveSeconds - solverBefore_.totalSolveSeconds;
  ls.symbolicReuses = ls.last.symbolicReuses + symbolicReusesBefore_;
  ls.preconditionerSetups = ls.last.preconditionerSetups + preconditionerSetupsBefore_;
  // One linear solve per Newton step (1 without contact).
  ls.solves = contactProblem_ ? contactProblem_->solver().statistics().newtonIterations : 1;
  ls.iterationsPerSolve = linearIterations_;
  if (contactProblem_)
    ls.finalSolveIterations = contactProblem_->solver().statistics().finalSolveIterations;
  if (contactProblem_) {
    ContactRecord& c = r.contact.emplace();
    c.points = contactProblem_->solver().points();
    c.statistics = contactProblem_->solver().statistics();
    // The pressure at each point's position, for the fitted half-width: at degree 1 only, where
    // it is validated (docs/verification.md "Error bars"). At degree 2 the point values near the
    // zone's ends do not follow √(a − x): on hertz2d_frictionless.xml, 6 cycles, 15k DOFs, the fit
    // moved away from the peer's a with refinement (+18%), so no fitted half-width is reported.
    std::vector<double> pressures;
    if (settings_.discretization.degree == 1)
      for (const auto& v : contact::pointValues(c.points, settings_.problem.dimension, 1,
                                                contactProblem_->solver().bernsteinConstraints()))
        pressures.push_back(v.pressure);
    c.summary = contact::summarizeContact(
        c.points, settings_.problem.dimension, contact_.obstacleNormal, *comm_,
        1e-12 * 2.0 * settings_.material.shearModulus(), pressures);
    if (settings_.hertzRadius)
      c.hertz = contact::compareWithHertz(settings_.problem.dimension, c.summary,
                                          settings_.material, *settings_.hertzRadius);
  }
}

adapt::CycleEstimate Simulation::estimate(int /*cycle*/)
{
  estimateError();
  collectResults();
  const auto& estimate = results_->estimate;
  adapt::CycleEstimate e;
  e.dofs = solved_ ? space_->numGlobalDofs() : 0;
  e.numElements = mesh_->numElements();
  if (estimate) {
    e.available = true;
    e.eta = estimate->total();
    e.norm = estimate->stressEnergyNorm;
    // The next cycle's balanced Krylov stop (contact/BalancedStopping.hpp).
    balancedStopping_.setDiscretisationError(e.eta, e.norm > 0.0 ? e.eta / e.norm : 0.0);
    e.ownedElements = space_->ownedElements();
    e.indicators = estimate->indicators;
    // The error bars from the history of the earlier cycles (summary.json's records), and the
    // accuracy targets against them.
    if (solved_) {
      results_->estimatedErrors =
          estimateErrors(summary_->json()["cycles"], *results_, settings_.problem.dimension,
                         boundaryConditions_.hasContact() && contact_.needsFriction(),
                         settings_.loadSteps.given ? loadStep_ + 1 : 0);
      e.quantities = results_->estimatedErrors->targets;
      results_->targets = loop_->stopCriteria().targets(e.quantities);
    }
  }
  return e;
}

void Simulation::estimateError()
{
  if (!solved_) return;
  const assembly::ElasticityData data{settings_.material, boundaryConditions_, exact_.get(),
                                      bodyForce_};
  {
    auto t = timers_.scope("reconstruct");
    estimator_ =
        std::make_unique<estimator::ErrorEstimator>(*assembler_, settings_.estimator, comm_);
    if (boundaryConditions_.hasContact())
      estimator_->addContribution(std::make_shared<estimator::ContactContribution>(
          *space_, contact_, settings_.material,
          boundaryConditions_.boundariesOfType(core::BoundaryType::Contact)));
    estimator_->reconstruct(*solution_, data);
  }
  {
    auto t = timers_.scope("estimate");
    results_->estimate = estimator_->estimateReconstructed(*solution_, data);
  }
  const estimator::ErrorEstimate& estimate = *results_->estimate;
  std::ostringstream os;
  os << space_->numGlobalDofs() << " DOFs, eta = " << estimate.total() << " (";
  for (std::size_t i = 0; i < estimate.parts.size(); ++i)
    os << (i ? ", " : "") << estimate.parts[i].first << " " << std::sqrt(estimate.parts[i].second);
  // A zero solution (zero load) has η = 0 and ‖A^{1/2}σ_h‖ = 0: its relative estimate is 0.
  const double relative =
      estimate.stressEnergyNorm > 0.0 ? estimate.total() / estimate.stressEnergyNorm : 0.0;
  os << "), eta / |A^1/2 sigma_h| = " << relative;
  if (exact_) {
    auto t = timers_.scope("errors");
    results_->stressEnergyError = assembly::computeStressEnergyError(
        *assembler_, *solution_, *exact_, settings_.material, *comm_);
    os << ", efficiency index " << estimate.total() / results_->stressEnergyError;
  }
  progress_.report("estimate", os.str());
  if (exact_) {
    auto t = timers_.scope("errors");
    results_->errors = assembly::computeErrors(*assembler_, *solution_, *exact_, *comm_);
  }
}

void Simulation::collectResults()
{
  CycleResults& r = *results_;
  if (solved_) {
    // Reactions and the force balance, with the contact force of the contact record.
    std::array<double, 3> contactForce{0.0, 0.0, 0.0};
    if (r.contact)
      std::copy(r.contact->summary.force.begin(),
                r.contact->summary.force.begin() + settings_.problem.dimension,
                contactForce.begin());
    r.forces = computeCycleForces(
        *assembler_, *solution_,
        {settings_.material, boundaryConditions_, exact_.get(), bodyForce_},
        r.contact ? &contactForce : nullptr, settings_.output.momentPoint, *comm_);
  }
  // The measure of the discrete domain: with curved elements, that of their quadratic maps.
  const double measure = core::sumOverRanks(*comm_, disc::ownedMeasure(*space_));
  const auto* curved = space_->curvedElementsPtr().get();
  r.mesh.vertices = mesh_->numVertices();
  r.mesh.elements = mesh_->numElements();
  r.mesh.measure = measure;
  r.mesh.geometryOrder = space_->geometryOrder();
  r.mesh.curvedElements = curved ? curved->numCurvedElements() : 0;
  r.mesh.minAngleDeg = mesh_->minAngleDeg();
  r.mesh.elementsPerRank.assign(comm_->getSize(), 0);
  for (int o : elementOwner_)
    ++r.mesh.elementsPerRank[o];

  if (!writer_) return;
  auto t = timers_.scope("output");
  CycleFields& f = r.fields.emplace();
  f.vertices = mesh::vertexOwnership(*mesh_, elementOwner_, comm_->getRank(), comm_->getSize());
  if (r.estimate) {
    for (int v : f.vertices.owned) {
      double u[3];
      estimator_->reconstruction().vertexValue(v, u);
      f.reconstructedDisplacement.insert(f.reconstructedDisplacement.end(), u,
                                         u + settings_.problem.dimension);
    }
  }
  if (solved_) f.averages = assembly::computeCellAverages(*assembler_, *solution_);
  if (r.contact)  // the contact points with their point values (ContactFields.hpp)
    f.contactPoints = contactPointGrid(contactProblem_->solver(), settings_.problem.dimension,
                                       settings_.discretization.degree);
}

adapt::NextMeshForecast Simulation::forecastNextMesh(const adapt::Marking& marking) const
{
  adapt::NextMeshForecast f;
  if (!limit_.active() || space_.is_null() || mesh_->numElements() == 0) return f;  // no limit
  const double n = mesh_->numElements();
  const int d = settings_.problem.dimension;
  // Uniform: exactly 2^d per element; marked: each with its closure, at most a uniform level.
  const double uniform = n * (d == 2 ? 4.0 : 8.0);
  const double next = !marking.uniform
                          ? std::min(uniform, n + mesh::closureFactor(d, false) *
                                                      static_cast<double>(marking.elements.size()))
                          : uniform;
  f.dofs = static_cast<double>(space_->numGlobalDofs()) * next / n;
  const auto data = [&](double dofs, double elements) {
    return mesh::dataBytes(dofs, d, limit_.contact, limit_.multigridFromDofs,
                           limit_.multigridBytesPerDof) +
           limit_.ranks * elements * mesh::kMeshBytesPerElement;
  };
  f.bytes = data(f.dofs, next) + limit_.baselineBytes;
  // An explicit limit counts all the run's memory: the peak so far (all ranks) plus the data's
  // growth also counts the fixed costs that the per-DOF constant (measured at 1e5 to 1e6 DOFs)
  // leaves out at small sizes: Gmsh, MUMPS's workspace, HDF5 (docs/mesh.md "Resource limits").
  const double peak = timers_.peakMemory().sumMB * 1048576.0;  // collective
  if (limit_.baselineBytes > 0.0)
    f.bytes = std::max(f.bytes, peak + data(f.dofs, next) -
                                    data(static_cast<double>(space_->numGlobalDofs()), n));
  f.limitBytes = limit_.memoryBytes;
  f.limitSource = limit_.source();
  return f;
}

void Simulation::output(int cycle, const adapt::Marking& marking, const std::string& stopReason)
{
  if (settings_.output.writeContactCsv && results_->contact) {
    auto t = timers_.scope("output");
    recorder_->writeContactTable(*results_);
  }
  if (writer_) {
    auto t = timers_.scope("output");
    writeCycleFields(*writer_, *mesh_, elementOwner_, comm_->getRank(), *results_);
  }
  killIfAsked(cycle);
  recorder_->recordCycle(*results_, marking, stopReason);
  lastCycle_ = cycle;
  if (settings_.loadSteps.given) recordLoadStep();
  const auto timings = timers_.cycleTimings();
  const auto memory = timers_.peakMemory();
  timers_.nextCycle();
  recorder_->recordCost(*results_, timings, memory);
  recorder_->write();
}

void Simulation::checkpoint(int cycle, const adapt::Marking& marking)
{
  timedCheckpoint(cycle, marking.elements, false);
}

void Simulation::timedCheckpoint(int cycle, const std::vector<int>& marked, bool stepComplete)
{
  const double start = Teuchos::Time::wallTime();
  writeCheckpoint(cycle, marked, stepComplete);
  // Its time is known only after the summary record was written (and copied into the
  // checkpoint): summary.json has it from the next write on (the next cycle's, or the last).
  const double slowest = core::maxOverRanks(*comm_, Teuchos::Time::wallTime() - start);
  summary_->currentCycle()["timings"]["checkpoint"] = slowest;
}

void Simulation::checkScene()
{
  setupMesh();
  // --check --restart DIR: is the checkpoint readable and of this deck?
  if (!restartDirectory_.empty()) {
    std::vector<int> marked;
    readCheckpoint(marked);
  }
  // Would the run be able to create and write its output directory and files? (creates nothing)
  io::checkOutputDirectory(settings_.output.directory, *comm_);
  io::checkRunFileNamesAreFree(settings_.output.directory, settings_.output.baseName, *comm_);
  io::checkOutputLock(settings_.output.directory, *comm_);
}

void Simulation::openOutput(int firstCycle, const io::OutputLock& lock)
{
  if (comm_->getRank() == 0 && !lock.takenOver().empty())
    std::cerr << "stresscontact: note: " << lock.takenOver() << std::endl;
  // The run owns its directory: an earlier run's summary, fields and CSVs go before anything is
  // written, so that no file of that run stands beside this one's (docs/output.md). A restart
  // keeps the files of the cycles it continues and removes those of the killed cycle.
  const auto removed =
      firstCycle == 0
          ? io::removeEarlierRunFiles(settings_.output.directory, settings_.output.baseName, *comm_)
          : io::removeFilesAfterCycle(settings_.output.directory, settings_.output.baseName,
                                      firstCycle - 1, *comm_);
  if (!removed.empty()) {
    std::string names;
    for (std::size_t i = 0; i < removed.size() && i < 6; ++i)
      names += (i ? ", " : "") + removed[i];
    progress_.message("removed " + std::to_string(removed.size()) +
                      " file(s) of an earlier run from " + settings_.output.directory + ": " +
                      names + (removed.size() > 6 ? ", ..." : ""));
  }
  summary_ = std::make_unique<io::RunSummary>(comm_, settings_.output.directory, versionString(),
                                              *params_);
  summary_->json()["deck"] = deckPath_;
  summary_->json()["phases_missing"] = phasesMissing_;
  summary_->json()["warnings"] = warnings_;
  recorder_ =
      std::make_unique<RunRecorder>(*comm_, progress_, *summary_, settings_.output.directory,
                                    settings_.problem.dimension, boundaryConditions_.hasContact());
  if (settings_.output.writeXdmf)
    writer_ = std::make_unique<io::XdmfWriter>(comm_, settings_.output.directory,
                                               settings_.output.baseName);
  if (firstCycle > 0) restoreOutputs();
}

void Simulation::run()
{
  progress_.message("StressContact " + versionString() + ": " + deckPath_ + " on " +
                    std::to_string(comm_->getSize()) + " rank(s), output in " +
                    settings_.output.directory);
  for (const auto& m : phasesMissing_)
    progress_.message("  not in this build yet: " + m);
  progress_.setCycle(0, settings_.adaptivity.cycles);
  // The initial mesh is built (and the boundary names checked against it) before anything is
  // written, so that a bad scene leaves no output directory behind.
  setupMesh();
  // --restart: the checkpoint is read and checked before anything is written (a bad or foreign
  // checkpoint is an input error that leaves the directory as it was).
  std::vector<int> marked;  // the checkpoint's marking for its next cycle
  const int firstCycle = restartDirectory_.empty() ? 0 : readCheckpoint(marked);

  // A directory named like one of the run's files would stop it when that file is written.
  io::checkRunFileNamesAreFree(settings_.output.directory, settings_.output.baseName, *comm_);
  io::createOutputDirectory(settings_.output.directory, *comm_);
  // One run per directory: held until run() returns or throws (io/OutputLock.hpp).
  const io::OutputLock lock(*comm_, settings_.output.directory);
  openOutput(firstCycle, lock);

  try {
    const std::string stopReason = runLoadSteps(firstCycle, std::move(marked));
    const std::string outcome = recorder_->recordStop(stopReason, settings_.adaptivity);
    // A scene whose contact could not be solved is not "converged".
    summary_->setConverged(solved_);
    summary_->write();
    progress_.message("done" + outcome + ": " + settings_.output.directory + "/summary.json");
  } catch (const core::ConvergenceError& e) {
    // Collective (the active-set decision is global): every rank gets here. The steps before
    // are in summary.json; the failed step is named.
    if (settings_.loadSteps.given) summary_->json()["failed_load_step"] = loadStep_ + 1;
    summary_->setError(e.what());
    summary_->write();
    throw;
  } catch (const std::exception& e) {
    summary_->setError(e.what());
    summary_->writeLocal();
    throw;
  }
}

}  // namespace sc::app

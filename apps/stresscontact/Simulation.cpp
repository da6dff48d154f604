#include "Simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <numeric>
#include <iomanip>
#include <sstream>
#include <tuple>

#include <Teuchos_Time.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/adapt/AdaptiveLoop.hpp>
#include <sc/assembly/BodySupports.hpp>
#include <sc/assembly/LoadsAndSupports.hpp>
#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/assembly/MixedElasticitySystem.hpp>
#include <sc/solvers/StressHierarchy.hpp>
#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/contact/ContactProblem.hpp>
#include <sc/contact/BodyFrameCheck.hpp>
#include <sc/contact/ContactSummary.hpp>
#include <sc/contact/Hertz.hpp>
#include <sc/contact/Obstacle.hpp>
#include <sc/io/CsvWriter.hpp>
#include <sc/io/HistoryTable.hpp>
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
      progress_(comm_, std::cout, quiet), timers_(comm_)
{
  problem_ = core::ProblemSettings::fromParameters(params_->sublist("Problem"));
  const int dim = problem_.dimension;
  meshSettings_ = mesh::MeshSettings::fromParameters(params_->sublist("Mesh"));
  material_ = core::Material::fromParameters(params_->sublist("Material"), dim);
  boundaryConditions_ =
      core::BoundaryConditions::fromParameters(params_->sublist("Boundary Conditions"), dim);
  bodyForce_ = core::BodyForce::fromParameters(params_->sublist("Body Force"), problem_);
  // Contact data is read (and checked against the dimension) only if the scene has contact.
  if (boundaryConditions_.hasContact()) {
    contact_ = contact::ContactSettings::fromParameters(params_->sublist("Contact"), dim);
    balancedStopping_ =
        contact::BalancedStopping::fromParameters(params_->sublist("Contact").sublist("Newton"));
    // The balanced rule sets Krylov tolerances: with a direct solver it would change nothing (the
    // Newton loop stops on a settled active set by either rule), so it is refused, not ignored.
    const std::string type = params_->sublist("Linear Solver").get<std::string>("Type");
    SC_THROW_IF(balancedStopping_.isBalanced() && type != "Iterative", core::InputError,
                "'Contact/Newton/Stopping' = 'Balanced' balances the Krylov solves of the contact "
                "Newton steps with η_CF, but 'Linear Solver/Type' = '"
                    << type << "' gives exact (direct) solves, which the rule would not change. "
                    << "Valid: 'Linear Solver/Type' = 'Iterative' with 'Balanced', or "
                    << "'Contact/Newton/Stopping' = 'Fixed' (docs/theory.md §\"Solves balanced "
                    << "with the discretisation error\").");
  }
  // A large Coulomb coefficient inflates η's friction part, not the solution (docs/theory.md).
  if (const std::string w = estimator::largeFrictionWarning(contact_);
      boundaryConditions_.hasContact() && !w.empty()) {
    warnings_.push_back(w);
    if (comm_->getRank() == 0) std::cerr << "stresscontact: warning: " << w << std::endl;
  }
  // The frictionless Hertz scenes are compared with Hertz's values for their computed load
  // (contact::compareWithHertz).
  if (boundaryConditions_.hasContact() && !contact_.needsFriction() &&
      (meshSettings_.source == "Half disc" || meshSettings_.source == "Half ball"))
    hertzRadius_ = meshSettings_.radius;
  discretization_ =
      core::DiscretizationSettings::fromParameters(params_->sublist("Discretization"));
  if (boundaryConditions_.hasContact()) contact::checkContactDegree(dim, discretization_.degree);
  // Load steps: the tables must have a row per step; the run starts with step 1's data.
  loadSteps_ = core::LoadSteps::fromParameters(params_->sublist("Load steps"), dim);
  boundaryConditions_.checkStepTables(loadSteps_.numSteps(), dim);
  bodyForce_.checkStepTable(loadSteps_.numSteps(), dim);
  // Friction over several load steps is verified in 2D at degree 1 (contact_load_step_tests,
  // run_cattaneo_mindlin2d); the 3D slip-increment rows and degree 2 have no test yet, so they
  // are refused rather than trusted (docs/contact.md "Load steps").
  SC_THROW_IF(loadSteps_.numSteps() > 1 && boundaryConditions_.hasContact() &&
                  contact_.needsFriction() && (dim != 2 || discretization_.degree != 1),
              core::InputError,
              "'Load steps/Times' has "
                  << loadSteps_.numSteps() << " steps with friction in " << dim
                  << "D at 'Discretization/Degree' = " << discretization_.degree
                  << ": friction over load steps is verified in 2D at degree 1 only. Use one load "
                     "step, no friction, or a 2D scene at degree 1.");
  SC_THROW_IF(!loadSteps_.obstacleDisplacement.empty() && !boundaryConditions_.hasContact(),
              core::InputError,
              "'Load steps/Obstacle displacement' is given, but the scene has no boundary part of "
              "Type Contact (there is no obstacle to move).");
  deckConditions_ = boundaryConditions_;
  deckBodyForce_ = bodyForce_;
  deckContact_ = contact_;
  applyLoadStep(0);
  // What the Linear Solver list means for this scene, decided once: the nested meshes, the
  // per-cycle Auto choice, the rejected combinations (solvers/SolverPolicy.hpp).
  solverPolicy_ = std::make_unique<solvers::SolverPolicy>(
      params_->sublist("Linear Solver"),
      solvers::SolverPolicy::Scene{dim, discretization_.degree, boundaryConditions_.hasContact(),
                                   comm_->getSize()});
  if (solverPolicy_->needsHierarchy())
    hierarchy_ = std::make_unique<solvers::StressHierarchy>(discretization_.degree, comm_);
  estimatorSettings_ = estimator::EstimatorSettings::fromParameters(params_->sublist("Estimator"));
  adaptivity_ = adapt::AdaptivitySettings::fromParameters(params_->sublist("Adaptivity"));
  output_ = io::OutputSettings(params_->sublist(io::OutputSettings::sublistName));
  // Accuracy targets are on contact quantities (the stick zone's on friction): a target the scene
  // cannot measure is an input error, not a target silently never met.
  for (const auto& [key, value, needsFriction] :
       {std::tuple{"Target force error", adaptivity_.targetForceError, false},
        {"Target width error", adaptivity_.targetWidthError, false},
        {"Target pressure error", adaptivity_.targetPressureError, false},
        {"Target stick width error", adaptivity_.targetStickError, true}}) {
    SC_THROW_IF(
        value > 0.0 && !boundaryConditions_.hasContact(), core::InputError,
        "'Adaptivity/"
            << key << "' = " << value
            << " is a target on a contact quantity, but the scene has no boundary part of "
               "Type Contact. Use 'Adaptivity/Target error' (η relative) or remove the key.");
    SC_THROW_IF(
        value > 0.0 && needsFriction && !contact_.needsFriction(), core::InputError,
        "'Adaptivity/"
            << key << "' = " << value
            << " is a target on the stick zone, but the scene has no friction ('Contact/"
               "Friction law' None, or a zero coefficient or bound): there is no stick zone.");
  }
  loop_ = std::make_unique<adapt::AdaptiveLoop>(adaptivity_, comm_, &progress_, &timers_);
  if (loadSteps_.numSteps() > 1) {
    adapt::AdaptivitySettings later = adaptivity_;
    later.cycles = loadSteps_.cyclesPerLaterStep;
    laterStepLoop_ = std::make_unique<adapt::AdaptiveLoop>(later, comm_, &progress_, &timers_);
  }

  // Displacements enter the mixed formulation only through Displacement boundaries: without one,
  // rigid-body motions are free and the system is singular (a pure traction or contact problem
  // is ill-posed here). Say so now rather than let the solver fail (docs/reliability.md).
  // Symmetry and Normal displacement parts can fix them too (checked with the mesh,
  // assembly::checkLoadsAndSupports).
  if (boundaryConditions_.boundariesOfType(core::BoundaryType::Displacement).empty() &&
      boundaryConditions_.boundariesOfType(core::BoundaryType::Symmetry).empty() &&
      boundaryConditions_.boundariesOfType(core::BoundaryType::NormalDisplacement).empty()) {
    std::ostringstream given;
    for (const auto& bc : boundaryConditions_.conditions)
      given << (given.tellp() > 0 ? ", " : "") << "'" << bc.boundary << "' ("
            << core::toString(bc.type) << ")";
    SC_THROW_IF(true, core::InputError,
                "the deck has no boundary of Type 'Displacement' ('Boundary Conditions' gives "
                    << (given.tellp() > 0 ? given.str() : std::string("none"))
                    << "): rigid-body motions are not fixed and the problem is ill-posed in the "
                    << "stress-based formulation (contact and tractions do not fix them). Give at "
                    << "least one boundary part <ParameterList name=\"...\"> with Type = "
                    << "'Displacement' and a Value, or Type 'Symmetry' on parts that hold every "
                    << "rigid motion.");
  }

  exact_ = core::createExactSolution(problem_.exactSolution, dim, material_,
                                     problem_.manufacturedWavenumber);
  for (const auto& bc : boundaryConditions_.conditions)
    SC_THROW_IF(bc.fromExactSolution && !exact_, core::InputError,
                "'Boundary Conditions/"
                    << bc.boundary << "/Data' = 'Exact solution' needs "
                    << "'Problem/Exact solution' (valid: 'Manufactured smooth', 'Linear patch'), "
                    << "but it is 'None'.");
  // Type = Auto: resolved per cycle from the system's size (setupElasticity); MUMPS until then.
  solver_ = solverPolicy_->create(0);
}

Simulation::~Simulation() = default;

void Simulation::applyLoadStep(int step)
{
  const int dim = problem_.dimension;
  loadStep_ = step;
  boundaryConditions_ = deckConditions_.atStep(step, dim);
  bodyForce_ = deckBodyForce_.atStep(step, dim);
  core::Expression::setLoadTime(loadSteps_.times[step]);
  if (!boundaryConditions_.hasContact()) return;
  contact_ = deckContact_;
  balancedStopping_.setDiscretisationError(-1.0);  // η of another load is not this step's
  const auto shift = loadSteps_.obstacleDisplacementAt(step, dim);
  for (auto* point : {&contact_.obstaclePoint, &contact_.obstacleCenter})
    for (std::size_t i = 0; i < point->size() && i < shift.size(); ++i)
      (*point)[i] += shift[i];
  contact_.obstacleOffset = shift;  // a height function's graph moves as a whole
}

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
  limit_ = mesh::makeResourceLimit(meshSettings_.memoryLimitGB, problem_.dimension,
                                   discretization_.degree, comm_->getSize(), adaptivity_.maxDofs,
                                   available, source, baseline);
  // Rank 0 runs Gmsh and broadcasts: every rank holds the bit-identical mesh.
  refiner_ = mesh::MeshFactory::build(meshSettings_, problem_.dimension, *comm_,
                                      /*splitBoundarySimplices=*/false, limit_);
  mesh_ = refiner_->mesh();
  if (hierarchy_) hierarchy_->addMesh(mesh_, {});
  // Curved contact faces: Mesh/Geometry order = 2 on a domain with curved parts (the Hertz
  // scenes' contact boundary; a Gmsh geometry's or a quadratic file's curved parts). Known once
  // the geometry is, which for a Gmsh file is after reading it.
  if (boundaryConditions_.hasContact() &&
      mesh::MeshFactory::hasCurvedElements(meshSettings_, *refiner_))
    contact::checkCurvedContact(problem_.dimension, discretization_.degree, contact_.frame);
  // How faithful the domain is (a linear file's curved part is its polygon, and stays so).
  if (const auto geometry = refiner_->geometry();
      !geometry.is_null() && !geometry->warning().empty()) {
    warnings_.push_back(geometry->warning());
    if (comm_->getRank() == 0)
      std::cerr << "stresscontact: warning: " << geometry->warning() << std::endl;
  }
  boundaryConditions_.checkBoundaryNames(mesh_->boundaryNames(), meshSettings_.source);
  boundaryConditions_.checkPressureDetermined(mesh_->boundaryNames(), material_);
  // A plane obstacle may hold the body along its normal, when nothing else does.
  assembly::ContactPlane plane;
  if (boundaryConditions_.hasContact() && contact_.obstacle == "Plane")
    std::copy(contact_.obstacleNormal.begin(), contact_.obstacleNormal.end(), plane.normal.begin());
  const bool contactHoldsBody =
      assembly::checkLoadsAndSupports(
          *mesh_, {material_, boundaryConditions_, exact_.get(), bodyForce_},
          boundaryConditions_.hasContact() && contact_.obstacle == "Plane" ? &plane : nullptr) >= 0;
  assembly::checkEveryBodyIsHeld(*mesh_, boundaryConditions_);  // a file's mesh may hold several
  if (boundaryConditions_.hasContact()) {
    contactProblem_ = std::make_unique<contact::ContactProblem>(
        material_, boundaryConditions_.boundariesOfType(core::BoundaryType::Contact), comm_);
    contactProblem_->setContactHoldsBody(contactHoldsBody);
    if (balancedStopping_.isBalanced()) contactProblem_->setBalancedStopping(&balancedStopping_);
    contactProblem_->setStepCallback([this](int step, long long changes, double seconds) {
      std::ostringstream os;
      os << "Newton step " << step << ": " << changes << " points changed state";
      if (solver_->isIterative())
        os << ", " << solver_->lastSolveStats().iterations << " Krylov iterations";
      os << " (" << std::fixed << std::setprecision(1) << seconds << " s)";
      progress_.report("contact", os.str());
    });
  }
  if (std::any_of(boundaryConditions_.conditions.begin(), boundaryConditions_.conditions.end(),
                  [](const auto& c) { return c.inNormalFrame(); }) &&
      mesh::MeshFactory::hasCurvedElements(meshSettings_, *refiner_))
    assembly::checkNormalFramePartsFlat(
        *mesh_, boundaryConditions_, *mesh::MeshFactory::curvedElements(meshSettings_, *refiner_));
  if (boundaryConditions_.hasContact()) {
    // The body's size (bounding-box diagonal, a tenth of the miss cap): the height function's
    // finite-difference steps are fractions of it, for every step and cycle alike.
    deckContact_.lengthScale = contact::missCap(*mesh_) / 10.0;
    contact_.lengthScale = deckContact_.lengthScale;
    // Every load step's obstacle position, before anything is written (a step that moves the
    // obstacle off the body, or too deep into it, is an input error of the deck).
    for (int step = loadSteps_.numSteps() - 1; step >= 0; --step) {
      applyLoadStep(step);
      try {
        contact::checkObstacle(*mesh_, contact_,
                               boundaryConditions_.boundariesOfType(core::BoundaryType::Contact));
      } catch (const core::InputError& e) {
        SC_THROW_IF(loadSteps_.given, core::InputError,
                    "load step " << step + 1 << " ('Load steps/Obstacle displacement' row "
                                 << step + 1 << "): " << e.what());
        throw;
      }
    }
    contact::checkBodyFrameFaces(*mesh_, contact_,
                                 boundaryConditions_.boundariesOfType(core::BoundaryType::Contact));
  }
  // Every rank needs an element of the initial mesh; found here, before anything is written
  // (the partitioner would find it only after the output directory exists).
  SC_THROW_IF(mesh_->numElements() < comm_->getSize(), core::InputError,
              "the initial mesh has "
                  << mesh_->numElements() << " elements, fewer than the " << comm_->getSize()
                  << " MPI ranks: make 'Mesh/Initial mesh size' smaller, add "
                  << "'Mesh/Uniform refinements', or run on at most " << mesh_->numElements()
                  << " ranks.");
  warnIfLargeDisplacement();
  progress_.report("mesh", std::to_string(mesh_->numElements()) + " elements, " +
                               std::to_string(mesh_->numVertices()) + " vertices");
}

void Simulation::warnIfLargeDisplacement() const
{
  // The model is linear (small strain): a prescribed displacement that is not small against
  // the body is outside its range. Warn, on rank 0, and go on (docs/reliability.md).
  double uMax = 0.0;
  std::string where;
  for (const auto& bc : boundaryConditions_.conditions) {
    if (bc.type != core::BoundaryType::Displacement || bc.fromExactSolution) continue;
    double n2 = 0.0;
    for (double v : bc.value)
      n2 += v * v;
    if (std::sqrt(n2) > uMax) uMax = std::sqrt(n2), where = bc.boundary;
  }
  const int dim = mesh_->dim();
  const auto& x = mesh_->coordinates();
  double diag2 = 0.0;
  for (int d = 0; d < dim; ++d) {
    double lo = x.empty() ? 0.0 : x[d], hi = lo;
    for (std::size_t i = d; i < x.size(); i += dim)
      lo = std::min(lo, x[i]), hi = std::max(hi, x[i]);
    diag2 += (hi - lo) * (hi - lo);
  }
  const double size = std::sqrt(diag2);
  if (comm_->getRank() == 0 && size > 0.0 && uMax > kLargeDisplacementFraction * size)
    std::cerr << "stresscontact: warning: the displacement prescribed on '" << where << "' ("
              << uMax << ") is " << std::lround(100.0 * uMax / size)
              << "% of the size of the body (" << size << ", the diagonal of its bounding box); "
              << "the model is linear elasticity with small strains, valid for displacements "
              << "small against the body (the warning starts at "
              << 100.0 * kLargeDisplacementFraction << "%)." << std::endl;
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
  progress_.report("refine", adaptivity_.marking + ": " + std::to_string(before) + " -> " +
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
    curved = mesh::MeshFactory::curvedElements(meshSettings_, *refiner_);
  }
  // The pipeline shared with the tests and benchmarks: METIS partition ("partition" phase), DOF
  // numbering and the assembler's graph ("setup").
  system_ = std::make_unique<assembly::MixedElasticitySystem>(mesh_, discretization_.degree, comm_,
                                                              curved, &timers_);
  system_->setupAssembler();
  elementOwner_ = system_->elementOwner();
  space_ = system_->spacePtr();
  assembler_ = &system_->assembler();
  if (solverPolicy_->isAuto()) {
    // Type = Auto (docs/solvers.md): the solver for this cycle's size; a new one only if the
    // choice changes.
    const std::string type = solverPolicy_->typeFor(space_->numGlobalDofs());
    if (type != autoType_) {
      solver_ = solverPolicy_->create(space_->numGlobalDofs());
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
      {material_, boundaryConditions_, exact_.get(), bodyForce_});  // "assemble" phase
  progress_.report("assemble", std::to_string(assembler_->statistics().nonzeros) + " nonzeros");
}

std::vector<solvers::MultigridLevel> Simulation::multigridLevels()
{
  // Type = Auto keeps the meshes in 3D but builds levels only for the cycles it solves with the
  // multigrid.
  if (!hierarchy_ || !solverPolicy_->usesMultigrid(space_->numGlobalDofs())) return {};
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
  progress_.report("contact solve", os.str());
  solved_ = true;
  warnIfNoContact();
}

void Simulation::warnIfNoContact()
{
  // No point in contact: a zero contact force, which is right for a body that does not reach the
  // obstacle, and wrong for one pressed onto it on a mesh too coarse to close any weighted gap
  // (the coarse faces' points lie further from the obstacle than the prescribed displacement:
  // measured below about 1e-3 R on the Hertz half disc's 0.2 mesh, docs/performance.md). The
  // run cannot tell the two apart, so it says so (once, on stderr and in summary.json).
  long long active = 0;
  for (const auto& p : contactProblem_->points())
    active += p.status != contact::PointStatus::Free;
  const long long global = core::sumOverRanks(*comm_, active);
  if (global > 0 || warnedNoContact_) return;
  warnedNoContact_ = true;
  const std::string w =
      "no contact point is in contact (every weighted gap stays open), so the contact force is "
      "zero. If the body should touch the obstacle, the mesh does not resolve the gap where it "
      "first touches: refine there ('Mesh/Local refinement') or check the obstacle's position "
      "and the prescribed displacement (docs/contact.md).";
  warnings_.push_back(w);
  if (summary_) summary_->json()["warnings"] = warnings_;
  if (comm_->getRank() == 0) std::cerr << "stresscontact: warning: " << w << std::endl;
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
  ls.symbolicReuses = ls.last.symbolicReuses + symbolicReusesBefore_;
  ls.preconditionerSetups = ls.last.preconditionerSetups + preconditionerSetupsBefore_;
  // One linear solve per Newton step (1 without contact).
  ls.solves = contactProblem_ ? contactProblem_->solver().statistics().newtonIterations : 1;
  ls.iterationsPerSolve = linearIterations_;
  if (contactProblem_) {
    ContactRecord& c = r.contact.emplace();
    c.points = contactProblem_->solver().points();
    c.statistics = contactProblem_->solver().statistics();
    c.summary = contact::summarizeContact(c.points, problem_.dimension, contact_.obstacleNormal,
                                          *comm_, 1e-12 * 2.0 * material_.shearModulus());
    if (hertzRadius_)
      c.hertz = contact::compareWithHertz(problem_.dimension, c.summary, material_, *hertzRadius_);
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
          estimateErrors(summary_->json()["cycles"], *results_, problem_.dimension,
                         boundaryConditions_.hasContact() && contact_.needsFriction(),
                         loadSteps_.given ? loadStep_ + 1 : 0);
      e.quantities = results_->estimatedErrors->targets;
      results_->targets = loop_->stopCriteria().targets(e.quantities);
    }
  }
  return e;
}

void Simulation::estimateError()
{
  if (!solved_) return;
  const assembly::ElasticityData data{material_, boundaryConditions_, exact_.get(), bodyForce_};
  {
    auto t = timers_.scope("reconstruct");
    estimator_ =
        std::make_unique<estimator::ErrorEstimator>(*assembler_, estimatorSettings_, comm_);
    if (boundaryConditions_.hasContact())
      estimator_->addContribution(std::make_shared<estimator::ContactContribution>(
          *space_, contact_, material_,
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
    results_->stressEnergyError =
        assembly::computeStressEnergyError(*assembler_, *solution_, *exact_, material_, *comm_);
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
                r.contact->summary.force.begin() + problem_.dimension, contactForce.begin());
    r.forces = computeCycleForces(*assembler_, *solution_,
                                  {material_, boundaryConditions_, exact_.get(), bodyForce_},
                                  r.contact ? &contactForce : nullptr, output_.momentPoint, *comm_);
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
                                         u + problem_.dimension);
    }
  }
  if (solved_) f.averages = assembly::computeCellAverages(*assembler_, *solution_);
  if (r.contact)  // the contact points with their point values (ContactFields.hpp)
    f.contactPoints =
        contactPointGrid(contactProblem_->solver(), problem_.dimension, discretization_.degree);
}

adapt::NextMeshForecast Simulation::forecastNextMesh(const adapt::Marking& marking) const
{
  adapt::NextMeshForecast f;
  if (!limit_.active() || space_.is_null() || mesh_->numElements() == 0) return f;  // no limit
  const double n = mesh_->numElements();
  const int d = problem_.dimension;
  // Uniform: exactly 2^d per element; marked: each with its closure, at most a uniform level.
  const double uniform = n * (d == 2 ? 4.0 : 8.0);
  const double next = !marking.uniform
                          ? std::min(uniform, n + mesh::closureFactor(d, false) *
                                                      static_cast<double>(marking.elements.size()))
                          : uniform;
  f.dofs = static_cast<double>(space_->numGlobalDofs()) * next / n;
  const auto data = [&](double dofs, double elements) {
    return dofs * mesh::bytesPerDof(d) + limit_.ranks * elements * mesh::kMeshBytesPerElement;
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
  if (output_.writeContactCsv && results_->contact) {
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
  if (loadSteps_.given) {
    // Load steps (docs/output.md): the step and its time, and the 2D stick zone's two ends
    // (after a tangential step the zone is not centred).
    auto& c = summary_->currentCycle();
    c["load_step"] = {{"step", loadStep_ + 1}, {"time", loadSteps_.times[loadStep_]}};
    // The values the step prescribes from tables (Values per step, Obstacle displacement).
    auto& prescribed = c["load_step"]["prescribed"];
    prescribed = nlohmann::ordered_json::object();
    for (const auto& bc : boundaryConditions_.conditions)
      if (!deckConditions_.find(bc.boundary)->valuesPerStep.empty())
        prescribed[bc.boundary] = bc.value;
    if (!deckBodyForce_.valuesPerStep.empty()) prescribed["body_force"] = bodyForce_.value;
    if (!loadSteps_.obstacleDisplacement.empty())
      prescribed["obstacle"] = loadSteps_.obstacleDisplacementAt(loadStep_, problem_.dimension);
    if (results_->contact && problem_.dimension == 2) {
      // The ends as coordinates along the plane's direction τ = (ν_y, −ν_x) (x for ν = (0, 1)):
      // the summary's ends are signed coordinates s along −τ = (−ν_y, ν_x) from the zone's
      // centre, so the end at s lies at centre·τ − s. (Taken as centre_x + s before, which
      // mirrored the zone about its centre.)
      const auto& cs = results_->contact->summary;
      const auto& nu = contact_.obstacleNormal;
      const double centre = cs.center[0] * nu[1] - cs.center[1] * nu[0];
      c["contact"]["stick_zone_ends"] = {centre - cs.stickZoneEnds[1],
                                         centre - cs.stickZoneEnds[0]};
    }
  }
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
  io::checkOutputDirectory(output_.directory, *comm_);
  io::checkRunFileNamesAreFree(output_.directory, output_.baseName, *comm_);
  io::checkOutputLock(output_.directory, *comm_);
}

void Simulation::run()
{
  progress_.message("StressContact " + versionString() + ": " + deckPath_ + " on " +
                    std::to_string(comm_->getSize()) + " rank(s), output in " + output_.directory);
  for (const auto& m : phasesMissing_)
    progress_.message("  not in this build yet: " + m);
  progress_.setCycle(0, adaptivity_.cycles);
  // The initial mesh is built (and the boundary names checked against it) before anything is
  // written, so that a bad scene leaves no output directory behind.
  setupMesh();
  // --restart: the checkpoint is read and checked before anything is written (a bad or foreign
  // checkpoint is an input error that leaves the directory as it was).
  std::vector<int> marked;  // the checkpoint's marking for its next cycle
  const int firstCycle = restartDirectory_.empty() ? 0 : readCheckpoint(marked);

  // A directory named like one of the run's files would stop it when that file is written.
  io::checkRunFileNamesAreFree(output_.directory, output_.baseName, *comm_);
  io::createOutputDirectory(output_.directory, *comm_);
  // One run per directory: held until run() returns or throws (io/OutputLock.hpp).
  const io::OutputLock lock(*comm_, output_.directory);
  if (comm_->getRank() == 0 && !lock.takenOver().empty())
    std::cerr << "stresscontact: note: " << lock.takenOver() << std::endl;
  // The run owns its directory: an earlier run's summary, fields and CSVs go before anything is
  // written, so that no file of that run stands beside this one's (docs/output.md). A restart
  // keeps the files of the cycles it continues and removes those of the killed cycle.
  const auto removed =
      firstCycle == 0
          ? io::removeEarlierRunFiles(output_.directory, output_.baseName, *comm_)
          : io::removeFilesAfterCycle(output_.directory, output_.baseName, firstCycle - 1, *comm_);
  if (!removed.empty()) {
    std::string names;
    for (std::size_t i = 0; i < removed.size() && i < 6; ++i)
      names += (i ? ", " : "") + removed[i];
    progress_.message("removed " + std::to_string(removed.size()) +
                      " file(s) of an earlier run from " + output_.directory + ": " + names +
                      (removed.size() > 6 ? ", ..." : ""));
  }
  summary_ = std::make_unique<io::RunSummary>(comm_, output_.directory, versionString(), *params_);
  summary_->json()["deck"] = deckPath_;
  summary_->json()["phases_missing"] = phasesMissing_;
  summary_->json()["warnings"] = warnings_;
  recorder_ = std::make_unique<RunRecorder>(*comm_, progress_, *summary_, output_.directory,
                                            problem_.dimension, boundaryConditions_.hasContact());
  if (output_.writeXdmf)
    writer_ = std::make_unique<io::XdmfWriter>(comm_, output_.directory, output_.baseName);
  if (firstCycle > 0) restoreOutputs();

  try {
    std::string stopReason;
    // The load steps (docs/theory.md §"Load steps"), from the first, or from the checkpoint's
    // (resume_): each step after the first starts from the last mesh and contact state of the
    // step before, whose r_T becomes the friction history. A restart continues a step from the
    // checkpoint's cycle, or starts the next step when the checkpoint is of a step's last cycle.
    for (int step = resume_.step; step < loadSteps_.numSteps(); ++step) {
      const bool continues = step == resume_.step && !resume_.startsStep;
      if (step > 0) {
        applyLoadStep(step);
        std::ostringstream os;
        os << "load step " << step + 1 << " of " << loadSteps_.numSteps()
           << ", t = " << loadSteps_.times[step];
        progress_.message(os.str());
      }
      if (step > 0 && !continues && contactProblem_)
        contactProblem_->commitLoadStep(*mesh_);  // the same mesh, r_T the friction history
      stepFirstCycle_ = continues ? resume_.stepFirstCycle : lastCycle_ + 1;
      adapt::AdaptiveLoop& loop = step == 0 ? *loop_ : *laterStepLoop_;
      if (continues)
        stopReason =
            loop.run(*this, firstCycle - stepFirstCycle_, std::move(marked), stepFirstCycle_);
      else
        stopReason = loop.run(*this, 0, {}, stepFirstCycle_);
      // The next step can start from here: a checkpoint of the step's last cycle (the loop
      // writes none for the cycle it stops at).
      if (step + 1 < loadSteps_.numSteps()) timedCheckpoint(lastCycle_, {}, true);
    }
    // Why the run stopped, and with accuracy targets or a time budget whether the targets were
    // met (docs/adaptivity.md "Accuracy targets and a time budget").
    auto& stop = summary_->json()["stop"];
    stop = {{"reason", stopReason}};
    std::string outcome;
    if (adaptivity_.hasQuantityTargets() || adaptivity_.timeBudget > 0.0) {
      const bool met = stopReason.rfind("accuracy targets met", 0) == 0;
      const bool budget = stopReason.rfind("time budget", 0) == 0;
      stop["accuracy_targets_met"] = adaptivity_.hasQuantityTargets()
                                         ? nlohmann::ordered_json(met)
                                         : nlohmann::ordered_json(nullptr);
      stop["time_budget_reached"] = budget;
      outcome = met      ? " (accuracy targets met)"
                : budget ? (adaptivity_.hasQuantityTargets()
                                ? " (best within the time budget; accuracy targets not met)"
                                : " (best within the time budget)")
                         : (adaptivity_.hasQuantityTargets() ? " (accuracy targets not met)" : "");
    }
    // A scene whose contact could not be solved is not "converged".
    summary_->setConverged(solved_);
    summary_->write();
    progress_.message("done" + outcome + ": " + output_.directory + "/summary.json");
  } catch (const core::ConvergenceError& e) {
    // Collective (the active-set decision is global): every rank gets here. The steps before
    // are in summary.json; the failed step is named.
    if (loadSteps_.given) summary_->json()["failed_load_step"] = loadStep_ + 1;
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

#pragma once
// What a run is told by its deck, read once from the validated parameter list (docs/user-guide.md,
// docs/parameters.txt): the scene (problem, mesh, material, loads and supports, contact), the
// method (discretization, estimator, adaptivity), the load steps and the output; and the
// combinations this build cannot run, refused before any work with an InputError naming the keys.
// Simulation holds one RunSettings and makes each load step's loads from it (atStep).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include <sc/adapt/AdaptivitySettings.hpp>
#include <sc/contact/BalancedStopping.hpp>
#include <sc/contact/ContactSettings.hpp>
#include <sc/core/LoadSteps.hpp>
#include <sc/core/ProblemData.hpp>
#include <sc/estimator/EstimatorSettings.hpp>
#include <sc/io/OutputSettings.hpp>
#include <sc/mesh/MeshSettings.hpp>

namespace sc::solvers {
class SolverPolicy;
}

namespace sc::app {

struct RunSettings {
  core::ProblemSettings problem;
  mesh::MeshSettings mesh;
  core::Material material;
  /// The deck's boundary conditions, body force ("Body Force", f = 0 when not given) and contact
  /// settings, from which each load step's are made (atStep).
  core::BoundaryConditions conditions;
  core::BodyForce bodyForce;
  contact::ContactSettings contact;
  /// Contact/Newton/Stopping (the rule and its fraction; η is set by the run).
  contact::BalancedStopping balancedStopping;
  core::DiscretizationSettings discretization;
  /// What the Linear Solver list means for this scene, decided once: the nested meshes, the
  /// per-cycle Auto choice, the rejected combinations (solvers/SolverPolicy.hpp).
  std::shared_ptr<const solvers::SolverPolicy> solverPolicy;
  core::LoadSteps loadSteps;
  estimator::EstimatorSettings estimator;
  adapt::AdaptivitySettings adaptivity;
  io::OutputSettings output;
  /// The frictionless Hertz scenes (Mesh/Source = Half disc or Half ball): their radius, for the
  /// comparison with Hertz's values; none otherwise.
  std::optional<double> hertzRadius;
  /// Warnings about the deck (summary.json "warnings"), already printed on rank 0.
  std::vector<std::string> warnings;

  bool hasContact() const { return conditions.hasContact(); }

  /// The loads of load step `step` (0-based, docs/theory.md §"Load steps"): the step's boundary
  /// values and body force, and the contact settings with the obstacle moved by the step's
  /// displacement (the deck's contact settings without contact).
  struct StepLoads {
    core::BoundaryConditions conditions;
    core::BodyForce bodyForce;
    contact::ContactSettings contact;
  };
  StepLoads atStep(int step) const;
};

/// Reads the validated deck `params` of a run on `ranks` ranks and checks the combinations:
/// contact at a supported degree, the balanced Krylov stop only with a Krylov solver, friction
/// over load steps only where verified, an obstacle to move, the linear solver for the scene,
/// accuracy targets the scene can measure, boundaries that fix the rigid motions. Warnings are
/// printed on rank 0 (`rank`) as they are found.
RunSettings readRunSettings(Teuchos::ParameterList& params, int rank, int ranks);

}  // namespace sc::app

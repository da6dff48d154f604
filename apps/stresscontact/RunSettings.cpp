#include "RunSettings.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <tuple>

#include <sc/contact/ContactConstraints.hpp>
#include <sc/core/Error.hpp>
#include <sc/estimator/ContactContribution.hpp>
#include <sc/solvers/SolverPolicy.hpp>

namespace sc::app {

RunSettings readRunSettings(Teuchos::ParameterList& params, int rank, int ranks)
{
  RunSettings s;
  s.problem = core::ProblemSettings::fromParameters(params.sublist("Problem"));
  const int dim = s.problem.dimension;
  s.mesh = mesh::MeshSettings::fromParameters(params.sublist("Mesh"));
  s.material = core::Material::fromParameters(params.sublist("Material"), dim);
  s.conditions =
      core::BoundaryConditions::fromParameters(params.sublist("Boundary Conditions"), dim);
  s.bodyForce = core::BodyForce::fromParameters(params.sublist("Body Force"), s.problem);
  // Contact data is read (and checked against the dimension) only if the scene has contact.
  if (s.conditions.hasContact()) {
    s.contact = contact::ContactSettings::fromParameters(params.sublist("Contact"), dim);
    s.balancedStopping =
        contact::BalancedStopping::fromParameters(params.sublist("Contact").sublist("Newton"));
    // The balanced rule sets Krylov tolerances: with a direct solver it would change nothing (the
    // Newton loop stops on a settled active set by either rule), so it is refused, not ignored.
    const std::string type = params.sublist("Linear Solver").get<std::string>("Type");
    SC_THROW_IF(s.balancedStopping.isBalanced() && type != "Iterative", core::InputError,
                "'Contact/Newton/Stopping' = 'Balanced' balances the Krylov solves of the contact "
                "Newton steps with η_CF, but 'Linear Solver/Type' = '"
                    << type << "' gives exact (direct) solves, which the rule would not change. "
                    << "Valid: 'Linear Solver/Type' = 'Iterative' with 'Balanced', or "
                    << "'Contact/Newton/Stopping' = 'Fixed' (docs/theory.md §\"Solves balanced "
                    << "with the discretisation error\").");
  }
  // A large Coulomb coefficient inflates η's friction part, not the solution (docs/theory.md).
  if (const std::string w = estimator::largeFrictionWarning(s.contact);
      s.conditions.hasContact() && !w.empty()) {
    s.warnings.push_back(w);
    if (rank == 0) std::cerr << "stresscontact: warning: " << w << std::endl;
  }
  // The frictionless Hertz scenes are compared with Hertz's values for their computed load
  // (contact::compareWithHertz).
  if (s.conditions.hasContact() && !s.contact.needsFriction() &&
      (s.mesh.source == "Half disc" || s.mesh.source == "Half ball"))
    s.hertzRadius = s.mesh.radius;
  s.discretization = core::DiscretizationSettings::fromParameters(params.sublist("Discretization"));
  if (s.conditions.hasContact()) contact::checkContactDegree(dim, s.discretization.degree);
  // Load steps: the tables must have a row per step; the run starts with step 1's data.
  s.loadSteps = core::LoadSteps::fromParameters(params.sublist("Load steps"), dim);
  s.conditions.checkStepTables(s.loadSteps.numSteps(), dim);
  s.bodyForce.checkStepTable(s.loadSteps.numSteps(), dim);
  // Friction over several load steps is verified in 2D at degree 1 (contact_load_step_tests,
  // run_cattaneo_mindlin2d); the 3D slip-increment rows and degree 2 have no test yet, so they
  // are refused rather than trusted (docs/contact.md "Load steps").
  SC_THROW_IF(s.loadSteps.numSteps() > 1 && s.conditions.hasContact() &&
                  s.contact.needsFriction() && (dim != 2 || s.discretization.degree != 1),
              core::InputError,
              "'Load steps/Times' has "
                  << s.loadSteps.numSteps() << " steps with friction in " << dim
                  << "D at 'Discretization/Degree' = " << s.discretization.degree
                  << ": friction over load steps is verified in 2D at degree 1 only. Use one load "
                     "step, no friction, or a 2D scene at degree 1.");
  SC_THROW_IF(!s.loadSteps.obstacleDisplacement.empty() && !s.conditions.hasContact(),
              core::InputError,
              "'Load steps/Obstacle displacement' is given, but the scene has no boundary part of "
              "Type Contact (there is no obstacle to move).");
  // What the Linear Solver list means for this scene, decided once: the nested meshes, the
  // per-cycle Auto choice, the rejected combinations (solvers/SolverPolicy.hpp).
  s.solverPolicy = std::make_shared<const solvers::SolverPolicy>(
      params.sublist("Linear Solver"),
      solvers::SolverPolicy::Scene{dim, s.discretization.degree, s.conditions.hasContact(), ranks});
  s.estimator = estimator::EstimatorSettings::fromParameters(params.sublist("Estimator"));
  s.adaptivity = adapt::AdaptivitySettings::fromParameters(params.sublist("Adaptivity"));
  s.output = io::OutputSettings::fromParameters(params.sublist(io::OutputSettings::sublistName));
  // Accuracy targets are on contact quantities (the stick zone's on friction): a target the scene
  // cannot measure is an input error, not a target silently never met.
  for (const auto& [key, value, needsFriction] :
       {std::tuple{"Target force error", s.adaptivity.targetForceError, false},
        {"Target width error", s.adaptivity.targetWidthError, false},
        {"Target pressure error", s.adaptivity.targetPressureError, false},
        {"Target stick width error", s.adaptivity.targetStickError, true}}) {
    SC_THROW_IF(
        value > 0.0 && !s.conditions.hasContact(), core::InputError,
        "'Adaptivity/"
            << key << "' = " << value
            << " is a target on a contact quantity, but the scene has no boundary part of "
               "Type Contact. Use 'Adaptivity/Target error' (η relative) or remove the key.");
    SC_THROW_IF(
        value > 0.0 && needsFriction && !s.contact.needsFriction(), core::InputError,
        "'Adaptivity/"
            << key << "' = " << value
            << " is a target on the stick zone, but the scene has no friction ('Contact/"
               "Friction law' None, or a zero coefficient or bound): there is no stick zone.");
  }
  // Displacements enter the mixed formulation only through Displacement boundaries: without one,
  // rigid-body motions are free and the system is singular (a pure traction or contact problem
  // is ill-posed here). Say so now rather than let the solver fail (docs/reliability.md).
  // Symmetry, Normal displacement and Components parts with a displacement component can fix
  // them too (checked with the mesh, assembly::checkLoadsAndSupports).
  if (s.conditions.boundariesOfType(core::BoundaryType::Displacement).empty() &&
      s.conditions.boundariesOfType(core::BoundaryType::Symmetry).empty() &&
      s.conditions.boundariesOfType(core::BoundaryType::NormalDisplacement).empty() &&
      std::none_of(s.conditions.conditions.begin(), s.conditions.conditions.end(),
                   [](const auto& c) { return c.hasDisplacementComponent(); })) {
    std::ostringstream given;
    for (const auto& bc : s.conditions.conditions)
      given << (given.tellp() > 0 ? ", " : "") << "'" << bc.boundary << "' ("
            << core::toString(bc.type) << ")";
    SC_THROW_IF(true, core::InputError,
                "the deck has no boundary of Type 'Displacement' ('Boundary Conditions' gives "
                    << (given.tellp() > 0 ? given.str() : std::string("none"))
                    << "): rigid-body motions are not fixed and the problem is ill-posed in the "
                    << "stress-based formulation (contact and tractions do not fix them). Give at "
                    << "least one boundary part <ParameterList name=\"...\"> with Type = "
                    << "'Displacement' and a Value, or Type 'Symmetry' (or 'Components' with "
                    << "displacement components) on parts that hold every rigid motion.");
  }
  return s;
}

RunSettings::StepLoads RunSettings::atStep(int step) const
{
  const int dim = problem.dimension;
  StepLoads loads{conditions.atStep(step, dim), bodyForce.atStep(step, dim), contact};
  if (!hasContact()) return loads;
  const auto shift = loadSteps.obstacleDisplacementAt(step, dim);
  for (auto* point : {&loads.contact.obstaclePoint, &loads.contact.obstacleCenter})
    for (std::size_t i = 0; i < point->size() && i < shift.size(); ++i)
      (*point)[i] += shift[i];
  loads.contact.obstacleOffset = shift;  // a height function's graph moves as a whole
  return loads;
}

}  // namespace sc::app

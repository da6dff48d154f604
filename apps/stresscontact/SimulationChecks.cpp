// The scene checked against its initial mesh before anything is written (docs/reliability.md):
// the boundary names and supports, curved contact faces, every load step's obstacle position,
// the ranks' share of elements, and the warnings of a scene the model may not describe well
// (large prescribed displacements, no point in contact).
#include "Simulation.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include <sc/assembly/BodySupports.hpp>
#include <sc/assembly/LoadsAndSupports.hpp>
#include <sc/contact/BodyFrameCheck.hpp>
#include <sc/contact/ContactConstraints.hpp>
#include <sc/contact/ContactProblem.hpp>
#include <sc/contact/Obstacle.hpp>
#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/ExactSolution.hpp>
#include <sc/io/RunSummary.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::app {

namespace {
/// A prescribed displacement above this fraction of the body's size (bounding-box diagonal)
/// draws a small-strain warning.
constexpr double kLargeDisplacementFraction = 0.05;
}  // namespace

bool Simulation::checkSceneOnMesh()
{
  // Curved contact faces: Mesh/Geometry order = 2 on a domain with curved parts (the Hertz
  // scenes' contact boundary; a Gmsh geometry's or a quadratic file's curved parts). Known once
  // the geometry is, which for a Gmsh file is after reading it.
  if (boundaryConditions_.hasContact() &&
      mesh::MeshFactory::hasCurvedElements(settings_.mesh, *refiner_))
    contact::checkCurvedContact(settings_.problem.dimension, settings_.discretization.degree,
                                contact_.frame);
  // How faithful the domain is (a linear file's curved part is its polygon, and stays so).
  if (const auto geometry = refiner_->geometry();
      !geometry.is_null() && !geometry->warning().empty()) {
    warnings_.push_back(geometry->warning());
    if (comm_->getRank() == 0)
      std::cerr << "stresscontact: warning: " << geometry->warning() << std::endl;
  }
  boundaryConditions_.checkBoundaryNames(mesh_->boundaryNames(), settings_.mesh.source);
  boundaryConditions_.checkPressureDetermined(mesh_->boundaryNames(), settings_.material);
  // A plane obstacle may hold the body along its normal, when nothing else does.
  assembly::ContactPlane plane;
  if (boundaryConditions_.hasContact() && contact_.obstacle == "Plane")
    std::copy(contact_.obstacleNormal.begin(), contact_.obstacleNormal.end(), plane.normal.begin());
  const bool contactHoldsBody =
      assembly::checkLoadsAndSupports(
          *mesh_, {settings_.material, boundaryConditions_, exact_.get(), bodyForce_},
          boundaryConditions_.hasContact() && contact_.obstacle == "Plane" ? &plane : nullptr) >= 0;
  assembly::checkEveryBodyIsHeld(*mesh_, boundaryConditions_);  // a file's mesh may hold several
  if (std::any_of(boundaryConditions_.conditions.begin(), boundaryConditions_.conditions.end(),
                  [](const auto& c) { return c.inNormalFrame(); }) &&
      mesh::MeshFactory::hasCurvedElements(settings_.mesh, *refiner_))
    assembly::checkNormalFramePartsFlat(
        *mesh_, boundaryConditions_, *mesh::MeshFactory::curvedElements(settings_.mesh, *refiner_));
  if (boundaryConditions_.hasContact()) {
    // The body's size (bounding-box diagonal, a tenth of the miss cap): the height function's
    // finite-difference steps are fractions of it, for every step and cycle alike.
    settings_.contact.lengthScale = contact::missCap(*mesh_) / 10.0;
    contact_.lengthScale = settings_.contact.lengthScale;
    checkObstacleAtEveryLoadStep();
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
  return contactHoldsBody;
}

void Simulation::checkObstacleAtEveryLoadStep()
{
  // Every load step's obstacle position, before anything is written (a step that moves the
  // obstacle off the body, or too deep into it, is an input error of the deck).
  for (int step = settings_.loadSteps.numSteps() - 1; step >= 0; --step) {
    applyLoadStep(step);
    try {
      contact::checkObstacle(*mesh_, contact_,
                             boundaryConditions_.boundariesOfType(core::BoundaryType::Contact));
    } catch (const core::InputError& e) {
      SC_THROW_IF(settings_.loadSteps.given, core::InputError,
                  "load step " << step + 1 << " ('Load steps/Obstacle displacement' row "
                               << step + 1 << "): " << e.what());
      throw;
    }
  }
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

}  // namespace sc::app

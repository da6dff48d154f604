#include "sc/contact/ContactProblem.hpp"

#include <sc/mesh/RefinementTransfer.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::contact {

ContactProblem::ContactProblem(const core::Material& material,
                               std::vector<std::string> contactBoundaries,
                               Teuchos::RCP<const Teuchos::Comm<int>> comm)
    : material_(material), boundaries_(std::move(contactBoundaries)), comm_(std::move(comm))
{
}

ContactProblem::~ContactProblem() = default;

void ContactProblem::refined(const mesh::SimplexMesh& previous, const mesh::SimplexMesh& next,
                             const mesh::RefinementStep& step)
{
  parents_ = mesh::boundaryFaceParents(previous, next, step);
}

void ContactProblem::commitLoadStep(const mesh::SimplexMesh& mesh)
{
  contact::commitLoadStep(points_);
  stepStart_ = true;
  // The same mesh: every contact face is its own parent.
  parents_.assign(mesh.numFaces(), -1);
  for (int f : mesh.boundaryFaces())
    parents_[f] = f;
}

void ContactProblem::restorePoints(std::vector<ContactPoint> points)
{
  points_ = std::move(points);
  parents_.clear();
}

void ContactProblem::setUp(const disc::MixedElasticitySpace& space, const ContactSettings& settings)
{
  solver_ = std::make_unique<ActiveSetSolver>(space, settings, material_, boundaries_, comm_);
  solver_->setContactHoldsBody(holdsBody_);
  solver_->setBalancedStopping(balanced_);
  if (callback_) solver_->setStepCallback(callback_);
  solver_->setLoadStepStart(stepStart_);
}

void ContactProblem::transferState()
{
  solver_->transferState(points_, parents_);
  // The parents are dropped once the state is transferred (memory stays O(N)).
  parents_ = std::vector<int>();
}

void ContactProblem::solve(const Tpetra::CrsMatrix<>& K, const Tpetra::MultiVector<>& b,
                           solvers::LinearSolver& linearSolver, Tpetra::MultiVector<>& x)
{
  solver_->solve(K, b, linearSolver, x);
  stepStart_ = false;
  points_ = solver_->points();
}

}  // namespace sc::contact

#pragma once
// Contact as a problem that lives across the cycles of a run (docs/contact.md): it owns the
// contact points, carries their state to the next mesh through the refinement step (nested
// iteration: each cycle's Newton starts from the previous cycle's state) and to the next load
// step, and solves a cycle given the assembled system and the linear solver, with an
// ActiveSetSolver built on the cycle's space.

#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix_fwd.hpp>
#include <Tpetra_MultiVector_fwd.hpp>

#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/contact/ContactPoint.hpp>
#include <sc/contact/ContactSettings.hpp>
#include <sc/core/ProblemData.hpp>

namespace sc::disc {
class MixedElasticitySpace;
}
namespace sc::mesh {
class SimplexMesh;
struct RefinementStep;
}  // namespace sc::mesh
namespace sc::solvers {
class LinearSolver;
}

namespace sc::contact {

class ContactProblem {
public:
  /// Contact on the boundary parts `contactBoundaries` of a body of `material`.
  ContactProblem(const core::Material& material, std::vector<std::string> contactBoundaries,
                 Teuchos::RCP<const Teuchos::Comm<int>> comm);
  ~ContactProblem();

  /// See ActiveSetSolver::setContactHoldsBody and setStepCallback; kept for every cycle.
  void setContactHoldsBody(bool holds) { holdsBody_ = holds; }
  void setStepCallback(ActiveSetSolver::StepCallback callback) { callback_ = std::move(callback); }
  /// See ActiveSetSolver::setBalancedStopping (borrowed); kept for every cycle.
  void setBalancedStopping(BalancedStopping* stopping) { balanced_ = stopping; }

  /// The mesh `previous` was refined into `next` by `step`: the points' state goes to `next`
  /// through the parents of its boundary faces (taken now, while the refiner holds the step).
  void refined(const mesh::SimplexMesh& previous, const mesh::SimplexMesh& next,
               const mesh::RefinementStep& step);
  /// End of a load step (docs/theory.md §"Load steps"): every point's r_T becomes its friction
  /// history, and the next step starts on the same mesh `mesh` from the same state.
  void commitLoadStep(const mesh::SimplexMesh& mesh);
  /// A restart: the points of the checkpoint's cycle (on the restored mesh), carried to the next
  /// cycle by its refinement step as if they had been solved.
  void restorePoints(std::vector<ContactPoint> points);

  /// The cycle's active-set solver on `space` with the obstacle and Newton settings of the
  /// current load step (collective).
  void setUp(const disc::MixedElasticitySpace& space, const ContactSettings& settings);
  /// Start from the carried state (ActiveSetSolver::transferState; all free in the first
  /// cycle). Collective.
  void transferState();
  /// Solve K x = b with the contact conditions (ActiveSetSolver::solve); the solved points are
  /// the state carried to the next cycle.
  void solve(const Tpetra::CrsMatrix<>& K, const Tpetra::MultiVector<>& b,
             solvers::LinearSolver& linearSolver, Tpetra::MultiVector<>& x);

  /// The cycle's solver (after setUp): its points, statistics and constraint basis.
  const ActiveSetSolver& solver() const { return *solver_; }
  /// The state carried to the next cycle: the last solved (or restored) points of this rank.
  const std::vector<ContactPoint>& points() const { return points_; }

private:
  core::Material material_;
  std::vector<std::string> boundaries_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  bool holdsBody_ = false;
  /// Set by commitLoadStep until the next solve: the cycle is a later load step's first
  /// (ActiveSetSolver::setLoadStepStart).
  bool stepStart_ = false;
  ActiveSetSolver::StepCallback callback_;
  BalancedStopping* balanced_ = nullptr;
  std::unique_ptr<ActiveSetSolver> solver_;
  std::vector<ContactPoint> points_;
  /// For every face of the current mesh, the boundary face of the points' mesh that contains it
  /// (-1 off the boundary); empty: no history (all points start free).
  std::vector<int> parents_;
};

}  // namespace sc::contact

#pragma once
// What a run's "Linear Solver" list means for the run (docs/solvers.md): decided once from the
// validated list and the scene, then asked by the application: does it need the nested meshes,
// which solver does Type = Auto choose for a cycle, and does that cycle use the multigrid levels.
// The combinations no test covers are rejected when it is built.
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/solvers/LinearSolver.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

namespace sc::solvers {

class SolverPolicy {
public:
  struct Scene {
    int dimension = 2;
    int degree = 1;        ///< Discretization/Degree
    bool contact = false;  ///< the scene has contact rows (non-symmetric systems)
    int ranks = 1;
  };

  /// `validatedList`: the deck's validated "Linear Solver" list (every key present). Throws
  /// InputError for Type = Iterative with contact at degree ≥ 2 or in 3D with an exact stress
  /// block (3D contact: Stress block = Multigrid only), and Method = MINRES with contact or
  /// Symmetric = false.
  SolverPolicy(const Teuchos::ParameterList& validatedList, const Scene& scene);

  /// Keep the nested meshes of the run: Stress block = Multigrid, or Type = Auto where it may
  /// choose the multigrid (3D; with contact at degree 1).
  bool needsHierarchy() const { return hierarchy_; }
  /// Type = Auto: the solver is chosen per cycle from the system's size.
  bool isAuto() const { return type_ == "Auto"; }
  /// The Type a system of `dofs` unknowns is solved with (Auto resolved by resolveAutoType).
  std::string typeFor(long long dofs) const;
  /// Whether that system's solve uses the stress multigrid levels of the hierarchy.
  bool usesMultigrid(long long dofs) const { return hierarchy_ && typeFor(dofs) == "Iterative"; }
  /// The solver for a system of `dofs` unknowns.
  Teuchos::RCP<LinearSolver> create(long long dofs) const;
  /// Type = Auto: the unknowns from which the multigrid is chosen (the threshold key that
  /// applies to the scene); -1 when the run never uses it under Auto (or Type is not Auto). The
  /// resource estimate switches to the multigrid's memory model there (docs/mesh.md).
  long long autoIterativeFrom() const;
  /// Vectors of the system's length that GMRES allocates when it runs (flexible GMRES, Belos:
  /// V and Z of Iterative/Restart + 1 columns each, allocated at the first iteration).
  int gmresBasisVectors() const;

private:
  ProblemSize problem(long long dofs) const;

  Teuchos::ParameterList list_;
  Scene scene_;
  std::string type_;
  bool hierarchy_ = false;
};

}  // namespace sc::solvers

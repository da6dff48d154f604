#pragma once
// Owner of the "Linear Solver" sublist (docs/theory.md §"Linear solvers", §8): its valid parameters
// and the solvers it names (direct: KLU2, MUMPS; Krylov: Iterative). Types are registered by name;
// an unknown type is an InputError listing the known ones (docs/architecture.md "Parameters").

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <sc/solvers/DirectSolver.hpp>
#include <sc/solvers/LinearSolver.hpp>

namespace sc::solvers {

class LinearSolverFactory {
public:
  /// The "Linear Solver" sublist: Type, Symmetric, Equilibrate, Equilibration iterations,
  /// Maximum relative residual, Verbose, the Iterative sublist (Method, Tolerance, Maximum
  /// iterations, Restart, Output frequency, Stress block) and the MUMPS sublist (Memory
  /// relaxation percent, Workspace retries, Ordering). Every entry has a default, a doc string and
  /// a validator.
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();

  /// Known solver types, in the order they are listed to users (KLU2, MUMPS, Iterative, Auto).
  static std::vector<std::string> knownTypes();

  /// A "Linear Solver" list checked against getValidParameters() with its defaults filled in:
  /// unknown keys, bad values and unknown types are sc::core::InputError. Done once, where a
  /// list enters (the application validates the whole deck; createLinearSolver for a list of
  /// a test or benchmark).
  static Teuchos::ParameterList validate(const Teuchos::ParameterList& linearSolverList);

  /// Build the solver named by the validated list's "Type" (not validated again: every key is
  /// read without a default). Type = Auto is an InputError here (resolveAutoType first).
  static Teuchos::RCP<LinearSolver> create(const Teuchos::ParameterList& validatedList);
};

/// What `Type = Auto` looks at (docs/solvers.md, "Type = Auto").
struct ProblemSize {
  int dimension = 2;
  long long dofs = 0;  ///< global unknowns of the system
  int ranks = 1;
  bool contact = false;    ///< contact rows (non-symmetric; the multigrid only in 3D at k = 1)
  bool hierarchy = false;  ///< the caller provides BlockStructure::multigrid (nested meshes)
  int degree = 1;          ///< Discretization/Degree (the contact rule holds at k = 1 only)
};

/// `Type = Auto`: MUMPS, except in 3D with a mesh hierarchy and at least `Auto iterative
/// unknowns` (default kAutoIterativeDofs3D) unknowns without contact, or at least `Auto iterative
/// contact unknowns` (default kAutoIterativeContactDofs3D) with contact at degree 1, where MUMPS'
/// memory (~N^{4/3}; LU with contact) exceeds one 24 GB node: there Iterative with Stress block =
/// Multigrid (memory ~N). 2D, and 3D contact at degree >= 2, always MUMPS. Measured in
/// docs/solvers.md ("Type = Auto").
constexpr long long kAutoIterativeDofs3D = 1500000;
constexpr long long kAutoIterativeContactDofs3D = 1000000;
/// Whether `Type = Auto` with these thresholds gives a problem the multigrid (the rule above,
/// without the hierarchy and the size: whether it can, at some size).
bool autoMayUseMultigrid(int dimension, bool contact, int degree);
/// The Auto threshold for a problem (the key that applies to it), from the validated list.
long long autoIterativeThreshold(const Teuchos::ParameterList& validatedList, bool contact);
/// The list to build for `problem`: the validated list itself unless its Type is Auto, else a
/// copy with Type = MUMPS or Type = Iterative and Iterative/Stress block = Multigrid, by the rule
/// above.
Teuchos::ParameterList resolveAutoType(const Teuchos::ParameterList& validatedList,
                                       const ProblemSize& problem);

/// LinearSolverFactory::create(LinearSolverFactory::validate(list)). Type = Auto is an
/// InputError here: it needs the problem (resolveAutoType, or the overload below).
Teuchos::RCP<LinearSolver> createLinearSolver(const Teuchos::ParameterList& linearSolverList);
/// The validated list's solver for `problem` (Type = Auto resolved).
Teuchos::RCP<LinearSolver> createLinearSolver(const Teuchos::ParameterList& linearSolverList,
                                              const ProblemSize& problem);
/// The same for a direct type (KLU2, MUMPS), with the factorisation interface of DirectSolver;
/// Type = Iterative is an InputError.
Teuchos::RCP<DirectSolver> createDirectSolver(const Teuchos::ParameterList& linearSolverList);
/// The same for a list validated already (the Krylov solver's stress-block and coarse solvers:
/// its own validated list with the direct Type).
Teuchos::RCP<DirectSolver>
createDirectSolverFromValidated(const Teuchos::ParameterList& validatedList);

}  // namespace sc::solvers

#pragma once
// Owner of the "Linear Solver" sublist (docs/theory.md §"Linear solvers", §8): its valid parameters
// and the solvers it names (direct: KLU2, MUMPS; Krylov: Iterative). Types are registered by name;
// an unknown type is an InputError listing the known ones (STYLE.md, Trilinos anchor).

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

  /// Known solver types, in the order they are listed to users.
  static std::vector<std::string> knownTypes();

  /// Build the solver named by list's "Type". The list is validated (a copy, defaults filled in):
  /// unknown keys, bad values and unknown types are sc::core::InputError.
  static Teuchos::RCP<LinearSolver> create(const Teuchos::ParameterList& linearSolverList);
};

/// Same as LinearSolverFactory::create.
Teuchos::RCP<LinearSolver> createLinearSolver(const Teuchos::ParameterList& linearSolverList);
/// The same for a direct type (KLU2, MUMPS), with the factorisation interface of DirectSolver;
/// Type = Iterative is an InputError.
Teuchos::RCP<DirectSolver> createDirectSolver(const Teuchos::ParameterList& linearSolverList);

}  // namespace sc::solvers

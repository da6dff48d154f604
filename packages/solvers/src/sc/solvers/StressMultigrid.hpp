#pragma once
// One symmetric V-cycle of geometric multigrid for the stress block S_σ of the block preconditioner
// (docs/theory.md §"Linear solvers", docs/solvers.md "Geometric multigrid"), on the levels of
// BlockStructure::multigrid (StressHierarchy.hpp): Galerkin coarse operators, the Chebyshev-
// accelerated patch smoother (PatchSmoother.hpp), a direct coarsest solve. Tpetra stays in
// StressMultigrid.cpp.

#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Tpetra_Operator_fwd.hpp>

#include <sc/solvers/IterativeSolver.hpp>
#include <sc/solvers/LinearSolver.hpp>

namespace sc::solvers {

/// The V-cycle of S (the finest level's S_σ, on the σ rows of the operator) on the hierarchy of
/// `blocks`, as an operator Y = V(X). `constraintRows[i]` (local rows of S): a row without
/// displacement coupling (traction data, a replaced contact row), which takes no coarse
/// correction. The smoother's degree and ratio come from `options`; the coarsest level is solved
/// by the direct solver of the validated list `directList` (its `Type`). `stressBasis`: the σ
/// block of BlockStructure::stressBasis on S's maps (S's unknowns are stressBasis × the σ DOFs;
/// the finest prolongation becomes stressBasis P), or null. Throws InputError when `blocks` has
/// no hierarchy.
Teuchos::RCP<Tpetra::Operator<>>
buildStressMultigrid(const BlockStructure& blocks, const Teuchos::RCP<CrsMatrix>& S,
                     const std::vector<char>& constraintRows, bool symmetric,
                     const IterativeOptions& options, const Teuchos::ParameterList& directList,
                     const Teuchos::RCP<const CrsMatrix>& stressBasis);

}  // namespace sc::solvers

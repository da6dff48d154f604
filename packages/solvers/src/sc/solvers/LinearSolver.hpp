#pragma once
// The one interface of every linear solver of StressContact (docs/theory.md §"Linear solvers"):
// direct (KLU2, MUMPS) and Krylov (Belos with a block preconditioner) solvers implement it, and
// callers (the elasticity solve, the contact Newton loop, tests, benchmarks) see only it.
//
// Usage:
//   auto solver = createLinearSolver(linearSolverList);      // LinearSolverFactory.hpp
//   solver->setScaling(D);                 // optional diagonal scaling, owned here (see below)
//   solver->setBlockStructure(blocks);     // field layout + masses, for block preconditioners
//   solver->setOperator(A, /*symmetric=*/true);
//   solver->solve(b, x);                   // x: initial guess in (Krylov), solution out
//   ... change A's values (contact rows) ...
//   solver->setOperator(A2, false);        // the solver rebuilds what depends on the values
//   solver->solve(b, x);
//
// Scaling: with D set, the solver works on D A D y = D b and returns x = D y. This is the only
// place where the physical block scaling (√(2μ) on σ, 1/√(2μ) on u and θ, docs/theory.md §"Contact
// and friction") is applied; callers hand over the unscaled operator. Symmetry: the caller states
// whether its operator is symmetric (contact rows make it non-symmetric, docs/theory.md §"Contact
// and friction"); the user's `Linear Solver/Symmetric` says whether the solver may exploit it
// (MUMPS LDLᵀ, MINRES). Both must hold.
//
// Every solve checks the relative residual ‖b̃ − Ã ỹ‖₂/‖b̃‖₂ of the working system (Ã = D A D,
// b̃ = D b, the max over columns; Ã = A without scaling); a value above the limit or not finite
// throws sc::core::ConvergenceError on every rank. With the physical scaling this is the residual
// in which σ, u and θ rows weigh alike whatever E is.

#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>

#include <sc/solvers/LinearAlgebraTypes.hpp>
#include <sc/solvers/SolveStatistics.hpp>

namespace sc::solvers {

/// One level of the nested mesh hierarchy for the multigrid of the stress block (docs/theory.md
/// §"Linear solvers").
struct MultigridLevel {
  /// Exact prolongation of σ from the next coarser level into this one (σ global ids 0..#σ of
  /// each level; row map = this level's owned σ DOFs in the order of the operator's row map on
  /// the finest level); null on the coarsest level.
  Teuchos::RCP<const CrsMatrix> prolongation;
  /// σ DOF ids of the smoother patches (vertex stars in 2D, edge stars in 3D) this rank smooths on
  /// this level (unused on the coarsest).
  std::vector<std::vector<long long>> patches;
  /// For each element E of the next coarser level that this rank handles (the owner of its
  /// lowest-numbered fine element): the σ DOF ids of the fine elements inside E, split into
  /// those on fine faces that lie on E's boundary (`boundary`) and the rest (`interior`: element
  /// interiors and faces between two fine elements of E). The multigrid extends coarse
  /// functions cut by contact constraints into E's interior (StressMultigrid.cpp); empty on the
  /// coarsest level.
  struct CoarseElement {
    std::vector<long long> interior, boundary;
  };
  std::vector<CoarseElement> coarseElements;
};

/// The 3×3 field layout of the mixed system (docs/theory.md §"Mixed formulation"): monolithic
/// global ids [0, σ) are stress, [σ, σ + u) displacement, the rest rotation; and what block
/// preconditioners need besides the operator. Direct solvers ignore it.
struct BlockStructure {
  long long stressDofs = 0, displacementDofs = 0, rotationDofs = 0;
  int dimension = 0;  ///< 2 or 3
  /// 2μ of the material (the preconditioner's u and θ blocks are 2μ M_u, 2μ M_θ, docs/theory.md
  /// §"Linear solvers").
  double twoMu = 1.0;
  /// The L² mass matrices of u and θ in one matrix on the operator's row map (σ rows empty or
  /// zero), unscaled. M_u must be element-block diagonal (discontinuous displacements).
  Teuchos::RCP<const CrsMatrix> fieldMass;
  /// Nested hierarchy, coarsest level first, the last level being the operator's mesh: needed by
  /// `Stress block` = Multigrid (StressHierarchy.hpp: stressProlongation, stressPatches).
  std::vector<MultigridLevel> multigrid;
  /// The operator's unknowns y in terms of the space's DOFs x, y = T x (null: y = x). A contact
  /// solve works in its constraints' coordinates on the contact faces (contact::ActiveSetSolver);
  /// the multigrid's finest prolongation becomes T P. T is the identity off the σ block.
  Teuchos::RCP<const CrsMatrix> stressBasis;

  bool isSet() const { return stressDofs + displacementDofs + rotationDofs > 0; }
  long long begin(int field) const
  {
    return field == 0 ? 0 : field == 1 ? stressDofs : stressDofs + displacementDofs;
  }
  long long end(int field) const { return field == 2 ? begin(2) + rotationDofs : begin(field + 1); }
};

class LinearSolver {
public:
  virtual ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  /// Name of the method, e.g. "MUMPS", "KLU2", "MINRES/block diagonal (S_σ: MUMPS)".
  virtual std::string name() const = 0;
  virtual bool isIterative() const { return false; }

  /// Diagonal scaling D (owned-map vector, entries > 0), or null for none. Applies from the next
  /// setOperator on.
  void setScaling(const Teuchos::RCP<const Vector>& D);
  /// Field layout and masses (see BlockStructure). Required by Krylov solvers before setOperator.
  void setBlockStructure(const BlockStructure& blocks);
  const BlockStructure& blockStructure() const { return blocks_; }

  /// Set (or replace) the square operator A (fill-complete; row, range and domain maps with the
  /// same global indices, each owned by exactly one rank). `symmetric` states that A = Aᵀ. A is
  /// kept (not copied) and must stay unchanged until the next setOperator.
  void setOperator(const Teuchos::RCP<const CrsMatrix>& A, bool symmetric);

  /// x = A⁻¹ b for every column. x's values on input are the initial guess of Krylov solvers
  /// (use the previous Newton iterate); direct solvers overwrite them.
  void solve(const MultiVector& b, MultiVector& x);

  const SolveStatistics& lastSolveStats() const { return stats_; }

  /// `Linear Solver/Symmetric`: exploit a symmetric operator (default true).
  void setExploitSymmetry(bool exploit);
  bool exploitsSymmetry() const { return exploitSymmetry_; }
  /// The current operator is treated as symmetric (declared symmetric and exploited).
  bool isSymmetric() const { return symmetric_; }

  /// Krylov solvers: the relative residual ‖b − A x‖/‖b‖ a solve reaches (`Linear
  /// Solver/Iterative/Tolerance` until set here); direct solvers have none (0) and ignore the
  /// setter. The contact Newton's balanced stopping changes it per solve
  /// (contact/BalancedStopping.hpp).
  virtual double relativeTolerance() const { return 0.0; }
  virtual void setRelativeTolerance(double /*tolerance*/) {}

  /// Krylov solvers: an approximation of the error x* − x of an approximate solution x of the
  /// current operator's system, the preconditioner applied to the residual, P⁻¹(b − A x), in A's
  /// unknowns (the scaling D undone). With the block preconditioner spectrally equivalent to the
  /// operator (docs/theory.md §"Linear solvers") it is within a bounded factor of the error.
  /// Returns false (error untouched) for direct solvers: no preconditioner, and exact solves.
  bool estimateError(const MultiVector& b, const MultiVector& x, MultiVector& error) const;

  /// Largest accepted relative residual of a solve (<= 0: not checked).
  void setMaximumRelativeResidual(double limit) { maxRelativeResidual_ = limit; }
  double maximumRelativeResidual() const { return maxRelativeResidual_; }

protected:
  LinearSolver();

  /// The operator the solver works on changed: `A` is D A D (or A without scaling); `symmetric`
  /// is the effective flag. Runs on every rank; must throw the same sc::core::Error on all.
  virtual void operatorChanged(const Teuchos::RCP<const CrsMatrix>& A, bool symmetric) = 0;
  /// Solve the (scaled) system A x = b; x holds the (scaled) initial guess on input.
  virtual void solveOperator(const MultiVector& b, MultiVector& x) = 0;

  /// z = P⁻¹ r with the preconditioner of the working system (false: the solver has none).
  virtual bool applyPreconditioner(const MultiVector& /*r*/, MultiVector& /*z*/) const
  {
    return false;
  }

  /// The operator passed to operatorChanged (null before the first setOperator).
  const Teuchos::RCP<const CrsMatrix>& workingOperator() const { return working_; }
  const Teuchos::RCP<const Vector>& scaling() const { return D_; }

  SolveStatistics stats_;

private:
  Teuchos::RCP<const CrsMatrix> A_;        // the caller's operator
  Teuchos::RCP<const CrsMatrix> working_;  // D A D or A
  // D A D of a direct solver, rewritten in place when the next operator has the same graph
  // (the Newton steps of a contact solve): no new matrix per step. A Krylov solver's
  // preconditioner may keep the previous operator, so it gets a new one each time.
  Teuchos::RCP<CrsMatrix> scaledWorking_;
  Teuchos::RCP<const Vector> D_;
  BlockStructure blocks_;
  bool exploitSymmetry_ = true;
  bool symmetric_ = false;
  double maxRelativeResidual_ = 1e-6;
};

/// A copy of `source`'s values on its graph: written into `reuse` when that matrix shares the
/// graph (no allocation: the Newton steps of a contact solve change values, not the graph),
/// otherwise a new copy. `reuse` may be null; it must not be `source` itself.
Teuchos::RCP<CrsMatrix> copyMatrixValues(const CrsMatrix& source,
                                         const Teuchos::RCP<CrsMatrix>& reuse);

}  // namespace sc::solvers

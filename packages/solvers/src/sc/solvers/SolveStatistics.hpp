#pragma once
// What the last factorisations and solve of a LinearSolver cost and how accurate the solve was.

namespace sc::solvers {

struct SolveStatistics {
  // Wall-clock seconds of the most recent call of each phase (rank 0's clock; all ranks take
  // part in every phase).
  double equilibrationSeconds = 0.0;
  double symbolicSeconds = 0.0;
  double numericSeconds = 0.0;
  double solveSeconds = 0.0;
  /// Sums of the above since the solver was built (each cycle's share is the difference).
  double totalEquilibrationSeconds = 0.0;
  double totalSymbolicSeconds = 0.0;
  double totalNumericSeconds = 0.0;
  double totalSolveSeconds = 0.0;

  // Counters since the operator was first set.
  int symbolicFactorizations = 0;  ///< analyses (orderings) done
  int numericFactorizations = 0;   ///< numerical factorisations done
  int symbolicReuses = 0;          ///< numerical factorisations that reused an earlier analysis
  int solves = 0;
  int workspaceRetries = 0;  ///< MUMPS factorisations repeated with a larger ICNTL(14)

  int equilibrationIterations = 0;  ///< Ruiz sweeps of the last equilibration (0: off)

  /// max over right-hand sides of ‖b − A x‖₂ / ‖b‖₂ of the working system (D A D with the
  /// LinearSolver's scaling), after the last solve (‖b‖ = 0 counts as ‖b − A x‖).
  double relativeResidual = 0.0;

  // Krylov solvers (-1 / 0 for direct solvers):
  int iterations = -1;                 ///< Krylov iterations of the last solve (all restarts)
  long long totalIterations = 0;       ///< Krylov iterations since the solver was built
  int preconditionerSetups = 0;        ///< preconditioner (re)builds since the solver was built
  double preconditionerSeconds = 0.0;  ///< wall-clock seconds of the last preconditioner build

  /// Entries in the factors (KLU2: nnz(L)+nnz(U); MUMPS: INFOG(29)); -1 if unknown.
  long long factorNonzeros = -1;

  // MUMPS memory (MB) of the last analysis and factorisation, -1 for other solvers:
  // INFOG(16)/(17): the analysis' estimate for an in-core full-rank factorisation, max per rank /
  // sum over ranks (the workspace is allocated from it, also with block low-rank);
  // INFOG(18)/(19): factorisation, max per rank / sum over ranks;
  // INFOG(21)/(22): factorisation + solve, max per rank / sum over ranks.
  double mumpsEstimatedMemoryMaxMB = -1.0;
  double mumpsEstimatedMemoryTotalMB = -1.0;
  double mumpsFactorMemoryMaxMB = -1.0;
  double mumpsFactorMemoryTotalMB = -1.0;
  double mumpsMemoryMaxMB = -1.0;
  double mumpsMemoryTotalMB = -1.0;
  /// MUMPS: the scaling MUMPS applied in the last factorisation, INFOG(33) (the effective
  /// ICNTL(8): 0 none, 7/8 its iterative row/column scalings); -1 for other solvers.
  int mumpsScaling = -1;
};

}  // namespace sc::solvers

#pragma once
// MUMPS 5.5 (multifrontal, parallel) through its C interface dmumps_c.h. The matrix is given in
// distributed assembled form (ICNTL(18) = 3): each rank passes its own rows with 1-based global
// indices; right-hand side and solution are centralised on rank 0 (ICNTL(20) = ICNTL(21) = 0) and
// moved with Tpetra Import/Export. SYM = 0 (general LU) or 2 (general symmetric LDLᵀ, lower
// triangle only) from DirectSolver::setSymmetric. Analysis (JOB = 1) once per graph, factorisation
// (JOB = 2) per operator, solve (JOB = 3) per right-hand side block.
//
// Errors (INFOG(1) < 0) become sc::core::Error on every rank with the MUMPS code and its meaning;
// -8/-9 (workspace too small) are retried with ICNTL(14) doubled, a few times.

#include <memory>

#include <sc/solvers/DirectSolver.hpp>

namespace sc::solvers {

struct MumpsOptions {
  int memoryRelaxationPercent{};  ///< ICNTL(14): extra workspace over the analysis estimate
  int workspaceRetries{};         ///< on INFOG(1) = -8/-9: retry with ICNTL(14) doubled
  int ordering{};  ///< ICNTL(7): 0 AMD, 2 AMF, 3 SCOTCH, 4 PORD, 5 METIS, 6 QAMD, 7 auto
  bool verbose{};  ///< MUMPS diagnostics on stdout (ICNTL(1..4))
  /// CNTL(7), the block low-rank dropping parameter; > 0 turns BLR on in the factorisation and
  /// the solve (ICNTL(35) = 2), 0 keeps the full-rank factorisation (ICNTL(35) = 0).
  double lowRankTolerance{};
  /// ICNTL(8), MUMPS' own scaling: 77 (MUMPS chooses), 0 (none), or -1: none when our Ruiz
  /// equilibration ran (DirectSolver::equilibrationEnabled), else 77 (docs/solvers.md
  /// "Equilibration").
  int scaling = -1;
};

class MumpsSolver : public DirectSolver {
public:
  explicit MumpsSolver(const MumpsOptions& options);
  ~MumpsSolver() override;  // JOB = -2 on the communicator of the last operator
  std::string name() const override { return "MUMPS"; }

  /// Text for a MUMPS error code INFOG(1) (e.g. -10: "numerically singular matrix").
  static std::string errorMeaning(int infog1);

protected:
  void doSymbolicFactorization(const Teuchos::RCP<const CrsMatrix>& A) override;
  void doNumericFactorization(const Teuchos::RCP<const CrsMatrix>& A) override;
  void doSolve(const MultiVector& b, MultiVector& x) override;
  void symmetryChanged() override;

private:
  struct Impl;  // DMUMPS_STRUC_C, index/value arrays, gather/scatter plans
  std::unique_ptr<Impl> impl_;
  MumpsOptions options_;
};

}  // namespace sc::solvers

#pragma once
// The additive Schwarz smoother B = Σ_i R_iᵀ A_i⁻¹ R_i of the stress-block multigrid
// (docs/theory.md §"Linear solvers") over the patches (σ global ids) of this rank, applied
// matrix-free: each patch block A_i is factorised once by LAPACK in double (Cholesky when
// symmetric, LU with partial pivoting otherwise). Cholesky factors are kept in single precision
// (MINRES needs no more; it halves the largest memory item). LU factors stay in double: a smoother
// solved in single precision is not one linear operator to working precision, and GMRES, which
// forms its solution with one more application of the preconditioner than its residual
// recurrence saw, then lost accuracy on adaptive Coulomb systems (true residual 15 for a recurrence
// at 1e-8, docs/solvers.md "Contact with the stress multigrid"). apply() imports the residual
// onto the union of this rank's patches (rows of patches cut by the partition come from the other
// ranks), solves with each patch's factors and exports (adds) the corrections to their owners.
// Memory: Σ_i m_i² floats. (Assembling B as a sparse matrix took more than 5 GB at 262k 3D DOFs
// with vertex stars.)

#include <vector>

#include <Teuchos_RCP.hpp>
#include <Tpetra_Export_fwd.hpp>
#include <Tpetra_Import_fwd.hpp>

#include <sc/solvers/LinearAlgebraTypes.hpp>

namespace sc::solvers {

class PatchSmoother {
public:
  /// Factorises the blocks of A (the level's operator) on `patches`; throws
  /// sc::core::ConvergenceError when a block is not positive definite (symmetric) or singular.
  PatchSmoother(const CrsMatrix& A, const std::vector<std::vector<long long>>& patches,
                bool symmetric);
  ~PatchSmoother();

  /// z ← β z + ω B r.
  void apply(const MultiVector& r, MultiVector& z, double omega, double beta) const;

private:
  Teuchos::RCP<const Map> rowMap_, overlapMap_;
  Teuchos::RCP<Tpetra::Import<>> import_;
  Teuchos::RCP<Tpetra::Export<>> export_;
  bool symmetric_ = true;
  std::vector<int> sizes_;         // patch sizes m_i
  std::vector<int> lids_;          // the patches' rows, local ids of the overlap map, concatenated
  std::vector<float> factors_;     // Cholesky factors (lower), column-major m_i × m_i
  std::vector<double> luFactors_;  // or LU factors, column-major m_i × m_i
  std::vector<int> pivots_;        // LU: the pivots of each patch, concatenated
};

}  // namespace sc::solvers
